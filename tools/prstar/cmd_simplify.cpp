// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar simplify: local half-edge-collapse simplification (paper Section 9).

#include "commands.h"

#include <CGAL/PR_star_octree/parameters.h>
#include <CGAL/PR_star_octree/mesh_quality.h>
#include <CGAL/bounding_box.h>
#include <CGAL/PR_star_octree/simplification.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include <iostream>
#include <limits>

namespace prstar {

namespace {

namespace params = CGAL::PR_star_octree::parameters;
namespace PSO = CGAL::PR_star_octree;

// The options, checked before anything runs (the library checks them too, with messages that do
// not name the options).
struct Simplify_settings {
  double target_fraction = 0, max_edge_length = std::numeric_limits<double>::infinity();
  PSO::Quality_measure measure = PSO::Quality_measure::MIN_DIHEDRAL_ANGLE;
  double floor = 5, feature_angle = 40;
  double max_error = 0.2; // in percent of the diagonal when `error_relative`
  bool error_relative = true;
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
  if (o.has("--min-dihedral") && o.has("--min-radius-ratio"))
    throw Usage_error("give one quality floor: --min-dihedral or --min-radius-ratio");
  if (o.has("--min-radius-ratio")) {
    s.measure = PSO::Quality_measure::RADIUS_RATIO;
    s.floor = o.get_double("--min-radius-ratio", 0.1);
    if (!(s.floor >= 0 && s.floor <= 1))
      throw Usage_error("--min-radius-ratio must be in [0, 1] (0: no floor)");
  } else {
    s.floor = o.get_double("--min-dihedral", 5);
    if (!(s.floor >= 0 && s.floor <= 70.5))
      throw Usage_error("--min-dihedral must be in [0, 70.5] degrees (0: no floor)");
  }
  s.feature_angle = o.get_double("--feature-angle", 40);
  if (!(s.feature_angle >= 0 && s.feature_angle <= 180))
    throw Usage_error("--feature-angle must be in [0, 180] degrees (180: no sharp edges)");
  const std::string e = o.get("--max-error", "0.2%");
  if (e == "none" || e == "inf") {
    s.error_relative = false;
    s.max_error = std::numeric_limits<double>::infinity();
  } else {
    s.error_relative = !e.empty() && e.back() == '%';
    const std::string number = s.error_relative ? e.substr(0, e.size() - 1) : e;
    char* end = nullptr;
    s.max_error = std::strtod(number.c_str(), &end);
    if (number.empty() || *end != '\0' || !(s.max_error >= 0) || !std::isfinite(s.max_error))
      throw Usage_error(
          "--max-error must be a distance, a percentage of the bounding-box diagonal (0.2%) or none");
  }
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

// The reasons of a Blocked record, named as in the JSON, largest first.
std::vector<std::pair<std::string, std::size_t>> reasons(const PSO::Simplification_statistics::Blocked& b) {
  std::vector<std::pair<std::string, std::size_t>> r{{"different_leaves", b.different_leaves},
                                                     {"feature", b.feature},
                                                     {"boundary", b.boundary},
                                                     {"flip", b.flip},
                                                     {"link", b.link},
                                                     {"quality", b.quality},
                                                     {"error", b.error}};
  std::stable_sort(r.begin(), r.end(), [](const auto& x, const auto& y) { return x.second > y.second; });
  return r;
}

void json_quality(Json& j, const char* key, const PSO::Mesh_quality& q) {
  j.key(key).begin_object();
  j.field("min_dihedral", q.min_dihedral_angle)
      .field("max_dihedral", q.max_dihedral_angle)
      .field("min_radius_ratio", q.min_radius_ratio)
      .field("share_under_5", q.share_under_5())
      .field("share_under_10", q.share_under_10());
  j.end_object();
}

int run_simplify(const Options& o) {
  const std::string& input = o.input();
  const std::string out = o.output();
  const std::size_t kv = o.kv();
  const Simplify_settings settings = simplify_settings(o);
  Progress_bar progress(o.show_progress());
  const Mesh mesh = read_mesh(input, progress);
  double error_bound = settings.max_error;
  if (settings.error_relative) {
    const CGAL::Bbox_3 box = CGAL::bbox_3(mesh.points.begin(), mesh.points.end());
    const double dx = box.xmax() - box.xmin(), dy = box.ymax() - box.ymin(), dz = box.zmax() - box.zmin();
    error_bound = settings.max_error / 100 * std::sqrt(dx * dx + dy * dy + dz * dz);
  }
  progress.phase("simplifying (k_v = " + bucket_size_string(kv) + ")");
  const auto res = PSO::simplify(mesh, params::target_fraction(settings.target_fraction)
                                           .max_edge_length(settings.max_edge_length)
                                           .bucket_size(kv)
                                           .quality_measure(settings.measure)
                                           .quality_floor(settings.floor)
                                           .feature_angle(settings.feature_angle)
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
  const bool short_of_target =
      s.stop == PSO::Simplification_stop::BLOCKED || s.stop == PSO::Simplification_stop::MAX_ROUNDS;
  const double removed_percent =
      s.input_tetrahedra ? 100. * double(s.removed_tetrahedra) / double(s.input_tetrahedra) : 0.;
  if (short_of_target) {
    const auto why = reasons(s.blocked_last_round);
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
  auto blocked = [](Json& j, const char* key, const PSO::Simplification_statistics::Blocked& b) {
    j.key(key).begin_object();
    j.field("different_leaves", b.different_leaves)
        .field("feature", b.feature)
        .field("boundary", b.boundary)
        .field("flip", b.flip)
        .field("link", b.link)
        .field("quality", b.quality)
        .field("error", b.error);
    j.end_object();
  };
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
    j.field("stop", PSO::simplification_stop_name(s.stop));
    blocked(j, "blocked", s.blocked);
    blocked(j, "blocked_last_round", s.blocked_last_round);
    json_quality(j, "input_quality", q_in);
    json_quality(j, "output_quality", q_out);
    j.key("boundary_error").begin_object();
    j.field("bound", s.max_boundary_error)
        .field("input_to_output", d.input_to_output)
        .field("output_to_input", d.output_to_input)
        .field("relative", d.relative());
    j.end_object();
    j.field("output", out).end_object();
    std::cout << j.str() << '\n';
    return status;
  }
  if (!o.show_summary()) return status;
  Table t({"", "input", "output"});
  t.add({"tetrahedra", std::to_string(s.input_tetrahedra),
         std::to_string(s.output_tetrahedra) + " (" + fixed(removed_percent, 1) + "% removed)"});
  t.add({"vertices", std::to_string(s.input_vertices), std::to_string(s.output_vertices)});
  t.add({"smallest dihedral angle", fixed(q_in.min_dihedral_angle, 2), fixed(q_out.min_dihedral_angle, 2)});
  t.add({"under 5 / 10 degrees",
         fixed(100 * q_in.share_under_5(), 3) + "% / " + fixed(100 * q_in.share_under_10(), 2) + "%",
         fixed(100 * q_out.share_under_5(), 3) + "% / " + fixed(100 * q_out.share_under_10(), 2) + "%"});
  t.add({"smallest radius ratio", fixed(q_in.min_radius_ratio, 3), fixed(q_out.min_radius_ratio, 3)});
  t.add({"boundary distance (of diagonal)", "",
         fixed(100 * d.relative(), 3) + "% (bound " +
             (std::isfinite(s.max_boundary_error) && d.diagonal > 0
                  ? fixed(100 * s.max_boundary_error / d.diagonal, 3) + "%)"
                  : std::string("none)"))});
  t.add({"rounds", "", std::to_string(s.rounds) + " (" + PSO::simplification_stop_name(s.stop) + ")"});
  t.add({"max queue size", "", std::to_string(s.max_queue_size)});
  Table b({"blocked candidates", "all rounds", "last round"});
  const auto all = reasons(s.blocked);
  for (const auto& r : all) {
    std::size_t last = 0;
    for (const auto& x : reasons(s.blocked_last_round))
      if (x.first == r.first) last = x.second;
    b.add({r.first, std::to_string(r.second), std::to_string(last)});
  }
  std::cout << input << " (k_v = " << bucket_size_string(kv) << ", " << fixed(s.seconds, 3) << " s)\n"
            << t.str() << b.str() << "wrote " << out << '\n';
  return status;
}

} // namespace

Command simplify_command() {
  return Command("simplify", "local half-edge-collapse simplification (paper Section 9)")
      .input()
      .synopsis("(--target F | --keep F | --max-length L)")
      .description(
          R"(Simplifies MESH by edge collapses leaf by leaf (paper Section 9): each leaf collapses its
short edges, shortest first, under the boundary, geometric (exact orientation) and link
conditions; then the mesh is compacted and the octree rebuilt, until the target is met or a round
removes nothing.  The sharp edges and corners of the boundary and the surfaces between labels are
kept (a feature vertex only slides along its curve, a corner never moves), no collapse creates a
tetrahedron under the quality floor unless it replaces a worse one, and the surface stays within
--max-error of the input's.  Point data, cell data and labels follow.  With --kv inf the octree
has one leaf: the global algorithm.  Exit status 4 when it stops before the target (the reason on
stderr and in the JSON); the mesh written is the last valid one reached.)")
      .option("--target", "F",
              "stop once this fraction of the tetrahedra is removed (0 < F < 1, or a\n"
              "percentage: 0.75 or 75%)")
      .option("--keep", "F",
              "stop once this fraction of the tetrahedra is left, as CGAL and MeshLab\n"
              "count it: --keep 25% is --target 75%")
      .option("--max-length", "L", "collapse only edges shorter than L (with --target: both)")
      .option("--min-dihedral", "DEG",
              "quality floor: smallest dihedral angle of a new tetrahedron (default 5; 0: none)")
      .option("--min-radius-ratio", "R", "quality floor on the radius ratio instead, in [0, 1] (e.g. 0.1)")
      .option("--feature-angle", "DEG",
              "surface edges bending more than DEG are sharp features (default 40; 180: none)")
      .option("--max-error", "E",
              "bound on the distance to the input surface: a distance, P% of the bounding-box\n"
              "diagonal (default 0.2%) or none")
      .option("--priority", "P",
              "length (shortest edge first, default) or quadric (smallest surface error first)")
      .option("--placement", "P",
              "half-edge (vertices never move, default) or optimal (the merged vertex at the best\n"
              "point of the edge when both ends are inside or on one smooth surface patch)")
      .kv()
      .output("OUT", "", "write the simplified mesh to OUT", true)
      .json_keys("keys: input_tetrahedra, output_tetrahedra, removed_tetrahedra, input_vertices,\n"
                 "output_vertices, kv, rounds, max_queue, seconds, stop (target_reached, nothing_left,\n"
                 "blocked, max_rounds), blocked and blocked_last_round {different_leaves, feature,\n"
                 "boundary, flip, link, quality, error}, input_quality and output_quality\n"
                 "{min_dihedral, max_dihedral, min_radius_ratio, share_under_5, share_under_10},\n"
                 "boundary_error {bound, input_to_output, output_to_input, relative}, output")
      .quiet_silences_summary()
      .check(simplify_settings)
      .run(run_simplify);
}

} // namespace prstar
