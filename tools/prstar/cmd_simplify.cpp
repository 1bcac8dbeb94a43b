// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar simplify: local half-edge-collapse simplification (paper Section 9).

#include "commands.h"

#include <CGAL/PR_star_octree/parameters.h>
#include <CGAL/PR_star_octree/simplification.h>

#include <iostream>
#include <limits>

namespace prstar {

namespace {

namespace params = CGAL::PR_star_octree::parameters;

// --target and --max-length, checked before anything runs (the library checks them too, with
// messages that do not name the options).
struct Simplify_settings {
  double target_fraction, max_edge_length;
};

Simplify_settings simplify_settings(const Options& o) {
  if (!o.has("--target") && !o.has("--max-length")) throw Usage_error("give --target or --max-length");
  Simplify_settings s;
  s.target_fraction = o.get_double("--target", 0);
  if (o.has("--target") && !(s.target_fraction > 0 && s.target_fraction < 1))
    throw Usage_error("--target must be a fraction of the tetrahedra in (0, 1), e.g. 0.5");
  s.max_edge_length = o.get_double("--max-length", std::numeric_limits<double>::infinity());
  if (!(s.max_edge_length > 0)) throw Usage_error("--max-length must be positive");
  return s;
}

int run_simplify(const Options& o) {
  const std::string& input = o.input();
  const std::string out = o.output();
  const std::size_t kv = o.kv();
  const Simplify_settings settings = simplify_settings(o);
  Progress_bar progress(o.show_progress());
  const Mesh mesh = read_mesh(input, progress);
  progress.phase("simplifying (k_v = " + bucket_size_string(kv) + ")");
  const auto res = CGAL::PR_star_octree::simplify(mesh, params::target_fraction(settings.target_fraction)
                                                            .max_edge_length(settings.max_edge_length)
                                                            .bucket_size(kv));
  progress.finish();
  progress.phase("writing " + out);
  write_mesh_file(out, res.mesh);
  progress.finish();
  const auto& s = res.statistics;
  if (o.json()) {
    Json j;
    j.begin_object()
        .field("input_tetrahedra", s.input_tetrahedra)
        .field("output_tetrahedra", s.output_tetrahedra)
        .field("removed_tetrahedra", s.removed_tetrahedra)
        .field("input_vertices", s.input_vertices)
        .field("output_vertices", s.output_vertices)
        .key("kv");
    json_kv(j, kv).field("rounds", s.rounds).field("max_queue", s.max_queue_size).field("seconds", s.seconds);
    j.key("blocked").begin_object();
    j.field("different_leaves", s.blocked.different_leaves)
        .field("boundary", s.blocked.boundary)
        .field("flip", s.blocked.flip)
        .field("link", s.blocked.link);
    j.end_object();
    j.field("output", out).end_object();
    std::cout << j.str() << '\n';
    return exit_success;
  }
  if (!o.show_summary()) return exit_success;
  Table t({"", "count"});
  t.add({"input tetrahedra", std::to_string(s.input_tetrahedra)});
  t.add({"output tetrahedra", std::to_string(s.output_tetrahedra)});
  t.add({"removed",
         std::to_string(s.removed_tetrahedra) + " (" +
             fixed(s.input_tetrahedra ? 100. * double(s.removed_tetrahedra) / double(s.input_tetrahedra) : 0.,
                   1) +
             "%)"});
  t.add({"vertices", std::to_string(s.input_vertices) + " -> " + std::to_string(s.output_vertices)});
  t.add({"rounds", std::to_string(s.rounds)});
  t.add({"max queue size", std::to_string(s.max_queue_size)});
  t.add({"blocked: ends in different leaves", std::to_string(s.blocked.different_leaves)});
  t.add({"blocked: boundary", std::to_string(s.blocked.boundary)});
  t.add({"blocked: flip (exact orientation)", std::to_string(s.blocked.flip)});
  t.add({"blocked: link condition", std::to_string(s.blocked.link)});
  std::cout << input << " (k_v = " << bucket_size_string(kv) << ", " << fixed(s.seconds, 3) << " s)\n"
            << t.str() << "wrote " << out << '\n';
  return exit_success;
}

} // namespace

Command simplify_command() {
  return Command("simplify", "local half-edge-collapse simplification (paper Section 9)")
      .input()
      .synopsis("(--target F | --max-length L)")
      .description(
          R"(Simplifies MESH by half-edge collapses leaf by leaf (paper Section 9): each leaf collapses its
short edges, shortest first, under the boundary, geometric (exact orientation) and link
conditions; then the mesh is compacted and the octree rebuilt, until the target is met or a round
removes nothing.  Vertices never move; point data (the scalar field) is kept.  With --kv inf the
octree has one leaf: the global algorithm.)")
      .option("--target", "F", "stop once this fraction of the tetrahedra is removed (0 < F < 1)")
      .option("--max-length", "L", "collapse only edges shorter than L (with --target: both)")
      .kv()
      .output("OUT", "", "write the simplified mesh to OUT", true)
      .json_keys("keys: input_tetrahedra, output_tetrahedra, removed_tetrahedra, input_vertices,\n"
                 "output_vertices, kv, rounds, max_queue, seconds,\n"
                 "blocked {different_leaves, boundary, flip, link}, output")
      .quiet_silences_summary()
      .check(simplify_settings)
      .run(run_simplify);
}

} // namespace prstar
