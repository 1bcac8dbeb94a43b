// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_REMESHING_H
#define CGAL_PR_STAR_OCTREE_REMESHING_H

/// \file remeshing.h
/// Local remeshing of a tetrahedral mesh to a target edge length on a PR-star octree: every leaf
/// splits its long edges, collapses its short ones, flips and smooths, round after round, with the
/// guarantees of `simplify()` (validity by exact predicates, features, labels, error bound).

#include <CGAL/PR_star_octree/simplification.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

// The target edge length at each input vertex: a number, or a readable property map from the input
// vertex index to a length.
template <class Sizing>
std::vector<double> sizing_values(const Sizing& sizing, std::size_t vertices) {
  std::vector<double> h(vertices);
  for (std::size_t v = 0; v < vertices; ++v) {
    if constexpr (std::is_arithmetic<Sizing>::value)
      h[v] = static_cast<double>(sizing);
    else
      h[v] = static_cast<double>(get(sizing, v));
    if (!(h[v] > 0) || !std::isfinite(h[v]))
      throw std::invalid_argument("remesh: the target edge length must be positive and finite (vertex " +
                                  std::to_string(v) + ")");
  }
  return h;
}

// The placement of the remeshing's collapses: the midpoint of an edge inside the volume (both ends
// interior: the new edges are the shortest, so fewer collapses make an edge too long), else a
// half-edge collapse.
struct Midpoint_placement {
  template <class EdgeProfile>
  std::optional<typename EdgeProfile::Point_3> operator()(const EdgeProfile& e) const {
    if (e.stratum(e.v0()) != 3 || e.stratum(e.v1()) != 3) return std::nullopt;
    return make_point<typename EdgeProfile::Point_3>(lerp(e.coordinates(e.v0()), e.coordinates(e.v1()), 0.5));
  }
  template <class EdgeProfile>
  bool remove_v1_first(const EdgeProfile&) const {
    return true;
  }
};

} // namespace internal

/// \ingroup PkgPRStarOctreeRef
///
/// Remeshes a tetrahedral mesh towards a target edge length by local operations on PR-star octrees
/// (see the user manual, Section Remeshing), as %CGAL's `tetrahedral_isotropic_remeshing()` and
/// MMG's `-hmin`/`-hmax` do on a global structure.
///
/// Each round builds the PR-star octree of the current mesh and visits its leaves in depth-first
/// order.  A leaf, on the edges with an end among its vertices,
/// - splits at its midpoint every edge longer than 4/3 of the target (longest first);
/// - collapses every edge shorter than 4/5 of the target (shortest first; inside the volume into
///   its midpoint, else into one end) that creates no edge longer than 4/3 of it, with every check of
///   `simplify()` (strata, exact orientation, link condition, quality floors, error bound);
/// - flips (2-3, 3-2, 4-4 and the removal of edges in up to seven tetrahedra) where the worst
///   tetrahedron of the region gets better, inside one label only and never on the surface;
/// - smooths its vertices: interior ones towards the volume-weighted circumcentres of their star,
///   surface ones in their tangent plane and back onto the input surface, feature vertices along
///   their curve, corners never; a move is made when the worst tetrahedron around the vertex gets
///   better, every tetrahedron stays positive (exact `Orientation_3`) and the surface stays within
///   the error bound.
/// The mesh is then compacted and the next round begins.
///
/// A split cuts the surface nowhere new (the midpoint of a surface edge is on the surface), so the
/// surface changes only by collapses and moves, both checked against the error bound.
///
/// \tparam InputMesh a model of `PRStarOctreeInputMesh` (see `make_input()`); its scalar field, if
///         any, is the output's point-data array "scalar"
/// \tparam Sizing `double`, or a readable property map with the input vertex index (`std::size_t`)
///         as key type and the target edge length there as value type (a sizing field; an edge's
///         target is the mean of its ends', a new vertex's the mean of its edge's)
/// \param input the mesh
/// \param target_edge_length the target edge length, or the sizing field
/// \param np a sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the number of rounds (%CGAL's named parameter); the rounds stop earlier
///       when one changes nothing}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{5}
///   \cgalParamNEnd
///   \cgalParamNBegin{min_dihedral_angle}
///     \cgalParamDescription{the floor on the smallest dihedral angle (degrees; 0: none)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{5}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_dihedral_angle}
///     \cgalParamDescription{the ceiling on the largest dihedral angle (degrees; 180: none)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{165}
///   \cgalParamNEnd
///   \cgalParamNBegin{min_radius_ratio}
///     \cgalParamDescription{the floor on the radius ratio (0: none)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.1}
///   \cgalParamNEnd
///   \cgalParamNBegin{feature_angle}
///     \cgalParamDescription{as in `simplify()`}
///     \cgalParamType{`double` (degrees)}
///     \cgalParamDefault{40}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_boundary_error}
///     \cgalParamDescription{as in `simplify()`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.2% of the diagonal of the bounding box}
///   \cgalParamNEnd
///   \cgalParamNBegin{bucket_size}
///     \cgalParamDescription{the bucket threshold `k_v` of the octrees}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{50}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_is_constrained_map}
///     \cgalParamDescription{as in `simplify()`: vertices never removed nor moved}
///     \cgalParamType{a readable property map with key type `std::size_t` and value type `bool`}
///     \cgalParamDefault{no constrained vertex}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_constrained_map}
///     \cgalParamDescription{as in `simplify()`: feature edges}
///     \cgalParamType{a readable property map with key type `std::pair<std::size_t, std::size_t>`
///       and value type `bool`}
///     \cgalParamDefault{no constrained edge}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the traits; the output points are its `Point_3`, made from doubles}
///     \cgalParamType{a model of `PRStarOctreeTraits`}
///     \cgalParamDefault{`Exact_predicates_inexact_constructions_kernel`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns a `Simplification_result<Point_3>`: the mesh, and for each output vertex the input
/// vertex whose point data it carries (itself; for a vertex made by a split, the first end of the
/// edge split), for each output tetrahedron the input tetrahedron it lies in part of (its label
/// and cell data); `statistics.optimization` counts the splits, flips and moves.
///
/// \throws std::invalid_argument for a target edge length that is not positive and finite, bad
/// floors, and as the `PR_star_octree_3` constructor for a bad input.
template <class InputMesh, class Sizing, class NP = parameters::Default_named_parameters>
auto remesh(const InputMesh& input, const Sizing& target_edge_length,
            const NP& np = parameters::default_values()) {
  const internal::Simplify_options<NP> options(np, true);
  using GeomTraits = typename internal::Simplify_options<NP>::Geom_traits;
  using Octree = PR_star_octree_3<GeomTraits>;
  using Point_3 = typename GeomTraits::Point_3;
  static_assert(std::is_constructible<Point_3, double, double, double>::value,
                "remesh() makes new points: Point_3 must be constructible from three doubles");
  const auto start = std::chrono::steady_clock::now();
  Simplification_result<Point_3> result;
  Simplification_statistics& s = result.statistics;

  std::optional<Octree> tree;
  tree.emplace(input, parameters::bucket_size(options.settings.bucket_size).geom_traits(options.gt));
  const std::vector<int> labels = internal::input_labels(*tree);
  s.input_vertices = tree->number_of_vertices();
  s.input_tetrahedra = tree->number_of_tetrahedra();
  internal::Simplification_settings settings = options.settings;
  settings.max_boundary_error = options.boundary_error(tree->points());
  s.max_boundary_error = settings.max_boundary_error;
  settings.remesh_iterations = parameters::choose_parameter(
      parameters::get_parameter(np, CGAL::internal_np::number_of_iterations), std::size_t(5));
  std::vector<double> sizing = internal::sizing_values(target_edge_length, tree->number_of_vertices());

  Simplification_visitor_base visitor;
  const auto constraints = options.constraints();
  internal::Compact_mesh<GeomTraits> out;
  using Cost = internal::Priority_cost<Edge_length_priority<GeomTraits>>;
  internal::Local_simplifier<GeomTraits, Cost, internal::Midpoint_placement, Quality_and_error_filter,
                             Simplification_visitor_base>
      remesher(settings, Cost{Edge_length_priority<GeomTraits>{options.gt}}, internal::Midpoint_placement(),
               Quality_and_error_filter(), visitor, options.gt);
  remesher.run_remesh(tree, labels, std::move(sizing), constraints.first, constraints.second, s, out);
  tree.reset();

  internal::finish_result(input, labels, out, result);
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

/// \ingroup PkgPRStarOctreeRef
/// Remeshes an `Indexed_tetrahedral_mesh` (named parameters as above): every point-data array,
/// every cell-data array and the tetrahedron labels and their names are carried along, as
/// `Simplification_result::input_vertex` and `Simplification_result::input_tetrahedron` say.
template <class P, class I, class Sizing, class NP = parameters::Default_named_parameters>
auto remesh(const Indexed_tetrahedral_mesh<P, I>& mesh, const Sizing& target_edge_length,
            const NP& np = parameters::default_values()) {
  auto input = make_input(mesh.points, mesh.tetrahedra);
  if (!mesh.tetrahedron_labels.empty()) input.set_tetrahedron_labels(mesh.tetrahedron_labels);
  auto result = remesh(input, target_edge_length, np);
  internal::carry_mesh_data(mesh, result);
  return result;
}

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_REMESHING_H
