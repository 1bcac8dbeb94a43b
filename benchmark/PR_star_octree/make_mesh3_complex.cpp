// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A labelled multi-domain CGAL Mesh_3 mesh for the remeshing benchmark (make_remesh_data.sh): the
// polyhedral complex of CGAL's data set (data/meshes/patch-*.off of Debian's libcgal-demo, a cube of
// side 100 cut into three subdomains by internal surfaces), meshed with its sharp features protected.
// The outer boundary is one sphere (genus 0), which CGAL's tetrahedral remeshing needs on a
// tetrahedron soup, and the internal surfaces give the package's label interfaces something to keep.
//
// Not part of the CMake build (a Mesh_3 translation unit takes minutes to compile and the benchmark
// needs the mesh once): make_remesh_data.sh compiles it with g++.
//
// usage: make_mesh3_complex CGAL_DATA_DIR CELL_SIZE OUT.mesh
//   CELL_SIZE: Mesh_3's cell size (the edge size of the features and the facet size are the same,
//   the facet distance is 0.2, as in CGAL's example); writes Medit with the subdomain as the label.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_polyhedron_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_complex_mesh_domain_3.h>
#include <CGAL/make_mesh_3.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Polyhedron = CGAL::Mesh_polyhedron_3<K>::type;
using Domain = CGAL::Polyhedral_complex_mesh_domain_3<K>;
using Tr = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;

} // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: make_mesh3_complex CGAL_DATA_DIR CELL_SIZE OUT.mesh\n";
    return 2;
  }
  const std::string data = argv[1];
  const double cell_size = std::atof(argv[2]);
  if (!(cell_size > 0)) {
    std::cerr << "make_mesh3_complex: CELL_SIZE must be positive\n";
    return 2;
  }
  // The patches and the subdomains on their two sides (0 = outside), as CGAL's data set defines them.
  const std::vector<std::pair<std::string, std::pair<int, int>>> patches{
      {"patch-01.off", {0, 1}}, {"patch-13.off", {1, 3}}, {"patch-20.off", {2, 0}},
      {"patch-21.off", {2, 1}}, {"patch-23.off", {2, 3}}, {"patch-30.off", {3, 0}}};
  std::vector<Polyhedron> surfaces(patches.size());
  std::vector<std::pair<int, int>> sides;
  for (std::size_t i = 0; i < patches.size(); ++i) {
    const std::string file = data + "/meshes/" + patches[i].first;
    std::ifstream in(file);
    if (!(in >> surfaces[i])) {
      std::cerr << "make_mesh3_complex: cannot read " << file << " as a polyhedron\n";
      return 1;
    }
    sides.push_back(patches[i].second);
  }
  Domain domain(surfaces.begin(), surfaces.end(), sides.begin(), sides.end());
  domain.detect_features(); // the sharp edges and the borders of the patches
  namespace p = CGAL::parameters;
  const Criteria criteria(p::edge_size = cell_size, p::facet_angle = 25, p::facet_size = cell_size,
                          p::facet_distance = 0.2, p::cell_radius_edge_ratio = 3, p::cell_size = cell_size);
  const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria);
  std::ofstream out(argv[3]);
  c3t3.output_to_medit(out);
  if (!out) {
    std::cerr << "make_mesh3_complex: cannot write " << argv[3] << '\n';
    return 1;
  }
  std::cerr << "make_mesh3_complex: " << c3t3.triangulation().number_of_vertices() << " vertices, "
            << c3t3.number_of_cells_in_complex() << " tetrahedra\n";
  return 0;
}
