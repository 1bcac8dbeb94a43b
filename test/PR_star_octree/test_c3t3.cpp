// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The Mesh_complex_3_in_triangulation_3 input adapter, checked against CGAL's own iteration over
// the complex, and the mesh generator (Mesh_3 and TetGen) checked with geometric invariants.
//
// Usage: test_c3t3 [generated_data_dir] [shared_data_dir]   (both ignored: the test makes its inputs)

#include "generate.h"

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/Index_arrays_input.h>
#include <CGAL/PR_star_octree/Mesh_complex_3_input.h>
#include <CGAL/PR_star_octree/simplification.h>

#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/make_mesh_3.h>

#include <boost/property_map/property_map.hpp>

#include "test_harness.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <unordered_map>
#include <vector>

namespace {

using C3t3 = prstar::Generate_c3t3;
using Tr = C3t3::Triangulation;
using Vertex_handle = Tr::Vertex_handle;
using Cell_handle = Tr::Cell_handle;
using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;

const double pi = 3.14159265358979323846;

prstar::Generate_options options(const std::string& shape, double cell_size) {
  prstar::Generate_options o;
  o.shape = shape;
  o.cell_size = cell_size;
  o.quiet = true;
  return o;
}

// The adapter against the complex, for one generated C3T3.
// `convex`: for a convex domain every finite cell may lie in the complex; otherwise some must not.
void check_adapter(const C3t3& c3t3, const std::string& name, bool convex) {
  std::cerr << "adapter on " << name << std::endl;
  const Tr& tr = c3t3.triangulation();
  const auto input = CGAL::PR_star_octree::make_input(c3t3);
  const std::size_t nv = input.number_of_vertices(), nt = input.number_of_tetrahedra();

  // the tetrahedra are exactly the cells in the complex, in CGAL's iteration order
  CHECK_EQUAL(nt, static_cast<std::size_t>(c3t3.number_of_cells_in_complex()));
  CHECK(nt > 1000);
  std::size_t t = 0;
  for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c, ++t)
    CHECK(t < nt && input.cell_handle(t) == Cell_handle(c));
  CHECK_EQUAL(t, nt);

  // cells outside the domain are left out (they exist in the hole of the torus)
  std::size_t outside = 0;
  for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
    if (!c3t3.is_in_complex(c)) ++outside;
  CHECK(convex || outside > 0);

  // the vertices are the vertices of the cells in the complex, each once
  std::set<Vertex_handle> from_cells;
  for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    for (int k = 0; k < 4; ++k) from_cells.insert(c->vertex(k));
  std::set<Vertex_handle> from_input;
  for (std::size_t i = 0; i < nv; ++i) from_input.insert(input.vertex_handle(i));
  CHECK(from_input.size() == nv); // no vertex twice
  CHECK_EQUAL(from_input, from_cells);
  // ... and not the corners of the complex (none for these smooth shapes)
  CHECK(static_cast<std::size_t>(c3t3.number_of_vertices_in_complex()) != nv);
  CHECK(nv <= static_cast<std::size_t>(tr.number_of_vertices()));

  // each tetrahedron maps back to its cell's vertices, in order; the subdomain is the cell's
  bool order_ok = true, subdomain_ok = true, orientation_ok = true, first_seen_ok = true;
  std::size_t next_new = 0;
  for (t = 0; t < nt; ++t) {
    const std::array<std::size_t, 4> tet = input.tetrahedron(t);
    const Cell_handle c = input.cell_handle(t);
    for (int k = 0; k < 4; ++k) {
      if (tet[k] >= nv || input.vertex_handle(tet[k]) != c->vertex(k)) order_ok = false;
      // vertices are numbered in order of first appearance
      if (tet[k] > next_new) first_seen_ok = false;
      if (tet[k] == next_new) ++next_new;
    }
    if (input.subdomain_index(t) != c3t3.subdomain_index(c) || input.subdomain_index(t) != 1)
      subdomain_ok = false;
    if (CGAL::orientation(input.point(tet[0]), input.point(tet[1]), input.point(tet[2]),
                          input.point(tet[3])) != CGAL::POSITIVE)
      orientation_ok = false;
  }
  CHECK(order_ok);
  CHECK(subdomain_ok);
  CHECK(orientation_ok);
  CHECK(first_seen_ok && next_new == nv);

  // points are the bare points of the weighted points
  bool points_ok = true;
  for (std::size_t i = 0; i < nv; ++i) {
    const Tr::Weighted_point& wp = tr.point(input.vertex_handle(i));
    if (input.point(i) != wp.point()) points_ok = false;
  }
  CHECK(points_ok);

  // no scalar field by default; a functor and a property map give one
  CHECK(!input.has_scalar_field());
  const auto with_functor = CGAL::PR_star_octree::make_input(
      c3t3, [&tr](Vertex_handle v) { return tr.point(v).x() + 2 * tr.point(v).z(); });
  std::unordered_map<Vertex_handle, double> values;
  for (std::size_t i = 0; i < nv; ++i) values[input.vertex_handle(i)] = double(i);
  const auto with_map = CGAL::PR_star_octree::make_input(c3t3, boost::make_assoc_property_map(values));
  CHECK(with_functor.has_scalar_field() && with_map.has_scalar_field());
  bool scalars_ok = with_functor.number_of_vertices() == nv && with_map.number_of_vertices() == nv;
  for (std::size_t i = 0; scalars_ok && i < nv; ++i) {
    const Point p = input.point(i);
    if (with_functor.scalar(i) != p.x() + 2 * p.z() || with_map.scalar(i) != double(i)) scalars_ok = false;
  }
  CHECK(scalars_ok);

  // the conversion to arrays gives the adapter's numbering and the subdomain labels
  const Mesh mesh = CGAL::PR_star_octree::c3t3_to_indexed_tetrahedral_mesh(c3t3);
  CHECK(mesh.number_of_vertices() == nv && mesh.number_of_tetrahedra() == nt);
  CHECK_EQUAL(mesh.tetrahedron_labels.size(), nt);
  bool same = mesh.number_of_vertices() == nv && mesh.number_of_tetrahedra() == nt;
  for (std::size_t i = 0; same && i < nv; ++i) same = mesh.points[i] == input.point(i);
  for (t = 0; same && t < nt; ++t) {
    const std::array<std::size_t, 4> tet = input.tetrahedron(t);
    for (int k = 0; k < 4; ++k) same = same && mesh.tetrahedra[t][k] == tet[k];
    same = same && mesh.tetrahedron_labels[t] == 1;
  }
  CHECK(same);

  // with Index_arrays_input.h also included, make_input() still picks the right adapter
  const auto from_arrays = CGAL::PR_star_octree::make_input(mesh.points, mesh.tetrahedra);
  const auto from_mesh = CGAL::PR_star_octree::make_input(mesh);
  CHECK(from_arrays.number_of_tetrahedra() == nt && from_mesh.number_of_vertices() == nv);

  // the adapter is a PRStarOctreeInputMesh: build the octree from it and map back
  const CGAL::PR_star_octree_3<> octree(with_functor, CGAL::PR_star_octree::parameters::bucket_size(20));
  CHECK(octree.number_of_vertices() == nv && octree.number_of_tetrahedra() == nt);
  CHECK(octree.has_scalar_field());
  bool octree_ok = octree.number_of_vertices() == nv && octree.number_of_tetrahedra() == nt;
  for (std::size_t v = 0; octree_ok && v < nv; ++v) {
    const std::size_t o = octree.original_vertex(static_cast<std::uint32_t>(v));
    octree_ok = octree.point(static_cast<std::uint32_t>(v)) == input.point(o) &&
                octree.scalars()[v] == with_functor.scalar(o);
  }
  for (t = 0; octree_ok && t < nt; ++t) {
    const auto tet = octree.tetrahedron(static_cast<std::uint32_t>(t));
    const std::array<std::size_t, 4> original =
        input.tetrahedron(octree.original_tetrahedron(static_cast<std::uint32_t>(t)));
    for (int k = 0; k < 4; ++k) octree_ok = octree_ok && octree.original_vertex(tet[k]) == original[k];
  }
  CHECK(octree_ok);
}

// Validity of an indexed mesh: indices in range, every vertex used, every tetrahedron positively
// oriented (exact predicate); returns the volume.
double check_mesh(const Mesh& mesh, const std::string& name) {
  std::cerr << "mesh " << name << ": " << mesh.number_of_vertices() << " vertices, "
            << mesh.number_of_tetrahedra() << " tetrahedra" << std::endl;
  CHECK(mesh.number_of_tetrahedra() > 100);
  CHECK_EQUAL(mesh.tetrahedron_labels.size(), mesh.number_of_tetrahedra());
  std::vector<bool> used(mesh.number_of_vertices(), false);
  bool in_range = true, positive = true;
  double volume = 0;
  for (const Mesh::Tetrahedron& t : mesh.tetrahedra) {
    for (auto v : t) {
      if (v >= mesh.number_of_vertices())
        in_range = false;
      else
        used[v] = true;
    }
    if (!in_range) break;
    const Point &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]],
                &d = mesh.points[t[3]];
    if (CGAL::orientation(a, b, c, d) != CGAL::POSITIVE) positive = false;
    volume += CGAL::volume(a, b, c, d);
  }
  CHECK(in_range);
  CHECK(positive);
  CHECK_EQUAL(std::find(used.begin(), used.end(), false), used.end());
  return volume;
}

// `f()` must throw std::runtime_error whose message contains `part`.
template <class F>
void check_throws(F f, const std::string& part) {
  CHECK_THROWS(std::runtime_error, part, f());
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

// the unit cube [0,1]^3, 12 outward-oriented triangles
const char* cube_off = "OFF\n8 12 0\n"
                       "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                       "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n"
                       "3 2 3 7\n3 2 7 6\n3 1 2 6\n3 1 6 5\n3 0 4 7\n3 0 7 3\n";

} // namespace

// Labels through simplification: a unit ball in two subdomains (1 above z = 0, 2 below) meshed by
// Mesh_3, simplified to half its tetrahedra with the defaults.  Both subdomains survive with their
// labels; the interface stays on z = 0 (as close as Mesh_3 put it); the volume of each label
// changes by no more than the area of its boundary times the error bound; and
// build_mesh_complex() gives back a C3T3 with the same cells per subdomain.
void test_two_subdomains_simplified() {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Domain = CGAL::Labeled_mesh_domain_3<K>;
  using Tr2 = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
  using C3t3_2 = CGAL::Mesh_complex_3_in_triangulation_3<Tr2>;
  using Criteria = CGAL::Mesh_criteria_3<Tr2>;
  namespace mp = CGAL::parameters;
  auto label = [](const K::Point_3& p) {
    if (p.x() * p.x() + p.y() * p.y() + p.z() * p.z() >= 1) return 0;
    return p.z() > 0 ? 1 : 2;
  };
  const std::function<int(const K::Point_3&)> f = label;
  const Domain domain(mp::function = f, mp::bounding_object = K::Sphere_3(CGAL::ORIGIN, 4.),
                      mp::relative_error_bound = 1e-7);
  const Criteria criteria(mp::facet_angle = 25, mp::facet_size = 0.12, mp::facet_distance = 0.01,
                          mp::cell_radius_edge_ratio = 3, mp::cell_size = 0.12);
  CGAL::get_default_random() = CGAL::Random(7);
  const C3t3_2 c3t3 = CGAL::make_mesh_3<C3t3_2>(domain, criteria, mp::no_perturb(), mp::no_exude());
  const auto mesh = CGAL::PR_star_octree::c3t3_to_indexed_tetrahedral_mesh(c3t3);
  const auto res =
      CGAL::PR_star_octree::simplify(mesh, CGAL::PR_star_octree::parameters::target_fraction(0.5));
  const auto& out = res.mesh;
  std::cout << "two subdomains: " << mesh.number_of_tetrahedra() << " -> " << out.number_of_tetrahedra()
            << " tetrahedra" << std::endl;
  CHECK(res.statistics.stop == CGAL::PR_star_octree::Simplification_stop::TARGET_REACHED);
  CHECK_EQUAL(out.tetrahedron_labels.size(), out.tetrahedra.size());
  // Volumes and boundary areas per label, and the interface's height, by brute force.
  auto measure = [](const auto& m, double volume[3], double area[3], double& max_abs_z) {
    std::map<std::array<std::size_t, 3>, std::vector<int>> faces;
    for (std::size_t t = 0; t < m.tetrahedra.size(); ++t) {
      const auto& c = m.tetrahedra[t];
      const int l = m.tetrahedron_labels[t];
      volume[l] += CGAL::volume(m.points[c[0]], m.points[c[1]], m.points[c[2]], m.points[c[3]]);
      for (int j = 0; j < 4; ++j) {
        std::array<std::size_t, 3> f{{c[(j + 1) % 4], c[(j + 2) % 4], c[(j + 3) % 4]}};
        std::sort(f.begin(), f.end());
        faces[f].push_back(l);
      }
    }
    max_abs_z = 0;
    for (const auto& f : faces) {
      const double a =
          std::sqrt(CGAL::squared_area(m.points[f.first[0]], m.points[f.first[1]], m.points[f.first[2]]));
      const std::vector<int>& l = f.second;
      if (l.size() == 1) area[l[0]] += a;
      if (l.size() == 2 && l[0] != l[1]) {
        area[l[0]] += a;
        area[l[1]] += a;
        for (std::size_t v : f.first) max_abs_z = std::max(max_abs_z, std::abs(m.points[v].z()));
      }
    }
  };
  double vin[3] = {0, 0, 0}, ain[3] = {0, 0, 0}, vout[3] = {0, 0, 0}, aout[3] = {0, 0, 0}, zin = 0, zout = 0;
  measure(mesh, vin, ain, zin);
  measure(out, vout, aout, zout);
  const double bound = res.statistics.max_boundary_error;
  for (int l = 1; l <= 2; ++l) {
    CHECK(vout[l] > 0);
    std::cout << "  label " << l << ": volume " << vin[l] << " -> " << vout[l] << " (allowed change "
              << ain[l] * bound << ")" << std::endl;
    CHECK(std::abs(vout[l] - vin[l]) <= ain[l] * bound);
  }
  CHECK(zout <= zin + 1e-12); // the interface vertices are the input's interface vertices
  std::cout << "  interface: |z| <= " << zin << " (input), " << zout << " (output)" << std::endl;
  // Back to a C3T3.
  C3t3_2 back;
  CHECK(CGAL::PR_star_octree::build_mesh_complex(out, back));
  CHECK(back.triangulation()
            .tds()
            .is_valid()); // combinatorially (a simplified mesh is no regular triangulation)
  CHECK_EQUAL(static_cast<std::size_t>(back.number_of_cells_in_complex()), out.number_of_tetrahedra());
  std::size_t cells[3] = {0, 0, 0}, tets[3] = {0, 0, 0};
  for (auto c = back.cells_in_complex_begin(); c != back.cells_in_complex_end(); ++c)
    ++cells[back.subdomain_index(c)];
  for (int l : out.tetrahedron_labels) ++tets[l];
  CHECK(cells[1] == tets[1] && cells[2] == tets[2]);
  CHECK(back.number_of_facets_in_complex() > 0); // boundary and interface as surface patches
}

int main(int, char**) {
  test_two_subdomains_simplified();
  // 1. The adapter on Mesh_3 output (~18K and ~10K tetrahedra).
  const C3t3 sphere = prstar::generate_c3t3(options("sphere", 0.1));
  check_adapter(sphere, "sphere", true);
  const C3t3 torus = prstar::generate_c3t3(options("torus", 0.1));
  check_adapter(torus, "torus", false);

  // 2. generate_mesh: valid, deterministic, the right volume (Mesh_3 and TetGen).
  const Mesh m1 = prstar::generate_mesh(options("sphere", 0.1));
  const Mesh m2 = prstar::generate_mesh(options("sphere", 0.1));
  CHECK_EQUAL(m1.points, m2.points);
  CHECK_EQUAL(m1.tetrahedra, m2.tetrahedra);
  CHECK_EQUAL(m1.number_of_tetrahedra(), static_cast<std::size_t>(sphere.number_of_cells_in_complex()));
  CHECK_CLOSE(check_mesh(m1, "sphere (Mesh_3)"), 4. / 3. * pi, 0.03);

  prstar::Generate_options tg = options("sphere", 0.1);
  tg.tetgen = true;
  const Mesh t1 = prstar::generate_mesh(tg);
  CHECK_CLOSE(check_mesh(t1, "sphere (TetGen)"), 4. / 3. * pi, 0.03);
  const Mesh t2 = prstar::generate_mesh(tg);
  CHECK(t1.points == t2.points && t1.tetrahedra == t2.tetrahedra);

  CHECK_CLOSE(check_mesh(prstar::generate_mesh(options("torus", 0.1)), "torus (Mesh_3)"),
              2 * pi * pi * 1. * 0.16, 0.03);
  // two overlapping balls and a separate one: both components must be meshed (the separate
  // ball alone is 4/3 pi 0.35^3 = 0.18, i.e. 13% of the total)
  {
    // volume of the union: two balls minus their lens, plus the third ball
    const double r1 = 0.6, r2 = 0.5, d = 0.9;
    const double lens = pi * (r1 + r2 - d) * (r1 + r2 - d) *
                        (d * d + 2 * d * r2 - 3 * r2 * r2 + 2 * d * r1 + 6 * r1 * r2 - 3 * r1 * r1) /
                        (12 * d);
    const double expected = 4. / 3. * pi * (r1 * r1 * r1 + r2 * r2 * r2 + 0.35 * 0.35 * 0.35) - lens;
    CHECK_CLOSE(check_mesh(prstar::generate_mesh(options("balls", 0.06)), "balls (Mesh_3)"), expected, 0.03);
  }
  CHECK(!prstar::implicit_shapes().empty());
  for (const auto& shape : prstar::implicit_shapes()) CHECK(!shape.first.empty() && !shape.second.empty());

  // 3. A polyhedral domain from an OFF file.
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("prstar_test_c3t3_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string cube = (dir / "cube.off").string();
  write_file(cube, cube_off);
  prstar::Generate_options co;
  co.surface_file = cube;
  co.cell_size = 0.08;
  co.quiet = true;
  // Mesh_3 rounds the unprotected edges and corners a little
  CHECK_CLOSE(check_mesh(prstar::generate_mesh(co), "cube.off (Mesh_3)"), 1., 0.03);
  co.tetgen = true; // TetGen keeps the input triangles: exact volume
  CHECK_CLOSE(check_mesh(prstar::generate_mesh(co), "cube.off (TetGen)"), 1., 1e-9);

  // 4. Errors.
  check_throws([] { prstar::generate_mesh(options("dodecahedron", 0.1)); }, "unknown shape 'dodecahedron'");
  check_throws([] { prstar::generate_mesh(options("sphere", 0)); }, "cell size");
  check_throws([] { prstar::generate_mesh(options("sphere", -1)); }, "cell size");
  check_throws([] { prstar::generate_c3t3(options("sphere", 0)); }, "cell size");
  check_throws([] { prstar::generate_mesh(options("", 0.1)); }, "either");
  check_throws(
      [&] {
        prstar::Generate_options o = options("sphere", 0.1);
        o.surface_file = cube;
        prstar::generate_mesh(o);
      },
      "either");
  check_throws(
      [] {
        prstar::Generate_options o = options("sphere", 0.1);
        o.tetgen = true;
        prstar::generate_c3t3(o);
      },
      "TetGen");
  const std::string missing = (dir / "missing.off").string();
  check_throws(
      [&] {
        prstar::Generate_options o = options("", 0.1);
        o.surface_file = missing;
        prstar::generate_mesh(o);
      },
      "cannot open surface file");
  const std::string open_surface = (dir / "open.off").string();
  write_file(open_surface, "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n");
  check_throws(
      [&] {
        prstar::Generate_options o = options("", 0.1);
        o.surface_file = open_surface;
        prstar::generate_mesh(o);
      },
      "not a closed surface");
  const std::string quads = (dir / "quads.off").string();
  write_file(quads, "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3\n");
  check_throws(
      [&] {
        prstar::Generate_options o = options("", 0.1);
        o.surface_file = quads;
        prstar::generate_mesh(o);
      },
      "not a triangle mesh");
  fs::remove_all(dir);

  return prstar_test::summary("test_c3t3");
}
