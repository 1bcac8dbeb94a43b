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
#include <CGAL/PR_star_octree/Leaf_executor.h>
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

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

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
  const Octree tree(PSO::make_input(mesh), CGAL::PR_star_octree::parameters::bucket_size(kv));
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

// The leaf executor itself: the sequence of leaf results the reduction sees is the same for 1, 2
// and 8 threads and sequentially; a partition of the leaves into `Leaf_range`s gives the same
// results part by part; `stop` stops; `VERTEX_LINKS` gives the types of the per-vertex
// classification (`Vertex_classifier::classify()`, one `Vertex_link` per star).
void check_executor(const Mesh& mesh, std::size_t kv, const std::string& what) {
  prstar_test::Failure_context context(what + " executor k_v " + std::to_string(kv));
  const Octree tree(PSO::make_input(mesh), CGAL::PR_star_octree::parameters::bucket_size(kv));
  using Local = PSO::Leaf_topology<Octree>;
  // Per leaf: its node, the number of owned edges, and the checked and unchecked link types.
  struct Leaf_record {
    Octree::Node_index leaf;
    std::size_t edges;
    std::vector<PSO::Vertex_type> types;
    bool operator==(const Leaf_record& o) const {
      return leaf == o.leaf && edges == o.edges && types == o.types;
    }
  };
  auto run = [&](const auto& executor, unsigned links, std::vector<Leaf_record>& out) {
    std::size_t last = 0;
    bool monotone = true;
    executor.map_reduce(
        tree, PSO::EDGES | links, std::vector<int>(3, 7), // a state that must arrive intact
        [&](std::vector<int>& state, const Local& local) {
          CHECK(state.size() == 3 && state[0] == 7);
          Leaf_record r{local.leaf(), 0, {}};
          for (std::size_t e = 0; e < local.number_of_edges(); ++e) r.edges += local.owns_edge(e);
          for (auto v = local.vertex_begin(); v < local.vertex_end(); ++v)
            r.types.push_back(local.vertex_type(v));
          return r;
        },
        [&](Leaf_record&& r) { out.push_back(std::move(r)); },
        [&](std::size_t done, std::size_t total) {
          monotone = monotone && done == last + 1 && done <= total;
          last = done;
        });
    CHECK(monotone);
  };
  std::vector<Leaf_record> seq, unchecked;
  run(PSO::Leaf_executor<CGAL::Sequential_tag>(), PSO::VERTEX_LINKS, seq);
  run(PSO::Leaf_executor<CGAL::Sequential_tag>(), PSO::VERTEX_LINKS | PSO::UNCHECKED_LINKS, unchecked);
  CHECK_EQUAL(seq.size(), tree.number_of_leaves());
  for (std::size_t i = 0; i < seq.size(); ++i) CHECK(seq[i].leaf == tree.leaves()[i]);

  // Against the per-vertex classification, checked and unchecked.
  PSO::Vertex_classifier<Octree> checked_classifier, unchecked_classifier(params::check_links(false));
  std::size_t differ = 0;
  for (std::size_t i = 0; i < seq.size(); ++i) {
    const Local local(tree, seq[i].leaf, PSO::VERTEX_TETRAHEDRA);
    for (auto v = local.vertex_begin(); v < local.vertex_end(); ++v) {
      differ += seq[i].types[v - local.vertex_begin()] != checked_classifier.classify(local, v);
      differ += unchecked[i].types[v - local.vertex_begin()] != unchecked_classifier.classify(local, v);
    }
  }
  CHECK_EQUAL(differ, std::size_t(0));

#ifdef CGAL_LINKED_WITH_TBB
  for (int threads : {1, 2, 8}) {
    // (eight threads even on a machine with fewer cores)
    tbb::global_control allow(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(threads));
    tbb::task_arena arena(threads);
    std::vector<Leaf_record> par;
    arena.execute([&] { run(PSO::Leaf_executor<CGAL::Parallel_tag>(), PSO::VERTEX_LINKS, par); });
    CHECK_MSG(par == seq, "threads " + std::to_string(threads));
    // The whole boundary pass too, bit for bit.
    std::vector<PSO::Vertex_type> t_seq(mesh.points.size()), t_par(mesh.points.size());
    std::vector<std::array<std::size_t, 3>> f_seq, f_par;
    PSO::compute_boundary<CGAL::Sequential_tag>(tree, CGAL::make_property_map(t_seq),
                                                params::boundary_triangles_output(std::back_inserter(f_seq)));
    arena.execute([&] {
      PSO::compute_boundary<CGAL::Parallel_tag>(tree, CGAL::make_property_map(t_par),
                                                params::boundary_triangles_output(std::back_inserter(f_par)));
    });
    CHECK(t_seq == t_par);
    CHECK(f_seq == f_par);
  }
#endif

  // A partition into three ranges (one of them empty, one past the end): the same records in order.
  const std::size_t n = tree.number_of_leaves();
  std::vector<Leaf_record> parts;
  for (PSO::Leaf_range r :
       {PSO::Leaf_range{0, n / 3}, PSO::Leaf_range{n / 3, n / 3}, PSO::Leaf_range{n / 3, n + 5}}) {
    std::vector<Leaf_record> part;
    run(PSO::Leaf_executor<CGAL::Parallel_if_available_tag>(r), PSO::VERTEX_LINKS, part);
    CHECK_EQUAL(part.size(), (std::min)(r.last, n) - (std::min)(r.first, (std::min)(r.last, n)));
    parts.insert(parts.end(), part.begin(), part.end());
  }
  CHECK(parts == seq);

  // Stop after five leaves: sequentially exactly five, in parallel at least five and all in order.
  for (int parallel = 0; parallel < 2; ++parallel) {
    std::atomic<std::size_t> reduced{0}; // (`stop` and `reduce` may run on different threads)
    bool in_order = true;
    auto f = [](int, const Local& local) { return local.leaf(); };
    auto reduce = [&](Octree::Node_index leaf) { in_order = in_order && leaf == tree.leaves()[reduced++]; };
    auto stop = [&] { return reduced >= 5; };
    if (parallel)
      PSO::Leaf_executor<CGAL::Parallel_if_available_tag>().map_reduce(tree, 0, 0, f, reduce,
                                                                       PSO::internal::No_progress(), stop);
    else
      PSO::Leaf_executor<CGAL::Sequential_tag>().map_reduce(tree, 0, 0, f, reduce,
                                                            PSO::internal::No_progress(), stop);
    CHECK(in_order);
    if (parallel)
      CHECK(reduced.load() >= (std::min<std::size_t>)(5, n));
    else
      CHECK_EQUAL(reduced.load(), (std::min<std::size_t>)(5, n));
  }
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
    check_executor(mesh, 20, name);
  }
  if (data.report_shared())
    if (const auto path = data.shared_file("skull_14k.off")) { // non-manifold vertices
      Mesh mesh;
      PSO::IO::read_tetrahedral_mesh(*path, mesh);
      compare(mesh, 50, "skull_14k.off");
      check_executor(mesh, 50, "skull_14k.off");
    }
  return prstar_test::summary("test_parallel");
}
