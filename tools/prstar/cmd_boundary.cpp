// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar boundary: boundary and non-manifold vertices, boundary triangles and tetrahedra (paper
// Section 7).

#include "commands.h"
#include "octree_mesh_view.h"
#include <CGAL/PR_star_octree/boundary.h>

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/IO/surface.h>
#include <CGAL/PR_star_octree/IO/vtu_source.h>
#include <CGAL/PR_star_octree/parameters.h>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <iterator>
#include <optional>
#include <iostream>

namespace prstar {

// The summary of the boundary command (one process or distributed): JSON or a table.
void report_boundary(const Options& o, std::size_t nv, std::size_t nt,
                     const CGAL::PR_star_octree::Boundary_counts& b, double seconds, long long interfaces,
                     bool compact, bool streamed) {
  const std::string& input = o.input();
  const std::string out = o.output(), surface = o.output("--surface");
  if (o.json()) {
    Json j;
    j.begin_object().field("vertices", nv).field("tetrahedra", nt).key("kv");
    json_kv(j, o)
        .field("boundary_vertices", b.boundary_vertices)
        .field("interior_vertices", b.interior_vertices)
        .field("nonmanifold_vertices", b.nonmanifold_vertices)
        .field("unreferenced_vertices", b.unreferenced_vertices)
        .field("boundary_triangles", b.boundary_triangles)
        .field("boundary_tetrahedra", b.boundary_tetrahedra)
        .field("boundary_face_tetrahedra", b.boundary_face_tetrahedra)
        .field("compact_tetrahedra", compact)
        .field("streamed", streamed)
        .field("seconds", seconds);
    if (interfaces >= 0) j.field("interface_triangles", interfaces);
    if (!out.empty()) j.field("output", out);
    if (!surface.empty()) j.field("surface", surface);
    j.end_object();
    std::cout << j.str() << '\n';
    return;
  }
  Table t({"", "count"});
  t.add({"vertices", std::to_string(nv)});
  t.add({"  interior", std::to_string(b.interior_vertices)});
  t.add({"  boundary", std::to_string(b.boundary_vertices)});
  t.add({"  non-manifold", std::to_string(b.nonmanifold_vertices)});
  t.add({"  in no tetrahedron", std::to_string(b.unreferenced_vertices)});
  t.add({"boundary triangles", std::to_string(b.boundary_triangles)});
  if (interfaces >= 0) t.add({"triangles between two labels", std::to_string(interfaces)});
  t.add({"tetrahedra touching the boundary", std::to_string(b.boundary_tetrahedra)});
  t.add({"  with a boundary face", std::to_string(b.boundary_face_tetrahedra)});
  std::cout << input << " (k_v = " << o.kv_label()
            << (streamed  ? ", compact tetrahedra, read in passes"
                : compact ? ", compact tetrahedra"
                          : "")
            << ", " << fixed(seconds, 3) << " s)\n"
            << t.str();
  if (b.nonmanifold_vertices)
    std::cout << "warning: " << b.nonmanifold_vertices
              << " vertices have a link that is neither a sphere nor a disc (non-manifold)\n";
  if (!out.empty()) std::cout << "wrote " << out << '\n';
  if (!surface.empty()) std::cout << "wrote " << surface << '\n';
}

namespace {

// ".off,.stl,..." for Command::output, from the surface format table
std::string surface_output_extensions() {
  std::string r;
  for (const auto& f : CGAL::PR_star_octree::IO::surface_formats)
    r += (r.empty() ? "." : ",.") + std::string(f.extension);
  return r;
}

using Octree = CGAL::PR_star_octree_3<>;
using CGAL::PR_star_octree::Vertex_type;
namespace params = CGAL::PR_star_octree::parameters;

// Writes the code of each vertex type (`vertex_type_code()`) into `codes[v]`, v in the user's
// numbering; a null `codes` writes nothing (only the counts are wanted).
struct Vertex_code_map {
  using key_type = std::size_t;
  using value_type = Vertex_type;
  using reference = value_type;
  using category = boost::writable_property_map_tag;
  double* codes;
  friend void put(const Vertex_code_map& m, std::size_t v, Vertex_type t) {
    if (m.codes) m.codes[v] = vertex_type_code(t);
  }
};

namespace PIO = CGAL::PR_star_octree::IO;

// The surface of the mesh (boundary and interfaces between labels) with its data: the surface's
// vertices in the user's order, with their index in the input (`vertex`) and kind
// (`boundary_type`), the input's point data, the label pair of each triangle and the label names.
CGAL::PR_star_octree::Triangle_surface<Octree::Point_3>
make_surface(const Octree& tree, const std::vector<CGAL::PR_star_octree::Surface_triangle>& triangles,
             const std::vector<double>& codes, const Mesh_arrays& arrays) {
  constexpr std::uint32_t none = 0xffffffffu;
  const std::size_t nv = tree.number_of_vertices();
  std::vector<std::uint32_t> index(nv, none);
  std::vector<char> on_interface(nv, 0);
  for (const auto& t : triangles)
    for (std::size_t v : t.vertices) {
      index[v] = 0;
      on_interface[v] = on_interface[v] || t.interface;
    }
  CGAL::PR_star_octree::Triangle_surface<Octree::Point_3> s;
  CGAL::PR_star_octree::Int_array vertex{"vertex", {}}, kind{"boundary_type", {}};
  const std::vector<Octree::Index> from_original = tree.vertex_from_original();
  for (std::size_t v = 0; v < nv; ++v) {
    if (index[v] == none) continue;
    index[v] = static_cast<std::uint32_t>(s.points.size());
    s.points.push_back(tree.point(from_original[v]));
    vertex.values.push_back(static_cast<int>(v));
    // 0 interior (never on the surface), 1 boundary, 2 interior on an interface, 3 non-manifold
    kind.values.push_back(codes[v] == 2 ? 3 : codes[v] == 1 ? 1 : on_interface[v] ? 2 : 0);
  }
  for (const auto& a : arrays.point_data) {
    CGAL::PR_star_octree::Data_array b{a.name, {}};
    b.values.reserve(s.points.size());
    for (std::size_t v = 0; v < nv; ++v)
      if (index[v] != none) b.values.push_back(a.values[v]);
    s.point_data.push_back(std::move(b));
  }
  CGAL::PR_star_octree::Int_array inside{"label_inside", {}}, outside{"label_outside", {}}, interface {
    "interface", {}
  };
  for (const auto& t : triangles) {
    s.triangles.push_back({{index[t.vertices[0]], index[t.vertices[1]], index[t.vertices[2]]}});
    inside.values.push_back(t.inside);
    outside.values.push_back(t.interface ? t.outside : -1);
    interface.values.push_back(t.interface ? 1 : 0);
  }
  s.point_int_data = {std::move(vertex), std::move(kind)};
  s.cell_int_data = {std::move(inside), std::move(outside), std::move(interface)};
  s.label_names = arrays.label_names;
  return s;
}

int run_boundary(const Options& o) {
  const std::string& input = o.input();
  const std::size_t kv = o.kv();
  const std::string out = o.output(), surface_out = o.output("--surface");
  Progress_bar progress(o.show_progress());
  const bool writes = !out.empty() || !surface_out.empty();
  // A .vtu readable by ranges, nothing written, with --compact or by default from 2^25 cells: the
  // streaming construction, which never holds the plain tetrahedron array (the tetrahedra are read
  // from the file several times).  By default, a header the ranges cannot read leaves the file to
  // the whole-file reader (and its messages).
  std::optional<PIO::Vtu_tetrahedron_source> streaming;
  if (!writes) streaming = streaming_source(o, input);
  if (streaming) progress.phase("reading the vertices of " + input);
  Mesh mesh = streaming ? streaming->read_vertices() : read_mesh(input, progress);
  // The octree takes the mesh over (no second copy of V and T).  Without an output to write it keeps
  // no permutation (only counts are reported); with one, the vertex permutation (4 bytes a vertex)
  // gives the output the user's vertex order, and the tetrahedron permutation, only when the mesh
  // has cell data, puts those arrays in the octree's order of the tetrahedra (the one written).
  Mesh_arrays arrays(mesh);            // point and cell data, label names: kept aside in the user's order,
  if (!writes) arrays = Mesh_arrays(); // or dropped when not written
  const auto start = std::chrono::steady_clock::now();
  progress.phase("building the PR-star octree (k_v = " + bucket_size_string(kv) + ")");
  const auto np = params::bucket_size(kv)
                      .maximum_depth(o.max_depth())
                      .compact_tetrahedra(o.compact())
                      .coordinate_precision(o.coordinate_precision());
  const Octree tree = streaming
                          ? Octree(std::move(mesh), *streaming, np.vertex_permutation(false))
                          : Octree(std::move(mesh), np.vertex_permutation(writes).tetrahedron_permutation(
                                                        !out.empty() && !arrays.cell_data.empty()));
  o.set_used_kv(tree);
  const std::size_t nv = tree.number_of_vertices(), nt = tree.number_of_tetrahedra();
  progress.phase("classifying the vertices");
  // the output's array, in the user's numbering (3: in no tetrahedron), written directly
  std::vector<CGAL::PR_star_octree::Point_data_array> result;
  if (writes) result.push_back({"boundary", std::vector<double>(nv, 3.)});
  CGAL::PR_star_octree::Boundary_counts b = CGAL::PR_star_octree::compute_boundary(
      tree, Vertex_code_map{result.empty() ? nullptr : result[0].values.data()},
      params::progress(progress.callback()));
  std::vector<CGAL::PR_star_octree::Surface_triangle> triangles;
  if (!surface_out.empty()) {
    progress.phase("gathering the boundary and interface triangles");
    CGAL::PR_star_octree::boundary_surface(tree, std::back_inserter(triangles),
                                           params::progress(progress.callback()));
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.finish();
  if (!surface_out.empty()) {
    progress.phase("writing " + surface_out);
    const auto surface = make_surface(tree, triangles, result[0].values, arrays);
    write_through_temporary(surface_out, [&](const std::string& tmp) { PIO::write_surface(tmp, surface); });
    progress.finish();
  }
  const std::size_t interfaces = static_cast<std::size_t>(
      std::count_if(triangles.begin(), triangles.end(), [](const auto& t) { return t.interface; }));
  if (!out.empty()) {
    progress.phase("writing " + out);
    Octree_mesh_view<Octree> view(tree, std::move(arrays));
    write_octree_mesh(out, view, result);
    progress.finish();
  }
  report_boundary(o, nv, nt, b, seconds, surface_out.empty() ? -1 : static_cast<long long>(interfaces),
                  tree.is_compact(), streaming.has_value());
  return exit_success;
}

} // namespace

Command boundary_command() {
  return Command("boundary",
                 "boundary and non-manifold vertices, boundary triangles and tetrahedra (paper Section 7)")
      .input()
      .description(
          R"(Classifies every vertex of MESH as interior, boundary or non-manifold, leaf by leaf (paper
Section 7: 2|e| != 3|t| in the vertex link, plus a check that the link is a sphere or a disc).
With neither OUT nor SURF, a .vtu whose arrays are appended raw (as prstar generate writes them)
and that has 2^25 cells or more (any size with --compact; never with --no-compact) is read in
passes, the tetrahedra a slab at a time, into the compact array: the plain tetrahedron array
(16 bytes each) is never held whole.  The 105M-tetrahedra lattice then peaks at about 1.5 GB
instead of 2.6, in the same time.)")
      .kv()
      .max_depth()
      .output("OUT", point_data_outputs(),
              "write the mesh (labels kept) with the point array `boundary` (0 interior,\n"
              "1 boundary, 2 non-manifold, 3 in no tetrahedron): .vtu/.vtk for ParaView, or\n"
              ".node/.ele (TetGen attribute)")
      .output("SURF", surface_output_extensions(),
              "write the boundary surface, outward oriented, with the triangles between two\n"
              "labels (cell arrays label_inside, label_outside (-1 on the boundary), interface),\n"
              "the point arrays vertex (index in MESH), boundary_type (1 boundary, 2 on an\n"
              "interface, 3 non-manifold) and MESH's point data, and the label names",
              false, "--surface")
      .json_keys("keys: vertices, tetrahedra, kv, kv_automatic, boundary_vertices, interior_vertices,\n"
                 "nonmanifold_vertices, unreferenced_vertices, boundary_triangles, boundary_tetrahedra\n"
                 "(tetrahedra with a boundary or non-manifold vertex), boundary_face_tetrahedra (with a\n"
                 "face on the boundary), compact_tetrahedra, streamed (read in passes), interface_triangles\n"
                 "(with --surface), seconds, output, surface")
      .run(run_boundary);
}

} // namespace prstar
