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
// Each run is done in a child process (fork) whose peak RSS counter is reset first
// (/proc/self/clear_refs "5"), so that VmHWM measures that run alone.  Times are the minimum over
// --reps repetitions inside the child (default 1: the algorithm is deterministic).
//
// usage: bench_simplification [--kv 20,50,...,inf] [--targets 0.25,0.5,0.75] [--reps R]
//                             [--no-cgal] [--cgal-iterations N] [--csv OUT.csv] MESH...
// Markdown on stdout.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/mesh_quality.h>
#include <CGAL/PR_star_octree/simplification.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_3/tet_soup_to_c3t3.h>
#include <CGAL/Tetrahedral_remeshing/Remeshing_triangulation_3.h>
#include <CGAL/tetrahedral_remeshing.h>

#include "bench_util.h"

#include <array>
#include <cmath>
#include <map>
#include <set>
#include <unordered_map>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
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

Cgal_result run_cgal_in_child(const Mesh& mesh, double edge_length, int iterations) {
  Cgal_result r = prstar_bench::in_child<Cgal_result>([&] {
    Cgal_result r;
    try {
      r.edge_length = edge_length;
      const std::size_t base = prstar_bench::status_kib("VmRSS:");
      const double t0 = prstar_bench::now();
      // The soup, positively oriented, with a non-zero subdomain index (the label, or 1), on the
      // vertices of the tetrahedra only (an unreferenced vertex would be an isolated vertex of the TDS).
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
        c[4] = mesh.tetrahedron_labels.empty() ? 1 : mesh.tetrahedron_labels[t];
        if (CGAL::orientation(points[c[0]], points[c[1]], points[c[2]], points[c[3]]) == CGAL::NEGATIVE)
          std::swap(c[2], c[3]);
        cells.push_back(c);
      }
      Remeshing_tr tr;
      std::vector<Remeshing_tr::Vertex_handle> handles;
      const std::map<std::array<int, 3>, Remeshing_tr::Cell::Surface_patch_index> no_patches;
      if (!CGAL::build_triangulation<Remeshing_tr, true>(tr, points, cells, no_patches, handles, false,
                                                         /* label 0 -> a new label */ true))
        throw std::runtime_error("CGAL's build_triangulation failed");
      // Its input must be a valid triangulation of the sphere once the boundary is coned to the infinite
      // vertex (a boundary of genus 0, connected): checked here, out of the time (CGAL asserts it).
      const double check_start = prstar_bench::now();
      const bool valid = tr.tds().is_valid();
      const double check_seconds = prstar_bench::now() - check_start;
      if (!valid)
        throw std::runtime_error("CGAL: the soup coned to the infinite vertex is not a valid Triangulation_3 "
                                 "(a boundary of genus > 0 or of several components?); not remeshed");

      // The input's sharp edges (40 degrees), found by mesh_quality.h, as constraints.
      namespace I = P::internal::mesh_quality_impl;
      std::set<Vertex_pair> constrained;
      for (const auto& e :
           I::sharp_edges(I::to_epick(mesh.points), I::boundary_triangles(mesh.tetrahedra), 40.)) {
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
      std::vector<Kernel::Point_3> out_points;
      std::unordered_map<Remeshing_tr::Vertex_handle, std::uint32_t> index;
      std::vector<std::array<std::uint32_t, 4>> out_tets;
      for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) {
        if (c->subdomain_index() == Remeshing_tr::Cell::Subdomain_index()) continue;
        std::array<std::uint32_t, 4> t;
        for (int i = 0; i < 4; ++i) {
          const auto it = index.emplace(c->vertex(i), std::uint32_t(out_points.size()));
          if (it.second) out_points.push_back(c->vertex(i)->point());
          t[i] = it.first->second;
        }
        out_tets.push_back(t);
      }
      r.out = measure(mesh, out_points, out_tets);
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

} // namespace

int main(int argc, char** argv) {
  std::vector<std::size_t> kvs{inf, 20, 50, 100, 200, 400, 800};
  std::vector<double> targets{0.25, 0.5, 0.75};
  int reps = 1, cgal_iterations = 1;
  bool cgal = true;
  std::string csv_file;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--no-cgal") {
      cgal = false;
      continue;
    }
    if ((a == "--kv" || a == "--targets" || a == "--reps" || a == "--csv" || a == "--cgal-iterations") &&
        i + 1 < argc) {
      const std::string v = argv[++i];
      if (a == "--kv") {
        kvs.assign(1, inf); // the global run is always the reference
        for (const std::string& k : split(v))
          if (k != "inf") kvs.push_back(std::stoull(k));
      } else if (a == "--targets") {
        targets.clear();
        for (const std::string& t : split(v)) targets.push_back(std::stod(t));
      } else if (a == "--reps")
        reps = std::max(1, std::stoi(v));
      else if (a == "--cgal-iterations")
        cgal_iterations = std::max(1, std::stoi(v));
      else
        csv_file = v;
    } else if (!a.empty() && a[0] == '-') {
      std::cerr << "usage: bench_simplification [--kv 20,50,...,inf] [--targets 0.25,0.5,0.75] [--reps R] "
                   "[--no-cgal] [--cgal-iterations N] [--csv OUT.csv] MESH...\n";
      return 2;
    } else
      files.push_back(a);
  }
  if (files.empty()) {
    std::cerr << "bench_simplification: no mesh given\n";
    return 2;
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
    try {
      P::IO::read_tetrahedral_mesh(file, mesh);
    } catch (const std::exception& e) {
      std::cerr << e.what() << '\n';
      return 1;
    }
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
