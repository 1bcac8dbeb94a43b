// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar curvature: discrete distortion of a scalar field at every vertex (paper Section 8).

#include "commands.h"
#include "octree_mesh_view.h"
#include <CGAL/PR_star_octree/boundary.h>

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/distortion.h>
#include <CGAL/PR_star_octree/parameters.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>

namespace prstar {

namespace {

// The min, max and mean of a summary, as JSON fields `<prefix>_min`... (none when it is empty).
void json_summary(Json& j, const std::string& prefix, const Value_summary& s) {
  if (s.count == 0) return;
  j.field(prefix + "_min", s.min).field(prefix + "_max", s.max).field(prefix + "_mean", s.mean());
}

// Three table cells: min, max, mean ("-" when empty).
void table_cells(std::vector<std::string>& row, const Value_summary& s) {
  for (double x : {s.min, s.max, s.mean()}) row.push_back(s.count ? short_number(x) : "-");
}

} // namespace

// The summary of the curvature command (one process or distributed): JSON or a table.
void report_curvature(const Options& o, std::size_t nv, std::size_t nt, const std::string& field_name,
                      const Curvature_summary& summary, double seconds, bool compact, bool streamed) {
  const std::string& input = o.input();
  const std::string out = o.output(), csv = o.output("--csv");
  Value_summary distortion = summary.distortion[0], domain = summary.domain[0];
  distortion.add(summary.distortion[1]);
  domain.add(summary.domain[1]);
  if (o.json()) {
    Json j;
    j.begin_object().field("vertices", nv).field("tetrahedra", nt).key("kv");
    json_kv(j, o)
        .field("field", field_name)
        .field("interior_vertices", summary.counts[0])
        .field("boundary_vertices", summary.counts[1])
        .field("nonmanifold_vertices", summary.counts[2])
        .field("unreferenced_vertices", summary.counts[3]);
    json_summary(j, "distortion", distortion);
    json_summary(j, "domain_curvature", domain);
    const char* names[2] = {"interior", "boundary"};
    for (int k = 0; k < 2; ++k) {
      j.key(names[k]).begin_object().field("vertices", summary.counts[k]);
      json_summary(j, "distortion", summary.distortion[k]);
      json_summary(j, "domain_curvature", summary.domain[k]);
      j.end_object();
    }
    j.field("compact_tetrahedra", compact).field("streamed", streamed).field("seconds", seconds);
    if (!out.empty()) j.field("output", out);
    if (!csv.empty()) j.field("csv", csv);
    j.end_object();
    std::cout << j.str() << '\n';
    return;
  }
  std::cout << input << ": distortion of '" << field_name
            << "' and curvature of the domain (k_v = " << o.kv_label()
            << (streamed  ? ", compact tetrahedra, read in passes"
                : compact ? ", compact tetrahedra"
                          : "")
            << ", " << fixed(seconds, 3) << " s)\n";
  Table t({"vertices", "count", "distortion min", "max", "mean", "domain curvature min", "max", "mean"});
  auto row = [&](const std::string& name, std::uint64_t count, const Value_summary& d,
                 const Value_summary& c) {
    std::vector<std::string> r{name, std::to_string(count)};
    table_cells(r, d);
    table_cells(r, c);
    t.add(r);
  };
  row("all manifold", distortion.count, distortion, domain);
  row("interior", summary.counts[0], summary.distortion[0], summary.domain[0]);
  row("boundary", summary.counts[1], summary.distortion[1], summary.domain[1]);
  t.add({"non-manifold (undefined)", std::to_string(summary.counts[2]), "-", "-", "-", "-", "-", "-"});
  if (summary.counts[3] != 0)
    t.add({"in no tetrahedron", std::to_string(summary.counts[3]), "-", "-", "-", "-", "-", "-"});
  std::cout << t.str();
  if (!out.empty()) std::cout << "wrote " << out << '\n';
  if (!csv.empty()) std::cout << "wrote " << csv << '\n';
}

void write_curvature_csv(const std::string& csv, std::size_t n,
                         const std::function<Curvature_row(std::size_t)>& row) {
  write_text_file(csv, [&](std::ostream& f) {
    f << "vertex,x,y,z,boundary,distortion,domain_curvature\n";
    std::string line;
    for (std::size_t v = 0; v < n; ++v) {
      const Curvature_row r = row(v);
      const bool defined = r.code <= 1; // nan for non-manifold and unreferenced vertices
      line = std::to_string(v) + ',' + number(r.x) + ',' + number(r.y) + ',' + number(r.z) + ',' +
             std::to_string(r.code) + ',' + (defined ? number(r.distortion) : "nan") + ',' +
             (defined ? number(r.domain) : "nan") + '\n';
      f << line;
    }
  });
}

namespace {

using Octree = CGAL::PR_star_octree_3<>;
namespace params = CGAL::PR_star_octree::parameters;

// What the command keeps of each vertex's `Vertex_curvature` (40 bytes): the vertex code (1 byte),
// the distortion and the domain curvature; in the user's numbering.
struct Curvature_arrays {
  std::vector<std::uint8_t> code;
  std::vector<double> distortion, domain;
  explicit Curvature_arrays(std::size_t nv) : code(nv, 3), distortion(nv, 0), domain(nv, 0) {}

  struct Map { // a WritablePropertyMap; each vertex written once, by one thread
    using key_type = std::size_t;
    using value_type = CGAL::PR_star_octree::Vertex_curvature;
    using reference = value_type;
    using category = boost::writable_property_map_tag;
    Curvature_arrays* a;
    friend void put(const Map& m, std::size_t v, const value_type& c) {
      m.a->code[v] = static_cast<std::uint8_t>(vertex_type_code(c.type));
      m.a->distortion[v] = c.distortion;
      m.a->domain[v] = c.domain_curvature;
    }
  };
  Map map() { return Map{this}; }
};

// Without a file to write, only the summary is kept: each vertex's curvature is added to it as it
// comes (the sums are exact, so the order does not matter), with no array per vertex.
struct Summary_map { // a WritablePropertyMap; never written by two threads at once
  using key_type = std::size_t;
  using value_type = CGAL::PR_star_octree::Vertex_curvature;
  using reference = value_type;
  using category = boost::writable_property_map_tag;
  Curvature_summary* s;
  friend void put(const Summary_map& m, std::size_t, const value_type& c) {
    m.s->add(vertex_type_code(c.type), c.distortion, c.domain_curvature);
  }
};

int run_curvature(const Options& o) {
  const std::string& input = o.input();
  const std::size_t kv = o.kv();
  const std::string out = o.output(), csv = o.output("--csv");
  Progress_bar progress(o.show_progress());
  const bool lean = out.empty() && csv.empty();
  // Without a file to write, a .vtu may be read in passes (`streaming_source()`: --compact, or by
  // default from 2^25 cells), as boundary does: the vertices and the field first, then the
  // tetrahedra straight into the compact array.
  std::optional<CGAL::PR_star_octree::IO::Vtu_tetrahedron_source> streaming;
  if (lean) streaming = streaming_source(o, input);
  if (streaming) progress.phase("reading the vertices of " + input);
  Mesh mesh = streaming ? streaming->read_vertices() : read_mesh(input, progress);

  // The octree takes the mesh over (no second copy of V and T).  The field: a coordinate, or a
  // point-data array.  Without a file to write (lean), that array alone goes into the octree as
  // its scalar field and no permutation is kept.  With one, the mesh's arrays are kept aside in the
  // user's order (the field read from there), and the octree keeps the vertex permutation (the
  // files are in the user's vertex order) and, only when the mesh has cell data, the tetrahedron
  // permutation (those arrays follow the octree's order of the tetrahedra, the one written).
  std::string field_name = o.get("--field");
  const int axis = (field_name == "x" || field_name == "y" || field_name == "z") ? field_name[0] - 'x' : -1;
  Mesh_arrays arrays;
  if (!lean) arrays = Mesh_arrays(mesh);
  auto& pd = lean ? mesh.point_data : arrays.point_data;
  const CGAL::PR_star_octree::Point_data_array* field = nullptr; // not lean: in the user's order
  if (axis < 0) {
    const auto it = pd.begin() + static_cast<std::ptrdiff_t>(find_point_field(pd, field_name, input));
    if (lean) { // the field alone, first: the octree's scalar field
      std::rotate(pd.begin(), it, it + 1);
      pd.resize(1);
    } else {
      field = &*it;
    }
  }
  if (lean) {
    if (axis >= 0) mesh.point_data.clear();
    mesh.cell_data.clear();
  }

  const auto start = std::chrono::steady_clock::now();
  progress.phase("building the PR-star octree (k_v = " + bucket_size_string(kv) + ")");
  // (the curvature builds the links and the leaf's tetrahedra in local ids)
  const auto np = params::bucket_size(kv)
                      .bucket_size_relations(CGAL::PR_star_octree::compute_curvature_relations)
                      .maximum_depth(o.max_depth())
                      .compact_tetrahedra(o.compact())
                      .coordinate_precision(o.coordinate_precision());
  const Octree tree = streaming
                          ? Octree(std::move(mesh), *streaming, np.vertex_permutation(false))
                          : Octree(std::move(mesh), np.vertex_permutation(!lean).tetrahedron_permutation(
                                                        !out.empty() && !arrays.cell_data.empty()));
  o.set_used_kv(tree);
  const std::size_t nv = tree.number_of_vertices(), nt = tree.number_of_tetrahedra();
  progress.phase("computing the distortion");
  Curvature_summary summary;
  std::optional<Curvature_arrays> curv; // the user's numbering, for the files
  if (!lean) curv.emplace(nv);
  const auto compute = [&](auto map) {
    if (field)
      CGAL::PR_star_octree::compute_curvature(tree, CGAL::make_property_map(field->values), map,
                                              params::progress(progress.callback()));
    else if (axis < 0)
      CGAL::PR_star_octree::compute_curvature(tree, CGAL::PR_star_octree::scalar_field_map(tree), map,
                                              params::progress(progress.callback()));
    else
      CGAL::PR_star_octree::compute_curvature(tree, CGAL::PR_star_octree::coordinate_field_map(tree, axis),
                                              map, params::progress(progress.callback()));
  };
  if (lean)
    compute(Summary_map{&summary});
  else
    compute(curv->map());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.finish();

  // The summary: the values are added exactly (the same mean in any order, as a distributed run
  // finds it).
  if (!lean)
    for (std::size_t v = 0; v < nv; ++v) summary.add(curv->code[v], curv->distortion[v], curv->domain[v]);
  if (!lean) {
    // the mesh of the octree in the user's vertex order (its points for the CSV), with its arrays
    if (out.empty()) arrays.cell_data.clear(); // the CSV alone: no cell data (nor their permutation)
    Octree_mesh_view<Octree> view(tree, std::move(arrays));
    if (!csv.empty()) {
      progress.phase("writing " + csv);
      write_curvature_csv(csv, nv, [&](std::size_t v) {
        const auto p = view.points[v];
        return Curvature_row{p.x(), p.y(), p.z(), curv->code[v], curv->distortion[v], curv->domain[v]};
      });
      progress.finish();
    }
    if (!out.empty()) {
      progress.phase("writing " + out);
      // VTU point data must be finite (our reader refuses NaN, and so do some of ParaView's): the
      // undefined values of non-manifold vertices are written as 0 there, flagged by boundary = 2.
      std::vector<CGAL::PR_star_octree::Point_data_array> result(3);
      result[0] = {"boundary", std::vector<double>(curv->code.begin(), curv->code.end())};
      result[1] = {"distortion", std::move(curv->distortion)};
      result[2] = {"domain_curvature", std::move(curv->domain)};
      for (auto& a : result)
        for (double& x : a.values)
          if (!std::isfinite(x)) x = 0;
      write_octree_mesh(out, view, result);
      progress.finish();
    }
  }
  report_curvature(o, nv, nt, field_name, summary, seconds, tree.is_compact(), streaming.has_value());
  return exit_success;
}

} // namespace

Command curvature_command() {
  return Command("curvature", "discrete distortion of a scalar field at every vertex (paper Section 8)")
      .input()
      .description(
          R"(Discrete distortion of a scalar field at every vertex (paper Section 8): the field lifts the mesh
into R^4; the distortion at v is (4 pi, or the sum of the 3D solid angles on the boundary) minus
the sum of the solid angles at v of the lifted tetrahedra of its star.  Also computes the 3D
concentrated curvature of the domain ((4 pi or 2 pi) minus the sum of the 3D solid angles).
Non-manifold vertices get NaN.  With neither OUT nor OUT.csv, a .vtu whose arrays are appended raw
(as prstar generate writes them) and that has 2^25 cells or more (any size with --compact; never
with --no-compact) is read in passes, as boundary reads it: the plain tetrahedron array is never
held whole.)")
      .option("--field", "NAME|x|y|z",
              "a point-data array of MESH (default: its first one), or x, y, z for a coordinate")
      .kv()
      .max_depth()
      .output("OUT", point_data_outputs(),
              "write the mesh (labels kept) with point arrays `boundary`, `distortion`,\n"
              "`domain_curvature` (non-manifold vertices: boundary = 2 and 0 for the undefined\n"
              "values): .vtu/.vtk for ParaView, or .node/.ele (TetGen attributes)")
      .output("OUT.csv", ".csv",
              "write one row per input vertex, in the input order:\n"
              "vertex,x,y,z,boundary,distortion,domain_curvature (boundary: 0 interior,\n"
              "1 boundary, 2 non-manifold, 3 in no tetrahedron; nan where undefined)",
              false, "--csv")
      .json_keys(
          "keys: vertices, tetrahedra, kv, kv_automatic, field, interior_vertices, boundary_vertices,\n"
          "nonmanifold_vertices, unreferenced_vertices, distortion_min/max/mean and\n"
          "domain_curvature_min/max/mean (over manifold vertices, when there are some),\n"
          "interior and boundary (objects: vertices and the same six keys), compact_tetrahedra,\n"
          "streamed (read in passes), seconds, output, csv")
      .run(run_curvature);
}

} // namespace prstar
