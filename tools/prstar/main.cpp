// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar: the command-line tool of the PR-star octree package.

#include "cli.h"
#include "generate.h"

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/Leaf_topology.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/distortion.h>
#include <CGAL/PR_star_octree/simplification.h>
#include <CGAL/PR_star_octree/validity.h>

#include <sys/stat.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iomanip>
#include <limits>
#include <iostream>
#include <string>
#include <vector>

namespace {

using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;
using Octree = CGAL::PR_star_octree_3<>;
using prstar::Arguments;
using prstar::Usage_error;

const char* const main_usage = R"(prstar - the PR-star octree for tetrahedral meshes

usage: prstar COMMAND [options]

commands:
  demo       build the PR-star octree of a built-in mesh (CGAL Mesh_3 unit ball) and show its statistics
  stats      storage statistics of the PR-star octree of a mesh (paper Table 1) and simplex counts
  boundary   boundary and non-manifold vertices, boundary triangles and tetrahedra (paper Section 7)
  curvature  discrete distortion of a scalar field at every vertex (paper Section 8)
  validate   orientation, flat and non-manifold elements, Euler characteristic, boundary components
  simplify   local half-edge-collapse simplification (paper Section 9)
  generate   make a tetrahedral mesh with CGAL Mesh_3 or TetGen

Run 'prstar COMMAND --help' for the options of a command.
Mesh files: .mesh (Medit), .node/.ele (TetGen), .vtk (legacy VTK), .vtu (VTK XML), .off/.ts (tet-OFF).
)";

const char* const stats_usage =
    R"(usage: prstar stats MESH [--kv N|inf[,N...]] [--max-depth D] [--json] [--quiet]

Builds the PR-star octree of MESH and prints its storage statistics (paper Table 1): |V|, |T|,
k_v, |N|, |N_leaf|, depth, chi, the cost model of the PR-star octree and of the extended IA data
structure (in multiples of |V|), and the bytes really used.

options:
  --kv N|inf       bucket threshold k_v (default 50); a comma-separated list gives one row per value
  --max-depth D    depth bound of the octree (default 32); leaves over k_v at the bound are reported
  --json           one JSON object on stdout (an array of objects for a list of k_v)
  --quiet          no progress on stderr
)";

const char* const generate_usage =
    R"(usage: prstar generate (--shape NAME | --surface FILE.off) --cell-size S -o OUT [options]

Makes a tetrahedral mesh with CGAL Mesh_3 (default) or TetGen (--tetgen) and writes it to OUT
(.mesh or .vtu).

options:
  --shape NAME          an implicit domain (see the list below)
  --surface FILE.off    a closed triangle surface bounding a polyhedral domain
  --cell-size S         target tetrahedron size (required, > 0)
  --facet-size S        target surface triangle size (default: the cell size)
  --facet-distance D    surface approximation error (default: cell size / 10)
  --tetgen              mesh the same surface with TetGen (quality, max volume from the cell size)
  -o, --output OUT      output file (.mesh or .vtu)
  --force               overwrite OUT if it exists
  --json                print a JSON summary on stdout
  --quiet               no progress on stderr
)";

const char* const demo_usage = R"(usage: prstar demo [--cell-size S] [--kv N|inf[,N...]] [--json] [--quiet]

Meshes the unit ball with CGAL Mesh_3 (no input file needed) and prints the statistics of its
PR-star octree for several bucket thresholds k_v (default 10,20,50,100,200,inf).
)";

const char* const boundary_usage =
    R"(usage: prstar boundary MESH [--kv N] [--json] [-o OUT.vtu [--force]] [--quiet]

Classifies every vertex of MESH as interior, boundary or non-manifold, leaf by leaf (paper
Section 7: 2|e| != 3|t| in the vertex link, plus a check that the link is a sphere or a disc).

options:
  --kv N          bucket threshold of the octree (default 50)
  --json          one JSON object on stdout: boundary_vertices, boundary_triangles,
                  boundary_tetrahedra (tetrahedra with a boundary or non-manifold vertex),
                  boundary_face_tetrahedra (with a face on the boundary), nonmanifold_vertices, ...
  -o OUT.vtu      write the mesh with the point arrays `boundary` (0 interior, 1 boundary,
                  2 non-manifold, 3 in no tetrahedron) for ParaView
  --force         overwrite OUT if it exists
  --quiet         no progress on stderr
)";

const char* const curvature_usage =
    R"(usage: prstar curvature MESH [--field NAME|x|y|z] [--kv N] [--json] [-o OUT.vtu] [--csv OUT.csv] [--force] [--quiet]

Discrete distortion of a scalar field at every vertex (paper Section 8): the field lifts the mesh
into R^4; the distortion at v is (4 pi, or the sum of the 3D solid angles on the boundary) minus
the sum of the solid angles at v of the lifted tetrahedra of its star.  Also computes the 3D
concentrated curvature of the domain ((4 pi or 2 pi) minus the sum of the 3D solid angles).
Non-manifold vertices get NaN.

options:
  --field NAME    a point-data array of MESH (default: its first one), or x, y, z for a coordinate
  --kv N          bucket threshold of the octree (default 50)
  --json          a JSON summary on stdout
  -o OUT.vtu      the mesh with point arrays `boundary`, `distortion`, `domain_curvature`
                  (non-manifold vertices: boundary = 2 and 0 for the undefined values)
  --csv OUT.csv   one row per input vertex, in the input order: vertex,x,y,z,boundary,distortion
                  (boundary: 0 interior, 1 boundary, 2 non-manifold, 3 in no tetrahedron;
                  distortion: nan for non-manifold vertices)
  --force         overwrite existing output files
  --quiet         no progress on stderr
)";

const char* const validate_usage = R"(usage: prstar validate MESH [--kv N] [--json] [--quiet]

Checks MESH leaf by leaf: the orientation of every tetrahedron with an exact predicate (all must
have the same sign as listed; "inverted" counts the minority sign), flat tetrahedra, triangles in
three or more tetrahedra, non-manifold vertices, the Euler characteristic and the number of
boundary components (boundary triangles connected through edges).  Exit code 0 if the mesh is
valid, 1 if not.

options:
  --kv N          bucket threshold of the octree (default 50)
  --json          one JSON object: valid, inverted, degenerate, nonmanifold_triangles,
                  nonmanifold_vertices, euler_characteristic, boundary_components, ...
  --quiet         no progress on stderr
)";

const char* const simplify_usage =
    R"(usage: prstar simplify MESH (--target F | --max-length L) [--kv N|inf] -o OUT [--force] [--json] [--quiet]

Simplifies MESH by half-edge collapses leaf by leaf (paper Section 9): each leaf collapses its
short edges, shortest first, under the boundary, geometric (exact orientation) and link
conditions; then the mesh is compacted and the octree rebuilt, until the target is met or a round
removes nothing.  Vertices never move; point data (the scalar field) is kept.

options:
  --target F        stop once this fraction of the tetrahedra is removed (0 < F < 1)
  --max-length L    collapse only edges shorter than L (with --target: both)
  --kv N|inf        bucket threshold k_v (default 50); inf is the global algorithm
  -o, --output OUT  the simplified mesh (.mesh, .vtu, .off/.ts)
  --force           overwrite OUT if it exists
  --json            one JSON object: input_tetrahedra, output_tetrahedra, removed_tetrahedra,
                    rounds, max_queue, seconds, blocked {different_leaves, boundary, flip, link}
  --quiet           no progress on stderr, no table
)";

bool wants_help(int argc, char** argv) {
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") return true;
  }
  return false;
}

std::vector<std::size_t> parse_bucket_list(const std::string& s) {
  std::vector<std::size_t> r;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = s.find(',', start);
    r.push_back(prstar::parse_bucket_size(s.substr(start, comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return r;
}

// k_v in JSON: a number, or the string "inf".
prstar::Json& json_kv(prstar::Json& j, std::size_t kv) {
  if (kv == Octree::infinite_bucket_size) return j.value("inf");
  return j.value(kv);
}

void statistics_json(prstar::Json& j, const CGAL::PR_star_octree::Statistics& s,
                     const CGAL::PR_star_octree::Simplex_counts& c) {
  j.begin_object();
  j.field("vertices", s.vertices).field("tetrahedra", s.tetrahedra);
  j.field("edges", c.edges).field("triangles", c.triangles).field("boundary_triangles", c.boundary_triangles);
  j.field("nonmanifold_triangles", c.nonmanifold_triangles);
  j.field("euler_characteristic", c.euler_characteristic());
  if (s.infinite_bucket_size)
    j.field("kv", "inf");
  else
    j.field("kv", s.bucket_size);
  j.field("nodes", s.nodes).field("leaves", s.leaves).field("empty_leaves", s.empty_leaves);
  j.field("depth", s.depth).field("max_depth", s.max_depth).field("chi", s.chi);
  j.field("max_leaf_vertices", s.max_leaf_vertices).field("max_leaf_tetrahedra", s.max_leaf_tetrahedra);
  j.field("depth_limited_leaves", s.depth_limited_leaves).field("coincident_leaves", s.coincident_leaves);
  j.field("duplicate_vertices", s.duplicate_vertices).field("unreferenced_vertices", s.unreferenced_vertices);
  j.field("reoriented_tetrahedra", s.reoriented_tetrahedra)
      .field("degenerate_tetrahedra", s.degenerate_tetrahedra);
  j.key("storage").begin_object();
  j.field("prstar_overhead_per_vertex", s.prstar_overhead_per_vertex);
  j.field("prstar_total_per_vertex", s.prstar_total_per_vertex);
  j.field("ia_overhead_per_vertex", s.ia_overhead_per_vertex);
  j.field("ia_total_per_vertex", s.ia_total_per_vertex);
  j.field("bytes", s.bytes.total());
  j.key("bytes_detail").begin_object();
  j.field("points", s.bytes.points).field("scalars", s.bytes.scalars).field("tetrahedra", s.bytes.tetrahedra);
  j.field("nodes", s.bytes.nodes).field("leaf_tetrahedra", s.bytes.leaf_tetrahedra);
  j.field("permutations", s.bytes.permutations).field("index", s.bytes.index());
  j.end_object();
  j.end_object();
  j.end_object();
}

// Builds the octree for each k_v and prints the statistics (a table, or JSON).
void report_statistics(const Mesh& mesh, const std::string& name, const std::vector<std::size_t>& kvs,
                       std::size_t max_depth, bool json, prstar::Progress& progress) {
  std::vector<CGAL::PR_star_octree::Statistics> stats;
  std::vector<double> seconds;
  CGAL::PR_star_octree::Simplex_counts counts;
  for (std::size_t kv : kvs) {
    progress.phase("building the PR-star octree (k_v = " + prstar::bucket_size_string(kv) + ")");
    Octree tree(CGAL::PR_star_octree::make_input(mesh), kv, max_depth);
    seconds.push_back(progress.seconds());
    progress.finish();
    stats.push_back(tree.statistics());
    if (stats.size() == 1) { // the counts do not depend on k_v: compute them once, locally
      progress.phase("counting edges and triangles leaf by leaf");
      counts = CGAL::PR_star_octree::count_simplices(tree);
      progress.finish();
    }
  }
  if (json) {
    prstar::Json j;
    if (stats.size() > 1) j.begin_array();
    for (const auto& s : stats) statistics_json(j, s, counts);
    if (stats.size() > 1) j.end_array();
    std::cout << j.str() << '\n';
    return;
  }
  const auto& s0 = stats.front();
  std::cout << name << ": " << s0.vertices << " vertices, " << s0.tetrahedra << " tetrahedra (|T|/|V| = "
            << prstar::fixed(s0.vertices ? double(s0.tetrahedra) / double(s0.vertices) : 0., 2) << ")\n";
  std::cout << "  " << counts.edges << " edges, " << counts.triangles << " triangles ("
            << counts.boundary_triangles << " on the boundary), Euler characteristic "
            << counts.euler_characteristic() << "\n";
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
  std::cout << "  extended IA cost model: overhead " << prstar::fixed(s0.ia_overhead_per_vertex, 2)
            << " |V|, total " << prstar::fixed(s0.ia_total_per_vertex, 2) << " |V|\n\n";

  prstar::Table t({"k_v", "|N|", "|N_leaf|", "depth", "chi", "overhead/|V|", "total/|V|", "index bytes",
                   "total bytes", "build s"});
  for (std::size_t i = 0; i < stats.size(); ++i) {
    const auto& s = stats[i];
    t.add({prstar::bucket_size_string(kvs[i]), std::to_string(s.nodes), std::to_string(s.leaves),
           std::to_string(s.depth), prstar::fixed(s.chi, 3), prstar::fixed(s.prstar_overhead_per_vertex, 2),
           prstar::fixed(s.prstar_total_per_vertex, 2), prstar::human_bytes(double(s.bytes.index())),
           prstar::human_bytes(double(s.bytes.total())), prstar::fixed(seconds[i], 3)});
  }
  std::cout << t.str();
  for (std::size_t i = 0; i < stats.size(); ++i) {
    const auto& s = stats[i];
    if (s.depth_limited_leaves || s.coincident_leaves)
      std::cout << "note (k_v = " << prstar::bucket_size_string(kvs[i]) << "): " << s.depth_limited_leaves
                << " leaves stopped at the depth bound " << s.max_depth << ", " << s.coincident_leaves
                << " leaves of coincident points hold more than k_v vertices (largest leaf: "
                << s.max_leaf_vertices << " vertices)\n";
  }
}

Mesh read_mesh(const std::string& file, prstar::Progress& progress) {
  progress.phase("reading " + file);
  Mesh mesh;
  CGAL::PR_star_octree::IO::read_tetrahedral_mesh(file, mesh);
  progress.finish();
  return mesh;
}

int cmd_stats(int argc, char** argv) {
  Arguments args(argc, argv, 2, {"--json", "--quiet"}, {"--kv", "--max-depth"});
  if (args.positional().size() != 1)
    throw Usage_error(args.positional().empty() ? "missing MESH" : "expected one MESH, got several");
  const std::vector<std::size_t> kvs = parse_bucket_list(args.get("--kv", "50"));
  const double depth = args.get_double("--max-depth", double(Octree::default_max_depth));
  if (depth < 1 || depth > 64 || depth != std::floor(depth))
    throw Usage_error("--max-depth must be in 1..64");
  prstar::Progress progress(args.flag("--quiet") || args.flag("--json"));
  const Mesh mesh = read_mesh(args.positional()[0], progress);
  report_statistics(mesh, args.positional()[0], kvs, static_cast<std::size_t>(depth), args.flag("--json"),
                    progress);
  return 0;
}

bool file_exists(const std::string& f) {
  struct stat st;
  return ::stat(f.c_str(), &st) == 0;
}

// Writes OUT through a temporary file renamed at the end: an error never leaves a half-written
// OUT, and an existing OUT stays untouched until the new one is complete.  `write(tmp)` writes the
// temporary; its name keeps the extension, which selects the format: OUT.mesh -> OUT.prstar-tmp.mesh
template <class Write>
void write_through_temporary(const std::string& out, Write&& write) {
  const std::size_t dot = out.find_last_of('.');
  const std::size_t slash = out.find_last_of('/');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  const std::string tmp =
      has_ext ? out.substr(0, dot) + ".prstar-tmp" + out.substr(dot) : out + ".prstar-tmp";
  try {
    write(tmp);
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
  if (std::rename(tmp.c_str(), out.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error(out + ": cannot write the output file");
  }
}

void write_mesh_safely(const std::string& out, const Mesh& mesh) {
  write_through_temporary(
      out, [&](const std::string& tmp) { CGAL::PR_star_octree::IO::write_tetrahedral_mesh(tmp, mesh); });
}

int cmd_generate(int argc, char** argv) {
  Arguments args(
      argc, argv, 2, {"--tetgen", "--force", "--json", "--quiet"},
      {"--shape", "--surface", "--cell-size", "--facet-size", "--facet-distance", "-o", "--output"});
  if (!args.positional().empty()) throw Usage_error("unexpected argument '" + args.positional()[0] + "'");
  prstar::Generate_options opt;
  opt.shape = args.get("--shape");
  opt.surface_file = args.get("--surface");
  if (opt.shape.empty() == opt.surface_file.empty())
    throw Usage_error("give exactly one of --shape and --surface");
  if (!args.has("--cell-size")) throw Usage_error("missing --cell-size");
  opt.cell_size = args.get_double("--cell-size", 0);
  opt.facet_size = args.get_double("--facet-size", 0);
  opt.facet_distance = args.get_double("--facet-distance", 0);
  if (!(opt.cell_size > 0)) throw Usage_error("--cell-size must be positive");
  if (opt.facet_size < 0 || opt.facet_distance < 0) throw Usage_error("sizes must be positive");
  opt.tetgen = args.flag("--tetgen");
  // The generator's own progress messages are finer than ours: let it speak, and keep ours silent.
  opt.quiet = args.flag("--quiet") || args.flag("--json");
  if (args.has("-o") && args.has("--output")) throw Usage_error("give -o or --output once");
  const std::string out = args.has("-o") ? args.get("-o") : args.get("--output");
  if (out.empty()) throw Usage_error("missing -o OUT");
  if (!CGAL::PR_star_octree::IO::is_writable_extension(out))
    throw Usage_error(out + ": cannot write this format (use .mesh or .vtu)");
  if (out == opt.surface_file) throw Usage_error("the output would overwrite the input surface " + out);
  if (file_exists(out) && !args.flag("--force"))
    throw std::runtime_error(out + ": the file exists (use --force to overwrite it)");

  prstar::Progress progress(opt.quiet);
  const auto start = std::chrono::steady_clock::now();
  const Mesh mesh = prstar::generate_mesh(opt);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.phase("writing " + out);
  write_mesh_safely(out, mesh);
  progress.finish();
  if (args.flag("--json")) {
    prstar::Json j;
    j.begin_object()
        .field("output", out)
        .field("mesher", opt.tetgen ? "tetgen" : "mesh_3")
        .field("vertices", mesh.points.size())
        .field("tetrahedra", mesh.tetrahedra.size())
        .field("seconds", seconds)
        .end_object();
    std::cout << j.str() << '\n';
  } else if (!args.flag("--quiet"))
    std::cout << out << ": " << mesh.points.size() << " vertices, " << mesh.tetrahedra.size()
              << " tetrahedra (" << (opt.tetgen ? "TetGen" : "CGAL Mesh_3") << ", "
              << prstar::fixed(seconds, 2) << " s)\n";
  return 0;
}

// Refuses to overwrite an input or (without --force) an existing file; checks the extension.
void check_output(const std::string& out, const std::string& input, bool force,
                  const std::string& extension) {
  if (out == input) throw Usage_error("the output " + out + " would overwrite the input");
  if (out.size() < extension.size() ||
      out.compare(out.size() - extension.size(), extension.size(), extension) != 0)
    throw Usage_error(out + ": the output must be a " + extension + " file");
  if (file_exists(out) && !force)
    throw std::runtime_error(out + ": the file exists (use --force to overwrite it)");
}

// The mesh as the user gave it, with extra point arrays (user order), written through a temporary.
void write_vtu_safely(const std::string& out, const Mesh& mesh,
                      const std::vector<CGAL::PR_star_octree::Point_data_array>& arrays) {
  write_through_temporary(
      out, [&](const std::string& tmp) { CGAL::PR_star_octree::IO::write_vtu(tmp, mesh, arrays); });
}

std::size_t parse_single_kv(const Arguments& args) {
  const std::vector<std::size_t> kvs = parse_bucket_list(args.get("--kv", "50"));
  if (kvs.size() != 1) throw Usage_error("--kv takes one value here");
  return kvs[0];
}

double type_code(CGAL::PR_star_octree::Vertex_type t) {
  using CGAL::PR_star_octree::Vertex_type;
  switch (t) {
  case Vertex_type::INTERIOR:
    return 0;
  case Vertex_type::BOUNDARY:
    return 1;
  case Vertex_type::NONMANIFOLD:
    return 2;
  default:
    return 3;
  }
}

int cmd_boundary(int argc, char** argv) {
  Arguments args(argc, argv, 2, {"--json", "--quiet", "--force"}, {"--kv", "-o", "--output"});
  if (args.positional().size() != 1)
    throw Usage_error(args.positional().empty() ? "missing MESH" : "expected one MESH, got several");
  const std::string input = args.positional()[0];
  const std::size_t kv = parse_single_kv(args);
  const std::string out = args.has("-o") ? args.get("-o") : args.get("--output");
  if (!out.empty()) check_output(out, input, args.flag("--force"), ".vtu");
  prstar::Progress progress(args.flag("--quiet") || args.flag("--json"));
  const Mesh mesh = read_mesh(input, progress);
  progress.phase("building the PR-star octree and classifying the vertices");
  const auto start = std::chrono::steady_clock::now();
  Octree tree(CGAL::PR_star_octree::make_input(mesh), kv);
  const auto b = CGAL::PR_star_octree::compute_boundary(tree);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.finish();
  if (!out.empty()) {
    progress.phase("writing " + out);
    CGAL::PR_star_octree::Point_data_array a{"boundary", std::vector<double>(mesh.points.size())};
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
      a.values[tree.original_vertex(static_cast<Octree::Index>(v))] = type_code(b.vertex_type[v]);
    write_vtu_safely(out, mesh, {a});
    progress.finish();
  }
  if (args.flag("--json")) {
    prstar::Json j;
    j.begin_object()
        .field("vertices", mesh.points.size())
        .field("tetrahedra", mesh.tetrahedra.size())
        .key("kv");
    json_kv(j, kv)
        .field("boundary_vertices", b.boundary_vertices)
        .field("interior_vertices", b.interior_vertices)
        .field("nonmanifold_vertices", b.nonmanifold_vertices)
        .field("unreferenced_vertices", b.unreferenced_vertices)
        .field("boundary_triangles", b.boundary_triangles.size())
        .field("boundary_tetrahedra", b.boundary_tetrahedra)
        .field("boundary_face_tetrahedra", b.boundary_face_tetrahedra)
        .field("seconds", seconds);
    if (!out.empty()) j.field("output", out);
    j.end_object();
    std::cout << j.str() << '\n';
    return 0;
  }
  prstar::Table t({"", "count"});
  t.add({"vertices", std::to_string(mesh.points.size())});
  t.add({"  interior", std::to_string(b.interior_vertices)});
  t.add({"  boundary", std::to_string(b.boundary_vertices)});
  t.add({"  non-manifold", std::to_string(b.nonmanifold_vertices)});
  t.add({"  in no tetrahedron", std::to_string(b.unreferenced_vertices)});
  t.add({"boundary triangles", std::to_string(b.boundary_triangles.size())});
  t.add({"tetrahedra touching the boundary", std::to_string(b.boundary_tetrahedra)});
  t.add({"  with a boundary face", std::to_string(b.boundary_face_tetrahedra)});
  std::cout << input << " (k_v = " << prstar::bucket_size_string(kv) << ", " << prstar::fixed(seconds, 3)
            << " s)\n"
            << t.str();
  if (b.nonmanifold_vertices)
    std::cout << "warning: " << b.nonmanifold_vertices
              << " vertices have a link that is neither a sphere nor a disc (non-manifold)\n";
  if (!out.empty()) std::cout << "wrote " << out << '\n';
  return 0;
}

int cmd_curvature(int argc, char** argv) {
  Arguments args(argc, argv, 2, {"--json", "--quiet", "--force"},
                 {"--kv", "--field", "-o", "--output", "--csv"});
  if (args.positional().size() != 1)
    throw Usage_error(args.positional().empty() ? "missing MESH" : "expected one MESH, got several");
  const std::string input = args.positional()[0];
  const std::size_t kv = parse_single_kv(args);
  const std::string out = args.has("-o") ? args.get("-o") : args.get("--output");
  const std::string csv = args.get("--csv");
  if (!out.empty()) check_output(out, input, args.flag("--force"), ".vtu");
  if (!csv.empty()) check_output(csv, input, args.flag("--force"), ".csv");
  if (!out.empty() && out == csv) throw Usage_error("-o and --csv name the same file");
  prstar::Progress progress(args.flag("--quiet") || args.flag("--json"));
  const Mesh mesh = read_mesh(input, progress);

  // The field, in the user's vertex order.
  std::string field_name = args.get("--field");
  std::vector<double> values(mesh.points.size());
  if (field_name == "x" || field_name == "y" || field_name == "z") {
    const int axis = field_name[0] - 'x';
    for (std::size_t v = 0; v < values.size(); ++v)
      values[v] = axis == 0 ? mesh.points[v].x() : axis == 1 ? mesh.points[v].y() : mesh.points[v].z();
  } else {
    const CGAL::PR_star_octree::Point_data_array* a =
        field_name.empty() ? mesh.scalar_field() : mesh.find_point_data(field_name);
    if (!a) {
      std::string known;
      for (const auto& d : mesh.point_data) known += (known.empty() ? "" : ", ") + d.name;
      throw std::runtime_error(input + ": " +
                               (field_name.empty() ? std::string("the mesh has no point data")
                                                   : "no point-data array named '" + field_name + "'") +
                               (known.empty() ? "" : " (it has: " + known + ")") +
                               "; use --field x|y|z for a coordinate");
    }
    field_name = a->name;
    values = a->values;
  }
  for (std::size_t v = 0; v < values.size(); ++v)
    if (!std::isfinite(values[v]))
      throw std::runtime_error(input + ": field '" + field_name + "' is not finite at vertex " +
                               std::to_string(v));

  progress.phase("building the PR-star octree and computing the distortion");
  const auto start = std::chrono::steady_clock::now();
  Octree tree(CGAL::PR_star_octree::make_input(mesh), kv);
  const auto curv =
      CGAL::PR_star_octree::compute_curvature(tree, CGAL::PR_star_octree::original_order_field(tree, values));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.finish();

  // Back to the user's order.
  const std::size_t nv = mesh.points.size();
  CGAL::PR_star_octree::Point_data_array boundary{"boundary", std::vector<double>(nv)},
      distortion{"distortion", std::vector<double>(nv)}, domain{"domain_curvature", std::vector<double>(nv)};
  std::size_t counts[4] = {0, 0, 0, 0};
  double dmin = std::numeric_limits<double>::infinity(), dmax = -dmin, dsum = 0;
  std::size_t dn = 0;
  for (std::size_t v = 0; v < nv; ++v) {
    const auto o = tree.original_vertex(static_cast<Octree::Index>(v));
    const auto& c = curv[v];
    boundary.values[o] = type_code(c.type);
    distortion.values[o] = c.distortion;
    domain.values[o] = c.domain_curvature;
    ++counts[static_cast<int>(type_code(c.type))];
    if (c.type == CGAL::PR_star_octree::Vertex_type::INTERIOR ||
        c.type == CGAL::PR_star_octree::Vertex_type::BOUNDARY) {
      dmin = std::min(dmin, c.distortion);
      dmax = std::max(dmax, c.distortion);
      dsum += c.distortion;
      ++dn;
    }
  }
  if (!out.empty()) {
    progress.phase("writing " + out);
    // VTU point data must be finite (our reader refuses NaN, and so do some of ParaView's): the
    // undefined values of non-manifold vertices are written as 0 there, flagged by boundary = 2.
    auto finite = [](CGAL::PR_star_octree::Point_data_array a) {
      for (double& x : a.values)
        if (!std::isfinite(x)) x = 0;
      return a;
    };
    write_vtu_safely(out, mesh, {boundary, finite(distortion), finite(domain)});
    progress.finish();
  }
  if (!csv.empty()) {
    progress.phase("writing " + csv);
    write_through_temporary(csv, [&](const std::string& tmp) {
      std::ofstream f(tmp);
      f << std::setprecision(std::numeric_limits<double>::max_digits10);
      f << "vertex,x,y,z,boundary,distortion\n";
      for (std::size_t v = 0; v < nv; ++v)
        f << v << ',' << mesh.points[v].x() << ',' << mesh.points[v].y() << ',' << mesh.points[v].z() << ','
          << static_cast<int>(boundary.values[v]) << ',' << distortion.values[v] << '\n';
      f.flush();
      if (!f) throw std::runtime_error(csv + ": cannot write the output file");
    });
    progress.finish();
  }
  if (args.flag("--json")) {
    prstar::Json j;
    j.begin_object().field("vertices", nv).field("tetrahedra", mesh.tetrahedra.size()).key("kv");
    json_kv(j, kv)
        .field("field", field_name)
        .field("interior_vertices", counts[0])
        .field("boundary_vertices", counts[1])
        .field("nonmanifold_vertices", counts[2])
        .field("unreferenced_vertices", counts[3]);
    if (dn)
      j.field("distortion_min", dmin)
          .field("distortion_max", dmax)
          .field("distortion_mean", dsum / double(dn));
    j.field("seconds", seconds);
    if (!out.empty()) j.field("output", out);
    if (!csv.empty()) j.field("csv", csv);
    j.end_object();
    std::cout << j.str() << '\n';
    return 0;
  }
  std::cout << input << ": distortion of '" << field_name << "' (k_v = " << prstar::bucket_size_string(kv)
            << ", " << prstar::fixed(seconds, 3) << " s)\n";
  prstar::Table t({"vertices", "count", "distortion min", "max", "mean"});
  t.add({"all manifold", std::to_string(dn), dn ? prstar::fixed(dmin, 6) : "-",
         dn ? prstar::fixed(dmax, 6) : "-", dn ? prstar::fixed(dsum / double(dn), 6) : "-"});
  t.add({"interior", std::to_string(counts[0]), "", "", ""});
  t.add({"boundary", std::to_string(counts[1]), "", "", ""});
  t.add({"non-manifold (NaN)", std::to_string(counts[2]), "", "", ""});
  std::cout << t.str();
  if (!out.empty()) std::cout << "wrote " << out << '\n';
  if (!csv.empty()) std::cout << "wrote " << csv << '\n';
  return 0;
}

int cmd_validate(int argc, char** argv) {
  Arguments args(argc, argv, 2, {"--json", "--quiet"}, {"--kv"});
  if (args.positional().size() != 1)
    throw Usage_error(args.positional().empty() ? "missing MESH" : "expected one MESH, got several");
  const std::string input = args.positional()[0];
  const std::size_t kv = parse_single_kv(args);
  prstar::Progress progress(args.flag("--quiet") || args.flag("--json"));
  const Mesh mesh = read_mesh(input, progress);
  progress.phase("checking the mesh leaf by leaf");
  const auto start = std::chrono::steady_clock::now();
  const auto r = CGAL::PR_star_octree::check_validity(mesh.points, mesh.tetrahedra, kv);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.finish();
  if (args.flag("--json")) {
    prstar::Json j;
    j.begin_object()
        .field("valid", r.valid)
        .field("tetrahedra", r.tetrahedra)
        .field("inverted", r.inverted)
        .field("degenerate", r.degenerate)
        .field("nonmanifold_triangles", r.nonmanifold_triangles)
        .field("nonmanifold_vertices", r.nonmanifold_vertices)
        .field("euler_characteristic", r.euler_characteristic)
        .field("boundary_triangles", r.boundary_triangles)
        .field("boundary_components", r.boundary_components)
        .field("seconds", seconds)
        .end_object();
    std::cout << j.str() << '\n';
  } else {
    prstar::Table t({"check", "count"});
    t.add({"tetrahedra", std::to_string(r.tetrahedra)});
    t.add({"  positive as listed", std::to_string(r.positive)});
    t.add({"  negative as listed", std::to_string(r.negative)});
    t.add({"  inverted (minority sign)", std::to_string(r.inverted)});
    t.add({"  flat (degenerate)", std::to_string(r.degenerate)});
    t.add({"triangles in 3+ tetrahedra", std::to_string(r.nonmanifold_triangles)});
    t.add({"non-manifold vertices", std::to_string(r.nonmanifold_vertices)});
    t.add({"Euler characteristic", std::to_string(r.euler_characteristic)});
    t.add({"boundary triangles", std::to_string(r.boundary_triangles)});
    t.add({"boundary components", std::to_string(r.boundary_components)});
    std::cout << input << ": " << (r.valid ? "valid" : "INVALID") << " (" << prstar::fixed(seconds, 3)
              << " s)\n"
              << t.str();
  }
  return r.valid ? 0 : 1;
}

int cmd_simplify(int argc, char** argv) {
  Arguments args(argc, argv, 2, {"--json", "--quiet", "--force"},
                 {"--target", "--max-length", "--kv", "-o", "--output"});
  if (args.positional().size() != 1)
    throw Usage_error(args.positional().empty() ? "missing MESH" : "expected one MESH, got several");
  const std::string input = args.positional()[0];
  CGAL::PR_star_octree::Simplification_options opt;
  if (!args.has("--target") && !args.has("--max-length")) throw Usage_error("give --target or --max-length");
  opt.target_fraction = args.get_double("--target", 0);
  if (args.has("--target") && !(opt.target_fraction > 0 && opt.target_fraction < 1))
    throw Usage_error("--target must be a fraction of the tetrahedra in (0, 1), e.g. 0.5");
  opt.max_edge_length = args.get_double("--max-length", std::numeric_limits<double>::infinity());
  if (!(opt.max_edge_length > 0)) throw Usage_error("--max-length must be positive");
  opt.bucket_size = parse_single_kv(args);
  if (args.has("-o") && args.has("--output")) throw Usage_error("give -o or --output once");
  const std::string out = args.has("-o") ? args.get("-o") : args.get("--output");
  if (out.empty()) throw Usage_error("missing -o OUT");
  if (!CGAL::PR_star_octree::IO::is_writable_extension(out))
    throw Usage_error(out + ": cannot write this format (writable: " +
                      CGAL::PR_star_octree::IO::writable_extensions() + ")");
  if (out == input) throw Usage_error("the output " + out + " would overwrite the input");
  if (file_exists(out) && !args.flag("--force"))
    throw std::runtime_error(out + ": the file exists (use --force to overwrite it)");
  prstar::Progress progress(args.flag("--quiet") || args.flag("--json"));
  const Mesh mesh = read_mesh(input, progress);
  progress.phase("simplifying (k_v = " + prstar::bucket_size_string(opt.bucket_size) + ")");
  const auto res = CGAL::PR_star_octree::simplify(mesh, opt);
  progress.finish();
  progress.phase("writing " + out);
  write_mesh_safely(out, res.mesh);
  progress.finish();
  const auto& s = res.statistics;
  if (args.flag("--json")) {
    prstar::Json j;
    j.begin_object()
        .field("input_tetrahedra", s.input_tetrahedra)
        .field("output_tetrahedra", s.output_tetrahedra)
        .field("removed_tetrahedra", s.removed_tetrahedra)
        .field("input_vertices", s.input_vertices)
        .field("output_vertices", s.output_vertices)
        .key("kv");
    json_kv(j, opt.bucket_size)
        .field("rounds", s.rounds)
        .field("max_queue", s.max_queue_size)
        .field("seconds", s.seconds);
    j.key("blocked").begin_object();
    j.field("different_leaves", s.blocked.different_leaves)
        .field("boundary", s.blocked.boundary)
        .field("flip", s.blocked.flip)
        .field("link", s.blocked.link);
    j.end_object();
    j.field("output", out).end_object();
    std::cout << j.str() << '\n';
    return 0;
  }
  if (args.flag("--quiet")) return 0;
  prstar::Table t({"", "count"});
  t.add({"input tetrahedra", std::to_string(s.input_tetrahedra)});
  t.add({"output tetrahedra", std::to_string(s.output_tetrahedra)});
  t.add({"removed", std::to_string(s.removed_tetrahedra) + " (" +
                        prstar::fixed(s.input_tetrahedra
                                          ? 100. * double(s.removed_tetrahedra) / double(s.input_tetrahedra)
                                          : 0.,
                                      1) +
                        "%)"});
  t.add({"vertices", std::to_string(s.input_vertices) + " -> " + std::to_string(s.output_vertices)});
  t.add({"rounds", std::to_string(s.rounds)});
  t.add({"max queue size", std::to_string(s.max_queue_size)});
  t.add({"blocked: ends in different leaves", std::to_string(s.blocked.different_leaves)});
  t.add({"blocked: boundary", std::to_string(s.blocked.boundary)});
  t.add({"blocked: flip (exact orientation)", std::to_string(s.blocked.flip)});
  t.add({"blocked: link condition", std::to_string(s.blocked.link)});
  std::cout << input << " (k_v = " << prstar::bucket_size_string(opt.bucket_size) << ", "
            << prstar::fixed(s.seconds, 3) << " s)\n"
            << t.str() << "wrote " << out << '\n';
  return 0;
}

int cmd_demo(int argc, char** argv) {
  Arguments args(argc, argv, 2, {"--json", "--quiet"}, {"--cell-size", "--kv"});
  if (!args.positional().empty()) throw Usage_error("unexpected argument '" + args.positional()[0] + "'");
  prstar::Generate_options opt;
  opt.shape = "sphere";
  opt.cell_size = args.get_double("--cell-size", 0.04);
  if (!(opt.cell_size >= 0.005)) throw Usage_error("--cell-size must be at least 0.005 for the demo");
  opt.quiet = args.flag("--quiet") || args.flag("--json");
  const std::vector<std::size_t> kvs = parse_bucket_list(args.get("--kv", "10,20,50,100,200,inf"));
  prstar::Progress progress(opt.quiet);
  progress.phase("meshing the unit ball with CGAL Mesh_3 (cell size " + prstar::fixed(opt.cell_size, 3) +
                 ")");
  const Mesh mesh = prstar::generate_mesh(opt);
  progress.finish();
  report_statistics(mesh,
                    "built-in unit ball (CGAL Mesh_3, cell size " + prstar::fixed(opt.cell_size, 3) + ")",
                    kvs, Octree::default_max_depth, args.flag("--json"), progress);
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << main_usage;
    return 2;
  }
  const std::string command = argv[1];
  if (command == "--help" || command == "-h" || command == "help") {
    std::cout << main_usage;
    return 0;
  }
  struct Command {
    const char* name;
    const char* usage;
    int (*run)(int, char**);
  };
  const Command commands[] = {{"stats", stats_usage, cmd_stats},
                              {"generate", generate_usage, cmd_generate},
                              {"boundary", boundary_usage, cmd_boundary},
                              {"curvature", curvature_usage, cmd_curvature},
                              {"validate", validate_usage, cmd_validate},
                              {"simplify", simplify_usage, cmd_simplify},
                              {"demo", demo_usage, cmd_demo}};
  for (const Command& c : commands) {
    if (command != c.name) continue;
    if (wants_help(argc, argv)) {
      std::cout << c.usage;
      if (command == "generate") {
        std::cout << "\nshapes:\n";
        for (const auto& s : prstar::implicit_shapes())
          std::cout << "  " << s.first << ": " << s.second << '\n';
      }
      return 0;
    }
    try {
      return c.run(argc, argv);
    } catch (const Usage_error& e) {
      std::cerr << "prstar " << c.name << ": " << e.what() << "\n\n" << c.usage;
      return 2;
    } catch (const std::bad_alloc&) {
      std::cerr << "prstar " << c.name << ": out of memory\n";
      return 1;
    } catch (const std::exception& e) {
      std::cerr << "prstar " << c.name << ": " << e.what() << '\n';
      return 1;
    }
  }
  std::cerr << "prstar: unknown command '" << command << "'\n\n" << main_usage;
  return 2;
}
