// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Self-test of the CGAL Triangulation_3 baseline (benchmark/PR_star_octree/baselines): builds
// triangulations from index arrays (a cube, grids of Kuhn-split cubes, a grid with a hole, two
// separate blocks), checks their combinatorial validity and every relation against brute force,
// and checks that invalid inputs are rejected.  Also the mesh quality measures (mesh_quality.h,
// test_mesh_quality.cpp) against closed forms and CGAL's Polygon_mesh_processing.  With `--bench`, also times
// the build on a 100 x 100 x 20 grid (1.2M tetrahedra).

#include <baselines/Cgal_triangulation_baseline.h>

#include "test_harness.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <map>
#include <set>
#include <string>

namespace {

using Baseline = prstar_baselines::Cgal_triangulation_baseline;
using Index = Baseline::Index;
using Point_3 = Baseline::Point_3;
using Tetrahedron = Baseline::Tetrahedron;
constexpr Index no_index = Baseline::no_index;

struct Mesh {
  std::vector<Point_3> points;
  std::vector<Tetrahedron> tets;
};

// The six Kuhn tetrahedra of the unit cube, corners numbered x + 2y + 4z.
const Tetrahedron kuhn[6] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7},
                             {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};

// nx * ny * nz cubes split into Kuhn tetrahedra (consistent across cubes); the cubes with
// `skip(x, y, z)` are left out.  Every third tetrahedron is listed negatively oriented.
template <class Skip>
Mesh grid(int nx, int ny, int nz, Skip skip, double x0 = 0) {
  Mesh m;
  for (int z = 0; z <= nz; ++z)
    for (int y = 0; y <= ny; ++y)
      for (int x = 0; x <= nx; ++x) m.points.emplace_back(x0 + x, y, z);
  auto id = [&](int x, int y, int z) { return Index(x + (nx + 1) * (y + (ny + 1) * z)); };
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        if (skip(x, y, z)) continue;
        for (const Tetrahedron& k : kuhn) {
          Tetrahedron t;
          for (int i = 0; i < 4; ++i) t[i] = id(x + (k[i] & 1), y + ((k[i] >> 1) & 1), z + ((k[i] >> 2) & 1));
          if (m.tets.size() % 3 == 1) std::swap(t[2], t[3]);
          m.tets.push_back(t);
        }
      }
  return m;
}
Mesh grid(int nx, int ny, int nz) {
  return grid(nx, ny, nz, [](int, int, int) { return false; });
}

using Face = std::array<Index, 3>;
Face sorted_face(const Tetrahedron& t, int k) {
  Face f;
  int n = 0;
  for (int i = 0; i < 4; ++i)
    if (i != k) f[n++] = t[i];
  std::sort(f.begin(), f.end());
  return f;
}

// Brute-force relations from the index arrays.
struct Reference {
  std::map<Face, std::vector<Index>> face_tets;
  std::vector<std::vector<Index>> vt;
  std::vector<bool> boundary_vertex;
  std::map<std::pair<Index, Index>, std::vector<Index>> edge_tets; // a < b, sorted
  std::set<std::pair<Index, Index>> boundary_edges;

  explicit Reference(const Mesh& m) : vt(m.points.size()), boundary_vertex(m.points.size(), false) {
    for (Index t = 0; t < m.tets.size(); ++t) {
      for (int k = 0; k < 4; ++k) {
        face_tets[sorted_face(m.tets[t], k)].push_back(t);
        vt[m.tets[t][k]].push_back(t);
        for (int l = k + 1; l < 4; ++l) edge_tets[std::minmax(m.tets[t][k], m.tets[t][l])].push_back(t);
      }
    }
    for (const auto& ft : face_tets)
      if (ft.second.size() == 1) {
        const Face& f = ft.first;
        for (Index v : f) boundary_vertex[v] = true;
        boundary_edges.insert({f[0], f[1]});
        boundary_edges.insert({f[0], f[2]});
        boundary_edges.insert({f[1], f[2]});
      }
  }
  std::array<Index, 4> neighbors(const Mesh& m, Index t) const {
    std::array<Index, 4> r;
    for (int k = 0; k < 4; ++k) {
      const std::vector<Index>& ts = face_tets.at(sorted_face(m.tets[t], k));
      r[k] = no_index;
      for (Index u : ts)
        if (u != t) r[k] = u;
    }
    return r;
  }
};

// The combinatorial validity of every cell and vertex of the TDS (what tds().is_valid() checks
// besides the Euler relation), and the orientation of the finite cells.
bool cells_and_vertices_valid(const Baseline& b) {
  const Baseline::Tds& tds = b.triangulation().tds();
  bool ok = tds.dimension() == 3;
  for (auto c = tds.cells_begin(); c != tds.cells_end(); ++c) ok = ok && tds.is_valid(c, true, 1);
  for (auto v = tds.vertices_begin(); v != tds.vertices_end(); ++v) ok = ok && tds.is_valid(v, true, 1);
  const Baseline::Triangulation& tr = b.triangulation();
  for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
    ok = ok && CGAL::orientation(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(),
                                 c->vertex(3)->point()) == CGAL::POSITIVE;
  return ok;
}

// cells - facets + edges - vertices of the whole TDS (0 for a combinatorial 3-sphere).
long euler_defect(const Baseline& b) {
  const Baseline::Tds& tds = b.triangulation().tds();
  return long(tds.number_of_cells()) - long(tds.number_of_facets()) + long(tds.number_of_edges()) -
         long(tds.number_of_vertices());
}

// Checks that `star` is the star of edge (a, b) in right-hand order around a -> b: each
// tetrahedron (a, b, from, to) positive, `to` of one = `from` of the next, cyclically if closed.
bool is_ordered_star(const Mesh& m, Index a, Index b, const std::vector<Index>& star, bool closed) {
  if (star.empty()) return false;
  std::vector<std::pair<Index, Index>> wings;
  for (Index t : star) {
    Index w[2];
    int n = 0;
    for (Index v : m.tets[t])
      if (v != a && v != b) {
        if (n == 2) return false;
        w[n++] = v;
      }
    if (n != 2) return false;
    const CGAL::Orientation o = CGAL::orientation(m.points[a], m.points[b], m.points[w[0]], m.points[w[1]]);
    wings.push_back(o == CGAL::POSITIVE ? std::make_pair(w[0], w[1]) : std::make_pair(w[1], w[0]));
  }
  for (std::size_t k = 0; k + 1 < wings.size(); ++k)
    if (wings[k].second != wings[k + 1].first) return false;
  return !closed || wings.back().second == wings.front().first;
}

// Every relation of `b` against brute force on `m`.
void check_against_reference(const Mesh& m, const Baseline& b) {
  const Reference ref(m);
  CHECK_EQUAL(b.number_of_finite_cells(), m.tets.size());
  // TT
  std::size_t tt_errors = 0;
  for (Index t = 0; t < m.tets.size(); ++t) tt_errors += b.tetrahedron_neighbors(t) != ref.neighbors(m, t);
  CHECK_EQUAL(tt_errors, std::size_t(0));
  // VT, by both entry points, and the boundary vertices
  std::size_t vt_errors = 0, boundary_errors = 0;
  for (Index v = 0; v < m.points.size(); ++v) {
    std::vector<Index> star;
    b.vertex_tetrahedra(v, std::back_inserter(star));
    std::sort(star.begin(), star.end());
    vt_errors += star != ref.vt[v];
    boundary_errors += b.is_boundary_vertex(v) != ref.boundary_vertex[v];
  }
  Index expected_v = 0;
  b.for_each_vertex_star([&](Index v, const std::vector<Index>& star) {
    vt_errors += v != expected_v++;
    std::vector<Index> s = star;
    std::sort(s.begin(), s.end());
    vt_errors += s != ref.vt[v];
  });
  vt_errors += expected_v != m.points.size();
  CHECK_EQUAL(vt_errors, std::size_t(0));
  CHECK_EQUAL(boundary_errors, std::size_t(0));
  // Edge stars: all edges once, ordered, boundary flag; edge_star() agrees
  std::size_t edges = 0, edge_errors = 0;
  b.for_each_edge_star([&](Index a, Index c, const std::vector<Index>& star, bool on_boundary) {
    ++edges;
    const auto it = ref.edge_tets.find({a, c});
    if (a >= c || it == ref.edge_tets.end()) {
      ++edge_errors;
      return;
    }
    std::vector<Index> s = star;
    std::sort(s.begin(), s.end());
    edge_errors += s != it->second;
    edge_errors += on_boundary != (ref.boundary_edges.count({a, c}) == 1);
    edge_errors += !is_ordered_star(m, a, c, star, !on_boundary);
    if (edges % 7 == 0) {
      bool bd = !on_boundary;
      edge_errors += b.edge_star(a, c, &bd) != star || bd != on_boundary;
      // the reverse edge turns the other way
      const std::vector<Index> r = b.edge_star(c, a);
      edge_errors += !is_ordered_star(m, c, a, r, !on_boundary);
    }
  });
  CHECK_EQUAL(edges, ref.edge_tets.size());
  CHECK_EQUAL(edge_errors, std::size_t(0));
}

void test_cube() {
  Mesh m;
  for (int i = 0; i < 8; ++i) m.points.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  m.tets.assign(std::begin(kuhn), std::end(kuhn));
  std::swap(m.tets[1][0], m.tets[1][1]); // some listed negatively...
  std::swap(m.tets[4][2], m.tets[4][3]);
  int negative = 0;
  for (const Tetrahedron& t : m.tets)
    negative +=
        CGAL::orientation(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]) == CGAL::NEGATIVE;
  CHECK(negative > 0 && negative < 6);

  const Baseline b(m.points, m.tets);
  CHECK(b.triangulation().tds().is_valid(false, 1));
  CHECK(cells_and_vertices_valid(b));
  CHECK_EQUAL(euler_defect(b), 0L);
  CHECK_EQUAL(b.number_of_finite_cells(), 6);
  CHECK_EQUAL(b.number_of_infinite_cells(), 12);
  CHECK_EQUAL(b.number_of_vertices(), 8);

  std::vector<Index> vt0, vt1;
  b.vertex_tetrahedra(0, std::back_inserter(vt0));
  b.vertex_tetrahedra(1, std::back_inserter(vt1));
  std::sort(vt0.begin(), vt0.end());
  std::sort(vt1.begin(), vt1.end());
  CHECK((vt0 == std::vector<Index>{0, 1, 2, 3, 4, 5}));
  CHECK((vt1 == std::vector<Index>{0, 1}));
  for (Index v = 0; v < 8; ++v) CHECK(b.is_boundary_vertex(v));

  // The diagonal (0, 7) is interior: a closed cycle of the six tetrahedra, consecutive ones
  // sharing a face.
  bool on_boundary = true;
  const std::vector<Index> diagonal = b.edge_star(0, 7, &on_boundary);
  CHECK(!on_boundary);
  CHECK_EQUAL(diagonal.size(), 6);
  CHECK_EQUAL(diagonal.front(), 0);
  auto share_face = [&](Index s, Index t) {
    const std::array<Index, 4> n = b.tetrahedron_neighbors(s);
    return std::find(n.begin(), n.end(), t) != n.end();
  };
  for (std::size_t k = 0; k < diagonal.size(); ++k) CHECK(share_face(diagonal[k], diagonal[(k + 1) % 6]));
  CHECK(is_ordered_star(m, 0, 7, diagonal, true));

  // A boundary edge: an open fan from one boundary face to the other.
  const std::vector<Index> fan = b.edge_star(0, 1, &on_boundary);
  CHECK(on_boundary);
  CHECK_EQUAL(fan.size(), 2);
  CHECK(share_face(fan[0], fan[1]));
  CHECK(is_ordered_star(m, 0, 1, fan, false));
  CHECK(b.edge_star(1, 2).empty()); // not an edge

  check_against_reference(m, b);

  const Baseline::Memory mem = b.memory();
  CHECK(mem.cells >= 18 * sizeof(Baseline::Cell));
  CHECK(mem.vertices >= 9 * sizeof(Baseline::Vertex));
}

void test_grid() {
  Mesh m = grid(10, 10, 10);
  m.points.emplace_back(-5, -5, -5); // a point used by no tetrahedron
  CHECK_EQUAL(m.tets.size(), 6000);
  const Baseline b(m.points, m.tets);
  CHECK(b.triangulation().tds().is_valid(false, 1));
  CHECK(cells_and_vertices_valid(b));
  CHECK_EQUAL(euler_defect(b), 0L);
  CHECK_EQUAL(b.number_of_vertices(), 11 * 11 * 11);
  CHECK_EQUAL(b.number_of_input_vertices(), 11 * 11 * 11 + 1);
  CHECK_EQUAL(b.vertex_handle(11 * 11 * 11), Baseline::Vertex_handle());
  CHECK(!b.is_boundary_vertex(11 * 11 * 11));
  check_against_reference(m, b);
}

void test_torus() {
  // A 5 x 5 x 3 block with the middle column of cubes removed: the boundary is a torus.
  const Mesh m = grid(5, 5, 3, [](int x, int y, int) { return x == 2 && y == 2; });
  const Baseline b(m.points, m.tets);
  CHECK(cells_and_vertices_valid(b));
  // cone over a genus-1 surface: C - F + E - V = -genus (tds().is_valid() expects 0)
  CHECK_EQUAL(euler_defect(b), -1L);
  check_against_reference(m, b);
}

void test_two_components() {
  Mesh m = grid(2, 2, 2);
  const Mesh other = grid(
      2, 2, 2, [](int, int, int) { return false; }, 10.0);
  const Index offset = Index(m.points.size());
  m.points.insert(m.points.end(), other.points.begin(), other.points.end());
  for (Tetrahedron t : other.tets) {
    for (Index& v : t) v += offset;
    m.tets.push_back(t);
  }
  const Baseline b(m.points, m.tets);
  CHECK(cells_and_vertices_valid(b));
  CHECK_EQUAL(euler_defect(b), 1L); // two balls coned to one vertex
  check_against_reference(m, b);
}

bool throws(const Mesh& m) {
  try {
    const Baseline b(m.points, m.tets);
  } catch (const std::runtime_error& e) {
    std::cout << "  rejected as expected: " << e.what() << "\n";
    return true;
  }
  return false;
}

void test_invalid_inputs() {
  const std::vector<Point_3> p = {{0, 0, 0},  {1, 0, 0},  {0, 1, 0},  {0, 0, 1}, {1, 1, 1},
                                  {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}, {1, 1, 0}, {0.5, 0.5, 0}};
  CHECK(throws(Mesh{p, {}}));                           // empty
  CHECK(throws(Mesh{p, {{0, 1, 2, 42}}}));              // index out of range
  CHECK(throws(Mesh{p, {{0, 1, 2, 2}}}));               // repeated vertex
  CHECK(throws(Mesh{p, {{0, 1, 2, 8}}}));               // flat
  CHECK(throws(Mesh{p, {{0, 1, 2, 3}, {0, 5, 6, 7}}})); // pinched at vertex 0
  CHECK(throws(Mesh{p, {{0, 1, 2, 3}, {0, 1, 6, 7}}})); // two tetrahedra sharing only edge (0, 1)
  CHECK(throws(Mesh{p, {{0, 1, 2, 3}, {0, 1, 2, 4}}})); // same side of face (0, 1, 2)
  CHECK(throws(Mesh{p, {{0, 1, 2, 3}, {1, 0, 2, 3}}})); // duplicated
  CHECK(throws(Mesh{p, {{0, 1, 2, 3}, {0, 1, 2, 7}, {0, 1, 2, 4}}})); // face shared by three
  // Valid: two tetrahedra on both sides of a face.
  const Mesh ok{p, {{0, 1, 2, 3}, {0, 1, 2, 7}}};
  CHECK(!throws(ok));
  const Baseline b(ok.points, ok.tets);
  CHECK(b.triangulation().tds().is_valid(false, 1));
  check_against_reference(ok, b);
}

void bench() {
  const Mesh m = grid(100, 100, 20);
  std::cout << "bench: grid 100 x 100 x 20: " << m.points.size() << " vertices, " << m.tets.size()
            << " tetrahedra\n";
  using Clock = std::chrono::steady_clock;
  double best = 1e30;
  std::size_t bytes = 0;
  for (int rep = 0; rep < 3; ++rep) {
    const auto t0 = Clock::now();
    const Baseline b(m.points, m.tets);
    const double s = std::chrono::duration<double>(Clock::now() - t0).count();
    best = std::min(best, s);
    bytes = b.memory_bytes();
    std::cout << "  build " << s << " s\n";
    if (rep == 2) {
      const Baseline::Memory mem = b.memory();
      std::cout << "  memory: vertices " << mem.vertices << " B, cells " << mem.cells << " B ("
                << b.number_of_finite_cells() << " finite + " << b.number_of_infinite_cells()
                << " infinite), index maps " << mem.index_maps << " B; total " << mem.total()
                << " B = " << double(mem.total()) / double(m.tets.size()) << " B/tet\n";
      std::size_t sum = 0;
      double vt_best = 1e30, et_best = 1e30;
      for (int r = 0; r < 3; ++r) {
        auto t1 = Clock::now();
        b.for_each_vertex_star([&](Index, const std::vector<Index>& s) { sum += s.size(); });
        vt_best = std::min(vt_best, std::chrono::duration<double>(Clock::now() - t1).count());
        t1 = Clock::now();
        b.for_each_edge_star([&](Index, Index, const std::vector<Index>& s, bool) { sum += s.size(); });
        et_best = std::min(et_best, std::chrono::duration<double>(Clock::now() - t1).count());
      }
      std::cout << "  all vertex stars " << vt_best << " s, all edge stars " << et_best << " s (checksum "
                << sum << ")\n";
    }
  }
  std::cout << "  sizeof Vertex " << sizeof(Baseline::Vertex) << ", Cell " << sizeof(Baseline::Cell)
            << " (plain Triangulation_3<Epick>: " << sizeof(CGAL::Triangulation_3<Baseline::Kernel>::Vertex)
            << ", " << sizeof(CGAL::Triangulation_3<Baseline::Kernel>::Cell) << ")\n";
  std::cout << "  best build " << best << " s, " << double(bytes) / double(m.tets.size()) << " B/tet\n";
}

} // namespace

// test_mesh_quality.cpp
void test_mesh_quality(const prstar_test::Data_folders& data);

int main(int argc, char** argv) {
  const prstar_test::Data_folders data(argc, argv);
  test_cube();
  test_grid();
  test_torus();
  test_two_components();
  test_invalid_inputs();
  test_mesh_quality(data);
  if (argc > 1 && std::string(argv[1]) == "--bench") bench();
  return prstar_test::summary("test_cgal_baseline");
}
