// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Parallel leaves give the same results as the sequential run, bit for bit and in the same order:
// boundary (types, counts, the boundary triangles in output order), curvature (every double of
// every vertex), simplex counts, validity, on generated meshes and a real one, for several k_v.
// With TBB absent, Parallel_if_available_tag is sequential and the test still checks the
// sequential run against an independent per-vertex evaluation.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/Leaf_topology.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/distortion.h>
#include <CGAL/PR_star_octree/validity.h>
#include <CGAL/property_map.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "test_harness.h"

namespace {

namespace PSO = CGAL::PR_star_octree;
namespace params = CGAL::PR_star_octree::parameters;
using Mesh = PSO::Indexed_tetrahedral_mesh<>;
using Octree = CGAL::PR_star_octree_3<>;

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

void compare(const Mesh& mesh, std::size_t kv, const std::string& what) {
  prstar_test::Failure_context context(what + " k_v " + std::to_string(kv));
  const Octree tree(PSO::make_input(mesh), kv);
  const std::size_t nv = mesh.points.size();

  // Boundary.
  std::vector<PSO::Vertex_type> t_seq(nv), t_par(nv);
  std::vector<std::array<std::size_t, 3>> f_seq, f_par;
  std::atomic<std::size_t> calls{0};
  std::size_t last = 0;
  bool monotone = true;
  const auto b_seq = PSO::compute_boundary<CGAL::Sequential_tag>(
      tree, CGAL::make_property_map(t_seq), params::boundary_triangles_output(std::back_inserter(f_seq)));
  const auto b_par = PSO::compute_boundary<CGAL::Parallel_if_available_tag>(
      tree, CGAL::make_property_map(t_par),
      params::boundary_triangles_output(std::back_inserter(f_par))
          .progress([&](std::size_t done, std::size_t total) {
            ++calls;
            monotone = monotone && done > last && done <= total;
            last = done;
          }));
  CHECK(t_seq == t_par);
  CHECK(f_seq == f_par);
  CHECK_EQUAL(b_seq.boundary_vertices, b_par.boundary_vertices);
  CHECK_EQUAL(b_seq.boundary_tetrahedra, b_par.boundary_tetrahedra);
  CHECK_EQUAL(b_seq.boundary_face_tetrahedra, b_par.boundary_face_tetrahedra);
  CHECK_EQUAL(b_seq.boundary_triangles, f_seq.size());
  CHECK(monotone);
  CHECK(calls.load() >= 1 && calls.load() <= tree.number_of_leaves());
  CHECK_EQUAL(last, tree.number_of_leaves());

  // Curvature: every double identical, and equal to the per-vertex evaluation of curvature_at().
  std::vector<double> field(nv);
  for (std::size_t v = 0; v < nv; ++v)
    field[v] =
        mesh.points[v].x() * mesh.points[v].x() + std::sin(3 * mesh.points[v].y()) + mesh.points[v].z();
  std::vector<PSO::Vertex_curvature> c_seq(nv), c_par(nv);
  const auto k_seq = PSO::compute_curvature<CGAL::Sequential_tag>(tree, CGAL::make_property_map(field),
                                                                  CGAL::make_property_map(c_seq));
  const auto k_par = PSO::compute_curvature<CGAL::Parallel_if_available_tag>(
      tree, CGAL::make_property_map(field), CGAL::make_property_map(c_par));
  std::size_t differ = 0, differ_at = 0;
  for (std::size_t v = 0; v < nv; ++v) {
    differ += !(same_bits(c_seq[v].distortion, c_par[v].distortion) &&
                same_bits(c_seq[v].domain_curvature, c_par[v].domain_curvature) &&
                same_bits(c_seq[v].solid_angle_sum_4, c_par[v].solid_angle_sum_4) &&
                c_seq[v].type == c_par[v].type);
    const auto at = PSO::curvature_at(tree, static_cast<Octree::Index>(v), CGAL::make_property_map(field));
    const auto& mine = c_seq[tree.original_vertex(static_cast<Octree::Index>(v))];
    differ_at += !(same_bits(at.solid_angle_sum_3, mine.solid_angle_sum_3) &&
                   same_bits(at.solid_angle_sum_4, mine.solid_angle_sum_4) && at.type == mine.type);
  }
  CHECK_EQUAL(differ, std::size_t(0));
  CHECK_EQUAL(differ_at, std::size_t(0));
  CHECK_EQUAL(k_seq.nonmanifold_vertices, k_par.nonmanifold_vertices);
  CHECK_EQUAL(k_seq.interior_vertices, b_seq.interior_vertices);

  // Counts and validity.
  const auto s_seq = PSO::count_simplices<CGAL::Sequential_tag>(tree);
  const auto s_par = PSO::count_simplices<CGAL::Parallel_if_available_tag>(tree);
  CHECK_EQUAL(s_seq.edges, s_par.edges);
  CHECK_EQUAL(s_seq.triangles, s_par.triangles);
  CHECK_EQUAL(s_seq.vertices, s_par.vertices);
  CHECK_EQUAL(s_seq.boundary_triangles, b_seq.boundary_triangles);
  const auto v_seq = PSO::check_validity<CGAL::Sequential_tag>(tree);
  const auto v_par = PSO::check_validity<CGAL::Parallel_if_available_tag>(tree);
  CHECK_EQUAL(v_seq.valid, v_par.valid);
  CHECK_EQUAL(v_seq.positive, v_par.positive);
  CHECK_EQUAL(v_seq.negative, v_par.negative);
  CHECK_EQUAL(v_seq.degenerate, v_par.degenerate);
  CHECK_EQUAL(v_seq.nonmanifold_vertices, v_par.nonmanifold_vertices);
  CHECK_EQUAL(v_seq.nonmanifold_vertices, b_seq.nonmanifold_vertices);
  CHECK_EQUAL(v_seq.boundary_components, v_par.boundary_components);
  CHECK_EQUAL(v_seq.euler_characteristic, v_par.euler_characteristic);
}

} // namespace

int main(int argc, char** argv) {
  const prstar_test::Data_folders data(argc, argv);
#ifdef CGAL_LINKED_WITH_TBB
  std::cout << "TBB: parallel leaves compared with the sequential run\n";
#else
  prstar_test::skip("TBB absent: Parallel_if_available_tag is sequential");
#endif
  for (const char* name : {"sphere.mesh", "torus.mesh", "cube_tetgen.vtu"}) {
    const auto path = data.generated_file(name);
    if (!path) continue;
    Mesh mesh;
    PSO::IO::read_tetrahedral_mesh(*path, mesh);
    for (std::size_t kv : {std::size_t(1), std::size_t(20), std::size_t(200), Octree::infinite_bucket_size})
      compare(mesh, kv, name);
  }
  if (data.report_shared())
    if (const auto path = data.shared_file("skull_14k.off")) { // non-manifold vertices
      Mesh mesh;
      PSO::IO::read_tetrahedral_mesh(*path, mesh);
      compare(mesh, 50, "skull_14k.off");
    }
  return prstar_test::summary("test_parallel");
}
