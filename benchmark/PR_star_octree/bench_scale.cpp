// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// bench_scale: the PR-star octree from 1M to 100M tetrahedra (issue 10, item 7).
//
// usage: bench_scale [--cells 55,120,203,260] [--threads 1,2] [--kv auto|K] [--storage S,...] [--cgal-max T]
//                    [--keep] DIR
//   For each N of --cells, makes DIR/lattice_N.vtu with `prstar generate --shape lattice --cells N`
//   (a jittered Kuhn lattice, 6 N^3 tetrahedra, a scalar field, raw binary VTU; kept if present).
//   Then, for each thread count, three forked children each read the file and build the octree in
//   place as the prstar command does without an output file (k_v = --kv, default auto, sized for the
//   application's relations as the tool sizes it; no permutations), then run one application: boundary
//   (compute_boundary, the paper's link count plus the link check), curvature
//   (compute_curvature of the scalar field: discrete distortion), stats (statistics() and
//   count_simplices).  Reported per child: read, build and application seconds, its peak RSS, and
//   the structure's bytes (B/tet as prstar stats reports it, with its breakdown; peak RSS / structure);
//   per size, the speed-up of 2 threads over 1.  --storage lists how the octree stores the mesh, one
//   set of rows each (default plain): plain (four 32-bit indices per tetrahedron, the file's
//   coordinates: doubles here), compact (`compact_tetrahedra`), float32 (`coordinate_precision`
//   float32) or compact+float32.
//   The children with more threads must give the same counts (checked, "MISMATCH" otherwise).
//   CGAL's Triangulation_3 (the baseline of bench_relations) is built on the meshes of at most
//   --cgal-max tetrahedra (default 11M): build seconds, bytes, peak RSS, B/tet; the number of
//   tetrahedra at which it and the octree stop fitting in this machine's memory is extrapolated from
//   the measured peak B/tet.  Prints Markdown tables on stdout.  Files removed unless --keep.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/Leaf_topology.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/distortion.h>
#include <CGAL/PR_star_octree/parameters.h>
#include <CGAL/property_map.h>

#include "baselines/Cgal_triangulation_baseline.h"
#include "bench_util.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#ifndef PRSTAR_EXECUTABLE
#define PRSTAR_EXECUTABLE "prstar"
#endif

namespace {

using namespace prstar_bench;
using Octree = CGAL::PR_star_octree_3<>;
using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;
namespace params = CGAL::PR_star_octree::parameters;
namespace fs = std::filesystem;

enum Application { BOUNDARY, CURVATURE, STATS };
const char* const application_name[] = {"boundary", "curvature", "stats"};

struct Result {
  bool ok = false;
  std::size_t peak_rss_bytes = 0;
  double read_s = 0, build_s = 0, application_s = 0;
  std::size_t vertices = 0, tetrahedra = 0, structure_bytes = 0, kv = 0;
  prstar_bench::Bytes_per_tetrahedron bpt;
  std::size_t check[3] = {0, 0, 0}; // counts that must not depend on the number of threads
  double value = 0;                 // the same (sum of the distortions)
};

// The curvature results the benchmark keeps: 9 bytes per vertex (each vertex written by one thread).
struct Curvature_arrays {
  std::vector<std::uint8_t> type;
  std::vector<double> distortion;
  struct Map {
    using key_type = std::size_t;
    using value_type = CGAL::PR_star_octree::Vertex_curvature;
    using reference = value_type;
    using category = boost::writable_property_map_tag;
    Curvature_arrays* a;
    friend void put(const Map& m, std::size_t v, const value_type& c) {
      m.a->type[v] = static_cast<std::uint8_t>(c.type);
      m.a->distortion[v] = c.distortion;
    }
  };
};

struct Storage {
  std::string name;
  bool compact, float32;
};

Storage parse_storage(const std::string& s) {
  if (s == "plain") return {s, false, false};
  if (s == "compact") return {s, true, false};
  if (s == "float32") return {s, false, true};
  if (s == "compact+float32") return {s, true, true};
  throw std::invalid_argument(
      "bench_scale: --storage takes plain, compact, float32 or compact+float32, not '" + s + "'");
}

Result run(const std::string& file, std::size_t kv, std::size_t threads, Application app,
           const Storage& storage) {
#ifdef CGAL_LINKED_WITH_TBB
  tbb::global_control control(tbb::global_control::max_allowed_parallelism, threads);
#else
  (void)threads;
#endif
  Result r;
  double t0 = now();
  Mesh mesh;
  CGAL::PR_star_octree::IO::read_tetrahedral_mesh(file, mesh);
  r.read_s = now() - t0;
  t0 = now();
  // the relations the tool sizes the automatic k_v for: curvature's links and local tetrahedra,
  // the default (links, triangles) for boundary and stats
  const unsigned relations = app == CURVATURE ? CGAL::PR_star_octree::compute_curvature_relations
                                              : CGAL::PR_star_octree::default_bucket_size_relations;
  const Octree tree(std::move(mesh),
                    params::bucket_size(kv)
                        .bucket_size_relations(relations)
                        .vertex_permutation(false)
                        .tetrahedron_permutation(false)
                        .compact_tetrahedra(storage.compact)
                        .coordinate_precision(storage.float32
                                                  ? CGAL::PR_star_octree::Coordinate_precision::float32
                                                  : CGAL::PR_star_octree::Coordinate_precision::as_input));
  r.build_s = now() - t0;
  r.vertices = tree.number_of_vertices();
  r.tetrahedra = tree.number_of_tetrahedra();
  const auto stats = tree.statistics();
  r.structure_bytes = stats.bytes.without_permutations();
  r.bpt = prstar_bench::Bytes_per_tetrahedron(stats);
  r.kv = stats.bucket_size;
  t0 = now();
  if (app == BOUNDARY) {
    std::vector<CGAL::PR_star_octree::Vertex_type> types(tree.number_of_vertices());
    const auto b = CGAL::PR_star_octree::compute_boundary(tree, CGAL::make_property_map(types));
    r.check[0] = b.boundary_vertices;
    r.check[1] = b.boundary_triangles;
    r.check[2] = b.nonmanifold_vertices;
  } else if (app == CURVATURE) {
    Curvature_arrays c{std::vector<std::uint8_t>(tree.number_of_vertices()),
                       std::vector<double>(tree.number_of_vertices())};
    const auto counts = CGAL::PR_star_octree::compute_curvature(
        tree, CGAL::PR_star_octree::scalar_field_map(tree), Curvature_arrays::Map{&c});
    r.check[0] = counts.boundary_vertices;
    r.check[1] = counts.interior_vertices;
    for (double d : c.distortion)
      if (std::isfinite(d)) r.value += d;
  } else {
    const auto counts = CGAL::PR_star_octree::count_simplices(tree);
    r.check[0] = counts.edges;
    r.check[1] = counts.triangles;
    r.check[2] = counts.boundary_triangles;
  }
  r.application_s = now() - t0;
  return r;
}

struct Cgal_result {
  bool ok = false;
  std::size_t peak_rss_bytes = 0;
  double build_s = 0;
  std::size_t bytes = 0, tetrahedra = 0;
};

std::vector<std::size_t> parse_list(const std::string& s) {
  std::vector<std::size_t> r;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) r.push_back(std::stoull(item));
  return r;
}

std::string fixed(double x, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << x;
  return s.str();
}

std::string mb(std::size_t bytes) {
  return fixed(double(bytes) / double(1 << 20), 0);
}

std::size_t mem_total_bytes() {
  std::ifstream f("/proc/meminfo");
  std::string key;
  std::size_t kib = 0;
  while (f >> key >> kib)
    if (key == "MemTotal:") return kib * 1024;
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  const char* const usage = "usage: bench_scale [--cells N,...] [--threads T,...] [--kv auto|K] [--storage "
                            "plain|compact|float32|compact+float32,...] [--cgal-max T] [--keep] DIR\n";
  std::vector<std::size_t> cells{55, 120, 203, 260}, threads{1, 2};
  std::size_t kv = prstar_bench::automatic_kv, cgal_max = 11000000;
  bool keep = false;
  std::string dir;
  std::vector<Storage> storages{parse_storage("plain")};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--cells" && i + 1 < argc)
      cells = parse_list(argv[++i]);
    else if (a == "--threads" && i + 1 < argc)
      threads = parse_list(argv[++i]);
    else if (a == "--kv" && i + 1 < argc)
      kv = prstar_bench::parse_kv_list(argv[++i]).front();
    else if (a == "--storage" && i + 1 < argc) {
      storages.clear();
      std::stringstream list(argv[++i]);
      for (std::string item; std::getline(list, item, ',');) storages.push_back(parse_storage(item));
    } else if (a == "--cgal-max" && i + 1 < argc)
      cgal_max = std::stoull(argv[++i]);
    else if (a == "--keep")
      keep = true;
    else if (!a.empty() && a[0] != '-' && dir.empty())
      dir = a;
    else {
      std::cerr << usage;
      return 2;
    }
  }
  if (dir.empty()) {
    std::cerr << usage;
    return 2;
  }
  fs::create_directories(dir);
  const std::size_t ram = mem_total_bytes();

  std::cout << "| tetrahedra | threads | application | storage | k_v | read s | build s | application s | "
               "total s | "
               "peak RSS MB | "
               "structure MB | B/tet | B/tet breakdown | peak / structure | speed-up build | speed-up "
               "application |\n"
               "|---:|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|\n";
  std::vector<std::string> cgal_rows;
  double octree_peak_per_tet = 0;
  for (std::size_t n : cells) {
    const std::string file = dir + "/lattice_" + std::to_string(n) + ".vtu";
    if (!fs::exists(file)) {
      const std::string cmd = std::string(PRSTAR_EXECUTABLE) + " generate --shape lattice --cells " +
                              std::to_string(n) + " -o " + file + " --quiet";
      if (std::system(cmd.c_str()) != 0) {
        std::cerr << "bench_scale: '" << cmd << "' failed\n";
        return 1;
      }
    }
    for (Application app : {BOUNDARY, CURVATURE, STATS})
      for (const Storage& storage : storages) {
        Result first{};
        for (std::size_t t : threads) {
          const Result r = in_child<Result>([&] { return run(file, kv, t, app, storage); });
          if (!r.ok) {
            std::cout << "| " << 6 * n * n * n << " | " << t << " | " << application_name[app] << " | "
                      << storage.name << " | failed |\n";
            continue;
          }
          const bool same =
              t == threads.front() || (r.check[0] == first.check[0] && r.check[1] == first.check[1] &&
                                       r.check[2] == first.check[2] && r.value == first.value);
          if (t == threads.front()) first = r;
          if (n == cells.back()) // the largest mesh: fixed costs (threads, buffers) matter least
            octree_peak_per_tet =
                std::max(octree_peak_per_tet, double(r.peak_rss_bytes) / double(r.tetrahedra));
          std::cout << "| " << r.tetrahedra << " | " << t << " | " << application_name[app]
                    << (same ? "" : " MISMATCH") << " | " << storage.name << " | "
                    << (kv == prstar_bench::automatic_kv ? "auto " : "") + std::to_string(r.kv) << " | "
                    << fixed(r.read_s, 2) << " | " << fixed(r.build_s, 2) << " | "
                    << fixed(r.application_s, 2) << " | " << fixed(r.read_s + r.build_s + r.application_s, 2)
                    << " | " << mb(r.peak_rss_bytes) << " | " << mb(r.structure_bytes) << " | "
                    << fixed(double(r.structure_bytes) / double(r.tetrahedra), 1) << " | "
                    << r.bpt.breakdown() << " | "
                    << fixed(double(r.peak_rss_bytes) / double(r.structure_bytes), 2) << " | "
                    << (t == threads.front() ? "" : fixed(first.build_s / r.build_s, 2)) << " | "
                    << (t == threads.front() ? "" : fixed(first.application_s / r.application_s, 2)) << " |"
                    << std::endl;
        }
      }
    if (6 * n * n * n <= cgal_max) {
      const Cgal_result c = in_child<Cgal_result>([&] {
        Mesh mesh;
        CGAL::PR_star_octree::IO::read_tetrahedral_mesh(file, mesh);
        const std::size_t before = status_kib("VmRSS:") * 1024;
        Cgal_result r;
        const double t0 = now();
        prstar_baselines::Cgal_triangulation_baseline cgal(mesh.points, mesh.tetrahedra);
        r.build_s = now() - t0;
        r.bytes = cgal.memory_bytes();
        r.tetrahedra = mesh.tetrahedra.size();
        (void)before;
        return r;
      });
      if (c.ok)
        cgal_rows.push_back(
            "| " + std::to_string(c.tetrahedra) + " | " + fixed(c.build_s, 2) + " | " + mb(c.bytes) + " | " +
            fixed(double(c.bytes) / double(c.tetrahedra), 1) + " | " + mb(c.peak_rss_bytes) + " | " +
            fixed(double(c.peak_rss_bytes) / double(c.tetrahedra), 1) + " | " +
            fixed(double(ram) / (double(c.peak_rss_bytes) / double(c.tetrahedra)) / 1e6, 0) + " |");
    }
    if (!keep) fs::remove(file);
  }
  if (!cgal_rows.empty()) {
    std::cout << "\nCGAL Triangulation_3 (the baseline of bench_relations: the mesh's cells and adjacencies, "
                 "infinite cells coning the boundary), one thread:\n\n"
                 "| tetrahedra | build s | structure MB | B/tet | peak RSS MB (mesh + triangulation) | peak "
                 "B/tet | fits up to (M tetrahedra, extrapolated) |\n|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& row : cgal_rows) std::cout << row << '\n';
  }
  if (octree_peak_per_tet > 0)
    std::cout << "\nPR-star octree (lean construction, k_v = " << prstar_bench::kv_name(kv) << "): peak "
              << fixed(octree_peak_per_tet, 1) << " B/tet at most, so it fits up to about "
              << fixed(double(ram) / octree_peak_per_tet / 1e6, 0) << "M tetrahedra in this machine's "
              << mb(ram) << " MB (extrapolated)\n";
  return 0;
}
