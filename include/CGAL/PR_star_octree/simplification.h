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
#include <CGAL/PR_star_octree/internal/Simplification/collapse_candidate.h>
#include <CGAL/PR_star_octree/internal/Simplification/compaction.h>
#include <CGAL/PR_star_octree/internal/Simplification/round_driver.h>
#include <CGAL/PR_star_octree/internal/Simplification/round_mesh.h>
#include <CGAL/PR_star_octree/internal/Simplification/settings.h>
#include <CGAL/PR_star_octree/parameters.h>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {

/// \ingroup PkgPRStarOctreeRef
/// The default cost of a collapse: the squared length of the edge (shortest first), through the
/// traits' `Compute_squared_distance_3`.  A model of `PRStarOctreeCollapseCost`.
///
/// It is also a functor `double operator()(const std::vector<Point_3>& points, Index v1, Index v2)`,
/// the older form of a cost that the named parameter `priority` takes (the collapse of the edge
/// `(v1, v2)`, current numbering of the round).
template <class GeomTraits = Exact_predicates_inexact_constructions_kernel>
struct Edge_length_priority {
  GeomTraits gt; ///< the traits
  /// the squared length of the edge `(v1, v2)`
  template <class Point_3, class Index>
  double operator()(const std::vector<Point_3>& points, Index v1, Index v2) const {
    return CGAL::to_double(gt.compute_squared_distance_3_object()(points[v1], points[v2]));
  }
  /// the squared length of the edge of `profile`
  template <class EdgeProfile>
  double operator()(const EdgeProfile& profile) const {
    return (*this)(profile.points(), profile.v0(), profile.v1());
  }
};

/// \ingroup PkgPRStarOctreeRef
/// The cost of a collapse by quadric error (Garland-Heckbert): the mean squared distance of the
/// merged vertex to the planes of the input surface triangles its ends stand for, at the best
/// place the strata allow (an end, or with `optimal_points` the point of the edge of smallest
/// error), plus a hundredth of the squared length of the edge (so that edges of no error, inside
/// or on planes, go shortest first).  A model of `PRStarOctreeCollapseCost`; `simplify()` uses it
/// with `collapse_priority(Collapse_priority::QUADRIC_ERROR)`.
struct Quadric_error_cost {
  bool optimal_points = false; ///< also consider the point of the edge of smallest error
  /// the cost of the edge of `profile`
  template <class EdgeProfile>
  double operator()(const EdgeProfile& e) const {
    const auto &a = e.coordinates(e.v0()), &b = e.coordinates(e.v1());
    double best = std::numeric_limits<double>::infinity();
    const double t = optimal_points ? e.optimal_parameter() : -1;
    if (t >= 0) best = e.quadric_error(internal::lerp(a, b, t));
    if (e.can_remove(e.v1(), e.v0())) best = (std::min)(best, e.quadric_error(a));
    if (e.can_remove(e.v0(), e.v1())) best = (std::min)(best, e.quadric_error(b));
    if (!(best < std::numeric_limits<double>::infinity())) best = 0;
    const double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    return best + 0.01 * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  }
};

/// \ingroup PkgPRStarOctreeRef
/// The default placement of a collapse, a model of `PRStarOctreeCollapsePlacement`: half-edge
/// collapses only, or first the point of the edge of smallest quadric error
/// (`Collapse_placement::OPTIMAL`, when both ends are of one stratum of dimension 2 or 3, the
/// point is inside the edge and `Point_3` is made from three doubles).  The end of the higher
/// stratum is removed first; on a tie, with `smaller_error_first`, the one whose removal leaves the
/// smaller quadric error, else `v1`.
struct Edge_collapse_placement {
  Collapse_placement placement = Collapse_placement::HALF_EDGE; ///< half-edge or optimal
  bool smaller_error_first = false; ///< order the half-edge collapses by quadric error
  /// the point the merged vertex moves to, if any
  template <class EdgeProfile>
  std::optional<typename EdgeProfile::Point_3> operator()(const EdgeProfile& e) const {
    using Point_3 = typename EdgeProfile::Point_3;
    if (placement != Collapse_placement::OPTIMAL ||
        !std::is_constructible<Point_3, double, double, double>::value)
      return std::nullopt;
    const double t = e.optimal_parameter();
    if (!(t > 0 && t < 1)) return std::nullopt;
    return internal::make_point<Point_3>(internal::lerp(e.coordinates(e.v0()), e.coordinates(e.v1()), t));
  }
  /// whether the half-edge collapse of `v1` into `v0` is tried before that of `v0` into `v1`
  template <class EdgeProfile>
  bool remove_v1_first(const EdgeProfile& e) const {
    if (!smaller_error_first || e.stratum(e.v0()) != e.stratum(e.v1())) return true;
    return e.quadric_error(e.coordinates(e.v0())) <= e.quadric_error(e.coordinates(e.v1()));
  }
};

/// \ingroup PkgPRStarOctreeRef
/// The default collapse filter, a model of `PRStarOctreeCollapseFilter`: the quality floor, then
/// the error bound (named parameters `quality_measure`, `quality_floor`, `max_boundary_error`).
struct Quality_and_error_filter {
  /// `Collapse_refusal::QUALITY`, `Collapse_refusal::ERROR` or `Collapse_refusal::NONE`
  template <class CollapseProfile>
  Collapse_refusal operator()(const CollapseProfile& c) const {
    if (!c.above_quality_floor()) return Collapse_refusal::QUALITY;
    if (!c.within_error_bound()) return Collapse_refusal::ERROR;
    return Collapse_refusal::NONE;
  }
};

/// \ingroup PkgPRStarOctreeRef
/// A simplification visitor that does nothing, a model of `PRStarOctreeSimplificationVisitor`: the
/// default, and a base for a visitor that needs only some of the calls.
struct Simplification_visitor_base {
  /// a round begins on a mesh of `vertices` vertices and `tetrahedra` tetrahedra
  void on_round_started(std::size_t /* round */, std::size_t /* vertices */, std::size_t /* tetrahedra */) {}
  /// a candidate edge was not collapsed
  template <class EdgeProfile>
  void on_refused(const EdgeProfile&, Collapse_refusal) {}
  /// a collapse is about to be applied
  template <class CollapseProfile>
  void on_collapse(const CollapseProfile&) {}
  /// a round removed `removed_tetrahedra` tetrahedra
  void on_round_finished(std::size_t /* round */, std::size_t /* removed_tetrahedra */) {}
};

namespace internal {

// A cost that is `first` or `second`, chosen at run time (the enum `collapse_priority`).
template <class First, class Second>
struct Either_cost {
  First first;
  Second second;
  bool use_second = false;
  template <class EdgeProfile>
  double operator()(const EdgeProfile& e) const {
    return use_second ? second(e) : first(e);
  }
};

// The older form of a cost, `f(points, v1, v2)` (named parameter `priority`).
template <class F>
struct Priority_cost {
  F f;
  template <class EdgeProfile>
  double operator()(const EdgeProfile& e) const {
    return f(e.points(), e.v0(), e.v1());
  }
};

// The visitor: the user's (a `std::reference_wrapper`) or a copy of it.
template <class V>
V& mutable_visitor(V& v, std::optional<V>&) {
  return v;
}
template <class V>
V& mutable_visitor(const V& v, std::optional<V>& copy) {
  copy.emplace(v);
  return *copy;
}

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

// The named parameters of `simplify()`, read in one place.
template <class NP>
struct Simplify_options {
  using Geom_traits =
      typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::geom_traits_t, NP,
                                                         Exact_predicates_inexact_constructions_kernel>::type;
  using Point_3 = typename Geom_traits::Point_3;
  using Priority = std::decay_t<decltype(parameters::choose_parameter(
      parameters::get_parameter(std::declval<const NP&>(), internal_np::priority),
      Edge_length_priority<Geom_traits>()))>;
  using Default_cost = Either_cost<Priority_cost<Priority>, Quadric_error_cost>;

  // `remeshing`: for `remesh()` (no target needed).
  explicit Simplify_options(const NP& np, bool remeshing = false)
      : gt(parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::geom_traits),
                                        Geom_traits())),
        np_(np) {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    settings.target_fraction = choose_parameter(get_parameter(np, internal_np::target_fraction), 0.);
    settings.max_edge_length = choose_parameter(get_parameter(np, internal_np::max_edge_length),
                                                std::numeric_limits<double>::infinity());
    settings.bucket_size = choose_parameter(get_parameter(np, internal_np::bucket_size),
                                            std::size_t(PR_star_octree_3<Geom_traits>::default_bucket_size));
    settings.max_rounds = choose_parameter(get_parameter(np, internal_np::max_rounds), std::size_t(1000));
    // The older pair (measure, floor) sets the floor of its measure; the three named floors override.
    const Quality_measure measure = choose_parameter(get_parameter(np, internal_np::quality_measure),
                                                     Quality_measure::MIN_DIHEDRAL_ANGLE);
    const double floor = choose_parameter(get_parameter(np, internal_np::quality_floor), -1.);
    if (floor >= 0 || std::isnan(floor)) {
      if (measure == Quality_measure::RADIUS_RATIO)
        settings.min_radius_ratio = floor;
      else
        settings.min_dihedral = floor;
    }
    settings.min_dihedral =
        choose_parameter(get_parameter(np, internal_np::min_dihedral_angle), settings.min_dihedral);
    settings.max_dihedral = choose_parameter(get_parameter(np, internal_np::max_dihedral_angle), 165.);
    settings.min_radius_ratio =
        choose_parameter(get_parameter(np, internal_np::min_radius_ratio), settings.min_radius_ratio);
    settings.optimization_rounds =
        choose_parameter(get_parameter(np, internal_np::optimization_rounds), std::size_t(2));
    settings.remesh = remeshing;
    settings.feature_angle = choose_parameter(get_parameter(np, internal_np::feature_angle), 40.);
    error_bound = choose_parameter(get_parameter(np, internal_np::max_boundary_error), -1.);
    quadric_priority = choose_parameter(get_parameter(np, internal_np::collapse_priority),
                                        Collapse_priority::EDGE_LENGTH) == Collapse_priority::QUADRIC_ERROR;
    optimal_placement = choose_parameter(get_parameter(np, internal_np::collapse_placement),
                                         Collapse_placement::HALF_EDGE) == Collapse_placement::OPTIMAL;
    settings.with_quadrics = quadric_priority || optimal_placement;
    check();
  }

  auto cost() const {
    const Default_cost by_default{
        Priority_cost<Priority>{parameters::choose_parameter(
            parameters::get_parameter(np_, internal_np::priority), Edge_length_priority<Geom_traits>{gt})},
        Quadric_error_cost{optimal_placement &&
                           std::is_constructible<Point_3, double, double, double>::value},
        quadric_priority};
    return parameters::choose_parameter(parameters::get_parameter(np_, CGAL::internal_np::get_cost_policy),
                                        by_default);
  }
  auto placement() const {
    return parameters::choose_parameter(
        parameters::get_parameter(np_, CGAL::internal_np::get_placement_policy),
        Edge_collapse_placement{optimal_placement ? Collapse_placement::OPTIMAL
                                                  : Collapse_placement::HALF_EDGE,
                                quadric_priority});
  }
  auto filter() const {
    return parameters::choose_parameter(parameters::get_parameter(np_, CGAL::internal_np::filter),
                                        Quality_and_error_filter());
  }
  auto constraints() const {
    const auto vertex = parameters::get_parameter(np_, CGAL::internal_np::vertex_is_constrained);
    const auto edge = parameters::get_parameter(np_, CGAL::internal_np::edge_is_constrained);
    return std::make_pair([vertex](std::size_t v) { return constrained_vertex(vertex, v); },
                          [edge](std::size_t a, std::size_t b) { return constrained_edge(edge, a, b); });
  }

  // The default error bound: 0.2% of the diagonal of the bounding box of `points`.
  template <class Points>
  double boundary_error(const Points& points) const {
    if (!(error_bound < 0)) return error_bound;
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for (std::size_t v = 0; v < points.size(); ++v) {
      const Vec3 c = to_vec3(gt, points[v]);
      for (int i = 0; i < 3; ++i) {
        lo[i] = v == 0 ? c[i] : (std::min)(lo[i], c[i]);
        hi[i] = v == 0 ? c[i] : (std::max)(hi[i], c[i]);
      }
    }
    return 0.002 * std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                             (hi[2] - lo[2]) * (hi[2] - lo[2]));
  }

  Geom_traits gt;
  Simplification_settings settings;
  double error_bound = -1; // < 0: the default
  bool quadric_priority = false, optimal_placement = false;

private:
  void check() const {
    const Simplification_settings& s = settings;
    if (!(s.target_fraction >= 0 && s.target_fraction < 1))
      throw std::invalid_argument("simplify: the target fraction must be in [0, 1)");
    if (!(s.max_edge_length > 0))
      throw std::invalid_argument("simplify: the maximum edge length must be positive");
    if (!s.remesh && s.target_fraction == 0 && !(s.max_edge_length < std::numeric_limits<double>::infinity()))
      throw std::invalid_argument("simplify: give a target fraction or a maximum edge length");
    if (s.bucket_size == 0) throw std::invalid_argument("simplify: the bucket size k_v must be at least 1");
    if (!(s.min_dihedral >= 0 && s.min_dihedral <= 70.5))
      throw std::invalid_argument(
          "simplify: the floor on the smallest dihedral angle must be in [0, 70.5] degrees");
    if (!(s.max_dihedral >= 70.6 && s.max_dihedral <= 180))
      throw std::invalid_argument(
          "simplify: the ceiling on the largest dihedral angle must be in [70.6, 180] degrees");
    if (!(s.min_radius_ratio >= 0 && s.min_radius_ratio <= 1))
      throw std::invalid_argument("simplify: the floor on the radius ratio must be in [0, 1]");
    if (!(s.feature_angle >= 0))
      throw std::invalid_argument("simplify: the feature angle must be non-negative (degrees)");
    if (std::isnan(error_bound))
      throw std::invalid_argument("simplify: the boundary error bound is not a number");
  }

  const NP& np_;
};

} // namespace internal

namespace internal {

// The tetrahedron labels of the octree's input, in the input's numbering (empty without labels).
template <class Octree>
std::vector<int> input_labels(const Octree& tree) {
  std::vector<int> labels;
  if (!tree.has_tetrahedron_labels()) return labels;
  labels.resize(tree.number_of_tetrahedra());
  for (std::size_t t = 0; t < labels.size(); ++t)
    labels[tree.original_tetrahedron(static_cast<typename Octree::Index>(t))] =
        tree.tetrahedron_label(static_cast<typename Octree::Index>(t));
  return labels;
}

// The result of `simplify()` or `remesh()` from the last compact mesh `out`: the mesh, the input's
// scalar field and labels carried along, the input index of each vertex and tetrahedron.
template <class InputMesh, class GeomTraits, class Point_3>
void finish_result(const InputMesh& input, const std::vector<int>& labels, Compact_mesh<GeomTraits>& out,
                   Simplification_result<Point_3>& result) {
  Simplification_statistics& s = result.statistics;
  s.output_vertices = out.points.size();
  s.output_tetrahedra = out.tetrahedra.size();
  result.mesh.points = std::move(out.points);
  result.mesh.tetrahedra.assign(out.tetrahedra.begin(), out.tetrahedra.end());
  if (input.has_scalar_field()) {
    Point_data_array a{"scalar", std::vector<double>(out.input_vertex.size())};
    for (std::size_t v = 0; v < out.input_vertex.size(); ++v)
      a.values[v] = static_cast<double>(input.scalar(out.input_vertex[v]));
    result.mesh.point_data.push_back(std::move(a));
  }
  if (!labels.empty()) {
    result.mesh.tetrahedron_labels.resize(out.input_tetrahedron.size());
    for (std::size_t t = 0; t < out.input_tetrahedron.size(); ++t)
      result.mesh.tetrahedron_labels[t] = labels[out.input_tetrahedron[t]];
  }
  result.input_vertex = std::move(out.input_vertex);
  result.input_tetrahedron = std::move(out.input_tetrahedron);
}

// The point data, cell data and label names of `mesh` onto the output of `result`.
template <class P, class I, class Result>
void carry_mesh_data(const Indexed_tetrahedral_mesh<P, I>& mesh, Result& result) {
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
}

} // namespace internal

/// \ingroup PkgPRStarOctreeRef
///
/// Simplifies a tetrahedral mesh by edge collapses on a PR-star octree (paper Section 9), keeping
/// its sharp features, label interfaces, a quality floor and an error bound (see the user manual,
/// Section Simplification).
///
/// Each round builds the PR-star octree of the current mesh with bucket threshold `bucket_size` and
/// visits its leaves in depth-first order.  A leaf queues the edges with an end in it that are
/// shorter than the round's threshold, by cost (shortest first by default), and collapses them one
/// by one: an end `v2` in the leaf is removed into the other end `v1` (which stays where it is, or
/// moves to the point the placement gives) when
/// - *strata*: `v2` is not a corner, `v1` is of the stratum of `v2` or a lower one (interior,
///   surface, feature curve, corner), and a feature vertex moves along a feature edge, a surface
///   vertex along a surface edge (a non-manifold end is a corner);
/// - *geometric condition*: no new tetrahedron flips or becomes flat, decided with the traits'
///   exact `Orientation_3`;
/// - *link condition*: `Lk(v1) ∩ Lk(v2) = Lk(e)` as simplicial complexes (vertices, edges,
///   triangles), the boundary being coned to a dummy vertex so that the boundary surface keeps its
///   topology too; and the same on the surface and on the feature curves;
/// - *filter*: by default the quality floor and the error bound (see the named parameters below
///   and the user manual).
/// Then the mesh is compacted and the octree rebuilt.  Rounds go on while one removes a tetrahedron
/// and the target is not met; `Simplification_statistics::stop` says why they stopped.  The first
/// round's octree is built on `input` directly (it validates and orients the input).
///
/// The cost, the placement, the filter and a visitor are policies, as in %CGAL's
/// Surface_mesh_simplification: see the concepts `PRStarOctreeCollapseCost`,
/// `PRStarOctreeCollapsePlacement`, `PRStarOctreeCollapseFilter` and
/// `PRStarOctreeSimplificationVisitor`.  The strata, geometric and link conditions are not: they
/// keep the mesh valid and its features.
///
/// The round's threshold is `max_edge_length`; with a target fraction it is also bounded by
/// the `q`-quantile of the current edge lengths (sampled), `q` being the fraction of the current
/// tetrahedra still to remove, so that short edges all over the mesh go first; when such a round
/// removes nothing, the next ones take every edge under `max_edge_length`.
///
/// \tparam InputMesh a model of `PRStarOctreeInputMesh` (see `make_input()`); its scalar field, if
///         any, is the output's point-data array "scalar"
/// \param input the mesh
/// \param np a sequence of named parameters among the ones listed below (at least one of
///        `target_fraction` and `max_edge_length`)
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{target_fraction}
///     \cgalParamDescription{stop once this fraction of the input tetrahedra is removed}
///     \cgalParamType{`double` in `[0, 1)`}
///     \cgalParamDefault{0: no target}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_edge_length}
///     \cgalParamDescription{collapse only edges shorter than this}
///     \cgalParamType{`double`}
///     \cgalParamDefault{infinity: no bound}
///   \cgalParamNEnd
///   \cgalParamNBegin{bucket_size}
///     \cgalParamDescription{the bucket threshold `k_v` of the octrees;
///       `PR_star_octree_3::infinite_bucket_size` gives the global algorithm (one leaf, one queue)}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{50}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_rounds}
///     \cgalParamDescription{an upper bound on the number of rounds}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{1000}
///   \cgalParamNEnd
///   \cgalParamNBegin{collapse_priority}
///     \cgalParamDescription{the default cost: shortest edge first (`priority`), or smallest quadric
///       error first (`Quadric_error_cost`); ignored with `get_cost`}
///     \cgalParamType{`Collapse_priority`}
///     \cgalParamDefault{`Collapse_priority::EDGE_LENGTH`}
///   \cgalParamNEnd
///   \cgalParamNBegin{priority}
///     \cgalParamDescription{the cost of the edge-length priority, in the older form
///       `double f(const std::vector<Point_3>& points, Index v1, Index v2)`; ignored with `get_cost`}
///     \cgalParamType{a functor}
///     \cgalParamDefault{`Edge_length_priority<GeomTraits>`}
///   \cgalParamNEnd
///   \cgalParamNBegin{get_cost}
///     \cgalParamDescription{the cost of a collapse (%CGAL's named parameter): smaller costs are
///       collapsed first}
///     \cgalParamType{a model of `PRStarOctreeCollapseCost`}
///     \cgalParamDefault{from `collapse_priority` and `priority`}
///   \cgalParamNEnd
///   \cgalParamNBegin{collapse_placement}
///     \cgalParamDescription{the default placement: half-edge collapses, or the point of the edge of
///       smallest quadric error first; ignored with `get_placement`}
///     \cgalParamType{`Collapse_placement`}
///     \cgalParamDefault{`Collapse_placement::HALF_EDGE`}
///   \cgalParamNEnd
///   \cgalParamNBegin{get_placement}
///     \cgalParamDescription{where the merged vertex goes (%CGAL's named parameter)}
///     \cgalParamType{a model of `PRStarOctreeCollapsePlacement`}
///     \cgalParamDefault{`Edge_collapse_placement` from `collapse_placement` and `collapse_priority`}
///   \cgalParamNEnd
///   \cgalParamNBegin{filter}
///     \cgalParamDescription{refuses collapses that passed the strata, geometric and link conditions
///       (%CGAL's named parameter)}
///     \cgalParamType{a model of `PRStarOctreeCollapseFilter`}
///     \cgalParamDefault{`Quality_and_error_filter`}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{told of the rounds, the collapses and the refusals (%CGAL's named
///       parameter); copied, unless given as `std::ref(v)`}
///     \cgalParamType{a model of `PRStarOctreeSimplificationVisitor`}
///     \cgalParamDefault{`Simplification_visitor_base` (does nothing)}
///   \cgalParamNEnd
///   \cgalParamNBegin{min_dihedral_angle}
///     \cgalParamDescription{the floor on the smallest dihedral angle: no collapse creates a
///       tetrahedron under a floor (or over the ceiling) unless the tetrahedra it replaces were as
///       bad, by every measure, and as many; checked by the default filter (degrees; 0: none)}
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
///   \cgalParamNBegin{quality_measure}
///     \cgalParamDescription{the measure `quality_floor` sets the floor of (the older form of the
///       two floors above, which override it)}
///     \cgalParamType{`Quality_measure`}
///     \cgalParamDefault{`Quality_measure::MIN_DIHEDRAL_ANGLE`}
///   \cgalParamNEnd
///   \cgalParamNBegin{quality_floor}
///     \cgalParamDescription{the floor of `quality_measure`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`min_dihedral_angle` or `min_radius_ratio`}
///   \cgalParamNEnd
///   \cgalParamNBegin{optimization_rounds}
///     \cgalParamDescription{the rounds of optimisation only (flips and smoothing leaf by leaf, see
///       `remesh()`) after the collapses; with a positive number, each leaf is also optimised after
///       its collapses in every round; 0: no optimisation, the mesh is only coarsened}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{2}
///   \cgalParamNEnd
///   \cgalParamNBegin{feature_angle}
///     \cgalParamDescription{surface edges deviating from flat by more than this are sharp features;
///       their vertices only slide along them, corners never move; the triangles between
///       tetrahedra of different labels are kept as surfaces too}
///     \cgalParamType{`double` (degrees; 180: no sharp edges)}
///     \cgalParamDefault{40}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_boundary_error}
///     \cgalParamDescription{the bound on the distance between the input surface and the simplified
///       one (infinity: none; negative: the default); checked by the default filter}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.2% of the diagonal of the bounding box}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_is_constrained_map}
///     \cgalParamDescription{the user's corners: vertices that are never removed nor moved (%CGAL's
///       named parameter)}
///     \cgalParamType{a readable property map with an input vertex index (`std::size_t`) as key
///       type and `bool` as value type}
///     \cgalParamDefault{no constrained vertex}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_constrained_map}
///     \cgalParamDescription{the user's feature edges: their vertices only slide along them (%CGAL's
///       named parameter)}
///     \cgalParamType{a readable property map with a pair of input vertex indices,
///       `std::pair<std::size_t, std::size_t>` with the smaller first, as key type and `bool` as
///       value type}
///     \cgalParamDefault{no constrained edge}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the traits; the output points are its `Point_3`}
///     \cgalParamType{a model of `PRStarOctreeTraits`}
///     \cgalParamDefault{`Exact_predicates_inexact_constructions_kernel`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns a `Simplification_result<Point_3>`
///
/// \throws std::invalid_argument when neither a target in `(0, 1)` nor a finite positive length
/// bound is given, and as the `PR_star_octree_3` constructor for a bad input.
template <class InputMesh, class NP = parameters::Default_named_parameters>
auto simplify(const InputMesh& input, const NP& np = parameters::default_values()) {
  const internal::Simplify_options<NP> options(np);
  using GeomTraits = typename internal::Simplify_options<NP>::Geom_traits;
  using Octree = PR_star_octree_3<GeomTraits>;
  using Point_3 = typename GeomTraits::Point_3;
  const auto start = std::chrono::steady_clock::now();
  Simplification_result<Point_3> result;
  Simplification_statistics& s = result.statistics;

  // The first round's octree, on the input: it validates and orients it.
  std::optional<Octree> tree;
  tree.emplace(input, parameters::bucket_size(options.settings.bucket_size).geom_traits(options.gt));
  const std::vector<int> labels = internal::input_labels(*tree);
  s.input_vertices = tree->number_of_vertices();
  s.input_tetrahedra = tree->number_of_tetrahedra();
  internal::Simplification_settings settings = options.settings;
  settings.max_boundary_error = options.boundary_error(tree->points());
  s.max_boundary_error = settings.max_boundary_error;

  const auto cost = options.cost();
  const auto placement = options.placement();
  const auto filter = options.filter();
  Simplification_visitor_base no_visitor;
  auto&& user_visitor = parameters::choose_parameter(
      parameters::get_parameter_reference(np, CGAL::internal_np::visitor), no_visitor);
  std::optional<std::decay_t<decltype(user_visitor)>> visitor_copy;
  auto& visitor = internal::mutable_visitor(user_visitor, visitor_copy);
  const auto constraints = options.constraints();
  internal::Compact_mesh<GeomTraits> out;
  internal::Local_simplifier<GeomTraits, std::decay_t<decltype(cost)>, std::decay_t<decltype(placement)>,
                             std::decay_t<decltype(filter)>, std::decay_t<decltype(visitor)>>
      simplifier(settings, cost, placement, filter, visitor, options.gt);
  simplifier.run(tree, labels, constraints.first, constraints.second, s, out);
  tree.reset();

  internal::finish_result(input, labels, out, result);
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
  internal::carry_mesh_data(mesh, result);
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
