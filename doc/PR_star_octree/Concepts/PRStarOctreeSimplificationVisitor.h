/*!
\ingroup PkgPRStarOctreeConcepts
\cgalConcept

The concept `PRStarOctreeSimplificationVisitor` describes an object that
`CGAL::PR_star_octree::simplify()` tells what it does (named parameter `visitor`): the rounds, the
collapses, the refused candidate edges.  The visitor is copied unless it is given as
`std::ref(visitor)`.

The profiles are those of `PRStarOctreeCollapseCost` (an edge) and `PRStarOctreeCollapseFilter`
(a collapse).

\cgalHasModel `CGAL::PR_star_octree::Simplification_visitor_base`

\sa `PRStarOctreeCollapseFilter`
*/
class PRStarOctreeSimplificationVisitor {
public:
  /*!
  called when a round begins, on a mesh of `vertices` vertices and `tetrahedra` tetrahedra
  (`round` counts from 1).
  */
  void on_round_started(std::size_t round, std::size_t vertices, std::size_t tetrahedra);

  /*!
  called when a candidate edge is not collapsed, with the reason.
  */
  template <class EdgeProfile>
  void on_refused(const EdgeProfile& e, CGAL::PR_star_octree::Collapse_refusal why);

  /*!
  called for each collapse, every check passed, just before it is applied.
  */
  template <class CollapseProfile>
  void on_collapse(const CollapseProfile& c);

  /*!
  called when a round ends, with the number of tetrahedra it removed.
  */
  void on_round_finished(std::size_t round, std::size_t removed_tetrahedra);
};
