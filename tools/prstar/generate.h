// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Mesh generation for the prstar tool, the tests and the benchmarks: CGAL Mesh_3 on an implicit
// shape or on the inside of a closed triangle surface, or TetGen on the same boundary surface.
// Everything heavy is compiled once, in generate.cpp.

#ifndef PRSTAR_GENERATE_H
#define PRSTAR_GENERATE_H

#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>

#include <string>
#include <utility>
#include <vector>

namespace prstar {

/// What to mesh and how finely.  Exactly one of `shape` and `surface_file` is set.
struct Generate_options {
  std::string shape;         ///< an implicit shape name (see `implicit_shapes()`), or empty
  std::string surface_file;  ///< a closed triangle surface (.off) bounding a polyhedral domain, or empty
  double cell_size = 0;      ///< required, > 0: Mesh_3 bound on the circumradius of the tetrahedra
  double facet_size = 0;     ///< 0 means `cell_size`
  double facet_distance = 0; ///< 0 means `cell_size / 10`
  double facet_angle = 25;   ///< in degrees, in (0, 30]
  double cell_radius_edge_ratio = 3; ///< >= 2
  /// mesh the boundary surface with Mesh_3 (implicit shape) or take the input triangles
  /// (surface file), then fill the volume with TetGen ("pq1.414a<v>", v = volume of a regular
  /// tetrahedron of edge `cell_size`) instead of Mesh_3's volume refinement
  bool tetgen = false;
  bool quiet = false; ///< no progress messages (they go to stderr, and only when it is a terminal)
};

/// The implicit shapes: (name, one-line description), in a fixed order.
std::vector<std::pair<std::string, std::string>> implicit_shapes();

/// The C3T3 type produced by `generate_c3t3()`, the same for implicit shapes and surface files:
/// a `Labeled_mesh_domain_3` over Epick, sequential.  The meshed domain has subdomain index 1.
using Generate_kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Generate_domain = CGAL::Labeled_mesh_domain_3<Generate_kernel>;
using Generate_triangulation =
    CGAL::Mesh_triangulation_3<Generate_domain, CGAL::Default, CGAL::Sequential_tag>::type;
using Generate_c3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Generate_triangulation>;

/// Runs Mesh_3: refinement, then perturbation and exudation up to minimum dihedral angles of 10 and
/// 15 degrees, without time limits so that the result is the same on every run.  Sequential.
/// `options.tetgen` must be false.
/// \throws std::runtime_error on invalid options or an unreadable / unsuitable surface file
Generate_c3t3 generate_c3t3(const Generate_options& options);

/// The generated mesh as arrays: the cells in the complex (Mesh_3) or TetGen's tetrahedra, all
/// positively oriented, the vertices they use, and the label 1 for every tetrahedron.
/// \throws std::runtime_error on invalid options, an unreadable / unsuitable surface file, or a
/// TetGen failure
CGAL::PR_star_octree::Indexed_tetrahedral_mesh<> generate_mesh(const Generate_options& options);

} // namespace prstar

#endif // PRSTAR_GENERATE_H
