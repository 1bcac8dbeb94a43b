// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project
//
// Ranges of a .vtu file (IO/internal/vtu_ranges.h), part of test_io_vtk: files written here by hand
// (either byte order, UInt32 and UInt64 headers, Int32/Int64/UInt32/UInt64 connectivity, Float32
// and Float64 points, mixed cells, point arrays of several types, label arrays chosen as the
// whole-file reader chooses them) and by the package's writer, read in 1, 2, 3, 7 ranges, in
// ranges with empty ones and in ranges of one cell: the concatenation must be what
// `read_tetrahedral_mesh` reads from the whole file.  Files whose ranges cannot be read (compressed,
// ascii, base64, several pieces) must say why; malformed and truncated files throw `Read_error`.
// Also the piece files of a .pvtu file.

#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/IO/internal/vtu_ranges.h>
#include <CGAL/PR_star_octree/IO/vtu_source.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "test_harness.h"

namespace {

namespace IO = CGAL::PR_star_octree::IO;
namespace NP = CGAL::PR_star_octree::parameters;
using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;
using Reader = IO::internal::Vtu_range_reader;
namespace fs = std::filesystem;

/// The cells of a hand-made file: a 2 x 2 x 2 block of cubes cut in 6 tetrahedra each, with a
/// triangle, a hexahedron, a quadratic tetrahedron and a vertex among them (unless
/// `tetrahedra_only`).
struct Grid {
  std::vector<double> xyz;
  std::vector<long long> connectivity, offsets;
  std::vector<int> types;
  std::vector<std::uint64_t> tet_cells; // the indices of the tetrahedra
};

Grid make_grid(bool tetrahedra_only = false) {
  Grid g;
  const int k = 3;
  for (int z = 0; z < k; ++z)
    for (int y = 0; y < k; ++y)
      for (int x = 0; x < k; ++x) g.xyz.insert(g.xyz.end(), {x * 1.5, y * 0.75 - 1, z * 0.1});
  const auto id = [&](int x, int y, int z) { return (z * k + y) * k + x; };
  const auto add = [&](int type, std::vector<long long> v) {
    if (tetrahedra_only && type != 10) return;
    if (type == 10) g.tet_cells.push_back(g.types.size());
    g.connectivity.insert(g.connectivity.end(), v.begin(), v.end());
    g.offsets.push_back(static_cast<long long>(g.connectivity.size()));
    g.types.push_back(type);
  };
  static const int t[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                              {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  int cube = 0;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x, ++cube) {
        const long long c[8] = {
            id(x, y, z),     id(x + 1, y, z),     id(x + 1, y + 1, z),     id(x, y + 1, z),
            id(x, y, z + 1), id(x + 1, y, z + 1), id(x + 1, y + 1, z + 1), id(x, y + 1, z + 1)};
        for (const auto& q : t) add(10, {c[q[0]], c[q[1]], c[q[2]], c[q[3]]});
        if (cube == 0) add(5, {c[0], c[1], c[4]});
        if (cube == 3) add(12, {c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]});
        if (cube == 5) add(24, {c[0], c[1], c[2], c[6], c[3], c[4], c[5], c[7], 0, 1});
      }
  add(1, {5});
  return g;
}

/// How a hand-made file is written.
struct Spec {
  bool big_endian = false;
  bool header64 = false;
  std::string conn_type = "Int64";
  bool points64 = true;
  int labels = 1; // 0 none, 1 Int32 'CellEntityIds' after a Float64 'label' that is not integers,
                  // 2 Float64 'labels' of integers, 3 UInt8 'MaterialIds'
  std::string encoding = "raw";
  std::string compressor; // written as the attribute only (the data are not compressed)
  bool two_pieces = false;
};

void put_value(std::string& out, std::uint64_t bits, std::size_t size, bool big_endian) {
  for (std::size_t i = 0; i < size; ++i)
    out += static_cast<char>((bits >> (8 * (big_endian ? size - 1 - i : i))) & 0xff);
}
std::uint64_t double_bits(double d) {
  std::uint64_t b;
  std::memcpy(&b, &d, 8);
  return b;
}
std::uint64_t float_bits(double d) {
  const float f = static_cast<float>(d);
  std::uint32_t b;
  std::memcpy(&b, &f, 4);
  return b;
}

std::string base64(const std::string& bytes) {
  static const char* a = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string r;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const unsigned b0 = static_cast<unsigned char>(bytes[i]);
    const unsigned b1 = i + 1 < bytes.size() ? static_cast<unsigned char>(bytes[i + 1]) : 0;
    const unsigned b2 = i + 2 < bytes.size() ? static_cast<unsigned char>(bytes[i + 2]) : 0;
    const unsigned v = (b0 << 16) | (b1 << 8) | b2;
    r += a[v >> 18];
    r += a[(v >> 12) & 63];
    r += i + 1 < bytes.size() ? a[(v >> 6) & 63] : '=';
    r += i + 2 < bytes.size() ? a[v & 63] : '=';
  }
  return r;
}

/// The text of a .vtu file of `g`, its arrays appended as `s` says.
std::string make_vtu(const Grid& g, const Spec& s) {
  const bool be = s.big_endian;
  const std::size_t nv = g.xyz.size() / 3, nc = g.types.size();
  std::string appended;
  const auto array = [&](const std::string& attributes, std::size_t size, std::size_t n, auto bits) {
    std::string raw;
    put_value(raw, n * size, s.header64 ? 8 : 4, be);
    for (std::size_t i = 0; i < n; ++i) put_value(raw, bits(i), size, be);
    const std::string e = "<DataArray " + attributes + " format=\"appended\" offset=\"" +
                          std::to_string(appended.size()) + "\"/>\n";
    appended += s.encoding == "raw" ? raw : base64(raw);
    return e;
  };
  const std::size_t cs = s.conn_type.find("64") != std::string::npos ? 8 : 4;
  std::string piece = "<Piece NumberOfPoints=\"" + std::to_string(nv) + "\" NumberOfCells=\"" +
                      std::to_string(nc) + "\">\n<PointData Scalars=\"height\">\n";
  piece += array("type=\"Float64\" Name=\"height\"", 8, nv,
                 [&](std::size_t i) { return double_bits(g.xyz[3 * i + 2] * 3); });
  piece += array("type=\"Float32\" Name=\"velocity\" NumberOfComponents=\"3\"", 4, 3 * nv,
                 [&](std::size_t i) { return float_bits(g.xyz[i]); });
  piece += array("type=\"Int16\" Name=\"temperature\"", 2, nv,
                 [&](std::size_t i) { return std::uint64_t(std::uint16_t(std::int16_t(100 - 7 * int(i)))); });
  piece += array("type=\"Float32\"", 4, nv, [&](std::size_t i) { return float_bits(0.1 * double(i)); });
  piece +=
      array("type=\"UInt64\" Name=\"ids\"", 8, nv, [&](std::size_t i) { return std::uint64_t(1000 + i); });
  piece += "</PointData>\n<CellData>\n";
  if (s.labels == 1) {
    piece +=
        array("type=\"Float64\" Name=\"label\"", 8, nc, [&](std::size_t i) { return double_bits(i + 0.5); });
    piece += array("type=\"Int32\" Name=\"CellEntityIds\"", 4, nc,
                   [&](std::size_t i) { return std::uint64_t(std::uint32_t(std::int32_t(3 - int(i % 5)))); });
  } else if (s.labels == 2) {
    piece += array("type=\"Float64\" Name=\"labels\"", 8, nc,
                   [&](std::size_t i) { return double_bits(double(i % 4) - 1); });
  } else if (s.labels == 3) {
    piece += array("type=\"UInt8\" Name=\"MaterialIds\"", 1, nc,
                   [&](std::size_t i) { return std::uint64_t(i % 3 + 1); });
  }
  piece += array("type=\"Float64\" Name=\"pressure\"", 8, nc,
                 [&](std::size_t i) { return double_bits(i * 0.25); });
  piece += "</CellData>\n<Points>\n";
  piece +=
      array(std::string("type=\"") + (s.points64 ? "Float64" : "Float32") + "\" NumberOfComponents=\"3\"",
            s.points64 ? 8 : 4, 3 * nv,
            [&](std::size_t i) { return s.points64 ? double_bits(g.xyz[i]) : float_bits(g.xyz[i]); });
  piece += "</Points>\n<Cells>\n";
  piece += array("type=\"" + s.conn_type + "\" Name=\"connectivity\"", cs, g.connectivity.size(),
                 [&](std::size_t i) { return std::uint64_t(g.connectivity[i]); });
  piece += array("type=\"" + s.conn_type + "\" Name=\"offsets\"", cs, nc,
                 [&](std::size_t i) { return std::uint64_t(g.offsets[i]); });
  piece +=
      array("type=\"UInt8\" Name=\"types\"", 1, nc, [&](std::size_t i) { return std::uint64_t(g.types[i]); });
  piece += "</Cells>\n</Piece>\n";
  std::string t = "<?xml version=\"1.0\"?>\n<!-- ranges -->\n<VTKFile type=\"UnstructuredGrid\" "
                  "version=\"1.0\" byte_order=\"";
  t += be ? "BigEndian" : "LittleEndian";
  t += std::string("\" header_type=\"") + (s.header64 ? "UInt64" : "UInt32") + "\"";
  if (!s.compressor.empty()) t += " compressor=\"" + s.compressor + "\"";
  t += ">\n<UnstructuredGrid>\n" + piece + (s.two_pieces ? piece : std::string()) + "</UnstructuredGrid>\n";
  t += "<AppendedData encoding=\"" + s.encoding + "\">\n   _" + appended + "\n</AppendedData>\n</VTKFile>\n";
  return t;
}

fs::path tmp_dir;

std::string write_file(const std::string& name, const std::string& text) {
  const std::string f = (tmp_dir / name).string();
  std::ofstream out(f, std::ios::binary);
  out << text;
  return f;
}

/// What the ranges gave, concatenated.
struct Read {
  std::vector<double> xyz;
  std::vector<std::vector<double>> arrays;
  std::vector<std::uint64_t> tets, cell_ids;
  std::vector<int> labels;
  std::map<std::string, std::size_t> skipped;
};

/// The bounds of `k` ranges of `[0, n)` of nearly equal sizes.
std::vector<std::uint64_t> split(std::uint64_t n, std::uint64_t k) {
  std::vector<std::uint64_t> b;
  for (std::uint64_t i = 0; i <= k; ++i) b.push_back(n * i / k);
  return b;
}

Read read_ranges(const Reader& r, const std::vector<std::uint64_t>& points,
                 const std::vector<std::uint64_t>& cells) {
  Read out;
  out.arrays.resize(r.point_array_names().size());
  for (std::size_t i = 0; i + 1 < points.size(); ++i)
    r.read_points(points[i], points[i + 1], out.xyz, out.arrays);
  for (std::size_t i = 0; i + 1 < cells.size(); ++i)
    r.read_cells(cells[i], cells[i + 1], out.tets, out.cell_ids, &out.labels, out.skipped);
  return out;
}

/// The tetrahedron source of the streaming construction gives what the whole-file reader gives,
/// chunk by chunk (one cell, five cells, all of them at a time), every pass, asked for its number
/// of tetrahedra first (then a file of tetrahedra only is read from its connectivity alone) or not.
void check_source(const std::string& file, const Mesh& m) {
  for (std::size_t chunk : {std::size_t(1), std::size_t(5), std::size_t(1) << 19})
    for (bool counted : {true, false}) {
      prstar_test::Failure_context c("Vtu_tetrahedron_source, chunks of " + std::to_string(chunk) +
                                     (counted ? ", counted" : ""));
      const IO::Vtu_tetrahedron_source source(file, chunk);
      CHECK(source.supported());
      if (counted) CHECK_EQUAL(source.number_of_tetrahedra(), std::uint64_t(m.tetrahedra.size()));
      const Mesh v = source.read_vertices();
      CHECK(v.points == m.points);
      CHECK_EQUAL(v.float32_points, m.float32_points);
      CHECK(v.tetrahedra.empty() && v.tetrahedron_labels.empty());
      CHECK_EQUAL(v.point_data.size(), m.point_data.size());
      for (std::size_t i = 0; i < v.point_data.size() && i < m.point_data.size(); ++i)
        CHECK(v.point_data[i].name == m.point_data[i].name &&
              v.point_data[i].values == m.point_data[i].values);
      for (int pass = 0; pass < 2; ++pass) {
        std::vector<std::array<std::uint32_t, 4>> tets;
        std::vector<int> labels;
        bool labels_given = false;
        std::size_t calls = 0;
        source.for_each_chunk([&](const std::uint64_t* t, const int* l, std::size_t n) {
          ++calls;
          CHECK(n <= chunk);
          for (std::size_t i = 0; i < n; ++i) {
            tets.push_back({std::uint32_t(t[4 * i]), std::uint32_t(t[4 * i + 1]), std::uint32_t(t[4 * i + 2]),
                            std::uint32_t(t[4 * i + 3])});
            if (l != nullptr) labels.push_back(l[i]);
          }
          labels_given = labels_given || l != nullptr;
        });
        CHECK(tets == m.tetrahedra);
        CHECK_EQUAL(labels_given, !m.tetrahedron_labels.empty());
        CHECK(labels == m.tetrahedron_labels);
        CHECK(source.skipped_cells() == m.skipped_cells);
        CHECK_EQUAL(calls, std::size_t((source.number_of_cells() + chunk - 1) / chunk));
      }
    }
  CHECK_THROWS(std::invalid_argument, "chunk size", IO::Vtu_tetrahedron_source(file, 0));
}

/// Reads `file` whole and in ranges of every kind; checks that they agree.
void check_ranges(const std::string& file, const std::string& label_name,
                  const std::vector<std::uint64_t>* tet_cells) {
  prstar_test::Failure_context context(file);
  Mesh m;
  IO::read_tetrahedral_mesh(file, m);
  const Reader r(file);
  CHECK_MSG(r.ranges_supported(), r.reason());
  if (!r.ranges_supported()) return;
  CHECK_EQUAL(r.number_of_points(), std::uint64_t(m.points.size()));
  CHECK_EQUAL(r.float32_points(), m.float32_points); // Float32 points, as read_vtu says
  CHECK_EQUAL(r.has_labels(), !m.tetrahedron_labels.empty());
  CHECK_EQUAL(r.label_array_name(), label_name);
  std::vector<std::string> names;
  for (const auto& a : m.point_data) names.push_back(a.name);
  CHECK(r.point_array_names() == names);
  std::vector<double> xyz;
  for (const auto& p : m.points) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  std::vector<std::uint64_t> tets;
  for (const auto& t : m.tetrahedra) tets.insert(tets.end(), t.begin(), t.end());
  const std::uint64_t nv = r.number_of_points(), nc = r.number_of_cells();
  std::vector<std::pair<std::vector<std::uint64_t>, std::vector<std::uint64_t>>> partitions;
  for (std::uint64_t k : {1, 2, 3, 7}) partitions.emplace_back(split(nv, k), split(nc, k));
  partitions.emplace_back(std::vector<std::uint64_t>{0, 0, 1, 1, 2, nv / 2, nv / 2, nv - 1, nv, nv},
                          std::vector<std::uint64_t>{0, 0, 1, 1, 2, nc / 2, nc / 2, nc - 1, nc, nc});
  partitions.emplace_back(split(nv, nv), split(nc, nc)); // one point, one cell at a time
  for (const auto& p : partitions) {
    std::ostringstream what;
    what << (p.second.size() - 1) << " ranges of cells";
    prstar_test::Failure_context c(what.str());
    Read got;
    try {
      got = read_ranges(r, p.first, p.second);
    } catch (const std::exception& e) {
      FAIL(e.what());
      continue;
    }
    CHECK(got.xyz == xyz);
    CHECK_EQUAL(got.arrays.size(), m.point_data.size());
    for (std::size_t i = 0; i < got.arrays.size() && i < m.point_data.size(); ++i)
      CHECK(got.arrays[i] == m.point_data[i].values);
    CHECK(got.tets == tets);
    CHECK(got.labels == m.tetrahedron_labels);
    CHECK(got.skipped == m.skipped_cells);
    CHECK_EQUAL(got.cell_ids.size(), m.tetrahedra.size());
    if (tet_cells != nullptr) CHECK(got.cell_ids == *tet_cells);
  }
  // without point data, without labels
  std::vector<double> x;
  std::vector<std::vector<double>> none;
  r.read_points(0, nv, x, none);
  CHECK(none.empty());
  std::vector<std::uint64_t> t, ids;
  std::map<std::string, std::size_t> skipped;
  r.read_cells(0, nc, t, ids, nullptr, skipped);
  CHECK(t == tets);
  // the summary of the cells, and the cells read from the connectivity alone when it allows
  const Reader::Cell_summary summary = r.summarize_cells();
  CHECK_EQUAL(summary.tetrahedra, std::uint64_t(m.tetrahedra.size()));
  CHECK_EQUAL(summary.only_tetrahedra_in_order, m.skipped_cells.empty());
  if (summary.only_tetrahedra_in_order) {
    for (const auto& p : partitions) {
      Read got;
      for (std::size_t i = 0; i + 1 < p.second.size(); ++i)
        r.read_tetrahedra(p.second[i], p.second[i + 1], got.tets, &got.labels);
      CHECK(got.tets == tets);
      CHECK(got.labels == m.tetrahedron_labels);
    }
  }
  check_source(file, m);
}

void test_hand_made() {
  const Grid g = make_grid();
  CHECK_EQUAL(g.tet_cells.size(), std::size_t(48));
  int files = 0;
  for (bool be : {false, true})
    for (bool h64 : {false, true})
      for (const char* ct : {"Int32", "Int64", "UInt32", "UInt64"})
        for (bool p64 : {false, true}) {
          Spec s;
          s.big_endian = be;
          s.header64 = h64;
          s.conn_type = ct;
          s.points64 = p64;
          s.labels = files % 4;
          const std::string file = write_file("hand_" + std::to_string(files) + ".vtu", make_vtu(g, s));
          const char* names[] = {"", "CellEntityIds", "labels", "MaterialIds"};
          try {
            CHECK_EQUAL(Reader(file).float32_points(), !p64);
            check_ranges(file, names[s.labels], &g.tet_cells);
          } catch (const std::exception& e) {
            FAIL(file << ": " << e.what());
          }
          ++files;
        }
  // tetrahedra only: read from the connectivity alone when the source has counted them
  const Grid tg = make_grid(true);
  for (int i = 0; i < 8; ++i) {
    Spec s;
    s.big_endian = i % 2 == 1;
    s.header64 = i % 3 == 0;
    s.conn_type = i < 4 ? "Int32" : i < 6 ? "UInt64" : "Int64";
    s.points64 = i % 2 == 0;
    s.labels = i % 4;
    const std::string file = write_file("tets_" + std::to_string(i) + ".vtu", make_vtu(tg, s));
    const char* names[] = {"", "CellEntityIds", "labels", "MaterialIds"};
    try {
      check_ranges(file, names[s.labels], &tg.tet_cells);
    } catch (const std::exception& e) {
      FAIL(file << ": " << e.what());
    }
  }
  // the names the whole-file reader gives (the unnamed array too), the cells skipped
  Mesh m;
  IO::read_tetrahedral_mesh((tmp_dir / "hand_0.vtu").string(), m);
  const Reader r((tmp_dir / "hand_0.vtu").string());
  CHECK((r.point_array_names() == std::vector<std::string>{"height", "temperature", "point_data_2", "ids"}));
  CHECK_EQUAL(m.skipped_cells.size(), std::size_t(4));
  CHECK_EQUAL(m.skipped_cells["quadratic tetrahedron"], std::size_t(1));
}

void test_writer_files() {
  const Grid g = make_grid();
  Mesh m;
  for (std::size_t i = 0; i < g.xyz.size(); i += 3)
    m.points.emplace_back(g.xyz[i], g.xyz[i + 1], g.xyz[i + 2]);
  m.point_data.push_back({"height", {}});
  for (const auto& p : m.points) m.point_data.back().values.push_back(p.z() * 0.5 + p.x());
  for (std::uint64_t c : g.tet_cells) {
    const long long* v = &g.connectivity[static_cast<std::size_t>(g.offsets[c] - 4)];
    m.tetrahedra.push_back(
        {std::uint32_t(v[0]), std::uint32_t(v[1]), std::uint32_t(v[2]), std::uint32_t(v[3])});
    m.tetrahedron_labels.push_back(int(c % 3) - 1);
  }
  // The package's writer puts the data inline (base64, which VTK 9.1/9.2 read with any libexpat):
  // such a file is read whole, not in ranges, and says why.
  const std::string binary = (tmp_dir / "writer_binary.vtu").string();
  IO::write_tetrahedral_mesh(binary, m, NP::compression(IO::Compression::none).use_binary_mode(true));
  const Reader b(binary);
  CHECK(!b.ranges_supported());
  CHECK_MSG(b.reason().find("format=\"binary\"") != std::string::npos, b.reason());

  const std::string ascii = (tmp_dir / "writer_ascii.vtu").string();
  IO::write_tetrahedral_mesh(ascii, m, CGAL::parameters::use_binary_mode(false));
  const Reader a(ascii);
  CHECK(!a.ranges_supported());
  CHECK_MSG(a.reason().find("ascii") != std::string::npos, a.reason());
  std::vector<double> xyz;
  std::vector<std::vector<double>> arrays;
  CHECK_THROWS(IO::Read_error, "cannot be read", a.read_points(0, 1, xyz, arrays));
#ifdef CGAL_PR_STAR_OCTREE_HAS_ZLIB
  const std::string zlib = (tmp_dir / "writer_zlib.vtu").string();
  IO::write_tetrahedral_mesh(zlib, m, NP::compression(IO::Compression::zlib).use_binary_mode(true));
  const Reader z(zlib);
  CHECK(!z.ranges_supported());
  CHECK_MSG(z.reason().find("not appended") != std::string::npos, z.reason());
#else
  prstar_test::skip("VTU ranges of a zlib-compressed file: zlib not found at build time");
#endif
}

void test_unsupported() {
  const Grid g = make_grid();
  const auto reason = [&](const Spec& s) {
    const std::string f = write_file("unsupported.vtu", make_vtu(g, s));
    const Reader r(f);
    CHECK(!r.ranges_supported());
    return r.reason();
  };
  Spec s;
  s.encoding = "base64";
  CHECK_MSG(reason(s).find("base64") != std::string::npos, reason(s));
  s = Spec();
  s.two_pieces = true;
  CHECK_MSG(reason(s).find("2 pieces") != std::string::npos, reason(s));
  s = Spec();
  s.compressor = "vtkLZ4DataCompressor";
  CHECK_MSG(reason(s).find("lz4") != std::string::npos, reason(s));
}

/// `text` with the first `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t p = text.find(from);
  CHECK_MSG(p != std::string::npos, from);
  if (p != std::string::npos) text.replace(p, from.size(), to);
  return text;
}

void test_malformed() {
  const Grid g = make_grid();
  Spec s;
  const std::string good = make_vtu(g, s);
  const auto header_error = [&](const std::string& name, const std::string& text,
                                const std::string& message) {
    prstar_test::Failure_context c(name);
    const std::string f = write_file(name, text);
    CHECK_THROWS(IO::Read_error, message, Reader r(f));
    Mesh m;
    CHECK_THROWS(IO::Read_error, f, IO::read_tetrahedral_mesh(f, m)); // the whole-file reader agrees
  };
  CHECK_THROWS(IO::Read_error, "missing.vtu", Reader r((tmp_dir / "missing.vtu").string()));
  header_error("huge.vtu", replaced(good, "NumberOfPoints=\"27\"", "NumberOfPoints=\"1152921504606846976\""),
               "invalid NumberOfPoints");
  header_error("short.vtu", replaced(good, "NumberOfPoints=\"27\"", "NumberOfPoints=\"28\""),
               "the binary block holds");
  header_error("cut_data.vtu", good.substr(0, good.size() - 60), "truncated");
  header_error("cut_header.vtu", good.substr(0, good.find("<PointData")), "not closed");
  header_error("unclosed.vtu", replaced(good, "</Piece>", ""), "does not match");
  header_error("byte_order.vtu", replaced(good, "LittleEndian", "MiddleEndian"), "byte_order");
  header_error("offset.vtu", replaced(good, "offset=\"0\"", "offset=\"99999\""),
               "beyond the end of the file");

  // bad data: found by the ranges that hold them, with the cell named
  const auto cell_error = [&](const std::string& name, const Grid& bad, std::uint64_t cell,
                              const std::string& message) {
    prstar_test::Failure_context c(name);
    const std::string f = write_file(name, make_vtu(bad, s));
    Mesh m;
    CHECK_THROWS(IO::Read_error, message, IO::read_tetrahedral_mesh(f, m));
    const Reader r(f);
    std::vector<std::uint64_t> t, ids;
    std::vector<int> labels;
    std::map<std::string, std::size_t> skipped;
    CHECK_THROWS(IO::Read_error, message, r.read_cells(0, r.number_of_cells(), t, ids, &labels, skipped));
    CHECK_THROWS(IO::Read_error, message, r.read_cells(cell, cell + 1, t, ids, &labels, skipped));
    CHECK(t.empty() && ids.empty() && labels.empty() && skipped.empty()); // left as they were
    r.read_cells(0, cell - 1, t, ids, &labels, skipped);                  // before it: fine
    // the tetrahedron source: the error comes out of the pass, read ahead by another thread or not,
    // also from the connectivity alone (a file of tetrahedra only, counted first)
    for (std::size_t chunk : {std::size_t(1), std::size_t(2), std::size_t(64)})
      for (bool counted : {false, true}) {
        std::size_t given = 0;
        const IO::Vtu_tetrahedron_source source(f, chunk);
        if (counted) CHECK_EQUAL(source.number_of_tetrahedra(), std::uint64_t(bad.tet_cells.size()));
        CHECK_THROWS(
            IO::Read_error, message,
            source.for_each_chunk([&](const std::uint64_t*, const int*, std::size_t n) { given += n; }));
        CHECK(given <= cell);
      }
  };
  Grid bad = g;
  bad.connectivity[4 * 3 + 2] = 27;
  cell_error("index.vtu", bad, 3, "cell 3: vertex index 27 out of range");
  bad = g;
  bad.connectivity[4 * 3 + 2] = -1;
  cell_error("negative.vtu", bad, 3, "cell 3: vertex index -1 out of range");
  bad = g;
  bad.connectivity[4 * 5 + 1] = bad.connectivity[4 * 5];
  cell_error("twice.vtu", bad, 5, "listed twice");
  bad = g;
  bad.offsets[10] = bad.offsets[9] - 1;
  cell_error("decrease.vtu", bad, 10, "cell offsets decrease at cell 10");
  // the same in a file of tetrahedra only (the connectivity read alone after counting)
  const Grid tg = make_grid(true);
  bad = tg;
  bad.connectivity[4 * 7 + 1] = 27;
  cell_error("tets_index.vtu", bad, 7, "cell 7: vertex index 27 out of range");
  bad = tg;
  bad.connectivity[4 * 40 + 3] = bad.connectivity[4 * 40];
  cell_error("tets_twice.vtu", bad, 40, "cell 40: vertex index");
  bad = tg;
  bad.offsets[10] = bad.offsets[9] - 1;
  cell_error("tets_decrease.vtu", bad, 10, "cell offsets decrease at cell 10");
  {
    const Reader r(write_file("tets_decrease.vtu", make_vtu(bad, s)));
    CHECK(!r.summarize_cells().only_tetrahedra_in_order);
  }

  // a coordinate that is not finite
  Grid nan = g;
  nan.xyz[3 * 5 + 1] = std::numeric_limits<double>::quiet_NaN();
  const std::string f = write_file("nan.vtu", make_vtu(nan, s));
  const Reader r(f);
  std::vector<double> xyz;
  std::vector<std::vector<double>> arrays;
  CHECK_THROWS(IO::Read_error, "value 16 is not finite", r.read_points(4, 6, xyz, arrays));
  CHECK(xyz.empty()); // left as it was
  r.read_points(0, 5, xyz, arrays);
  CHECK_EQUAL(xyz.size(), std::size_t(15));

  // ranges beyond the counts
  const Reader ok(write_file("good.vtu", good));
  CHECK_THROWS(IO::Read_error, "points [0, 28) requested, the file has 27",
               ok.read_points(0, 28, xyz, arrays));
  std::vector<std::uint64_t> t, ids;
  std::map<std::string, std::size_t> skipped;
  CHECK_THROWS(IO::Read_error, "cells [5, 4)", ok.read_cells(5, 4, t, ids, nullptr, skipped));
}

void test_pvtu() {
  fs::create_directories(tmp_dir / "p");
  const std::string pvtu = write_file("p/mesh.pvtu", "<?xml version=\"1.0\"?>\n"
                                                     "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\">\n"
                                                     "  <PUnstructuredGrid GhostLevel=\"0\">\n"
                                                     "    <PPoints><PDataArray type=\"Float64\" "
                                                     "NumberOfComponents=\"3\"/></PPoints>\n"
                                                     "    <Piece Source=\"mesh_0.vtu\"/>\n"
                                                     "    <Piece Source='parts/mesh_1.vtu'/>\n"
                                                     "    <Piece Source=\"/abs/mesh_2.vtu\"/>\n"
                                                     "  </PUnstructuredGrid>\n</VTKFile>\n");
  const std::vector<std::string> files = IO::internal::read_pvtu_piece_files(pvtu);
  CHECK_EQUAL(files.size(), std::size_t(3));
  if (files.size() == 3) {
    CHECK_EQUAL(files[0], (tmp_dir / "p" / "mesh_0.vtu").string());
    CHECK_EQUAL(files[1], (tmp_dir / "p" / "parts" / "mesh_1.vtu").string());
    CHECK_EQUAL(files[2], std::string("/abs/mesh_2.vtu"));
  }
  const std::string no_source =
      write_file("p/bad.pvtu", "<VTKFile type=\"PUnstructuredGrid\"><PUnstructuredGrid>"
                               "<Piece/></PUnstructuredGrid></VTKFile>");
  CHECK_THROWS(IO::Read_error, "without a Source", IO::internal::read_pvtu_piece_files(no_source));
  const std::string wrong = write_file("p/wrong.pvtu", "<VTKFile type=\"UnstructuredGrid\"></VTKFile>");
  CHECK_THROWS(IO::Read_error, "PUnstructuredGrid", IO::internal::read_pvtu_piece_files(wrong));
  const std::string cut = write_file("p/cut.pvtu", "<VTKFile type=\"PUnstructuredGrid\"><PUnstructuredGrid>");
  CHECK_THROWS(IO::Read_error, "not closed", IO::internal::read_pvtu_piece_files(cut));
}

} // namespace

/// Called by test_io_vtk's main.
void test_vtu_ranges() {
  tmp_dir = fs::temp_directory_path() / ("test_io_vtu_ranges_" + std::to_string(::getpid()));
  fs::create_directories(tmp_dir);
  try {
    test_hand_made();
    test_writer_files();
    test_unsupported();
    test_malformed();
    test_pvtu();
  } catch (const std::exception& e) {
    FAIL("test_vtu_ranges: " << e.what());
  }
  fs::remove_all(tmp_dir);
}
