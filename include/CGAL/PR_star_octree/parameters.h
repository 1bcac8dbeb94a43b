// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_PARAMETERS_H
#define CGAL_PR_STAR_OCTREE_PARAMETERS_H

/// \file parameters.h
/// The named parameters of the PR-star octree package.

#include <CGAL/Named_function_parameters.h>

#include <cstddef>

namespace CGAL {
namespace PR_star_octree {

// The package's own named parameters, listed once: X(name) for each.
#define CGAL_PR_STAR_OCTREE_FOR_EACH_PARAMETER(X)                                                            \
  X(bucket_size)                                                                                             \
  X(bucket_size_relations)                                                                                   \
  X(maximum_depth)                                                                                           \
  X(check_links)                                                                                             \
  X(with_boundary_triangles)                                                                                 \
  X(boundary_triangles_output)                                                                               \
  X(problems_output)                                                                                         \
  X(critical_points_output)                                                                                  \
  X(persistence_threshold)                                                                                   \
  X(arcs_output)                                                                                             \
  X(target_fraction)                                                                                         \
  X(max_edge_length)                                                                                         \
  X(max_rounds)                                                                                              \
  X(priority)                                                                                                \
  X(quality_measure)                                                                                         \
  X(quality_floor)                                                                                           \
  X(min_dihedral_angle)                                                                                      \
  X(max_dihedral_angle)                                                                                      \
  X(min_radius_ratio)                                                                                        \
  X(optimization_rounds)                                                                                     \
  X(feature_angle)                                                                                           \
  X(max_boundary_error)                                                                                      \
  X(collapse_priority)                                                                                       \
  X(collapse_placement)                                                                                      \
  X(progress)                                                                                                \
  X(domain_curvature_map)                                                                                    \
  X(vertex_type_map)                                                                                         \
  X(vertex_permutation)                                                                                      \
  X(tetrahedron_permutation)                                                                                 \
  X(concurrency_tag)                                                                                         \
  X(compact_tetrahedra)                                                                                      \
  X(coordinate_precision)                                                                                    \
  X(slab_tetrahedra)                                                                                         \
  X(compression)                                                                                             \
  X(format_version)                                                                                          \
  X(communicator)

/// \ingroup PkgPRStarOctreeRef
/// How `PR_star_octree_3` stores the coordinates of the points (named parameter
/// `coordinate_precision`).  The predicates are evaluated exactly on the stored values either way.
enum class Coordinate_precision {
  /// 32-bit floats when the input's coordinates are 32-bit floats
  /// (`Indexed_tetrahedral_mesh::float32_points`, an input mesh whose `has_float32_points()` is
  /// `true`, or points whose `x()` is a `float`); otherwise as `point_3`
  as_input,
  /// 32-bit floats (12 bytes per vertex): each coordinate rounded to the nearest `float`
  float32,
  /// the traits' `Point_3` (three `double`s with the default kernel), as given
  point_3
};

namespace internal_np {
// The tags of the package's own named parameters (CGAL's tags live in `CGAL::internal_np`).
#define CGAL_PR_STAR_OCTREE_TAG(NAME) enum NAME##_t{NAME};
CGAL_PR_STAR_OCTREE_FOR_EACH_PARAMETER(CGAL_PR_STAR_OCTREE_TAG)
#undef CGAL_PR_STAR_OCTREE_TAG
} // namespace internal_np

/// \ingroup PkgPRStarOctreeRef
/// The named parameters of the package.
///
/// They are used as %CGAL's (`CGAL/Named_function_parameters.h`): a function takes an optional last
/// argument `np` made by chaining parameters, e.g.
/// \code
/// namespace params = CGAL::PR_star_octree::parameters;
/// compute_boundary(tree, type_map, params::check_links(false).progress(report));
/// simplify(input, params::target_fraction(0.5).bucket_size(100).geom_traits(gt));
/// \endcode
/// The package's own parameters chain with each other and are followed by %CGAL's (`geom_traits`,
/// `verbose`, ...); a chain may also start with a %CGAL parameter when no package parameter is needed.
/// A %CGAL parameter returns %CGAL's chain, on which the package's parameters are no member functions:
/// put them first.  `simplify()` reads %CGAL's own `vertex_is_constrained_map`,
/// `edge_is_constrained_map`, `get_cost`, `get_placement`, `filter` and `visitor`, e.g.
/// `params::target_fraction(0.5).bucket_size(100).edge_is_constrained_map(m).visitor(std::ref(v))`.
///
// clang-format off
/// | parameter | used by | default |
/// |---|---|---|
/// | `bucket_size(std::size_t)` | the `PR_star_octree_3` constructors, `simplify()`, `check_validity()` on arrays | `automatic_bucket_size` (chosen by `choose_bucket_size()`) |
/// | `bucket_size_relations(unsigned)` | the `PR_star_octree_3` constructors: the `Relations` the automatic k_v is sized for | `default_bucket_size_relations` |
/// | `maximum_depth(std::size_t)` | the `PR_star_octree_3` constructors | 32 |
/// | `geom_traits(gt)` (%CGAL's) | the `PR_star_octree_3` constructors, `simplify()` | `GeomTraits()` |
/// | `vertex_permutation(bool)`, `tetrahedron_permutation(bool)` | the `PR_star_octree_3` constructors | `true` |
/// | `compact_tetrahedra(bool)` | the `PR_star_octree_3` constructors | `false` |
/// | `coordinate_precision(Coordinate_precision)` | the `PR_star_octree_3` constructors | `Coordinate_precision::as_input` |
/// | `slab_tetrahedra(std::size_t)` | the streaming `PR_star_octree_3` constructor: the tetrahedra placed in one pass (T is cut in |T| / this, rounded up, equal parts by smallest vertex; a part may take the star of one vertex more) | 2^20, and at most 6 parts |
/// | `concurrency_tag(Tag)` | the `PR_star_octree_3` constructors (the algorithms take the tag as their `ConcurrencyTag` template argument) | `CGAL::Parallel_if_available_tag()` |
/// | `check_links(bool)` | `compute_boundary()`, `Vertex_classifier` | `true` |
/// | `with_boundary_triangles(bool)` | `compute_boundary()` | `true` |
/// | `boundary_triangles_output(OutputIterator)` | `compute_boundary()` | none |
/// | `problems_output(OutputIterator)` | `check_validity()` (one process) | none |
/// | `critical_points_output(OutputIterator)` | `compute_critical_points()` | none |
/// | `persistence_threshold(double)`, `arcs_output(OutputIterator)` | `compute_morse_complexes()` | 0, none |
/// | `domain_curvature_map(PMap)`, `vertex_type_map(PMap)` | `compute_discrete_distortion()` | none |
/// | `progress(F)` | every leaf-streaming function, `simplify()` | none |
/// | `target_fraction`, `max_edge_length`, `max_rounds`, `priority`, `quality_measure`, `quality_floor`, `min_dihedral_angle`, `max_dihedral_angle`, `min_radius_ratio`, `optimization_rounds`, `feature_angle`, `max_boundary_error`, `collapse_priority`, `collapse_placement` | `simplify()` (see its documentation) | |
/// | `min_dihedral_angle`, `max_dihedral_angle`, `min_radius_ratio`, `feature_angle`, `max_boundary_error`, `bucket_size`, `number_of_iterations` (%CGAL's) | `remesh()` (see its documentation) | |
/// | `vertex_is_constrained_map`, `edge_is_constrained_map`, `get_cost`, `get_placement`, `filter`, `visitor` (%CGAL's) | `simplify()` | none |
/// | `use_binary_mode(bool)` (%CGAL's), `compression(IO::Compression)`, `format_version(double)` | the writers of `CGAL/PR_star_octree/IO.h` (what each format accepts: `IO/formats.h`) | per format |
/// | `communicator(MPI_Comm)` | `Distributed_octree_3`, `IO::read_mesh_part()` (MPI) | `MPI_COMM_WORLD` |
// clang-format on
namespace parameters {
using namespace CGAL::parameters;

using CGAL::parameters::Default_named_parameters;
using CGAL::parameters::default_values;
using CGAL::parameters::geom_traits;
using CGAL::parameters::verbose;

/// \ingroup PkgPRStarOctreeRef
/// A chain of named parameters that accepts the package's own parameters as member functions, as
/// well as %CGAL's (inherited from `CGAL::Named_function_parameters`).
template <class T, class Tag, class Base = CGAL::internal_np::No_property>
struct Named_parameters : CGAL::Named_function_parameters<T, Tag, Base> {
  using CGAL::Named_function_parameters<T, Tag, Base>::Named_function_parameters;

#define CGAL_PR_STAR_OCTREE_PARAMETER(NAME)                                                                  \
  template <class K>                                                                                         \
  Named_parameters<K, internal_np::NAME##_t, Named_parameters> NAME(const K& k) const {                      \
    return Named_parameters<K, internal_np::NAME##_t, Named_parameters>(k, *this);                           \
  }
  /// \cond SKIP_IN_MANUAL
  CGAL_PR_STAR_OCTREE_FOR_EACH_PARAMETER(CGAL_PR_STAR_OCTREE_PARAMETER)
  /// \endcond
#undef CGAL_PR_STAR_OCTREE_PARAMETER
};

/// \cond SKIP_IN_MANUAL
#define CGAL_PR_STAR_OCTREE_PARAMETER(NAME)                                                                  \
  template <class K>                                                                                         \
  Named_parameters<K, internal_np::NAME##_t> NAME(const K& k) {                                              \
    return Named_parameters<K, internal_np::NAME##_t>(k);                                                    \
  }
CGAL_PR_STAR_OCTREE_FOR_EACH_PARAMETER(CGAL_PR_STAR_OCTREE_PARAMETER)
#undef CGAL_PR_STAR_OCTREE_PARAMETER
/// \endcond

} // namespace parameters

namespace internal {

// Calls the `progress` named parameter, if any, with (done, total).
template <class NP>
struct Progress_reporter {
  explicit Progress_reporter(const NP& np) : np_(np) {}
  void operator()(std::size_t done, std::size_t total) const { call(done, total, get()); }

private:
  decltype(auto) get() const { return CGAL::parameters::get_parameter(np_, internal_np::progress); }
  static void call(std::size_t, std::size_t, CGAL::internal_np::Param_not_found) {}
  template <class F>
  static void call(std::size_t done, std::size_t total, const F& f) {
    f(done, total);
  }
  const NP& np_;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_PARAMETERS_H
