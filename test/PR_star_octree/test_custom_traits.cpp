// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A traits class with its own point type (no x(), y(), z(), no CGAL kernel object) runs through
// every application of the package: all geometry goes through the traits' functors, which count
// their calls.  Results are checked against closed forms for a jittered Kuhn grid and against the
// same computation with CGAL's Epick kernel.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/Leaf_topology.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/distortion.h>
#include <CGAL/PR_star_octree/simplification.h>
#include <CGAL/PR_star_octree/validity.h>
#include <CGAL/property_map.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <iterator>
#include <vector>

#include "test_harness.h"

namespace {

// A point that is only an array: the package must not call p.x().
struct My_point {
  double c[3];
};

struct Calls {
  std::atomic<std::size_t> orientation{0}, squared_distance{0}, coordinates{0},
      construct{0}; // functors may run in parallel
};
Calls calls;

struct My_traits {
  using FT = double;
  using Point_3 = My_point;
  struct Compute_x_3 {
    double operator()(const My_point& p) const { return ++calls.coordinates, p.c[0]; }
  };
  struct Compute_y_3 {
    double operator()(const My_point& p) const { return ++calls.coordinates, p.c[1]; }
  };
  struct Compute_z_3 {
    double operator()(const My_point& p) const { return ++calls.coordinates, p.c[2]; }
  };
  struct Orientation_3 {
    CGAL::Orientation operator()(const My_point& p, const My_point& q, const My_point& r,
                                 const My_point& s) const {
      ++calls.orientation;
      auto e = [](const My_point& a) { return CGAL::Epick::Point_3(a.c[0], a.c[1], a.c[2]); };
      return CGAL::Epick().orientation_3_object()(e(p), e(q), e(r), e(s)); // exact
    }
  };
  struct Compute_squared_distance_3 {
    double operator()(const My_point& p, const My_point& q) const {
      ++calls.squared_distance;
      double d = 0;
      for (int a = 0; a < 3; ++a) d += (p.c[a] - q.c[a]) * (p.c[a] - q.c[a]);
      return d;
    }
  };
  struct Construct_point_3 {
    My_point operator()(double x, double y, double z) const { return ++calls.construct, My_point{{x, y, z}}; }
  };
  Compute_x_3 compute_x_3_object() const { return {}; }
  Compute_y_3 compute_y_3_object() const { return {}; }
  Compute_z_3 compute_z_3_object() const { return {}; }
  Orientation_3 orientation_3_object() const { return {}; }
  Compute_squared_distance_3 compute_squared_distance_3_object() const { return {}; }
  Construct_point_3 construct_point_3_object() const { return {}; }
};

namespace PSO = CGAL::PR_star_octree;
namespace params = CGAL::PR_star_octree::parameters;

// A jittered n^3 Kuhn grid (6 tetrahedra per cube, some listed negatively oriented).
template <class Point>
void grid(int n, std::vector<Point>& points, std::vector<std::array<int, 4>>& tets,
          Point (*make)(double, double, double)) {
  auto id = [n](int x, int y, int z) { return x + (n + 1) * (y + (n + 1) * z); };
  for (int z = 0; z <= n; ++z)
    for (int y = 0; y <= n; ++y)
      for (int x = 0; x <= n; ++x) {
        const bool inner = x > 0 && x < n && y > 0 && y < n && z > 0 && z < n;
        const double j = inner ? 0.1 * (((x * 7 + y * 3 + z * 5) % 5) - 2) / 2. : 0.;
        points.push_back(make(x + j, y - 0.7 * j, z + 0.4 * j));
      }
  const int paths[6][2] = {{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}};
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        int c[8];
        for (int b = 0; b < 8; ++b) c[b] = id(x + (b & 1), y + ((b >> 1) & 1), z + ((b >> 2) & 1));
        for (int k = 0; k < 6; ++k) {
          std::array<int, 4> t{{c[0], c[paths[k][0]], c[paths[k][1]], c[7]}};
          // All listed negatively oriented (a consistent convention the octree turns around),
          // decided on the lattice by CGAL's exact predicate.
          auto lattice = [n](int v) {
            return CGAL::Epick::Point_3(v % (n + 1), (v / (n + 1)) % (n + 1), v / ((n + 1) * (n + 1)));
          };
          if (CGAL::orientation(lattice(t[0]), lattice(t[1]), lattice(t[2]), lattice(t[3])) == CGAL::POSITIVE)
            std::swap(t[0], t[1]);
          tets.push_back(t);
        }
      }
}

My_point make_mine(double x, double y, double z) {
  return My_point{{x, y, z}};
}
CGAL::Epick::Point_3 make_epick(double x, double y, double z) {
  return CGAL::Epick::Point_3(x, y, z);
}

} // namespace

int main() {
  const int n = 7;
  std::vector<My_point> points;
  std::vector<std::array<int, 4>> tets;
  grid(n, points, tets, make_mine);
  std::vector<CGAL::Epick::Point_3> epoints;
  std::vector<std::array<int, 4>> etets;
  grid(n, epoints, etets, make_epick);
  const std::size_t nv = points.size(), nt = tets.size();

  using Octree = CGAL::PR_star_octree_3<My_traits>;
  const Octree tree(PSO::make_input(points, tets), params::bucket_size(20).geom_traits(My_traits()));
  const CGAL::PR_star_octree_3<> etree(PSO::make_input(epoints, etets), params::bucket_size(20));
  CHECK(calls.orientation >= nt);     // every tetrahedron oriented through the traits
  CHECK(calls.coordinates >= 3 * nv); // the split through the traits' coordinates
  CHECK_EQUAL(tree.number_of_leaves(), etree.number_of_leaves());
  CHECK_EQUAL(tree.statistics().reoriented_tetrahedra, etree.statistics().reoriented_tetrahedra);
  CHECK_EQUAL(tree.statistics().reoriented_tetrahedra, nt);

  // Boundary: closed forms of the grid.
  std::vector<PSO::Vertex_type> types(nv);
  std::vector<std::array<std::size_t, 3>> triangles;
  const auto b = PSO::compute_boundary(tree, CGAL::make_property_map(types),
                                       params::boundary_triangles_output(std::back_inserter(triangles)));
  const std::size_t inner = std::size_t(n - 1) * (n - 1) * (n - 1);
  CHECK_EQUAL(b.interior_vertices, inner);
  CHECK_EQUAL(b.boundary_vertices, nv - inner);
  CHECK_EQUAL(b.boundary_triangles, std::size_t(12 * n * n));
  CHECK_EQUAL(triangles.size(), std::size_t(12 * n * n));
  // Outward orientation: the normal of every boundary triangle points away from the grid's centre.
  std::size_t inward = 0;
  for (const auto& t : triangles) {
    const My_point &p = points[t[0]], &q = points[t[1]], &r = points[t[2]];
    double u[3], v[3], c[3], w[3];
    for (int a = 0; a < 3; ++a) {
      u[a] = q.c[a] - p.c[a];
      v[a] = r.c[a] - p.c[a];
      w[a] = p.c[a] - n / 2.;
    }
    c[0] = u[1] * v[2] - u[2] * v[1];
    c[1] = u[2] * v[0] - u[0] * v[2];
    c[2] = u[0] * v[1] - u[1] * v[0];
    inward += (c[0] * w[0] + c[1] * w[1] + c[2] * w[2] <= 0);
  }
  CHECK_EQUAL(inward, std::size_t(0));
  for (int x = 0; x <= n; ++x) // a vertex on an edge of the cube, one inside
    CHECK(types[std::size_t(x)] == PSO::Vertex_type::BOUNDARY);
  CHECK(types[std::size_t(1 + (n + 1) * (1 + (n + 1)))] == PSO::Vertex_type::INTERIOR);

  // Distortion of a linear field: 0 inside; domain curvature at a cube corner: 2 pi - pi / 2.
  std::vector<double> distortion(nv), domain(nv);
  const auto cc = PSO::compute_discrete_distortion(
      tree, PSO::coordinate_field_map(tree, 1), CGAL::make_property_map(distortion),
      params::domain_curvature_map(CGAL::make_property_map(domain)));
  CHECK_EQUAL(cc.interior_vertices, inner);
  double worst = 0;
  for (std::size_t v = 0; v < nv; ++v)
    if (types[v] == PSO::Vertex_type::INTERIOR) worst = (std::max)(worst, std::abs(distortion[v]));
  CHECK(worst < 1e-9);
  const double pi = std::acos(-1.);
  CHECK_NEAR(domain[0], 1.5 * pi, 1e-12);
  // Same field values from a vector in the user's order, and the Epick kernel.
  std::vector<double> field(nv), d2(nv), d3(nv);
  for (std::size_t v = 0; v < nv; ++v) field[v] = points[v].c[0] * points[v].c[0] - points[v].c[2];
  PSO::compute_discrete_distortion(tree, CGAL::make_property_map(field), CGAL::make_property_map(d2));
  PSO::compute_discrete_distortion(etree, CGAL::make_property_map(field), CGAL::make_property_map(d3));
  std::size_t differ = 0;
  for (std::size_t v = 0; v < nv; ++v) differ += !(std::abs(d2[v] - d3[v]) <= 1e-12);
  CHECK_EQUAL(differ, std::size_t(0));
  // One vertex and a box, in the octree's numbering.
  const auto at = PSO::curvature_at(tree, Octree::Index(5), CGAL::make_property_map(field));
  CHECK_NEAR(at.distortion, d2[tree.original_vertex(5)], 1e-12);
  std::vector<std::pair<Octree::Index, PSO::Vertex_curvature>> in_box;
  PSO::curvature_in_box(tree, CGAL::Bbox_3(-1, -1, -1, 1.5, 1.5, 1.5), CGAL::make_property_map(field),
                        in_box);
  CHECK(!in_box.empty());
  for (const auto& x : in_box) CHECK_NEAR(x.second.distortion, d2[tree.original_vertex(x.first)], 1e-12);

  // Validity, counts, local relations.
  const auto validity = PSO::check_validity(tree);
  CHECK(validity.valid);
  CHECK_EQUAL(validity.euler_characteristic, 1LL);
  CHECK_EQUAL(validity.boundary_components, std::size_t(1));
  CHECK_EQUAL(validity.negative, nt);
  CHECK_EQUAL(validity.inverted, std::size_t(0));
  const auto counts = PSO::count_simplices(tree);
  CHECK_EQUAL(counts.edges, PSO::count_simplices(etree).edges);
  std::vector<Octree::Index> star;
  PSO::vertex_star(tree, Octree::Index(0), std::back_inserter(star));
  CHECK(!star.empty());
  const auto nb = PSO::tetrahedron_neighbors(tree, Octree::Index(0));
  CHECK(nb[0] != Octree::no_node || nb[1] != Octree::no_node || nb[2] != Octree::no_node ||
        nb[3] != Octree::no_node);

  // Simplification through the traits (squared distances and orientations), checked with Epick.
  const std::size_t before = calls.squared_distance;
  const auto result = PSO::simplify(PSO::make_input(points, tets),
                                    params::target_fraction(0.3).bucket_size(40).geom_traits(My_traits()));
  CHECK(calls.squared_distance > before);
  CHECK(result.statistics.removed_tetrahedra >= std::size_t(0.3 * double(nt)));
  std::vector<CGAL::Epick::Point_3> out_points;
  for (const My_point& p : result.mesh.points) out_points.emplace_back(p.c[0], p.c[1], p.c[2]);
  const auto out_validity = PSO::check_validity(out_points, result.mesh.tetrahedra);
  CHECK(out_validity.valid);
  CHECK_EQUAL(out_validity.euler_characteristic, 1LL);
  // The collapse test through the traits, on an edge of the first tetrahedron, and on a vertex with
  // itself (no edge: UBSan once caught the fan code reading past a 2-array there).
  const auto& first = tree.tetrahedron(*tree.leaf_tetrahedra(tree.leaves()[0]).begin());
  const auto check = PSO::check_half_edge_collapse(tree, first[0], first[1]);
  CHECK(check.edge_exists);
  CHECK(check.allowed() == (check.boundary && check.geometry && check.link));
  const auto self = PSO::check_half_edge_collapse(tree, first[0], first[0]);
  CHECK(!self.edge_exists && !self.allowed());

  return prstar_test::summary("test_custom_traits");
}
