// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The cost of the bucket threshold k_v (issue 24: k_v chosen by itself): for each mesh and k_v,
// the build and the applications (boundary, curvature, validity, VT and the edges of every leaf)
// on 1 and 2 threads, the bytes per tetrahedron and the largest leaf's working set; then the k_v
// that `choose_bucket_size()` picks for the mesh and how far each application's time at that k_v
// is from its best over the sweep.  Times are the minimum of several repetitions in one process
// after a warm-up.
//
// usage: bench_bucket_size [--kv 16,32,...] [--reps R] [--threads 1,2] [--apps build,...,counts]
//                          [--csv OUT.csv] [--calibrate] MESH...
// (`counts` is count_simplices(), not in the default list)
// Prints a Markdown table on stdout.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/Leaf_executor.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/distortion.h>
#include <CGAL/PR_star_octree/validity.h>
#include <CGAL/property_map.h>

#include "bench_util.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace P = CGAL::PR_star_octree;
using Mesh = P::Indexed_tetrahedral_mesh<>;
using Octree = CGAL::PR_star_octree_3<>;
using Local = P::Leaf_topology<Octree>;

using prstar_bench::base_name;
using prstar_bench::best_of;
using prstar_bench::kv_name;

const char* const usage =
    "usage: bench_bucket_size [--kv 16,32,...] [--reps R] [--threads 1,2] [--apps "
    "build,boundary,curvature,validity,VT,edges,counts] [--csv OUT.csv] [--calibrate] MESH...\n";

std::vector<std::size_t> parse_list(const std::string& s) {
  std::vector<std::size_t> r;
  std::stringstream in(s);
  for (std::string x; std::getline(in, x, ',');) r.push_back(std::stoull(x));
  return r;
}

// The applications timed at each k_v, in the columns' order.
std::vector<std::string> applications = {"build", "boundary", "curvature", "validity", "VT", "edges"};

// The relations each application's leaves build (what its automatic k_v is sized for).
unsigned relations_of(const std::string& app) {
  if (app == "curvature") return P::compute_curvature_relations;
  if (app == "VT") return P::VERTEX_TETRAHEDRA;
  if (app == "edges") return P::EDGES;
  if (app == "counts") return P::count_simplices_relations;
  return P::VERTEX_LINKS | P::TRIANGLES; // build (the default), boundary, validity
}

// One application's time on `tree` (the build: of `tree` itself from `mesh`).
double time_application(const std::string& app, const Mesh& mesh, const Octree& tree, std::size_t kv,
                        int reps) {
  const std::size_t nv = tree.number_of_vertices();
  if (app == "build")
    return best_of(reps, [&] {
      Octree t(P::make_input(mesh), P::parameters::bucket_size(kv));
      if (t.number_of_vertices() != nv) std::abort();
    });
  if (app == "boundary") {
    std::vector<P::Vertex_type> types(nv);
    return best_of(reps, [&] { P::compute_boundary(tree, CGAL::make_property_map(types)); });
  }
  if (app == "curvature") {
    std::vector<P::Vertex_curvature> curv(nv);
    return best_of(reps, [&] {
      P::compute_curvature(tree, P::coordinate_field_map(tree, 2), CGAL::make_property_map(curv));
    });
  }
  if (app == "counts")
    return best_of(reps, [&] {
      if (P::count_simplices(tree).tetrahedra != tree.number_of_tetrahedra()) std::abort();
    });
  if (app == "validity")
    return best_of(reps, [&] {
      if (P::check_validity(tree).tetrahedra != tree.number_of_tetrahedra()) std::abort();
    });
  const unsigned relations = app == "VT" ? unsigned(P::VERTEX_TETRAHEDRA) : unsigned(P::EDGES);
  std::size_t sum = 0;
  const double t = best_of(reps, [&] {
    sum = 0;
    P::Leaf_executor<> ex;
    ex.map_reduce(
        tree, relations, 0,
        [&](int&, const Local& local) -> std::size_t {
          std::size_t s = 0;
          if (relations == P::VERTEX_TETRAHEDRA)
            for (auto v = local.vertex_begin(); v != local.vertex_end(); ++v)
              s += local.vertex_tetrahedra(v).size();
          else
            s = local.number_of_edges();
          return s;
        },
        [&](std::size_t s) { sum += s; });
  });
  if (sum == 0 && tree.number_of_tetrahedra() > 0) std::abort();
  return t;
}

// The largest working set of a leaf (the bytes `Leaf_topology` holds after building `relations`).
std::size_t largest_working_set(const Octree& tree, unsigned relations) {
  Local local;
  std::size_t m = 0;
  for (auto n : tree.leaves()) {
    local.build(tree, n, relations);
    m = (std::max)(m, local.memory_bytes());
  }
  return m;
}

// The calibration of the cost model of `choose_bucket_size()`: for the leaf listing the most
// tetrahedra, its tetrahedra per vertex of capacity (gamma: listed tetrahedra / (k_v |T| / |V|)) and
// the bytes `Leaf_topology` holds per listed tetrahedron for each relation built alone.
void calibrate(const std::string& name, const Mesh& mesh, const std::vector<std::size_t>& kvs) {
  for (std::size_t kv : kvs) {
    const Octree tree(P::make_input(mesh), P::parameters::bucket_size(kv));
    Octree::Node_index largest = tree.leaves().front();
    for (auto n : tree.leaves())
      if (tree.node(n).number_of_tetrahedra() > tree.node(largest).number_of_tetrahedra()) largest = n;
    const double nt = double(tree.node(largest).number_of_tetrahedra());
    const double tau = double(tree.number_of_tetrahedra()) / double(tree.number_of_vertices());
    std::printf("| %s | %s | %.2f | %zu | %.0f | %.3f", name.c_str(), kv_name(kv).c_str(), tau,
                tree.node(largest).number_of_vertices(), nt, nt / (double(kv) * tau));
    for (int i = 0; i < 7; ++i) {
      const Local local(tree, largest, 1u << i);
      std::printf(" | %.1f", double(local.memory_bytes()) / nt);
    }
    std::printf(" |\n");
  }
}

} // namespace

int main(int argc, char** argv) {
  std::vector<std::size_t> kvs = {16, 32, 64, 128, 256, 512, 1024, 2048};
  std::vector<std::size_t> thread_counts = {1, 2};
  int reps = 3;
  bool calibration = false;
  std::string csv_file;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--reps" && i + 1 < argc)
      reps = std::max(1, std::atoi(argv[++i]));
    else if (a == "--csv" && i + 1 < argc)
      csv_file = argv[++i];
    else if (a == "--kv" && i + 1 < argc)
      kvs = prstar_bench::parse_kv_list(argv[++i]);
    else if (a == "--apps" && i + 1 < argc) {
      applications.clear();
      std::stringstream in(argv[++i]);
      for (std::string x; std::getline(in, x, ',');) applications.push_back(x);
    } else if (a == "--calibrate")
      calibration = true;
    else if (a == "--threads" && i + 1 < argc)
      thread_counts = parse_list(argv[++i]);
    else if (!a.empty() && a[0] == '-') {
      std::cerr << usage;
      return 2;
    } else
      files.push_back(a);
  }
  if (files.empty()) {
    std::cerr << usage;
    return 2;
  }

  std::ostringstream csv;
  csv << "mesh,vertices,tetrahedra,kv,threads,leaves,chi,bytes_per_tet,compact_bytes_per_tet,ws_vt_bytes,ws_"
         "edges_bytes";
  for (const auto& a : applications) csv << ',' << a << "_seconds";
  csv << ",chosen_kv\n";
  std::cout
      << "| mesh | |T| | k_v | threads | leaves | chi | B/tet | B/tet compact | largest leaf VT / edges KiB";
  for (const auto& a : applications) std::cout << " | " << a << " s";
  std::cout << " |\n|---|---:|---:|---:|---:|---:|---:|---:|---:";
  for (std::size_t i = 0; i < applications.size(); ++i) std::cout << "|---:";
  std::cout << "|\n";

  for (const std::string& file : files) {
    Mesh mesh;
    if (!prstar_bench::read_mesh_file(file, mesh)) return 1;
    const std::string name = base_name(file);
    if (calibration) {
      if (&file == &files.front())
        std::cout
            << "| mesh | k_v | |T|/|V| | largest leaf: vertices | tetrahedra | gamma | bytes per listed "
               "tetrahedron: VT | TT | VV | edges | triangles | links | local "
               "|\n|---|---:|---:|---:|---:|---:|"
               "---:|---:|---:|---:|---:|---:|---:|\n";
      calibrate(name, mesh, kvs);
      continue;
    }
    std::map<std::string, std::size_t> chosen; // the automatic k_v of each application
    for (const auto& a : applications)
      chosen[a] =
          P::choose_bucket_size(mesh.points.size(), mesh.tetrahedra.size(), relations_of(a)).bucket_size;
    // [threads][application] -> (k_v, seconds) of the sweep
    std::map<std::size_t, std::map<std::string, std::vector<std::pair<std::size_t, double>>>> sweep;
    for (std::size_t kv : kvs) {
      const Octree tree(P::make_input(mesh), P::parameters::bucket_size(kv));
      const P::Statistics s = tree.statistics();
      const Octree compact(P::make_input(mesh), P::parameters::bucket_size(kv).compact_tetrahedra(true));
      const double compact_bpt = compact.statistics().bytes_per_tetrahedron_without_permutations();
      const std::size_t ws_vt = largest_working_set(tree, P::VERTEX_TETRAHEDRA);
      const std::size_t ws_edges = largest_working_set(tree, P::EDGES);
      for (std::size_t threads : thread_counts) {
#ifdef CGAL_LINKED_WITH_TBB
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
#endif
        std::vector<double> t;
        for (const auto& a : applications) {
          t.push_back(time_application(a, mesh, tree, kv, reps));
          sweep[threads][a].emplace_back(kv, t.back());
        }
        char row[512];
        std::snprintf(row, sizeof row, "| %s | %zu | %s | %zu | %zu | %.3f | %.2f | %.2f | %.0f / %.0f",
                      name.c_str(), s.tetrahedra, kv_name(kv).c_str(), threads, s.leaves, s.chi,
                      s.bytes_per_tetrahedron_without_permutations(), compact_bpt, ws_vt / 1024.,
                      ws_edges / 1024.);
        std::cout << row;
        for (double x : t) std::printf(" | %.4f", x);
        std::cout << " |" << std::endl;
        csv << name << ',' << s.vertices << ',' << s.tetrahedra << ',' << kv_name(kv) << ',' << threads << ','
            << s.leaves << ',' << s.chi << ',' << s.bytes_per_tetrahedron_without_permutations() << ','
            << compact_bpt << ',' << ws_vt << ',' << ws_edges;
        for (double x : t) csv << ',' << x;
        csv << ',' << chosen["boundary"] << '\n';
      }
    }
    // How far the chosen k_v is from the best of the sweep, per application and thread count.
    std::cout << "\n"
              << name
              << ": the automatic k_v of each application (its own relations), its time over the "
                 "best of the sweep\n\n| threads";
    for (const auto& a : applications) std::cout << " | " << a << ": auto k_v, best k_v, auto/best";
    std::cout << " |\n|---:";
    for (std::size_t i = 0; i < applications.size(); ++i) std::cout << "|---";
    std::cout << "|\n";
    for (auto& [threads, apps] : sweep) {
      std::cout << "| " << threads;
      for (const auto& a : applications) {
        const auto& v = apps[a];
        auto best =
            std::min_element(v.begin(), v.end(), [](auto& x, auto& y) { return x.second < y.second; });
        // the chosen k_v's own time (measured when it is in the sweep, else the nearest k_v's)
        const double k = double(chosen[a]);
        auto near = std::min_element(v.begin(), v.end(), [&](auto& x, auto& y) {
          return std::abs(std::log(double(x.first) / k)) < std::abs(std::log(double(y.first) / k));
        });
        char cell[160];
        std::snprintf(cell, sizeof cell, " | %zu, %s, %.2f%s", chosen[a], kv_name(best->first).c_str(),
                      near->second / best->second, near->first == chosen[a] ? "" : " (nearest)");
        std::cout << cell;
      }
      std::cout << " |\n";
    }
    std::cout << std::endl;
  }
  if (!csv_file.empty() && !prstar_bench::write_text_file(csv_file, csv.str())) return 1;
  return 0;
}
