// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What `prstar simplify` and `prstar remesh` share: the options that guard a mesh being changed
// (the quality floors and ceiling, the feature angle, the error bound), declared once with one help
// text and one check each, and the parts of their reports (quality, refusals, optimisation) with
// the same JSON keys and table rows.

#ifndef PRSTAR_SIMPLIFICATION_CLI_H
#define PRSTAR_SIMPLIFICATION_CLI_H

#include "command.h"

#include <CGAL/PR_star_octree/Simplification_statistics.h>
#include <CGAL/PR_star_octree/mesh_quality.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace prstar {

/// The guards of a mesh being changed, as the options give them.
struct Mesh_guards {
  double min_dihedral = 5;       // degrees; 0: none
  double max_dihedral = 165;     // degrees; 180: none
  double min_radius_ratio = 0.1; // 0: none
  double feature_angle = 40;     // degrees; 180: no sharp edges
  double max_error = 0.2;        // in percent of the diagonal when `error_relative`
  bool error_relative = true;
};

/// Declares --min-dihedral, --max-dihedral, --min-radius-ratio, --feature-angle and --max-error.
inline Command& guard_options(Command& c) {
  return c
      .option("--min-dihedral", "DEG",
              "floor on the smallest dihedral angle of new tetrahedra (default 5; 0: none)")
      .option("--min-radius-ratio", "R",
              "floor on the radius ratio 3r/R of new tetrahedra (default 0.1; 0: none)")
      .option("--max-dihedral", "DEG",
              "ceiling on the largest dihedral angle of new tetrahedra (default 165; 180: none)")
      .option("--feature-angle", "DEG",
              "surface edges bending more than DEG are sharp features (default 40; 180: none)")
      .option("--max-error", "E",
              "bound on the distance to the input surface: a distance, P% of the bounding-box\n"
              "diagonal (default 0.2%) or none");
}

/// The guards of `o`, checked (`Usage_error` with the option's name).
inline Mesh_guards guard_settings(const Options& o) {
  Mesh_guards g;
  g.min_dihedral = o.get_double("--min-dihedral", 5);
  if (!(g.min_dihedral >= 0 && g.min_dihedral <= 70.5))
    throw Usage_error("--min-dihedral must be in [0, 70.5] degrees (0: no floor)");
  // Every tetrahedron has a dihedral angle of at least 70.53 degrees (the regular one's): a lower
  // ceiling would refuse everything.
  g.max_dihedral = o.get_double("--max-dihedral", 165);
  if (!(g.max_dihedral >= 70.6 && g.max_dihedral <= 180))
    throw Usage_error("--max-dihedral must be in [70.6, 180] degrees (180: no ceiling)");
  g.min_radius_ratio = o.get_double("--min-radius-ratio", 0.1);
  if (!(g.min_radius_ratio >= 0 && g.min_radius_ratio <= 1))
    throw Usage_error("--min-radius-ratio must be in [0, 1] (0: no floor)");
  g.feature_angle = o.get_double("--feature-angle", 40);
  if (!(g.feature_angle >= 0 && g.feature_angle <= 180))
    throw Usage_error("--feature-angle must be in [0, 180] degrees (180: no sharp edges)");
  const std::string e = o.get("--max-error", "0.2%");
  if (e == "none" || e == "inf") {
    g.error_relative = false;
    g.max_error = std::numeric_limits<double>::infinity();
  } else {
    g.error_relative = !e.empty() && e.back() == '%';
    const std::string number = g.error_relative ? e.substr(0, e.size() - 1) : e;
    char* end = nullptr;
    g.max_error = std::strtod(number.c_str(), &end);
    if (number.empty() || *end != '\0' || !(g.max_error >= 0) || !std::isfinite(g.max_error))
      throw Usage_error(
          "--max-error must be a distance, a percentage of the bounding-box diagonal (0.2%) or none");
  }
  return g;
}

/// The length of the diagonal of the bounding box of `points` (0 for none).
template <class Point>
double bounding_box_diagonal(const std::vector<Point>& points) {
  if (points.empty()) return 0;
  double lo[3], hi[3];
  for (int i = 0; i < 3; ++i) lo[i] = hi[i] = CGAL::to_double(points[0][i]);
  for (const Point& p : points)
    for (int i = 0; i < 3; ++i) {
      lo[i] = (std::min)(lo[i], CGAL::to_double(p[i]));
      hi[i] = (std::max)(hi[i], CGAL::to_double(p[i]));
    }
  const double dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

/// The absolute error bound of `g` for a mesh whose bounding box has this diagonal.
inline double absolute_error_bound(const Mesh_guards& g, double diagonal) {
  return g.error_relative ? g.max_error / 100 * diagonal : g.max_error;
}

/// The reasons of a Blocked record, named as in the JSON, largest first (stable: the JSON's order
/// on ties).
inline std::vector<std::pair<std::string, std::size_t>>
blocked_reasons(const CGAL::PR_star_octree::Simplification_statistics::Blocked& b) {
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

/// One count of a Blocked record by its JSON name.
inline std::size_t blocked_count(const CGAL::PR_star_octree::Simplification_statistics::Blocked& b,
                                 const std::string& reason) {
  for (const auto& r : blocked_reasons(b))
    if (r.first == reason) return r.second;
  return 0;
}

/// `"key": {different_leaves, feature, boundary, flip, link, quality, error}`.
inline void json_blocked(Json& j, const char* key,
                         const CGAL::PR_star_octree::Simplification_statistics::Blocked& b) {
  j.key(key).begin_object();
  j.field("different_leaves", b.different_leaves)
      .field("feature", b.feature)
      .field("boundary", b.boundary)
      .field("flip", b.flip)
      .field("link", b.link)
      .field("quality", b.quality)
      .field("error", b.error);
  j.end_object();
}

/// `"key": {min_dihedral, max_dihedral, min_radius_ratio, share_under_5, share_under_10}`.
inline void json_quality(Json& j, const char* key, const CGAL::PR_star_octree::Mesh_quality& q) {
  j.key(key).begin_object();
  j.field("min_dihedral", q.min_dihedral_angle)
      .field("max_dihedral", q.max_dihedral_angle)
      .field("min_radius_ratio", q.min_radius_ratio)
      .field("share_under_5", q.share_under_5())
      .field("share_under_10", q.share_under_10());
  j.end_object();
}

/// The operation counts of the optimisation, without the refusals: vertex_moves, flips_2_3,
/// flips_3_2, flips_4_4, edge_removals, splits, tetrahedra_added, tetrahedra_deleted (by the flips
/// and splits).
inline Json& json_operation_counts(Json& j,
                                   const CGAL::PR_star_octree::Simplification_statistics::Optimization& s) {
  return j.field("vertex_moves", s.vertex_moves)
      .field("flips_2_3", s.flips_2_3)
      .field("flips_3_2", s.flips_3_2)
      .field("flips_4_4", s.flips_4_4)
      .field("edge_removals", s.edge_removals)
      .field("splits", s.splits)
      .field("tetrahedra_added", s.tetrahedra_added)
      .field("tetrahedra_deleted", s.tetrahedra_deleted);
}

/// The rows "smallest dihedral angle" ... "smallest radius ratio" of a table with an input and an
/// output column.
inline void quality_rows(Table& t, const CGAL::PR_star_octree::Mesh_quality& in,
                         const CGAL::PR_star_octree::Mesh_quality& out) {
  t.add({"smallest dihedral angle", fixed(in.min_dihedral_angle, 2), fixed(out.min_dihedral_angle, 2)});
  t.add({"largest dihedral angle", fixed(in.max_dihedral_angle, 2), fixed(out.max_dihedral_angle, 2)});
  t.add({"under 5 / 10 degrees",
         fixed(100 * in.share_under_5(), 3) + "% / " + fixed(100 * in.share_under_10(), 2) + "%",
         fixed(100 * out.share_under_5(), 3) + "% / " + fixed(100 * out.share_under_10(), 2) + "%"});
  t.add({"smallest radius ratio", fixed(in.min_radius_ratio, 3), fixed(out.min_radius_ratio, 3)});
}

/// The row "boundary distance (of diagonal)": the measured distance and the bound, in percent.
// The "boundary_error" object of the JSON of simplify and remesh: the bound and the distances.
inline void json_boundary_error(Json& j, const CGAL::PR_star_octree::Boundary_distance& d, double bound) {
  j.key("boundary_error").begin_object();
  j.field("bound", bound)
      .field("input_to_output", d.input_to_output)
      .field("output_to_input", d.output_to_input)
      .field("relative", d.relative());
  j.end_object();
}

inline void boundary_distance_row(Table& t, const CGAL::PR_star_octree::Boundary_distance& d, double bound) {
  t.add({"boundary distance (of diagonal)", "",
         fixed(100 * d.relative(), 3) + "% (bound " +
             (std::isfinite(bound) && d.diagonal > 0 ? fixed(100 * bound / d.diagonal, 3) + "%)"
                                                     : std::string("none)"))});
}

} // namespace prstar

#endif // PRSTAR_SIMPLIFICATION_CLI_H
