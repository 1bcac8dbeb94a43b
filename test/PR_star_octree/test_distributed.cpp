// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project
//
// The distributed octree (MPI), run by ctest with mpiexec -np 1, 2, 3, 4: on each mesh, the
// distributed counts, vertex types, curvature and validity against (a) closed forms of the lattice
// and (b) the one-process PR_star_octree_3 of the whole mesh (built by every rank, the meshes are
// small): counts equal, per-vertex values identical bit for bit.  Meshes: a jittered lattice with a
// scalar field, a lattice with most vertices in one corner, two lattices touching at one vertex
// (non-manifold across ranks), a single tetrahedron (ranks with nothing), and every file given on
// the command line read with IO::read_mesh_part() (an appended-raw .vtu: read in byte ranges).

#include "test_harness.h"

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/Distributed_octree_3.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/IO/distributed.h>
#include <CGAL/PR_star_octree/IO/internal/pvtu_writer.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/distortion.h>
#include <CGAL/PR_star_octree/distributed_algorithms.h>
#include <CGAL/PR_star_octree/validity.h>

#include <CGAL/property_map.h>
#include <mpi.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace PRS = CGAL::PR_star_octree;
namespace params = CGAL::PR_star_octree::parameters;
using Mesh = PRS::Indexed_tetrahedral_mesh<>;
using Octree = CGAL::PR_star_octree_3<>;
using Distributed = PRS::Distributed_octree_3<>;

namespace {

int rank_ = 0, ranks_ = 1;

// The lattice of n^3 cubes cut into the 6 Kuhn tetrahedra, point (i, j, k) at warp(i, j, k), with
// the scalar field x^2 + y - z (jitter: a deterministic perturbation inside each cell).
template <class Warp>
Mesh lattice(int n, Warp warp) {
  Mesh m;
  auto id = [n](int i, int j, int k) { return std::uint32_t((k * (n + 1) + j) * (n + 1) + i); };
  std::vector<double> f;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const std::array<double, 3> p = warp(i, j, k);
        m.points.emplace_back(p[0], p[1], p[2]);
        f.push_back(p[0] * p[0] + p[1] - p[2]);
      }
  m.point_data.push_back({"f", f});
  static const int kuhn[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& axes : kuhn) {
          std::array<int, 3> c{{i, j, k}};
          Mesh::Tetrahedron t;
          t[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[axes[s]];
            t[s + 1] = id(c[0], c[1], c[2]);
          }
          const bool odd = ((axes[0] > axes[1]) != (axes[1] > axes[2])) != (axes[0] > axes[2]);
          if (odd) std::swap(t[2], t[3]); // positively oriented
          m.tetrahedra.push_back(t);
          m.tetrahedron_labels.push_back(1 + (i + j + k) % 3);
        }
  return m;
}

std::array<double, 3> jittered(int i, int j, int k, int n) {
  auto jitter = [n](int a, int b, int c) {
    if (a == 0 || a == n) return 0.;
    return 0.1 * std::sin(12.9898 * a + 78.233 * b + 37.719 * c);
  };
  return {{i + jitter(i, j, k), j + jitter(j, k, i), k + jitter(k, i, j)}};
}

// This rank's block of `m` (vertices and tetrahedra cut evenly, as IO::read_mesh_part does).
PRS::Distributed_mesh_part part_of(const Mesh& m) {
  PRS::Distributed_mesh_part part;
  const auto vb = PRS::IO::internal::block(m.points.size(), rank_, ranks_);
  const auto tb = PRS::IO::internal::block(m.tetrahedra.size(), rank_, ranks_);
  part.first_vertex = vb.first;
  for (auto v = vb.first; v < vb.second; ++v)
    part.coordinates.insert(part.coordinates.end(), {m.points[v].x(), m.points[v].y(), m.points[v].z()});
  for (const auto& a : m.point_data) {
    part.point_array_names.push_back(a.name);
    part.point_arrays.emplace_back(a.values.begin() + std::ptrdiff_t(vb.first),
                                   a.values.begin() + std::ptrdiff_t(vb.second));
  }
  for (auto t = tb.first; t < tb.second; ++t) {
    const auto& c = m.tetrahedra[t];
    part.tetrahedra.push_back({{c[0], c[1], c[2], c[3]}});
    if (!m.tetrahedron_labels.empty()) part.tetrahedron_labels.push_back(m.tetrahedron_labels[t]);
  }
  return part;
}

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// Everything the distributed octree computes, against the one-process octree of `m` built with the
// same parameters (`compact`: the compact tetrahedron array; `float32`: coordinates rounded to
// floats, which each rank does to the doubles it read; without it, floats when the file's were,
// `m.float32_points`).
void compare(const std::string& name, const Mesh& m, PRS::Distributed_mesh_part part, std::size_t kv,
             bool compact = false, bool float32 = false) {
  prstar_test::Failure_context context(name + " (" + std::to_string(ranks_) + " ranks, k_v " +
                                       std::to_string(kv) + (compact ? ", compact" : "") +
                                       (float32 ? ", float32" : "") + ")");
  const auto np = params::bucket_size(kv).compact_tetrahedra(compact).coordinate_precision(
      float32 ? PRS::Coordinate_precision::float32 : PRS::Coordinate_precision::as_input);
  const Octree one(PRS::make_input(m), np);
  const Distributed d(std::move(part), np);
  CHECK_EQUAL(d.local_octree().is_compact(), compact);
  CHECK_EQUAL(d.local_octree().has_float_coordinates(), float32 || m.float32_points);
  CHECK_EQUAL(one.has_float_coordinates(), float32 || m.float32_points);
  CHECK_EQUAL(d.number_of_vertices(), m.points.size());
  CHECK_EQUAL(d.number_of_tetrahedra(), m.tetrahedra.size());

  // every vertex owned once, and every tetrahedron counted once
  std::uint64_t owned = d.number_of_owned_vertices(), all_owned = 0;
  MPI_Allreduce(&owned, &all_owned, 1, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
  CHECK_EQUAL(all_owned, m.points.size());
  std::uint64_t counted = 0, all_counted = 0;
  for (Octree::Index t = 0; t < d.local_octree().number_of_tetrahedra(); ++t)
    counted += d.counts_tetrahedron(t);
  MPI_Allreduce(&counted, &all_counted, 1, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
  CHECK_EQUAL(all_counted, m.tetrahedra.size());
  // the stars of the owned vertices are complete: their sizes are those of the whole mesh
  std::vector<std::size_t> star(m.points.size(), 0);
  for (const auto& c : m.tetrahedra)
    for (auto v : c) ++star[v];
  std::vector<std::size_t> local_star(d.number_of_local_vertices(), 0);
  for (const auto& c : d.local_octree().tetrahedra())
    for (auto v : c) ++local_star[d.local_octree().original_vertex(v)];
  for (std::size_t i = 0; i < d.number_of_owned_vertices(); ++i)
    if (local_star[i] != star[d.global_vertex_id(i)]) {
      FAIL("owned vertex " << d.global_vertex_id(i) << ": star of " << local_star[i]
                           << " tetrahedra, expected " << star[d.global_vertex_id(i)]);
      break;
    }

  const PRS::Simplex_counts c1 = PRS::count_simplices(one), cd = PRS::count_simplices(d);
  CHECK_EQUAL(cd.vertices, c1.vertices);
  CHECK_EQUAL(cd.edges, c1.edges);
  CHECK_EQUAL(cd.triangles, c1.triangles);
  CHECK_EQUAL(cd.boundary_triangles, c1.boundary_triangles);
  CHECK_EQUAL(cd.nonmanifold_triangles, c1.nonmanifold_triangles);
  CHECK_EQUAL(cd.euler_characteristic(), c1.euler_characteristic());

  std::vector<PRS::Vertex_type> t1(m.points.size()), td(d.number_of_owned_vertices());
  const PRS::Boundary_counts b1 = PRS::compute_boundary(one, CGAL::make_property_map(t1));
  const PRS::Boundary_counts bd = PRS::compute_boundary(d, CGAL::make_property_map(td));
  CHECK_EQUAL(bd.interior_vertices, b1.interior_vertices);
  CHECK_EQUAL(bd.boundary_vertices, b1.boundary_vertices);
  CHECK_EQUAL(bd.nonmanifold_vertices, b1.nonmanifold_vertices);
  CHECK_EQUAL(bd.unreferenced_vertices, b1.unreferenced_vertices);
  CHECK_EQUAL(bd.boundary_triangles, b1.boundary_triangles);
  CHECK_EQUAL(bd.boundary_tetrahedra, b1.boundary_tetrahedra);
  CHECK_EQUAL(bd.boundary_face_tetrahedra, b1.boundary_face_tetrahedra);
  std::size_t type_mismatches = 0;
  for (std::size_t i = 0; i < td.size(); ++i) type_mismatches += td[i] != t1[d.global_vertex_id(i)];
  CHECK_EQUAL(type_mismatches, 0u);

  if (!m.point_data.empty()) {
    std::vector<PRS::Vertex_curvature> k1(m.points.size()), kd(d.number_of_owned_vertices());
    PRS::compute_curvature(one, CGAL::make_property_map(m.point_data[0].values), CGAL::make_property_map(k1));
    const PRS::Vertex_type_counts kc =
        PRS::compute_curvature(d, CGAL::make_property_map(d.point_array(0)), CGAL::make_property_map(kd));
    CHECK_EQUAL(kc.boundary_vertices, b1.boundary_vertices);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < kd.size(); ++i) {
      const auto& a = kd[i];
      const auto& b = k1[d.global_vertex_id(i)];
      differ += bits(a.distortion) != bits(b.distortion) ||
                bits(a.domain_curvature) != bits(b.domain_curvature) ||
                bits(a.solid_angle_sum_3) != bits(b.solid_angle_sum_3) || a.type != b.type;
    }
    CHECK_EQUAL(differ, 0u); // bit for bit
  }

  const PRS::Validity_result v1 = PRS::check_validity(one), vd = PRS::check_validity(d);
  CHECK_EQUAL(vd.valid, v1.valid);
  CHECK_EQUAL(vd.positive, v1.positive);
  CHECK_EQUAL(vd.negative, v1.negative);
  CHECK_EQUAL(vd.degenerate, v1.degenerate);
  CHECK_EQUAL(vd.nonmanifold_vertices, v1.nonmanifold_vertices);
  CHECK_EQUAL(vd.boundary_components, v1.boundary_components);
  CHECK_EQUAL(vd.euler_characteristic, v1.euler_characteristic);

  // ghost values: each rank's ghosts receive their owners' global ids
  std::vector<std::uint64_t> ids(d.number_of_local_vertices(), 0);
  for (std::size_t i = 0; i < d.number_of_owned_vertices(); ++i) ids[i] = d.global_vertex_id(i);
  d.update_ghosts(ids);
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < ids.size(); ++i) wrong += ids[i] != d.global_vertex_id(i);
  CHECK_EQUAL(wrong, 0u);
}

void test_lattices() {
  for (int n : {1, 6}) {
    const Mesh m = lattice(n, [n](int i, int j, int k) { return jittered(i, j, k, n); });
    // closed forms first: the distributed counts are those of a cube of n^3 cells
    {
      prstar_test::Failure_context context("closed forms, lattice " + std::to_string(n));
      const Distributed d(part_of(m), params::bucket_size(8));
      const PRS::Simplex_counts c = PRS::count_simplices(d);
      const std::size_t N = std::size_t(n), V = (N + 1) * (N + 1) * (N + 1);
      CHECK_EQUAL(c.vertices, V);
      CHECK_EQUAL(c.tetrahedra, 6 * N * N * N);
      CHECK_EQUAL(c.boundary_triangles, 12 * N * N);
      CHECK_EQUAL(c.euler_characteristic(), 1);
      std::vector<PRS::Vertex_type> types(d.number_of_owned_vertices());
      const PRS::Boundary_counts b = PRS::compute_boundary(d, CGAL::make_property_map(types));
      CHECK_EQUAL(b.boundary_vertices, V - (N - 1) * (N - 1) * (N - 1));
      CHECK_EQUAL(b.nonmanifold_vertices, 0u);
      const PRS::Validity_result v = PRS::check_validity(d);
      CHECK(v.valid);
      CHECK_EQUAL(v.boundary_components, 1u);
    }
    for (std::size_t kv : {std::size_t(1), std::size_t(8), std::size_t(1000)})
      compare("lattice " + std::to_string(n), m, part_of(m), kv);
    // the local octrees compact, with float coordinates (jittered: the rounding changes them)
    compare("lattice " + std::to_string(n), m, part_of(m), 8, true, false);
    compare("lattice " + std::to_string(n), m, part_of(m), 8, false, true);
    compare("lattice " + std::to_string(n), m, part_of(m), 1000, true, true);
  }
  // most vertices in one corner: (x/n)^4 on each axis
  const int n = 7;
  const Mesh skewed = lattice(n, [](int i, int j, int k) {
    auto w = [](int a) { return std::pow(a / 7., 4.); };
    return std::array<double, 3>{{w(i), w(j), w(k)}};
  });
  compare("corner-heavy lattice", skewed, part_of(skewed), 4);
}

// Two lattices sharing one corner: that vertex is non-manifold, its two sheets on any ranks.
void test_nonmanifold() {
  const int n = 3;
  Mesh a = lattice(n, [](int i, int j, int k) {
    return std::array<double, 3>{{double(i), double(j), double(k)}};
  });
  const Mesh b = lattice(n, [](int i, int j, int k) {
    return std::array<double, 3>{{double(i + 3), double(j + 3), double(k + 3)}};
  });
  const std::uint32_t offset = std::uint32_t(a.points.size()) - 1; // b's vertex 0 is a's last
  for (std::size_t v = 1; v < b.points.size(); ++v) {
    a.points.push_back(b.points[v]);
    a.point_data[0].values.push_back(b.point_data[0].values[v]);
  }
  for (std::size_t t = 0; t < b.tetrahedra.size(); ++t) {
    Mesh::Tetrahedron c = b.tetrahedra[t];
    for (auto& v : c) v = v == 0 ? offset : v + offset;
    a.tetrahedra.push_back(c);
    a.tetrahedron_labels.push_back(b.tetrahedron_labels[t]);
  }
  compare("two lattices touching at a vertex", a, part_of(a), 4);
  const Octree one(PRS::make_input(a));
  CHECK_EQUAL(PRS::check_validity(one).nonmanifold_vertices, 1u); // the test means something
}

// One tetrahedron: with 2 to 4 ranks, some ranks own nothing.
void test_tiny() {
  Mesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.tetrahedra = {{{0, 1, 2, 3}}};
  compare("one tetrahedron", m, part_of(m), 1);
  Mesh empty;
  const Distributed d(part_of(empty));
  CHECK_EQUAL(PRS::count_simplices(d).vertices, 0u);
}

// A part that is not a mesh: every rank gets the same exception, none hangs.
void test_bad_parts() {
  Mesh m = lattice(2, [](int i, int j, int k) {
    return std::array<double, 3>{{double(i), double(j), double(k)}};
  });
  PRS::Distributed_mesh_part part = part_of(m);
  if (rank_ == ranks_ - 1) part.tetrahedra.push_back({{0, 1, 2, 1000}});
  if (rank_ == ranks_ - 1 && !part.tetrahedron_labels.empty()) part.tetrahedron_labels.push_back(1);
  CHECK_THROWS(std::runtime_error, "has vertex 1000", Distributed(std::move(part)));
}

// The files given (files, or folders of files): read_mesh_part against read_tetrahedral_mesh.
void test_files(const std::vector<std::string>& paths) {
  std::vector<std::string> files;
  for (const std::string& path : paths) {
    if (std::filesystem::is_regular_file(path)) {
      files.push_back(path);
      continue;
    }
    if (!std::filesystem::is_directory(path)) {
      prstar_test::skip("test data " + path);
      continue;
    }
    std::vector<std::string> in_folder;
    for (const auto& e : std::filesystem::directory_iterator(path)) {
      const std::string ext = e.path().extension().string();
      if (ext == ".vtu" || ext == ".mesh" || ext == ".msh" || ext == ".vtk")
        in_folder.push_back(e.path().string());
    }
    std::sort(in_folder.begin(), in_folder.end());
    files.insert(files.end(), in_folder.begin(), in_folder.end());
  }
  for (const std::string& f : files) {
    Mesh m;
    try {
      PRS::IO::read_tetrahedral_mesh(f, m);
    } catch (const std::exception&) {
      continue; // the malformed inputs of other tests
    }
    if (m.tetrahedra.size() > 300000) continue;
    compare(std::filesystem::path(f).filename().string(), m, PRS::IO::read_mesh_part(f), 50);
  }
}

// Files whose points are 32-bit floats: the local octrees store floats by default, as one process
// does, whichever reader the ranks use (an appended-raw .vtu read in byte ranges, a compressed
// .vtu and a binary .vtk read by rank 0 and scattered).
void test_float32_files() {
  namespace fs = std::filesystem;
  const int n = 6;
  Mesh m = lattice(n, [n](int i, int j, int k) { return jittered(i, j, k, n); });
  for (auto& q : m.points)
    q = Mesh::Point_3(double(float(q.x())), double(float(q.y())), double(float(q.z())));
  m.float32_points = true;
  const std::string folder = "distributed_float32_" + std::to_string(ranks_);
  if (rank_ == 0) {
    fs::create_directories(folder);
    PRS::IO::write_tetrahedral_mesh(folder + "/raw.vtu", m, params::compression(PRS::IO::Compression::none));
    PRS::IO::write_tetrahedral_mesh(folder + "/zlib.vtu", m);
    PRS::IO::write_tetrahedral_mesh(folder + "/binary.vtk", m, CGAL::parameters::use_binary_mode(true));
  }
  MPI_Barrier(MPI_COMM_WORLD);
  for (const std::string f : {"raw.vtu", "zlib.vtu", "binary.vtk"}) {
    Mesh back;
    PRS::IO::read_tetrahedral_mesh(folder + "/" + f, back);
    CHECK(back.float32_points);
    compare("float32 points, " + f, back, PRS::IO::read_mesh_part(folder + "/" + f), 8);
    compare("float32 points, " + f, back, PRS::IO::read_mesh_part(folder + "/" + f), 8, true);
  }
}

// A .pvtu read back: (a) written by write_pvtu (ghost cells, global ids: the vertices keep their
// ids, everything is compared), (b) pieces without ghosts or global ids, cut by hand (the copies of
// the shared points merged by coordinates: the counts are compared).
void test_pvtu() {
  namespace fs = std::filesystem;
  const int n = 5;
  const Mesh m = lattice(n, [n](int i, int j, int k) { return jittered(i, j, k, n); });
  const std::string folder = "distributed_pvtu_" + std::to_string(ranks_);
  if (rank_ == 0) fs::create_directories(folder);
  MPI_Barrier(MPI_COMM_WORLD);
  {
    const std::string file = folder + "/written.pvtu";
    {
      const Distributed d(part_of(m), params::bucket_size(8));
      PRS::IO::write_pvtu(file, d, {});
    }
    compare("a .pvtu with ghosts and global ids", m, PRS::IO::read_mesh_part(file), 8);
  }
  for (int pieces : {1, 3, 5}) {
    const std::string file = folder + "/cut_" + std::to_string(pieces) + ".pvtu";
    if (rank_ == 0) {
      std::vector<std::string> names;
      for (int k = 0; k < pieces; ++k) {
        // the tetrahedra of piece k and their vertices, numbered in the piece
        std::vector<std::int64_t> local(m.points.size(), -1);
        std::vector<double> xyz, f;
        std::vector<std::uint32_t> tets;
        std::vector<int> labels;
        for (std::size_t t = k; t < m.tetrahedra.size(); t += std::size_t(pieces)) {
          for (auto v : m.tetrahedra[t]) {
            if (local[v] < 0) {
              local[v] = std::int64_t(xyz.size() / 3);
              xyz.insert(xyz.end(), {m.points[v].x(), m.points[v].y(), m.points[v].z()});
              f.push_back(m.point_data[0].values[v]);
            }
            tets.push_back(std::uint32_t(local[v]));
          }
          labels.push_back(m.tetrahedron_labels[t]);
        }
        PRS::IO::internal::Vtu_piece piece;
        piece.xyz = xyz.data();
        piece.number_of_points = xyz.size() / 3;
        piece.tetrahedra = tets.data();
        piece.number_of_tetrahedra = tets.size() / 4;
        piece.labels = labels.data();
        piece.point_arrays = {{"f", f.data()}};
        names.push_back("cut_" + std::to_string(pieces) + "_" + std::to_string(k) + ".vtu");
        PRS::IO::internal::write_vtu_piece(folder + "/" + names.back(), piece);
        if (k + 1 == pieces) PRS::IO::internal::write_pvtu(file, names, piece);
      }
    }
    MPI_Barrier(MPI_COMM_WORLD);
    prstar_test::Failure_context context(file + " on " + std::to_string(ranks_) + " ranks");
    const Octree one(PRS::make_input(m), params::bucket_size(8));
    const Distributed d(PRS::IO::read_mesh_part(file), params::bucket_size(8));
    CHECK_EQUAL(d.number_of_vertices(), m.points.size()); // the copies merged
    CHECK_EQUAL(d.number_of_tetrahedra(), m.tetrahedra.size());
    const PRS::Simplex_counts c1 = PRS::count_simplices(one), cd = PRS::count_simplices(d);
    CHECK_EQUAL(cd.edges, c1.edges);
    CHECK_EQUAL(cd.triangles, c1.triangles);
    CHECK_EQUAL(cd.boundary_triangles, c1.boundary_triangles);
    CHECK_EQUAL(cd.euler_characteristic(), c1.euler_characteristic());
    std::vector<PRS::Vertex_type> types(d.number_of_owned_vertices());
    CHECK_EQUAL(PRS::compute_boundary(d, CGAL::make_property_map(types)).boundary_vertices,
                PRS::compute_boundary(one, CGAL::Constant_property_map<std::size_t, PRS::Vertex_type>())
                    .boundary_vertices);
    CHECK_EQUAL(d.point_array_names().size(), 1u);
    // each vertex's field value came with it: f = x^2 + y - z at its coordinates
    std::size_t wrong = 0;
    const auto& octree = d.local_octree();
    for (Octree::Index v = 0; v < octree.number_of_vertices(); ++v) {
      const auto q = octree.coordinates(octree.point(v));
      wrong += d.point_array(0)[octree.original_vertex(v)] != q[0] * q[0] + q[1] - q[2];
    }
    CHECK_EQUAL(wrong, 0u);
    CHECK(d.has_tetrahedron_labels());
  }
}

} // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks_);
  test_lattices();
  test_nonmanifold();
  test_tiny();
  test_bad_parts();
  test_pvtu();
  test_float32_files();
  test_files(std::vector<std::string>(argv + 1, argv + argc));
  // every rank's failures count; rank 0 reports
  long long failures = prstar_test::failures(), all = 0;
  MPI_Allreduce(&failures, &all, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  int code = 0;
  if (rank_ == 0)
    code = prstar_test::summary("test_distributed (" + std::to_string(ranks_) + " ranks)");
  else
    code = failures ? 1 : 0;
  if (all && !code) code = 1;
  MPI_Finalize();
  return code;
}
