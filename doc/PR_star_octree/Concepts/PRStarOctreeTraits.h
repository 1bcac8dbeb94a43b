/*!
\ingroup PkgPRStarOctreeConcepts
\cgalConcept

The concept `PRStarOctreeTraits` describes the geometric traits class of
`CGAL::PR_star_octree_3`: a point type with Cartesian coordinates, used to build the PR octree,
and an exact orientation predicate, used to orient every tetrahedron positively.

The requirements are checked at compile time: a class that misses one of them is rejected with a
`static_assert` naming the missing type or function.

\cgalHasModel All %CGAL kernels, for instance `CGAL::Exact_predicates_inexact_constructions_kernel`
(the default of `CGAL::PR_star_octree_3`), `CGAL::Exact_predicates_exact_constructions_kernel`,
`CGAL::Simple_cartesian<double>`.

\sa `PRStarOctreeInputMesh`
*/
class PRStarOctreeTraits {
public:
  /// \name Types
  /// @{

  /*!
  The number type of the coordinates.
  */
  typedef unspecified_type FT;

  /*!
  The point type.  It provides `x()`, `y()` and `z()`, whose values are converted to `double` with
  `CGAL::to_double()` to build the octree (the cube of the root, the split planes); it is
  constructible from three `double`s when the points of the input mesh are of another type.
  */
  typedef unspecified_type Point_3;

  /*!
  A model of `Kernel::Orientation_3`: a functor with the operator
  `CGAL::Orientation operator()(const Point_3& p, const Point_3& q, const Point_3& r, const Point_3& s)`
  that returns `CGAL::POSITIVE` when `s` lies on the positive side of the plane through `p`, `q`,
  `r` (that is, when the tetrahedron `pqrs` is positively oriented), `CGAL::NEGATIVE` when it lies
  on the negative side and `CGAL::COPLANAR` otherwise.

  The predicate should be exact: it decides which input tetrahedra are reoriented and which are
  reported as degenerate (zero volume) in the statistics.
  */
  typedef unspecified_type Orientation_3;

  /// @}

  /// \name Operations
  /// @{

  /*!
  returns the orientation predicate.
  */
  Orientation_3 orientation_3_object() const;

  /// @}
};
