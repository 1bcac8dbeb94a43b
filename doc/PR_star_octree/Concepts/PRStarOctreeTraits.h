/*!
\ingroup PkgPRStarOctreeConcepts
\cgalConcept

The concept `PRStarOctreeTraits` describes the geometric traits class of
`CGAL::PR_star_octree_3` and of the applications built on it: a point type, functors giving its
Cartesian coordinates (used to build the PR octree, its boxes, and the solid angles of the discrete
distortion), the squared distance between two points (the edge lengths of the simplification), and
an exact orientation predicate (used to orient every tetrahedron positively, to check validity and
to test the geometric condition of a collapse).  The package reaches the geometry only through these
functors, so a traits class with a point type of its own works through every application.

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
  The number type of the coordinates, convertible to `double` with `CGAL::to_double()`.
  */
  typedef unspecified_type FT;

  /*!
  The point type in which the octree stores the points of the mesh.
  */
  typedef unspecified_type Point_3;

  /*!
  A model of `Kernel::ConstructPoint_3` with the operator
  `Point_3 operator()(double x, double y, double z)`: makes a `Point_3` from the `x()`, `y()`,
  `z()` of an input point of another type, or from the stored 32-bit floats.  Only needed when the
  points of the input mesh are not convertible to `Point_3`, or to store the coordinates as floats
  (named parameter `coordinate_precision`: without it, the octree keeps `Point_3`s).
  */
  typedef unspecified_type Construct_point_3;

  /*!
  Models of `Kernel::ComputeX_3`, `Kernel::ComputeY_3` and `Kernel::ComputeZ_3`: functors with the
  operator `FT operator()(const Point_3& p)` returning a Cartesian coordinate of `p`.  The values,
  converted to `double`, build the octree (the cube of the root, the split planes) and the
  geometry of the applications.
  */
  typedef unspecified_type Compute_x_3;
  /// \copydoc Compute_x_3
  typedef unspecified_type Compute_y_3;
  /// \copydoc Compute_x_3
  typedef unspecified_type Compute_z_3;

  /*!
  A model of `Kernel::ComputeSquaredDistance_3` with the operator
  `FT operator()(const Point_3& p, const Point_3& q)`: the squared distance of `p` and `q`, used for
  the edge lengths of `CGAL::PR_star_octree::simplify()`.
  */
  typedef unspecified_type Compute_squared_distance_3;

  /*!
  A model of `Kernel::Orientation_3`: a functor with the operator
  `CGAL::Orientation operator()(const Point_3& p, const Point_3& q, const Point_3& r, const Point_3& s)`
  that returns `CGAL::POSITIVE` when `s` lies on the positive side of the plane through `p`, `q`,
  `r` (that is, when the tetrahedron `pqrs` is positively oriented), `CGAL::NEGATIVE` when it lies
  on the negative side and `CGAL::COPLANAR` otherwise.

  The predicate should be exact: it decides which input tetrahedra are reoriented and which are
  reported as degenerate (zero volume) in the statistics, which tetrahedra `check_validity()`
  reports as inverted or flat, and whether a collapse would flip a tetrahedron.
  */
  typedef unspecified_type Orientation_3;

  /// @}

  /// \name Operations
  /// @{

  /*!
  returns the point construction functor.
  */
  Construct_point_3 construct_point_3_object() const;

  /*!
  returns the functor giving the x coordinate (likewise `compute_y_3_object()` and
  `compute_z_3_object()`).
  */
  Compute_x_3 compute_x_3_object() const;
  /// returns the functor giving the y coordinate.
  Compute_y_3 compute_y_3_object() const;
  /// returns the functor giving the z coordinate.
  Compute_z_3 compute_z_3_object() const;

  /*!
  returns the squared distance functor.
  */
  Compute_squared_distance_3 compute_squared_distance_3_object() const;

  /*!
  returns the orientation predicate.
  */
  Orientation_3 orientation_3_object() const;

  /// @}
};
