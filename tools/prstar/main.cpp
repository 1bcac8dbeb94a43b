// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar: the command-line tool of the PR-star octree package.

#include "cli.h"
#include "generate.h"

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/Leaf_topology.h>

#include <sys/stat.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
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
  stats      storage statistics of the PR-star octree of a mesh (paper Table 1)
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

// Writes through a temporary file renamed at the end: an error never leaves a half-written OUT.
void write_mesh_safely(const std::string& out, const Mesh& mesh) {
  // The temporary name keeps the extension, which selects the format: OUT.mesh -> OUT.prstar-tmp.mesh
  const std::size_t dot = out.find_last_of('.');
  const std::size_t slash = out.find_last_of('/');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  const std::string tmp =
      has_ext ? out.substr(0, dot) + ".prstar-tmp" + out.substr(dot) : out + ".prstar-tmp";
  try {
    CGAL::PR_star_octree::IO::write_tetrahedral_mesh(tmp, mesh);
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
  if (std::rename(tmp.c_str(), out.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error(out + ": cannot write the output file");
  }
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
