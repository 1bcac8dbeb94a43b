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
    const auto done = P::simplify(
        input, params::max_edge_length(bound).quality_floor(0.0).vertex_is_constrained_map(keep_map));
    if (done.statistics.removed_tetrahedra == 0) continue; // the link condition, say: not this case
    found = true;
    std::cout << "quality floor: k at " << l.points[k] << ", a sliver of " << worst << " degrees (attempt "
              << attempt << ")" << std::endl;
    CHECK(min_dihedral(done.mesh.points, done.mesh.tetrahedra) < 5);
    CHECK(P::check_validity(done.mesh.points, done.mesh.tetrahedra).valid);
    const auto refused =
        P::simplify(input, params::max_edge_length(bound).vertex_is_constrained_map(keep_map));
    CHECK_EQUAL(refused.statistics.removed_tetrahedra, std::size_t(0));
    CHECK(refused.statistics.blocked.quality >= 1);
    // (the other candidates join two kept vertices: refused as features in both runs)
    CHECK_EQUAL(refused.statistics.blocked.error + refused.statistics.blocked.link +
                    refused.statistics.blocked.flip,
                std::size_t(0));
    // The radius-ratio floor refuses it too.
    const auto rr = P::simplify(input, params::max_edge_length(bound)
                                           .quality_measure(P::Quality_measure::RADIUS_RATIO)
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
  bool paper = false; // the paper's conditions only: no sharp edges, no quality floor, no error bound
};

// Runs one simplification and checks everything that must hold of its output.
P::Simplification_statistics check_run(const Mesh& mesh, const Brute& in, const P::Validity_result& vin,
                                       const Run& o, const std::string& name) {
  const auto res =
      P::simplify(mesh, params::target_fraction(o.target_fraction)
                            .max_edge_length(o.max_edge_length)
                            .bucket_size(o.bucket_size)
                            .feature_angle(o.paper ? 180. : 40.)
                            .quality_floor(o.paper ? 0. : 5.)
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
  CHECK_EQUAL(s.input_tetrahedra - s.output_tetrahedra, s.removed_tetrahedra);
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
  // Quality floor (5 degrees by default): no tetrahedron is worse than the input's worst, unless
  // above the floor.
  const double min_in = min_dihedral(mesh.points, mesh.tetrahedra);
  const double min_out = min_dihedral(res.mesh.points, res.mesh.tetrahedra);
  if (!o.paper && !(min_out >= std::min(min_in, 5.0) - 1e-9))
    FAIL(name << ": smallest dihedral angle " << min_out << " < " << min_in);
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

  // Vertices never move; boundary vertices of the output were boundary vertices of the input.
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
  CHECK_EQUAL(moved, std::size_t(0));
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
        CHECK(s.removed_tetrahedra >= target);
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
  // With the paper's conditions only, something is removed.
  o.paper = true;
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

  for (const char* name : {"sphere.mesh", "torus.mesh"})
    if (const auto file = data.generated_file(name)) test_mesh(*file, true);
  for (const char* name : {"cube.mesh", "sphere_tetgen.mesh", "cube_tetgen.vtu"})
    if (const auto file = data.generated_file(name)) test_mesh(*file, false);
  if (data.report_shared())
    for (const char* name : {"armadillo_sofa.vtu", "bunny_sofa.vtu", "skull_14k.off", "spx_zsweep.off",
                             "part1.1.ele", "t13_data.1.ele"})
      if (const auto file = data.shared_file(name)) test_mesh(*file, false);
  return prstar_test::summary("test_simplification");
}
