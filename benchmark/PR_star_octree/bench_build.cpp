// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Table 1 of the paper on the given meshes: |N|, |N_leaf|, chi, the cost model, the bytes really
// used, and the build time of the PR-star octree from the index arrays, for several k_v.  Times are
// the minimum of several repetitions in one process after a warm-up.
//
// usage: bench_build [--kv 10,20,...,inf] [--reps R] [--csv OUT.csv] MESH...
// Prints a Markdown table on stdout.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>

#include "bench_util.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;
using Octree = CGAL::PR_star_octree_3<>;

using prstar_bench::base_name;
using prstar_bench::kv_name;
using prstar_bench::now;

// Peak resident set size of this process, in bytes (Linux).
std::size_t peak_rss() {
  return prstar_bench::status_kib("VmHWM:") * 1024;
}

} // namespace

int main(int argc, char** argv) {
  std::vector<std::size_t> kvs = {10, 20, 50, 100, 200, 400, 800, Octree::infinite_bucket_size};
  int reps = 3;
  std::string csv_file;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--reps" && i + 1 < argc)
      reps = std::max(1, std::atoi(argv[++i]));
    else if (a == "--csv" && i + 1 < argc)
      csv_file = argv[++i];
    else if (a == "--kv" && i + 1 < argc) {
      kvs = prstar_bench::parse_kv_list(argv[++i]);
    } else if (!a.empty() && a[0] == '-') {
      std::cerr << "usage: bench_build [--kv 10,20,...,inf] [--reps R] [--csv OUT.csv] MESH...\n";
      return 2;
    } else
      files.push_back(a);
  }
  if (files.empty()) {
    std::cerr << "usage: bench_build [--kv 10,20,...,inf] [--reps R] [--csv OUT.csv] MESH...\n";
    return 2;
  }

  std::ostringstream csv;
  csv << "mesh,vertices,tetrahedra,kv,nodes,leaves,depth,chi,prstar_overhead_per_vertex,prstar_total_per_"
         "vertex,"
         "ia_overhead_per_vertex,ia_total_per_vertex,index_bytes,total_bytes,build_seconds,peak_rss_bytes\n";
  std::cout
      << "| mesh | |V| | |T| | k_v | |N| | |N_leaf| | depth | chi | PR-star overhead/|V| | PR-star total/|V| "
         "| IA overhead/|V| | IA total/|V| | index bytes | bytes/tet (all) | build s |\n"
      << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const std::string& file : files) {
    Mesh mesh;
    try {
      CGAL::PR_star_octree::IO::read_tetrahedral_mesh(file, mesh);
    } catch (const std::exception& e) {
      std::cerr << e.what() << '\n';
      return 1;
    }
    const std::string name = base_name(file);
    for (std::size_t kv : kvs) {
      double best = std::numeric_limits<double>::infinity();
      CGAL::PR_star_octree::Statistics s;
      for (int r = 0; r <= reps; ++r) { // r = 0 is the warm-up
        const double t0 = now();
        Octree tree(CGAL::PR_star_octree::make_input(mesh),
                    CGAL::PR_star_octree::parameters::bucket_size(kv));
        const double t = now() - t0;
        if (r > 0) best = std::min(best, t);
        if (r == reps) s = tree.statistics();
      }
      char row[1024];
      std::snprintf(row, sizeof row,
                    "| %s | %zu | %zu | %s | %zu | %zu | %zu | %.3f | %.2f | %.2f | %.2f | %.2f | %zu | %.1f "
                    "| %.4f |\n",
                    name.c_str(), s.vertices, s.tetrahedra, kv_name(kv).c_str(), s.nodes, s.leaves, s.depth,
                    s.chi, s.prstar_overhead_per_vertex, s.prstar_total_per_vertex, s.ia_overhead_per_vertex,
                    s.ia_total_per_vertex, s.bytes.index(),
                    s.tetrahedra ? double(s.bytes.total()) / double(s.tetrahedra) : 0., best);
      std::cout << row;
      csv << name << ',' << s.vertices << ',' << s.tetrahedra << ',' << kv_name(kv) << ',' << s.nodes << ','
          << s.leaves << ',' << s.depth << ',' << s.chi << ',' << s.prstar_overhead_per_vertex << ','
          << s.prstar_total_per_vertex << ',' << s.ia_overhead_per_vertex << ',' << s.ia_total_per_vertex
          << ',' << s.bytes.index() << ',' << s.bytes.total() << ',' << best << ',' << peak_rss() << '\n';
    }
  }
  if (!csv_file.empty() && !prstar_bench::write_text_file(csv_file, csv.str())) return 1;
  return 0;
}
