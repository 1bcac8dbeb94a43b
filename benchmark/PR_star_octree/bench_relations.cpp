// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Tables 1 and 2 of the paper, side by side in one run: for each mesh, the PR-star octree for
// several k_v, the extended IA data structure and CGAL's Triangulation_3 built from the same arrays:
// build time, bytes really used, peak RSS, and the time to extract VT (the star of every vertex),
// plus one plain streaming pass over T (the memory-bandwidth floor).
//
// The baselines are measured twice: on the file's order and on the PR-star order (the mesh
// re-indexed by the octree with k_v = 100), because a locality-friendly order alone speeds them up.
//
// Each structure is built and queried in a child process (fork), so that its peak RSS is its own.
// Times are the minimum of several repetitions after a warm-up.
//
// Bytes: for the PR-star octree, the figure of `prstar stats` for the same mesh and k_v
// (Statistics::bytes_per_tetrahedron_without_permutations(): the octree measured keeps the vertex
// and tetrahedron permutations its queries answer through, which `prstar stats` does not build),
// with its breakdown and the permutations kept beside it; the baselines' bytes are their own.
//
// With --compact, every k_v has a second PR-star row, "PR-star compact": the octree with the
// compact tetrahedron array (named parameter `compact_tetrahedra`), the same queries.
//
// Times are the minimum of --reps repetitions inside each child.  With --rounds N, every child runs
// N times, the whole sequence of structures one round after the other, and each time is the
// minimum over the rounds: on a shared machine, whose slow spells last seconds, one round can
// favour a structure by 20% or more.
//
// usage: bench_relations [--kv auto,10,20,...,inf] [--reps R] [--rounds N] [--threads N]
//                        [--no-cgal] [--compact] [--csv OUT.csv] MESH...

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/Leaf_topology.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/distortion.h>
#include <CGAL/property_map.h>

#include <cmath>

#include "bench_util.h"
#include "baselines/Cgal_triangulation_baseline.h"
#include "baselines/Extended_IA.h"
#include "baselines/curvature_baselines.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

using prstar_bench::base_name;
using prstar_bench::best_of;
using prstar_bench::kv_name;
using prstar_bench::now;

using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;
using Octree = CGAL::PR_star_octree_3<>;
using Local = CGAL::PR_star_octree::Leaf_topology<Octree>;
using Index = std::uint32_t;

// What one child process measures.
struct Result {
  double build_seconds = 0;
  double vt_seconds = 0;
  double distortion_seconds = 0;           // discrete distortion of every vertex (boundary test included)
  double boundary_seconds = 0;             // boundary / interior classification of every vertex
  double boundary_count_seconds = 0;       // PR-star: the paper's count alone, without the link proof
  double distortion_sum = 0;               // over manifold vertices: must agree across structures
  std::size_t bytes = 0;                   // the whole structure, V and T included (PR-star: as prstar stats)
  prstar_bench::Bytes_per_tetrahedron bpt; // PR-star: the breakdown of bytes / |T|
  std::size_t kv = 0;                      // PR-star: the k_v used (the chosen one for "auto")
  std::size_t overhead_bytes = 0;          // the topological part only
  std::size_t peak_rss_bytes = 0;          // peak RSS growth during build + queries
  std::size_t checksum = 0;                // sum over all VT of the star sizes (must agree across structures)
  std::size_t checksum2 = 0;
  std::size_t nodes = 0, leaves = 0;
  double chi = 0, cost_overhead = 0, cost_total = 0;
  bool ok = false;
};

// The scalar field: the mesh's own (first point-data array), else x^2 + sin(3y) + z.
std::vector<double> field_values(const Mesh& m) {
  if (m.scalar_field()) return m.scalar_field()->values;
  std::vector<double> f(m.points.size());
  for (std::size_t v = 0; v < f.size(); ++v)
    f[v] = m.points[v].x() * m.points[v].x() + std::sin(3 * m.points[v].y()) + m.points[v].z();
  return f;
}

template <class Curvatures>
double manifold_sum(const Curvatures& c) {
  double s = 0;
  for (const auto& x : c)
    if (std::isfinite(x.distortion)) s += x.distortion;
  return s;
}

std::size_t mesh_bytes(const Mesh& m) {
  return m.points.capacity() * sizeof(Mesh::Point_3) + m.tetrahedra.capacity() * sizeof(Mesh::Tetrahedron);
}

Result run_prstar(const Mesh& mesh, std::size_t kv, int reps, bool compact) {
  Result r;
  std::unique_ptr<Octree> tree;
  r.build_seconds = best_of(reps, [&] {
    tree = std::make_unique<Octree>(
        CGAL::PR_star_octree::make_input(mesh),
        CGAL::PR_star_octree::parameters::bucket_size(kv).compact_tetrahedra(compact));
  });
  const auto s = tree->statistics();
  r.nodes = s.nodes;
  r.leaves = s.leaves;
  r.chi = s.chi;
  r.cost_overhead = s.prstar_overhead_per_vertex;
  r.cost_total = s.prstar_total_per_vertex;
  r.bytes = s.bytes.without_permutations();
  r.bpt = prstar_bench::Bytes_per_tetrahedron(s);
  r.kv = s.bucket_size;
  r.overhead_bytes = s.bytes.index();
  std::size_t local_bytes = 0;
  r.vt_seconds = best_of(reps, [&] {
    std::size_t sum = 0;
    CGAL::PR_star_octree::for_each_leaf(*tree, CGAL::PR_star_octree::VERTEX_TETRAHEDRA,
                                        [&](const Local& local) {
                                          for (Index v = local.vertex_begin(); v < local.vertex_end(); ++v)
                                            sum += local.vertex_tetrahedra(v).size();
                                          local_bytes = std::max(local_bytes, local.memory_bytes());
                                        });
    r.checksum = sum;
  });
  // Distortion and boundary through the public API: the field and the results in the user's order.
  namespace params = CGAL::PR_star_octree::parameters;
  const std::vector<double> f = field_values(mesh);
  std::vector<CGAL::PR_star_octree::Vertex_curvature> curvature(mesh.points.size());
  r.distortion_seconds = best_of(reps, [&] {
    CGAL::PR_star_octree::compute_curvature(*tree, CGAL::make_property_map(f),
                                            CGAL::make_property_map(curvature));
    r.distortion_sum = manifold_sum(curvature);
  });
  std::vector<CGAL::PR_star_octree::Vertex_type> types(mesh.points.size());
  r.boundary_seconds = best_of(reps, [&] {
    const auto b = CGAL::PR_star_octree::compute_boundary(*tree, CGAL::make_property_map(types),
                                                          params::with_boundary_triangles(false));
    if (b.unreferenced_vertices == mesh.points.size() && mesh.points.size()) r.ok = false;
  });
  r.boundary_count_seconds = best_of(reps, [&] {
    const auto b = CGAL::PR_star_octree::compute_boundary(
        *tree, CGAL::make_property_map(types), params::with_boundary_triangles(false).check_links(false));
    if (b.unreferenced_vertices == mesh.points.size() && mesh.points.size()) r.ok = false;
  });
  return r;
}

Result run_ia(const Mesh& mesh, int reps) {
  Result r;
  std::unique_ptr<prstar_baselines::Extended_IA<Index>> ia;
  r.build_seconds = best_of(reps, [&] {
    ia = std::make_unique<prstar_baselines::Extended_IA<Index>>(mesh.points.size(), mesh.tetrahedra);
  });
  r.overhead_bytes = ia->overhead_bytes();
  r.bytes = r.overhead_bytes + mesh_bytes(mesh);
  const double V = double(mesh.points.size()), T = double(mesh.tetrahedra.size());
  r.cost_overhead = (4 * T + V) / V;
  r.cost_total = (8 * T + 4 * V) / V;
  std::vector<Index> star, stack;
  r.vt_seconds = best_of(reps, [&] {
    std::size_t sum = 0;
    for (Index v = 0; v < mesh.points.size(); ++v) {
      ia->vertex_tetrahedra(v, star, stack);
      sum += star.size();
    }
    r.checksum = sum;
  });
  const std::vector<double> f = field_values(mesh);
  r.distortion_seconds = best_of(reps, [&] {
    const auto c =
        prstar_baselines::ia_curvature(mesh.points, mesh.tetrahedra, *ia, [&](Index v) { return f[v]; });
    r.distortion_sum = manifold_sum(c);
  });
  r.boundary_seconds = best_of(reps, [&] {
    const auto b = prstar_baselines::ia_boundary(*ia);
    if (b.size() != mesh.points.size()) r.ok = false;
  });
  return r;
}

Result run_cgal(const Mesh& mesh, int reps) {
  Result r;
  const double t0 = now();
  prstar_baselines::Cgal_triangulation_baseline cgal(mesh.points, mesh.tetrahedra);
  r.build_seconds = now() - t0; // one build: it is slow and deterministic
  r.bytes = cgal.memory_bytes();
  r.overhead_bytes = r.bytes;
  r.vt_seconds = best_of(reps, [&] {
    std::size_t sum = 0;
    cgal.for_each_vertex_star([&](Index, const std::vector<Index>& s) { sum += s.size(); });
    r.checksum = sum;
  });
  const std::vector<double> f = field_values(mesh);
  r.distortion_seconds = best_of(reps, [&] {
    const auto c =
        prstar_baselines::cgal_curvature(mesh.points, mesh.tetrahedra, cgal, [&](Index v) { return f[v]; });
    r.distortion_sum = manifold_sum(c);
  });
  // CGAL answers "is v on the boundary" in O(1) here (a vertex's cell is infinite exactly on the
  // boundary, by construction of the baseline): this column is its lookup, not a computation.
  r.boundary_seconds = best_of(reps, [&] {
    std::size_t n = 0;
    for (Index v = 0; v < mesh.points.size(); ++v) n += cgal.is_boundary_vertex(v);
    r.checksum2 = n;
  });
  return r;
}

// The mesh re-indexed in the PR-star order (V depth-first by leaves, T by smallest vertex).
Mesh prstar_order(const Mesh& mesh) {
  Octree tree(CGAL::PR_star_octree::make_input(mesh), CGAL::PR_star_octree::parameters::bucket_size(100));
  Mesh m;
  m.points.assign(tree.points().begin(), tree.points().end());
  m.tetrahedra.assign(tree.tetrahedra().begin(), tree.tetrahedra().end());
  if (tree.has_scalar_field()) m.point_data.push_back({"scalar", tree.scalars()});
  return m;
}

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// The minimum of each time over two measurements of the same row (the sizes are the same).
void merge_minimum(Result& r, const Result& o) {
  r.build_seconds = std::min(r.build_seconds, o.build_seconds);
  r.vt_seconds = std::min(r.vt_seconds, o.vt_seconds);
  r.distortion_seconds = std::min(r.distortion_seconds, o.distortion_seconds);
  r.boundary_seconds = std::min(r.boundary_seconds, o.boundary_seconds);
  r.boundary_count_seconds = std::min(r.boundary_count_seconds, o.boundary_count_seconds);
  r.peak_rss_bytes = std::max(r.peak_rss_bytes, o.peak_rss_bytes);
  r.ok = r.ok && o.ok;
}

const char* const usage =
    "usage: bench_relations [--kv auto,10,20,...,inf] [--reps R] [--rounds N] [--threads N] [--no-cgal] "
    "[--compact] [--csv OUT.csv] MESH...\n";

} // namespace

int main(int argc, char** argv) {
  std::vector<std::size_t> kvs = {prstar_bench::automatic_kv,  10, 20, 50, 100, 200, 400, 800,
                                  Octree::infinite_bucket_size};
  int reps = 3, rounds = 1;
  bool with_cgal = true, with_compact = false;
  int threads = 0; // 0: TBB's default (every core)
  std::string csv_file;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--reps" && i + 1 < argc)
      reps = std::max(1, std::atoi(argv[++i]));
    else if (a == "--rounds" && i + 1 < argc)
      rounds = std::max(1, std::atoi(argv[++i]));
    else if (a == "--csv" && i + 1 < argc)
      csv_file = argv[++i];
    else if (a == "--no-cgal")
      with_cgal = false;
    else if (a == "--compact")
      with_compact = true;
    else if (a == "--threads" && i + 1 < argc)
      threads = std::max(1, std::atoi(argv[++i]));
    else if (a == "--kv" && i + 1 < argc) {
      kvs = prstar_bench::parse_kv_list(argv[++i]);
    } else if (!a.empty() && a[0] == '-') {
      std::cerr << usage;
      return 2;
    } else
      files.push_back(a);
  }
  if (files.empty()) {
    std::cerr << usage;
    return 2;
  }

#ifdef CGAL_LINKED_WITH_TBB
  // The leaf-streaming algorithms run on every core by default; --threads 1 is the sequential run.
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
#endif
  std::ostringstream csv;
  csv << "mesh,vertices,tetrahedra,structure,order,kv,nodes,leaves,chi,cost_overhead_per_vertex,"
         "cost_total_per_vertex,bytes,overhead_bytes,"
      << prstar_bench::Bytes_per_tetrahedron::csv_header()
      << ",peak_rss_bytes,build_seconds,vt_seconds,"
         "vt_vs_ia_file,vt_vs_ia_same_order,vt_vs_cgal_same_order,vt_vs_stream,bytes_vs_ia,bytes_vs_cgal,"
         "overhead_vs_cgal,distortion_seconds,distortion_vs_ia_same_order,distortion_vs_cgal_same_order,"
         "boundary_seconds,boundary_vs_ia_same_order,boundary_count_seconds,boundary_count_vs_ia_same_"
         "order\n";
  std::cout
      << "| mesh | structure | order | k_v | |N| | |N_leaf| | chi | cost overhead/|V| | cost total/|V| | "
         "bytes | "
         "B/tet | B/tet breakdown (PR-star: as prstar stats; + the permutations kept here) | peak RSS | "
         "build s | VT s | VT/IA (file) | VT/IA (same order) | VT/CGAL (same order) | "
         "VT/stream | bytes/IA | bytes/CGAL | overhead/CGAL | distortion s | dist/IA (same order) | "
         "dist/CGAL (same order) | boundary s | bnd/IA (same order) | count-only boundary s | count/IA |\n"
      << "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|--"
         "-:|"
         "---:|---:|---:|---:|---:|---:|---:|---:|\n";

  for (const std::string& file : files) {
    Mesh file_mesh;
    try {
      CGAL::PR_star_octree::IO::read_tetrahedral_mesh(file, file_mesh);
    } catch (const std::exception& e) {
      std::cerr << e.what() << '\n';
      return 1;
    }
    const std::string name = base_name(file);
    const Mesh ordered = prstar_order(file_mesh);
    const double T = double(file_mesh.tetrahedra.size());
    std::cerr << name << ": " << file_mesh.points.size() << " vertices, " << file_mesh.tetrahedra.size()
              << " tetrahedra\n";

    // The floor: one streaming pass summing the tetrahedron index array.
    volatile std::size_t sink = 0;
    const double stream = best_of(std::max(reps, 5), [&] {
      std::size_t s = 0;
      for (const auto& c : file_mesh.tetrahedra) s += c[0] + c[1] + c[2] + c[3];
      sink = s;
    });
    (void)sink;

    struct Row {
      std::string structure, order, kv;
      Result r;
    };
    // Every structure is measured in its own child, one after the other; with --rounds R the whole
    // sequence runs R times and each time is the minimum over the rounds, so that a slow spell of
    // the machine (seconds long on a shared virtual machine) cannot fall on one structure only.
    std::vector<Row> rows;
    for (int round = 0; round < rounds; ++round) {
      if (rounds > 1) std::cerr << "  round " << round + 1 << " of " << rounds << '\n';
      std::vector<Row> measured;
      std::cerr << "  extended IA ...\n";
      measured.push_back({"extended IA", "file", "-",
                          prstar_bench::in_child<Result>([&] { return run_ia(file_mesh, reps); })});
      measured.push_back({"extended IA", "PR-star", "-",
                          prstar_bench::in_child<Result>([&] { return run_ia(ordered, reps); })});
      if (with_cgal) {
        std::cerr << "  CGAL Triangulation_3 ...\n";
        measured.push_back({"CGAL Triangulation_3", "file", "-",
                            prstar_bench::in_child<Result>([&] { return run_cgal(file_mesh, reps); })});
        measured.push_back({"CGAL Triangulation_3", "PR-star", "-",
                            prstar_bench::in_child<Result>([&] { return run_cgal(ordered, reps); })});
      }
      for (std::size_t kv : kvs) {
        std::cerr << "  PR-star k_v = " << kv_name(kv) << " ...\n";
        for (const bool compact : {false, true}) {
          if (compact && !with_compact) continue;
          measured.push_back(
              {compact ? "PR-star compact" : "PR-star", "file", kv_name(kv),
               prstar_bench::in_child<Result>([&] { return run_prstar(file_mesh, kv, reps, compact); })});
          if (kv == prstar_bench::automatic_kv)
            measured.back().kv += " (" + std::to_string(measured.back().r.kv) + ")";
        }
      }
      if (round == 0)
        rows = std::move(measured);
      else
        for (std::size_t i = 0; i < rows.size(); ++i) merge_minimum(rows[i].r, measured[i].r);
    }
    const Result& ia_file = rows[0].r;
    const Result& ia_same = rows[1].r;
    const Result* cgal_same = with_cgal ? &rows[3].r : nullptr;
    for (const Row& row : rows) {
      const Result& r = row.r;
      if (!r.ok) {
        std::cout << "| " << name << " | " << row.structure << " | " << row.order << " | " << row.kv
                  << " | failed |\n";
        continue;
      }
      if (r.checksum != ia_file.checksum)
        std::cerr << "  warning: " << row.structure << " VT checksum " << r.checksum << " != IA "
                  << ia_file.checksum << '\n';
      const bool pr = row.structure.rfind("PR-star", 0) == 0;
      const double vs_ia_file = r.vt_seconds / ia_file.vt_seconds;
      const double vs_ia_same = r.vt_seconds / ia_same.vt_seconds;
      const double vs_cgal = cgal_same && cgal_same->ok ? r.vt_seconds / cgal_same->vt_seconds : 0;
      const double vs_stream = r.vt_seconds / stream;
      const double bytes_ia = double(r.bytes) / double(ia_file.bytes);
      const double bytes_cgal = cgal_same && cgal_same->ok ? double(r.bytes) / double(cgal_same->bytes) : 0;
      const double overhead_cgal =
          cgal_same && cgal_same->ok ? double(r.overhead_bytes) / double(cgal_same->bytes) : 0;
      const double dist_ia = r.distortion_seconds / ia_same.distortion_seconds;
      const double dist_cgal =
          cgal_same && cgal_same->ok ? r.distortion_seconds / cgal_same->distortion_seconds : 0;
      const double bnd_ia = r.boundary_seconds / ia_same.boundary_seconds;
      if (std::abs(r.distortion_sum - ia_file.distortion_sum) > 1e-6 * (1 + std::abs(ia_file.distortion_sum)))
        std::cerr << "  warning: " << row.structure << " distortion sum " << r.distortion_sum << " != IA "
                  << ia_file.distortion_sum << '\n';
      std::cout << "| " << name << " | " << row.structure << " | " << row.order << " | " << row.kv << " | "
                << (pr ? std::to_string(r.nodes) : "-") << " | " << (pr ? std::to_string(r.leaves) : "-")
                << " | " << (pr ? fmt("%.3f", r.chi) : "-") << " | "
                << (r.cost_overhead > 0 ? fmt("%.2f", r.cost_overhead) : "-") << " | "
                << (r.cost_total > 0 ? fmt("%.2f", r.cost_total) : "-") << " | " << r.bytes << " | "
                << fmt("%.1f", double(r.bytes) / T) << " | "
                << (pr ? r.bpt.breakdown() + fmt(" (+ %.2f)", r.bpt.permutations) : "-") << " | "
                << fmt("%.1f MiB", double(r.peak_rss_bytes) / 1048576.) << " | "
                << fmt("%.4f", r.build_seconds) << " | " << fmt("%.4f", r.vt_seconds) << " | "
                << fmt("%.2f", vs_ia_file) << " | " << fmt("%.2f", vs_ia_same) << " | "
                << (vs_cgal > 0 ? fmt("%.3f", vs_cgal) : "-") << " | " << fmt("%.1f", vs_stream) << " | "
                << fmt("%.2f", bytes_ia) << " | " << (bytes_cgal > 0 ? fmt("%.3f", bytes_cgal) : "-") << " | "
                << (overhead_cgal > 0 ? fmt("%.3f", overhead_cgal) : "-") << " | "
                << fmt("%.4f", r.distortion_seconds) << " | " << fmt("%.2f", dist_ia) << " | "
                << (dist_cgal > 0 ? fmt("%.2f", dist_cgal) : "-") << " | " << fmt("%.4f", r.boundary_seconds)
                << " | " << fmt("%.2f", bnd_ia) << " | " << (pr ? fmt("%.4f", r.boundary_count_seconds) : "-")
                << " | " << (pr ? fmt("%.2f", r.boundary_count_seconds / ia_same.boundary_seconds) : "-")
                << " |\n";
      csv << name << ',' << file_mesh.points.size() << ',' << file_mesh.tetrahedra.size() << ','
          << row.structure << ',' << row.order << ',' << row.kv << ',' << (pr ? r.nodes : 0) << ','
          << (pr ? r.leaves : 0) << ',' << r.chi << ',' << r.cost_overhead << ',' << r.cost_total << ','
          << r.bytes << ',' << r.overhead_bytes << ','
          << (pr ? r.bpt.csv() : fmt("%.4f", double(r.bytes) / T) + ",0,0,0,0,0,0") << ',' << r.peak_rss_bytes
          << ',' << r.build_seconds << ',' << r.vt_seconds << ',' << vs_ia_file << ',' << vs_ia_same << ','
          << vs_cgal << ',' << vs_stream << ',' << bytes_ia << ',' << bytes_cgal << ',' << overhead_cgal
          << ',' << r.distortion_seconds << ',' << dist_ia << ',' << dist_cgal << ',' << r.boundary_seconds
          << ',' << bnd_ia << ',' << r.boundary_count_seconds << ','
          << (pr ? r.boundary_count_seconds / ia_same.boundary_seconds : 0.) << '\n';
    }
    std::cout << "| " << name << " | streaming pass over T | file | - | | | | | | | | | | | "
              << fmt("%.4f", stream) << " | | | | 1.0 | | | | | | | | | | |\n";
    std::cout.flush();
  }
  if (!csv_file.empty() && !prstar_bench::write_text_file(csv_file, csv.str())) return 1;
  return 0;
}
