// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Tests of validity.h (against brute force on a hand-made invalid mesh) and of the local
// half-edge-collapse simplification of simplification.h: validity and topology of every output,
// boundary vertices kept on the boundary, crafted cases where only the exact predicate or only the
// link condition rejects a collapse, and the 25% / 50% targets with k_v = infinity and finite k_v.
//
// argv[1]: the generated test meshes; argv[2] (optional): the shared real meshes.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/mesh_quality.h>
#include <CGAL/PR_star_octree/remeshing.h>
#include <CGAL/PR_star_octree/simplification.h>
#include <CGAL/PR_star_octree/validity.h>

#include "test_harness.h"

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;
using Octree = CGAL::PR_star_octree_3<>;
using Tet = std::array<std::uint32_t, 4>;
namespace P = CGAL::PR_star_octree;
namespace params = CGAL::PR_star_octree::parameters;

// ---------------------------------------------------------------------------------------------
// Brute force
// ---------------------------------------------------------------------------------------------

struct Brute {
  std::size_t positive = 0, negative = 0, flat = 0, nonmanifold_triangles = 0;
  long long euler = 0;
  std::size_t boundary_components = 0;
  std::set<std::size_t> boundary_vertices;
};

std::size_t find(std::vector<std::size_t>& p, std::size_t x) {
  while (p[x] != x) x = p[x] = p[p[x]];
  return x;
}

Brute brute_force(const std::vector<Point>& pts, const std::vector<Tet>& tets) {
  Brute b;
  std::map<std::array<std::uint32_t, 3>, int> faces;
  std::set<std::array<std::uint32_t, 2>> edges;
  std::set<std::uint32_t> vertices;
  for (const Tet& c : tets) {
    const CGAL::Orientation o = CGAL::orientation(pts[c[0]], pts[c[1]], pts[c[2]], pts[c[3]]);
    b.positive += o == CGAL::POSITIVE;
    b.negative += o == CGAL::NEGATIVE;
    b.flat += o == CGAL::COPLANAR;
    for (int i = 0; i < 4; ++i) {
      vertices.insert(c[i]);
      for (int j = i + 1; j < 4; ++j) edges.insert({std::min(c[i], c[j]), std::max(c[i], c[j])});
      std::array<std::uint32_t, 3> f{{c[(i + 1) % 4], c[(i + 2) % 4], c[(i + 3) % 4]}};
      std::sort(f.begin(), f.end());
      ++faces[f];
    }
  }
  b.euler =
      (long long)vertices.size() - (long long)edges.size() + (long long)faces.size() - (long long)tets.size();
  std::vector<std::array<std::uint32_t, 3>> boundary;
  for (const auto& f : faces) {
    b.nonmanifold_triangles += f.second > 2;
    if (f.second == 1) boundary.push_back(f.first);
  }
  // Components of the boundary triangles through shared edges.
  std::vector<std::size_t> parent(boundary.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
  std::map<std::array<std::uint32_t, 2>, std::size_t> first_triangle;
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    const auto& f = boundary[i];
    for (auto e : {std::array<std::uint32_t, 2>{{f[0], f[1]}}, std::array<std::uint32_t, 2>{{f[1], f[2]}},
                   std::array<std::uint32_t, 2>{{f[0], f[2]}}}) {
      auto it = first_triangle.find(e);
      if (it == first_triangle.end())
        first_triangle[e] = i;
      else
        parent[find(parent, i)] = find(parent, it->second);
    }
    for (auto v : f) b.boundary_vertices.insert(v);
  }
  for (std::size_t i = 0; i < parent.size(); ++i) b.boundary_components += find(parent, i) == i;
  return b;
}

// ---------------------------------------------------------------------------------------------
// validity.h against brute force
// ---------------------------------------------------------------------------------------------

void test_validity_hand_made() {
  // A valid cube of 6 positive tetrahedra (Kuhn), then defects added one at a time.
  std::vector<Point> pts;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) pts.emplace_back(i, j, k);
  auto id = [](int i, int j, int k) { return std::uint32_t(i + 2 * j + 4 * k); };
  std::vector<Tet> tets;
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& p : perms) {
    int x[3] = {0, 0, 0};
    Tet c;
    c[0] = id(0, 0, 0);
    for (int s = 0; s < 3; ++s) {
      x[p[s]] = 1;
      c[s + 1] = id(x[0], x[1], x[2]);
    }
    if (CGAL::orientation(pts[c[0]], pts[c[1]], pts[c[2]], pts[c[3]]) == CGAL::NEGATIVE)
      std::swap(c[2], c[3]);
    tets.push_back(c);
  }
  {
    const auto r = P::check_validity(pts, tets);
    CHECK(r.valid);
    CHECK_EQUAL(r.euler_characteristic, 1LL);
    CHECK_EQUAL(r.boundary_components, std::size_t(1));
    CHECK_EQUAL(r.boundary_triangles, std::size_t(12));
  }

  // A separate tetrahedron, listed inverted.
  const std::uint32_t a = std::uint32_t(pts.size());
  pts.emplace_back(5, 0, 0);
  pts.emplace_back(6, 0, 0);
  pts.emplace_back(5, 1, 0);
  pts.emplace_back(5, 0, 1);
  tets.push_back(Tet{{a, a + 2, a + 1, a + 3}});
  // A separate flat tetrahedron.
  const std::uint32_t f = std::uint32_t(pts.size());
  pts.emplace_back(10, 0, 0);
  pts.emplace_back(11, 0, 0);
  pts.emplace_back(10, 1, 0);
  pts.emplace_back(11, 1, 0);
  tets.push_back(Tet{{f, f + 1, f + 2, f + 3}});
  // A triangle (0, 1, 2) of the cube's bottom face in three tetrahedra: two more below it.
  const std::uint32_t d = std::uint32_t(pts.size());
  pts.emplace_back(0.3, 0.3, -1);
  pts.emplace_back(0.2, 0.4, -2);
  tets.push_back(Tet{{id(0, 0, 0), id(1, 0, 0), id(1, 1, 0), d}});
  tets.push_back(Tet{{id(0, 0, 0), id(1, 0, 0), id(1, 1, 0), d + 1}});

  const Brute b = brute_force(pts, tets);
  const auto r = P::check_validity(pts, tets, params::bucket_size(3));
  CHECK(!r.valid);
  CHECK_EQUAL(r.tetrahedra, tets.size());
  CHECK_EQUAL(r.positive, b.positive);
  CHECK_EQUAL(r.negative, b.negative);
  CHECK_EQUAL(r.degenerate, b.flat);
  CHECK_EQUAL(r.degenerate, std::size_t(1));
  CHECK_EQUAL(r.inverted, std::min(b.positive, b.negative));
  CHECK(r.inverted >= 1);
  CHECK_EQUAL(r.nonmanifold_triangles, b.nonmanifold_triangles);
  CHECK(r.nonmanifold_triangles >= 1);
  CHECK(r.nonmanifold_vertices >= 3); // at least the vertices of the triangle in three tetrahedra
  CHECK_EQUAL(r.euler_characteristic, b.euler);
  CHECK_EQUAL(r.boundary_components, b.boundary_components);
  // Same answers whatever k_v.
  const auto r1 = P::check_validity(pts, tets, params::bucket_size(Octree::infinite_bucket_size));
  CHECK_EQUAL(r1.inverted, r.inverted);
  CHECK_EQUAL(r1.degenerate, r.degenerate);
  CHECK_EQUAL(r1.nonmanifold_triangles, r.nonmanifold_triangles);
  CHECK_EQUAL(r1.nonmanifold_vertices, r.nonmanifold_vertices);
  CHECK_EQUAL(r1.euler_characteristic, r.euler_characteristic);
  CHECK_EQUAL(r1.boundary_components, r.boundary_components);

  // All tetrahedra listed negatively: consistent (the other convention), nothing inverted.
  std::vector<Tet> flipped(tets.begin(), tets.begin() + 6);
  for (Tet& c : flipped) std::swap(c[0], c[1]);
  const auto rf = P::check_validity(pts, flipped);
  CHECK(rf.valid);
  CHECK_EQUAL(rf.inverted, std::size_t(0));
  CHECK_EQUAL(rf.negative, std::size_t(6));
}

// The problems of check_validity (problems_output) against brute force: the orientation of every
// input tetrahedron with CGAL::orientation (the minority sign, the negative one on a tie), the
// triangles counted with a map over all faces, the vertex links checked to be spheres or discs
// from the faces opposite each vertex, the unreferenced vertices with a mark array.
std::vector<P::Validity_problem> brute_force_problems(const std::vector<Point>& pts,
                                                      const std::vector<Tet>& tets) {
  using Problem = P::Validity_problem;
  using Kind = P::Validity_problem_kind;
  std::vector<Problem> r;
  std::vector<CGAL::Orientation> sign(tets.size());
  std::size_t positive = 0, negative = 0;
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const Tet& c = tets[t];
    sign[t] = CGAL::orientation(pts[c[0]], pts[c[1]], pts[c[2]], pts[c[3]]);
    positive += sign[t] == CGAL::POSITIVE;
    negative += sign[t] == CGAL::NEGATIVE;
  }
  const CGAL::Orientation minority = negative <= positive ? CGAL::NEGATIVE : CGAL::POSITIVE;
  auto tetrahedron = [&](std::size_t t, Kind kind) {
    Problem p;
    p.kind = kind;
    p.tetrahedron = t;
    for (int k = 0; k < 4; ++k) p.vertices[k] = tets[t][k];
    r.push_back(p);
  };
  for (std::size_t t = 0; t < tets.size(); ++t) {
    if (sign[t] == CGAL::COPLANAR) tetrahedron(t, Kind::FLAT_TETRAHEDRON);
    if (sign[t] == minority && std::min(positive, negative) > 0) tetrahedron(t, Kind::INVERTED_TETRAHEDRON);
  }
  std::map<std::array<std::uint32_t, 3>, std::vector<std::size_t>> faces;
  std::vector<std::vector<std::array<std::uint32_t, 3>>> links(pts.size());
  std::vector<char> used(pts.size(), 0);
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (int i = 0; i < 4; ++i) {
      std::array<std::uint32_t, 3> f{{tets[t][(i + 1) % 4], tets[t][(i + 2) % 4], tets[t][(i + 3) % 4]}};
      std::sort(f.begin(), f.end());
      faces[f].push_back(t);
      links[tets[t][i]].push_back(f);
      used[tets[t][i]] = 1;
    }
  for (const auto& f : faces)
    if (f.second.size() > 2) {
      Problem p;
      p.kind = Kind::NONMANIFOLD_TRIANGLE;
      for (int k = 0; k < 3; ++k) p.vertices[k] = f.first[k];
      p.tetrahedra = f.second; // increasing
      r.push_back(p);
    }
  for (std::uint32_t v = 0; v < pts.size(); ++v) {
    Problem p;
    p.vertices[0] = v;
    if (!used[v]) {
      p.kind = Kind::UNREFERENCED_VERTEX;
      r.push_back(p);
      continue;
    }
    // The link: every edge in one or two triangles, connected through edges, and either closed
    // with Euler characteristic 2 or with one boundary loop and Euler characteristic 1.
    const auto& link = links[v];
    std::map<std::array<std::uint32_t, 2>, std::vector<std::size_t>> edges;
    std::set<std::uint32_t> vertices;
    for (std::size_t i = 0; i < link.size(); ++i) {
      const auto& f = link[i];
      for (auto e : {std::array<std::uint32_t, 2>{{f[0], f[1]}}, std::array<std::uint32_t, 2>{{f[1], f[2]}},
                     std::array<std::uint32_t, 2>{{f[0], f[2]}}})
        edges[e].push_back(i);
      vertices.insert(f.begin(), f.end());
    }
    bool manifold = true;
    std::vector<std::size_t> parent(link.size());
    for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
    std::map<std::uint32_t, int> boundary_degree;
    std::size_t boundary_edges = 0;
    for (const auto& e : edges) {
      manifold = manifold && e.second.size() <= 2;
      for (std::size_t i : e.second) parent[find(parent, i)] = find(parent, e.second.front());
      if (e.second.size() == 1) {
        ++boundary_edges;
        ++boundary_degree[e.first[0]];
        ++boundary_degree[e.first[1]];
      }
    }
    std::size_t components = 0;
    for (std::size_t i = 0; i < parent.size(); ++i) components += find(parent, i) == i;
    const long long euler = (long long)vertices.size() - (long long)edges.size() + (long long)link.size();
    for (const auto& d : boundary_degree) manifold = manifold && d.second == 2;
    // a single boundary loop: as many edges as vertices, and (degrees all 2) one cycle when the
    // loop's vertices are connected through its edges
    if (boundary_edges > 0) {
      std::map<std::uint32_t, std::uint32_t> loop_parent;
      for (const auto& d : boundary_degree) loop_parent[d.first] = d.first;
      std::function<std::uint32_t(std::uint32_t)> root = [&](std::uint32_t x) {
        return loop_parent[x] == x ? x : loop_parent[x] = root(loop_parent[x]);
      };
      for (const auto& e : edges)
        if (e.second.size() == 1) loop_parent[root(e.first[0])] = root(e.first[1]);
      std::size_t loops = 0;
      for (const auto& d : boundary_degree) loops += root(d.first) == d.first;
      manifold = manifold && loops == 1 && euler == 1;
    } else
      manifold = manifold && euler == 2;
    manifold = manifold && components == 1;
    if (!manifold) {
      p.kind = Kind::NONMANIFOLD_VERTEX;
      r.push_back(p);
    }
  }
  std::sort(r.begin(), r.end());
  return r;
}

std::vector<P::Validity_problem> reported_problems(const Octree& tree, bool parallel,
                                                   P::Validity_result* result) {
  std::vector<P::Validity_problem> problems;
  const auto np = params::problems_output(std::back_inserter(problems));
  *result = parallel ? P::check_validity<CGAL::Parallel_if_available_tag>(tree, np)
                     : P::check_validity<CGAL::Sequential_tag>(tree, np);
  return problems;
}

void test_validity_problems() {
  using Kind = P::Validity_problem_kind;
  // The Kuhn cube of test_validity_hand_made, listed positively, and planted defects.
  std::vector<Point> pts;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) pts.emplace_back(i, j, k);
  auto id = [](int i, int j, int k) { return std::uint32_t(i + 2 * j + 4 * k); };
  std::vector<Tet> tets;
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& p : perms) {
    int x[3] = {0, 0, 0};
    Tet c;
    c[0] = id(0, 0, 0);
    for (int s = 0; s < 3; ++s) {
      x[p[s]] = 1;
      c[s + 1] = id(x[0], x[1], x[2]);
    }
    if (CGAL::orientation(pts[c[0]], pts[c[1]], pts[c[2]], pts[c[3]]) == CGAL::NEGATIVE)
      std::swap(c[2], c[3]);
    tets.push_back(c);
  }
  auto add_point = [&](double x, double y, double z) {
    pts.emplace_back(x, y, z);
    return std::uint32_t(pts.size() - 1);
  };
  // two unreferenced vertices, numbered among the others
  const std::uint32_t lonely1 = add_point(3, 3, 3);
  // one inverted tetrahedron (listed negatively), apart
  const std::uint32_t a = add_point(5, 0, 0), a1 = add_point(6, 0, 0), a2 = add_point(5, 1, 0),
                      a3 = add_point(5, 0, 1);
  const std::size_t inverted_tet = tets.size();
  tets.push_back(Tet{{a, a2, a1, a3}});
  // one flat tetrahedron, apart
  const std::uint32_t f = add_point(10, 0, 0), f1 = add_point(11, 0, 0), f2 = add_point(10, 1, 0),
                      f3 = add_point(11, 1, 0);
  const std::size_t flat_tet = tets.size();
  tets.push_back(Tet{{f, f1, f2, f3}});
  const std::uint32_t lonely2 = add_point(-3, 2, 7);
  // a triangle (0, 1, 3) of the cube's bottom face in three tetrahedra: two more below it
  const std::uint32_t d = add_point(0.3, 0.3, -1), d1 = add_point(0.2, 0.4, -2);
  for (std::uint32_t apex : {d, d1}) {
    Tet c{{id(0, 0, 0), id(1, 0, 0), id(1, 1, 0), apex}};
    if (CGAL::orientation(pts[c[0]], pts[c[1]], pts[c[2]], pts[c[3]]) == CGAL::NEGATIVE)
      std::swap(c[2], c[3]);
    tets.push_back(c);
  }
  // a fin, apart: the triangle (g, g1, g2) in three tetrahedra, two of them on the same side
  const std::uint32_t g = add_point(20, 0, 0), g1 = add_point(21, 0, 0), g2 = add_point(20, 1, 0),
                      g3 = add_point(20, 0, 1), g4 = add_point(20, 0, -1), g5 = add_point(21, 1, 1);
  for (Tet c : {Tet{{g, g1, g2, g3}}, Tet{{g, g2, g1, g4}}, Tet{{g, g1, g2, g5}}}) {
    if (CGAL::orientation(pts[c[0]], pts[c[1]], pts[c[2]], pts[c[3]]) == CGAL::NEGATIVE)
      std::swap(c[2], c[3]);
    tets.push_back(c);
  }
  // a bow tie, apart: two tetrahedra sharing only the vertex h (a non-manifold vertex)
  const std::uint32_t h = add_point(30, 0, 0);
  for (double s : {1.0, -1.0}) {
    Tet c{{h, add_point(30 + s, 0, 0), add_point(30, s, 0), add_point(30, 0, s)}};
    if (CGAL::orientation(pts[c[0]], pts[c[1]], pts[c[2]], pts[c[3]]) == CGAL::NEGATIVE)
      std::swap(c[2], c[3]);
    tets.push_back(c);
  }

  const auto expected = brute_force_problems(pts, tets);
  // the planted defects are in the brute force's list (it means something)
  auto has = [&](Kind kind, std::size_t tetrahedron, std::size_t vertex) {
    return std::any_of(expected.begin(), expected.end(), [&](const P::Validity_problem& p) {
      return p.kind == kind && p.tetrahedron == tetrahedron && p.vertices[0] == vertex;
    });
  };
  CHECK(has(Kind::INVERTED_TETRAHEDRON, inverted_tet, a));
  CHECK(has(Kind::FLAT_TETRAHEDRON, flat_tet, f));
  CHECK(has(Kind::NONMANIFOLD_TRIANGLE, P::Validity_problem::no_id, id(0, 0, 0)));
  CHECK(has(Kind::NONMANIFOLD_TRIANGLE, P::Validity_problem::no_id, g));
  CHECK(has(Kind::NONMANIFOLD_VERTEX, P::Validity_problem::no_id, h));
  CHECK(has(Kind::UNREFERENCED_VERTEX, P::Validity_problem::no_id, lonely1));
  CHECK(has(Kind::UNREFERENCED_VERTEX, P::Validity_problem::no_id, lonely2));
  CHECK_EQUAL(
      std::count_if(expected.begin(), expected.end(),
                    [](const P::Validity_problem& p) { return p.kind == Kind::INVERTED_TETRAHEDRON; }),
      std::ptrdiff_t(1));

  for (std::size_t kv : {std::size_t(1), std::size_t(3), std::size_t(8), Octree::infinite_bucket_size}) {
    const Octree tree(P::make_input(pts, tets), params::bucket_size(kv));
    P::Validity_result rs, rp;
    const auto seq = reported_problems(tree, false, &rs);
    const auto par = reported_problems(tree, true, &rp);
    CHECK_MSG(seq == expected, "k_v = " + std::to_string(kv) + ": the problems are not the brute force's");
    CHECK_MSG(par == seq, "k_v = " + std::to_string(kv) + ": sequential and parallel problems differ");
    CHECK(!rs.valid);
    CHECK_EQUAL(rs.unreferenced_vertices, std::size_t(2));
    CHECK_EQUAL(rp.unreferenced_vertices, std::size_t(2));
    // the counts agree with the lists, and with a run without the list
    auto count = [&](Kind kind) {
      return std::size_t(std::count_if(seq.begin(), seq.end(),
                                       [&](const P::Validity_problem& p) { return p.kind == kind; }));
    };
    CHECK_EQUAL(count(Kind::INVERTED_TETRAHEDRON), rs.inverted);
    CHECK_EQUAL(count(Kind::FLAT_TETRAHEDRON), rs.degenerate);
    CHECK_EQUAL(count(Kind::NONMANIFOLD_TRIANGLE), rs.nonmanifold_triangles);
    CHECK_EQUAL(count(Kind::NONMANIFOLD_VERTEX), rs.nonmanifold_vertices);
    CHECK_EQUAL(count(Kind::UNREFERENCED_VERTEX), rs.unreferenced_vertices);
    const auto plain = P::check_validity(tree);
    CHECK_EQUAL(plain.unreferenced_vertices, rs.unreferenced_vertices);
    CHECK_EQUAL(plain.nonmanifold_vertices, rs.nonmanifold_vertices);
    CHECK_EQUAL(plain.inverted, rs.inverted);
  }
  // the same through the array overload
  {
    std::vector<P::Validity_problem> problems;
    P::check_validity(pts, tets, params::bucket_size(2).problems_output(std::back_inserter(problems)));
    CHECK(problems == expected);
  }

  // The cube and two unreferenced vertices: a warning, the mesh stays valid.
  {
    std::vector<Point> cube_pts(pts.begin(), pts.begin() + 8);
    cube_pts.emplace_back(4, 4, 4);
    cube_pts.emplace_back(-4, 4, 4);
    const std::vector<Tet> cube(tets.begin(), tets.begin() + 6);
    std::vector<P::Validity_problem> problems;
    const auto r = P::check_validity(cube_pts, cube, params::problems_output(std::back_inserter(problems)));
    CHECK(r.valid);
    CHECK_EQUAL(r.unreferenced_vertices, std::size_t(2));
    CHECK_EQUAL(problems.size(), std::size_t(2));
    CHECK(problems == brute_force_problems(cube_pts, cube));
  }
  // A tie (one positive, one negative tetrahedron): the negative one is reported.
  {
    const std::vector<Tet> tie{{tets[inverted_tet], Tet{{a, a1, a2, a3}}}};
    std::vector<P::Validity_problem> problems;
    const auto r = P::check_validity(pts, tie, params::problems_output(std::back_inserter(problems)));
    CHECK_EQUAL(r.inverted, std::size_t(1));
    const auto inverted = std::find_if(problems.begin(), problems.end(), [](const P::Validity_problem& p) {
      return p.kind == Kind::INVERTED_TETRAHEDRON;
    });
    CHECK(inverted != problems.end() && inverted->tetrahedron == 0);
    // all listed negatively (the other convention), the positive one is the minority
    const std::vector<Tet> mostly_negative{{Tet{{a, a1, a2, a3}}, tets[inverted_tet], Tet{{a1, a, a2, a3}}}};
    problems.clear();
    P::check_validity(pts, mostly_negative, params::problems_output(std::back_inserter(problems)));
    CHECK(problems == brute_force_problems(pts, mostly_negative));
    CHECK(!problems.empty() && problems.front().kind == Kind::INVERTED_TETRAHEDRON &&
          problems.front().tetrahedron == 0);
  }
}

// ---------------------------------------------------------------------------------------------
// Crafted collapses
// ---------------------------------------------------------------------------------------------

double naive_orientation(const Point& p, const Point& q, const Point& r, const Point& s) {
  const double ax = q.x() - p.x(), ay = q.y() - p.y(), az = q.z() - p.z();
  const double bx = r.x() - p.x(), by = r.y() - p.y(), bz = r.z() - p.z();
  const double cx = s.x() - p.x(), cy = s.y() - p.y(), cz = s.z() - p.z();
  return ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
}

// Two tetrahedra T1 = (v2, a, b, c) and T2 = (v1, v2, a, b) sharing the face (v2, a, b); v1 lies a
// hair off the plane of (a, b, c), on the far side from v2, so moving v2 to v1 flips T1 by a
// volume smaller than the rounding error of a double determinant.
void test_exact_predicate_rejects() {
  const Point a(0.1, 0.2, 0.3), b(1.7, 0.45, 0.35), c(0.6, 1.9, 0.5), v2(0.7, 0.5, 2.0);
  const Point v1(0x1.e359cb0a65fe8p-1, -0x1.1f17683f86693p-1, 0x1.cc9ace08f70b8p-3);
  const std::vector<Point> pts{v1, v2, a, b, c};
  const std::vector<Tet> tets{Tet{{1, 2, 3, 4}}, Tet{{0, 1, 2, 3}}};
  const Octree tree(P::make_input(pts, tets), P::parameters::bucket_size(Octree::infinite_bucket_size));
  const auto from = tree.vertex_from_original();
  const auto n1 = from[0], n2 = from[1];

  // The moved tetrahedron as the octree stores T1 (positively oriented), v2 replaced by v1.
  bool found = false;
  for (const auto& t : tree.tetrahedra()) {
    if (!std::count(t.begin(), t.end(), n2) || std::count(t.begin(), t.end(), n1)) continue;
    found = true;
    CHECK(CGAL::orientation(tree.point(t[0]), tree.point(t[1]), tree.point(t[2]), tree.point(t[3])) ==
          CGAL::POSITIVE);
    std::array<Point, 4> moved;
    for (int k = 0; k < 4; ++k) moved[k] = tree.point(t[k] == n2 ? n1 : t[k]);
    // A floating-point volume would accept the collapse ...
    CHECK(naive_orientation(moved[0], moved[1], moved[2], moved[3]) > 0);
    // ... the exact predicate sees the flip.
    CHECK(CGAL::orientation(moved[0], moved[1], moved[2], moved[3]) != CGAL::POSITIVE);
  }
  CHECK(found);
  const P::Collapse_check check = P::check_half_edge_collapse(tree, n1, n2);
  CHECK(check.edge_exists);
  CHECK(check.boundary);
  CHECK(check.link);
  CHECK(!check.geometry);
  CHECK(!check.allowed());
}

// A single tetrahedron: every condition but the link one holds for any edge (both ends on the
// boundary, a boundary edge, nothing left to flip), but collapsing it would flatten the ball:
// Lk(v1) ∩ Lk(v2) holds the coned triangle (omega, a, b), which is not in Lk(e).
void test_link_condition_rejects_single_tetrahedron() {
  const std::vector<Point> pts{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)};
  const std::vector<Tet> tets{Tet{{0, 1, 2, 3}}};
  const Octree tree(P::make_input(pts, tets), P::parameters::bucket_size(Octree::infinite_bucket_size));
  const P::Collapse_check check = P::check_half_edge_collapse(tree, Octree::Index(0), Octree::Index(1));
  CHECK(check.edge_exists);
  CHECK(check.boundary);
  CHECK(check.geometry);
  CHECK(!check.link);
  // With the defaults, every vertex is a corner (its three edges are sharp): nothing moves.
  const auto res = P::simplify(P::make_input(pts, tets), params::max_edge_length(10.0));
  CHECK_EQUAL(res.mesh.tetrahedra.size(), std::size_t(1));
  CHECK_EQUAL(res.statistics.blocked.feature, std::size_t(6));
  // Without sharp edges (feature angle 180 degrees), the link condition is what refuses.
  const auto smooth =
      P::simplify(P::make_input(pts, tets), params::max_edge_length(10.0).feature_angle(180.0));
  CHECK_EQUAL(smooth.mesh.tetrahedra.size(), std::size_t(1));
  CHECK_EQUAL(smooth.statistics.blocked.link, std::size_t(6));
  CHECK(smooth.statistics.stop == P::Simplification_stop::NOTHING_LEFT);
}

// A solid torus with a triangular cross-section, one prism (three tetrahedra) per sector and
// three sectors: all vertices on the boundary.  The edge e = (v1, v2) along the ring between the
// sections 0 and 1 is a boundary edge; the same corner w of section 2 is joined to both v1 and v2
// by edges outside St(e) ((v1, v2, w) is not a triangle: it would span the hole): collapsing e
// would pinch the loop v1-v2-w around the hole into one edge.  The ring is wide and the collapse
// flips nothing: only the link condition rejects it.
void test_link_condition_rejects_ring() {
  // Cross-section triangle i (i = 0..2) at angle 2 pi i / 3, vertices 3 i + {0, 1, 2}.
  std::vector<Point> pts;
  const double R = 10;
  for (int i = 0; i < 3; ++i) {
    const double t = 2 * CGAL_PI * i / 3, ct = std::cos(t), st = std::sin(t);
    // inner, outer, top corners of the section in the (radial, z) plane
    const double rz[3][2] = {{R - 1, 0}, {R + 1, 0}, {R, 1.5}};
    for (const auto& q : rz) pts.emplace_back(q[0] * ct, q[0] * st, q[1]);
  }
  std::vector<Tet> tets;
  for (int i = 0; i < 3; ++i) {
    const std::uint32_t a0 = 3 * i, a1 = 3 * i + 1, a2 = 3 * i + 2;
    const std::uint32_t b0 = 3 * ((i + 1) % 3), b1 = b0 + 1, b2 = b0 + 2;
    // the prism (a0 a1 a2 | b0 b1 b2) in three tetrahedra, staircase split with the lowest index first
    const Tet split[3] = {Tet{{a0, a1, a2, b2}}, Tet{{a0, a1, b1, b2}}, Tet{{a0, b0, b1, b2}}};
    for (Tet c : split) {
      if (CGAL::orientation(pts[c[0]], pts[c[1]], pts[c[2]], pts[c[3]]) == CGAL::NEGATIVE)
        std::swap(c[2], c[3]);
      tets.push_back(c);
    }
  }
  const Brute b = brute_force(pts, tets);
  CHECK_EQUAL(b.flat, std::size_t(0));
  CHECK_EQUAL(b.nonmanifold_triangles, std::size_t(0));
  CHECK_EQUAL(b.euler, 0LL); // a solid torus
  const auto valid = P::check_validity(pts, tets);
  CHECK(valid.valid);
  CHECK_EQUAL(valid.euler_characteristic, 0LL);

  const Octree tree(P::make_input(pts, tets), P::parameters::bucket_size(Octree::infinite_bucket_size));
  const auto from = tree.vertex_from_original();
  // The ring edges between two sections at the same corner, e.g. (0, 3): the corner of the third
  // section (6) is joined to both ends, but (0, 3, 6) is not a triangle.  The link condition
  // rejects every such collapse; in some of them (the moving vertex slides along the ring without
  // crossing a face) nothing else does.
  std::size_t link_only = 0;
  for (std::uint32_t s0 = 0; s0 < 3; ++s0)
    for (std::uint32_t corner = 0; corner < 3; ++corner)
      for (int dir = 0; dir < 2; ++dir) {
        const std::uint32_t p0 = 3 * s0 + corner, p1 = 3 * ((s0 + 1) % 3) + corner;
        const P::Collapse_check ch =
            P::check_half_edge_collapse(tree, from[dir ? p1 : p0], from[dir ? p0 : p1]);
        CHECK(ch.edge_exists);
        CHECK(ch.boundary);
        CHECK(!ch.link);
        link_only += ch.geometry;
      }
  std::cout << "ring: " << link_only << " of 18 ring-edge collapses rejected by the link condition alone"
            << std::endl;
  CHECK(link_only >= 1);
  // No collapse at all can keep a one-sector-thick ring of three sectors a solid torus.
  std::set<std::array<std::uint32_t, 2>> edges;
  for (const Tet& c : tets)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) edges.insert({std::min(c[i], c[j]), std::max(c[i], c[j])});
  for (const auto& e : edges)
    for (int dir = 0; dir < 2; ++dir)
      CHECK(!P::check_half_edge_collapse(tree, from[e[dir]], from[e[1 - dir]]).allowed());
  const auto res = P::simplify(P::make_input(pts, tets), params::max_edge_length(100.0));
  CHECK_EQUAL(res.mesh.tetrahedra.size(), tets.size());
}

// The smallest dihedral angle of a mesh, in degrees, by the definition: the angle between the
// two faces at each edge, from their normals (independent of tetrahedron_quality.h).
template <class Tets>
double min_dihedral(const std::vector<Point>& pts, const Tets& tets) {
  double best = 180;
  for (const auto& c : tets)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        int k = 0;
        while (k == i || k == j) ++k;
        int l = 6 - i - j - k;
        const Kernel::Vector_3 e = pts[c[j]] - pts[c[i]];
        const Kernel::Vector_3 n1 = CGAL::cross_product(e, pts[c[k]] - pts[c[i]]);
        const Kernel::Vector_3 n2 = CGAL::cross_product(e, pts[c[l]] - pts[c[i]]);
        const double cosine = n1 * n2 / std::sqrt(n1.squared_length() * n2.squared_length());
        best = std::min(best, std::acos(std::max(-1.0, std::min(1.0, cosine))) * 180 / CGAL_PI);
      }
  return best;
}

// ---------------------------------------------------------------------------------------------
// Crafted cases: one constraint alone refuses a collapse
// ---------------------------------------------------------------------------------------------

// The Kuhn triangulation of [0, n]^3 (six tetrahedra per unit cube around its (1, 1, 1) diagonal),
// positively oriented.  Vertex (x, y, z) has index x + (n + 1) (y + (n + 1) z).
struct Lattice {
  std::vector<Point> points;
  std::vector<Tet> tets;
  int n;
  std::uint32_t index(int x, int y, int z) const { return std::uint32_t(x + (n + 1) * (y + (n + 1) * z)); }
};

Lattice kuhn_lattice(int n) {
  Lattice l;
  l.n = n;
  for (int z = 0; z <= n; ++z)
    for (int y = 0; y <= n; ++y)
      for (int x = 0; x <= n; ++x) l.points.emplace_back(x, y, z);
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        for (const auto& p : perms) {
          int c[3] = {x, y, z};
          Tet t;
          t[0] = l.index(c[0], c[1], c[2]);
          for (int k = 0; k < 3; ++k) {
            ++c[p[k]];
            t[k + 1] = l.index(c[0], c[1], c[2]);
          }
          if (CGAL::orientation(l.points[t[0]], l.points[t[1]], l.points[t[2]], l.points[t[3]]) ==
              CGAL::NEGATIVE)
            std::swap(t[2], t[3]);
          l.tets.push_back(t);
        }
  return l;
}

// Only the quality floor: the interior vertex r = (2, 2, 2) is removed into its neighbour k (kept
// by the user's vertex map), k being moved so that (r, k) is the only edge shorter than the
// length bound and the collapse creates a sliver: positive (the exact orientation accepts it),
// the link condition holds (both inside), no surface moves.  Every other vertex is kept by the
// user's vertex map.  The position of k is searched
// (deterministic pseudo-random points near (2.6, 2, 2)) by brute force on the star of r: every
// tetrahedron of the input positive, every tetrahedron the collapse creates positive, one of them
// under 5 degrees.  Without the floor the collapse is done; with it, it is refused for quality alone.
void test_only_quality_floor_refuses() {
  bool found = false;
  unsigned seed = 12345;
  auto uniform = [&seed]() {
    seed = seed * 1103515245u + 12345u;
    return double((seed >> 8) & 0xFFFF) / 65535.0;
  };
  for (int attempt = 0; attempt < 4000 && !found; ++attempt) {
    Lattice l = kuhn_lattice(4);
    const std::uint32_t r = l.index(2, 2, 2), k = l.index(3, 2, 2);
    l.points[k] = Point(2 + uniform(), 2 + (uniform() - 0.5), 2 + (uniform() - 0.5));
    bool ok = true;
    double worst = 180;
    for (const Tet& c : l.tets) {
      ok = ok && CGAL::orientation(l.points[c[0]], l.points[c[1]], l.points[c[2]], l.points[c[3]]) ==
                     CGAL::POSITIVE;
      const bool has_r = std::find(c.begin(), c.end(), r) != c.end();
      const bool has_k = std::find(c.begin(), c.end(), k) != c.end();
      if (!has_r || has_k) continue;
      Tet n = c;
      for (auto& v : n)
        if (v == r) v = k;
      ok = ok && CGAL::orientation(l.points[n[0]], l.points[n[1]], l.points[n[2]], l.points[n[3]]) ==
                     CGAL::POSITIVE;
      worst = std::min(worst, min_dihedral(l.points, std::vector<Tet>{n}));
    }
    if (!ok || !(worst < 4)) continue;
    // (r, k) the only edge of r under the bound (r's other edges are at least 1 long)
    const double bound = 0.999;
    if (!(CGAL::squared_distance(l.points[r], l.points[k]) < bound * bound)) continue;
    const auto input = P::make_input(l.points, l.tets);
    std::map<std::size_t, bool> keep; // every vertex but r is kept: only r can go
    for (std::size_t v = 0; v < l.points.size(); ++v) keep[v] = v != r;
    // (%CGAL's vertex_is_constrained_map returns CGAL's parameters: the package's come first)
    const auto keep_map = boost::make_assoc_property_map(keep);
    const auto done = P::simplify(input, params::max_edge_length(bound)
                                             .min_dihedral_angle(0.0)
                                             .min_radius_ratio(0.0)
                                             .max_dihedral_angle(180.0)
                                             .optimization_rounds(0)
                                             .vertex_is_constrained_map(keep_map));
    if (done.statistics.removed_tetrahedra == 0) continue; // the link condition, say: not this case
    found = true;
    std::cout << "quality floor: k at " << l.points[k] << ", a sliver of " << worst << " degrees (attempt "
              << attempt << ")" << std::endl;
    CHECK(min_dihedral(done.mesh.points, done.mesh.tetrahedra) < 5);
    CHECK(P::check_validity(done.mesh.points, done.mesh.tetrahedra).valid);
    const auto refused = P::simplify(
        input, params::max_edge_length(bound).optimization_rounds(0).vertex_is_constrained_map(keep_map));
    CHECK_EQUAL(refused.statistics.removed_tetrahedra, std::size_t(0));
    CHECK(refused.statistics.blocked.quality >= 1);
    // (the other candidates join two kept vertices: refused as features in both runs)
    CHECK_EQUAL(refused.statistics.blocked.error + refused.statistics.blocked.link +
                    refused.statistics.blocked.flip,
                std::size_t(0));
    // The radius-ratio floor alone refuses it too (the older form of the floor, the others off).
    const auto rr = P::simplify(input, params::max_edge_length(bound)
                                           .quality_measure(P::Quality_measure::RADIUS_RATIO)
                                           .quality_floor(0.1)
                                           .min_dihedral_angle(0.0)
                                           .max_dihedral_angle(180.0)
                                           .optimization_rounds(0)
                                           .vertex_is_constrained_map(keep_map));
    CHECK_EQUAL(rr.statistics.removed_tetrahedra, std::size_t(0));
    CHECK(rr.statistics.blocked.quality >= 1);
  }
  if (!found) FAIL("no position of k gives a sliver only the quality floor refuses");
}

// Only the feature constraints: the same collapse without the floor, with both ends made corners by
// the user's vertex map (input indices), is refused; and the cube's own corners and sharp edges
// survive a 50% simplification exactly (the sharp edges are straight: distance 0 both ways).
void test_only_features_refuse() {
  Lattice l = kuhn_lattice(4);
  const std::uint32_t r = l.index(2, 2, 2), k = l.index(3, 2, 2);
  l.points[k] = Point(2.98, 2, 2);
  const auto input = P::make_input(l.points, l.tets);
  std::map<std::size_t, bool> corner{{r, true}, {k, true}};
  const auto refused =
      P::simplify(input, params::max_edge_length(0.99).quality_floor(0.0).vertex_is_constrained_map(
                             boost::make_assoc_property_map(corner)));
  CHECK_EQUAL(refused.statistics.removed_tetrahedra, std::size_t(0));
  CHECK(refused.statistics.blocked.feature >= 1);
  // A user feature edge (r, k) makes both ends feature-curve vertices: the collapse along it is allowed.
  std::map<std::pair<std::size_t, std::size_t>, bool> edge{{{r, k}, true}};
  const auto along =
      P::simplify(input, params::max_edge_length(0.99).quality_floor(0.0).edge_is_constrained_map(
                             boost::make_assoc_property_map(edge)));
  CHECK(along.statistics.removed_tetrahedra > 0);

  const Lattice cube = kuhn_lattice(6);
  const auto half =
      P::simplify(P::make_input(cube.points, cube.tets), params::target_fraction(0.5).bucket_size(40));
  CHECK(half.statistics.stop == P::Simplification_stop::TARGET_REACHED);
  std::size_t corners = 0;
  for (const Point& p : half.mesh.points)
    corners += (p.x() == 0 || p.x() == 6) && (p.y() == 0 || p.y() == 6) && (p.z() == 0 || p.z() == 6);
  CHECK_EQUAL(corners, std::size_t(8));
  const auto sharp =
      P::sharp_edge_distance(cube.points, cube.tets, half.mesh.points, half.mesh.tetrahedra, 40.);
  CHECK_EQUAL(sharp.input_to_output, 0.);
  CHECK_EQUAL(sharp.output_to_input, 0.);
  CHECK(sharp.output_sharp_edges >= 12);
  const auto surface =
      P::boundary_distance(cube.points, cube.tets, half.mesh.points, half.mesh.tetrahedra, 0.);
  CHECK(surface.hausdorff() < 1e-9);
  // Without sharp edges, no floor and no bound, the corners go.
  const auto free = P::simplify(
      P::make_input(cube.points, cube.tets),
      params::target_fraction(0.5).bucket_size(40).feature_angle(180.0).quality_floor(0.0).max_boundary_error(
          std::numeric_limits<double>::infinity()));
  const auto lost = P::boundary_distance(cube.points, cube.tets, free.mesh.points, free.mesh.tetrahedra, 0.);
  std::cout << "cube without constraints: boundary distance " << lost.hausdorff() << std::endl;
  CHECK(lost.hausdorff() > 0.1);
}

// %CGAL's own constraint maps (`CGAL::parameters::vertex_is_constrained_map`,
// `edge_is_constrained_map`, which the package's `parameters` namespace now is) take effect: on the
// flat top face of a cube, the surface edge (r, k) is the only one under the length bound; without
// a map k is removed into r; with k constrained, k survives (r goes instead); with the edge (r, k)
// constrained, both survive.  Then the policies: a filter, a cost and a visitor of the user's.
struct Count_visitor : P::Simplification_visitor_base {
  std::size_t rounds = 0, collapses = 0, refused = 0;
  void on_round_started(std::size_t, std::size_t, std::size_t) { ++rounds; }
  template <class Profile>
  void on_collapse(const Profile&) {
    ++collapses;
  }
  template <class Profile>
  void on_refused(const Profile&, P::Collapse_refusal) {
    ++refused;
  }
};

void test_cgal_constraint_maps_and_policies() {
  Lattice l = kuhn_lattice(4);
  const std::uint32_t r = l.index(2, 2, 4), k = l.index(3, 2, 4);
  l.points[k] = Point(2.9, 2, 4);
  const auto input = P::make_input(l.points, l.tets);
  auto kept = [](const auto& res, std::size_t v) {
    return std::find(res.input_vertex.begin(), res.input_vertex.end(), v) != res.input_vertex.end();
  };
  const auto free = P::simplify(input, params::max_edge_length(0.95).quality_floor(0.0));
  CHECK(free.statistics.removed_tetrahedra > 0);
  CHECK(kept(free, r));
  CHECK(!kept(free, k));

  std::map<std::size_t, bool> corner{{k, true}};
  const auto vertex_map = boost::make_assoc_property_map(corner);
  // the package's name is CGAL's: same function, same tag
  static_assert(std::is_same<decltype(params::vertex_is_constrained_map(vertex_map)),
                             decltype(CGAL::parameters::vertex_is_constrained_map(vertex_map))>::value,
                "vertex_is_constrained_map is CGAL's");
  // (CGAL's parameter returns CGAL's chain: the package's parameters come first)
  const auto by_vertex = P::simplify(
      input, params::max_edge_length(0.95).quality_floor(0.0).vertex_is_constrained_map(vertex_map));
  CHECK(by_vertex.statistics.removed_tetrahedra > 0);
  CHECK(kept(by_vertex, k));
  CHECK(!kept(by_vertex, r));

  std::map<std::pair<std::size_t, std::size_t>, bool> feature{{{(std::min)(r, k), (std::max)(r, k)}, true}};
  const auto edge_map = boost::make_assoc_property_map(feature);
  static_assert(std::is_same<decltype(params::edge_is_constrained_map(edge_map)),
                             decltype(CGAL::parameters::edge_is_constrained_map(edge_map))>::value,
                "edge_is_constrained_map is CGAL's");
  const auto by_edge =
      P::simplify(input, params::max_edge_length(0.95).quality_floor(0.0).edge_is_constrained_map(edge_map));
  CHECK_EQUAL(by_edge.statistics.removed_tetrahedra, std::size_t(0));
  CHECK(kept(by_edge, r) && kept(by_edge, k));

  // A filter that refuses everything: nothing removed, every refusal counted as the filter's.
  const auto refuse_all = [](const auto&) { return P::Collapse_refusal::FILTER; };
  const auto filtered =
      P::simplify(input, params::max_edge_length(0.95).quality_floor(0.0).filter(refuse_all));
  CHECK_EQUAL(filtered.statistics.removed_tetrahedra, std::size_t(0));
  CHECK(filtered.statistics.blocked.filter >= 1);
  // A visitor (by reference) sees every collapse and refusal; a cost of the user's is used.
  Count_visitor visitor;
  std::size_t costs = 0;
  const auto cost = [&costs](const auto& e) {
    ++costs;
    return -e.quadric_error(e.coordinates(e.v0())); // (0: no quadrics without the quadric options)
  };
  const auto half = P::simplify(P::make_input(l.points, l.tets),
                                params::target_fraction(0.3).get_cost(cost).visitor(std::ref(visitor)));
  CHECK(costs > 0);
  CHECK_EQUAL(visitor.collapses, half.statistics.collapses);
  CHECK_EQUAL(visitor.rounds, half.statistics.rounds);
  CHECK(visitor.refused > 0);
}

// Only the error bound: the top-centre vertex r of the cube is raised by 0.3 (a smooth bump: its
// triangles bend by less than 40 degrees) and its neighbour k on the top face pulled towards it,
// so that (r, k) is the only edge shorter than 0.9.  Flattening the bump moves the surface by
// about 0.3: refused under a bound of 0.01, allowed without a bound (no floor in either run).
void test_only_error_bound_refuses() {
  Lattice l = kuhn_lattice(4);
  const std::uint32_t r = l.index(2, 2, 4), k = l.index(3, 2, 4);
  l.points[r] = Point(2, 2, 4.3);
  l.points[k] = Point(2.8, 2, 4);
  const auto input = P::make_input(l.points, l.tets);
  const auto refused =
      P::simplify(input, params::max_edge_length(0.9).quality_floor(0.0).max_boundary_error(0.01));
  CHECK_EQUAL(refused.statistics.removed_tetrahedra, std::size_t(0));
  CHECK(refused.statistics.blocked.error >= 1);
  CHECK_EQUAL(refused.statistics.blocked.feature + refused.statistics.blocked.quality, std::size_t(0));
  const auto done = P::simplify(input, params::max_edge_length(0.9).quality_floor(0.0).max_boundary_error(
                                           std::numeric_limits<double>::infinity()));
  CHECK(done.statistics.removed_tetrahedra > 0);
  const auto d = P::boundary_distance(l.points, l.tets, done.mesh.points, done.mesh.tetrahedra, 0.);
  CHECK(d.hausdorff() > 0.01);
  // The default bound (0.2% of the diagonal, 0.0139) refuses it too.
  const auto by_default = P::simplify(input, params::max_edge_length(0.9).quality_floor(0.0));
  CHECK_EQUAL(by_default.statistics.removed_tetrahedra, std::size_t(0));
}

// ---------------------------------------------------------------------------------------------
// Simplification of real meshes
// ---------------------------------------------------------------------------------------------

// The options of one run (given to simplify() as named parameters).
struct Run {
  double target_fraction = 0;                                       // 0: no target
  double max_edge_length = std::numeric_limits<double>::infinity(); // no bound
  std::size_t bucket_size = Octree::default_bucket_size;
  bool paper = false;       // the paper's conditions only: no sharp edges, no quality floor, no error bound
  std::size_t optimize = 2; // optimisation rounds (0: vertices never move)
};

// The three measures of the floors by their definitions, independently of tetrahedron_quality.h:
// the dihedral angles from the face normals at each edge, the radius ratio 3 r / R from the volume,
// the face areas and CGAL's circumcentre.
struct Measures {
  double min_dihedral = 180, max_dihedral = 0, min_radius_ratio = 1;
};
template <class Tets>
Measures measures(const std::vector<Point>& pts, const Tets& tets) {
  Measures m;
  for (const auto& c : tets) {
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        int k = 0;
        while (k == i || k == j) ++k;
        const int l = 6 - i - j - k;
        const Kernel::Vector_3 e = pts[c[j]] - pts[c[i]];
        const Kernel::Vector_3 n1 = CGAL::cross_product(e, pts[c[k]] - pts[c[i]]);
        const Kernel::Vector_3 n2 = CGAL::cross_product(e, pts[c[l]] - pts[c[i]]);
        const double cosine = n1 * n2 / std::sqrt(n1.squared_length() * n2.squared_length());
        const double a = std::acos(std::max(-1.0, std::min(1.0, cosine))) * 180 / CGAL_PI;
        m.min_dihedral = std::min(m.min_dihedral, a);
        m.max_dihedral = std::max(m.max_dihedral, a);
      }
    const Point &p = pts[c[0]], &q = pts[c[1]], &r = pts[c[2]], &s = pts[c[3]];
    const double volume = std::abs(CGAL::volume(p, q, r, s));
    const double area = std::sqrt(CGAL::squared_area(q, r, s)) + std::sqrt(CGAL::squared_area(p, r, s)) +
                        std::sqrt(CGAL::squared_area(p, q, s)) + std::sqrt(CGAL::squared_area(p, q, r));
    const double inradius = 3 * volume / area;
    // the circumradius from the edge lengths, R = sqrt((aA+bB+cC)(aA+bB-cC)(aA-bB+cC)(-aA+bB+cC)) / (24 V)
    // with opposite edges a, A...: no construction that asserts on a tetrahedron flat in doubles
    const auto len = [](const Point& x, const Point& y) { return std::sqrt(CGAL::squared_distance(x, y)); };
    const double aA = len(p, q) * len(r, s), bB = len(p, r) * len(q, s), cC = len(p, s) * len(q, r);
    const double product = (aA + bB + cC) * (aA + bB - cC) * (aA - bB + cC) * (-aA + bB + cC);
    const double ratio = volume > 0 ? 3 * inradius / (std::sqrt(std::max(product, 0.)) / (24 * volume)) : 0.;
    m.min_radius_ratio = std::min(m.min_radius_ratio, ratio);
  }
  return m;
}

// Runs one simplification and checks everything that must hold of its output.
P::Simplification_statistics check_run(const Mesh& mesh, const Brute& in, const P::Validity_result& vin,
                                       const Run& o, const std::string& name) {
  const auto res =
      P::simplify(mesh, params::target_fraction(o.target_fraction)
                            .max_edge_length(o.max_edge_length)
                            .bucket_size(o.bucket_size)
                            .feature_angle(o.paper ? 180. : 40.)
                            .min_dihedral_angle(o.paper ? 0. : 5.)
                            .min_radius_ratio(o.paper ? 0. : 0.1)
                            .max_dihedral_angle(o.paper ? 180. : 165.)
                            .optimization_rounds(o.optimize)
                            .max_boundary_error(o.paper ? std::numeric_limits<double>::infinity() : -1.));
  const auto& s = res.statistics;
  std::cout << "  " << name << " target " << o.target_fraction << " k_v "
            << (o.bucket_size == Octree::infinite_bucket_size ? std::string("inf")
                                                              : std::to_string(o.bucket_size))
            << ": removed " << s.removed_tetrahedra << " / " << s.input_tetrahedra << " in " << s.rounds
            << " rounds, max queue " << s.max_queue_size << ", blocked " << s.blocked.different_leaves
            << " leaves, " << s.blocked.boundary << " boundary, " << s.blocked.flip << " flip, "
            << s.blocked.link << " link, " << s.seconds << " s" << std::endl;
  CHECK_EQUAL(s.input_tetrahedra, mesh.tetrahedra.size());
  CHECK_EQUAL(s.output_tetrahedra, res.mesh.tetrahedra.size());
  // Collapses, flips and splits account for every tetrahedron.
  CHECK_EQUAL(s.input_tetrahedra + s.optimization.tetrahedra_added,
              s.output_tetrahedra + s.removed_tetrahedra + s.optimization.tetrahedra_deleted);
  if (o.optimize == 0)
    CHECK_EQUAL(s.optimization.tetrahedra_added + s.optimization.vertex_moves, std::size_t(0));
  CHECK_EQUAL(s.optimization.rounds, o.optimize);
  CHECK_EQUAL(s.optimization.splits, std::size_t(0));
  CHECK_EQUAL(res.input_vertex.size(), res.mesh.points.size());
  CHECK_EQUAL(s.removed_per_round.size(), s.rounds);
  std::size_t per_round = 0;
  for (std::size_t n : s.removed_per_round) per_round += n;
  CHECK_EQUAL(per_round, s.removed_tetrahedra);

  // Validity and topology.
  const auto v = P::check_validity(res.mesh.points, res.mesh.tetrahedra);
  CHECK_EQUAL(v.inverted, std::size_t(0));
  CHECK_EQUAL(v.negative, std::size_t(0)); // the output is positively oriented
  CHECK_EQUAL(v.degenerate, std::size_t(0));
  CHECK_EQUAL(v.nonmanifold_triangles, vin.nonmanifold_triangles);
  CHECK(v.nonmanifold_vertices <= vin.nonmanifold_vertices);
  if (vin.valid) CHECK(v.valid);
  CHECK_EQUAL(v.euler_characteristic, vin.euler_characteristic);
  CHECK_EQUAL(v.boundary_components, vin.boundary_components);
  // Quality floors (5 and 165 degrees, radius ratio 0.1): by each measure, no tetrahedron is worse
  // than the input's worst, unless within the floor.
  const Measures in_q = measures(mesh.points, mesh.tetrahedra);
  const Measures out_q = measures(res.mesh.points, res.mesh.tetrahedra);
  if (!o.paper && !(out_q.min_dihedral >= std::min(in_q.min_dihedral, 5.0) - 1e-9))
    FAIL(name << ": smallest dihedral angle " << out_q.min_dihedral << " < " << in_q.min_dihedral);
  if (!o.paper && !(out_q.max_dihedral <= std::max(in_q.max_dihedral, 165.0) + 1e-9))
    FAIL(name << ": largest dihedral angle " << out_q.max_dihedral << " > " << in_q.max_dihedral);
  if (!o.paper && !(out_q.min_radius_ratio >= std::min(in_q.min_radius_ratio, 0.1) - 1e-9))
    FAIL(name << ": smallest radius ratio " << out_q.min_radius_ratio << " < " << in_q.min_radius_ratio);
  // Error bound (0.2% of the diagonal by default), measured independently both ways (sampled).
  if (!o.paper) {
    const auto d =
        P::boundary_distance(mesh.points, mesh.tetrahedra, res.mesh.points, res.mesh.tetrahedra, 0.);
    if (!(d.hausdorff() <= s.max_boundary_error))
      FAIL(name << ": boundary distance " << d.input_to_output << " / " << d.output_to_input
                << " over the bound " << s.max_boundary_error);
  }
  if (o.target_fraction > 0 && s.stop != P::Simplification_stop::TARGET_REACHED)
    CHECK(s.stop == P::Simplification_stop::BLOCKED);

  // Vertices never move without optimisation; boundary vertices of the output were boundary
  // vertices of the input.
  const Brute out = brute_force(res.mesh.points, res.mesh.tetrahedra);
  CHECK_EQUAL(out.euler, in.euler);
  CHECK_EQUAL(out.boundary_components, in.boundary_components);
  std::size_t moved = 0, off_boundary = 0;
  for (std::size_t i = 0; i < res.mesh.points.size(); ++i) {
    const std::size_t o_i = res.input_vertex[i];
    moved += !(res.mesh.points[i] == mesh.points[o_i]);
    if (out.boundary_vertices.count(static_cast<std::uint32_t>(i)) && !in.boundary_vertices.count(o_i))
      ++off_boundary;
  }
  if (o.optimize == 0) CHECK_EQUAL(moved, std::size_t(0));
  CHECK(moved <= s.optimization.vertex_moves);
  CHECK_EQUAL(off_boundary, std::size_t(0));
  // The scalar field follows its vertex.
  CHECK_EQUAL(res.mesh.point_data.size(), mesh.point_data.size());
  for (std::size_t k = 0; k < std::min(res.mesh.point_data.size(), mesh.point_data.size()); ++k)
    for (std::size_t i = 0; i < res.mesh.points.size(); ++i)
      if (res.mesh.point_data[k].values[i] != mesh.point_data[k].values[res.input_vertex[i]]) {
        FAIL(name << ": point data " << k << " not carried at vertex " << i);
        break;
      }
  return s;
}

// ---------------------------------------------------------------------------------------------
// Flips, smoothing and remeshing
// ---------------------------------------------------------------------------------------------

// The one-number score of the optimisation (the worst of the three measures scaled to [0, 1]),
// from the independent measures above.
template <class Tets>
double worst_score(const std::vector<Point>& pts, const Tets& tets) {
  double worst = 1;
  for (const auto& c : tets) {
    const Measures m = measures(pts, std::vector<Tet>{Tet{{c[0], c[1], c[2], c[3]}}});
    worst =
        std::min({worst, m.min_dihedral / 70.5288, (180 - m.max_dihedral) / 109.4712, m.min_radius_ratio});
  }
  return worst;
}

// Every tetrahedron positive (exact), every triangle in one or two of them.
template <class Tets>
bool conforming_and_positive(const std::vector<Point>& pts, const Tets& tets) {
  std::vector<Tet> t(tets.begin(), tets.end());
  const Brute b = brute_force(pts, t);
  return b.negative == 0 && b.flat == 0 && b.nonmanifold_triangles == 0;
}

// The bipyramid over the triangle (a, b, c) with apexes d above and e below, as two tetrahedra
// (`three` false) or as three around the edge (d, e), positively oriented.
Mesh bipyramid(double h, bool three) {
  Mesh m;
  m.points = {Point(0, 0, 0), Point(1, 0, 0), Point(0.45, 0.9, 0), Point(0.5, 0.3, h), Point(0.46, 0.33, -h)};
  auto add = [&](std::uint32_t p, std::uint32_t q, std::uint32_t r, std::uint32_t s) {
    Tet t{{p, q, r, s}};
    if (CGAL::orientation(m.points[p], m.points[q], m.points[r], m.points[s]) == CGAL::NEGATIVE)
      std::swap(t[2], t[3]);
    m.tetrahedra.push_back(t);
  };
  if (three) {
    add(3, 4, 0, 1);
    add(3, 4, 1, 2);
    add(3, 4, 2, 0);
  } else {
    add(0, 1, 2, 3);
    add(0, 1, 2, 4);
  }
  return m;
}

// Optimisation only: no collapse (every edge longer than the bound), no surface move (no bound on
// the surface, so no input surface to stay on), floors off.
auto optimize_only(const Mesh& m, std::size_t rounds = 1) {
  return P::simplify(m, params::max_edge_length(1e-9)
                            .optimization_rounds(rounds)
                            .min_dihedral_angle(0.)
                            .min_radius_ratio(0.)
                            .max_dihedral_angle(180.)
                            .max_boundary_error(std::numeric_limits<double>::infinity())
                            .bucket_size(Octree::infinite_bucket_size));
}

// 2-3 and 3-2 on bipyramids of several heights: the flip is made exactly when the worst score of
// the other configuration (brute force) is better and the worst is bad (under 0.35).
void test_flips_2_3_and_3_2() {
  std::size_t flips_23 = 0, flips_32 = 0;
  for (double h : {0.05, 0.1, 0.2, 0.4, 0.7, 1.0, 1.5, 2.5, 4.0}) {
    const Mesh two = bipyramid(h, false), three = bipyramid(h, true);
    CHECK(conforming_and_positive(two.points, two.tetrahedra));
    CHECK(conforming_and_positive(three.points, three.tetrahedra));
    const double s2 = worst_score(two.points, two.tetrahedra),
                 s3 = worst_score(three.points, three.tetrahedra);
    if (std::abs(s2 - s3) < 1e-6) continue; // a tie: either is right
    for (int from = 2; from <= 3; ++from) {
      const Mesh& in = from == 2 ? two : three;
      const double s_in = from == 2 ? s2 : s3, s_other = from == 2 ? s3 : s2;
      const auto res = optimize_only(in);
      const std::size_t expected = (s_in < 0.35 && s_other > s_in) ? 5 - from : from;
      if (res.mesh.tetrahedra.size() != expected)
        FAIL("bipyramid h = " << h << " from " << from << " tetrahedra (worst score " << s_in << ", other "
                              << s_other << "): " << res.mesh.tetrahedra.size() << " tetrahedra, expected "
                              << expected);
      CHECK(conforming_and_positive(res.mesh.points, res.mesh.tetrahedra));
      CHECK(worst_score(res.mesh.points, res.mesh.tetrahedra) >= s_in - 1e-12);
      CHECK_EQUAL(res.statistics.optimization.flips_2_3, std::size_t(from == 2 && expected == 3));
      CHECK_EQUAL(res.statistics.optimization.flips_3_2, std::size_t(from == 3 && expected == 2));
      flips_23 += res.statistics.optimization.flips_2_3;
      flips_32 += res.statistics.optimization.flips_3_2;
      CHECK_EQUAL(res.statistics.collapses, std::size_t(0));
    }
  }
  std::cout << "bipyramids: " << flips_23 << " flips 2-3, " << flips_32 << " flips 3-2" << std::endl;
  CHECK(flips_23 >= 1);
  CHECK(flips_32 >= 1);
}

// The best worst score over every triangulation of the polygon ring[i..j] (brute force, for the
// removal of the edge (a, b) whose ring it is).
double best_triangulation(const std::vector<Point>& pts, const std::vector<std::uint32_t>& ring,
                          std::size_t i, std::size_t j, std::uint32_t a, std::uint32_t b) {
  if (j - i < 2) return 1;
  double best = -1;
  for (std::size_t k = i + 1; k < j; ++k) {
    std::vector<Tet> cells{Tet{{ring[i], ring[k], ring[j], b}}, Tet{{ring[i], ring[j], ring[k], a}}};
    bool positive = true;
    for (const Tet& c : cells)
      positive = positive && CGAL::orientation(pts[c[0]], pts[c[1]], pts[c[2]], pts[c[3]]) == CGAL::POSITIVE;
    if (!positive) continue;
    best = std::max(best, std::min({worst_score(pts, cells), best_triangulation(pts, ring, i, k, a, b),
                                    best_triangulation(pts, ring, k, j, a, b)}));
  }
  return best;
}

// Edge removal: an edge (a, b) in n = 3..7 tetrahedra around it, a long vertical edge through a
// ring of points on a perturbed circle (the tetrahedra around it needles).  After one round, the worst
// score is at least that of the best triangulation of the ring (all of them enumerated), when that
// one is better, and the edge is gone.
void test_edge_removal() {
  for (std::size_t n = 3; n <= 7; ++n) {
    Mesh m;
    m.points.push_back(Point(0.02, -0.01, -2.5)); // a
    m.points.push_back(Point(-0.01, 0.03, 2.6));  // b
    std::vector<std::uint32_t> ring;
    for (std::size_t i = 0; i < n; ++i) {
      const double angle = 2 * CGAL_PI * (double(i) + 0.13 * double(i % 3)) / double(n);
      const double radius = 1 + 0.15 * double((i * 7) % 5) / 4;
      m.points.push_back(Point(radius * std::cos(angle), radius * std::sin(angle), 0.05 * double(i % 2)));
      ring.push_back(std::uint32_t(i + 2));
    }
    for (std::size_t i = 0; i < n; ++i) {
      Tet t{{0, 1, ring[i], ring[(i + 1) % n]}};
      CHECK(CGAL::orientation(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]) ==
            CGAL::POSITIVE);
      m.tetrahedra.push_back(t);
    }
    const double before = worst_score(m.points, m.tetrahedra);
    const double best = best_triangulation(m.points, ring, 0, n - 1, 0, 1);
    const auto res = optimize_only(m, 2);
    const double after = worst_score(res.mesh.points, res.mesh.tetrahedra);
    std::cout << "edge in " << n << " tetrahedra: worst score " << before << ", best triangulation " << best
              << ", after " << after << " (" << res.mesh.tetrahedra.size() << " tetrahedra)" << std::endl;
    CHECK(conforming_and_positive(res.mesh.points, res.mesh.tetrahedra));
    CHECK(after >= before - 1e-12);
    CHECK(before < 0.35 && best > before + 1e-6); // (this ring is made so: an edge removal helps)
    {
      CHECK(after >= best - 1e-9);
      // a and b in the output's numbering (the octree's order, not the input's)
      std::uint32_t a = 0, b = 0;
      for (std::size_t v = 0; v < res.input_vertex.size(); ++v) {
        if (res.input_vertex[v] == 0) a = std::uint32_t(v);
        if (res.input_vertex[v] == 1) b = std::uint32_t(v);
      }
      CHECK(res.mesh.points[a] == m.points[0] && res.mesh.points[b] == m.points[1]);
      bool edge_left = false;
      for (const auto& c : res.mesh.tetrahedra)
        edge_left = edge_left || (std::count(c.begin(), c.end(), a) && std::count(c.begin(), c.end(), b));
      CHECK(!edge_left);
    }
    const auto& o = res.statistics.optimization;
    CHECK_EQUAL(o.tetrahedra_added + n, res.mesh.tetrahedra.size() + o.tetrahedra_deleted);
  }
}

// Kuhn lattice of [0, n]^3 with labels 1 (x < n / 2) and 2.
Mesh labelled_lattice(int n) {
  const Lattice l = kuhn_lattice(n);
  Mesh m;
  m.points = l.points;
  m.tetrahedra.assign(l.tets.begin(), l.tets.end());
  for (const Tet& c : l.tets) {
    double x = 0;
    for (auto v : c) x += l.points[v].x() / 4;
    m.tetrahedron_labels.push_back(x < n / 2.0 ? 1 : 2);
  }
  return m;
}

// The share of the edges of a mesh within [0.8 h, 1.33 h] (h by the mean of the ends).
template <class Tets, class H>
double share_in_range(const std::vector<Point>& pts, const Tets& tets, H h) {
  std::set<std::array<std::uint32_t, 2>> edges;
  for (const auto& c : tets)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        edges.insert({std::min<std::uint32_t>(c[i], c[j]), std::max<std::uint32_t>(c[i], c[j])});
  std::size_t in = 0;
  for (const auto& e : edges) {
    const double target = 0.5 * (h(pts[e[0]]) + h(pts[e[1]]));
    const double l = std::sqrt(CGAL::squared_distance(pts[e[0]], pts[e[1]]));
    in += l >= 0.8 * target && l <= 4. / 3 * target;
  }
  return double(in) / double(edges.size());
}

// Remeshing the labelled lattice (a unit box of two labels, flat faces and a flat interface):
// valid, the same topology, both labels' volumes exactly kept (every tetrahedron's centroid on the
// side of its label), the eight corners kept, the floors, more edges near the target, and a sizing
// field that makes edges shorter where it is smaller.
void test_remesh_lattice() {
  const int n = 6;
  const Mesh in = labelled_lattice(n);
  const auto vin = P::check_validity(in.points, in.tetrahedra);
  const Measures qin = measures(in.points, in.tetrahedra);
  for (double h : {0.6, 2.0}) {
    const auto res = P::remesh(in, h);
    const auto& m = res.mesh;
    const auto& s = res.statistics;
    std::cout << "lattice " << in.tetrahedra.size() << " tetrahedra, h = " << h << ": " << m.tetrahedra.size()
              << " tetrahedra, " << s.optimization.splits << " splits, " << s.collapses << " collapses, "
              << s.optimization.flips_2_3 + s.optimization.flips_3_2 + s.optimization.flips_4_4 +
                     s.optimization.edge_removals
              << " flips, " << s.optimization.vertex_moves << " moves, " << s.rounds << " rounds, "
              << s.seconds << " s" << std::endl;
    CHECK(conforming_and_positive(m.points, m.tetrahedra));
    const auto v = P::check_validity(m.points, m.tetrahedra);
    CHECK(v.valid);
    CHECK_EQUAL(v.euler_characteristic, vin.euler_characteristic);
    CHECK_EQUAL(v.boundary_components, vin.boundary_components);
    CHECK_EQUAL(s.input_tetrahedra + s.optimization.tetrahedra_added,
                s.output_tetrahedra + s.removed_tetrahedra + s.optimization.tetrahedra_deleted);
    double volume[3] = {0, 0, 0};
    std::size_t wrong_side = 0;
    for (std::size_t t = 0; t < m.tetrahedra.size(); ++t) {
      const auto& c = m.tetrahedra[t];
      const int label = m.tetrahedron_labels[t];
      CHECK(label == 1 || label == 2);
      volume[label] += CGAL::volume(m.points[c[0]], m.points[c[1]], m.points[c[2]], m.points[c[3]]);
      const double x =
          (m.points[c[0]].x() + m.points[c[1]].x() + m.points[c[2]].x() + m.points[c[3]].x()) / 4;
      wrong_side += (x < n / 2.0) != (label == 1);
    }
    CHECK_EQUAL(wrong_side, std::size_t(0));
    CHECK_NEAR(volume[1], n * n * n / 2.0, 1e-9 * n * n * n);
    CHECK_NEAR(volume[2], n * n * n / 2.0, 1e-9 * n * n * n);
    std::set<std::array<double, 3>> points;
    for (const Point& p : m.points) points.insert({p.x(), p.y(), p.z()});
    for (int c = 0; c < 8; ++c)
      CHECK(points.count({double(n * (c & 1)), double(n * ((c >> 1) & 1)), double(n * ((c >> 2) & 1))}) == 1);
    const Measures q = measures(m.points, m.tetrahedra);
    CHECK(q.min_dihedral >= std::min(qin.min_dihedral, 5.0) - 1e-9);
    CHECK(q.max_dihedral <= std::max(qin.max_dihedral, 165.0) + 1e-9);
    CHECK(q.min_radius_ratio >= std::min(qin.min_radius_ratio, 0.1) - 1e-9);
    const auto uniform = [h](const Point&) { return h; };
    const double share_in = share_in_range(in.points, in.tetrahedra, uniform),
                 share_out = share_in_range(m.points, m.tetrahedra, uniform);
    std::cout << "  edges within [0.8 h, 1.33 h]: " << share_in << " -> " << share_out << std::endl;
    CHECK(share_out > share_in + 0.2);
    CHECK(h < 1 ? m.tetrahedra.size() > 2 * in.tetrahedra.size()
                : m.tetrahedra.size() < in.tetrahedra.size());
    // Labels and cell data follow their tetrahedra (input_tetrahedron), point data its vertices.
    for (std::size_t t = 0; t < m.tetrahedra.size(); ++t)
      CHECK_EQUAL(m.tetrahedron_labels[t], in.tetrahedron_labels[res.input_tetrahedron[t]]);
  }
  // A sizing field: 0.5 at x = 0 to 2 at x = n.
  std::vector<double> sizes;
  for (const Point& p : in.points) sizes.push_back(0.5 + 1.5 * p.x() / n);
  const auto res = P::remesh(in, CGAL::make_property_map(sizes));
  CHECK(P::check_validity(res.mesh.points, res.mesh.tetrahedra).valid);
  double sum[2] = {0, 0};
  std::size_t count[2] = {0, 0};
  for (const auto& c : res.mesh.tetrahedra)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const double x = (res.mesh.points[c[i]].x() + res.mesh.points[c[j]].x()) / 2;
        if (x > n / 3.0 && x < 2 * n / 3.0) continue;
        const int side = x >= 2 * n / 3.0;
        sum[side] += std::sqrt(CGAL::squared_distance(res.mesh.points[c[i]], res.mesh.points[c[j]]));
        ++count[side];
      }
  const double small = sum[0] / double(count[0]), large = sum[1] / double(count[1]);
  std::cout << "  sizing field 0.5..2: mean edge length " << small << " (x < n/3), " << large << " (x > 2n/3)"
            << std::endl;
  CHECK(large > 1.8 * small);
  const auto field = [&](const Point& p) { return 0.5 + 1.5 * p.x() / n; };
  const double field_in = share_in_range(in.points, in.tetrahedra, field),
               field_out = share_in_range(res.mesh.points, res.mesh.tetrahedra, field);
  std::cout << "  edges within [0.8 h, 1.33 h] of the sizing field: " << field_in << " -> " << field_out
            << std::endl;
  // (measured 0.44 -> 0.638 at the automatic k_v = 64, 0.642 at 50, 0.660 at 20, 0.655 at infinity:
  // the share moves by 0.02 with the leaves; more than 0.18 better, whatever the leaves)
  CHECK(field_out > field_in + 0.18);
  // Bad targets.
  CHECK_THROWS(std::invalid_argument, "positive", P::remesh(in, -1.0));
  CHECK_THROWS(std::invalid_argument, "positive", P::remesh(in, std::numeric_limits<double>::quiet_NaN()));
  sizes[7] = 0;
  CHECK_THROWS(std::invalid_argument, "vertex 7", P::remesh(in, CGAL::make_property_map(sizes)));
}

// Remeshing a curved mesh: valid, same topology, within the error bound both ways, volume within
// the bound times the area, floors kept, edges nearer the target.
void test_remesh_curved(const std::string& file) {
  Mesh in;
  P::IO::read_tetrahedral_mesh(file, in);
  double mean = 0;
  for (const auto& c : in.tetrahedra)
    mean += std::sqrt(CGAL::squared_distance(in.points[c[0]], in.points[c[1]]));
  mean /= double(in.tetrahedra.size());
  const auto vin = P::check_validity(in.points, in.tetrahedra);
  const Measures qin = measures(in.points, in.tetrahedra);
  for (double h : {0.7 * mean, 1.6 * mean}) {
    const auto res = P::remesh(in, h, params::number_of_iterations(3));
    const auto& m = res.mesh;
    std::cout << file << " h = " << h << ": " << in.tetrahedra.size() << " -> " << m.tetrahedra.size()
              << " tetrahedra, " << res.statistics.seconds << " s" << std::endl;
    CHECK(conforming_and_positive(m.points, m.tetrahedra));
    const auto v = P::check_validity(m.points, m.tetrahedra);
    CHECK(v.valid);
    CHECK_EQUAL(v.euler_characteristic, vin.euler_characteristic);
    CHECK_EQUAL(v.boundary_components, vin.boundary_components);
    const auto d = P::boundary_distance(in.points, in.tetrahedra, m.points, m.tetrahedra, 0.);
    if (!(d.hausdorff() <= res.statistics.max_boundary_error))
      FAIL(file << ": boundary distance " << d.hausdorff() << " over the bound "
                << res.statistics.max_boundary_error);
    const Measures q = measures(m.points, m.tetrahedra);
    CHECK(q.min_dihedral >= std::min(qin.min_dihedral, 5.0) - 1e-9);
    CHECK(q.max_dihedral <= std::max(qin.max_dihedral, 165.0) + 1e-9);
    CHECK(q.min_radius_ratio >= std::min(qin.min_radius_ratio, 0.1) - 1e-9);
    const auto uniform = [h](const Point&) { return h; };
    CHECK(share_in_range(m.points, m.tetrahedra, uniform) >
          share_in_range(in.points, in.tetrahedra, uniform));
    CHECK_EQUAL(m.point_data.size(), in.point_data.size());
  }
}

void test_mesh(const std::string& file, bool targets) {
  Mesh mesh;
  P::IO::read_tetrahedral_mesh(file, mesh);
  // A scalar field to carry along (keep the mesh's own when it has one).
  if (mesh.point_data.empty()) {
    P::Point_data_array a{"x_plus_2y", {}};
    for (const Point& p : mesh.points) a.values.push_back(p.x() + 2 * p.y());
    mesh.point_data.push_back(a);
  }
  std::cout << file << ": " << mesh.points.size() << " vertices, " << mesh.tetrahedra.size() << " tetrahedra"
            << std::endl;
  std::vector<Tet> tets(mesh.tetrahedra.begin(), mesh.tetrahedra.end());
  const Brute in = brute_force(mesh.points, tets);
  const auto vin = P::check_validity(mesh.points, mesh.tetrahedra);
  CHECK_EQUAL(vin.euler_characteristic, in.euler);
  CHECK_EQUAL(vin.boundary_components, in.boundary_components);
  CHECK_EQUAL(vin.nonmanifold_triangles, in.nonmanifold_triangles);
  CHECK_EQUAL(vin.inverted, std::min(in.positive, in.negative));
  CHECK_EQUAL(vin.degenerate, in.flat);

  const std::size_t kvs[] = {20, Octree::infinite_bucket_size};
  const double fractions_all[] = {0.25, 0.5};
  const double fractions_one[] = {0.5};
  const double* fb = targets ? fractions_all : fractions_one;
  const std::size_t nf = targets ? 2 : 1;
  for (std::size_t i = 0; i < nf; ++i) {
    for (std::size_t kv : kvs) {
      Run o;
      o.target_fraction = fb[i];
      o.bucket_size = kv;
      const auto s = check_run(mesh, in, vin, o, file);
      if (targets) {
        CHECK(vin.valid); // the generated meshes given with `targets` are valid
        // Both the global and the local algorithm reach the target on a mesh of >= 10K tetrahedra.
        const std::size_t target =
            static_cast<std::size_t>(std::ceil(fb[i] * double(mesh.tetrahedra.size())));
        CHECK(s.removed_tetrahedra + s.optimization.tetrahedra_deleted >=
              target + s.optimization.tetrahedra_added);
        if (kv == Octree::infinite_bucket_size) CHECK_EQUAL(s.blocked.different_leaves, std::size_t(0));
      }
    }
  }
  // A length threshold only (0.8 times the mean length of the first edges): something is removed,
  // and the output passes every check of check_run.
  Run o;
  double sum = 0;
  std::size_t n = 0;
  for (const auto& c : mesh.tetrahedra) {
    sum += std::sqrt(CGAL::squared_distance(mesh.points[c[0]], mesh.points[c[1]]));
    ++n;
  }
  o.max_edge_length = 0.8 * sum / double(n);
  o.bucket_size = 50;
  const auto s = check_run(mesh, in, vin, o, file + " (length only)");
  if (s.removed_tetrahedra == 0) CHECK(s.stop == P::Simplification_stop::NOTHING_LEFT);
  // With the paper's conditions only, something is removed (and nothing moves).
  o.paper = true;
  o.optimize = 0;
  CHECK(check_run(mesh, in, vin, o, file + " (length only, paper's conditions)").removed_tetrahedra > 0);
}

} // namespace

int main(int argc, char** argv) {
  const prstar_test::Data_folders data(argc, argv);
  test_validity_hand_made();
  test_validity_problems();
  test_exact_predicate_rejects();
  test_link_condition_rejects_single_tetrahedron();
  test_link_condition_rejects_ring();
  test_only_quality_floor_refuses();
  test_only_features_refuse();
  test_only_error_bound_refuses();
  test_cgal_constraint_maps_and_policies();
  test_flips_2_3_and_3_2();
  test_edge_removal();
  test_remesh_lattice();
  // (one curved mesh: the torus takes as long again, under the sanitizers too)
  if (const auto file = data.generated_file("sphere.mesh")) test_remesh_curved(*file);

  // (under the sanitizers, PRSTAR_SANITIZER_LIGHT, the sphere only: the torus is the same kind of
  // Mesh_3 mesh, and this test is the sanitizer run's longest)
  const bool light = std::getenv("PRSTAR_SANITIZER_LIGHT") != nullptr;
  for (const char* name : {"sphere.mesh", "torus.mesh"})
    if (const auto file = data.generated_file(name); file && !(light && std::string(name) == "torus.mesh"))
      test_mesh(*file, true);
  // (under the sanitizers, the TetGen sphere is left to the normal build: 40% of this test alone
  // under ASan, 70 s of 173, and cube_tetgen.vtu is a TetGen mesh too)
  for (const char* name : {"cube.mesh", "sphere_tetgen.mesh", "cube_tetgen.vtu"})
    if (const auto file = data.generated_file(name);
        file && !(light && std::string(name) == "sphere_tetgen.mesh"))
      test_mesh(*file, false);
  // Under the sanitizers (scripts/test_sanitizers.sh sets PRSTAR_SANITIZER_LIGHT) the real meshes
  // are left to the normal build: they are 40% of this test, the sanitizer run's longest.
  if (light)
    std::cout << "PRSTAR_SANITIZER_LIGHT: the torus, the TetGen sphere and the shared real meshes are skipped"
              << std::endl;
  else if (data.report_shared())
    for (const char* name : {"armadillo_sofa.vtu", "bunny_sofa.vtu", "skull_14k.off", "spx_zsweep.off",
                             "part1.1.ele", "t13_data.1.ele"})
      if (const auto file = data.shared_file(name)) test_mesh(*file, false);
  return prstar_test::summary("test_simplification");
}
