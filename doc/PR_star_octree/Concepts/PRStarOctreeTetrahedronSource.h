/*!
\ingroup PkgPRStarOctreeConcepts
\cgalConcept

The concept `PRStarOctreeTetrahedronSource` describes where the streaming construction of
`CGAL::PR_star_octree_3` reads the tetrahedra of a mesh from: a sequence of tetrahedra (each the
0-based indices of its four vertices) and optionally one label each, given chunk by chunk, from the
first to the last, as many times as the construction asks (a file read again, or arrays in memory).
Every pass must give the same tetrahedra in the same order; the construction checks it and throws
otherwise.

\cgalHasModel `CGAL::PR_star_octree::Tetrahedron_range_source`
\cgalHasModel `CGAL::PR_star_octree::IO::Vtu_tetrahedron_source`

\sa `PRStarOctreeInputMesh`
*/
class PRStarOctreeTetrahedronSource {
public:
  /*!
  calls `f(const std::uint64_t* vertices, const int* labels, std::size_t n)` for consecutive chunks
  of the tetrahedra, from the first one: `vertices` holds the 4 vertex indices of each of the `n`
  tetrahedra of the chunk, `labels` their labels, or is `nullptr` for a mesh without labels.  The
  pointers are valid during the call only.  What it throws (e.g. a read error) goes through the
  construction.
  */
  template <class F>
  void for_each_chunk(F f) const;

  /*!
  Optional: the number of tetrahedra `for_each_chunk()` gives, when the source knows it without
  a pass over them (a count in memory, a file's cell types).  The construction then checks the
  tetrahedra in its pass counting them by smallest vertex instead of a pass of their own, and
  throws when the number given differs.
  */
  std::size_t number_of_tetrahedra() const;
};
