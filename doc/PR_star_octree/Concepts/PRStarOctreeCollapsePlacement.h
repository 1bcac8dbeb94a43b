/*!
\ingroup PkgPRStarOctreeConcepts
\cgalConcept

The concept `PRStarOctreeCollapsePlacement` describes where the vertex that survives a collapse
of `CGAL::PR_star_octree::simplify()` goes (named parameter `get_placement`).  For a candidate
edge with both ends in the leaf being simplified, the collapse to the placement's point (the end
`v1` removed, `v0` moved there) is tried first; then the half-edge collapses the strata allow (one
end removed into the other, which stays where it is), in the order the placement gives.  The first
one that passes every check is applied.

A placement receives the edge profile `e` described in `PRStarOctreeCollapseCost`.

\cgalHasModel `CGAL::PR_star_octree::Edge_collapse_placement`

\sa `PRStarOctreeCollapseCost`
*/
class PRStarOctreeCollapsePlacement {
public:
  /*!
  returns the point the merged vertex moves to, or `std::nullopt` for half-edge collapses only.
  `Point_3` is the traits' point type.
  */
  template <class EdgeProfile>
  std::optional<Point_3> operator()(const EdgeProfile& e) const;

  /*!
  returns `true` if the half-edge collapse of `e.v1()` into `e.v0()` is to be tried before that of
  `e.v0()` into `e.v1()`.
  */
  template <class EdgeProfile>
  bool remove_v1_first(const EdgeProfile& e) const;
};
