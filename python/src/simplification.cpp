// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Validation and simplification for the Python module: `_validate` (check_validity on an Octree, the
// problems grouped by kind as arrays in the user's numbering) and `_simplify` (simplify() on numpy
// arrays read in place, or on an Octree seen in the user's numbering, with the statistics, the
// quality and the boundary distance that `prstar simplify --json` reports).  The option checks and
// their messages are in python/prstar/_simplification.py; the library checks them again.

#include "prstar_python.h"

#include <CGAL/PR_star_octree/mesh_quality.h>
#include <CGAL/PR_star_octree/simplification.h>
#include <CGAL/PR_star_octree/validity.h>

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
  const Point_3& point(std::size_t i) const { return tree_.point(vertex_[i]); }
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

// The options of `prstar simplify`, already checked by the Python side (the library checks again).
struct Simplify_options {
  double target_fraction = 0, max_edge_length = std::numeric_limits<double>::infinity();
  bool radius_ratio = false;
  double floor = 5, feature_angle = 40;
  double max_error = 0.2; // percent of the diagonal when `error_relative`
  bool error_relative = true;
  bool quadric = false, optimal = false;
  std::size_t bucket_size = 50;
};

// The progress of a simplification (simplify() has no progress parameter; its visitor is told of
// every collapse and round): `progress(removed, to_remove)`, the tetrahedra removed by the rounds
// finished, at each round's end (the last call: `removed == to_remove` when the target is reached)
// and, throttled, during a round (so that Ctrl-C and an exception of the callable stop a long round).
struct Progress_visitor : PSO::Simplification_visitor_base {
  const Progress* progress = nullptr;
  std::size_t removed = 0, total = 0;
  template <class CollapseProfile>
  void on_collapse(const CollapseProfile&) {
    (*progress)(removed, total);
  }
  void on_round_finished(std::size_t, std::size_t n) {
    removed += n;
    (*progress)((std::min)(removed, total), total);
  }
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

py::dict quality_dict(const PSO::Mesh_quality& q) {
  py::dict d;
  d["min_dihedral"] = q.min_dihedral_angle;
  d["max_dihedral"] = q.max_dihedral_angle;
  d["min_radius_ratio"] = q.min_radius_ratio;
  d["share_under_5"] = q.share_under_5();
  d["share_under_10"] = q.share_under_10();
  return d;
}

// The error bound as the CLI computes it: a distance, or a percentage of the diagonal of the
// bounding box of all the input points (the same arithmetic, so the same double).
template <class Input>
double error_bound(const Input& input, const Simplify_options& s) {
  if (!s.error_relative) return s.max_error;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (std::size_t v = 0; v < input.number_of_vertices(); ++v) {
    const Point_3 p = input.point(v);
    for (int i = 0; i < 3; ++i) {
      lo[i] = v == 0 ? p[i] : (std::min)(lo[i], p[i]);
      hi[i] = v == 0 ? p[i] : (std::max)(hi[i], p[i]);
    }
  }
  const double dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
  return s.max_error / 100 * std::sqrt(dx * dx + dy * dy + dz * dz);
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
  PSO::Simplification_result<Point_3> res;
  PSO::Mesh_quality q_in, q_out;
  PSO::Boundary_distance distance;
  {
    Compute_scope scope(threads);
    const double bound = error_bound(input, s);
    try {
      res =
          PSO::simplify(input, params::target_fraction(s.target_fraction)
                                   .max_edge_length(s.max_edge_length)
                                   .bucket_size(s.bucket_size)
                                   .quality_measure(s.radius_ratio ? PSO::Quality_measure::RADIUS_RATIO
                                                                   : PSO::Quality_measure::MIN_DIHEDRAL_ANGLE)
                                   .quality_floor(s.floor)
                                   .feature_angle(s.feature_angle)
                                   .max_boundary_error(bound)
                                   .collapse_priority(s.quadric ? PSO::Collapse_priority::QUADRIC_ERROR
                                                                : PSO::Collapse_priority::EDGE_LENGTH)
                                   .collapse_placement(s.optimal ? PSO::Collapse_placement::OPTIMAL
                                                                 : PSO::Collapse_placement::HALF_EDGE)
                                   .visitor(std::ref(visitor)));
    } catch (const std::invalid_argument& e) {
      // The octree's refusals of the input are InvalidMeshError; the library's option checks (which
      // the Python side makes first, naming the arguments) stay ValueError.
      if (std::string(e.what()).rfind("simplify: ", 0) == 0) throw;
      throw Invalid_mesh(e.what());
    }
    // The measures of `prstar simplify`: they need the input as vectors (the library's measures take
    // std::vector<Point_3>): a copy for as long as they run.
    std::vector<Point_3> points(input.number_of_vertices());
    for (std::size_t v = 0; v < points.size(); ++v) points[v] = input.point(v);
    std::vector<std::array<std::size_t, 4>> tets(m);
    for (std::size_t t = 0; t < m; ++t) {
      const auto c = input.tetrahedron(t);
      for (int k = 0; k < 4; ++k) tets[t][k] = static_cast<std::size_t>(c[k]);
    }
    q_in = PSO::mesh_quality(points, tets);
    q_out = PSO::mesh_quality(res.mesh.points, res.mesh.tetrahedra);
    distance = PSO::boundary_distance(points, tets, res.mesh.points, res.mesh.tetrahedra, 0.);
  }
  const auto& st = res.statistics;
  py::dict stats; // the keys of `prstar simplify --json` (but "output"), in its order
  stats["input_tetrahedra"] = st.input_tetrahedra;
  stats["output_tetrahedra"] = st.output_tetrahedra;
  stats["removed_tetrahedra"] = st.removed_tetrahedra;
  stats["input_vertices"] = st.input_vertices;
  stats["output_vertices"] = st.output_vertices;
  if (s.bucket_size == Octree::infinite_bucket_size)
    stats["kv"] = std::numeric_limits<double>::infinity();
  else
    stats["kv"] = s.bucket_size;
  stats["rounds"] = st.rounds;
  stats["max_queue"] = st.max_queue_size;
  stats["seconds"] = st.seconds;
  stats["stop"] = PSO::simplification_stop_name(st.stop);
  stats["blocked"] = blocked_dict(st.blocked);
  stats["blocked_last_round"] = blocked_dict(st.blocked_last_round);
  stats["input_quality"] = quality_dict(q_in);
  stats["output_quality"] = quality_dict(q_out);
  py::dict error;
  error["bound"] = st.max_boundary_error;
  error["input_to_output"] = distance.input_to_output;
  error["output_to_input"] = distance.output_to_input;
  error["relative"] = distance.relative();
  stats["boundary_error"] = error;
  py::dict d;
  d["statistics"] = stats;
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
  return d;
}

py::dict simplify(py::object source, py::object tetrahedra, py::object labels, double target_fraction,
                  double max_edge_length, bool radius_ratio, double floor, double feature_angle,
                  double max_error, bool error_relative, bool quadric, bool optimal, py::handle bucket_size,
                  py::handle threads, py::object progress) {
  Simplify_options s;
  s.target_fraction = target_fraction;
  s.max_edge_length = max_edge_length;
  s.radius_ratio = radius_ratio;
  s.floor = floor;
  s.feature_angle = feature_angle;
  s.max_error = max_error;
  s.error_relative = error_relative;
  s.quadric = quadric;
  s.optimal = optimal;
  if (py::isinstance<Py_octree>(source)) {
    Py_octree& o = source.cast<Py_octree&>();
    s.bucket_size = bucket_size.is_none() ? o.get().bucket_size() : bucket_size_argument(bucket_size);
    const std::size_t n = threads.is_none() ? o.threads : thread_count(threads);
    const Octree_input input(o);
    return run_simplify(input, s, n, std::move(progress));
  }
  s.bucket_size = bucket_size.is_none() ? std::size_t(50) : bucket_size_argument(bucket_size);
  const Numpy_input input(source, tetrahedra, labels);
  return run_simplify(input, s, thread_count(threads), std::move(progress));
}

} // namespace

void bind_simplification(py::module_& m) {
  m.def("_validate", &validate, py::arg("octree"), py::arg("progress") = py::none(),
        "check_validity on an Octree: the counts of `prstar validate --json` and the problems by kind (user "
        "numbering).");
  m.def(
      "_simplify", &simplify, py::arg("source"), py::arg("tetrahedra"), py::arg("labels"), py::kw_only(),
      py::arg("target_fraction"), py::arg("max_edge_length"), py::arg("radius_ratio"), py::arg("floor"),
      py::arg("feature_angle"), py::arg("max_error"), py::arg("error_relative"), py::arg("quadric"),
      py::arg("optimal"), py::arg("bucket_size"), py::arg("threads"), py::arg("progress"),
      "simplify() on numpy arrays (read in place) or on an Octree (its arrays in the user's numbering); the "
      "options checked by prstar._simplification.");
}

} // namespace prstar_python
