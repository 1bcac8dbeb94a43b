// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project
//
// mesh_quality.h against independent truth: closed forms of the dihedral angles and radius
// ratios of known tetrahedra; `mesh_quality()` and `edge_length_quality()` on a few tetrahedra
// counted by hand; the boundary surfaces against a brute-force std::map of faces;
// `boundary_distance()` against closed forms (a cube and its translate, a two-label cube) and
// against CGAL's Polygon_mesh_processing::approximate_Hausdorff_distance on the boundary surfaces
// (a cube with a bump, a real mesh and its scaled copy); `sharp_edge_distance()` on a cube (12 n
// sharp edges) and a bevelled cube (distance = the width of the bevel).  Part of the
// test_cgal_baseline program.

#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/mesh_quality.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include "test_harness.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Tet = std::array<std::uint32_t, 4>;
namespace P = CGAL::PR_star_octree;
namespace PMP = CGAL::Polygon_mesh_processing;

const double pi = 3.14159265358979323846;
double degrees(double radians) {
  return radians * 180 / pi;
}

struct Mesh {
  std::vector<Point> points;
  std::vector<Tet> tets;
};

// An n x n x n grid of cubes of side `side`, each split in the six Kuhn tetrahedra around its
// diagonal (conforming); `f` moves the points.
template <class F>
Mesh cube_grid(int n, double side, F f) {
  Mesh m;
  for (int z = 0; z <= n; ++z)
    for (int y = 0; y <= n; ++y)
      for (int x = 0; x <= n; ++x) m.points.push_back(f(Point(side * x / n, side * y / n, side * z / n)));
  auto id = [&](int x, int y, int z) { return std::uint32_t(x + (n + 1) * (y + (n + 1) * z)); };
  const int kuhn[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        for (const auto& k : kuhn) {
          Tet t;
          for (int i = 0; i < 4; ++i) t[i] = id(x + (k[i] & 1), y + ((k[i] >> 1) & 1), z + ((k[i] >> 2) & 1));
          m.tets.push_back(t);
        }
  return m;
}
Mesh cube_grid(int n, double side) {
  return cube_grid(n, side, [](const Point& p) { return p; });
}

// The polygon (y, z) extruded along x over [0, length] in `layers` layers: each triangle of a fan
// from the first corner makes prisms cut in three tetrahedra by the vertex order (conforming).
Mesh extrusion(const std::vector<std::array<double, 2>>& polygon, double length, int layers) {
  Mesh m;
  const std::uint32_t np = std::uint32_t(polygon.size());
  for (int l = 0; l <= layers; ++l)
    for (const auto& c : polygon) m.points.emplace_back(length * l / layers, c[0], c[1]);
  for (int l = 0; l < layers; ++l)
    for (std::uint32_t i = 1; i + 1 < np; ++i) {
      const std::uint32_t a = 0, b = i, c = i + 1; // a < b < c
      auto v = [&](std::uint32_t corner, int layer) {
        return std::uint32_t(corner + np * std::uint32_t(l + layer));
      };
      m.tets.push_back({{v(a, 0), v(b, 0), v(c, 0), v(c, 1)}});
      m.tets.push_back({{v(a, 0), v(b, 0), v(b, 1), v(c, 1)}});
      m.tets.push_back({{v(a, 0), v(a, 1), v(b, 1), v(c, 1)}});
    }
  return m;
}

// The boundary triangles by brute force: the faces of exactly one tetrahedron (sorted triples).
std::vector<std::array<std::size_t, 3>> brute_force_boundary(const Mesh& m) {
  std::map<std::array<std::size_t, 3>, int> count;
  for (const Tet& t : m.tets)
    for (int k = 0; k < 4; ++k) {
      std::array<std::size_t, 3> f;
      int n = 0;
      for (int i = 0; i < 4; ++i)
        if (i != k) f[n++] = t[i];
      std::sort(f.begin(), f.end());
      ++count[f];
    }
  std::vector<std::array<std::size_t, 3>> r;
  for (const auto& c : count)
    if (c.second == 1) r.push_back(c.first);
  return r;
}

// The boundary surface as a Surface_mesh (made from the brute-force triangles, oriented by CGAL).
CGAL::Surface_mesh<Point> boundary_surface(const Mesh& m) {
  // Only the boundary's vertices (CGAL samples every vertex of the surface mesh).
  std::vector<Point> points;
  std::map<std::size_t, std::size_t> renumber;
  std::vector<std::vector<std::size_t>> polygons;
  for (const auto& f : brute_force_boundary(m)) {
    polygons.emplace_back();
    for (std::size_t v : f) {
      const auto it = renumber.emplace(v, points.size());
      if (it.second) points.push_back(m.points[v]);
      polygons.back().push_back(it.first->second);
    }
  }
  PMP::orient_polygon_soup(points, polygons); // the sorted triples are not consistently oriented
  CGAL::Surface_mesh<Point> sm;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, sm);
  return sm;
}

// CGAL's one-sided approximate Hausdorff distance from a's boundary to b's.
double cgal_hausdorff(const Mesh& a, const Mesh& b, double points_per_area_unit) {
  const auto sa = boundary_surface(a), sb = boundary_surface(b);
  return PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(
      sa, sb, CGAL::parameters::number_of_points_per_area_unit(points_per_area_unit));
}

void test_tetrahedron_closed_forms() {
  // Regular tetrahedron: every dihedral angle is acos(1/3), the radius ratio is 1.
  const Point a(1, 1, 1), b(1, -1, -1), c(-1, 1, -1), d(-1, -1, 1);
  CHECK_NEAR(P::min_dihedral_angle(a, b, c, d), degrees(std::acos(1. / 3)), 1e-9);
  CHECK_NEAR(P::min_dihedral_angle(a, b, c, d), 70.528779365509308, 1e-9);
  CHECK_NEAR(P::max_dihedral_angle(a, b, c, d), 70.528779365509308, 1e-9);
  CHECK_NEAR(P::radius_ratio(a, b, c, d), 1, 1e-12);
  CHECK_NEAR(P::max_dihedral_angle(b, a, c, d), 70.528779365509308, 1e-9); // any orientation
  // The corner of the unit cube: angles 90 (three axis edges) and acos(1/sqrt 3) = 54.7356 (the
  // three others); inradius 1 / (3 + sqrt 3), circumradius sqrt(3) / 2: radius ratio sqrt(3) - 1.
  const Point o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  CHECK_NEAR(P::min_dihedral_angle(o, x, y, z), degrees(std::acos(1 / std::sqrt(3.))), 1e-9);
  CHECK_NEAR(P::min_dihedral_angle(o, x, y, z), 54.735610317245346, 1e-9);
  CHECK_NEAR(P::max_dihedral_angle(o, x, y, z), 90, 1e-9);
  CHECK_NEAR(P::radius_ratio(o, x, y, z), std::sqrt(3.) - 1, 1e-12);
  CHECK_NEAR(P::radius_ratio(o, x, y, z), 0.7320508075688772, 1e-12);
  // A flat one (four coplanar points): 0 and 180 degrees, radius ratio 0.
  const Point w(1, 1, 0);
  CHECK_EQUAL(P::min_dihedral_angle(o, x, y, w), 0.);
  CHECK_NEAR(P::max_dihedral_angle(o, x, y, w), 180, 1e-9);
  CHECK_EQUAL(P::radius_ratio(o, x, y, w), 0.);
  // The corner flattened to height h: smallest angle atan(h sqrt 2) at the hypotenuse edge; radius
  // ratio 6 h / ((1 + 2 h + sqrt(2 h^2 + 1)) sqrt(2 + h^2)).
  for (double h : {0.05, 0.1, 0.5}) {
    const Point t(0, 0, h);
    CHECK_NEAR(P::min_dihedral_angle(o, x, y, t), degrees(std::atan(h * std::sqrt(2.))), 1e-9);
    CHECK_NEAR(P::max_dihedral_angle(o, x, y, t), 90, 1e-9);
    CHECK_NEAR(P::radius_ratio(o, x, y, t),
               6 * h / ((1 + 2 * h + std::sqrt(2 * h * h + 1)) * std::sqrt(2 + h * h)), 1e-12);
  }
}

void test_mesh_quality_by_hand() {
  // Four separate tetrahedra: a regular one, the cube corner, the corner at heights 0.05 (4.04
  // degrees) and 0.1 (8.05 degrees).
  Mesh m;
  m.points = {Point(1, 1, 1), Point(1, -1, -1), Point(-1, 1, -1), Point(-1, -1, 1),  Point(0, 0, 0),
              Point(1, 0, 0), Point(0, 1, 0),   Point(0, 0, 1),   Point(0, 0, 0.05), Point(0, 0, 0.1)};
  m.tets = {{{0, 1, 2, 3}}, {{4, 5, 6, 7}}, {{4, 6, 5, 8}}, {{9, 4, 5, 6}}};
  const P::Mesh_quality q = P::mesh_quality(m.points, m.tets);
  CHECK_EQUAL(q.tetrahedra, std::size_t(4));
  CHECK_NEAR(q.min_dihedral_angle, degrees(std::atan(0.05 * std::sqrt(2.))), 1e-9);
  CHECK_NEAR(q.max_dihedral_angle, 90, 1e-9);
  const double h = 0.05;
  CHECK_NEAR(q.min_radius_ratio, 6 * h / ((1 + 2 * h + std::sqrt(2 * h * h + 1)) * std::sqrt(2 + h * h)),
             1e-12);
  CHECK_EQUAL(q.under_5_degrees, std::size_t(1));
  CHECK_EQUAL(q.under_10_degrees, std::size_t(2));
  CHECK_NEAR(q.share_under_5(), 0.25, 1e-15);
  CHECK_NEAR(q.share_under_10(), 0.5, 1e-15);
  // A Kuhn cube: six tetrahedra with angles 45 (smallest), 60 and 90 (largest).
  const Mesh cube = cube_grid(1, 1);
  const P::Mesh_quality c = P::mesh_quality(cube.points, cube.tets);
  CHECK_EQUAL(c.tetrahedra, std::size_t(6));
  CHECK_NEAR(c.min_dihedral_angle, 45, 1e-9);
  CHECK_NEAR(c.max_dihedral_angle, 90, 1e-9);
  CHECK_EQUAL(c.under_10_degrees, std::size_t(0));
  const P::Mesh_quality e = P::mesh_quality(m.points, std::vector<Tet>{});
  CHECK_EQUAL(e.tetrahedra, std::size_t(0));
  CHECK_EQUAL(e.share_under_5(), 0.);
}

// `edge_length_quality()` on the Kuhn cube (12 edges of length 1, 6 face diagonals, 1 body
// diagonal), counted by hand.
void test_edge_length_quality_by_hand() {
  const Mesh cube = cube_grid(1, 1);
  const P::Edge_length_quality a = P::edge_length_quality(cube.points, cube.tets, 1.);
  CHECK_EQUAL(a.edges, std::size_t(19));
  CHECK_EQUAL(a.in_range, std::size_t(12));
  CHECK_EQUAL(a.too_short, std::size_t(0));
  CHECK_EQUAL(a.too_long, std::size_t(7)); // sqrt(2) and sqrt(3) > 1.33
  CHECK_EQUAL(a.median_ratio, 1.);
  CHECK_NEAR(a.share_long(), 7. / 19, 1e-15);
  // target 1.2: 1/1.2 and sqrt(2)/1.2 are in [0.8, 1.33], sqrt(3)/1.2 is not
  const P::Edge_length_quality b = P::edge_length_quality(cube.points, cube.tets, 1.2);
  CHECK_EQUAL(b.in_range, std::size_t(18));
  CHECK_EQUAL(b.too_long, std::size_t(1));
  CHECK_NEAR(b.median_ratio, 1 / 1.2, 1e-15);
  // a sizing field 1 + x: an edge's target is the mean of its ends'
  std::vector<double> sizing;
  for (const Point& p : cube.points) sizing.push_back(1 + p.x());
  const P::Edge_length_quality c = P::edge_length_quality(cube.points, cube.tets, sizing);
  // short: the 4 x edges (1/1.5), the 4 y and z edges at x = 1 (1/2), the diagonal at x = 1
  // (sqrt(2)/2); long: the diagonal at x = 0 (sqrt(2)); the other 9 in range
  CHECK_EQUAL(c.edges, std::size_t(19));
  CHECK_EQUAL(c.too_short, std::size_t(9));
  CHECK_EQUAL(c.too_long, std::size_t(1));
  CHECK_EQUAL(c.in_range, std::size_t(9));
  CHECK_NEAR(c.median_ratio, 2 * std::sqrt(2.) / 3, 1e-15); // the 10th of 19: a diagonal across x
  // an even number of edges: the mean of the two middle ones (one tetrahedron: 1, 1, 1, sqrt(2),
  // sqrt(2), sqrt(3))
  const std::vector<Tet> one{cube.tets[0]};
  const P::Edge_length_quality d = P::edge_length_quality(cube.points, one, 1.);
  CHECK_EQUAL(d.edges, std::size_t(6));
  CHECK_NEAR(d.median_ratio, (1 + std::sqrt(2.)) / 2, 1e-15);
  // no tetrahedron: no edge, shares 0, the median NaN
  const P::Edge_length_quality e = P::edge_length_quality(cube.points, std::vector<Tet>{}, 1.);
  CHECK_EQUAL(e.edges, std::size_t(0));
  CHECK_EQUAL(e.share_in_range(), 0.);
  CHECK(std::isnan(e.median_ratio));
}

void test_boundary_triangles() {
  namespace I = P::internal::mesh_quality_impl;
  for (const Mesh& m : {cube_grid(3, 1), extrusion({{{0, 0}, {4, 0}, {4, 3}, {3, 4}, {0, 4}}}, 4, 4)}) {
    const auto expected = brute_force_boundary(m);
    CHECK(I::boundary_triangles(m.tets) == expected); // both sorted lexicographically
  }
  CHECK_EQUAL(I::boundary_triangles(cube_grid(3, 1).tets).size(), std::size_t(6 * 9 * 2));
}

void test_boundary_distance() {
  const Mesh cube = cube_grid(4, 4);
  // With itself: 0.
  const P::Boundary_distance self = P::boundary_distance(cube.points, cube.tets, cube.points, cube.tets);
  CHECK_EQUAL(self.hausdorff(), 0.);
  CHECK_NEAR(self.diagonal, 4 * std::sqrt(3.), 1e-12);
  CHECK(self.samples > 0);
  // The cube [0, 4]^3 against its translate by d along x: both one-sided distances are d (the
  // centre of the face x = 0 is at d from the other surface, and no point is farther).
  const double d = 0.3;
  const Mesh moved = cube_grid(4, 4, [&](const Point& p) { return Point(p.x() + d, p.y(), p.z()); });
  const P::Boundary_distance t = P::boundary_distance(cube.points, cube.tets, moved.points, moved.tets, 0.05);
  CHECK_NEAR(t.input_to_output, d, 1e-12);
  CHECK_NEAR(t.output_to_input, d, 1e-12);
  CHECK_NEAR(t.relative(), d / (4 * std::sqrt(3.)), 1e-12);
  // CGAL agrees (its sampling is random, from below).
  CHECK_NEAR(cgal_hausdorff(cube, moved, 200), d, 0.01);
  CHECK_NEAR(cgal_hausdorff(moved, cube, 200), d, 0.01);
  // A cube whose top face is pushed up in its middle (a piecewise linear bump of height 0.8):
  // no closed form; against CGAL both ways.
  const Mesh bump = cube_grid(4, 4, [](const Point& p) {
    const double lift = p.z() == 4 ? 0.8 * std::sin(pi * p.x() / 4) * std::sin(pi * p.y() / 4) : 0;
    return Point(p.x(), p.y(), p.z() + lift);
  });
  const P::Boundary_distance b = P::boundary_distance(cube.points, cube.tets, bump.points, bump.tets, 0.01);
  const double cgal_in_out = cgal_hausdorff(cube, bump, 4000), cgal_out_in = cgal_hausdorff(bump, cube, 4000);
  CHECK(b.input_to_output > 0.3 && b.output_to_input > 0.3);
  CHECK_NEAR(b.input_to_output, cgal_in_out, 0.01);
  CHECK_NEAR(b.output_to_input, cgal_out_in, 0.01);
  CHECK_NEAR(b.output_to_input, 0.8, 1e-12); // the top of the bump is a vertex, 0.8 above the face
  // A tight sample cap enlarges the step, never the result (sampling is from below).
  const P::Boundary_distance capped =
      P::boundary_distance(cube.points, cube.tets, bump.points, bump.tets, 0.01, 1000);
  CHECK(capped.sampling_step > 0.01 && capped.samples < b.samples);
  CHECK(capped.input_to_output <= b.input_to_output + 1e-12);
  // Two labels: the interface x = 2 of the labelled cube is a boundary too; its centre (2, 2, 2)
  // is at 2 from the outer boundary.
  std::vector<int> labels;
  for (const Tet& tet : cube.tets) {
    double cx = 0;
    for (std::uint32_t v : tet) cx += cube.points[v].x() / 4;
    labels.push_back(cx < 2 ? 1 : 2);
  }
  const P::Boundary_distance l =
      P::boundary_distance(cube.points, cube.tets, cube.points, cube.tets, 0.05, 1000000, &labels,
                           static_cast<const std::vector<int>*>(nullptr));
  CHECK_NEAR(l.input_to_output, 2, 1e-12);
  CHECK_EQUAL(l.output_to_input, 0.);
  // Empty against non-empty: infinite.
  const P::Boundary_distance e =
      P::boundary_distance(cube.points, cube.tets, cube.points, std::vector<Tet>{});
  CHECK(std::isinf(e.input_to_output) && e.output_to_input == 0);
}

void test_boundary_distance_real_mesh(const prstar_test::Data_folders& data) {
  const std::optional<std::string> file = data.shared_file("bunny_sofa.vtu");
  if (!file) return; // skip() reported by shared_file
  P::Indexed_tetrahedral_mesh<> in;
  P::IO::read_tetrahedral_mesh(*file, in);
  Mesh a, b;
  a.points = in.points;
  for (const auto& t : in.tetrahedra) a.tets.push_back({{t[0], t[1], t[2], t[3]}});
  // b: a scaled by 1.02 about the corner of its bounding box, so that the surfaces differ
  // everywhere by amounts that grow across the model.
  const CGAL::Bbox_3 box = CGAL::bbox_3(a.points.begin(), a.points.end());
  const Point corner(box.xmin(), box.ymin(), box.zmin());
  b.tets = a.tets;
  for (const Point& p : a.points) b.points.push_back(corner + 1.02 * (p - corner));
  const double diagonal =
      std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                CGAL::square(box.zmax() - box.zmin()));
  const P::Boundary_distance d = P::boundary_distance(a.points, a.tets, b.points, b.tets, 1e-3 * diagonal);
  const double area = PMP::area(boundary_surface(a));
  const double density = 2e5 / area; // 200K random points on each surface
  const double cgal_ab = cgal_hausdorff(a, b, density), cgal_ba = cgal_hausdorff(b, a, density);
  std::cout << "bunny_sofa scaled by 1.02: ours " << d.input_to_output << " / " << d.output_to_input
            << ", CGAL " << cgal_ab << " / " << cgal_ba << " (diagonal " << diagonal << ")\n";
  CHECK_NEAR(d.input_to_output, cgal_ab, 3e-3 * diagonal);
  CHECK_NEAR(d.output_to_input, cgal_ba, 3e-3 * diagonal);
  CHECK(d.input_to_output > 0.005 * diagonal); // the scaling moved the far side by about 2% of the box
}

void test_sharp_edge_distance() {
  // A cube of 4 x 4 x 4 cells: its 12 edges, 4 segments each, are the sharp edges.
  const Mesh cube = cube_grid(4, 4);
  const P::Sharp_edge_distance self = P::sharp_edge_distance(cube.points, cube.tets, cube.points, cube.tets);
  CHECK_EQUAL(self.input_sharp_edges, std::size_t(12 * 4));
  CHECK_EQUAL(self.output_sharp_edges, std::size_t(12 * 4));
  CHECK_EQUAL(self.input_to_output, 0.);
  CHECK_EQUAL(self.output_to_input, 0.);
  // The same cube with one edge (y = z = 4) bevelled at 45 degrees over a width of 1, extruded in
  // 4 layers: 5 edges along x in 4 segments each, and the 5 sides of the two end polygons.  Between
  // the bevel and its faces the surface turns by 45 degrees: sharp at 40, not at 50.  The vertices of
  // the bevel's edges are at 1 from the cut edge, and the cut edge's vertices at 1 from the bevel.
  const Mesh bevel = extrusion({{{0, 0}, {4, 0}, {4, 3}, {3, 4}, {0, 4}}}, 4, 4);
  const P::Sharp_edge_distance s = P::sharp_edge_distance(cube.points, cube.tets, bevel.points, bevel.tets);
  CHECK_EQUAL(s.input_sharp_edges, std::size_t(48));
  CHECK_EQUAL(s.output_sharp_edges, std::size_t(5 * 4 + 2 * 5));
  CHECK_NEAR(s.input_to_output, 1, 1e-12);
  CHECK_NEAR(s.output_to_input, 1, 1e-12);
  const P::Sharp_edge_distance s50 =
      P::sharp_edge_distance(cube.points, cube.tets, bevel.points, bevel.tets, 50);
  // At 50 degrees the bevel's two edges along x are not sharp (its sides on the end polygons still
  // are, at 90 degrees): the middle vertex (2, 4, 4) of the cut edge is then sqrt(2^2 + 1/2) from
  // the nearest sharp edge, the bevel's side (0, 4, 3)-(0, 3, 4) of the end polygon x = 0.
  CHECK_EQUAL(s50.output_sharp_edges, std::size_t(3 * 4 + 2 * 5));
  CHECK_EQUAL(s50.input_sharp_edges, std::size_t(48));
  CHECK_NEAR(s50.input_to_output, std::sqrt(4.5), 1e-12);
}

} // namespace

void test_mesh_quality(const prstar_test::Data_folders& data) {
  test_tetrahedron_closed_forms();
  test_mesh_quality_by_hand();
  test_edge_length_quality_by_hand();
  test_boundary_triangles();
  test_boundary_distance();
  test_boundary_distance_real_mesh(data);
  test_sharp_edge_distance();
}
