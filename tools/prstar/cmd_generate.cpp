// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar generate: a tetrahedral mesh made with CGAL Mesh_3 or TetGen.

#include "commands.h"
#include "generate.h"
#include "lattice.h"

#include <CGAL/PR_star_octree/IO.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <sstream>

namespace prstar {

namespace {

bool is_lattice(const Options& o) {
  return o.get("--shape") == "lattice";
}

// The lattice's options, checked before anything runs.
Lattice lattice_options(const Options& o) {
  if (!o.has("--cells")) throw Usage_error("--shape lattice needs --cells N");
  if (o.has("--cell-size") || o.has("--surface") || o.flag("--tetgen") || o.has("--facet-size") ||
      o.has("--facet-distance"))
    throw Usage_error("--shape lattice takes --cells only (no mesher options)");
  const double cells = o.get_double("--cells", 0);
  if (!(cells >= 1) || cells != static_cast<double>(static_cast<std::size_t>(cells)) || cells > 2000)
    throw Usage_error("--cells must be an integer from 1 to 2000");
  Lattice l;
  l.cells = static_cast<std::size_t>(cells);
  return l;
}

int run_lattice(const Options& o) {
  const Lattice lattice = lattice_options(o);
  const std::string out = o.output();
  Progress_bar progress(o.show_progress());
  const auto start = std::chrono::steady_clock::now();
  progress.phase("writing the lattice to " + out);
  if (CGAL::PR_star_octree::IO::internal::lower_extension(out) == "vtu") {
    // streamed: memory does not grow with the lattice
    write_through_temporary(out, [&](const std::string& tmp) {
      std::ofstream f(tmp, std::ios::binary);
      if (!f) throw std::runtime_error(tmp + ": cannot open for writing");
      write_lattice_vtu(f, lattice, progress.callback());
      f.close();
      if (!f) throw std::runtime_error(tmp + ": cannot write");
    });
  } else {
    // another format: the lattice made in memory (its binary VTU, then the mesh read from it),
    // refused first when that cannot fit (about 56 bytes of VTU and 16 of mesh per tetrahedron)
    CGAL::PR_star_octree::IO::internal::check_memory(out, 0, lattice.number_of_vertices(),
                                                     lattice.number_of_tetrahedra(), 24 + 8 + 32, 16 + 56);
    Mesh mesh;
    {
      std::stringstream vtu(std::ios::in | std::ios::out | std::ios::binary);
      write_lattice_vtu(vtu, lattice, progress.callback());
      CGAL::PR_star_octree::IO::read_vtu(vtu, mesh, out);
    }
    write_mesh_file(out, mesh);
  }
  progress.finish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (o.json()) {
    Json j;
    j.begin_object()
        .field("output", out)
        .field("mesher", "lattice")
        .field("vertices", lattice.number_of_vertices())
        .field("tetrahedra", lattice.number_of_tetrahedra())
        .field("seconds", seconds)
        .end_object();
    std::cout << j.str() << '\n';
  } else if (o.show_summary())
    std::cout << out << ": " << lattice.number_of_vertices() << " vertices, "
              << lattice.number_of_tetrahedra() << " tetrahedra (Kuhn lattice, " << fixed(seconds, 2)
              << " s)\n";
  return exit_success;
}

// The mesher's options, checked before anything runs.
Generate_options generate_options(const Options& o) {
  Generate_options opt;
  opt.shape = o.get("--shape");
  opt.surface_file = o.get("--surface");
  if (opt.shape.empty() == opt.surface_file.empty())
    throw Usage_error("give exactly one of --shape and --surface");
  if (!o.has("--cell-size")) throw Usage_error("missing --cell-size");
  opt.cell_size = o.get_double("--cell-size", 0);
  opt.facet_size = o.get_double("--facet-size", 0);
  opt.facet_distance = o.get_double("--facet-distance", 0);
  if (!(opt.cell_size > 0)) throw Usage_error("--cell-size must be positive");
  if (opt.facet_size < 0 || opt.facet_distance < 0) throw Usage_error("sizes must be positive");
  opt.tetgen = o.flag("--tetgen");
  if (!opt.shape.empty()) {
    std::vector<std::string> names{"lattice"};
    std::string list;
    for (const auto& shape : implicit_shapes()) {
      names.push_back(shape.first);
      list += shape.first + ", ";
    }
    if (std::find(names.begin(), names.end(), opt.shape) == names.end())
      throw Usage_error("unknown shape '" + opt.shape + "'" + did_you_mean(opt.shape, names) +
                        " (shapes: " + list + "lattice)");
  }
  // The generator's own progress messages are finer than ours: let it speak, and keep ours silent.
  opt.quiet = !o.show_progress();
  return opt;
}

int run_generate(const Options& o) {
  if (is_lattice(o)) return run_lattice(o);
  const Generate_options opt = generate_options(o);
  const std::string out = o.output();
  Progress_bar progress(o.show_progress());
  const auto start = std::chrono::steady_clock::now();
  const Mesh mesh = generate_mesh(opt);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.phase("writing " + out);
  write_mesh_file(out, mesh);
  progress.finish();
  if (o.json()) {
    Json j;
    j.begin_object()
        .field("output", out)
        .field("mesher", opt.tetgen ? "tetgen" : "mesh_3")
        .field("vertices", mesh.points.size())
        .field("tetrahedra", mesh.tetrahedra.size())
        .field("seconds", seconds)
        .end_object();
    std::cout << j.str() << '\n';
  } else if (o.show_summary())
    std::cout << out << ": " << mesh.points.size() << " vertices, " << mesh.tetrahedra.size()
              << " tetrahedra (" << (opt.tetgen ? "TetGen" : "CGAL Mesh_3") << ", " << fixed(seconds, 2)
              << " s)\n";
  return exit_success;
}

std::string shape_list() {
  std::string s = "\nshapes:\n";
  for (const auto& shape : implicit_shapes()) s += "  " + shape.first + ": " + shape.second + '\n';
  s += "  lattice: with --cells N, a jittered N x N x N Kuhn lattice (6 N^3 tetrahedra, point array\n"
       "           `scalar`), in any format; to a .vtu it is streamed without holding the mesh (for\n"
       "           huge inputs), as raw appended data, which MPI ranks read in byte ranges (VTK 9.1/9.2,\n"
       "           ParaView 5.11, cannot read appended data with Debian 12's current libexpat:\n"
       "           `prstar convert` it for them)\n";
  return s;
}

} // namespace

Command generate_command() {
  return Command("generate", "make a tetrahedral mesh with CGAL Mesh_3 or TetGen")
      .synopsis("(--shape NAME | --surface FILE.off) --cell-size S [--facet-size S] [--facet-distance D] "
                "[--tetgen] | --shape lattice --cells N")
      .description(
          R"(Makes a tetrahedral mesh with CGAL Mesh_3 (default) or TetGen (--tetgen) and writes it to OUT.)")
      .option("--shape", "NAME", "an implicit domain (see the list below)")
      .option("--surface", "FILE.off", "a closed triangle surface bounding a polyhedral domain", true)
      .option("--cell-size", "S", "target tetrahedron size (required, > 0)")
      .option("--facet-size", "S", "target surface triangle size (default: the cell size)")
      .option("--facet-distance", "D", "surface approximation error (default: cell size / 10)")
      .flag("--tetgen", "mesh the same surface with TetGen (quality, max volume from the cell size)")
      .option("--cells", "N", "--shape lattice: N^3 cubes of 6 tetrahedra each")
      .output("OUT", "", "write the mesh to OUT", true)
      .json_keys("keys: output, mesher (mesh_3, tetgen or lattice), vertices, tetrahedra, seconds")
      .quiet_silences_summary()
      .check([](const Options& o) {
        if (is_lattice(o))
          lattice_options(o);
        else
          generate_options(o);
      })
      .epilog(shape_list)
      .run(run_generate);
}

} // namespace prstar
