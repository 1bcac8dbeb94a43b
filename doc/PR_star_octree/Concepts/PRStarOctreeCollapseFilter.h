/*!
\ingroup PkgPRStarOctreeConcepts
\cgalConcept

The concept `PRStarOctreeCollapseFilter` describes the last test of a collapse of
`CGAL::PR_star_octree::simplify()` (named parameter `filter`): it is asked only about collapses
that keep the strata (features, surfaces, corners) and pass the geometric and link conditions,
which are not policies, and it may refuse them.

A filter receives a *collapse profile* `c` of an unspecified type, describing the collapse of
`c.removed()` into `c.kept()` (current round's numbering):
- `c.removed()`, `c.kept()`: the two vertices;
- `c.moves()`, `c.kept_point()`: whether the kept vertex moves, and where it ends up;
- `c.point(v)`, `c.coordinates(v)`, `c.stratum(v)`, `c.input_vertex(v)`: as in the edge profile
  of `PRStarOctreeCollapseCost`;
- `c.changed_tetrahedra()`: the tetrahedra the collapse changes, as they will be (vertex
  indices, `std::array` of four);
- `c.above_quality_floor()`, `c.within_error_bound()`: the package's quality floor and error
  bound (named parameters `quality_measure`, `quality_floor` and `max_boundary_error`), so that a
  filter can add its own tests to them;
- `c.geom_traits()`: the traits.

\cgalHasModel `CGAL::PR_star_octree::Quality_and_error_filter`

\sa `PRStarOctreeCollapseCost`
\sa `PRStarOctreeSimplificationVisitor`
*/
class PRStarOctreeCollapseFilter {
public:
  /*!
  returns `CGAL::PR_star_octree::Collapse_refusal::NONE` to accept the collapse, else the reason
  it is refused (counted in `CGAL::PR_star_octree::Simplification_statistics::blocked`;
  `Collapse_refusal::FILTER` for a reason of the filter's own).
  */
  template <class CollapseProfile>
  CGAL::PR_star_octree::Collapse_refusal operator()(const CollapseProfile& c) const;
};
