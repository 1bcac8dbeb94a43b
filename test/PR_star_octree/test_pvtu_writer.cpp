// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project
//
// The writer of distributed meshes (IO/internal/pvtu_writer.h): a .pvtu and one .vtu piece per part.
//
//   test_pvtu_writer DIR   builds a 6 x 2 x 2 lattice of cubes cut in 6 tetrahedra each, splits it
//                          by hand in 3 pieces (slabs of 2 cubes along x) with one layer of ghost
//                          cells (the cells sharing a vertex with an owned one) and their points,
//                          writes DIR/lattice.pvtu and DIR/lattice_{0,1,2}.vtu, reads every piece
//                          back with IO::read_tetrahedral_mesh and compares; checks the errors
//                          (nothing left behind, an existing file unchanged); writes
//                          DIR/expected.json (the counts of the whole mesh) for check_pvtu.py,
//                          which reads the .pvtu with VTK.

#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/IO/internal/pvtu_writer.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "test_harness.h"

namespace IO = CGAL::PR_star_octree::IO;
namespace fs = std::filesystem;
using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;

namespace {

constexpr std::size_t nx = 6, ny = 2, nz = 2, number_of_pieces = 3;

/// The whole mesh: points in x-fastest order, 6 tetrahedra per cube, the owner of each cube.
struct Whole {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::uint32_t, 4>> tetrahedra;
  std::vector<std::size_t> owner; // per tetrahedron
};

Whole lattice() {
  Whole w;
  const auto id = [](std::size_t x, std::size_t y, std::size_t z) {
    return std::uint32_t((z * (ny + 1) + y) * (nx + 1) + x);
  };
  for (std::size_t z = 0; z <= nz; ++z)
    for (std::size_t y = 0; y <= ny; ++y)
      for (std::size_t x = 0; x <= nx; ++x) w.points.push_back({double(x), double(y), double(z)});
  static const int split[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                  {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  for (std::size_t z = 0; z < nz; ++z)
    for (std::size_t y = 0; y < ny; ++y)
      for (std::size_t x = 0; x < nx; ++x) {
        const std::array<std::uint32_t, 8> c = {
            id(x, y, z),     id(x + 1, y, z),     id(x + 1, y + 1, z),     id(x, y + 1, z),
            id(x, y, z + 1), id(x + 1, y, z + 1), id(x + 1, y + 1, z + 1), id(x, y + 1, z + 1)};
        for (const auto& q : split) {
          w.tetrahedra.push_back({c[q[0]], c[q[1]], c[q[2]], c[q[3]]});
          w.owner.push_back(x / (nx / number_of_pieces));
        }
      }
  return w;
}

/// One piece with its arrays (what a rank would hold).
struct Piece {
  std::vector<double> xyz, height, centroid_x;
  std::vector<std::uint32_t> tetrahedra;
  std::vector<std::uint8_t> point_ghosts, cell_ghosts;
  std::vector<std::int64_t> global_point_ids, global_cell_ids;
  std::vector<int> labels;

  /// `v.data()`, never null (an empty vector's may be: the array would be missing from the piece)
  template <class T>
  static const T* data(const std::vector<T>& v) {
    static const T none{};
    return v.empty() ? &none : v.data();
  }

  IO::internal::Vtu_piece view() const {
    IO::internal::Vtu_piece v;
    v.xyz = data(xyz);
    v.number_of_points = global_point_ids.size();
    v.tetrahedra = data(tetrahedra);
    v.number_of_tetrahedra = global_cell_ids.size();
    v.point_ghosts = data(point_ghosts);
    v.cell_ghosts = data(cell_ghosts);
    v.global_point_ids = data(global_point_ids);
    v.global_cell_ids = data(global_cell_ids);
    v.labels = data(labels);
    v.label_name = "label";
    v.point_arrays = {{"height", height.data()}}; // (null when empty: allowed)
    v.cell_arrays = {{"centroid_x", centroid_x.data()}};
    return v;
  }
};

/// The owner of each vertex: the smallest piece owning a cell around it.
std::vector<std::size_t> vertex_owners(const Whole& w) {
  std::vector<std::size_t> owner(w.points.size(), number_of_pieces);
  for (std::size_t t = 0; t < w.tetrahedra.size(); ++t)
    for (std::uint32_t v : w.tetrahedra[t]) owner[v] = std::min(owner[v], w.owner[t]);
  return owner;
}

Piece make_piece(const Whole& w, const std::vector<std::size_t>& vertex_owner, std::size_t r) {
  // The vertices of the owned cells, then the cells touching one of them (owned and ghost).
  std::vector<bool> near(w.points.size(), false);
  for (std::size_t t = 0; t < w.tetrahedra.size(); ++t)
    if (w.owner[t] == r)
      for (std::uint32_t v : w.tetrahedra[t]) near[v] = true;
  std::vector<std::size_t> cells;
  for (std::size_t t = 0; t < w.tetrahedra.size(); ++t)
    for (std::uint32_t v : w.tetrahedra[t])
      if (near[v]) {
        cells.push_back(t);
        break;
      }
  std::map<std::uint32_t, std::uint32_t> local; // global -> local vertex, by global id
  for (std::size_t t : cells)
    for (std::uint32_t v : w.tetrahedra[t]) local.emplace(v, 0);
  Piece p;
  for (auto& [g, l] : local) {
    l = std::uint32_t(p.global_point_ids.size());
    p.global_point_ids.push_back(g);
    p.xyz.insert(p.xyz.end(), w.points[g].begin(), w.points[g].end());
    p.height.push_back(0.5 * w.points[g][2]);
    p.point_ghosts.push_back(vertex_owner[g] == r ? 0 : IO::internal::vtk_duplicate_point);
  }
  for (std::size_t t : cells) {
    double cx = 0;
    for (std::uint32_t v : w.tetrahedra[t]) {
      p.tetrahedra.push_back(local.at(v));
      cx += 0.25 * w.points[v][0];
    }
    p.global_cell_ids.push_back(std::int64_t(t));
    p.cell_ghosts.push_back(w.owner[t] == r ? 0 : IO::internal::vtk_duplicate_cell);
    p.labels.push_back(int(1 + w.owner[t]));
    p.centroid_x.push_back(cx);
  }
  return p;
}

template <class T>
void check_array(const Mesh& m, bool point, const std::string& name, const std::vector<T>& expected) {
  const auto& arrays = point ? m.point_data : m.cell_data;
  const CGAL::PR_star_octree::Data_array* found = nullptr;
  for (const auto& a : arrays)
    if (a.name == name) found = &a;
  CHECK_MSG(found != nullptr, "no array " << name);
  if (found == nullptr) return;
  CHECK_EQUAL(found->values.size(), expected.size());
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < expected.size() && i < found->values.size(); ++i)
    if (found->values[i] != double(expected[i])) ++wrong;
  CHECK_MSG(wrong == 0, name << ": " << wrong << " values differ");
}

void check_read_back(const std::string& file, const Piece& p) {
  prstar_test::Failure_context context(file);
  Mesh m;
  IO::read_tetrahedral_mesh(file, m);
  CHECK_EQUAL(m.points.size(), p.global_point_ids.size());
  CHECK_EQUAL(m.tetrahedra.size(), p.global_cell_ids.size());
  if (m.points.size() != p.global_point_ids.size() || m.tetrahedra.size() != p.global_cell_ids.size()) return;
  std::size_t wrong_points = 0, wrong_tets = 0;
  for (std::size_t i = 0; i < m.points.size(); ++i)
    if (m.points[i].x() != p.xyz[3 * i] || m.points[i].y() != p.xyz[3 * i + 1] ||
        m.points[i].z() != p.xyz[3 * i + 2])
      ++wrong_points;
  for (std::size_t t = 0; t < m.tetrahedra.size(); ++t)
    for (int k = 0; k < 4; ++k)
      if (m.tetrahedra[t][k] != p.tetrahedra[4 * t + k]) ++wrong_tets;
  CHECK_EQUAL(wrong_points, std::size_t(0));
  CHECK_EQUAL(wrong_tets, std::size_t(0));
  CHECK(m.tetrahedron_labels == p.labels);
  CHECK_EQUAL(m.point_data.size(), std::size_t(3)); // GlobalPointIds, vtkGhostType, height
  CHECK_EQUAL(m.cell_data.size(), std::size_t(3));  // GlobalCellIds, vtkGhostType, centroid_x
  check_array(m, true, "GlobalPointIds", p.global_point_ids);
  check_array(m, true, "vtkGhostType", p.point_ghosts);
  check_array(m, true, "height", p.height);
  check_array(m, false, "GlobalCellIds", p.global_cell_ids);
  check_array(m, false, "vtkGhostType", p.cell_ghosts);
  check_array(m, false, "centroid_x", p.centroid_x);
}

std::string file_text(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// No temporary file left in `dir`.
void check_no_temporary(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    CHECK_MSG(e.path().filename().string().find(".prstar-tmp-") == std::string::npos,
              "temporary left behind: " << e.path());
}

void test_errors(const fs::path& dir, const Piece& p) {
  const std::string file = (dir / "lattice_0.vtu").string();
  const std::string before = file_text(file);
  CHECK(!before.empty());
  Piece bad = p;
  bad.tetrahedra[5] = std::uint32_t(bad.global_point_ids.size());
  CHECK_THROWS(IO::Write_error, "vertex index", IO::internal::write_vtu_piece(file, bad.view()));
  bad = p;
  bad.xyz[4] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS(IO::Write_error, "non-finite coordinate", IO::internal::write_vtu_piece(file, bad.view()));
  IO::internal::Vtu_piece v = p.view();
  v.cell_arrays.push_back({"vtkGhostType", p.centroid_x.data()});
  CHECK_THROWS(IO::Write_error, "two cell-data arrays", IO::internal::write_vtu_piece(file, v));
  v = p.view();
  v.point_arrays.push_back({"missing", nullptr});
  CHECK_THROWS(IO::Write_error, "no values", IO::internal::write_vtu_piece(file, v));
  v = p.view();
  v.xyz = nullptr;
  CHECK_THROWS(IO::Write_error, "no coordinates", IO::internal::write_vtu_piece(file, v));
  CHECK_THROWS(IO::Write_error, "directory", IO::internal::write_vtu_piece(dir.string(), p.view()));
  CHECK_THROWS(IO::Write_error, "cannot open",
               IO::internal::write_pvtu((dir / "no_such_folder" / "x.pvtu").string(), {"a.vtu"}, p.view()));
  CHECK(file_text(file) == before);
  check_no_temporary(dir);
}

/// A piece without any optional array, and an empty piece: still valid files.
void test_minimal(const fs::path& dir, const Whole& w) {
  IO::internal::Vtu_piece v;
  std::vector<double> xyz;
  for (const auto& q : w.points) xyz.insert(xyz.end(), q.begin(), q.end());
  std::vector<std::uint32_t> tets;
  for (const auto& t : w.tetrahedra) tets.insert(tets.end(), t.begin(), t.end());
  v.xyz = xyz.data();
  v.number_of_points = w.points.size();
  v.tetrahedra = tets.data();
  v.number_of_tetrahedra = w.tetrahedra.size();
  const std::string whole = (dir / "whole.vtu").string();
  IO::internal::write_vtu_piece(whole, v);
  Mesh m;
  IO::read_tetrahedral_mesh(whole, m);
  CHECK_EQUAL(m.points.size(), w.points.size());
  CHECK_EQUAL(m.tetrahedra.size(), w.tetrahedra.size());
  CHECK(m.point_data.empty() && m.cell_data.empty() && m.tetrahedron_labels.empty());
  IO::internal::write_pvtu((dir / "whole.pvtu").string(), {"whole.vtu"}, v);
  const std::string text = file_text((dir / "whole.pvtu").string());
  CHECK(text.find("GhostLevel=\"0\"") != std::string::npos);
  CHECK(text.find("PPointData") == std::string::npos && text.find("PCellData") == std::string::npos);
  // A piece of a part without any cell, from empty vectors: every array written with no values;
  // listed in with_empty.pvtu beside the 3 pieces (check_pvtu.py).
  const Piece nothing;
  IO::internal::write_vtu_piece((dir / "empty_piece.vtu").string(), nothing.view());
  const std::string empty_text = file_text((dir / "empty_piece.vtu").string());
  CHECK(empty_text.find("Name=\"centroid_x\"") != std::string::npos);
  CHECK(empty_text.find("Name=\"GlobalCellIds\"") != std::string::npos);
  IO::internal::write_vtu_piece((dir / "empty.vtu").string(), IO::internal::Vtu_piece());
  CHECK(file_text((dir / "empty.vtu").string()).find("NumberOfPoints=\"0\" NumberOfCells=\"0\"") !=
        std::string::npos);
}

} // namespace

int main(int argc, char** argv) {
  const fs::path dir = argc > 1 ? fs::path(argv[1]) : fs::current_path() / "pvtu_writer";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const Whole w = lattice();
  const std::vector<std::size_t> vertex_owner = vertex_owners(w);
  std::vector<Piece> pieces;
  std::vector<std::string> names;
  std::size_t ghost_cells = 0;
  try {
    for (std::size_t r = 0; r < number_of_pieces; ++r) {
      pieces.push_back(make_piece(w, vertex_owner, r));
      for (std::uint8_t g : pieces.back().cell_ghosts) ghost_cells += g;
      names.push_back("lattice_" + std::to_string(r) + ".vtu");
      IO::internal::write_vtu_piece((dir / names.back()).string(), pieces.back().view());
    }
    IO::internal::write_pvtu((dir / "lattice.pvtu").string(), names, pieces.front().view());
    CHECK(ghost_cells > 0);
    for (std::size_t r = 0; r < number_of_pieces; ++r) check_read_back((dir / names[r]).string(), pieces[r]);
    const std::string pvtu = file_text((dir / "lattice.pvtu").string());
    CHECK(pvtu.find("GhostLevel=\"1\"") != std::string::npos);
    CHECK(pvtu.find("<PPointData GlobalIds=\"GlobalPointIds\">") != std::string::npos);
    CHECK(pvtu.find("<PCellData GlobalIds=\"GlobalCellIds\" Scalars=\"label\">") != std::string::npos);
    CHECK(pvtu.find("<Piece Source=\"lattice_2.vtu\"/>") != std::string::npos);
    // IdType="1": VTK reads the Int64 ids as a vtkIdTypeArray (a vtkLongLongArray without it)
    CHECK(pvtu.find("<PDataArray type=\"Int64\" IdType=\"1\" Name=\"GlobalCellIds\"/>") != std::string::npos);
    names.push_back("empty_piece.vtu");
    IO::internal::write_pvtu((dir / "with_empty.pvtu").string(), names, pieces.front().view());
    test_errors(dir, pieces.front());
    test_minimal(dir, w);
    check_no_temporary(dir);
  } catch (const std::exception& e) {
    FAIL("unexpected exception: " << e.what());
  }
  std::ofstream expected(dir / "expected.json");
  expected << "{\"points\": " << w.points.size() << ", \"cells\": " << w.tetrahedra.size()
           << ", \"pieces\": " << number_of_pieces << ", \"ghost_cells\": " << ghost_cells
           << ", \"volume\": " << nx * ny * nz << "}\n";
  return prstar_test::summary("test_pvtu_writer");
}
