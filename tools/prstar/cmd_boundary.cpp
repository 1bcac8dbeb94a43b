// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar boundary: boundary and non-manifold vertices, boundary triangles and tetrahedra (paper
// Section 7).

#include "commands.h"
#include "vertex_code.h"

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/parameters.h>
#include <CGAL/property_map.h>

#include <chrono>
#include <iostream>

namespace prstar {

namespace {

using Octree = CGAL::PR_star_octree_3<>;
using CGAL::PR_star_octree::Vertex_type;
namespace params = CGAL::PR_star_octree::parameters;

int run_boundary(const Options& o) {
  const std::string& input = o.input();
  const std::size_t kv = o.kv();
  const std::string out = o.output();
  Progress_bar progress(o.show_progress());
  Mesh mesh = read_mesh(input, progress); // written back with the computed point arrays
  const auto start = std::chrono::steady_clock::now();
  progress.phase("building the PR-star octree (k_v = " + bucket_size_string(kv) + ")");
  // Without an output to write, the octree takes the mesh over (no second copy of V and T) and
  // keeps no permutation (only counts are reported).
  const auto np = params::bucket_size(kv).maximum_depth(o.max_depth()).tetrahedron_permutation(false);
  const Octree tree = out.empty() ? Octree(std::move(mesh), np.vertex_permutation(false))
                                  : Octree(CGAL::PR_star_octree::make_input(mesh), np);
  const std::size_t nv = tree.number_of_vertices(), nt = tree.number_of_tetrahedra();
  progress.phase("classifying the vertices");
  std::vector<Vertex_type> types(nv, Vertex_type::UNREFERENCED); // the user's numbering
  const CGAL::PR_star_octree::Boundary_counts b = CGAL::PR_star_octree::compute_boundary(
      tree, CGAL::make_property_map(types), params::progress(progress.callback()));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.finish();
  if (!out.empty()) {
    progress.phase("writing " + out);
    CGAL::PR_star_octree::Point_data_array a{"boundary", std::vector<double>(nv)};
    for (std::size_t v = 0; v < types.size(); ++v) a.values[v] = vertex_type_code(types[v]);
    write_mesh_with_point_data(out, mesh, {a});
    progress.finish();
  }
  if (o.json()) {
    Json j;
    j.begin_object().field("vertices", nv).field("tetrahedra", nt).key("kv");
    json_kv(j, kv)
        .field("boundary_vertices", b.boundary_vertices)
        .field("interior_vertices", b.interior_vertices)
        .field("nonmanifold_vertices", b.nonmanifold_vertices)
        .field("unreferenced_vertices", b.unreferenced_vertices)
        .field("boundary_triangles", b.boundary_triangles)
        .field("boundary_tetrahedra", b.boundary_tetrahedra)
        .field("boundary_face_tetrahedra", b.boundary_face_tetrahedra)
        .field("seconds", seconds);
    if (!out.empty()) j.field("output", out);
    j.end_object();
    std::cout << j.str() << '\n';
    return exit_success;
  }
  Table t({"", "count"});
  t.add({"vertices", std::to_string(nv)});
  t.add({"  interior", std::to_string(b.interior_vertices)});
  t.add({"  boundary", std::to_string(b.boundary_vertices)});
  t.add({"  non-manifold", std::to_string(b.nonmanifold_vertices)});
  t.add({"  in no tetrahedron", std::to_string(b.unreferenced_vertices)});
  t.add({"boundary triangles", std::to_string(b.boundary_triangles)});
  t.add({"tetrahedra touching the boundary", std::to_string(b.boundary_tetrahedra)});
  t.add({"  with a boundary face", std::to_string(b.boundary_face_tetrahedra)});
  std::cout << input << " (k_v = " << bucket_size_string(kv) << ", " << fixed(seconds, 3) << " s)\n"
            << t.str();
  if (b.nonmanifold_vertices)
    std::cout << "warning: " << b.nonmanifold_vertices
              << " vertices have a link that is neither a sphere nor a disc (non-manifold)\n";
  if (!out.empty()) std::cout << "wrote " << out << '\n';
  return exit_success;
}

} // namespace

Command boundary_command() {
  return Command("boundary",
                 "boundary and non-manifold vertices, boundary triangles and tetrahedra (paper Section 7)")
      .input()
      .description(
          R"(Classifies every vertex of MESH as interior, boundary or non-manifold, leaf by leaf (paper
Section 7: 2|e| != 3|t| in the vertex link, plus a check that the link is a sphere or a disc).)")
      .kv()
      .max_depth()
      .output("OUT", point_data_outputs(),
              "write the mesh (labels kept) with the point array `boundary` (0 interior,\n"
              "1 boundary, 2 non-manifold, 3 in no tetrahedron): .vtu/.vtk for ParaView, or\n"
              ".node/.ele (TetGen attribute)")
      .json_keys("keys: vertices, tetrahedra, kv, boundary_vertices, interior_vertices,\n"
                 "nonmanifold_vertices, unreferenced_vertices, boundary_triangles, boundary_tetrahedra\n"
                 "(tetrahedra with a boundary or non-manifold vertex), boundary_face_tetrahedra (with a\n"
                 "face on the boundary), seconds, output")
      .run(run_boundary);
}

} // namespace prstar
