/*!
\ingroup PkgPRStarOctreeConcepts
\cgalConcept

The concept `PRStarOctreeCollapseCost` describes the cost of a candidate edge of
`CGAL::PR_star_octree::simplify()` (named parameter `get_cost`): each leaf collapses its candidate
edges by increasing cost.  The cost is evaluated when an edge enters a leaf's queue and again when
it leaves it: if the value changed (a cost depending on the neighbourhood, such as a quadric
error), the edge is queued again with the new value.

A cost receives an *edge profile* `e` of an unspecified type, describing the edge
`(e.v0(), e.v1())`, `e.v0() < e.v1()`, in the vertex numbering of the current round's octree:
- `e.v0()`, `e.v1()`: the two ends;
- `e.point(v)`, `e.points()`: the traits' point of a vertex, all the points;
- `e.coordinates(v)`: its coordinates as `std::array<double, 3>`;
- `e.stratum(v)`: 3 interior, 2 surface, 1 feature curve, 0 corner;
- `e.can_remove(r, k)`: whether the strata allow removing `r` into `k`;
- `e.in_leaf(v)`: whether `v` is a vertex of the leaf being simplified;
- `e.input_vertex(v)`: the index of `v` in the input mesh;
- `e.has_quadrics()`, `e.quadric_error(p)`, `e.optimal_parameter()`: the plane quadrics of the
  input surface the two ends stand for (computed with the quadric priority or the optimal
  placement), the error of the merged vertex at `p`, and the parameter in `[0, 1]` of the point of
  the edge of smallest error (-1 when the ends are not of one stratum of dimension 2 or 3);
- `e.geom_traits()`: the traits.

\cgalHasModel `CGAL::PR_star_octree::Edge_length_priority`
\cgalHasModel `CGAL::PR_star_octree::Quadric_error_cost`

\sa `PRStarOctreeCollapsePlacement`
\sa `PRStarOctreeCollapseFilter`
\sa `PRStarOctreeSimplificationVisitor`
*/
class PRStarOctreeCollapseCost {
public:
  /*!
  returns the cost of the collapse of the edge of the edge profile `e` (smaller costs first).
  */
  template <class EdgeProfile>
  double operator()(const EdgeProfile& e) const;
};
