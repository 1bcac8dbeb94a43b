// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project
//
// Discrete distortion and solid angles (paper Section 8) on small meshes built here, against values
// computed in this file only: closed forms (the corner of a regular tetrahedron, of a cube, of an
// octahedron, the centre of an octahedron lifted by c |x|) and, for any other field, the solid
// angles of the lifted corners by Girard's theorem (spherical excess from the three dihedral angles
// of the corner, in the 3-flat spanned by its edges).  The library's own solid-angle helpers are
// never used for an expected value.  Part of the test_relations program.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/distortion.h>
#include <CGAL/property_map.h>

#include "test_harness.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace prstar_test_meshes {

using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;

// The six tetrahedra of the Kuhn split of the unit cube with lowest corner (x, y, z) (the six
// monotone paths to the opposite corner); `id` numbers the grid points.
template <class Id>
void kuhn_cube(Mesh& m, int x, int y, int z, Id id) {
  const int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& p : paths) {
    int c[3] = {x, y, z};
    Mesh::Tetrahedron t;
    t[0] = id(c[0], c[1], c[2]);
    for (int s = 0; s < 3; ++s) {
      ++c[p[s]];
      t[s + 1] = id(c[0], c[1], c[2]);
    }
    m.tetrahedra.push_back(t);
  }
}

// n x n x n unit cubes, each split into six tetrahedra around its diagonal (a conforming mesh).
Mesh cube_grid(int n) {
  Mesh m;
  for (int z = 0; z <= n; ++z)
    for (int y = 0; y <= n; ++y)
      for (int x = 0; x <= n; ++x) m.points.emplace_back(x, y, z);
  auto id = [n](int x, int y, int z) { return std::uint32_t(x + (n + 1) * (y + (n + 1) * z)); };
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) kuhn_cube(m, x, y, z, id);
  return m;
}

} // namespace prstar_test_meshes

namespace {

using prstar_test_meshes::cube_grid;

using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;
using Octree = CGAL::PR_star_octree_3<>;
using CGAL::PR_star_octree::Vertex_curvature;
using CGAL::PR_star_octree::Vertex_type;

const double pi = 3.14159265358979323846;
// Tolerances: relative for the solid-angle sums (each angle is exact to a few ulps), absolute (on
// the scale of 4 pi) for the differences that may vanish.
const double rel = 1e-12;
const double abs_tol = 1e-12 * 4 * pi;

using Vec = std::vector<double>; // a vector of R^3 or R^4

double dot(const Vec& a, const Vec& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

// The dihedral angle of the cone (u, v, w) along its edge u: the angle between the components of v
// and w orthogonal to u.
double dihedral(const Vec& u, const Vec& v, const Vec& w) {
  Vec vp = v, wp = w;
  const double uu = dot(u, u), vu = dot(v, u) / uu, wu = dot(w, u) / uu;
  for (std::size_t i = 0; i < u.size(); ++i) {
    vp[i] -= vu * u[i];
    wp[i] -= wu * u[i];
  }
  const double c = dot(vp, wp) / std::sqrt(dot(vp, vp) * dot(wp, wp));
  return std::acos(std::max(-1.0, std::min(1.0, c)));
}

// The solid angle of the trihedral cone spanned by u, v, w, by Girard's theorem: the area of a
// spherical triangle is the sum of its angles minus pi.
double girard(const Vec& u, const Vec& v, const Vec& w) {
  return dihedral(u, v, w) + dihedral(v, w, u) + dihedral(w, u, v) - pi;
}

// What the test expects at one vertex, computed by brute force over all tetrahedra of the mesh.
struct Expected {
  double s3 = 0, s4 = 0; // solid-angle sums of the star and of the lifted star
  Vertex_type type = Vertex_type::UNREFERENCED;
};

// Sums of the corner solid angles at every vertex (Girard), in 3D and lifted by `f` to R^4; the
// type is given by the test (these meshes are manifold: BOUNDARY when the vertex is on a face of
// only one tetrahedron, INTERIOR otherwise).
std::vector<Expected> expected_by_girard(const Mesh& m, const std::vector<double>& f) {
  std::vector<Expected> e(m.points.size());
  for (const auto& t : m.tetrahedra)
    for (int k = 0; k < 4; ++k) {
      const auto& p = m.points[t[k]];
      Vec e3[3], e4[3];
      int n = 0;
      for (int i = 0; i < 4; ++i) {
        if (i == k) continue;
        const auto& q = m.points[t[i]];
        e3[n] = {q.x() - p.x(), q.y() - p.y(), q.z() - p.z()};
        e4[n] = {q.x() - p.x(), q.y() - p.y(), q.z() - p.z(), f[t[i]] - f[t[k]]};
        ++n;
      }
      e[t[k]].s3 += girard(e3[0], e3[1], e3[2]);
      e[t[k]].s4 += girard(e4[0], e4[1], e4[2]);
    }
  // Boundary faces (in one tetrahedron only), found by comparing sorted faces pairwise.
  std::vector<std::array<std::size_t, 3>> faces;
  for (const auto& t : m.tetrahedra)
    for (int k = 0; k < 4; ++k) {
      std::array<std::size_t, 3> f3{{t[(k + 1) % 4], t[(k + 2) % 4], t[(k + 3) % 4]}};
      std::sort(f3.begin(), f3.end());
      faces.push_back(f3);
    }
  std::vector<char> boundary(m.points.size(), 0), referenced(m.points.size(), 0);
  for (const auto& t : m.tetrahedra)
    for (auto v : t) referenced[v] = 1;
  for (std::size_t i = 0; i < faces.size(); ++i)
    if (std::count(faces.begin(), faces.end(), faces[i]) == 1)
      for (auto v : faces[i]) boundary[v] = 1;
  for (std::size_t v = 0; v < e.size(); ++v)
    e[v].type = !referenced[v] ? Vertex_type::UNREFERENCED
                : boundary[v]  ? Vertex_type::BOUNDARY
                               : Vertex_type::INTERIOR;
  return e;
}

// The library's curvature of every vertex, in the user's numbering (public API only: property maps
// keyed by the user's vertex index).
std::vector<Vertex_curvature> library_curvature(const Octree& tree, const std::vector<double>& values) {
  std::vector<Vertex_curvature> out(tree.number_of_vertices());
  const auto counts = CGAL::PR_star_octree::compute_curvature(tree, CGAL::make_property_map(values),
                                                              CGAL::make_property_map(out));
  // The counts returned are those of the types written.
  std::size_t interior = 0, boundary = 0;
  for (const auto& c : out) {
    interior += c.type == Vertex_type::INTERIOR;
    boundary += c.type == Vertex_type::BOUNDARY;
  }
  CHECK_EQUAL(counts.interior_vertices, interior);
  CHECK_EQUAL(counts.boundary_vertices, boundary);
  // compute_discrete_distortion writes the same values into three maps.
  std::vector<double> distortion(out.size(), -1), domain(out.size(), -1);
  std::vector<Vertex_type> types(out.size(), Vertex_type::NONMANIFOLD);
  namespace params = CGAL::PR_star_octree::parameters;
  CGAL::PR_star_octree::compute_discrete_distortion(
      tree, CGAL::make_property_map(values), CGAL::make_property_map(distortion),
      params::domain_curvature_map(CGAL::make_property_map(domain))
          .vertex_type_map(CGAL::make_property_map(types)));
  for (std::size_t v = 0; v < out.size(); ++v) {
    CHECK_EQUAL(distortion[v], out[v].distortion);
    CHECK_EQUAL(domain[v], out[v].domain_curvature);
    CHECK_EQUAL(types[v], out[v].type);
  }
  return out;
}

// The library's curvature of one vertex by random access (octree numbering), in the user's.
Vertex_curvature library_curvature_at(const Octree& tree, std::size_t user_vertex,
                                      const std::vector<double>& values) {
  const auto from = tree.vertex_from_original();
  return CGAL::PR_star_octree::curvature_at(tree, from[user_vertex], CGAL::make_property_map(values));
}

void check_vertex(const Vertex_curvature& got, const Expected& e, const std::string& what) {
  const prstar_test::Failure_context context(what);
  CHECK_EQUAL(got.type, e.type);
  CHECK_CLOSE(got.solid_angle_sum_3, e.s3, rel);
  CHECK_CLOSE(got.solid_angle_sum_4, e.s4, rel);
  if (e.type == Vertex_type::INTERIOR) {
    CHECK_NEAR(got.domain_curvature, 4 * pi - e.s3, abs_tol);
    CHECK_NEAR(got.distortion, 4 * pi - e.s4, abs_tol);
  } else if (e.type == Vertex_type::BOUNDARY) {
    CHECK_NEAR(got.domain_curvature, 2 * pi - e.s3, abs_tol);
    CHECK_NEAR(got.distortion, e.s3 - e.s4, abs_tol);
  }
}

// The library on `m` lifted by `values`, for several k_v, against `expected` at every vertex, by the
// streaming computation and by random access.
void check_mesh(const Mesh& m, const std::vector<double>& values, const std::vector<Expected>& expected,
                const std::string& name) {
  CHECK_EQUAL(expected.size(), m.points.size());
  for (std::size_t kv : {std::size_t(1), std::size_t(2), Octree::infinite_bucket_size}) {
    const Octree tree(CGAL::PR_star_octree::make_input(m), CGAL::PR_star_octree::parameters::bucket_size(kv));
    const auto all = library_curvature(tree, values);
    CHECK_EQUAL(all.size(), m.points.size());
    for (std::size_t v = 0; v < std::min(all.size(), expected.size()); ++v) {
      const std::string what = name + ", vertex " + std::to_string(v) + ", k_v " + std::to_string(kv);
      check_vertex(all[v], expected[v], what);
      check_vertex(library_curvature_at(tree, v, values), expected[v], what + " (curvature_at)");
    }
  }
}

Mesh regular_tetrahedron() {
  Mesh m;
  m.points = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  m.tetrahedra = {{0, 1, 2, 3}};
  return m;
}

// The octahedron |x| + |y| + |z| <= 1 as eight tetrahedra around the origin (vertex 0).
Mesh octahedron() {
  Mesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (std::uint32_t x : {1u, 2u})
    for (std::uint32_t y : {3u, 4u})
      for (std::uint32_t z : {5u, 6u}) m.tetrahedra.push_back({0, x, y, z});
  return m;
}

std::vector<double> field(const Mesh& m, double (*f)(double, double, double)) {
  std::vector<double> v;
  for (const auto& p : m.points) v.push_back(f(p.x(), p.y(), p.z()));
  return v;
}

double zero(double, double, double) {
  return 0;
}
double linear(double x, double y, double z) {
  return 2 * x - y + 0.5 * z + 3;
}
double bumpy(double x, double y, double z) {
  return x * x - 0.7 * y * z + std::sin(2 * z) + 0.25 * x * y * z;
}

void test_regular_tetrahedron() {
  const Mesh m = regular_tetrahedron();
  // The solid angle at a corner of a regular tetrahedron: its three dihedral angles are acos(1/3).
  const double corner = 3 * std::acos(1.0 / 3.0) - pi;
  // Girard's formula written here agrees with the closed form (a check of the test itself).
  CHECK_CLOSE(girard({0, -2, -2}, {-2, 0, -2}, {-2, -2, 0}), corner, rel);
  // A constant field does not lift anything: the lifted sums are the 3D ones, distortion 0.
  std::vector<Expected> e(4);
  for (auto& x : e) x = {corner, corner, Vertex_type::BOUNDARY};
  check_mesh(m, field(m, zero), e, "regular tetrahedron, f = 0");
  // Every corner is a boundary corner: domain curvature 2 pi - (3 acos(1/3) - pi) = 3 pi - 3 acos(1/3).
  const Octree tree(CGAL::PR_star_octree::make_input(m),
                    CGAL::PR_star_octree::parameters::bucket_size(Octree::infinite_bucket_size));
  const auto c = library_curvature(tree, field(m, zero));
  for (const auto& x : c) {
    CHECK_CLOSE(x.domain_curvature, 3 * pi - 3 * std::acos(1.0 / 3.0), rel);
    CHECK_NEAR(x.distortion, 0.0, abs_tol);
  }
  // A linear field changes the lifted corners (a boundary vertex: distortion s3 - s4 != 0).
  const auto lin = field(m, linear);
  const auto el = expected_by_girard(m, lin);
  for (const auto& x : el) CHECK_CLOSE(x.s3, corner, rel);
  check_mesh(m, lin, el, "regular tetrahedron, linear f");
}

void test_cube() {
  // The cube in six tetrahedra: every vertex is a cube corner, an octant: pi / 2; on the boundary,
  // domain curvature 2 pi - pi / 2.
  const Mesh m = cube_grid(1);
  CHECK_EQUAL(m.tetrahedra.size(), std::size_t(6));
  const Octree tree(CGAL::PR_star_octree::make_input(m), CGAL::PR_star_octree::parameters::bucket_size(1));
  const auto c = library_curvature(tree, field(m, zero));
  CHECK_EQUAL(c.size(), std::size_t(8));
  for (const auto& x : c) {
    CHECK_EQUAL(x.type, Vertex_type::BOUNDARY);
    CHECK_CLOSE(x.solid_angle_sum_3, pi / 2, rel);
    CHECK_CLOSE(x.domain_curvature, 1.5 * pi, rel);
    CHECK_NEAR(x.distortion, 0.0, abs_tol);
  }
  for (auto f : {linear, bumpy}) {
    const auto values = field(m, f);
    const auto e = expected_by_girard(m, values);
    for (const auto& x : e) CHECK_CLOSE(x.s3, pi / 2, rel);
    check_mesh(m, values, e, f == linear ? "cube, linear f" : "cube, bumpy f");
  }
}

void test_cube_grid() {
  // Two by two by two cubes: the centre is interior (4 pi, no domain curvature, and a linear field
  // does not bend the lifted star: distortion 0); the face centres are flat boundary points (half
  // of space, 2 pi), the edge midpoints see a quarter of space (pi), the corners an octant (pi / 2).
  Mesh m = cube_grid(2);
  CHECK_EQUAL(m.tetrahedra.size(), std::size_t(48));
  auto id = [](int x, int y, int z) { return std::size_t(x + 3 * (y + 3 * z)); };
  const std::size_t centre = id(1, 1, 1);
  std::vector<double> closed(m.points.size());
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 3; ++x) {
        const int on_faces = (x != 1) + (y != 1) + (z != 1); // 0 centre, 1 face, 2 edge, 3 corner
        const double closed_forms[4] = {4 * pi, 2 * pi, pi, pi / 2};
        closed[id(x, y, z)] = closed_forms[on_faces];
      }
  for (int moved = 0; moved < 2; ++moved) {
    // Then the centre moved off the grid (still inside, no tetrahedron flipped): every sum is the
    // solid angle of the block at the vertex, unchanged, and a linear field still gives 0.
    if (moved) {
      std::vector<CGAL::Orientation> before;
      for (const auto& t : m.tetrahedra)
        before.push_back(CGAL::orientation(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]));
      m.points[centre] = Mesh::Point_3(1.1, 0.93, 1.05);
      for (std::size_t i = 0; i < m.tetrahedra.size(); ++i) {
        const auto& t = m.tetrahedra[i];
        CHECK_EQUAL(CGAL::orientation(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]),
                    before[i]);
      }
    }
    const std::string name = moved ? "2x2x2 cubes, centre moved" : "2x2x2 cubes";
    for (std::size_t kv : {std::size_t(1), Octree::infinite_bucket_size}) {
      const Octree tree(CGAL::PR_star_octree::make_input(m),
                        CGAL::PR_star_octree::parameters::bucket_size(kv));
      const auto lin = library_curvature(tree, field(m, linear));
      CHECK_EQUAL(lin[centre].type, Vertex_type::INTERIOR);
      CHECK_CLOSE(lin[centre].solid_angle_sum_3, 4 * pi, rel);
      CHECK_NEAR(lin[centre].domain_curvature, 0.0, abs_tol);
      CHECK_CLOSE(lin[centre].solid_angle_sum_4, 4 * pi, rel);
      CHECK_NEAR(lin[centre].distortion, 0.0, abs_tol);
      for (std::size_t v = 0; v < m.points.size(); ++v) {
        if (v == centre) continue;
        const prstar_test::Failure_context context(name + ", vertex " + std::to_string(v));
        CHECK_EQUAL(lin[v].type, Vertex_type::BOUNDARY);
        CHECK_CLOSE(lin[v].solid_angle_sum_3, closed[v], rel);
        CHECK_NEAR(lin[v].domain_curvature, 2 * pi - closed[v], abs_tol);
      }
    }
    for (auto f : {linear, bumpy}) {
      const auto values = field(m, f);
      const auto e = expected_by_girard(m, values);
      CHECK_EQUAL(e[centre].type, Vertex_type::INTERIOR);
      CHECK_CLOSE(e[centre].s3, 4 * pi, rel);
      check_mesh(m, values, e, name + (f == linear ? ", linear f" : ", bumpy f"));
    }
  }
}

void test_octahedron() {
  const Mesh m = octahedron();
  for (double c : {0.5, 1.0, 2.0}) {
    // f = c |x|: the eight lifted corners at the centre are spanned by (+-e_i, c), with Gram matrix
    // (1 + c^2) on the diagonal and c^2 off it.  Their dihedral angles are acos(c^2 / (1 + 2 c^2))
    // (Girard: Omega = 3 acos(c^2 / (1 + 2 c^2)) - pi); the Gram determinant 1 + 3 c^2 gives the same
    // angle as 2 atan(sqrt(1 + 3 c^2) / (sqrt(1 + c^2) (1 + 4 c^2))).  For c = 1 the lifted corner is
    // the corner of a regular tetrahedron.
    const double by_excess = 3 * std::acos(c * c / (1 + 2 * c * c)) - pi;
    const double by_gram = 2 * std::atan(std::sqrt(1 + 3 * c * c) / (std::sqrt(1 + c * c) * (1 + 4 * c * c)));
    CHECK_CLOSE(by_excess, by_gram, rel);
    if (c == 1.0) CHECK_CLOSE(by_excess, 3 * std::acos(1.0 / 3.0) - pi, rel);
    std::vector<double> values(m.points.size(), c);
    values[0] = 0;
    const auto e = expected_by_girard(m, values);
    CHECK_CLOSE(e[0].s4, 8 * by_excess, rel);
    for (std::size_t kv : {std::size_t(1), Octree::infinite_bucket_size}) {
      const Octree tree(CGAL::PR_star_octree::make_input(m),
                        CGAL::PR_star_octree::parameters::bucket_size(kv));
      const auto got = library_curvature(tree, values);
      const prstar_test::Failure_context context("octahedron, f = " + std::to_string(c) + " |x|");
      CHECK_EQUAL(got[0].type, Vertex_type::INTERIOR);
      CHECK_CLOSE(got[0].solid_angle_sum_3, 4 * pi, rel); // eight octants
      CHECK_NEAR(got[0].domain_curvature, 0.0, abs_tol);
      CHECK_CLOSE(got[0].solid_angle_sum_4, 8 * by_excess, rel);
      CHECK_NEAR(got[0].distortion, 4 * pi - 8 * by_excess, abs_tol);
      // The six tips are boundary corners: the apex of a right square pyramid of height 1 over a
      // square of side sqrt 2, 4 asin(1/3).
      for (std::size_t v = 1; v < 7; ++v) {
        CHECK_EQUAL(got[v].type, Vertex_type::BOUNDARY);
        CHECK_CLOSE(got[v].solid_angle_sum_3, 4 * std::asin(1.0 / 3.0), rel);
        CHECK_NEAR(got[v].domain_curvature, 2 * pi - 4 * std::asin(1.0 / 3.0), abs_tol);
      }
    }
    check_mesh(m, values, e, "octahedron, f = " + std::to_string(c) + " |x|");
  }
  // A bumpy field on the octahedron.
  const auto values = field(m, bumpy);
  check_mesh(m, values, expected_by_girard(m, values), "octahedron, bumpy f");
}

} // namespace

// Called by test_relations' main.
void test_curvature_closed_forms() {
  test_regular_tetrahedron();
  test_cube();
  test_cube_grid();
  test_octahedron();
}
