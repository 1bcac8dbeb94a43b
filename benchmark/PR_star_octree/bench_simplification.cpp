// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Table 3 of the paper: the local half-edge-collapse simplification on PR-star octrees with
// several bucket thresholds k_v, against the global algorithm (k_v = infinity, one leaf), for
// targets of 25%, 50% and 75% of the tetrahedra removed: tetrahedra removed (and % of the global
// run), seconds (and % of the global run), the largest edge queue (the paper's memory proxy), the
// peak RSS growth, the rounds and the candidates blocked by each condition.
//
// Each run is done in a child process (fork) whose peak RSS counter is reset first
// (/proc/self/clear_refs "5"), so that VmHWM measures that run alone.  Times are the minimum over
// --reps repetitions inside the child (default 1: the algorithm is deterministic).
//
// usage: bench_simplification [--kv 20,50,...,inf] [--targets 0.25,0.5,0.75] [--reps R]
//                             [--csv OUT.csv] MESH...
// Markdown on stdout.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/simplification.h>

#include "bench_util.h"

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

// What one child process measures (plain data: it comes back through a pipe).
struct Result {
  bool ok = false;
  std::size_t removed = 0, first_round = 0, output_tetrahedra = 0, rounds = 0, max_queue = 0,
              peak_rss_bytes = 0;
  std::size_t blocked_leaves = 0, blocked_boundary = 0, blocked_flip = 0, blocked_link = 0;
  double seconds = 0;
};

Result run_in_child(const Mesh& mesh, std::size_t kv, double target, int reps) {
  return prstar_bench::in_child<Result>([&] {
    Result r;
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
    }
    return r;
  });
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
  int reps = 1;
  std::string csv_file;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "--kv" || a == "--targets" || a == "--reps" || a == "--csv") && i + 1 < argc) {
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
      else
        csv_file = v;
    } else if (!a.empty() && a[0] == '-') {
      std::cerr << "usage: bench_simplification [--kv 20,50,...,inf] [--targets 0.25,0.5,0.75] [--reps R] "
                   "[--csv OUT.csv] MESH...\n";
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
         "blocked_link\n";
  std::cout
      << "# Table 3: local half-edge-collapse simplification on the PR-star octree\n\n"
      << "Machine: " << cpu_model() << ", " << sysconf(_SC_NPROCESSORS_ONLN)
      << " cores online (shared), single thread.  Each run in its own process; peak RSS is the growth "
         "of VmHWM during the run (input mesh already loaded).  Times include every octree build "
         "(one per round); min of "
      << reps << " run(s).\n\n"
      << "Priority: shortest edge first; collapse v2 into v1 (v1 < v2); boundary, exact-orientation and "
         "link conditions; rounds of (per-leaf queues, compaction, rebuild).  (%) columns are relative to "
         "k_v = inf (the single-leaf, global run).  Rounds go on until the target is met, so \"removed\" "
         "is the target unless the local algorithm stalls; \"1st round\" is what the first pass of per-leaf "
         "queues removes under the same length threshold (the paper's measure of the edges lost to leaf "
         "borders).  \"blocked\" = candidates rejected: ends in different leaves / boundary / flip / "
         "link.\n\n";

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
    for (std::size_t t = 0; t < targets.size(); ++t)
      for (std::size_t k = 0; k < kvs.size(); ++k) {
        std::cerr << "  k_v = " << kv_string(kvs[k]) << ", target " << targets[t] << " ... " << std::flush;
        results[k][t] = run_in_child(mesh, kvs[k], targets[t], reps);
        std::cerr << (results[k][t].ok ? fixed(results[k][t].seconds, 2) + " s" : std::string("failed"))
                  << '\n';
      }
    for (std::size_t t = 0; t < targets.size(); ++t) {
      const Result& g = results[0][t];
      std::cout
          << "### about " << static_cast<int>(targets[t] * 100 + 0.5) << "% of the tetrahedra removed\n\n"
          << "| k_v | removed | (%) | 1st round | (%) | seconds | (%) | max queue | peak RSS | rounds | "
             "blocked: leaves | boundary | flip | link |\n"
          << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
      for (std::size_t k = 0; k < kvs.size(); ++k) {
        const Result& r = results[k][t];
        if (!r.ok) {
          std::cout << "| " << kv_string(kvs[k]) << " | failed |||||||||||||\n";
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
                  << fixed(double(r.peak_rss_bytes) / (1 << 20), 1) << " MiB | " << r.rounds << " | "
                  << human(double(r.blocked_leaves)) << " | " << human(double(r.blocked_boundary)) << " | "
                  << human(double(r.blocked_flip)) << " | " << human(double(r.blocked_link)) << " |\n";
        csv << name << ',' << mesh.points.size() << ',' << mesh.tetrahedra.size() << ',' << kv_string(kvs[k])
            << ',' << targets[t] << ',' << r.removed << ',' << fixed(rp, 2) << ',' << r.first_round << ','
            << fixed(fp, 2) << ',' << fixed(r.seconds, 4) << ',' << fixed(tp, 2) << ',' << r.max_queue << ','
            << r.peak_rss_bytes << ',' << r.rounds << ',' << r.output_tetrahedra << ',' << r.blocked_leaves
            << ',' << r.blocked_boundary << ',' << r.blocked_flip << ',' << r.blocked_link << '\n';
      }
      std::cout << '\n';
    }
  }
  if (!csv_file.empty()) {
    std::ofstream f(csv_file);
    f << csv.str();
    if (!f) {
      std::cerr << csv_file << ": cannot write\n";
      return 1;
    }
  }
  return 0;
}
