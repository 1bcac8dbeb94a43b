// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar generate: a tetrahedral mesh made with CGAL Mesh_3 or TetGen.

#include "commands.h"
#include "generate.h"

#include <chrono>
#include <iostream>

namespace prstar {

namespace {

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
  // The generator's own progress messages are finer than ours: let it speak, and keep ours silent.
  opt.quiet = !o.show_progress();
  return opt;
}

int run_generate(const Options& o) {
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
  return s;
}

} // namespace

Command generate_command() {
  return Command("generate", "make a tetrahedral mesh with CGAL Mesh_3 or TetGen")
      .synopsis("(--shape NAME | --surface FILE.off) --cell-size S [--facet-size S] [--facet-distance D] "
                "[--tetgen]")
      .description(
          R"(Makes a tetrahedral mesh with CGAL Mesh_3 (default) or TetGen (--tetgen) and writes it to OUT.)")
      .option("--shape", "NAME", "an implicit domain (see the list below)")
      .option("--surface", "FILE.off", "a closed triangle surface bounding a polyhedral domain", true)
      .option("--cell-size", "S", "target tetrahedron size (required, > 0)")
      .option("--facet-size", "S", "target surface triangle size (default: the cell size)")
      .option("--facet-distance", "D", "surface approximation error (default: cell size / 10)")
      .flag("--tetgen", "mesh the same surface with TetGen (quality, max volume from the cell size)")
      .output("OUT", "", "write the mesh to OUT", true)
      .json_keys("keys: output, mesher (mesh_3 or tetgen), vertices, tetrahedra, seconds")
      .quiet_silences_summary()
      .check([](const Options& o) { generate_options(o); })
      .epilog(shape_list)
      .run(run_generate);
}

} // namespace prstar
