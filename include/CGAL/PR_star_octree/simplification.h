// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_SIMPLIFICATION_H
#define CGAL_PR_STAR_OCTREE_SIMPLIFICATION_H

/// \file simplification.h
/// Local half-edge-collapse simplification of a tetrahedral mesh on a PR-star octree (paper
/// Section 9): every leaf collapses the short edges whose two ends it indexes, with a local
/// priority queue; then the mesh is compacted and the octree rebuilt, round after round.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/Index_arrays_input.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>
#include <CGAL/PR_star_octree/Leaf_topology.h>
#include <CGAL/PR_star_octree/Simplification_statistics.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/internal/collapse_tester.h>
#include <CGAL/PR_star_octree/internal/local_simplifier.h>
#include <CGAL/PR_star_octree/parameters.h>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

// The user's constraints, from the property maps (input indices), if given.
inline bool constrained_vertex(CGAL::internal_np::Param_not_found, std::size_t) {
  return false;
}
template <class Map>
bool constrained_vertex(const Map& map, std::size_t v) {
  return get(map, v);
}
inline bool constrained_edge(CGAL::internal_np::Param_not_found, std::size_t, std::size_t) {
  return false;
}
template <class Map>
bool constrained_edge(const Map& map, std::size_t a, std::size_t b) {
  return get(map, std::make_pair((std::min)(a, b), (std::max)(a, b)));
}

} // namespace internal

/// \ingroup PkgPRStarOctreeRef
/// The default priority of a half-edge collapse: the squared length of the edge (shortest first),
/// through the traits' `Compute_squared_distance_3`.
///
/// A priority is a functor `double operator()(const std::vector<Point_3>& points, Index v1, Index v2)`
/// called for the collapse of `v2` into `v1` (current numbering of the round); smaller values are
/// collapsed first.  It is evaluated when the edge enters a leaf's queue and again when it leaves it:
/// if the value changed (a priority depending on the neighbourhood, e.g. a quadric error), the edge is
/// queued again with the new value.
template <class GeomTraits = Exact_predicates_inexact_constructions_kernel>
struct Edge_length_priority {
  GeomTraits gt;
  template <class Point_3, class Index>
  double operator()(const std::vector<Point_3>& points, Index v1, Index v2) const {
    return CGAL::to_double(gt.compute_squared_distance_3_object()(points[v1], points[v2]));
  }
};

/// \ingroup PkgPRStarOctreeRef
///
/// Simplifies a tetrahedral mesh by edge collapses on a PR-star octree (paper Section 9), keeping
/// its sharp features, label interfaces, a quality floor and an error bound (see the user manual,
/// Section Simplification).
///
/// Each round builds the PR-star octree of the current mesh with bucket threshold `bucket_size` and
/// visits its leaves in depth-first order.  A leaf queues the edges with an end in it that are
/// shorter than the round's threshold, by `priority` (shortest first by default), and collapses
/// them one by one: an end `v2` in the leaf is removed into the other end `v1` (which stays where it
/// is, or moves to the optimal point of the edge with the optimal placement) when
/// - *strata*: `v2` is not a corner, `v1` is of the stratum of `v2` or a lower one (interior,
///   surface, feature curve, corner), and a feature vertex moves along a feature edge, a surface
///   vertex along a surface edge (a non-manifold end is a corner);
/// - *geometric condition*: no new tetrahedron flips or becomes flat, decided with the traits'
///   exact `Orientation_3`;
/// - *link condition*: `Lk(v1) ∩ Lk(v2) = Lk(e)` as simplicial complexes (vertices, edges,
///   triangles), the boundary being coned to a dummy vertex so that the boundary surface keeps its
///   topology too; and the same on the surface and on the feature curves;
/// - *quality floor* and *error bound* (see the named parameters below and the user manual).
/// Then the mesh is compacted and the octree rebuilt.  Rounds go on while one removes a tetrahedron
/// and the target is not met; `Simplification_statistics::stop` says why they stopped.
///
/// The round's threshold is `max_edge_length`; with a target fraction it is also bounded by
/// the `q`-quantile of the current edge lengths (sampled), `q` being the fraction of the current
/// tetrahedra still to remove, so that short edges all over the mesh go first; when such a round
/// removes nothing, the next ones take every edge under `max_edge_length`.
///
/// `InputMesh` is a model of `PRStarOctreeInputMesh` (see `make_input()`); its scalar field, if
/// any, is the output's point-data array "scalar".
///
/// \param input the mesh (a model of `PRStarOctreeInputMesh`)
/// \param np named parameters (at least one of `target_fraction` and `max_edge_length`):
/// - `target_fraction(double)`: stop once this fraction of the input tetrahedra is removed (in
///   `(0, 1)`; default 0: no target)
/// - `max_edge_length(double)`: collapse only edges shorter than this (default: no bound)
/// - `bucket_size(std::size_t)`: the bucket threshold `k_v` of the octree (default 50);
///   `PR_star_octree_3<>::infinite_bucket_size` gives the global algorithm (one leaf, one queue)
/// - `max_rounds(std::size_t)`: an upper bound on the number of rounds (default 1000)
/// - `priority(F)`: the collapse priority (default `Edge_length_priority`)
/// - `quality_measure(Quality_measure)` and `quality_floor(double)`: no collapse creates a
///   tetrahedron under the floor unless it replaces a worse one (default: smallest dihedral angle,
///   5 degrees; radius ratio: 0.1; floor 0: none)
/// - `feature_angle(double)`: surface edges deviating from flat by more than this (degrees,
///   default 40; 180: none) are sharp features; their vertices only slide along them, corners
///   never move; the triangles between tetrahedra of different labels are kept as surfaces too
/// - `max_boundary_error(double)`: the bound on the distance between the input surface and the
///   simplified one (default 0.2% of the bounding-box diagonal; infinity: none)
/// - `collapse_priority(Collapse_priority)`, `collapse_placement(Collapse_placement)`: shortest
///   edge or smallest quadric error first; half-edge collapses or the optimal point of the edge
/// - `vertex_is_constrained_map(m)`, `edge_is_constrained_map(m)`: property maps from an input
///   vertex index (`std::size_t`), or a pair of them (smaller first), to `bool`: the user's corners
///   and feature edges
/// - `geom_traits(gt)`: a model of `PRStarOctreeTraits` (default
///   `Exact_predicates_inexact_constructions_kernel`); the output points are its `Point_3`
///
/// \returns a `Simplification_result<Point_3>`
///
/// \throws std::invalid_argument when neither a target in `(0, 1)` nor a finite positive length
/// bound is given, and as the `PR_star_octree_3` constructor for a bad input.
template <class InputMesh, class NP = parameters::Default_named_parameters>
auto simplify(const InputMesh& input, const NP& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using GeomTraits =
      typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::geom_traits_t, NP,
                                                         Exact_predicates_inexact_constructions_kernel>::type;
  using Octree = PR_star_octree_3<GeomTraits>;
  using Point_3 = typename GeomTraits::Point_3;
  const GeomTraits gt = choose_parameter(get_parameter(np, CGAL::internal_np::geom_traits), GeomTraits());
  const auto priority =
      choose_parameter(get_parameter(np, internal_np::priority), Edge_length_priority<GeomTraits>{gt});
  using Priority = std::decay_t<decltype(priority)>;
  internal::Simplification_settings options;
  options.target_fraction = choose_parameter(get_parameter(np, internal_np::target_fraction), 0.);
  options.max_edge_length = choose_parameter(get_parameter(np, internal_np::max_edge_length),
                                             std::numeric_limits<double>::infinity());
  options.bucket_size =
      choose_parameter(get_parameter(np, internal_np::bucket_size), std::size_t(Octree::default_bucket_size));
  options.max_rounds = choose_parameter(get_parameter(np, internal_np::max_rounds), std::size_t(1000));
  options.quality_measure =
      choose_parameter(get_parameter(np, internal_np::quality_measure), Quality_measure::MIN_DIHEDRAL_ANGLE);
  options.quality_floor =
      choose_parameter(get_parameter(np, internal_np::quality_floor),
                       options.quality_measure == Quality_measure::RADIUS_RATIO ? 0.1 : 5.);
  options.feature_angle = choose_parameter(get_parameter(np, internal_np::feature_angle), 40.);
  const double error_bound = choose_parameter(get_parameter(np, internal_np::max_boundary_error), -1.);
  options.quadric_priority =
      choose_parameter(get_parameter(np, internal_np::collapse_priority), Collapse_priority::EDGE_LENGTH) ==
      Collapse_priority::QUADRIC_ERROR;
  options.optimal_placement = choose_parameter(get_parameter(np, internal_np::collapse_placement),
                                               Collapse_placement::HALF_EDGE) == Collapse_placement::OPTIMAL;
  const auto vertex_constrained = get_parameter(np, internal_np::vertex_is_constrained_map);
  const auto edge_constrained = get_parameter(np, internal_np::edge_is_constrained_map);
  if (!(options.target_fraction >= 0 && options.target_fraction < 1))
    throw std::invalid_argument("simplify: the target fraction must be in [0, 1)");
  if (!(options.max_edge_length > 0))
    throw std::invalid_argument("simplify: the maximum edge length must be positive");
  if (options.target_fraction == 0 && !(options.max_edge_length < std::numeric_limits<double>::infinity()))
    throw std::invalid_argument("simplify: give a target fraction or a maximum edge length");
  if (options.bucket_size == 0)
    throw std::invalid_argument("simplify: the bucket size k_v must be at least 1");
  if (!(options.quality_floor >= 0) ||
      (options.quality_measure == Quality_measure::RADIUS_RATIO ? options.quality_floor > 1
                                                                : options.quality_floor > 70.5))
    throw std::invalid_argument(
        "simplify: the quality floor must be in [0, 70.5] degrees (minimum dihedral angle) or "
        "[0, 1] (radius ratio)");
  if (!(options.feature_angle >= 0))
    throw std::invalid_argument("simplify: the feature angle must be non-negative (degrees)");
  if (std::isnan(error_bound))
    throw std::invalid_argument("simplify: the boundary error bound is not a number");

  const auto start = std::chrono::steady_clock::now();
  Simplification_result<Point_3> result;
  Simplification_statistics& s = result.statistics;

  // Validated, oriented copy of the input (the octree does both).
  std::vector<Point_3> points;
  std::vector<typename Octree::Tetrahedron> tets;
  std::vector<std::size_t> origin, tet_origin;
  std::vector<int> labels;
  {
    const Octree tree(input, options.bucket_size, Octree::default_max_depth, gt);
    points = tree.points();
    tets = tree.tetrahedra();
    origin.resize(points.size());
    for (std::size_t v = 0; v < points.size(); ++v)
      origin[v] = tree.original_vertex(static_cast<typename Octree::Index>(v));
    tet_origin.resize(tets.size());
    for (std::size_t t = 0; t < tets.size(); ++t)
      tet_origin[t] = tree.original_tetrahedron(static_cast<typename Octree::Index>(t));
    if (tree.has_tetrahedron_labels()) { // in the input's numbering
      labels.resize(tets.size());
      for (std::size_t t = 0; t < tets.size(); ++t)
        labels[tet_origin[t]] = tree.tetrahedron_label(static_cast<typename Octree::Index>(t));
    }
  }
  s.input_vertices = points.size();
  s.input_tetrahedra = tets.size();
  // The default error bound: 0.2% of the diagonal of the bounding box.
  if (error_bound < 0) {
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for (std::size_t v = 0; v < points.size(); ++v) {
      const double c[3] = {CGAL::to_double(gt.compute_x_3_object()(points[v])),
                           CGAL::to_double(gt.compute_y_3_object()(points[v])),
                           CGAL::to_double(gt.compute_z_3_object()(points[v]))};
      for (int i = 0; i < 3; ++i) {
        lo[i] = v == 0 ? c[i] : (std::min)(lo[i], c[i]);
        hi[i] = v == 0 ? c[i] : (std::max)(hi[i], c[i]);
      }
    }
    options.max_boundary_error =
        0.002 * std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                          (hi[2] - lo[2]) * (hi[2] - lo[2]));
  } else {
    options.max_boundary_error = error_bound;
  }
  s.max_boundary_error = options.max_boundary_error;

  internal::Local_simplifier<GeomTraits, Priority> simplifier(options, priority, gt);
  simplifier.run(
      points, tets, origin, tet_origin, labels,
      [&](std::size_t v) { return internal::constrained_vertex(vertex_constrained, v); },
      [&](std::size_t a, std::size_t b) { return internal::constrained_edge(edge_constrained, a, b); }, s);

  s.output_vertices = points.size();
  s.output_tetrahedra = tets.size();
  result.mesh.points = std::move(points);
  result.mesh.tetrahedra.assign(tets.begin(), tets.end());
  if (input.has_scalar_field()) {
    Point_data_array a{"scalar", std::vector<double>(origin.size())};
    for (std::size_t v = 0; v < origin.size(); ++v)
      a.values[v] = static_cast<double>(input.scalar(origin[v]));
    result.mesh.point_data.push_back(std::move(a));
  }
  if (!labels.empty()) {
    result.mesh.tetrahedron_labels.resize(tet_origin.size());
    for (std::size_t t = 0; t < tet_origin.size(); ++t)
      result.mesh.tetrahedron_labels[t] = labels[tet_origin[t]];
  }
  result.input_vertex = std::move(origin);
  result.input_tetrahedron = std::move(tet_origin);
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

/// \ingroup PkgPRStarOctreeRef
/// Simplifies an `Indexed_tetrahedral_mesh` (named parameters as above): every point-data array,
/// every cell-data array and the tetrahedron labels and their names are carried along (a half-edge
/// collapse keeps the surviving tetrahedra, and their data, as they are).
template <class P, class I, class NP = parameters::Default_named_parameters>
auto simplify(const Indexed_tetrahedral_mesh<P, I>& mesh, const NP& np = parameters::default_values()) {
  auto input = make_input(mesh.points, mesh.tetrahedra); // the point data is carried below, by name
  if (!mesh.tetrahedron_labels.empty()) input.set_tetrahedron_labels(mesh.tetrahedron_labels);
  auto result = simplify(input, np);
  for (const Point_data_array& a : mesh.point_data) {
    Point_data_array b{a.name, std::vector<double>(result.input_vertex.size())};
    for (std::size_t v = 0; v < b.values.size(); ++v) b.values[v] = a.values[result.input_vertex[v]];
    result.mesh.point_data.push_back(std::move(b));
  }
  for (const Point_data_array& a : mesh.cell_data) {
    Point_data_array b{a.name, std::vector<double>(result.input_tetrahedron.size())};
    for (std::size_t t = 0; t < b.values.size(); ++t) b.values[t] = a.values[result.input_tetrahedron[t]];
    result.mesh.cell_data.push_back(std::move(b));
  }
  result.mesh.label_names = mesh.label_names;
  return result;
}

/// \ingroup PkgPRStarOctreeRef
/// Evaluates the three conditions of the half-edge collapse of `v2` into `v1` (octree numbering)
/// independently, with the same code as `simplify()` (for tests and diagnostics; `O(|T|)` for
/// the vertex types).
template <class GT, class I>
Collapse_check check_half_edge_collapse(const PR_star_octree_3<GT, I>& tree,
                                        typename PR_star_octree_3<GT, I>::Index v1,
                                        typename PR_star_octree_3<GT, I>::Index v2) {
  using Index = I;
  Collapse_check r;
  internal::Collapse_tester<GT, Index> tester;
  std::vector<Index> st1, st2, st_e;
  vertex_star(tree, v1, std::back_inserter(st1));
  vertex_star(tree, v2, std::back_inserter(st2));
  tester.edge_star(tree.tetrahedra(), st2, v1, st_e);
  r.edge_exists = v1 != v2 && !st_e.empty(); // a vertex with itself is no edge
  if (!r.edge_exists) return r;
  std::vector<Vertex_type> types;
  internal::classify_vertices<CGAL::Sequential_tag>(
      tree, false, types, [](Index, int) {}, parameters::default_values());
  r.boundary = tester.boundary_ok(tree.tetrahedra(), st_e, v1, v2, types[v1], types[v2]);
  r.geometry = tester.geometry_ok(tree.geom_traits(), tree.points(), tree.tetrahedra(), st2, v1, v2);
  r.link = tester.link_ok(tree.tetrahedra(), st1, st2, st_e, v1, v2);
  return r;
}

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_SIMPLIFICATION_H
