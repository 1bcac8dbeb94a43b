// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar remesh: local remeshing to a target edge length (splits, collapses, flips, smoothing).

#include "commands.h"

#include "simplification_cli.h"

#include <CGAL/PR_star_octree/mesh_quality.h>
#include <CGAL/PR_star_octree/parameters.h>
#include <CGAL/PR_star_octree/remeshing.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace prstar {

namespace {

namespace params = CGAL::PR_star_octree::parameters;
namespace PSO = CGAL::PR_star_octree;

struct Remesh_settings {
  double edge_length = 0; // the target, or P% of the diagonal when `edge_length_relative`
  bool edge_length_relative = false;
  std::string size_field; // the name of the point-data array; empty: a uniform --edge-length
  std::size_t iterations = 5;
  Mesh_guards guards;
};

Remesh_settings remesh_settings(const Options& o) {
  Remesh_settings s;
  if (o.has("--edge-length") && o.has("--size-field"))
    throw Usage_error("give --edge-length or --size-field, not both");
  if (!o.has("--edge-length") && !o.has("--size-field"))
    throw Usage_error("give --edge-length or --size-field");
  if (o.has("--edge-length")) {
    const std::string h = o.get("--edge-length");
    s.edge_length_relative = !h.empty() && h.back() == '%';
    const std::string number = s.edge_length_relative ? h.substr(0, h.size() - 1) : h;
    char* end = nullptr;
    s.edge_length = std::strtod(number.c_str(), &end);
    if (number.empty() || *end != '\0' || !(s.edge_length > 0) || !std::isfinite(s.edge_length))
      throw Usage_error(
          "--edge-length must be a positive length or a percentage of the bounding-box diagonal "
          "(e.g. 0.05 or 2%)");
  } else {
    s.size_field = o.get("--size-field");
    if (s.size_field.empty()) throw Usage_error("--size-field needs the name of a point-data array");
  }
  const double n = o.get_double("--iterations", 5);
  if (!(n >= 1 && n <= 1000 && n == std::floor(n)))
    throw Usage_error("--iterations must be an integer in [1, 1000]");
  s.iterations = static_cast<std::size_t>(n);
  s.guards = guard_settings(o);
  return s;
}

// The size field named `name` of `mesh`, checked: every value positive and finite (the error names
// the array and the first vertex that is not).
const std::vector<double>& size_field(const Mesh& mesh, const std::string& name, const std::string& input) {
  const auto it = std::find_if(mesh.point_data.begin(), mesh.point_data.end(),
                               [&](const auto& a) { return a.name == name; });
  if (it == mesh.point_data.end()) {
    std::string known;
    for (const auto& d : mesh.point_data) known += (known.empty() ? "" : ", ") + d.name;
    throw std::runtime_error(input + ": no point-data array named '" + name + "' for --size-field" +
                             (known.empty() ? " (the mesh has no point data)" : " (it has: " + known + ")"));
  }
  for (std::size_t v = 0; v < it->values.size(); ++v)
    if (!(it->values[v] > 0) || !std::isfinite(it->values[v]))
      throw std::runtime_error(input + ": size field '" + name + "': the target edge length at vertex " +
                               std::to_string(v) + " is " + number(it->values[v]) +
                               " (it must be positive and finite)");
  return it->values;
}

void json_edges(Json& j, const char* key, const PSO::Edge_length_quality& e) {
  j.key(key).begin_object();
  j.field("edges", e.edges)
      .field("share_in_range", e.share_in_range())
      .field("share_short", e.share_short())
      .field("share_long", e.share_long())
      .field("median_ratio", e.median_ratio);
  j.end_object();
}

std::string percent(double share) {
  return fixed(100 * share, 2) + "%";
}

int run_remesh(const Options& o) {
  const std::string& input = o.input();
  const std::string out = o.output();
  const std::size_t kv = o.kv();
  const Remesh_settings settings = remesh_settings(o);
  Progress_bar progress(o.show_progress());
  const Mesh mesh = read_mesh(input, progress);
  const double diagonal = bounding_box_diagonal(mesh.points);
  const double error_bound = absolute_error_bound(settings.guards, diagonal);
  const bool uniform = settings.size_field.empty();
  const double h = !uniform                        ? 0.
                   : settings.edge_length_relative ? settings.edge_length / 100 * diagonal
                                                   : settings.edge_length;
  if (uniform && !(h > 0))
    throw std::runtime_error(input + ": --edge-length " + o.get("--edge-length") +
                             " is 0: the mesh has no extent");
  const std::vector<double>* field = uniform ? nullptr : &size_field(mesh, settings.size_field, input);
  // (the package's parameters first: CGAL's number_of_iterations ends the chain)
  const auto np = params::bucket_size(kv)
                      .min_dihedral_angle(settings.guards.min_dihedral)
                      .max_dihedral_angle(settings.guards.max_dihedral)
                      .min_radius_ratio(settings.guards.min_radius_ratio)
                      .feature_angle(settings.guards.feature_angle)
                      .max_boundary_error(error_bound)
                      .number_of_iterations(settings.iterations);
  progress.phase("remeshing (k_v = " + bucket_size_string(kv) + ")");
  const auto res =
      uniform ? PSO::remesh(mesh, h, np) : PSO::remesh(mesh, CGAL::make_property_map(*field), np);
  progress.finish();
  progress.phase("writing " + out);
  write_mesh_file(out, res.mesh);
  progress.finish();
  progress.phase("measuring the output");
  const PSO::Mesh_quality q_in = PSO::mesh_quality(mesh.points, mesh.tetrahedra);
  const PSO::Mesh_quality q_out = PSO::mesh_quality(res.mesh.points, res.mesh.tetrahedra);
  // The output's targets: the size field as the output carries it (each vertex the value of the
  // input vertex it stands for), so that the measure can be repeated on the file written.
  const std::vector<double>* out_field = nullptr;
  if (!uniform)
    for (const auto& a : res.mesh.point_data)
      if (a.name == settings.size_field) out_field = &a.values;
  // The edges within [0.8 h, 1.33 h] of their target (the range CGAL's isotropic remeshing aims at).
  auto edges = [&](const auto& points, const auto& tets, const std::vector<double>* sizing) {
    return sizing ? PSO::edge_length_quality(points, tets, *sizing)
                  : PSO::edge_length_quality(points, tets, h);
  };
  const PSO::Edge_length_quality e_in = edges(mesh.points, mesh.tetrahedra, field);
  const PSO::Edge_length_quality e_out = edges(res.mesh.points, res.mesh.tetrahedra, out_field);
  const PSO::Boundary_distance d =
      PSO::boundary_distance(mesh.points, mesh.tetrahedra, res.mesh.points, res.mesh.tetrahedra, 0.);
  progress.finish();
  const auto& s = res.statistics;
  const auto& opt = s.optimization;
  if (o.json()) {
    Json j;
    j.begin_object()
        .field("input_tetrahedra", s.input_tetrahedra)
        .field("output_tetrahedra", s.output_tetrahedra)
        .field("input_vertices", s.input_vertices)
        .field("output_vertices", s.output_vertices);
    if (uniform)
      j.field("edge_length", h).key("size_field").null();
    else
      j.key("edge_length").null().field("size_field", settings.size_field);
    j.key("kv");
    json_kv(j, kv)
        .field("iterations", settings.iterations)
        .field("rounds", s.rounds)
        .field("seconds", s.seconds);
    j.key("operations").begin_object();
    json_operation_counts(j, opt).field("collapses", s.collapses);
    j.end_object();
    j.key("refused").begin_object();
    json_blocked(j, "collapses", s.blocked);
    json_blocked(j, "splits", opt.refused_splits);
    json_blocked(j, "flips", opt.refused_flips);
    json_blocked(j, "moves", opt.refused_moves);
    j.end_object();
    json_quality(j, "input_quality", q_in);
    json_quality(j, "output_quality", q_out);
    json_edges(j, "input_edges", e_in);
    json_edges(j, "output_edges", e_out);
    json_boundary_error(j, d, s.max_boundary_error);
    j.field("output", out).end_object();
    std::cout << j.str() << '\n';
    return exit_success;
  }
  if (!o.show_summary()) return exit_success;
  std::string target;
  if (uniform)
    target =
        "h = " + short_number(h) +
        (settings.edge_length_relative ? " (" + number(settings.edge_length) + "% of the diagonal)" : "");
  else {
    const auto range = std::minmax_element(field->begin(), field->end());
    target =
        "h = size field '" + settings.size_field + "'" +
        (field->empty() ? ""
                        : " (" + short_number(*range.first) + " to " + short_number(*range.second) + ")");
  }
  Table t({"", "input", "output"});
  t.add({"tetrahedra", std::to_string(s.input_tetrahedra), std::to_string(s.output_tetrahedra)});
  t.add({"vertices", std::to_string(s.input_vertices), std::to_string(s.output_vertices)});
  quality_rows(t, q_in, q_out);
  t.add({"edges within [0.8 h, 1.33 h]", percent(e_in.share_in_range()), percent(e_out.share_in_range())});
  t.add({"  shorter / longer", percent(e_in.share_short()) + " / " + percent(e_in.share_long()),
         percent(e_out.share_short()) + " / " + percent(e_out.share_long())});
  t.add({"median edge length / h", fixed(e_in.median_ratio, 3), fixed(e_out.median_ratio, 3)});
  boundary_distance_row(t, d, s.max_boundary_error);
  t.add({"rounds", "", std::to_string(s.rounds) + " (of " + std::to_string(settings.iterations) + ")"});
  // What was done, and why the rest was refused (one row per reason, the most frequent first).
  const std::vector<std::pair<std::string, const PSO::Simplification_statistics::Blocked*>> kinds{
      {"collapses", &s.blocked},
      {"splits", &opt.refused_splits},
      {"flips", &opt.refused_flips},
      {"moves", &opt.refused_moves}};
  Table ops({"operations", "done"});
  ops.add({"edge splits", std::to_string(opt.splits)});
  ops.add({"edge collapses", std::to_string(s.collapses)});
  ops.add({"flips 2-3 / 3-2 / 4-4", std::to_string(opt.flips_2_3) + " / " + std::to_string(opt.flips_3_2) +
                                        " / " + std::to_string(opt.flips_4_4)});
  ops.add({"edge removals", std::to_string(opt.edge_removals)});
  ops.add({"vertex moves", std::to_string(opt.vertex_moves)});
  std::vector<std::string> header{"refused, by first reason"};
  for (const auto& k : kinds) header.push_back(k.first);
  Table refused(header);
  std::vector<std::pair<std::string, std::size_t>> order = blocked_reasons(s.blocked);
  for (auto& r : order) {
    r.second = 0;
    for (const auto& k : kinds) r.second += blocked_count(*k.second, r.first);
  }
  std::stable_sort(order.begin(), order.end(),
                   [](const auto& x, const auto& y) { return x.second > y.second; });
  for (const auto& r : order) {
    std::vector<std::string> row{r.first};
    for (const auto& k : kinds) row.push_back(std::to_string(blocked_count(*k.second, r.first)));
    refused.add(row);
  }
  std::cout << input << ": remeshed to " << target << " (k_v = " << bucket_size_string(kv) << ", "
            << fixed(s.seconds, 3) << " s)\n"
            << t.str() << ops.str() << refused.str() << "wrote " << out << '\n';
  return exit_success;
}

} // namespace

Command remesh_command() {
  Command c("remesh", "local remeshing to a target edge length (splits, collapses, flips, smoothing)");
  c.input()
      .synopsis("(--edge-length H | --size-field NAME)")
      .description(
          R"(Remeshes MESH towards a target edge length h, leaf by leaf on PR-star octrees: each round
splits the edges longer than 4/3 h at their midpoint, collapses those shorter than 4/5 h, flips
(2-3, 3-2, 4-4, edge removal) and moves vertices where the worst tetrahedron around gets better,
then compacts the mesh and rebuilds the octree.  Every operation is checked with exact
orientation tests; the sharp edges and corners of the boundary and the surfaces between labels
are kept (a feature vertex only slides along its curve, a corner never moves), no tetrahedron is
made under a quality floor or over the ceiling unless it replaces worse ones, and the surface
stays within --max-error of the input's.  h is one length (--edge-length) or a point-data array
of MESH giving the target at each vertex (--size-field; an edge's target is the mean of its
ends').  Point data, cell data and labels follow; a vertex made by a split carries the data of
the first end of its edge.  The table and the JSON give the share of the edges within
[0.8 h, 1.33 h] of their target (on the output, the target of a vertex is the size-field value
it carries), the quality before and after, the distance between the boundaries, and the
operations done and refused.)")
      .option("--edge-length", "H",
              "the target edge length: a length, or P% of the bounding-box diagonal\n"
              "(e.g. 0.05 or 2%)")
      .option("--size-field", "NAME",
              "the target edge length at each vertex: the point-data array NAME of\n"
              "MESH (positive values)")
      .option("--iterations", "N", "rounds of splits, collapses, flips and moves (default 5)");
  guard_options(c)
      .kv()
      .output("OUT", "", "write the remeshed mesh to OUT", true)
      .json_keys("keys: input_tetrahedra, output_tetrahedra, input_vertices, output_vertices,\n"
                 "edge_length (null with a size field), size_field (its name, or null), kv,\n"
                 "iterations, rounds, seconds, operations {vertex_moves, flips_2_3, flips_3_2,\n"
                 "flips_4_4, edge_removals, splits, tetrahedra_added, tetrahedra_deleted (by the\n"
                 "flips and splits), collapses}, refused {collapses, splits, flips,\n"
                 "moves: each {different_leaves, feature, boundary, flip, link, quality, error}},\n"
                 "input_quality and output_quality {min_dihedral, max_dihedral, min_radius_ratio,\n"
                 "share_under_5, share_under_10}, input_edges and output_edges {edges,\n"
                 "share_in_range (within [0.8 h, 1.33 h]), share_short, share_long, median_ratio\n"
                 "(of length / h)}, boundary_error {bound, input_to_output, output_to_input,\n"
                 "relative}, output")
      .quiet_silences_summary()
      .check(remesh_settings)
      .run(run_remesh);
  return c;
}

} // namespace prstar
