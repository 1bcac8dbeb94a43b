// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Table 3 of the paper: the local half-edge-collapse simplification on PR-star octrees with
// several bucket thresholds k_v, against the global algorithm (k_v = infinity, one leaf), for
// targets of 25%, 50% and 75% of the tetrahedra removed: tetrahedra removed (and % of the global
// run), seconds (and % of the global run), the largest edge queue (the paper's memory proxy), the
// peak RSS growth, the rounds and the candidates blocked by each condition.
//
// Then, for every run, what the output is worth (mesh_quality.h, computed after the run and outside
// its time and peak memory): the smallest dihedral angle and the shares of tetrahedra under 5 and 10
// degrees, the two-sided (sampled) Hausdorff distance between the boundary surfaces and the distance
// between their sharp edges (40 degrees), relative to the diagonal of the input's bounding box.  Side
// by side, CGAL's tetrahedral_isotropic_remeshing on the same input (the tetrahedron soup made into a
// Remeshing_triangulation_3 by CGAL's build_triangulation, the input's sharp edges at 40 degrees as
// constrained edges), with a target edge length chosen to give about the same output size: the mean
// edge length of the input times (N_in / N_out)^(1/3), N_out the output of the global PR-star run.
//
// --side-by-side (issue 22): per mesh, in one run, (a) CGAL's tetrahedral_isotropic_remeshing
// (3 iterations) at a target edge length h (the input's mean edge length x (1 / F)^(1/3), F =
// --fraction, or --edge-length), (b) the package's simplify() with its defaults to CGAL's output size,
// (c) its remesh() at the same h.  For each output: time, CPU time, the other processes' load, peak
// RSS, and the ratios to CGAL's; the quality histograms (the six dihedral angles of every tetrahedron
// in 5-degree bins, the smallest one, the radius ratio in 0.05 bins; --csv writes them to
// OUT_histograms.csv), the smallest and largest dihedral angles, the share under 10 degrees, the
// smallest radius ratio, the share of edges within [0.8h, 1.33h], the two-sided Hausdorff distance of
// the boundaries (with and without the label interfaces), the largest relative volume change of a
// label, and the tetrahedra that are not positive by the exact Orientation_3; then the issue's
// targets, met or not.
//
// Each run is done in a child process (fork) whose peak RSS counter is reset first
// (/proc/self/clear_refs "5"), so that VmHWM measures that run alone.  Times are the minimum over
// --reps repetitions inside the child (default 1: the algorithm is deterministic).
//
// usage: bench_simplification [--kv 20,50,...,inf] [--targets 0.25,0.5,0.75] [--reps R]
//                             [--no-cgal] [--cgal-iterations N] [--csv OUT.csv] MESH...
//        bench_simplification --side-by-side [--fraction F | --edge-length H1,H2,...]
//                             [--cgal-iterations N] [--optimize R1,R2,...|default]
//                             [--remesh-iterations N] [--no-remesh] [--kv K] [--threads T]
//                             [--output-dir DIR] [--csv OUT.csv] MESH...
// Markdown on stdout.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/mesh_quality.h>
#include <CGAL/PR_star_octree/remeshing.h>
#include <CGAL/PR_star_octree/simplification.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_3/tet_soup_to_c3t3.h>
#include <CGAL/Tetrahedral_remeshing/Remeshing_triangulation_3.h>
#include <CGAL/tetrahedral_remeshing.h>

#include "bench_util.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <sys/resource.h>

#include <array>
#include <cmath>
#include <map>
#include <set>
#include <unordered_map>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;
using Octree = CGAL::PR_star_octree_3<>;
namespace P = CGAL::PR_star_octree;

constexpr std::size_t inf = Octree::infinite_bucket_size;

// What an output mesh is worth, against the input (plain data: it crosses a pipe).
struct Output_measures {
  std::size_t vertices = 0, tetrahedra = 0;
  double min_dihedral = 0, max_dihedral = 0, min_radius_ratio = 0, share_under_5 = 0, share_under_10 = 0;
  std::size_t under_5 = 0, under_10 = 0;
  double boundary_in_out = 0, boundary_out_in = 0; // relative to the input's diagonal
  double sharp_in_out = 0, sharp_out_in = 0;       // relative to the input's diagonal
  std::size_t sharp_in = 0, sharp_out = 0;
  double seconds = 0; // to measure all this
};

template <class Points, class Tets>
Output_measures measure(const Mesh& in, const Points& points, const Tets& tets) {
  const double t0 = prstar_bench::now();
  Output_measures m;
  m.vertices = points.size();
  m.tetrahedra = tets.size();
  const P::Mesh_quality q = P::mesh_quality(points, tets);
  m.min_dihedral = q.min_dihedral_angle;
  m.max_dihedral = q.max_dihedral_angle;
  m.min_radius_ratio = q.min_radius_ratio;
  m.share_under_5 = q.share_under_5();
  m.share_under_10 = q.share_under_10();
  m.under_5 = q.under_5_degrees;
  m.under_10 = q.under_10_degrees;
  const P::Boundary_distance b = P::boundary_distance(in.points, in.tetrahedra, points, tets);
  m.boundary_in_out = b.diagonal > 0 ? b.input_to_output / b.diagonal : 0;
  m.boundary_out_in = b.diagonal > 0 ? b.output_to_input / b.diagonal : 0;
  const P::Sharp_edge_distance e = P::sharp_edge_distance(in.points, in.tetrahedra, points, tets, 40.);
  m.sharp_in_out = b.diagonal > 0 ? e.input_to_output / b.diagonal : 0;
  m.sharp_out_in = b.diagonal > 0 ? e.output_to_input / b.diagonal : 0;
  m.sharp_in = e.input_sharp_edges;
  m.sharp_out = e.output_sharp_edges;
  m.seconds = prstar_bench::now() - t0;
  return m;
}

// What one child process measures (plain data: it comes back through a pipe).
struct Result {
  bool ok = false;
  std::size_t removed = 0, first_round = 0, output_tetrahedra = 0, rounds = 0, max_queue = 0,
              peak_rss_bytes = 0;
  std::size_t run_peak_rss_bytes = 0; // the growth of VmHWM during the run only (not the measures)
  std::size_t blocked_leaves = 0, blocked_boundary = 0, blocked_flip = 0, blocked_link = 0;
  std::size_t blocked_feature = 0, blocked_quality = 0, blocked_error = 0;
  int stop = 0;
  double seconds = 0;
  Output_measures out;
};

Result run_in_child(const Mesh& mesh, std::size_t kv, double target, int reps) {
  return prstar_bench::in_child<Result>([&] {
    Result r;
    const std::size_t base = prstar_bench::status_kib("VmRSS:");
    r.seconds = std::numeric_limits<double>::infinity();
    for (int i = 0; i < reps; ++i) {
      const auto res = P::simplify(mesh, P::parameters::target_fraction(target).bucket_size(kv));
      const auto& s = res.statistics;
      r.seconds = std::min(r.seconds, s.seconds);
      r.removed = s.removed_tetrahedra;
      r.first_round = s.removed_per_round.empty() ? 0 : s.removed_per_round.front();
      r.output_tetrahedra = s.output_tetrahedra;
      r.rounds = s.rounds;
      r.max_queue = s.max_queue_size;
      r.blocked_leaves = s.blocked.different_leaves;
      r.blocked_boundary = s.blocked.boundary;
      r.blocked_flip = s.blocked.flip;
      r.blocked_link = s.blocked.link;
      r.blocked_feature = s.blocked.feature;
      r.blocked_quality = s.blocked.quality;
      r.blocked_error = s.blocked.error;
      r.stop = static_cast<int>(s.stop);
      if (i + 1 == reps) {
        r.run_peak_rss_bytes = (prstar_bench::status_kib("VmHWM:") - base) * 1024;
        r.out = measure(mesh, res.mesh.points, res.mesh.tetrahedra);
      }
    }
    return r;
  });
}

// --- CGAL's tetrahedral_isotropic_remeshing on the same input ---

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Remeshing_tr = CGAL::Tetrahedral_remeshing::Remeshing_triangulation_3<Kernel>;
using Vertex_pair = std::pair<Remeshing_tr::Vertex_handle, Remeshing_tr::Vertex_handle>;

// The constrained edges given to CGAL (read and written by the remeshing: edges are split and
// collapsed), keyed by ordered pairs of vertex handles.
struct Constrained_edges {
  using key_type = Vertex_pair;
  using value_type = bool;
  using reference = bool;
  using category = boost::read_write_property_map_tag;
  std::set<Vertex_pair>* edges = nullptr;
  friend bool get(const Constrained_edges& m, const Vertex_pair& e) { return m.edges->count(e) > 0; }
  friend void put(Constrained_edges& m, const Vertex_pair& e, bool constrained) {
    if (constrained)
      m.edges->insert(e);
    else
      m.edges->erase(e);
  }
};

struct Cgal_result {
  bool ok = false;
  std::size_t peak_rss_bytes = 0, run_peak_rss_bytes = 0, constrained_edges = 0;
  double edge_length = 0, seconds_build = 0, seconds_remesh = 0;
  double first_edge_length = 0;     // when the length was corrected: the first one tried,
  std::size_t first_tetrahedra = 0; // and the output size it gave
  Output_measures out;
  char error[200] = {}; // why CGAL could not run (then ok is false)
};

// The output of CGAL's remeshing as index arrays, with what it cost.
struct Cgal_output {
  std::vector<Kernel::Point_3> points;
  std::vector<std::array<std::uint32_t, 4>> tetrahedra;
  std::vector<int> labels; // the input's labels (empty when the input has none)
  std::size_t constrained_edges = 0, run_peak_rss_bytes = 0;
  double seconds_build = 0, seconds_remesh = 0;
};

// CGAL's tetrahedral_isotropic_remeshing of `mesh` at `edge_length`: the soup, positively oriented,
// made into a Remeshing_triangulation_3 by build_triangulation, with the sharp edges (40 degrees) of
// the boundary and of the label interfaces as constrained edges (CGAL keeps the interfaces between
// subdomains but not the creases inside one interface, like the rims of a cylinder in a box).
// `run_peak_rss_bytes` is the growth of VmHWM from the call to the end of the remeshing; the
// validity check of the built triangulation (which CGAL asserts) is left out of the time.
Cgal_output cgal_remesh(const Mesh& mesh, double edge_length, int iterations) {
  Cgal_output r;
  const std::size_t base = prstar_bench::status_kib("VmRSS:");
  const double t0 = prstar_bench::now();
  // The subdomain of a tetrahedron is the rank of its label among the input's labels, plus one (a
  // subdomain index 0 means "outside" to CGAL); the label comes back through the same table.
  std::vector<int> label_of_subdomain{0};
  if (!mesh.tetrahedron_labels.empty()) {
    std::vector<int> l = mesh.tetrahedron_labels;
    std::sort(l.begin(), l.end());
    l.erase(std::unique(l.begin(), l.end()), l.end());
    label_of_subdomain.insert(label_of_subdomain.end(), l.begin(), l.end());
  }
  auto subdomain = [&](std::size_t t) {
    if (mesh.tetrahedron_labels.empty()) return 1;
    return int(std::lower_bound(label_of_subdomain.begin() + 1, label_of_subdomain.end(),
                                mesh.tetrahedron_labels[t]) -
               label_of_subdomain.begin());
  };
  // The soup, on the vertices of the tetrahedra only (an unreferenced vertex would be an isolated
  // vertex of the TDS).
  std::vector<int> renumber(mesh.points.size(), -1);
  std::vector<Remeshing_tr::Point> points;
  std::vector<std::array<int, 5>> cells;
  cells.reserve(mesh.tetrahedra.size());
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    std::array<int, 5> c;
    for (int i = 0; i < 4; ++i) {
      int& v = renumber[mesh.tetrahedra[t][i]];
      if (v < 0) {
        v = int(points.size());
        points.push_back(mesh.points[mesh.tetrahedra[t][i]]);
      }
      c[i] = v;
    }
    c[4] = subdomain(t);
    if (CGAL::orientation(points[c[0]], points[c[1]], points[c[2]], points[c[3]]) == CGAL::NEGATIVE)
      std::swap(c[2], c[3]);
    cells.push_back(c);
  }
  Remeshing_tr tr;
  std::vector<Remeshing_tr::Vertex_handle> handles;
  const std::map<std::array<int, 3>, Remeshing_tr::Cell::Surface_patch_index> no_patches;
  if (!CGAL::build_triangulation<Remeshing_tr, true>(tr, points, cells, no_patches, handles, false, true))
    throw std::runtime_error("CGAL's build_triangulation failed");
  // Its input must be a valid triangulation of the sphere once the boundary is coned to the infinite
  // vertex (a boundary of genus 0, connected): checked here, out of the time (CGAL asserts it).
  const double check_start = prstar_bench::now();
  const bool valid = tr.tds().is_valid();
  const double check_seconds = prstar_bench::now() - check_start;
  if (!valid)
    throw std::runtime_error("CGAL: the soup coned to the infinite vertex is not a valid Triangulation_3 "
                             "(a boundary of genus > 0 or of several components?); not remeshed");

  // The sharp edges (40 degrees) of the boundary and of the label interfaces, found by mesh_quality.h,
  // as constraints.
  namespace I = P::internal::mesh_quality_impl;
  std::set<Vertex_pair> constrained;
  const std::vector<int>* labels = mesh.tetrahedron_labels.empty() ? nullptr : &mesh.tetrahedron_labels;
  for (const auto& e :
       I::sharp_edges(I::to_epick(mesh.points), I::boundary_triangles(mesh.tetrahedra, labels), 40.)) {
    // handles[0] is the infinite vertex
    Vertex_pair k(handles[std::size_t(renumber[e[0]]) + 1], handles[std::size_t(renumber[e[1]]) + 1]);
    if (k.second < k.first) std::swap(k.first, k.second);
    constrained.insert(k);
  }
  r.constrained_edges = constrained.size();
  const double t1 = prstar_bench::now();
  r.seconds_build = t1 - t0 - check_seconds;
  CGAL::tetrahedral_isotropic_remeshing(tr, edge_length,
                                        CGAL::parameters::number_of_iterations(iterations)
                                            .edge_is_constrained_map(Constrained_edges{&constrained}));
  r.seconds_remesh = prstar_bench::now() - t1;
  r.run_peak_rss_bytes = (prstar_bench::status_kib("VmHWM:") - base) * 1024;
  // The cells of the domain (non-zero subdomain index) as index arrays.
  std::unordered_map<Remeshing_tr::Vertex_handle, std::uint32_t> index;
  for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) {
    const int s = int(c->subdomain_index());
    if (s == 0) continue;
    std::array<std::uint32_t, 4> t;
    for (int i = 0; i < 4; ++i) {
      const auto it = index.emplace(c->vertex(i), std::uint32_t(r.points.size()));
      if (it.second) r.points.push_back(c->vertex(i)->point());
      t[i] = it.first->second;
    }
    r.tetrahedra.push_back(t);
    if (!mesh.tetrahedron_labels.empty())
      r.labels.push_back(s < int(label_of_subdomain.size()) ? label_of_subdomain[std::size_t(s)] : -s);
  }
  return r;
}

Cgal_result run_cgal_in_child(const Mesh& mesh, double edge_length, int iterations) {
  Cgal_result r = prstar_bench::in_child<Cgal_result>([&] {
    Cgal_result r;
    try {
      r.edge_length = edge_length;
      const Cgal_output c = cgal_remesh(mesh, edge_length, iterations);
      r.constrained_edges = c.constrained_edges;
      r.seconds_build = c.seconds_build;
      r.seconds_remesh = c.seconds_remesh;
      r.run_peak_rss_bytes = c.run_peak_rss_bytes;
      r.out = measure(mesh, c.points, c.tetrahedra);
    } catch (const std::exception& e) {
      std::strncpy(r.error, e.what(), sizeof r.error - 1);
    }
    return r;
  });
  if (r.error[0]) r.ok = false;
  return r;
}

// The mean length of the edges of the mesh (each edge once).
double mean_edge_length(const Mesh& mesh) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(6 * mesh.tetrahedra.size());
  for (const auto& t : mesh.tetrahedra)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) edges.push_back(std::minmax(std::uint32_t(t[i]), std::uint32_t(t[j])));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  double sum = 0;
  for (const auto& e : edges)
    sum += std::sqrt(CGAL::squared_distance(mesh.points[e.first], mesh.points[e.second]));
  return edges.empty() ? 0 : sum / double(edges.size());
}

std::string kv_string(std::size_t kv) {
  return kv == inf ? "inf" : std::to_string(kv);
}

// 68.7 K, 1.49 M, as in the paper
std::string human(double x) {
  std::ostringstream s;
  if (x >= 1e6)
    s << std::fixed << std::setprecision(x >= 1e7 ? 1 : 2) << x / 1e6 << " M";
  else if (x >= 1e3)
    s << std::fixed << std::setprecision(x >= 1e4 ? 1 : 2) << x / 1e3 << " K";
  else
    s << static_cast<long long>(x);
  return s.str();
}

std::string fixed(double x, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << x;
  return s.str();
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> r;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = s.find(',', start);
    r.push_back(s.substr(start, comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return r;
}

std::string cpu_model() {
  std::ifstream f("/proc/cpuinfo");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown CPU";
}

using prstar_bench::base_name;

// ==== Side by side (issue 22): CGAL's remeshing, simplify() to its size, remesh() at its length ====

constexpr int dihedral_bins = 36;     // 5 degrees each, over [0, 180]
constexpr int radius_ratio_bins = 20; // 0.05 each, over [0, 1]

// Everything the side-by-side mode measures on one mesh (plain data: it crosses a pipe).
struct Full_measures {
  Output_measures basic; // counts, dihedral angles, radius ratio, boundary and sharp-edge distances
  std::array<std::uint64_t, dihedral_bins> dihedral{};     // the six dihedral angles of every tetrahedron
  std::array<std::uint64_t, dihedral_bins> min_dihedral{}; // the smallest one of every tetrahedron
  std::array<std::uint64_t, radius_ratio_bins> radius_ratio{};
  std::size_t edges = 0, edges_in_range = 0, edges_short = 0, edges_long = 0; // against h: [0.8h, 1.33h]
  double surface_in_out = 0, surface_out_in = 0; // boundary and label interfaces; relative to the diagonal
  double max_label_volume_change = 0;            // the largest |V_out(l) - V_in(l)| / V_in(l) over labels l
  int worst_label = 0;                           // where it is
  double volume_change = 0;                      // (V_out - V_in) / V_in of the whole mesh
  struct Label_change {
    int label;
    double change; // signed, relative
  };
  std::array<Label_change, 8> label_changes{}; // those of the first 8 labels
  std::size_t negative = 0, flat = 0;          // tetrahedra NEGATIVE / COPLANAR by the exact Orientation_3
  std::size_t labels_out = 0;                  // the labels in the output (its own, new ones included)
};

// What the outputs are compared with, computed once per mesh in the parent (children see it by fork).
struct Reference {
  const Mesh* mesh = nullptr;
  std::map<int, double> label_volumes; // label (0 for an unlabelled mesh) -> volume
  double volume = 0;
  double edge_length = 0; // the target h
};

// 6 x the signed volume of (p, q, r, s): positive when CGAL::orientation says POSITIVE.
inline double six_volume(const P::internal::Vec3& p, const P::internal::Vec3& q, const P::internal::Vec3& r,
                         const P::internal::Vec3& s) {
  using namespace P::internal;
  return dot(minus(q, p), cross(minus(r, p), minus(s, p)));
}

// The volume of each label (of the whole mesh under label 0 when `labels` is empty).  `absolute`: the
// input may list its tetrahedra with either orientation (TetGen's are negative to CGAL); an output
// must be positive, so its volumes are signed and an inverted tetrahedron counts against its label.
template <class Points, class Tets>
std::map<int, double> label_volumes(const Points& points, const Tets& tets, const std::vector<int>& labels,
                                    bool absolute) {
  std::map<int, double> v;
  for (std::size_t t = 0; t < tets.size(); ++t) {
    using P::internal::to_vec3;
    double x = six_volume(to_vec3(points[tets[t][0]]), to_vec3(points[tets[t][1]]),
                          to_vec3(points[tets[t][2]]), to_vec3(points[tets[t][3]])) /
               6;
    if (absolute) x = std::abs(x);
    v[labels.empty() ? 0 : labels[t]] += x;
  }
  return v;
}

// All the measures of an output (`labels`: its tetrahedron labels, empty for none).  `distances`:
// false for the input itself (its distance to itself is 0; the sampling costs seconds).
template <class Points, class Tets>
Full_measures measure_full(const Reference& ref, const Points& points, const Tets& tets,
                           const std::vector<int>& labels, bool distances = true) {
  const Mesh& in = *ref.mesh;
  Full_measures m;
  if (distances)
    m.basic = measure(in, points, tets);
  else {
    const P::Mesh_quality q = P::mesh_quality(points, tets);
    m.basic.vertices = points.size();
    m.basic.tetrahedra = tets.size();
    m.basic.min_dihedral = q.min_dihedral_angle;
    m.basic.max_dihedral = q.max_dihedral_angle;
    m.basic.min_radius_ratio = q.min_radius_ratio;
    m.basic.share_under_5 = q.share_under_5();
    m.basic.share_under_10 = q.share_under_10();
    m.basic.under_5 = q.under_5_degrees;
    m.basic.under_10 = q.under_10_degrees;
  }
  for (const auto& t : tets) {
    using P::internal::to_vec3;
    const auto p = to_vec3(points[t[0]]), q = to_vec3(points[t[1]]), r = to_vec3(points[t[2]]),
               s = to_vec3(points[t[3]]);
    const auto angles = P::internal::dihedral_angles(p, q, r, s);
    for (double a : angles) ++m.dihedral[std::size_t(std::clamp(int(a / 5), 0, dihedral_bins - 1))];
    const double lo = *std::min_element(angles.begin(), angles.end());
    ++m.min_dihedral[std::size_t(std::clamp(int(lo / 5), 0, dihedral_bins - 1))];
    const double rr = P::internal::radius_ratio(p, q, r, s);
    ++m.radius_ratio[std::size_t(std::clamp(int(rr / 0.05), 0, radius_ratio_bins - 1))];
    // The exact predicate on the double coordinates (Epick's filtered Orientation_3).
    const auto o = CGAL::orientation(Kernel::Point_3(p[0], p[1], p[2]), Kernel::Point_3(q[0], q[1], q[2]),
                                     Kernel::Point_3(r[0], r[1], r[2]), Kernel::Point_3(s[0], s[1], s[2]));
    if (o == CGAL::NEGATIVE) ++m.negative;
    if (o == CGAL::COPLANAR) ++m.flat;
  }
  // The edges against h (each edge once), the range CGAL's isotropic remeshing aims at.
  std::vector<std::uint64_t> edges;
  edges.reserve(6 * tets.size());
  for (const auto& t : tets)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const std::uint64_t a = std::uint64_t(t[i]), b = std::uint64_t(t[j]);
        edges.push_back(a < b ? (a << 32) | b : (b << 32) | a);
      }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  m.edges = edges.size();
  for (const std::uint64_t e : edges) {
    using P::internal::to_vec3;
    const double l = P::internal::norm(P::internal::minus(to_vec3(points[std::size_t(e >> 32)]),
                                                          to_vec3(points[std::size_t(e & 0xffffffffu)])));
    if (l < 0.8 * ref.edge_length)
      ++m.edges_short;
    else if (l > 1.33 * ref.edge_length)
      ++m.edges_long;
    else
      ++m.edges_in_range;
  }
  // The boundary with the label interfaces (the same as the boundary alone for an unlabelled mesh).
  m.surface_in_out = m.basic.boundary_in_out;
  m.surface_out_in = m.basic.boundary_out_in;
  if (distances && !in.tetrahedron_labels.empty()) {
    const P::Boundary_distance b = P::boundary_distance(in.points, in.tetrahedra, points, tets, 0, 1000000,
                                                        &in.tetrahedron_labels, &labels);
    m.surface_in_out = b.diagonal > 0 ? b.input_to_output / b.diagonal : 0;
    m.surface_out_in = b.diagonal > 0 ? b.output_to_input / b.diagonal : 0;
  }
  // The volumes, per label.
  const std::map<int, double> volumes =
      label_volumes(points, tets, in.tetrahedron_labels.empty() ? std::vector<int>() : labels, !distances);
  m.labels_out = volumes.size();
  double total = 0;
  for (const auto& lv : volumes) total += lv.second;
  m.volume_change = ref.volume > 0 ? (total - ref.volume) / ref.volume : 0;
  std::size_t k = 0;
  for (const auto& lv : ref.label_volumes) {
    const auto it = volumes.find(lv.first);
    const double signed_change = ((it == volumes.end() ? 0. : it->second) - lv.second) / lv.second;
    if (k < m.label_changes.size()) m.label_changes[k++] = {lv.first, signed_change};
    const double change = std::abs(signed_change);
    if (change >= m.max_label_volume_change) {
      m.max_label_volume_change = change;
      m.worst_label = lv.first;
    }
  }
  return m;
}

// The time the other processes of the machine took meanwhile: all the cores' busy time from
// /proc/stat minus this process's own CPU time, per second of the run (0 on a quiet machine, up to the
// number of cores minus what the run itself used).
double machine_busy_seconds() {
  std::ifstream f("/proc/stat");
  std::string cpu;
  f >> cpu;
  double total = 0, idle = 0, x = 0;
  for (int i = 0; i < 8 && f >> x; ++i) {
    total += x;
    if (i == 3 || i == 4) idle += x; // idle, iowait
  }
  return (total - idle) / double(sysconf(_SC_CLK_TCK));
}

double own_cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// One output of the side-by-side mode (plain data: it crosses a pipe).
struct Side_run {
  bool ok = false;
  std::size_t peak_rss_bytes = 0, run_peak_rss_bytes = 0; // the child's, and the run's alone
  double seconds = 0, cpu_seconds = 0, others = 0;        // wall clock, CPU time, the other processes' cores
  double seconds_build = 0;          // CGAL: build_triangulation from the soup (in `seconds`)
  std::size_t constrained_edges = 0; // CGAL
  std::size_t rounds = 0, collapses = 0, moves = 0, flips = 0, splits = 0, optimization_rounds = 0;
  int stop = -1;
  Full_measures out;
  char error[200] = {};
};

// Times a run in the current (child) process: wall clock, own CPU time, the others' load.
struct Run_clock {
  double wall = prstar_bench::now(), cpu = own_cpu_seconds(), busy = machine_busy_seconds();
  void stop(Side_run& r) const {
    r.seconds = prstar_bench::now() - wall;
    r.cpu_seconds = own_cpu_seconds() - cpu;
    r.others = r.seconds > 0 ? std::max(0., (machine_busy_seconds() - busy - r.cpu_seconds) / r.seconds) : 0;
  }
};

// At most `threads` TBB threads in this process (the children are forked before any TBB work).
struct Thread_limit {
#ifdef CGAL_LINKED_WITH_TBB
  explicit Thread_limit(int threads)
      : control(tbb::global_control::max_allowed_parallelism, std::size_t(std::max(1, threads))) {}
  tbb::global_control control;
#else
  explicit Thread_limit(int) {}
#endif
};

// Writes an output for checks by other tools (`--output-dir`), after its measures; "" writes nothing.
template <class Points, class Tets>
void write_output(const std::string& file, const Points& points, const Tets& tets,
                  const std::vector<int>& labels) {
  if (file.empty()) return;
  Mesh m;
  m.points.assign(points.begin(), points.end());
  for (const auto& t : tets)
    m.tetrahedra.push_back({{Mesh::Index(t[0]), Mesh::Index(t[1]), Mesh::Index(t[2]), Mesh::Index(t[3])}});
  m.tetrahedron_labels = labels;
  P::IO::write_tetrahedral_mesh(file, m);
}

Side_run side_cgal(const Reference& ref, double edge_length, int iterations, const std::string& output_file) {
  Side_run r = prstar_bench::in_child<Side_run>([&] {
    Side_run r;
    try {
      const Run_clock clock;
      const Cgal_output c = cgal_remesh(*ref.mesh, edge_length, iterations);
      clock.stop(r);
      r.seconds = c.seconds_build + c.seconds_remesh; // without the extraction of the arrays
      r.seconds_build = c.seconds_build;
      r.run_peak_rss_bytes = c.run_peak_rss_bytes;
      r.constrained_edges = c.constrained_edges;
      r.out = measure_full(ref, c.points, c.tetrahedra, c.labels);
      write_output(output_file, c.points, c.tetrahedra, c.labels);
    } catch (const std::exception& e) {
      std::strncpy(r.error, e.what(), sizeof r.error - 1);
    }
    return r;
  });
  if (r.error[0]) r.ok = false;
  return r;
}

// The package's simplify() or remesh(), given as `run()` returning a Simplification_result.
template <class Run>
Side_run side_package(const Reference& ref, int threads, const std::string& output_file, const Run& run) {
  Side_run r = prstar_bench::in_child<Side_run>([&] {
    Side_run r;
    try {
      const Thread_limit limit(threads);
      const std::size_t base = prstar_bench::status_kib("VmRSS:");
      const Run_clock clock;
      const auto res = run();
      clock.stop(r);
      r.run_peak_rss_bytes = (prstar_bench::status_kib("VmHWM:") - base) * 1024;
      const auto& s = res.statistics;
      r.rounds = s.rounds;
      r.collapses = s.collapses;
      r.stop = static_cast<int>(s.stop);
      r.moves = s.optimization.vertex_moves;
      r.flips = s.optimization.flips_2_3 + s.optimization.flips_3_2 + s.optimization.flips_4_4 +
                s.optimization.edge_removals;
      r.splits = s.optimization.splits;
      r.optimization_rounds = s.optimization.rounds;
      r.out = measure_full(ref, res.mesh.points, res.mesh.tetrahedra, res.mesh.tetrahedron_labels);
      write_output(output_file, res.mesh.points, res.mesh.tetrahedra, res.mesh.tetrahedron_labels);
    } catch (const std::exception& e) {
      std::strncpy(r.error, e.what(), sizeof r.error - 1);
    }
    return r;
  });
  if (r.error[0]) r.ok = false;
  return r;
}

struct Side_options {
  double fraction = 0.25;           // CGAL's target: about this share of the input's tetrahedra
  std::vector<double> edge_lengths; // or these lengths, one per mesh
  int cgal_iterations = 3;
  std::vector<long> optimize{-1}; // simplify()'s optimization_rounds, one run each (-1: its default)
  long remesh_iterations = -1;    // remesh()'s number_of_iterations (-1: its default)
  bool remesh = true;
  std::size_t kv = 0; // 0: the package's default
  int threads = 1;
  std::string csv_file;
  std::string output_dir; // where to write the outputs (.vtu), or ""
};

struct Side_row {
  std::string method;
  Side_run run;
};

std::string percent(double x, int digits) {
  return fixed(100 * x, digits) + "%";
}

std::string yes_no(bool met) {
  return met ? "met" : "**not met**";
}

int run_side_by_side(const std::vector<std::string>& files, const Side_options& o) {
  std::ostringstream csv, hist;
  csv << "mesh,input_vertices,input_tetrahedra,edge_length,method,ok,seconds,cpu_seconds,others_cores,"
         "run_peak_rss_bytes,time_vs_cgal,memory_vs_cgal,vertices,tetrahedra,min_dihedral,max_dihedral,"
         "under_10,share_under_10,min_radius_ratio,boundary_in_out_rel,boundary_out_in_rel,"
         "surface_in_out_rel,surface_out_in_rel,sharp_in_out_rel,sharp_out_in_rel,max_label_volume_change,"
         "worst_label,volume_change,label_volume_changes,negative,flat,edges,edges_in_range,share_in_range,"
         "edges_short,"
         "edges_long,rounds,collapses,vertex_moves,flips,splits,error\n";
  hist << "mesh,method,measure,bin_low,bin_high,count,share\n";
  std::cout << "# Side by side: CGAL tetrahedral_isotropic_remeshing, PR-star simplify() and remesh()\n\n"
            << "Machine: " << cpu_model() << ", " << sysconf(_SC_NPROCESSORS_ONLN)
            << " cores online (shared); the package on " << o.threads
            << " thread(s), CGAL on one.  Each run in its own process; peak RSS is the growth of VmHWM "
               "during the run alone (input already loaded), measures computed after it; \"others\" = "
               "cores used by the other processes of the machine during the run.\n\n";
  for (std::size_t f = 0; f < files.size(); ++f) {
    Mesh mesh;
    try {
      P::IO::read_tetrahedral_mesh(files[f], mesh);
    } catch (const std::exception& e) {
      std::cerr << e.what() << '\n';
      return 1;
    }
    const std::string name = base_name(files[f]);
    Reference ref;
    ref.mesh = &mesh;
    ref.label_volumes = label_volumes(mesh.points, mesh.tetrahedra, mesh.tetrahedron_labels, true);
    for (const auto& lv : ref.label_volumes) ref.volume += lv.second;
    const double mean_edge = mean_edge_length(mesh);
    ref.edge_length = f < o.edge_lengths.size() ? o.edge_lengths[f] : mean_edge * std::cbrt(1 / o.fraction);
    const double h = ref.edge_length;
    std::cerr << name << ": " << mesh.points.size() << " vertices, " << mesh.tetrahedra.size()
              << " tetrahedra, " << ref.label_volumes.size() << " label(s); h = " << h << '\n';
    const Full_measures in = measure_full(ref, mesh.points, mesh.tetrahedra, mesh.tetrahedron_labels, false);

    // DIR/<mesh without extension>_<what>.vtu, or "" without --output-dir
    auto output_file = [&](const std::string& what) {
      return o.output_dir.empty() ? std::string()
                                  : o.output_dir + "/" + name.substr(0, name.find('.')) + "_" + what + ".vtu";
    };
    std::vector<Side_row> rows;
    std::cerr << "  CGAL tetrahedral_isotropic_remeshing, " << o.cgal_iterations << " iterations ... "
              << std::flush;
    rows.push_back({"CGAL remeshing", side_cgal(ref, h, o.cgal_iterations, output_file("cgal"))});
    const Side_run cgal = rows[0].run; // a copy: rows grows
    std::cerr << (cgal.ok ? fixed(cgal.seconds, 2) + " s, " + std::to_string(cgal.out.basic.tetrahedra) +
                                " tetrahedra"
                          : std::string("failed: ") + cgal.error)
              << '\n';
    // simplify() to CGAL's output size (or to the fraction when CGAL failed).
    const double n_out =
        cgal.ok ? double(cgal.out.basic.tetrahedra) : o.fraction * double(mesh.tetrahedra.size());
    const double target = std::clamp(1 - n_out / double(mesh.tetrahedra.size()), 0., 1.);
    for (const long rounds : o.optimize) {
      const std::string what =
          "simplify" + (rounds < 0 ? std::string() : " (optimization_rounds " + std::to_string(rounds) + ")");
      std::cerr << "  " << what << ", target " << target << " ... " << std::flush;
      const std::string file =
          output_file(rounds < 0 ? std::string("simplify") : "simplify_opt" + std::to_string(rounds));
      rows.push_back({what, side_package(ref, o.threads, file, [&] {
                        auto np = P::parameters::target_fraction(target).bucket_size(
                            o.kv ? o.kv : std::size_t(Octree::default_bucket_size));
                        return rounds < 0 ? P::simplify(mesh, np)
                                          : P::simplify(mesh, np.optimization_rounds(std::size_t(rounds)));
                      })});
      const Side_run& r = rows.back().run;
      std::cerr << (r.ok ? fixed(r.seconds, 2) + " s, " + std::to_string(r.out.basic.tetrahedra) +
                               " tetrahedra"
                         : std::string("failed: ") + r.error)
                << '\n';
    }
    if (o.remesh) {
      std::cerr << "  remesh, h = " << h << " ... " << std::flush;
      rows.push_back(
          {"remesh", side_package(ref, o.threads, output_file("remesh"), [&] {
             auto np = P::parameters::bucket_size(o.kv ? o.kv : std::size_t(Octree::default_bucket_size));
             return o.remesh_iterations < 0
                        ? P::remesh(mesh, h, np)
                        : P::remesh(mesh, h, np.number_of_iterations(std::size_t(o.remesh_iterations)));
           })});
      const Side_run& r = rows.back().run;
      std::cerr << (r.ok ? fixed(r.seconds, 2) + " s, " + std::to_string(r.out.basic.tetrahedra) +
                               " tetrahedra"
                         : std::string("failed: ") + r.error)
                << '\n';
    }

    // --- the tables ---
    std::cout << "## " << name << " (" << human(double(mesh.points.size())) << " vertices, "
              << human(double(mesh.tetrahedra.size())) << " tetrahedra, " << ref.label_volumes.size()
              << (ref.label_volumes.size() == 1 ? " label" : " labels") << ")\n\n"
              << "Target edge length h = " << h
              << (f < o.edge_lengths.size() ? " (given)"
                                            : " (the input's mean edge " + fixed(mean_edge, 6) + " x (1 / " +
                                                  fixed(o.fraction, 3) + ")^(1/3))")
              << "; CGAL " << o.cgal_iterations << " iterations"
              << (cgal.ok ? ", " + std::to_string(cgal.constrained_edges) +
                                " constrained sharp edges (boundary and interfaces, 40 degrees), of its " +
                                fixed(cgal.seconds, 2) + " s " + fixed(cgal.seconds_build, 2) +
                                " s build_triangulation from the soup"
                          : std::string())
              << "; simplify() to CGAL's output size (target fraction " << fixed(target, 4) << ")"
              << (o.remesh ? "; remesh() at h" : "") << ".\n\n";
    std::cout
        << "| | tetrahedra | seconds | x CGAL | CPU s | others | peak RSS | x CGAL | min dihedral | max "
           "dihedral | < 10° | min radius ratio | non-positive | edges in [0.8h, 1.33h] | Hausdorff in→out "
           "| out→in | with interfaces in→out | out→in | label volume change | rounds | collapses | "
           "moves | flips | splits |\n"
        << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
           "---:|---:|---:|---:|---:|\n"
        << "| input | " << human(double(in.basic.tetrahedra)) << " | | | | | | | "
        << fixed(in.basic.min_dihedral, 2) << "° | " << fixed(in.basic.max_dihedral, 2) << "° | "
        << percent(in.basic.share_under_10, 3) << " | " << fixed(in.basic.min_radius_ratio, 3) << " | | "
        << percent(double(in.edges_in_range) / double(std::max<std::size_t>(1, in.edges)), 1)
        << " | | | | | | | | | | |\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const Side_row& row = rows[i];
      const Side_run& r = row.run;
      if (!r.ok) {
        std::cout << "| " << row.method << " | " << (r.error[0] ? r.error : "failed")
                  << " |||||||||||||||||||||||\n";
        continue;
      }
      const bool is_cgal = i == 0;
      const Full_measures& m = r.out;
      auto ratio = [&](double a, double b) { return cgal.ok && b > 0 ? fixed(a / b, 3) : std::string("–"); };
      std::cout << "| " << row.method << " | " << human(double(m.basic.tetrahedra)) << " | "
                << fixed(r.seconds, 2) << " | " << (is_cgal ? "1" : ratio(r.seconds, cgal.seconds)) << " | "
                << fixed(r.cpu_seconds, 2) << " | " << fixed(r.others, 2) << " | "
                << fixed(double(r.run_peak_rss_bytes) / (1 << 20), 1) << " MiB | "
                << (is_cgal ? "1" : ratio(double(r.run_peak_rss_bytes), double(cgal.run_peak_rss_bytes)))
                << " | " << fixed(m.basic.min_dihedral, 2) << "° | " << fixed(m.basic.max_dihedral, 2)
                << "° | " << percent(m.basic.share_under_10, 3) << " (" << m.basic.under_10 << ") | "
                << fixed(m.basic.min_radius_ratio, 3) << " | " << m.negative + m.flat << " | "
                << percent(double(m.edges_in_range) / double(std::max<std::size_t>(1, m.edges)), 1) << " | "
                << percent(m.basic.boundary_in_out, 3) << " | " << percent(m.basic.boundary_out_in, 3)
                << " | " << percent(m.surface_in_out, 3) << " | " << percent(m.surface_out_in, 3) << " | "
                << percent(m.max_label_volume_change, 3)
                << (ref.label_volumes.size() > 1 ? " (label " + std::to_string(m.worst_label) + ")" : "")
                << " | " << (is_cgal ? std::string("–") : std::to_string(r.rounds)) << " | "
                << (is_cgal ? std::string("–") : human(double(r.collapses))) << " | "
                << (is_cgal ? std::string("–") : human(double(r.moves))) << " | "
                << (is_cgal ? std::string("–") : human(double(r.flips))) << " | "
                << (is_cgal ? std::string("–") : human(double(r.splits))) << " |\n";
    }
    std::cout
        << "\n(Hausdorff: sampled two-sided distance between the boundary surfaces, then between the "
           "boundaries with the label interfaces, relative to the diagonal of the input's bounding box; "
           "label volume change: the largest |V_out - V_in| / V_in over the input's labels; non-positive: "
           "tetrahedra not POSITIVE by the exact Orientation_3.)\n\n";

    // --- against the targets ---
    if (cgal.ok) {
      const double rr_floor = std::min(in.basic.min_radius_ratio, 0.1);
      std::cout << "Targets (issue 22): \n\n| output | < 10° ≤ CGAL's and ≤ 0.05% | min radius ratio ≥ "
                << fixed(rr_floor, 3)
                << " | max dihedral ≤ 165° | Hausdorff ≤ 0.2% both ways | label volumes within 0.5% | "
                   "valid | time ≤ 0.3x CGAL | peak memory ≤ 0.5x CGAL | edges in [0.8h, 1.33h] ≥ CGAL's |\n"
                << "|---|---|---|---|---|---|---|---|---|---|\n";
      const double cgal_share =
          double(cgal.out.edges_in_range) / double(std::max<std::size_t>(1, cgal.out.edges));
      for (std::size_t i = 1; i < rows.size(); ++i) {
        const Side_row& row = rows[i];
        const Side_run& r = row.run;
        if (!r.ok) continue;
        const Full_measures& m = r.out;
        const double hd =
            std::max({m.basic.boundary_in_out, m.basic.boundary_out_in, m.surface_in_out, m.surface_out_in});
        const double share = double(m.edges_in_range) / double(std::max<std::size_t>(1, m.edges));
        const double t = r.seconds / cgal.seconds, cpu = r.cpu_seconds / cgal.cpu_seconds;
        const double mem =
            double(r.run_peak_rss_bytes) / double(std::max<std::size_t>(1, cgal.run_peak_rss_bytes));
        std::cout << "| " << row.method << " | "
                  << yes_no(m.basic.share_under_10 <= cgal.out.basic.share_under_10 &&
                            m.basic.share_under_10 <= 0.0005)
                  << ": " << percent(m.basic.share_under_10, 3) << " vs "
                  << percent(cgal.out.basic.share_under_10, 3) << " | "
                  << yes_no(m.basic.min_radius_ratio >= rr_floor) << ": "
                  << fixed(m.basic.min_radius_ratio, 3) << " | " << yes_no(m.basic.max_dihedral <= 165)
                  << ": " << fixed(m.basic.max_dihedral, 1) << "° | " << yes_no(hd <= 0.002) << ": "
                  << percent(hd, 3) << " | " << yes_no(m.max_label_volume_change <= 0.005) << ": "
                  << percent(m.max_label_volume_change, 3) << " | " << yes_no(m.negative + m.flat == 0)
                  << ": " << m.negative + m.flat << " | " << yes_no(t <= 0.3) << ": " << fixed(t, 3)
                  << "x (CPU " << fixed(cpu, 3) << "x) | " << yes_no(mem <= 0.5) << ": " << fixed(mem, 3)
                  << "x | "
                  << (row.method == "remesh" ? yes_no(share >= cgal_share) + ": " + percent(share, 1) +
                                                   " vs " + percent(cgal_share, 1)
                                             : "(" + percent(share, 1) + ")")
                  << " |\n";
      }
      std::cout
          << "\n(The first six targets are the simplification's at CGAL's output size, shown for remesh() "
             "too; time (judged on the wall clock; the CPU time ratio next to it is less sensitive to the "
             "machine's load) and memory apply to both; the edge-length share is remesh()'s, at the same h "
             "as "
             "CGAL, in parentheses for simplify().)\n\n";
    }

    // --- CSV ---
    auto csv_row = [&](const std::string& method, const Side_run* r, const Full_measures& m, bool is_cgal) {
      const bool ok = !r || r->ok;
      csv << name << ',' << mesh.points.size() << ',' << mesh.tetrahedra.size() << ',' << h << ',' << method
          << ',' << (ok ? 1 : 0) << ',';
      if (r)
        csv << fixed(r->seconds, 4) << ',' << fixed(r->cpu_seconds, 4) << ',' << fixed(r->others, 3) << ','
            << r->run_peak_rss_bytes << ','
            << (cgal.ok && cgal.seconds > 0 ? fixed(r->seconds / cgal.seconds, 4) : std::string()) << ','
            << (cgal.ok && cgal.run_peak_rss_bytes
                    ? fixed(double(r->run_peak_rss_bytes) / double(cgal.run_peak_rss_bytes), 4)
                    : std::string())
            << ',';
      else
        csv << ",,,,,,";
      csv << m.basic.vertices << ',' << m.basic.tetrahedra << ',' << m.basic.min_dihedral << ','
          << m.basic.max_dihedral << ',' << m.basic.under_10 << ',' << m.basic.share_under_10 << ','
          << m.basic.min_radius_ratio << ',' << m.basic.boundary_in_out << ',' << m.basic.boundary_out_in
          << ',' << m.surface_in_out << ',' << m.surface_out_in << ',' << m.basic.sharp_in_out << ','
          << m.basic.sharp_out_in << ',' << m.max_label_volume_change << ',' << m.worst_label << ','
          << m.volume_change << ',';
      for (std::size_t k = 0; k < ref.label_volumes.size() && k < m.label_changes.size(); ++k)
        csv << (k ? ";" : "") << m.label_changes[k].label << ':' << m.label_changes[k].change;
      csv << ',' << m.negative << ',' << m.flat << ',' << m.edges << ',' << m.edges_in_range << ','
          << double(m.edges_in_range) / double(std::max<std::size_t>(1, m.edges)) << ',' << m.edges_short
          << ',' << m.edges_long << ',';
      if (r && !is_cgal)
        csv << r->rounds << ',' << r->collapses << ',' << r->moves << ',' << r->flips << ',' << r->splits
            << ',';
      else
        csv << ",,,,,";
      std::string error = r ? r->error : "";
      std::replace(error.begin(), error.end(), ',', ';');
      csv << error << '\n';
      if (!ok) return;
      auto bins = [&](const char* what, const auto& counts, double width) {
        std::uint64_t total = 0;
        for (const auto c : counts) total += c;
        for (std::size_t b = 0; b < counts.size(); ++b)
          hist << name << ',' << method << ',' << what << ',' << double(b) * width << ','
               << double(b + 1) * width << ',' << counts[b] << ','
               << (total ? double(counts[b]) / double(total) : 0.) << '\n';
      };
      bins("dihedral", m.dihedral, 5);
      bins("min_dihedral", m.min_dihedral, 5);
      bins("radius_ratio", m.radius_ratio, 0.05);
    };
    csv_row("input", nullptr, in, false);
    for (std::size_t i = 0; i < rows.size(); ++i)
      csv_row(rows[i].method, &rows[i].run, rows[i].run.out, i == 0);
  }
  if (!o.csv_file.empty()) {
    std::ofstream f(o.csv_file);
    f << csv.str();
    const std::string hist_file = o.csv_file.substr(0, o.csv_file.rfind(".csv")) + "_histograms.csv";
    std::ofstream fh(hist_file);
    fh << hist.str();
    if (!f || !fh) {
      std::cerr << o.csv_file << ": cannot write\n";
      return 1;
    }
  }
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  std::vector<std::size_t> kvs{inf, 20, 50, 100, 200, 400, 800};
  std::vector<double> targets{0.25, 0.5, 0.75};
  int reps = 1, cgal_iterations = 1;
  bool cgal = true, side_by_side = false, cgal_iterations_given = false;
  Side_options side;
  std::string csv_file;
  std::vector<std::string> files;
  const char* const usage =
      "usage: bench_simplification [--kv 20,50,...,inf] [--targets 0.25,0.5,0.75] [--reps R] [--no-cgal] "
      "[--cgal-iterations N] [--csv OUT.csv] MESH...\n"
      "       bench_simplification --side-by-side [--fraction F | --edge-length H1,H2,...] "
      "[--cgal-iterations N] "
      "[--optimize R1,R2,...|default] [--remesh-iterations N] [--no-remesh] [--kv K] [--threads T] "
      "[--output-dir DIR] [--csv OUT.csv] MESH...\n";
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--no-cgal")
        cgal = false;
      else if (a == "--side-by-side")
        side_by_side = true;
      else if (a == "--no-remesh")
        side.remesh = false;
      else if ((a == "--kv" || a == "--targets" || a == "--reps" || a == "--csv" ||
                a == "--cgal-iterations" || a == "--fraction" || a == "--edge-length" || a == "--optimize" ||
                a == "--remesh-iterations" || a == "--threads" || a == "--output-dir") &&
               i + 1 < argc) {
        const std::string v = argv[++i];
        if (a == "--kv") {
          kvs.assign(1, inf); // the global run is always the reference
          for (const std::string& k : split(v))
            if (k != "inf") kvs.push_back(std::stoull(k));
          side.kv = kvs.size() > 1 ? kvs[1] : inf;
        } else if (a == "--targets") {
          targets.clear();
          for (const std::string& t : split(v)) targets.push_back(std::stod(t));
        } else if (a == "--reps")
          reps = std::max(1, std::stoi(v));
        else if (a == "--cgal-iterations") {
          cgal_iterations = std::max(1, std::stoi(v));
          cgal_iterations_given = true;
        } else if (a == "--fraction") {
          side.fraction = std::stod(v);
          if (!(side.fraction > 0 && side.fraction < 1)) throw std::invalid_argument("--fraction: in (0, 1)");
        } else if (a == "--edge-length") {
          for (const std::string& h : split(v)) {
            side.edge_lengths.push_back(std::stod(h));
            if (!(side.edge_lengths.back() > 0)) throw std::invalid_argument("--edge-length: positive");
          }
        } else if (a == "--optimize") {
          side.optimize.clear();
          for (const std::string& r : split(v)) side.optimize.push_back(r == "default" ? -1 : std::stol(r));
        } else if (a == "--remesh-iterations")
          side.remesh_iterations = std::stol(v);
        else if (a == "--threads")
          side.threads = std::max(1, std::stoi(v));
        else if (a == "--output-dir")
          side.output_dir = v;
        else
          csv_file = v;
      } else if (!a.empty() && a[0] == '-') {
        std::cerr << usage;
        return 2;
      } else
        files.push_back(a);
    }
  } catch (const std::exception& e) {
    std::cerr << "bench_simplification: " << e.what() << "\n" << usage;
    return 2;
  }
  if (files.empty()) {
    std::cerr << "bench_simplification: no mesh given\n";
    return 2;
  }
  if (side_by_side) {
    side.cgal_iterations = cgal_iterations_given ? cgal_iterations : 3;
    side.csv_file = csv_file;
    return run_side_by_side(files, side);
  }

  std::ostringstream csv;
  csv << "mesh,vertices,tetrahedra,kv,target,removed,removed_pct_of_inf,first_round_removed,first_round_pct_"
         "of_inf,"
         "seconds,seconds_pct_of_inf,max_queue,"
         "peak_rss_bytes,rounds,output_tetrahedra,blocked_different_leaves,blocked_boundary,blocked_flip,"
         "blocked_link,blocked_feature,blocked_quality,blocked_error,stop,run_peak_rss_bytes,"
         "out_min_dihedral,out_max_dihedral,out_min_radius_ratio,out_share_under_5,out_share_under_10,"
         "boundary_in_out_rel,boundary_out_in_rel,sharp_in_out_rel,sharp_out_in_rel,sharp_edges_in,sharp_"
         "edges_out\n";
  std::ostringstream cgal_csv;
  cgal_csv << "mesh,target,edge_length,iterations,constrained_edges,seconds_build,seconds_remesh,run_peak_"
              "rss_bytes,"
              "output_tetrahedra,out_min_dihedral,out_max_dihedral,out_min_radius_ratio,out_share_under_5,"
              "out_share_under_10,boundary_in_out_rel,boundary_out_in_rel,sharp_in_out_rel,sharp_out_in_rel,"
              "sharp_edges_in,sharp_edges_out\n";
  std::cout
      << "# Table 3: local half-edge-collapse simplification on the PR-star octree\n\n"
      << "Machine: " << cpu_model() << ", " << sysconf(_SC_NPROCESSORS_ONLN)
      << " cores online (shared), single thread.  Each run in its own process; peak RSS is the growth "
         "of VmHWM during the run (input mesh already loaded).  Times include every octree build "
         "(one per round); min of "
      << reps << " run(s).\n\n"
      << "simplify() with its default parameters (shortest edge first, half-edge collapses, quality floor "
         "5 degrees of dihedral angle, sharp features at 40 degrees, boundary error bound) besides the "
         "target "
         "and k_v; rounds of (per-leaf queues, compaction, rebuild).  (%) columns are relative to "
         "k_v = inf (the single-leaf, global run).  Rounds go on until the target is met, so \"removed\" "
         "is the target unless the local algorithm stalls; \"1st round\" is what the first pass of per-leaf "
         "queues removes under the same length threshold (the paper's measure of the edges lost to leaf "
         "borders).  \"blocked\" = candidates rejected: ends in different leaves / boundary / flip / "
         "link / feature / quality floor / error bound; \"stop\" = why the run stopped.  Peak RSS is that of "
         "the run alone (the quality measures are computed after it).\n\n";

  for (const std::string& file : files) {
    Mesh mesh;
    if (!prstar_bench::read_mesh_file(file, mesh)) return 1;
    const std::string name = base_name(file);
    std::cerr << name << ": " << mesh.points.size() << " vertices, " << mesh.tetrahedra.size()
              << " tetrahedra\n";
    std::cout << "## " << name << " (" << human(double(mesh.points.size())) << " vertices, "
              << human(double(mesh.tetrahedra.size())) << " tetrahedra)\n\n";
    // results[k][t]
    std::vector<std::vector<Result>> results(kvs.size(), std::vector<Result>(targets.size()));
    std::vector<Cgal_result> cgal_results(targets.size());
    const double mean_edge = cgal ? mean_edge_length(mesh) : 0;
    for (std::size_t t = 0; t < targets.size(); ++t) {
      for (std::size_t k = 0; k < kvs.size(); ++k) {
        std::cerr << "  k_v = " << kv_string(kvs[k]) << ", target " << targets[t] << " ... " << std::flush;
        results[k][t] = run_in_child(mesh, kvs[k], targets[t], reps);
        std::cerr << (results[k][t].ok ? fixed(results[k][t].seconds, 2) + " s (measures " +
                                             fixed(results[k][t].out.seconds, 2) + " s)"
                                       : std::string("failed"))
                  << '\n';
      }
      if (cgal && t > 0 && !cgal_results[0].ok) // a mesh CGAL cannot take is tried once
        cgal_results[t] = cgal_results[0];
      else if (cgal) {
        // About the output size of the global PR-star run.
        const double n_out = results[0][t].ok && results[0][t].output_tetrahedra
                                 ? double(results[0][t].output_tetrahedra)
                                 : double(mesh.tetrahedra.size()) * (1 - targets[t]);
        const double length = mean_edge * std::cbrt(double(mesh.tetrahedra.size()) / n_out);
        std::cerr << "  CGAL tetrahedral_isotropic_remeshing, edge length " << length << " ... "
                  << std::flush;
        cgal_results[t] = run_cgal_in_child(mesh, length, cgal_iterations);
        auto report = [&](const Cgal_result& c) {
          std::cerr << (c.ok ? fixed(c.seconds_build + c.seconds_remesh, 2) + " s, " +
                                   std::to_string(c.out.tetrahedra) + " tetrahedra"
                             : std::string("failed"))
                    << '\n';
        };
        report(cgal_results[t]);
        if (cgal_results[t].error[0]) std::cerr << "  " << cgal_results[t].error << '\n';
        // Off by more than 15%: once more, with the length corrected by the size ratio.
        const Cgal_result first = cgal_results[t];
        if (first.ok && std::abs(double(first.out.tetrahedra) / n_out - 1) > 0.15) {
          const double corrected = length * std::cbrt(double(first.out.tetrahedra) / n_out);
          std::cerr << "  again, edge length " << corrected << " ... " << std::flush;
          cgal_results[t] = run_cgal_in_child(mesh, corrected, cgal_iterations);
          cgal_results[t].first_edge_length = length;
          cgal_results[t].first_tetrahedra = first.out.tetrahedra;
          report(cgal_results[t]);
        }
      }
    }
    const P::Mesh_quality in_quality = P::mesh_quality(mesh.points, mesh.tetrahedra);
    for (std::size_t t = 0; t < targets.size(); ++t) {
      const Result& g = results[0][t];
      std::cout
          << "### about " << static_cast<int>(targets[t] * 100 + 0.5) << "% of the tetrahedra removed\n\n"
          << "| k_v | removed | (%) | 1st round | (%) | seconds | (%) | max queue | peak RSS | rounds | stop "
             "| "
             "blocked: leaves | boundary | flip | link | feature | quality | error |\n"
          << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|\n";
      static const char* const stops[] = {"target", "nothing left", "blocked", "max rounds"};
      for (std::size_t k = 0; k < kvs.size(); ++k) {
        const Result& r = results[k][t];
        if (!r.ok) {
          std::cout << "| " << kv_string(kvs[k]) << " | failed |||||||||||||||||\n";
          continue;
        }
        const bool ref = k == 0;
        const double rp = g.ok && g.removed ? 100. * double(r.removed) / double(g.removed) : 0;
        const double tp = g.ok && g.seconds > 0 ? 100. * r.seconds / g.seconds : 0;
        const double fp = g.ok && g.first_round ? 100. * double(r.first_round) / double(g.first_round) : 0;
        std::cout << "| " << (ref ? std::string("∞") : kv_string(kvs[k])) << " | " << human(double(r.removed))
                  << " | " << (ref ? "–" : fixed(rp, 0)) << " | " << human(double(r.first_round)) << " | "
                  << (ref ? "–" : fixed(fp, 0)) << " | " << fixed(r.seconds, 2) << " | "
                  << (ref ? "–" : fixed(tp, 0)) << " | " << human(double(r.max_queue)) << " | "
                  << fixed(double(r.run_peak_rss_bytes) / (1 << 20), 1) << " MiB | " << r.rounds << " | "
                  << (r.stop >= 0 && r.stop < 4 ? stops[r.stop] : "?") << " | "
                  << human(double(r.blocked_leaves)) << " | " << human(double(r.blocked_boundary)) << " | "
                  << human(double(r.blocked_flip)) << " | " << human(double(r.blocked_link)) << " | "
                  << human(double(r.blocked_feature)) << " | " << human(double(r.blocked_quality)) << " | "
                  << human(double(r.blocked_error)) << " |\n";
        const Output_measures& o = r.out;
        csv << name << ',' << mesh.points.size() << ',' << mesh.tetrahedra.size() << ',' << kv_string(kvs[k])
            << ',' << targets[t] << ',' << r.removed << ',' << fixed(rp, 2) << ',' << r.first_round << ','
            << fixed(fp, 2) << ',' << fixed(r.seconds, 4) << ',' << fixed(tp, 2) << ',' << r.max_queue << ','
            << r.peak_rss_bytes << ',' << r.rounds << ',' << r.output_tetrahedra << ',' << r.blocked_leaves
            << ',' << r.blocked_boundary << ',' << r.blocked_flip << ',' << r.blocked_link << ','
            << r.blocked_feature << ',' << r.blocked_quality << ',' << r.blocked_error << ','
            << (r.stop >= 0 && r.stop < 4 ? stops[r.stop] : "?") << ',' << r.run_peak_rss_bytes << ','
            << o.min_dihedral << ',' << o.max_dihedral << ',' << o.min_radius_ratio << ',' << o.share_under_5
            << ',' << o.share_under_10 << ',' << o.boundary_in_out << ',' << o.boundary_out_in << ','
            << o.sharp_in_out << ',' << o.sharp_out_in << ',' << o.sharp_in << ',' << o.sharp_out << '\n';
      }
      // What the outputs are worth, and CGAL's remeshing at about the same size.
      std::cout
          << "\nOutput quality and distance to the input (boundary: two-sided sampled Hausdorff distance "
             "between the boundary surfaces; sharp: from the vertices of the sharp edges (40 degrees) of one "
             "to those of the other, both ways; in % of the input's bounding-box diagonal):\n\n"
          << "| | tetrahedra | seconds | peak RSS | min dihedral | < 5° | < 10° | min radius ratio | "
             "boundary in→out | out→in | sharp edges | sharp in→out | out→in |\n"
          << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n"
          << "| input | " << human(double(mesh.tetrahedra.size())) << " | | | "
          << fixed(in_quality.min_dihedral_angle, 2) << "° | " << fixed(100 * in_quality.share_under_5(), 3)
          << "% (" << in_quality.under_5_degrees << ") | " << fixed(100 * in_quality.share_under_10(), 3)
          << "% (" << in_quality.under_10_degrees << ") | " << fixed(in_quality.min_radius_ratio, 3)
          << " | | | " << (g.ok ? std::to_string(g.out.sharp_in) : std::string()) << " | | |\n";
      auto row = [&](const std::string& what, const Output_measures& o, double seconds, std::size_t rss) {
        std::cout << "| " << what << " | " << human(double(o.tetrahedra)) << " | " << fixed(seconds, 2)
                  << " | " << fixed(double(rss) / (1 << 20), 1) << " MiB | " << fixed(o.min_dihedral, 2)
                  << "° | " << fixed(100 * o.share_under_5, 3) << "% (" << o.under_5 << ") | "
                  << fixed(100 * o.share_under_10, 3) << "% (" << o.under_10 << ") | "
                  << fixed(o.min_radius_ratio, 3) << " | " << fixed(100 * o.boundary_in_out, 3) << "% | "
                  << fixed(100 * o.boundary_out_in, 3) << "% | " << o.sharp_out << " | "
                  << fixed(100 * o.sharp_in_out, 3) << "% | " << fixed(100 * o.sharp_out_in, 3) << "% |\n";
      };
      for (std::size_t k = 0; k < kvs.size(); ++k)
        if (results[k][t].ok)
          row("PR-star k_v = " + (k == 0 ? std::string("∞") : kv_string(kvs[k])), results[k][t].out,
              results[k][t].seconds, results[k][t].run_peak_rss_bytes);
      if (cgal) {
        const Cgal_result& c = cgal_results[t];
        if (c.ok) {
          row("CGAL remeshing", c.out, c.seconds_build + c.seconds_remesh, c.run_peak_rss_bytes);
          std::cout << "\nCGAL tetrahedral_isotropic_remeshing: target edge length " << c.edge_length
                    << " (mean " << mean_edge << " x (N_in / N_out)^(1/3)), " << cgal_iterations
                    << " iteration(s), " << c.constrained_edges << " constrained sharp edges"
                    << (c.first_tetrahedra
                            ? " (the first length tried, " + std::to_string(c.first_edge_length) + ", gave " +
                                  std::to_string(c.first_tetrahedra) + " tetrahedra)"
                            : std::string())
                    << "; seconds = " << fixed(c.seconds_build, 2)
                    << " (build_triangulation from the soup) + " << fixed(c.seconds_remesh, 2)
                    << " (remeshing).\n";
          const Output_measures& o = c.out;
          cgal_csv << name << ',' << targets[t] << ',' << c.edge_length << ',' << cgal_iterations << ','
                   << c.constrained_edges << ',' << fixed(c.seconds_build, 4) << ','
                   << fixed(c.seconds_remesh, 4) << ',' << c.run_peak_rss_bytes << ',' << o.tetrahedra << ','
                   << o.min_dihedral << ',' << o.max_dihedral << ',' << o.min_radius_ratio << ','
                   << o.share_under_5 << ',' << o.share_under_10 << ',' << o.boundary_in_out << ','
                   << o.boundary_out_in << ',' << o.sharp_in_out << ',' << o.sharp_out_in << ',' << o.sharp_in
                   << ',' << o.sharp_out << '\n';
        } else
          std::cout << "| CGAL remeshing | " << (c.error[0] ? c.error : "failed") << " ||||||||||||\n";
      }
      std::cout << '\n';
    }
  }
  if (!csv_file.empty()) {
    std::ofstream f(csv_file);
    f << csv.str();
    if (cgal) {
      std::ofstream fc(csv_file.substr(0, csv_file.rfind(".csv")) + "_cgal.csv");
      fc << cgal_csv.str();
    }
    if (!f) {
      std::cerr << csv_file << ": cannot write\n";
      return 1;
    }
  }
  return 0;
}
