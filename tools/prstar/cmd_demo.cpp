// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar demo: the statistics of the PR-star octree of a built-in mesh, no input file needed.

#include "commands.h"
#include "generate.h"

namespace prstar {

namespace {

// The demo's mesh: --cell-size, checked before anything runs.
double demo_cell_size(const Options& o) {
  const double cell_size = o.get_double("--cell-size", 0.04);
  if (!(cell_size >= 0.005)) throw Usage_error("--cell-size must be at least 0.005 for the demo");
  return cell_size;
}

int run_demo(const Options& o) {
  Generate_options opt;
  opt.shape = "sphere";
  opt.cell_size = demo_cell_size(o);
  // The mesher reports its own steps on a terminal (as in `prstar generate`): no bar of ours
  // meanwhile, which would redraw over its lines.
  opt.quiet = !o.show_progress();
  Progress_bar progress(o.show_progress());
  report_statistics(generate_mesh(opt),
                    "built-in unit ball (CGAL Mesh_3, cell size " + fixed(opt.cell_size, 3) + ")", o.kvs(),
                    o.max_depth(), o.compact(), o.coordinate_precision(), o.json(), progress);
  return exit_success;
}

} // namespace

Command demo_command() {
  return Command(
             "demo",
             "build the PR-star octree of a built-in mesh (CGAL Mesh_3 unit ball) and show its statistics")
      .description(
          R"(Meshes the unit ball with CGAL Mesh_3 (no input file needed) and prints the statistics of its
PR-star octree for several bucket thresholds k_v, as `prstar stats` does.)")
      .option("--cell-size", "S", "target tetrahedron size of the ball (default 0.04, at least 0.005)")
      .kv_list("10,20,50,100,200,inf")
      .max_depth()
      .json_keys("(an array of objects for a list of k_v); the keys of `prstar stats --json`")
      .check(demo_cell_size)
      .run(run_demo);
}

} // namespace prstar
