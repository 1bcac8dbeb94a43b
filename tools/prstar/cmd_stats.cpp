// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar stats: storage statistics of the PR-star octree (paper Table 1) and simplex counts.

#include "commands.h"

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/Leaf_topology.h>
#include <CGAL/PR_star_octree/parameters.h>

#include <fstream>
#include <iostream>

namespace prstar {

namespace {

using Octree = CGAL::PR_star_octree_3<>;
namespace params = CGAL::PR_star_octree::parameters;

void statistics_json(prstar::Json& j, const CGAL::PR_star_octree::Statistics& s,
                     const CGAL::PR_star_octree::Simplex_counts& c, bool streamed) {
  j.begin_object();
  j.field("vertices", s.vertices).field("tetrahedra", s.tetrahedra);
  j.field("edges", c.edges).field("triangles", c.triangles).field("boundary_triangles", c.boundary_triangles);
  j.field("nonmanifold_triangles", c.nonmanifold_triangles);
  j.field("euler_characteristic", c.euler_characteristic());
  if (s.infinite_bucket_size)
    j.field("kv", "inf");
  else
    j.field("kv", s.bucket_size);
  j.field("kv_automatic", s.automatic_bucket_size);
  if (s.automatic_bucket_size) { // what the octree chose k_v from (CGAL::PR_star_octree::choose_bucket_size)
    const auto& c = s.bucket_size_choice;
    j.key("kv_choice").begin_object();
    j.field("cache_bytes", c.cache_bytes).field("tetrahedra_per_vertex", c.tetrahedra_per_vertex);
    j.field("leaf_bytes_per_tetrahedron", c.leaf_bytes_per_tetrahedron);
    j.field("estimated_leaf_bytes", c.estimated_leaf_bytes)
        .field("limited_by_mesh_size", c.limited_by_mesh_size);
    j.end_object();
  }
  j.field("nodes", s.nodes).field("leaves", s.leaves).field("empty_leaves", s.empty_leaves);
  j.field("depth", s.depth).field("max_depth", s.max_depth).field("chi", s.chi);
  j.field("max_leaf_vertices", s.max_leaf_vertices).field("max_leaf_tetrahedra", s.max_leaf_tetrahedra);
  j.field("depth_limited_leaves", s.depth_limited_leaves).field("coincident_leaves", s.coincident_leaves);
  j.field("duplicate_vertices", s.duplicate_vertices).field("unreferenced_vertices", s.unreferenced_vertices);
  j.field("reoriented_tetrahedra", s.reoriented_tetrahedra)
      .field("degenerate_tetrahedra", s.degenerate_tetrahedra);
  if (!s.subdomains.empty()) { // the number of tetrahedra of each label
    j.key("subdomains").begin_object();
    for (const auto& l : s.subdomains) j.field(std::to_string(l.first), l.second);
    j.end_object();
  }
  j.key("storage").begin_object();
  j.field("prstar_overhead_per_vertex", s.prstar_overhead_per_vertex);
  j.field("prstar_total_per_vertex", s.prstar_total_per_vertex);
  j.field("ia_overhead_per_vertex", s.ia_overhead_per_vertex);
  j.field("ia_total_per_vertex", s.ia_total_per_vertex);
  j.field("bytes", s.bytes.total());
  j.field("compact_tetrahedra", s.compact_tetrahedra).field("streamed", streamed);
  j.field("float32_coordinates", s.float32_coordinates);
  // the same figures per tetrahedron (the one measure of compactness, as in the benchmarks)
  const double per_tet = s.tetrahedra ? 1. / double(s.tetrahedra) : 0.;
  j.field("bytes_per_tetrahedron", s.bytes_per_tetrahedron());
  j.key("bytes_per_tetrahedron_detail").begin_object();
  j.field("points", double(s.bytes.points) * per_tet).field("scalars", double(s.bytes.scalars) * per_tet);
  j.field("tetrahedra", double(s.bytes.tetrahedra) * per_tet)
      .field("labels", double(s.bytes.labels) * per_tet);
  j.field("nodes", double(s.bytes.nodes) * per_tet)
      .field("leaf_tetrahedra", double(s.bytes.leaf_tetrahedra) * per_tet);
  j.field("permutations", double(s.bytes.permutations) * per_tet)
      .field("reorientation", double(s.bytes.reorientation) * per_tet);
  j.end_object();
  j.key("bytes_detail").begin_object();
  j.field("points", s.bytes.points).field("scalars", s.bytes.scalars).field("tetrahedra", s.bytes.tetrahedra);
  if (s.bytes.labels) j.field("labels", s.bytes.labels);
  j.field("nodes", s.bytes.nodes).field("leaf_tetrahedra", s.bytes.leaf_tetrahedra);
  j.field("permutations", s.bytes.permutations).field("reorientation", s.bytes.reorientation);
  j.field("index", s.bytes.index());
  j.end_object();
  j.end_object();
  j.end_object();
}

// The leaf boxes of `tree` as an ASCII VTU of voxels (VTK type 11) with the cell arrays `depth`,
// `vertices` and `tetrahedra` (the leaf's counts), for ParaView (paper Figure 4).
void write_leaf_boxes(const std::string& out, const Octree& tree) {
  write_through_temporary(out, [&](const std::string& tmp) {
    std::ofstream f(tmp);
    f.precision(17);
    const std::size_t n = tree.number_of_leaves();
    f << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
         "byte_order=\"LittleEndian\">\n"
      << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << 8 * n << "\" NumberOfCells=\"" << n << "\">\n"
      << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (auto leaf : tree.leaves()) {
      const CGAL::Bbox_3 b = tree.node_bbox(leaf);
      for (int c = 0; c < 8; ++c)
        f << (c & 1 ? b.xmax() : b.xmin()) << ' ' << (c & 2 ? b.ymax() : b.ymin()) << ' '
          << (c & 4 ? b.zmax() : b.zmin()) << '\n';
    }
    f << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" "
         "format=\"ascii\">\n";
    for (std::size_t i = 0; i < 8 * n; ++i) f << i << (i % 8 == 7 ? '\n' : ' ');
    f << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t i = 1; i <= n; ++i) f << 8 * i << '\n';
    f << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < n; ++i) f << "11\n";
    f << "</DataArray>\n</Cells>\n<CellData>\n";
    auto array = [&](const char* name, auto value) {
      f << "<DataArray type=\"Int64\" Name=\"" << name << "\" format=\"ascii\">\n";
      for (auto leaf : tree.leaves()) f << value(leaf) << '\n';
      f << "</DataArray>\n";
    };
    array("depth", [&](Octree::Node_index l) { return tree.depth(l); });
    array("vertices", [&](Octree::Node_index l) { return tree.node(l).number_of_vertices(); });
    array("tetrahedra", [&](Octree::Node_index l) { return tree.node(l).number_of_tetrahedra(); });
    f << "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    f.close();
    if (!f) throw std::runtime_error(tmp + ": cannot write");
  });
}

} // namespace

// Builds the octree for each k_v and prints the statistics (a table, or JSON).  The octree of the
// last k_v takes the mesh over (lean construction: no second copy of V and T, no tetrahedron
// permutation, which nothing here reports).
void report_statistics(Mesh mesh, const std::string& name, const std::vector<std::size_t>& kvs,
                       std::size_t max_depth, bool compact,
                       CGAL::PR_star_octree::Coordinate_precision precision, bool json,
                       Progress_bar& progress, const std::string& octree_out,
                       const CGAL::PR_star_octree::IO::Vtu_tetrahedron_source* source) {
  std::vector<CGAL::PR_star_octree::Statistics> stats;
  std::vector<double> seconds;
  CGAL::PR_star_octree::Simplex_counts counts;
  for (std::size_t kv : kvs) {
    progress.phase("building the PR-star octree (k_v = " + bucket_size_string(kv) + ")");
    const auto np = params::bucket_size(kv)
                        .maximum_depth(max_depth)
                        .compact_tetrahedra(compact)
                        .coordinate_precision(precision)
                        .tetrahedron_permutation(false)
                        .vertex_permutation(false);
    const bool last = stats.size() + 1 == kvs.size();
    // streaming: the vertices read again for each k_v (the construction takes them over), the
    // tetrahedra in passes over the file (counted in the build's seconds)
    const Octree tree = source ? Octree(source->read_vertices(), *source, np)
                        : last ? Octree(std::move(mesh), np)
                               : Octree(CGAL::PR_star_octree::make_input(mesh), np);
    seconds.push_back(progress.seconds());
    progress.finish();
    stats.push_back(tree.statistics());
    if (!octree_out.empty() && stats.size() == kvs.size()) { // the last k_v of the list
      progress.phase("writing " + octree_out);
      write_leaf_boxes(octree_out, tree);
      progress.finish();
    }
    if (stats.size() == 1) { // the counts do not depend on k_v: compute them once, locally
      progress.phase("counting edges and triangles");
      counts = CGAL::PR_star_octree::count_simplices(tree, params::progress(progress.callback()));
      progress.finish();
    }
  }
  if (json) {
    Json j;
    if (stats.size() > 1) j.begin_array();
    for (const auto& s : stats) statistics_json(j, s, counts, source != nullptr);
    if (stats.size() > 1) j.end_array();
    std::cout << j.str() << '\n';
    return;
  }
  const auto& s0 = stats.front();
  std::cout << name << ": " << s0.vertices << " vertices, " << s0.tetrahedra << " tetrahedra (|T|/|V| = "
            << fixed(s0.vertices ? double(s0.tetrahedra) / double(s0.vertices) : 0., 2) << ")\n";
  std::cout << "  " << counts.edges << " edges, " << counts.triangles << " triangles ("
            << counts.boundary_triangles << " on the boundary), Euler characteristic "
            << counts.euler_characteristic() << "\n";
  std::cout << "  stored: coordinates as " << (s0.float32_coordinates ? "32-bit floats" : "doubles")
            << ", tetrahedra " << (s0.compact_tetrahedra ? "compact" : "as four 32-bit indices")
            << (source != nullptr ? " (read in passes)" : "") << "\n";
  if (counts.nonmanifold_triangles)
    std::cout << "  warning: " << counts.nonmanifold_triangles
              << " triangles are shared by three or more tetrahedra\n";
  if (s0.reoriented_tetrahedra)
    std::cout << "  " << s0.reoriented_tetrahedra
              << " tetrahedra listed with negative orientation (reoriented)\n";
  if (s0.degenerate_tetrahedra)
    std::cout << "  warning: " << s0.degenerate_tetrahedra << " tetrahedra have zero volume\n";
  if (s0.duplicate_vertices) std::cout << "  warning: " << s0.duplicate_vertices << " duplicate vertices\n";
  if (s0.unreferenced_vertices)
    std::cout << "  " << s0.unreferenced_vertices << " vertices in no tetrahedron\n";
  if (!s0.subdomains.empty()) {
    std::cout << "  " << s0.subdomains.size() << (s0.subdomains.size() == 1 ? " label:" : " labels:");
    std::size_t shown = 0;
    for (const auto& l : s0.subdomains) {
      if (++shown > 12) {
        std::cout << " ...";
        break;
      }
      std::cout << " " << l.first << " (" << l.second << " tetrahedra)";
    }
    std::cout << "\n";
  }
  std::cout << "  extended IA cost model: overhead " << fixed(s0.ia_overhead_per_vertex, 2) << " |V|, total "
            << fixed(s0.ia_total_per_vertex, 2) << " |V|\n\n";

  Table t({"k_v", "|N|", "|N_leaf|", "depth", "chi", "overhead/|V|", "total/|V|", "index bytes",
           "total bytes", "bytes/tet", "build s"});
  for (std::size_t i = 0; i < stats.size(); ++i) {
    const auto& s = stats[i];
    t.add({bucket_size_string(s.infinite_bucket_size ? kvs[i] : s.bucket_size) +
               (s.automatic_bucket_size ? " (auto)" : ""),
           std::to_string(s.nodes), std::to_string(s.leaves), std::to_string(s.depth), fixed(s.chi, 3),
           fixed(s.prstar_overhead_per_vertex, 2), fixed(s.prstar_total_per_vertex, 2),
           human_bytes(double(s.bytes.index())), human_bytes(double(s.bytes.total())),
           fixed(s.bytes_per_tetrahedron(), 1), fixed(seconds[i], 3)});
  }
  std::cout << t.str();
  for (std::size_t i = 0; i < stats.size(); ++i) {
    const auto& s = stats[i];
    if (s.automatic_bucket_size) {
      const auto& c = s.bucket_size_choice;
      std::cout << "k_v = " << s.bucket_size
                << " chosen by the octree (--kv auto): a full leaf's links and triangles\n"
                << "  need about " << human_bytes(c.estimated_leaf_bytes) << " ("
                << fixed(c.leaf_bytes_per_tetrahedron, 0)
                << " bytes per listed tetrahedron), at most 8 x the " << human_bytes(double(c.cache_bytes))
                << " cache of a core"
                << (c.limited_by_mesh_size ? ";\n  lowered to keep 16 leaves' worth of vertices (|V| / 16)"
                                           : "")
                << "\n";
    }
    if (s.depth_limited_leaves || s.coincident_leaves)
      std::cout << "note (k_v = " << bucket_size_string(s.infinite_bucket_size ? kvs[i] : s.bucket_size)
                << "): " << s.depth_limited_leaves << " leaves stopped at the depth bound " << s.max_depth
                << ", " << s.coincident_leaves
                << " leaves of coincident points hold more than k_v vertices (largest leaf: "
                << s.max_leaf_vertices << " vertices)\n";
  }
}

namespace {

int run_stats(const Options& o) {
  Progress_bar progress(o.show_progress());
  // A .vtu readable by ranges with --compact, or by default from 2^25 cells: the streaming
  // construction (never the plain tetrahedron array whole), as boundary.
  const auto streaming = streaming_source(o, o.input());
  Mesh mesh = streaming ? Mesh() : read_mesh(o.input(), progress);
  report_statistics(std::move(mesh), o.input(), o.kvs(), o.max_depth(), o.compact(), o.coordinate_precision(),
                    o.json(), progress, o.output("--octree"), streaming ? &*streaming : nullptr);
  return exit_success;
}

} // namespace

Command stats_command() {
  return Command("stats",
                 "storage statistics of the PR-star octree of a mesh (paper Table 1) and simplex counts")
      .input()
      .description(
          R"(Builds the PR-star octree of MESH and prints its storage statistics (paper Table 1): |V|, |T|,
k_v, |N|, |N_leaf|, depth, chi, the cost model of the PR-star octree and of the extended IA data
structure (in multiples of |V|), and the bytes really used; also the numbers of edges and
triangles and the Euler characteristic, counted leaf by leaf.  A .vtu whose arrays are appended
raw (as prstar generate writes them) and that has 2^25 cells or more (any size with --compact;
never with --no-compact) is read in passes, as boundary reads it: the plain tetrahedron array is
never held whole, and the build's seconds include the passes (JSON: streamed).)")
      .kv_list()
      .max_depth()
      .output("OUT.vtu", ".vtu",
              "write the leaf boxes of the octree (of the last k_v given) as VTK voxels with the\n"
              "cell arrays depth, vertices and tetrahedra, for ParaView",
              false, "--octree")
      .json_keys("(an array of objects for a list of k_v); the keys are listed in the README")
      .run(run_stats);
}

} // namespace prstar
