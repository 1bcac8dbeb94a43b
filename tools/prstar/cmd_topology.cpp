// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar critical and prstar morse: the topology of a scalar field (scalar_topology.h): critical
// points, the Forman gradient, Morse complexes, persistence pairs.

#include "commands.h"
#include "octree_mesh_view.h"

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>
#include <CGAL/PR_star_octree/Leaf_executor.h>
#include <CGAL/PR_star_octree/parameters.h>
#include <CGAL/PR_star_octree/scalar_topology.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <iterator>

namespace prstar {

namespace {

using Octree = CGAL::PR_star_octree_3<>;
namespace params = CGAL::PR_star_octree::parameters;
namespace PSO = CGAL::PR_star_octree;
const std::size_t no_vertex = PSO::Critical_simplex::no_vertex;

// The field of --field in the user's vertex order: a coordinate or a point-data array (taken out
// of the mesh); its range over the vertices of the tetrahedra.
struct Field {
  std::string name;
  std::vector<double> values;
  std::vector<char> referenced; // the vertices in a tetrahedron
  double min = 0, max = 0;
};

Field take_field(Mesh& mesh, const std::string& requested, const std::string& input) {
  Field f;
  f.name = requested;
  if (f.name == "x" || f.name == "y" || f.name == "z") {
    const int axis = f.name[0] - 'x';
    f.values.reserve(mesh.points.size());
    for (const auto& p : mesh.points) f.values.push_back(p[axis]);
  } else {
    const std::size_t i = find_point_field(mesh.point_data, f.name, input);
    f.values = mesh.point_data[i].values;
  }
  f.referenced.assign(mesh.points.size(), 0);
  for (const auto& t : mesh.tetrahedra)
    for (auto v : t)
      if (v < f.referenced.size()) f.referenced[v] = 1;
  bool first = true;
  for (std::size_t v = 0; v < f.values.size(); ++v) {
    if (!f.referenced[v]) continue;
    f.min = first ? f.values[v] : std::min(f.min, f.values[v]);
    f.max = first ? f.values[v] : std::max(f.max, f.values[v]);
    first = false;
  }
  return f;
}

// The octree of the mesh, which takes it over; the mesh's arrays are kept aside when a mesh file is
// written (and the tetrahedron permutation then, for its cell arrays and ours).
Octree build_octree(const Options& o, Mesh&& mesh, Mesh_arrays& arrays, bool write, Progress_bar& progress) {
  if (write)
    arrays = Mesh_arrays(mesh);
  else {
    mesh.point_data.clear();
    mesh.cell_data.clear();
  }
  progress.phase("building the PR-star octree (k_v = " + bucket_size_string(o.kv()) + ")");
  // (the lower stars are read from VT)
  Octree tree(std::move(mesh), params::bucket_size(o.kv())
                                   .bucket_size_relations(CGAL::PR_star_octree::VERTEX_TETRAHEDRA)
                                   .maximum_depth(o.max_depth())
                                   .compact_tetrahedra(o.compact())
                                   .coordinate_precision(o.coordinate_precision())
                                   .vertex_permutation(true)
                                   .tetrahedron_permutation(write));
  o.set_used_kv(tree);
  return tree;
}

std::string type_name(PSO::Critical_type t) {
  return PSO::critical_type_name(t);
}

// The check of the gradient: its critical simplices add up to the Euler characteristic, counted in
// the same pass apart from the lower stars.
long long checked_euler(const PSO::Forman_gradient<Octree>& g) {
  const long long chi = g.euler_characteristic();
  if (chi != g.alternating_sum())
    throw std::logic_error("internal error: the critical simplices of the gradient (alternating sum " +
                           std::to_string(g.alternating_sum()) +
                           ") do not add up to the Euler characteristic " + std::to_string(chi) +
                           "; please report it with the mesh");
  return chi;
}

Json& json_gradient(Json& j, const PSO::Forman_gradient<Octree>& g, long long chi) {
  j.key("gradient")
      .begin_object()
      .field("critical_vertices", g.number_of_critical_simplices(0))
      .field("critical_edges", g.number_of_critical_simplices(1))
      .field("critical_triangles", g.number_of_critical_simplices(2))
      .field("critical_tetrahedra", g.number_of_critical_simplices(3))
      .field("alternating_sum", g.alternating_sum())
      .field("euler_characteristic", chi)
      .field("bytes_per_tetrahedron", g.bytes_per_tetrahedron())
      .end_object();
  return j;
}

void table_gradient(Table& t, const PSO::Forman_gradient<Octree>& g, long long chi) {
  t.add({"gradient: critical vertices", std::to_string(g.number_of_critical_simplices(0))});
  t.add({"  critical edges", std::to_string(g.number_of_critical_simplices(1))});
  t.add({"  critical triangles", std::to_string(g.number_of_critical_simplices(2))});
  t.add({"  critical tetrahedra", std::to_string(g.number_of_critical_simplices(3))});
  t.add({"  alternating sum = Euler characteristic",
         std::to_string(g.alternating_sum()) + " = " + std::to_string(chi)});
  t.add({"  bytes per tetrahedron", number(g.bytes_per_tetrahedron())});
}

// ----------------------------------------------------------------------------------------------
// prstar critical

int run_critical(const Options& o) {
  const std::string& input = o.input();
  const std::string out = o.output(), csv = o.output("--csv");
  const bool gradient = o.flag("--gradient");
  Progress_bar progress(o.show_progress());
  Mesh mesh = read_mesh(input, progress);
  Field field = take_field(mesh, o.get("--field"), input);
  const auto start = std::chrono::steady_clock::now();
  Mesh_arrays arrays;
  const Octree tree = build_octree(o, std::move(mesh), arrays, !out.empty(), progress);
  const std::size_t nv = tree.number_of_vertices(), nt = tree.number_of_tetrahedra();
  progress.phase("classifying the vertices");
  std::vector<PSO::Critical_type> types(nv, PSO::Critical_type::REGULAR);
  std::vector<PSO::Critical_point> points;
  const auto values = CGAL::make_property_map(field.values);
  const PSO::Critical_point_counts counts = PSO::compute_critical_points(
      tree, values, CGAL::make_property_map(types),
      params::critical_points_output(std::back_inserter(points)).progress(progress.callback()));
  progress.finish();
  PSO::Forman_gradient<Octree> g;
  long long chi = 0;
  if (gradient) {
    progress.phase("computing the Forman gradient");
    g = PSO::compute_forman_gradient(tree, values, params::progress(progress.callback()));
    progress.finish();
    chi = checked_euler(g);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::vector<Octree::Index> from_original = tree.vertex_from_original();
  auto coordinates = [&](std::size_t v) { return tree.coordinates(tree.point(from_original[v])); };
  if (!csv.empty()) {
    progress.phase("writing " + csv);
    write_text_file(csv, [&](std::ostream& f) {
      f << "vertex,x,y,z,value,type,type_name,lower_components,upper_components,boundary\n";
      for (const auto& p : points) {
        const auto c = coordinates(p.vertex);
        f << p.vertex << ',' << number(c[0]) << ',' << number(c[1]) << ',' << number(c[2]) << ','
          << number(p.value) << ',' << int(p.type) << ',' << type_name(p.type) << ',' << p.lower_components
          << ',' << p.upper_components << ',' << (p.on_boundary ? 1 : 0) << '\n';
      }
    });
    progress.finish();
  }
  if (!out.empty()) {
    progress.phase("writing " + out);
    std::vector<PSO::Point_data_array> result(3);
    result[0] = {"critical_type", std::vector<double>(nv)};
    result[1] = {"lower_components", std::vector<double>(nv)};
    result[2] = {"upper_components", std::vector<double>(nv)};
    for (std::size_t v = 0; v < nv; ++v) {
      result[0].values[v] = static_cast<double>(types[v]);
      result[1].values[v] = result[2].values[v] = field.referenced[v] ? 1 : 0;
    }
    for (const auto& p : points) {
      result[1].values[p.vertex] = p.lower_components;
      result[2].values[p.vertex] = p.upper_components;
    }
    Octree_mesh_view<Octree> view(tree, std::move(arrays));
    write_octree_mesh(out, view, result);
    progress.finish();
  }

  // interior critical points, by type
  std::size_t interior[6] = {0, 0, 0, 0, 0, 0};
  for (const auto& p : points)
    if (!p.on_boundary) ++interior[static_cast<int>(p.type)];
  const std::size_t all[6] = {counts.minima, counts.saddles_1,  counts.saddles_2,
                              counts.maxima, counts.degenerate, counts.regular};
  const char* keys[6] = {"minima", "saddles_1", "saddles_2", "maxima", "degenerate", "regular"};
  if (o.json()) {
    Json j;
    j.begin_object().field("vertices", nv).field("tetrahedra", nt).key("kv");
    json_kv(j, o).field("field", field.name).field("field_min", field.min).field("field_max", field.max);
    for (int k = 0; k < 6; ++k) j.field(keys[k], all[k]);
    j.field("unreferenced", counts.unreferenced)
        .field("join_multiplicity", counts.join_multiplicity)
        .field("split_multiplicity", counts.split_multiplicity);
    j.key("interior").begin_object();
    for (int k = 0; k < 5; ++k) j.field(keys[k], interior[k]);
    j.end_object();
    j.key("critical_points").begin_array();
    for (const auto& p : points) {
      const auto c = coordinates(p.vertex);
      j.begin_object()
          .field("vertex", p.vertex)
          .field("type", type_name(p.type))
          .field("lower_components", p.lower_components)
          .field("upper_components", p.upper_components)
          .field("boundary", p.on_boundary)
          .field("value", p.value)
          .key("point")
          .begin_array()
          .value(c[0])
          .value(c[1])
          .value(c[2])
          .end_array()
          .end_object();
    }
    j.end_array();
    if (gradient) json_gradient(j, g, chi);
    j.field("seconds", seconds);
    if (!out.empty()) j.field("output", out);
    if (!csv.empty()) j.field("csv", csv);
    j.end_object();
    std::cout << j.str() << '\n';
    return exit_success;
  }
  Table t({"", "vertices", "inside"});
  const char* names[6] = {"minima", "1-saddles", "2-saddles", "maxima", "degenerate", "regular"};
  for (int k = 0; k < 6; ++k)
    t.add({names[k], std::to_string(all[k]), k < 5 ? std::to_string(interior[k]) : "-"});
  if (counts.unreferenced != 0) t.add({"in no tetrahedron", std::to_string(counts.unreferenced), "-"});
  if (gradient) {
    Table tg({"", "count"});
    table_gradient(tg, g, chi);
    std::cout << input << ": critical points of '" << field.name << "' (" << short_number(field.min) << " .. "
              << short_number(field.max) << "), k_v = " << o.kv_label() << ", " << fixed(seconds, 3) << " s\n"
              << t.str() << tg.str();
  } else {
    std::cout << input << ": critical points of '" << field.name << "' (" << short_number(field.min) << " .. "
              << short_number(field.max) << "), k_v = " << o.kv_label() << ", " << fixed(seconds, 3) << " s\n"
              << t.str();
  }
  if (!out.empty()) std::cout << "wrote " << out << '\n';
  if (!csv.empty()) std::cout << "wrote " << csv << '\n';
  return exit_success;
}

// ----------------------------------------------------------------------------------------------
// prstar morse

// The arcs as VTK XML poly data (ASCII): one polyline each, cell arrays saddle_dimension, saddle
// (its position in the list of critical simplices), saddle_vertex and extremum (user's vertex
// indices, -1 when the path leaves the domain), saddle_value.
void write_arcs_vtp(const std::string& path, const std::vector<PSO::Morse_arc>& arcs,
                    const std::vector<PSO::Critical_simplex>& critical) {
  write_text_file(path, [&](std::ostream& f) {
    std::size_t n = 0;
    for (const auto& a : arcs) n += a.points.size();
    f << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n<PolyData>\n<Piece NumberOfPoints=\""
      << n << "\" NumberOfVerts=\"0\" NumberOfLines=\"" << arcs.size()
      << "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n<Points>\n<DataArray type=\"Float64\" "
         "NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto& a : arcs)
      for (const auto& p : a.points) f << number(p[0]) << ' ' << number(p[1]) << ' ' << number(p[2]) << '\n';
    f << "</DataArray>\n</Points>\n<Lines>\n<DataArray type=\"Int64\" Name=\"connectivity\" "
         "format=\"ascii\">\n";
    std::size_t k = 0;
    for (const auto& a : arcs) {
      for (std::size_t i = 0; i < a.points.size(); ++i) f << k++ << (i + 1 < a.points.size() ? ' ' : '\n');
    }
    f << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    k = 0;
    for (const auto& a : arcs) f << (k += a.points.size()) << '\n';
    f << "</DataArray>\n</Lines>\n<CellData>\n";
    auto array = [&](const char* type, const char* name,
                     const std::function<std::string(const PSO::Morse_arc&)>& v) {
      f << "<DataArray type=\"" << type << "\" Name=\"" << name << "\" format=\"ascii\">\n";
      for (const auto& a : arcs) f << v(a) << '\n';
      f << "</DataArray>\n";
    };
    auto id = [](std::size_t v) { return v == no_vertex ? std::string("-1") : std::to_string(v); };
    array("Int32", "saddle_dimension",
          [](const PSO::Morse_arc& a) { return std::to_string(a.saddle_dimension); });
    array("Int64", "saddle", [](const PSO::Morse_arc& a) { return std::to_string(a.saddle); });
    array("Int64", "saddle_vertex",
          [&](const PSO::Morse_arc& a) { return id(critical[a.saddle].vertices[0]); });
    array("Int64", "extremum", [&](const PSO::Morse_arc& a) { return id(a.extremum); });
    array("Float64", "saddle_value",
          [&](const PSO::Morse_arc& a) { return number(critical[a.saddle].value); });
    f << "</CellData>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  });
}

const char* pair_type(const PSO::Persistence_pair& p) {
  return p.type == PSO::Persistence_pair::MINIMUM_SADDLE ? "minimum-saddle" : "saddle-maximum";
}

int run_morse(const Options& o) {
  const std::string& input = o.input();
  const std::string out = o.output(), csv = o.output("--csv"), arcs_file = o.output("--arcs");
  const double relative = o.get_fraction("--persistence", 0.0);
  if (!(relative >= 0 && relative <= 1))
    throw Usage_error("--persistence must be a fraction of the field's range in [0, 1] (or a percentage)");
  Progress_bar progress(o.show_progress());
  Mesh mesh = read_mesh(input, progress);
  Field field = take_field(mesh, o.get("--field"), input);
  const double threshold = relative * (field.max - field.min);
  const auto start = std::chrono::steady_clock::now();
  Mesh_arrays arrays;
  const Octree tree = build_octree(o, std::move(mesh), arrays, !out.empty(), progress);
  const std::size_t nv = tree.number_of_vertices(), nt = tree.number_of_tetrahedra();
  progress.phase("computing the Morse complexes");
  const auto values = CGAL::make_property_map(field.values);
  std::vector<PSO::Morse_arc> arcs;
  const auto np = params::persistence_threshold(threshold).progress(progress.callback());
  const PSO::Morse_complexes<Octree> m =
      arcs_file.empty()
          ? PSO::compute_morse_complexes(tree, values, np)
          : PSO::compute_morse_complexes(tree, values, np.arcs_output(std::back_inserter(arcs)));
  progress.finish();
  const long long chi = checked_euler(m.gradient);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::size_t kept[2] = {0, 0}, total[2] = {0, 0};
  for (const auto& p : m.persistence_pairs) {
    ++total[p.type];
    kept[p.type] += !(p.persistence() < threshold);
  }
  if (!csv.empty()) {
    progress.phase("writing " + csv);
    write_text_file(csv, [&](std::ostream& f) {
      f << "type,extremum,saddle,extremum_value,saddle_value,birth,death,persistence\n";
      for (const auto& p : m.persistence_pairs) {
        auto n = [](double x) { return std::isfinite(x) ? number(x) : std::string(x > 0 ? "inf" : "-inf"); };
        f << pair_type(p) << ',' << p.extremum << ','
          << (p.is_essential() ? std::string() : std::to_string(p.saddle)) << ',' << number(p.extremum_value)
          << ',' << (p.is_essential() ? std::string() : number(p.saddle_value)) << ',' << n(p.birth()) << ','
          << n(p.death()) << ',' << n(p.persistence()) << '\n';
      }
    });
    progress.finish();
  }
  if (!arcs_file.empty()) {
    progress.phase("writing " + arcs_file);
    write_arcs_vtp(arcs_file, arcs, m.gradient.critical_simplices());
    progress.finish();
  }
  if (!out.empty()) {
    progress.phase("writing " + out);
    std::vector<PSO::Point_data_array> result(2);
    result[0] = {"ascending_cell", std::vector<double>(nv)};
    result[1] = {"critical_type", std::vector<double>(nv)};
    for (std::size_t v = 0; v < nv; ++v) {
      result[0].values[v] =
          m.ascending_cell[v] == no_vertex ? -1.0 : static_cast<double>(m.ascending_cell[v]);
      result[1].values[v] = static_cast<double>(m.critical_type[v]);
    }
    Octree_mesh_view<Octree> view(tree, std::move(arrays));
    // the descending cells, in the octree's order of the tetrahedra (the order written)
    PSO::Point_data_array cells{"descending_cell", std::vector<double>(nt)};
    for (std::size_t t = 0; t < nt; ++t) {
      const std::size_t c = m.descending_cell[tree.original_tetrahedron(static_cast<Octree::Index>(t))];
      cells.values[t] = c == no_vertex ? -1.0 : static_cast<double>(c);
    }
    view.cell_data.push_back(std::move(cells));
    write_octree_mesh(out, view, result);
    progress.finish();
  }

  if (o.json()) {
    Json j;
    j.begin_object().field("vertices", nv).field("tetrahedra", nt).key("kv");
    json_kv(j, o)
        .field("field", field.name)
        .field("field_min", field.min)
        .field("field_max", field.max)
        .field("persistence", relative)
        .field("threshold", threshold);
    const auto& c = m.critical_points;
    j.key("critical_points")
        .begin_object()
        .field("minima", c.minima)
        .field("saddles_1", c.saddles_1)
        .field("saddles_2", c.saddles_2)
        .field("maxima", c.maxima)
        .field("degenerate", c.degenerate)
        .field("regular", c.regular)
        .end_object();
    json_gradient(j, m.gradient, chi);
    j.field("ascending_cells", m.ascending_cells)
        .field("descending_cells", m.descending_cells)
        .field("outflow_tetrahedra", m.outflow_tetrahedra)
        .field("minimum_saddle_pairs", total[0])
        .field("saddle_maximum_pairs", total[1])
        .field("minimum_saddle_pairs_kept", kept[0])
        .field("saddle_maximum_pairs_kept", kept[1]);
    j.key("pairs").begin_array();
    for (const auto& p : m.persistence_pairs) {
      j.begin_object().field("type", pair_type(p)).field("extremum", p.extremum);
      if (p.is_essential())
        j.key("saddle").null();
      else
        j.field("saddle", p.saddle);
      j.field("extremum_value", p.extremum_value)
          .field("saddle_value", p.is_essential() ? std::nan("") : p.saddle_value)
          .field("persistence", p.persistence())
          .end_object();
    }
    j.end_array();
    if (!arcs_file.empty()) j.field("arcs", arcs.size());
    j.field("seconds", seconds);
    if (!out.empty()) j.field("output", out);
    if (!arcs_file.empty()) j.field("arcs_file", arcs_file);
    if (!csv.empty()) j.field("csv", csv);
    j.end_object();
    std::cout << j.str() << '\n';
    return exit_success;
  }
  Table t({"", "count"});
  const auto& c = m.critical_points;
  t.add({"minima / 1-saddles / 2-saddles / maxima",
         std::to_string(c.minima) + " / " + std::to_string(c.saddles_1) + " / " +
             std::to_string(c.saddles_2) + " / " + std::to_string(c.maxima)});
  table_gradient(t, m.gradient, chi);
  t.add({"minimum-saddle pairs (kept)", std::to_string(total[0]) + " (" + std::to_string(kept[0]) + ")"});
  t.add({"saddle-maximum pairs (kept)", std::to_string(total[1]) + " (" + std::to_string(kept[1]) + ")"});
  t.add({"ascending 3-cells (minima)", std::to_string(m.ascending_cells)});
  t.add({"descending 3-cells (maxima)", std::to_string(m.descending_cells)});
  t.add({"tetrahedra flowing out of the boundary", std::to_string(m.outflow_tetrahedra)});
  if (!arcs_file.empty()) t.add({"arcs", std::to_string(arcs.size())});
  std::cout << input << ": Morse complexes of '" << field.name << "' (" << short_number(field.min) << " .. "
            << short_number(field.max) << "), persistence threshold " << number(relative * 100) << "% ("
            << short_number(threshold) << "), k_v = " << o.kv_label() << ", " << fixed(seconds, 3) << " s\n"
            << t.str();
  if (!out.empty()) std::cout << "wrote " << out << '\n';
  if (!arcs_file.empty()) std::cout << "wrote " << arcs_file << '\n';
  if (!csv.empty()) std::cout << "wrote " << csv << '\n';
  return exit_success;
}

const char* field_help = "a point-data array of MESH (default: its first one), or x, y, z for a coordinate";

} // namespace

Command critical_command() {
  return Command("critical", "critical points of a scalar field (minima, saddles, maxima)")
      .input()
      .description(
          R"(Classifies every vertex of MESH by the connected components of its lower and upper links
(the field compared as (value, vertex index), so that flat regions are well defined): minimum
(empty lower link), maximum (empty upper link), 1-saddle (2 lower components, 1 upper),
2-saddle (1 lower, 2 upper), degenerate (any other count: monkey saddles), regular.  The link
of a boundary vertex is its disc, as TTK's ScalarFieldCriticalPoints takes it; the table counts
the vertices inside the mesh apart.  The type codes are TTK's: 0 minimum, 1 1-saddle, 2 2-saddle,
3 maximum, 4 degenerate, 5 regular.)")
      .option("--field", "NAME|x|y|z", field_help)
      .flag("--gradient", "also compute the Forman gradient (ProcessLowerStars) and check that its critical\n"
                          "simplices add up to the Euler characteristic")
      .kv()
      .max_depth()
      .output("OUT", point_data_outputs(),
              "write the mesh (labels kept) with the point arrays critical_type (TTK's codes),\n"
              "lower_components and upper_components")
      .output("OUT.csv", ".csv",
              "write one row per vertex that is not regular, by vertex index:\n"
              "vertex,x,y,z,value,type,type_name,lower_components,upper_components,boundary",
              false, "--csv")
      .json_keys(
          "keys: vertices, tetrahedra, kv, kv_automatic, field, field_min, field_max, minima, saddles_1,\n"
          "saddles_2, maxima, degenerate, regular, unreferenced, join_multiplicity,\n"
          "split_multiplicity, interior (the same five counts inside the mesh), critical_points\n"
          "(objects: vertex, type, lower_components, upper_components, boundary, value, point),\n"
          "gradient (with --gradient: critical_vertices, critical_edges, critical_triangles,\n"
          "critical_tetrahedra, alternating_sum, euler_characteristic, bytes_per_tetrahedron),\n"
          "seconds, output, csv")
      .run(run_critical);
}

Command morse_command() {
  return Command("morse", "Morse complexes and persistence pairs of a scalar field")
      .input()
      .description(
          R"(The discrete (Forman) gradient of the field by the lower stars of the vertices, the ascending
3-cells of its minima (per vertex) and the descending 3-cells of its maxima (per tetrahedron,
-1 where the gradient path leaves through the boundary), and the persistence pairs of the
extrema: minimum-saddle (sublevel sets) and saddle-maximum (superlevel sets).  With
--persistence, the extrema of pairs below that fraction of the field's range are cancelled:
their cells join the cells they merge into.)")
      .option("--field", "NAME|x|y|z", field_help)
      .option("--persistence", "F",
              "cancel the pairs of persistence below F times the field's range (0.05 or 5%;\n"
              "default 0: the full complexes)")
      .kv()
      .max_depth()
      .output("OUT", point_data_outputs(),
              "write the mesh (labels kept) with the point arrays ascending_cell (the vertex of\n"
              "its minimum) and critical_type, and the cell array descending_cell (the vertex of\n"
              "its maximum, -1 for a path out of the boundary)")
      .output("ARCS", ".vtp",
              "write the Morse-Smale arcs (saddle to extremum gradient paths) as polylines, with\n"
              "the cell arrays saddle_dimension, saddle, saddle_vertex, extremum, saddle_value",
              false, "--arcs")
      .output("PAIRS.csv", ".csv",
              "write the persistence pairs: type,extremum,saddle,extremum_value,saddle_value,\n"
              "birth,death,persistence (essential pairs: no saddle, inf)",
              false, "--csv")
      .json_keys("keys: vertices, tetrahedra, kv, kv_automatic, field, field_min, field_max, persistence,\n"
                 "threshold, critical_points (minima, saddles_1, saddles_2, maxima, degenerate,\n"
                 "regular), gradient (as in critical --gradient), ascending_cells, descending_cells,\n"
                 "outflow_tetrahedra, minimum_saddle_pairs, saddle_maximum_pairs and their _kept\n"
                 "counts, pairs (objects: type, extremum, saddle, extremum_value, saddle_value,\n"
                 "persistence; null for an essential pair), arcs, seconds, output, arcs_file, csv")
      .run(run_morse);
}

} // namespace prstar
