// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Validation, simplification and remeshing for the Python module: `_validate` (check_validity on an
// Octree, the problems grouped by kind as arrays in the user's numbering), `_simplify` (simplify()
// on numpy arrays read in place, or on an Octree seen in the user's numbering, with the statistics,
// the quality and the boundary distance that `prstar simplify --json` reports) and `_remesh`
// (remesh() on the same inputs, with the statistics of `prstar remesh --json`).  The option checks
// and their messages are in python/prstar/_simplification.py; the library checks them again.

#include "prstar_python.h"

#include <CGAL/PR_star_octree/mesh_quality.h>
#include <CGAL/PR_star_octree/remeshing.h>
#include <CGAL/PR_star_octree/simplification.h>
#include <CGAL/PR_star_octree/validity.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace prstar_python {

namespace {

using Problem = PSO::Validity_problem;
using Kind = PSO::Validity_problem_kind;

// ---------------------------------------------------------------------------------------------
// validate
// ---------------------------------------------------------------------------------------------

py::dict validate(Py_octree& o, py::object progress) {
  const Octree& tree = o.get();
  std::vector<Problem> problems;
  PSO::Validity_result r;
  double seconds = 0;
  const Progress p(std::move(progress));
  {
    Compute_scope scope(o.threads);
    const auto start = std::chrono::steady_clock::now();
    r = PSO::check_validity(tree,
                            params::problems_output(std::back_inserter(problems)).progress(std::cref(p)));
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  // The problems come sorted by kind, then element: each kind becomes its own arrays, in that order.
  std::vector<std::int64_t> inverted, flat, nm_vertices, unreferenced, triangle_tets, triangle_offsets{0};
  std::vector<std::int64_t> inverted_vertices, flat_vertices, triangles;
  for (const Problem& q : problems) switch (q.kind) {
    case Kind::INVERTED_TETRAHEDRON:
      inverted.push_back(static_cast<std::int64_t>(q.tetrahedron));
      inverted_vertices.insert(inverted_vertices.end(), q.vertices.begin(), q.vertices.end());
      break;
    case Kind::FLAT_TETRAHEDRON:
      flat.push_back(static_cast<std::int64_t>(q.tetrahedron));
      flat_vertices.insert(flat_vertices.end(), q.vertices.begin(), q.vertices.end());
      break;
    case Kind::NONMANIFOLD_TRIANGLE:
      triangles.insert(triangles.end(), q.vertices.begin(), q.vertices.begin() + 3);
      triangle_tets.insert(triangle_tets.end(), q.tetrahedra.begin(), q.tetrahedra.end());
      triangle_offsets.push_back(static_cast<std::int64_t>(triangle_tets.size()));
      break;
    case Kind::NONMANIFOLD_VERTEX:
      nm_vertices.push_back(static_cast<std::int64_t>(q.vertices[0]));
      break;
    case Kind::UNREFERENCED_VERTEX:
      unreferenced.push_back(static_cast<std::int64_t>(q.vertices[0]));
      break;
    }
  problems = {};
  py::dict counts; // the keys of `prstar validate --json`, in its order
  counts["valid"] = r.valid;
  counts["tetrahedra"] = r.tetrahedra;
  counts["inverted"] = r.inverted;
  counts["degenerate"] = r.degenerate;
  counts["nonmanifold_triangles"] = r.nonmanifold_triangles;
  counts["nonmanifold_vertices"] = r.nonmanifold_vertices;
  counts["unreferenced_vertices"] = r.unreferenced_vertices;
  counts["euler_characteristic"] = r.euler_characteristic;
  counts["boundary_triangles"] = r.boundary_triangles;
  counts["boundary_components"] = r.boundary_components;
  counts["seconds"] = seconds;
  py::dict d;
  d["counts"] = counts;
  d["positive"] = r.positive;
  d["negative"] = r.negative;
  const auto rows = [](const std::vector<std::int64_t>& v, py::ssize_t k) {
    return static_cast<py::ssize_t>(v.size()) / k;
  };
  d["inverted_tetrahedra"] = to_numpy(std::move(inverted));
  d["inverted_vertices"] =
      to_numpy<std::int64_t>(std::move(inverted_vertices), {rows(inverted_vertices, 4), 4});
  d["flat_tetrahedra"] = to_numpy(std::move(flat));
  d["flat_vertices"] = to_numpy<std::int64_t>(std::move(flat_vertices), {rows(flat_vertices, 4), 4});
  d["nonmanifold_triangles"] = to_numpy<std::int64_t>(std::move(triangles), {rows(triangles, 3), 3});
  d["triangle_tetrahedra"] = to_numpy(std::move(triangle_tets));
  d["triangle_offsets"] = to_numpy(std::move(triangle_offsets));
  d["nonmanifold_vertices"] = to_numpy(std::move(nm_vertices));
  d["unreferenced_vertices"] = to_numpy(std::move(unreferenced));
  return d;
}

// ---------------------------------------------------------------------------------------------
// simplify
// ---------------------------------------------------------------------------------------------

// An Octree seen as the InputMesh of simplify() in the USER's numbering (vertices, tetrahedra as
// they were listed, labels, field), so that the result's `input_vertex` / `input_tetrahedron` and
// the output order are those the same arrays would give.
class Octree_input {
public:
  explicit Octree_input(Py_octree& o) : tree_(o.get()), vertex_(o.from_original()) {
    const auto& to_original = tree_.tetrahedron_permutation();
    tetrahedron_.resize(to_original.size());
    for (std::size_t t = 0; t < to_original.size(); ++t) tetrahedron_[to_original[t]] = static_cast<Index>(t);
  }
  std::size_t number_of_vertices() const { return tree_.number_of_vertices(); }
  std::size_t number_of_tetrahedra() const { return tree_.number_of_tetrahedra(); }
  Point_3 point(std::size_t i) const { return tree_.point(vertex_[i]); }
  bool has_float32_points() const { return tree_.has_float_coordinates(); }
  std::array<Index, 4> tetrahedron(std::size_t t) const {
    return tree_.original_tetrahedron_vertices(tetrahedron_[t]);
  }
  bool has_scalar_field() const { return tree_.has_scalar_field(); }
  double scalar(std::size_t i) const { return tree_.scalar(vertex_[i]); }
  bool has_tetrahedron_labels() const { return tree_.has_tetrahedron_labels(); }
  int tetrahedron_label(std::size_t t) const { return tree_.tetrahedron_label(tetrahedron_[t]); }

private:
  const Octree& tree_;
  const std::vector<Index>& vertex_; // user -> octree
  std::vector<Index> tetrahedron_;   // user -> octree
};

// The options of `prstar simplify` and `prstar remesh`, already checked by the Python side (the
// library checks again).
struct Simplify_options {
  double target_fraction = 0, max_edge_length = std::numeric_limits<double>::infinity();
  double min_dihedral = 5, max_dihedral = 165, min_radius_ratio = 0.1, feature_angle = 40;
  std::size_t optimization_rounds = 2;
  double max_error = 0.2; // percent of the diagonal when `error_relative`
  bool error_relative = true;
  bool quadric = false, optimal = false;
  std::size_t bucket_size = Octree::automatic_bucket_size;
  // remesh: the target edge length (percent of the diagonal when `edge_length_relative`; unused with
  // a size field), the rounds
  double edge_length = 0;
  bool edge_length_relative = false;
  std::size_t iterations = 5;
};

// The progress of a simplification (simplify() has no progress parameter; its visitor is told of
// every collapse and round): `progress(removed, to_remove)`, the tetrahedra removed so far, at each
// round's start (the input's count minus the round's: collapses and flips together) and end (plus
// what the round's collapses deleted), throttled during a round (so that Ctrl-C and an exception of
// the callable stop a long round), never decreasing, and `(to_remove, to_remove)` at the end when the
// target is reached.
struct Progress_visitor : PSO::Simplification_visitor_base {
  const Progress* progress = nullptr;
  std::size_t input = 0, removed = 0, total = 0;
  void report(std::size_t r) {
    removed = (std::max)(removed, (std::min)(r, total));
    (*progress)(removed, total);
  }
  template <class CollapseProfile>
  void on_collapse(const CollapseProfile&) {
    (*progress)(removed, total);
  }
  void on_round_started(std::size_t, std::size_t, std::size_t tetrahedra) {
    report(input - (std::min)(tetrahedra, input));
  }
  void on_round_finished(std::size_t, std::size_t n) { report(removed + n); }
};

py::dict blocked_dict(const PSO::Simplification_statistics::Blocked& b) {
  py::dict d; // the JSON's order
  d["different_leaves"] = b.different_leaves;
  d["feature"] = b.feature;
  d["boundary"] = b.boundary;
  d["flip"] = b.flip;
  d["link"] = b.link;
  d["quality"] = b.quality;
  d["error"] = b.error;
  return d;
}

// The "optimization" of `prstar simplify --json`.
py::dict optimization_dict(const PSO::Simplification_statistics::Optimization& o) {
  py::dict d;
  d["vertex_moves"] = o.vertex_moves;
  d["flips_2_3"] = o.flips_2_3;
  d["flips_3_2"] = o.flips_3_2;
  d["flips_4_4"] = o.flips_4_4;
  d["edge_removals"] = o.edge_removals;
  d["splits"] = o.splits;
  d["tetrahedra_added"] = o.tetrahedra_added;
  d["tetrahedra_deleted"] = o.tetrahedra_deleted;
  d["rounds"] = o.rounds;
  d["refused_moves"] = blocked_dict(o.refused_moves);
  d["refused_flips"] = blocked_dict(o.refused_flips);
  d["refused_splits"] = blocked_dict(o.refused_splits);
  return d;
}

py::dict edges_dict(const PSO::Edge_length_quality& e) {
  py::dict d;
  d["edges"] = e.edges;
  d["share_in_range"] = e.share_in_range();
  d["share_short"] = e.share_short();
  d["share_long"] = e.share_long();
  d["median_ratio"] = e.median_ratio;
  return d;
}

py::dict quality_dict(const PSO::Mesh_quality& q) {
  py::dict d;
  d["min_dihedral"] = q.min_dihedral_angle;
  d["max_dihedral"] = q.max_dihedral_angle;
  d["min_radius_ratio"] = q.min_radius_ratio;
  d["share_under_5"] = q.share_under_5();
  d["share_under_10"] = q.share_under_10();
  return d;
}

// The diagonal of the bounding box of all the input points, as the CLI computes it (the same
// arithmetic, so the same double).
template <class Input>
double diagonal(const Input& input) {
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (std::size_t v = 0; v < input.number_of_vertices(); ++v) {
    const Point_3 p = input.point(v);
    for (int i = 0; i < 3; ++i) {
      lo[i] = v == 0 ? p[i] : (std::min)(lo[i], p[i]);
      hi[i] = v == 0 ? p[i] : (std::max)(hi[i], p[i]);
    }
  }
  const double dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// The error bound as the CLI computes it: a distance, or a percentage of the diagonal.
template <class Input>
double error_bound(const Input& input, const Simplify_options& s) {
  return s.error_relative ? s.max_error / 100 * diagonal(input) : s.max_error;
}

// The input as the vectors the library's measures take (a copy for as long as they run).
template <class Input>
std::pair<std::vector<Point_3>, std::vector<std::array<std::size_t, 4>>> input_arrays(const Input& input) {
  std::vector<Point_3> points(input.number_of_vertices());
  for (std::size_t v = 0; v < points.size(); ++v) points[v] = input.point(v);
  std::vector<std::array<std::size_t, 4>> tets(input.number_of_tetrahedra());
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const auto c = input.tetrahedron(t);
    for (int k = 0; k < 4; ++k) tets[t][k] = static_cast<std::size_t>(c[k]);
  }
  return {std::move(points), std::move(tets)};
}

// The library's refusals of the input become InvalidMeshError; its option checks (which the Python
// side makes first, naming the arguments) stay ValueError.
[[noreturn]] void rethrow_invalid(const std::invalid_argument& e, const char* prefix) {
  if (std::string(e.what()).rfind(prefix, 0) == 0) throw e;
  throw Invalid_mesh(e.what());
}

// The arrays of a result: mesh, labels, the library's point data, where each element comes from.
template <class Result>
void result_arrays(py::dict& d, Result& res) {
  d["points"] = points_to_numpy(std::move(res.mesh.points));
  d["tetrahedra"] = tetrahedra_to_numpy(std::move(res.mesh.tetrahedra));
  d["labels"] = res.mesh.tetrahedron_labels.empty()
                    ? py::object(py::none())
                    : py::object(to_numpy(std::move(res.mesh.tetrahedron_labels)));
  py::dict point_data; // the scalar field of an Octree built with one ("scalar", as the library names it)
  for (auto& a : res.mesh.point_data) point_data[py::str(a.name)] = to_numpy(std::move(a.values));
  d["point_data"] = point_data;
  std::vector<std::int64_t> iv(res.input_vertex.begin(), res.input_vertex.end());
  std::vector<std::int64_t> it(res.input_tetrahedron.begin(), res.input_tetrahedron.end());
  d["input_vertex"] = to_numpy(std::move(iv));
  d["input_tetrahedron"] = to_numpy(std::move(it));
}

// The k_v the rounds' octrees use by default when the input is an Octree: its own, or "auto" again
// when it chose its own (each round's octree then chooses, as from arrays).
std::size_t octree_bucket_size(const Octree& tree) {
  return tree.has_automatic_bucket_size() ? Octree::automatic_bucket_size : tree.bucket_size();
}

py::object kv_value(std::size_t kv) {
  if (kv == Octree::infinite_bucket_size) return py::float_(std::numeric_limits<double>::infinity());
  if (kv == Octree::automatic_bucket_size) return py::str("auto"); // as the tool's JSON: chosen per round
  return py::int_(kv);
}

py::dict boundary_error_dict(double bound, const PSO::Boundary_distance& distance) {
  py::dict error;
  error["bound"] = bound;
  error["input_to_output"] = distance.input_to_output;
  error["output_to_input"] = distance.output_to_input;
  error["relative"] = distance.relative();
  return error;
}

template <class Input>
py::dict run_simplify(const Input& input, const Simplify_options& s, std::size_t threads,
                      py::object progress) {
  const Progress p(std::move(progress));
  Progress_visitor visitor;
  visitor.progress = &p;
  const std::size_t m = input.number_of_tetrahedra();
  visitor.total =
      s.target_fraction > 0 ? static_cast<std::size_t>(std::ceil(s.target_fraction * double(m))) : m;
  visitor.input = m;
  PSO::Simplification_result<Point_3> res;
  PSO::Mesh_quality q_in, q_out;
  PSO::Boundary_distance distance;
  {
    Compute_scope scope(threads);
    const double bound = error_bound(input, s);
    try {
      res = PSO::simplify(input, params::target_fraction(s.target_fraction)
                                     .max_edge_length(s.max_edge_length)
                                     .bucket_size(s.bucket_size)
                                     .min_dihedral_angle(s.min_dihedral)
                                     .max_dihedral_angle(s.max_dihedral)
                                     .min_radius_ratio(s.min_radius_ratio)
                                     .optimization_rounds(s.optimization_rounds)
                                     .feature_angle(s.feature_angle)
                                     .max_boundary_error(bound)
                                     .collapse_priority(s.quadric ? PSO::Collapse_priority::QUADRIC_ERROR
                                                                  : PSO::Collapse_priority::EDGE_LENGTH)
                                     .collapse_placement(s.optimal ? PSO::Collapse_placement::OPTIMAL
                                                                   : PSO::Collapse_placement::HALF_EDGE)
                                     .visitor(std::ref(visitor)));
    } catch (const std::invalid_argument& e) {
      rethrow_invalid(e, "simplify: ");
    }
    if (res.statistics.stop == PSO::Simplification_stop::TARGET_REACHED) visitor.report(visitor.total);
    // The measures of `prstar simplify`
    const auto [points, tets] = input_arrays(input);
    q_in = PSO::mesh_quality(points, tets);
    q_out = PSO::mesh_quality(res.mesh.points, res.mesh.tetrahedra);
    distance = PSO::boundary_distance(points, tets, res.mesh.points, res.mesh.tetrahedra, 0.);
  }
  const auto& st = res.statistics;
  py::dict stats; // the keys of `prstar simplify --json` (but "output"), in its order
  stats["input_tetrahedra"] = st.input_tetrahedra;
  stats["output_tetrahedra"] = st.output_tetrahedra;
  // collapses and flips together, as the CLI reports it (the library's count is the collapses' only)
  stats["removed_tetrahedra"] = st.input_tetrahedra - (std::min)(st.output_tetrahedra, st.input_tetrahedra);
  stats["input_vertices"] = st.input_vertices;
  stats["output_vertices"] = st.output_vertices;
  stats["kv"] = kv_value(s.bucket_size);
  stats["rounds"] = st.rounds;
  stats["max_queue"] = st.max_queue_size;
  stats["seconds"] = st.seconds;
  stats["stop"] = PSO::simplification_stop_name(st.stop);
  stats["blocked"] = blocked_dict(st.blocked);
  stats["blocked_last_round"] = blocked_dict(st.blocked_last_round);
  stats["optimization"] = optimization_dict(st.optimization);
  stats["input_quality"] = quality_dict(q_in);
  stats["output_quality"] = quality_dict(q_out);
  stats["boundary_error"] = boundary_error_dict(st.max_boundary_error, distance);
  py::dict d;
  d["statistics"] = stats;
  result_arrays(d, res);
  return d;
}

py::dict simplify(py::object source, py::object tetrahedra, py::object labels, double target_fraction,
                  double max_edge_length, double min_dihedral, double max_dihedral, double min_radius_ratio,
                  std::size_t optimization_rounds, double feature_angle, double max_error,
                  bool error_relative, bool quadric, bool optimal, py::handle bucket_size, py::handle threads,
                  py::object progress) {
  Simplify_options s;
  s.target_fraction = target_fraction;
  s.max_edge_length = max_edge_length;
  s.min_dihedral = min_dihedral;
  s.max_dihedral = max_dihedral;
  s.min_radius_ratio = min_radius_ratio;
  s.optimization_rounds = optimization_rounds;
  s.feature_angle = feature_angle;
  s.max_error = max_error;
  s.error_relative = error_relative;
  s.quadric = quadric;
  s.optimal = optimal;
  if (py::isinstance<Py_octree>(source)) {
    Py_octree& o = source.cast<Py_octree&>();
    s.bucket_size = bucket_size.is_none() ? octree_bucket_size(o.get()) : bucket_size_argument(bucket_size);
    const std::size_t n = threads.is_none() ? o.threads : thread_count(threads);
    const Octree_input input(o);
    return run_simplify(input, s, n, std::move(progress));
  }
  s.bucket_size = bucket_size.is_none() ? Octree::automatic_bucket_size : bucket_size_argument(bucket_size);
  const Numpy_input input(source, tetrahedra, labels);
  return run_simplify(input, s, thread_count(threads), std::move(progress));
}

// ---------------------------------------------------------------------------------------------
// remesh
// ---------------------------------------------------------------------------------------------

// `sizing`: the target at each input vertex (user's numbering), already checked by the Python side,
// or empty for the uniform target of `s`.  `field_name`: the statistics' "size_field".
template <class Input>
py::dict run_remesh(const Input& input, const Simplify_options& s, std::vector<double> sizing,
                    py::object field_name, std::size_t threads) {
  if (!sizing.empty() && sizing.size() != input.number_of_vertices())
    throw std::invalid_argument("remesh: the size field has " + std::to_string(sizing.size()) +
                                " values for " + std::to_string(input.number_of_vertices()) + " vertices");
  PSO::Simplification_result<Point_3> res;
  PSO::Mesh_quality q_in, q_out;
  PSO::Edge_length_quality e_in, e_out;
  PSO::Boundary_distance distance;
  double h = 0;
  {
    Compute_scope scope(threads);
    const double d = diagonal(input);
    const double bound = s.error_relative ? s.max_error / 100 * d : s.max_error;
    h = s.edge_length_relative ? s.edge_length / 100 * d : s.edge_length;
    if (sizing.empty() && !(h > 0))
      throw std::invalid_argument("remesh: edge_length " + std::to_string(s.edge_length) +
                                  "% is 0: the mesh has no extent");
    // (the package's parameters first: CGAL's number_of_iterations ends the chain)
    const auto np = params::bucket_size(s.bucket_size)
                        .min_dihedral_angle(s.min_dihedral)
                        .max_dihedral_angle(s.max_dihedral)
                        .min_radius_ratio(s.min_radius_ratio)
                        .feature_angle(s.feature_angle)
                        .max_boundary_error(bound)
                        .number_of_iterations(s.iterations);
    try {
      res = sizing.empty() ? PSO::remesh(input, h, np)
                           : PSO::remesh(input, CGAL::make_property_map(sizing), np);
    } catch (const std::invalid_argument& e) {
      rethrow_invalid(e, "remesh: ");
    }
    // The measures of `prstar remesh`: on the output, the size field as it is carried (each vertex
    // the value of the input vertex it stands for).
    const auto [points, tets] = input_arrays(input);
    q_in = PSO::mesh_quality(points, tets);
    q_out = PSO::mesh_quality(res.mesh.points, res.mesh.tetrahedra);
    if (sizing.empty()) {
      e_in = PSO::edge_length_quality(points, tets, h);
      e_out = PSO::edge_length_quality(res.mesh.points, res.mesh.tetrahedra, h);
    } else {
      std::vector<double> carried(res.input_vertex.size());
      for (std::size_t v = 0; v < carried.size(); ++v) carried[v] = sizing[res.input_vertex[v]];
      e_in = PSO::edge_length_quality(points, tets, sizing);
      e_out = PSO::edge_length_quality(res.mesh.points, res.mesh.tetrahedra, carried);
    }
    distance = PSO::boundary_distance(points, tets, res.mesh.points, res.mesh.tetrahedra, 0.);
  }
  const auto& st = res.statistics;
  const auto& opt = st.optimization;
  py::dict stats; // the keys of `prstar remesh --json` (but "output"), in its order
  stats["input_tetrahedra"] = st.input_tetrahedra;
  stats["output_tetrahedra"] = st.output_tetrahedra;
  stats["input_vertices"] = st.input_vertices;
  stats["output_vertices"] = st.output_vertices;
  stats["edge_length"] = sizing.empty() ? py::object(py::float_(h)) : py::object(py::none());
  stats["size_field"] = field_name;
  stats["kv"] = kv_value(s.bucket_size);
  stats["iterations"] = s.iterations;
  stats["rounds"] = st.rounds;
  stats["seconds"] = st.seconds;
  py::dict operations;
  operations["vertex_moves"] = opt.vertex_moves;
  operations["flips_2_3"] = opt.flips_2_3;
  operations["flips_3_2"] = opt.flips_3_2;
  operations["flips_4_4"] = opt.flips_4_4;
  operations["edge_removals"] = opt.edge_removals;
  operations["splits"] = opt.splits;
  operations["tetrahedra_added"] = opt.tetrahedra_added;
  operations["tetrahedra_deleted"] = opt.tetrahedra_deleted;
  operations["collapses"] = st.collapses;
  stats["operations"] = operations;
  py::dict refused;
  refused["collapses"] = blocked_dict(st.blocked);
  refused["splits"] = blocked_dict(opt.refused_splits);
  refused["flips"] = blocked_dict(opt.refused_flips);
  refused["moves"] = blocked_dict(opt.refused_moves);
  stats["refused"] = refused;
  stats["input_quality"] = quality_dict(q_in);
  stats["output_quality"] = quality_dict(q_out);
  stats["input_edges"] = edges_dict(e_in);
  stats["output_edges"] = edges_dict(e_out);
  stats["boundary_error"] = boundary_error_dict(st.max_boundary_error, distance);
  py::dict d;
  d["statistics"] = stats;
  result_arrays(d, res);
  return d;
}

py::dict remesh(py::object source, py::object tetrahedra, py::object labels, double edge_length,
                bool edge_length_relative,
                py::array_t<double, py::array::c_style | py::array::forcecast> sizing_array,
                py::object field_name, std::size_t iterations, double min_dihedral, double max_dihedral,
                double min_radius_ratio, double feature_angle, double max_error, bool error_relative,
                py::handle bucket_size, py::handle threads) {
  std::vector<double> sizing(sizing_array.data(), sizing_array.data() + sizing_array.size());
  Simplify_options s;
  s.edge_length = edge_length;
  s.edge_length_relative = edge_length_relative;
  s.iterations = iterations;
  s.min_dihedral = min_dihedral;
  s.max_dihedral = max_dihedral;
  s.min_radius_ratio = min_radius_ratio;
  s.feature_angle = feature_angle;
  s.max_error = max_error;
  s.error_relative = error_relative;
  if (py::isinstance<Py_octree>(source)) {
    Py_octree& o = source.cast<Py_octree&>();
    s.bucket_size = bucket_size.is_none() ? octree_bucket_size(o.get()) : bucket_size_argument(bucket_size);
    const std::size_t n = threads.is_none() ? o.threads : thread_count(threads);
    const Octree_input input(o);
    return run_remesh(input, s, std::move(sizing), std::move(field_name), n);
  }
  s.bucket_size = bucket_size.is_none() ? Octree::automatic_bucket_size : bucket_size_argument(bucket_size);
  const Numpy_input input(source, tetrahedra, labels);
  return run_remesh(input, s, std::move(sizing), std::move(field_name), thread_count(threads));
}

} // namespace

void bind_simplification(py::module_& m) {
  m.def("_validate", &validate, py::arg("octree"), py::arg("progress") = py::none(),
        "check_validity on an Octree: the counts of `prstar validate --json` and the problems by kind (user "
        "numbering).");
  m.def(
      "_simplify", &simplify, py::arg("source"), py::arg("tetrahedra"), py::arg("labels"), py::kw_only(),
      py::arg("target_fraction"), py::arg("max_edge_length"), py::arg("min_dihedral"),
      py::arg("max_dihedral"), py::arg("min_radius_ratio"), py::arg("optimization_rounds"),
      py::arg("feature_angle"), py::arg("max_error"), py::arg("error_relative"), py::arg("quadric"),
      py::arg("optimal"), py::arg("bucket_size"), py::arg("threads"), py::arg("progress"),
      "simplify() on numpy arrays (read in place) or on an Octree (its arrays in the user's numbering); the "
      "options checked by prstar._simplification.");
  m.def(
      "_remesh", &remesh, py::arg("source"), py::arg("tetrahedra"), py::arg("labels"), py::kw_only(),
      py::arg("edge_length"), py::arg("edge_length_relative"), py::arg("sizing"), py::arg("size_field"),
      py::arg("iterations"), py::arg("min_dihedral"), py::arg("max_dihedral"), py::arg("min_radius_ratio"),
      py::arg("feature_angle"), py::arg("max_error"), py::arg("error_relative"), py::arg("bucket_size"),
      py::arg("threads"),
      "remesh() on numpy arrays (read in place) or on an Octree (its arrays in the user's numbering); "
      "`sizing`: the target per vertex (empty: edge_length); the options checked by prstar._simplification.");
}

} // namespace prstar_python
