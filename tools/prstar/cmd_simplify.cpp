// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar simplify: local half-edge-collapse simplification (paper Section 9).

#include "commands.h"

#include "simplification_cli.h"

#include <CGAL/PR_star_octree/mesh_quality.h>
#include <CGAL/PR_star_octree/parameters.h>
#include <CGAL/PR_star_octree/simplification.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace prstar {

namespace {

namespace params = CGAL::PR_star_octree::parameters;
namespace PSO = CGAL::PR_star_octree;

// The options, checked before anything runs (the library checks them too, with messages that do
// not name the options).
struct Simplify_settings {
  double target_fraction = 0, max_edge_length = std::numeric_limits<double>::infinity();
  Mesh_guards guards;
  std::size_t optimization_rounds = 2;
  PSO::Collapse_priority priority = PSO::Collapse_priority::EDGE_LENGTH;
  PSO::Collapse_placement placement = PSO::Collapse_placement::HALF_EDGE;
};

Simplify_settings simplify_settings(const Options& o) {
  if (!o.has("--target") && !o.has("--keep") && !o.has("--max-length"))
    throw Usage_error("give --target, --keep or --max-length");
  Simplify_settings s;
  if (o.has("--target") && o.has("--keep")) throw Usage_error("give --target or --keep, not both");
  s.target_fraction = o.has("--keep") ? 1 - o.get_fraction("--keep", 1) : o.get_fraction("--target", 0);
  if (o.has("--target") && !(s.target_fraction > 0 && s.target_fraction < 1))
    throw Usage_error("--target must be a fraction of the tetrahedra in (0, 1), e.g. 0.5 or 50%");
  if (o.has("--keep") && !(s.target_fraction > 0 && s.target_fraction < 1))
    throw Usage_error("--keep must be a fraction of the tetrahedra in (0, 1), e.g. 0.25 or 25%");
  s.max_edge_length = o.get_double("--max-length", std::numeric_limits<double>::infinity());
  if (!(s.max_edge_length > 0)) throw Usage_error("--max-length must be positive");
  s.guards = guard_settings(o);
  const double rounds = o.get_double("--optimize", 2);
  if (!(rounds >= 0 && rounds <= 1000 && rounds == std::floor(rounds)))
    throw Usage_error("--optimize must be an integer in [0, 1000] (0: coarsen only)");
  s.optimization_rounds = static_cast<std::size_t>(rounds);
  const std::string priority = o.get("--priority", "length");
  if (priority == "quadric")
    s.priority = PSO::Collapse_priority::QUADRIC_ERROR;
  else if (priority != "length")
    throw Usage_error("--priority must be length or quadric");
  const std::string placement = o.get("--placement", "half-edge");
  if (placement == "optimal")
    s.placement = PSO::Collapse_placement::OPTIMAL;
  else if (placement != "half-edge")
    throw Usage_error("--placement must be half-edge or optimal");
  return s;
}

int run_simplify(const Options& o) {
  const std::string& input = o.input();
  const std::string out = o.output();
  const std::size_t kv = o.kv();
  const Simplify_settings settings = simplify_settings(o);
  Progress_bar progress(o.show_progress());
  const Mesh mesh = read_mesh(input, progress);
  const double error_bound = absolute_error_bound(settings.guards, bounding_box_diagonal(mesh.points));
  progress.phase("simplifying (k_v = " + bucket_size_string(kv) + ")");
  const auto res = PSO::simplify(mesh, params::target_fraction(settings.target_fraction)
                                           .max_edge_length(settings.max_edge_length)
                                           .bucket_size(kv)
                                           .min_dihedral_angle(settings.guards.min_dihedral)
                                           .max_dihedral_angle(settings.guards.max_dihedral)
                                           .min_radius_ratio(settings.guards.min_radius_ratio)
                                           .optimization_rounds(settings.optimization_rounds)
                                           .feature_angle(settings.guards.feature_angle)
                                           .max_boundary_error(error_bound)
                                           .collapse_priority(settings.priority)
                                           .collapse_placement(settings.placement));
  progress.finish();
  progress.phase("writing " + out);
  write_mesh_file(out, res.mesh);
  progress.finish();
  progress.phase("measuring the output");
  const PSO::Mesh_quality q_in = PSO::mesh_quality(mesh.points, mesh.tetrahedra);
  const PSO::Mesh_quality q_out = PSO::mesh_quality(res.mesh.points, res.mesh.tetrahedra);
  const PSO::Boundary_distance d =
      PSO::boundary_distance(mesh.points, mesh.tetrahedra, res.mesh.points, res.mesh.tetrahedra, 0.);
  progress.finish();
  const auto& s = res.statistics;
  const auto& opt = s.optimization;
  const bool short_of_target =
      s.stop == PSO::Simplification_stop::BLOCKED || s.stop == PSO::Simplification_stop::MAX_ROUNDS;
  // What left the mesh, collapses and flips together (the library's removed_tetrahedra counts the
  // collapses' only): what the target is measured against.
  const std::size_t removed = s.input_tetrahedra - (std::min)(s.output_tetrahedra, s.input_tetrahedra);
  const double removed_percent =
      s.input_tetrahedra ? 100. * double(removed) / double(s.input_tetrahedra) : 0.;
  if (short_of_target) {
    const auto why = blocked_reasons(s.blocked_last_round);
    std::cerr << "prstar simplify: stopped before the target: removed " << fixed(removed_percent, 1)
              << "% of the tetrahedra, target " << fixed(100 * settings.target_fraction, 1) << "%; ";
    if (s.stop == PSO::Simplification_stop::MAX_ROUNDS)
      std::cerr << "the maximum number of rounds was reached";
    else
      std::cerr << "the last round removed nothing, its candidates blocked mostly by " << why[0].first << " ("
                << why[0].second << "), then " << why[1].first << " (" << why[1].second << ")";
    std::cerr << "; wrote the last valid mesh to " << out << '\n';
  }
  const int status = short_of_target ? exit_target_not_reached : exit_success;
  if (o.json()) {
    Json j;
    j.begin_object()
        .field("input_tetrahedra", s.input_tetrahedra)
        .field("output_tetrahedra", s.output_tetrahedra)
        .field("removed_tetrahedra", removed)
        .field("input_vertices", s.input_vertices)
        .field("output_vertices", s.output_vertices)
        .key("kv");
    json_kv(j, kv).field("rounds", s.rounds).field("max_queue", s.max_queue_size).field("seconds", s.seconds);
    j.field("stop", PSO::simplification_stop_name(s.stop));
    json_blocked(j, "blocked", s.blocked);
    json_blocked(j, "blocked_last_round", s.blocked_last_round);
    j.key("optimization").begin_object();
    json_operation_counts(j, opt).field("rounds", opt.rounds);
    json_blocked(j, "refused_moves", opt.refused_moves);
    json_blocked(j, "refused_flips", opt.refused_flips);
    json_blocked(j, "refused_splits", opt.refused_splits);
    j.end_object();
    json_quality(j, "input_quality", q_in);
    json_quality(j, "output_quality", q_out);
    json_boundary_error(j, d, s.max_boundary_error);
    j.field("output", out).end_object();
    std::cout << j.str() << '\n';
    return status;
  }
  if (!o.show_summary()) return status;
  Table t({"", "input", "output"});
  t.add({"tetrahedra", std::to_string(s.input_tetrahedra),
         std::to_string(s.output_tetrahedra) + " (" + fixed(removed_percent, 1) + "% removed)"});
  t.add({"vertices", std::to_string(s.input_vertices), std::to_string(s.output_vertices)});
  quality_rows(t, q_in, q_out);
  boundary_distance_row(t, d, s.max_boundary_error);
  t.add({"rounds", "", std::to_string(s.rounds) + " (" + PSO::simplification_stop_name(s.stop) + ")"});
  t.add({"max queue size", "", std::to_string(s.max_queue_size)});
  const bool optimized = settings.optimization_rounds > 0;
  if (optimized) {
    t.add({"optimisation rounds", "", std::to_string(opt.rounds)});
    t.add({"vertex moves", "", std::to_string(opt.vertex_moves)});
    t.add({"flips 2-3 / 3-2 / 4-4", "",
           std::to_string(opt.flips_2_3) + " / " + std::to_string(opt.flips_3_2) + " / " +
               std::to_string(opt.flips_4_4)});
    t.add({"edge removals", "", std::to_string(opt.edge_removals)});
  }
  // Why collapses were blocked (all rounds, last round) and, with optimisation, why moves and flips
  // were refused: one row per reason, the collapses' most frequent first.
  std::vector<std::string> header{"blocked candidates", "all rounds", "last round"};
  if (optimized) {
    header.push_back("moves refused");
    header.push_back("flips refused");
  }
  Table b(header);
  for (const auto& r : blocked_reasons(s.blocked)) {
    std::vector<std::string> row{r.first, std::to_string(r.second),
                                 std::to_string(blocked_count(s.blocked_last_round, r.first))};
    if (optimized) {
      row.push_back(std::to_string(blocked_count(opt.refused_moves, r.first)));
      row.push_back(std::to_string(blocked_count(opt.refused_flips, r.first)));
    }
    b.add(row);
  }
  std::cout << input << " (k_v = " << bucket_size_string(kv) << ", " << fixed(s.seconds, 3) << " s)\n"
            << t.str() << b.str() << "wrote " << out << '\n';
  return status;
}

} // namespace

Command simplify_command() {
  Command c("simplify", "local half-edge-collapse simplification (paper Section 9)");
  c.input()
      .synopsis("(--target F | --keep F | --max-length L)")
      .description(
          R"(Simplifies MESH by edge collapses leaf by leaf (paper Section 9): each leaf collapses its
short edges, shortest first, under the boundary, geometric (exact orientation) and link
conditions, then improves its tetrahedra by flips and vertex moves (--optimize); the mesh is
compacted and the octree rebuilt, until the target is met or a round removes nothing, and
--optimize rounds of flips and moves follow.  The sharp edges and corners of the boundary and the
surfaces between labels are kept (a feature vertex only slides along its curve, a corner never
moves); no collapse, flip or move makes a tetrahedron under a quality floor (--min-dihedral,
--min-radius-ratio, both at once) or over the ceiling (--max-dihedral) unless it replaces worse
ones, and the surface stays within --max-error of the input's.  Point data, cell data and labels
follow.  With --kv inf the octree has one leaf: the global algorithm.  Exit status 4 when it stops
before the target (the reason on stderr and in the JSON); the mesh written is the last valid one
reached.)")
      .option("--target", "F",
              "stop once this fraction of the tetrahedra is removed (0 < F < 1, or a\n"
              "percentage: 0.75 or 75%)")
      .option("--keep", "F",
              "stop once this fraction of the tetrahedra is left, as CGAL and MeshLab\n"
              "count it: --keep 25% is --target 75%")
      .option("--max-length", "L", "collapse only edges shorter than L (with --target: both)");
  guard_options(c)
      .option("--optimize", "N",
              "rounds of flips and vertex moves after the collapses (default 2; 0: coarsen\n"
              "only, no vertex moves and no flips)")
      .option("--priority", "P",
              "length (shortest edge first, default) or quadric (smallest surface error first)")
      .option("--placement", "P",
              "half-edge (the removed end goes into the other, default) or optimal (the merged\n"
              "vertex at the best point of the edge when both ends are inside or on one smooth\n"
              "surface patch)")
      .kv()
      .output("OUT", "", "write the simplified mesh to OUT", true)
      .json_keys("keys: input_tetrahedra, output_tetrahedra, removed_tetrahedra (input - output),\n"
                 "input_vertices, output_vertices, kv, rounds, max_queue, seconds, stop\n"
                 "(target_reached, nothing_left, blocked, max_rounds), blocked and blocked_last_round\n"
                 "{different_leaves, feature, boundary, flip, link, quality, error}, optimization\n"
                 "{vertex_moves, flips_2_3, flips_3_2, flips_4_4, edge_removals, splits,\n"
                 "tetrahedra_added, tetrahedra_deleted (by the flips), rounds, refused_moves,\n"
                 "refused_flips, refused_splits (each as blocked)}, input_quality and\n"
                 "output_quality {min_dihedral, max_dihedral, min_radius_ratio, share_under_5,\n"
                 "share_under_10}, boundary_error {bound, input_to_output, output_to_input,\n"
                 "relative}, output")
      .quiet_silences_summary()
      .check(simplify_settings)
      .run(run_simplify);
  return c;
}

} // namespace prstar
