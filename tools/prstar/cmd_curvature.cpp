// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar curvature: discrete distortion of a scalar field at every vertex (paper Section 8).

#include "commands.h"
#include "octree_mesh_view.h"
#include "vertex_code.h"

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/distortion.h>
#include <CGAL/PR_star_octree/parameters.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>

namespace prstar {

// The summary of the curvature command (one process or distributed): JSON or a table.
void report_curvature(const Options& o, std::size_t nv, std::size_t nt, const std::string& field_name,
                      const std::size_t counts[4], const Distortion_summary& summary, double seconds) {
  const std::string& input = o.input();
  const std::size_t kv = o.kv();
  const std::string out = o.output(), csv = o.output("--csv");
  if (o.json()) {
    Json j;
    j.begin_object().field("vertices", nv).field("tetrahedra", nt).key("kv");
    json_kv(j, kv)
        .field("field", field_name)
        .field("interior_vertices", counts[0])
        .field("boundary_vertices", counts[1])
        .field("nonmanifold_vertices", counts[2])
        .field("unreferenced_vertices", counts[3]);
    if (summary.count)
      j.field("distortion_min", summary.min)
          .field("distortion_max", summary.max)
          .field("distortion_mean", summary.mean());
    j.field("seconds", seconds);
    if (!out.empty()) j.field("output", out);
    if (!csv.empty()) j.field("csv", csv);
    j.end_object();
    std::cout << j.str() << '\n';
    return;
  }
  std::cout << input << ": distortion of '" << field_name << "' (k_v = " << bucket_size_string(kv) << ", "
            << fixed(seconds, 3) << " s)\n";
  Table t({"vertices", "count", "distortion min", "max", "mean"});
  t.add({"all manifold", std::to_string(summary.count), summary.count ? fixed(summary.min, 6) : "-",
         summary.count ? fixed(summary.max, 6) : "-", summary.count ? fixed(summary.mean(), 6) : "-"});
  t.add({"interior", std::to_string(counts[0]), "", "", ""});
  t.add({"boundary", std::to_string(counts[1]), "", "", ""});
  t.add({"non-manifold (NaN)", std::to_string(counts[2]), "", "", ""});
  std::cout << t.str();
  if (!out.empty()) std::cout << "wrote " << out << '\n';
  if (!csv.empty()) std::cout << "wrote " << csv << '\n';
}

namespace {

using Octree = CGAL::PR_star_octree_3<>;
namespace params = CGAL::PR_star_octree::parameters;

// What the command keeps of each vertex's `Vertex_curvature` (40 bytes): the vertex code (1 byte),
// the distortion and, for an output, the domain curvature; in the user's numbering.
struct Curvature_arrays {
  std::vector<std::uint8_t> code;
  std::vector<double> distortion, domain;
  Curvature_arrays(std::size_t nv, bool with_domain)
      : code(nv, 3), distortion(nv, 0), domain(with_domain ? nv : 0) {}

  struct Map { // a WritablePropertyMap; each vertex written once, by one thread
    using key_type = std::size_t;
    using value_type = CGAL::PR_star_octree::Vertex_curvature;
    using reference = value_type;
    using category = boost::writable_property_map_tag;
    Curvature_arrays* a;
    friend void put(const Map& m, std::size_t v, const value_type& c) {
      m.a->code[v] = static_cast<std::uint8_t>(vertex_type_code(c.type));
      m.a->distortion[v] = c.distortion;
      if (!m.a->domain.empty()) m.a->domain[v] = c.domain_curvature;
    }
  };
  Map map() { return Map{this}; }
};

int run_curvature(const Options& o) {
  const std::string& input = o.input();
  const std::size_t kv = o.kv();
  const std::string out = o.output(), csv = o.output("--csv");
  Progress_bar progress(o.show_progress());
  Mesh mesh = read_mesh(input, progress);

  // The octree takes the mesh over (no second copy of V and T).  The field: a coordinate, or a
  // point-data array.  Without a file to write (lean), that array alone goes into the octree as
  // its scalar field and no permutation is kept.  With one, the mesh's arrays are kept aside in the
  // user's order (the field read from there), and the octree keeps the vertex permutation (the
  // files are in the user's vertex order) and, only when the mesh has cell data, the tetrahedron
  // permutation (those arrays follow the octree's order of the tetrahedra, the one written).
  std::string field_name = o.get("--field");
  const bool lean = out.empty() && csv.empty();
  const int axis = (field_name == "x" || field_name == "y" || field_name == "z") ? field_name[0] - 'x' : -1;
  Mesh_arrays arrays;
  if (!lean) arrays = Mesh_arrays(mesh);
  auto& pd = lean ? mesh.point_data : arrays.point_data;
  const CGAL::PR_star_octree::Point_data_array* field = nullptr; // not lean: in the user's order
  if (axis < 0) {
    auto it = field_name.empty()
                  ? pd.begin()
                  : std::find_if(pd.begin(), pd.end(), [&](const auto& a) { return a.name == field_name; });
    if (it == pd.end()) {
      std::string known;
      for (const auto& d : pd) known += (known.empty() ? "" : ", ") + d.name;
      throw std::runtime_error(input + ": " +
                               (field_name.empty() ? std::string("the mesh has no point data")
                                                   : "no point-data array named '" + field_name + "'") +
                               (known.empty() ? "" : " (it has: " + known + ")") +
                               "; use --field x|y|z for a coordinate");
    }
    field_name = it->name;
    for (std::size_t v = 0; v < it->values.size(); ++v)
      if (!std::isfinite(it->values[v]))
        throw std::runtime_error(input + ": field '" + field_name + "' is not finite at vertex " +
                                 std::to_string(v));
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
  const auto np = params::bucket_size(kv).maximum_depth(o.max_depth());
  const Octree tree(std::move(mesh), np.vertex_permutation(!lean).tetrahedron_permutation(
                                         !out.empty() && !arrays.cell_data.empty()));
  const std::size_t nv = tree.number_of_vertices(), nt = tree.number_of_tetrahedra();
  progress.phase("computing the distortion");
  Curvature_arrays curv(nv, !out.empty()); // the user's numbering
  if (field)
    CGAL::PR_star_octree::compute_curvature(tree, CGAL::make_property_map(field->values), curv.map(),
                                            params::progress(progress.callback()));
  else if (axis < 0)
    CGAL::PR_star_octree::compute_curvature(tree, CGAL::PR_star_octree::scalar_field_map(tree), curv.map(),
                                            params::progress(progress.callback()));
  else
    CGAL::PR_star_octree::compute_curvature(tree, CGAL::PR_star_octree::coordinate_field_map(tree, axis),
                                            curv.map(), params::progress(progress.callback()));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.finish();

  // The summary: the distortions are added exactly (the same mean in any order, as a distributed
  // run finds it).
  std::size_t counts[4] = {0, 0, 0, 0};
  Distortion_summary summary;
  for (std::size_t v = 0; v < nv; ++v) {
    ++counts[curv.code[v]];
    if (curv.code[v] <= 1) summary.add(curv.distortion[v]); // interior or boundary
  }
  if (!lean) {
    // the mesh of the octree in the user's vertex order (its points for the CSV), with its arrays
    Octree_mesh_view<Octree> view(tree, std::move(arrays));
    if (!csv.empty()) {
      progress.phase("writing " + csv);
      write_through_temporary(csv, [&](const std::string& tmp) {
        std::ofstream f(tmp);
        f << std::setprecision(std::numeric_limits<double>::max_digits10);
        f << "vertex,x,y,z,boundary,distortion\n";
        for (std::size_t v = 0; v < nv; ++v) {
          const auto p = view.points[v];
          f << v << ',' << p.x() << ',' << p.y() << ',' << p.z() << ',' << static_cast<int>(curv.code[v])
            << ',' << curv.distortion[v] << '\n';
        }
        f.flush();
        if (!f) throw std::runtime_error(csv + ": cannot write the output file");
      });
      progress.finish();
    }
    if (!out.empty()) {
      progress.phase("writing " + out);
      // VTU point data must be finite (our reader refuses NaN, and so do some of ParaView's): the
      // undefined values of non-manifold vertices are written as 0 there, flagged by boundary = 2.
      std::vector<CGAL::PR_star_octree::Point_data_array> result(3);
      result[0] = {"boundary", std::vector<double>(curv.code.begin(), curv.code.end())};
      result[1] = {"distortion", std::move(curv.distortion)};
      result[2] = {"domain_curvature", std::move(curv.domain)};
      for (auto& a : result)
        for (double& x : a.values)
          if (!std::isfinite(x)) x = 0;
      write_octree_mesh(out, view, result);
      progress.finish();
    }
  }
  report_curvature(o, nv, nt, field_name, counts, summary, seconds);
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
Non-manifold vertices get NaN.)")
      .option("--field", "NAME|x|y|z",
              "a point-data array of MESH (default: its first one), or x, y, z for a coordinate")
      .kv()
      .max_depth()
      .output("OUT", point_data_outputs(),
              "write the mesh (labels kept) with point arrays `boundary`, `distortion`,\n"
              "`domain_curvature` (non-manifold vertices: boundary = 2 and 0 for the undefined\n"
              "values): .vtu/.vtk for ParaView, or .node/.ele (TetGen attributes)")
      .output("OUT.csv", ".csv",
              "write one row per input vertex, in the input order: vertex,x,y,z,boundary,distortion\n"
              "(boundary: 0 interior, 1 boundary, 2 non-manifold, 3 in no tetrahedron;\n"
              "distortion: nan for non-manifold vertices)",
              false, "--csv")
      .json_keys("keys: vertices, tetrahedra, kv, field, interior_vertices, boundary_vertices,\n"
                 "nonmanifold_vertices, unreferenced_vertices, distortion_min, distortion_max,\n"
                 "distortion_mean (over manifold vertices, when there are some), seconds, output, csv")
      .run(run_curvature);
}

} // namespace prstar
