/*!
\ingroup PkgPRStarOctreeConcepts
\cgalConcept

The concept `PRStarOctreeInputMesh` describes the read-only view of a tetrahedral mesh from which
`CGAL::PR_star_octree_3` is built: an indexed tetrahedral mesh (the array of vertices `V` and the
array of tetrahedra `T`, each tetrahedron given by the 0-based indices of its four vertices in `V`),
with an optional scalar field (one value per vertex).

The octree reads the mesh once, at construction, and keeps its own re-indexed copy: the input is
not needed afterwards.  Vertices and tetrahedra are accessed by index, in any order.

The requirements are checked at compile time: a class that misses one of them is rejected with a
`static_assert` naming the missing function.  The functions
`CGAL::PR_star_octree::make_input()` build the models below from plain arrays, from a
`CGAL::PR_star_octree::Indexed_tetrahedral_mesh` or from a 3D mesh complex.

\cgalHasModel `CGAL::PR_star_octree::Index_arrays_input`
\cgalHasModel `CGAL::PR_star_octree::Mesh_complex_3_input`

\sa `PRStarOctreeTraits`
*/
class PRStarOctreeInputMesh {
public:
  /// \name Access to the vertices
  /// @{

  /*!
  returns the number of vertices `|V|`.
  */
  std::size_t number_of_vertices() const;

  /*!
  returns the point of vertex `i`, for `0 <= i < number_of_vertices()`.  The point type provides
  `x()`, `y()`, `z()` convertible with `CGAL::to_double()`; it is either convertible to the
  `Point_3` type of the traits or made from its three coordinates, converted to `double`, by the
  traits' `construct_point_3_object()`.  The
  coordinates must be finite.
  */
  unspecified_type point(std::size_t i) const;

  /// @}

  /// \name Access to the tetrahedra
  /// @{

  /*!
  returns the number of tetrahedra `|T|`.
  */
  std::size_t number_of_tetrahedra() const;

  /*!
  returns the four vertex indices of tetrahedron `t`, for `0 <= t < number_of_tetrahedra()`, as a
  value `c` supporting `c[0]`, ..., `c[3]` (for instance `std::array<std::size_t, 4>`).

  The indices are 0-based and must be pairwise distinct and smaller than `number_of_vertices()`;
  otherwise the construction of the octree throws `std::invalid_argument`.  The orientation is
  free: negatively oriented tetrahedra are reoriented by the octree.
  */
  unspecified_type tetrahedron(std::size_t t) const;

  /// @}

  /// \name The optional scalar field
  /// @{

  /*!
  returns whether the mesh carries a scalar field (one value per vertex).
  */
  bool has_scalar_field() const;

  /*!
  returns the scalar value of vertex `i`, as a value convertible to `double`.  Only called when
  `has_scalar_field()` is `true`, but must compile in any case.
  */
  double scalar(std::size_t i) const;

  /// @}

  /// \name The optional tetrahedron labels
  /// Both functions may be absent: the mesh then has no labels.  When they exist and
  /// `has_tetrahedron_labels()` is `true`, `CGAL::PR_star_octree_3` keeps one label per tetrahedron
  /// (`tetrahedron_label()`, per-label counts in its statistics) and `CGAL::PR_star_octree::simplify()`
  /// carries them to its output.
  /// @{

  /*!
  returns whether the mesh carries one label per tetrahedron (e.g. subdomain indices).
  */
  bool has_tetrahedron_labels() const;

  /*!
  returns the label of tetrahedron `t`.
  */
  int tetrahedron_label(std::size_t t) const;

  /// @}
};
