// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project
//
// The VTK family of readers and writers (VTU with compressed blocks, legacy VTK ascii and binary).
//
//   test_io_vtk                      the tests: files built by hand here in every combination of
//                                    compressor (none, zlib, lz4, lzma) x header type (UInt32, UInt64)
//                                    x encoding (inline base64, appended raw, appended base64) x byte
//                                    order x connectivity type x point type, mixed cells, labels, cell
//                                    and point data; malformed compressed data; round trips of the writers
//   test_io_vtk --dump FILE          prints what the reader read as one JSON object (interop_vtk.py)
//   test_io_vtk --convert IN OUT [ascii|binary]   reads IN, writes OUT (by extension)
//   test_io_vtk --lattice N OUT      writes an N x N x N lattice of cubes cut in 6 tetrahedra each
//   test_io_vtk --bench FILE [reps]  reads FILE reps times; prints the best time and the rate of
//                                    decompressed bytes (the sizes of the arrays) per second
//   test_io_vtk --quality FILE       prints the smallest and largest dihedral angles and the radius
//                                    ratio of every tetrahedron, in the file's order, and
//                                    mesh_quality() of the whole, as one JSON object (interop_vtk.py
//                                    compares them with VTK's vtkMeshQuality)

#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/mesh_quality.h>

#ifdef CGAL_PR_STAR_OCTREE_HAS_ZLIB
#include <zlib.h>
#endif
#ifdef CGAL_PR_STAR_OCTREE_HAS_LZ4
#include <lz4.h>
#endif
#ifdef CGAL_PR_STAR_OCTREE_HAS_LZMA
#include <lzma.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <cstring>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "test_harness.h"

namespace IO = CGAL::PR_star_octree::IO;
namespace NP = CGAL::PR_star_octree::parameters;
using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;
namespace fs = std::filesystem;

void test_vtu_ranges(); // test_io_vtu_ranges.cpp

static fs::path tmp;

static std::string put(const std::string& name, const std::string& content) {
  const fs::path p = tmp / name;
  std::ofstream out(p, std::ios::binary);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  return p.string();
}

// ------------------------------------------------------------------------------------------------
// JSON dump (for interop_vtk.py)
// ------------------------------------------------------------------------------------------------

static std::string json_string(const std::string& s) {
  std::string r = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') r += '\\';
    if (static_cast<unsigned char>(c) < 0x20) {
      char b[8];
      std::snprintf(b, sizeof b, "\\u%04x", c);
      r += b;
    } else {
      r += c;
    }
  }
  return r + "\"";
}

static void dump(const Mesh& m, std::ostream& out) {
  out << std::setprecision(17);
  double xyz = 0;
  for (const auto& p : m.points) xyz += p.x() + 2 * p.y() + 3 * p.z();
  unsigned long long index_sum = 0;
  for (const auto& t : m.tetrahedra)
    for (auto v : t) index_sum += v;
  out << "{\"vertices\": " << m.points.size() << ", \"tetrahedra\": " << m.tetrahedra.size()
      << ", \"coordinate_sum\": " << xyz << ", \"index_sum\": " << index_sum << ", \"labels\": {";
  std::map<int, std::size_t> hist;
  for (int l : m.tetrahedron_labels) ++hist[l];
  bool first = true;
  for (const auto& kv : hist) {
    out << (first ? "" : ", ") << json_string(std::to_string(kv.first)) << ": " << kv.second;
    first = false;
  }
  const auto arrays = [&](const std::vector<CGAL::PR_star_octree::Data_array>& v) {
    out << "{";
    bool f = true;
    for (const auto& a : v) {
      double s = 0;
      for (double x : a.values) s += x;
      out << (f ? "" : ", ") << json_string(a.name) << ": {\"count\": " << a.values.size()
          << ", \"sum\": " << s << "}";
      f = false;
    }
    out << "}";
  };
  out << "}, \"float32_points\": " << (m.float32_points ? "true" : "false") << ", \"point_data\": ";
  arrays(m.point_data);
  out << ", \"cell_data\": ";
  arrays(m.cell_data);
  out << ", \"skipped_cells\": {";
  first = true;
  for (const auto& kv : m.skipped_cells) {
    out << (first ? "" : ", ") << json_string(kv.first) << ": " << kv.second;
    first = false;
  }
  out << "}}\n";
}

// ------------------------------------------------------------------------------------------------
// The test mesh: a 2 x 1 x 1 block of cubes cut in tetrahedra, plus a triangle and a hexahedron
// ------------------------------------------------------------------------------------------------

/// Six tetrahedra around the diagonal 0-6 of a cube whose corners are c[0..7] (VTK hexahedron order).
static void cube_tetrahedra(const std::array<std::uint32_t, 8>& c, std::vector<Mesh::Tetrahedron>& out) {
  static const int t[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                              {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  for (const auto& q : t) out.push_back({c[q[0]], c[q[1]], c[q[2]], c[q[3]]});
}

static Mesh lattice(std::size_t n) {
  Mesh m;
  const std::size_t k = n + 1;
  m.points.reserve(k * k * k);
  for (std::size_t z = 0; z < k; ++z)
    for (std::size_t y = 0; y < k; ++y)
      for (std::size_t x = 0; x < k; ++x) m.points.emplace_back(double(x), double(y), double(z));
  m.tetrahedra.reserve(6 * n * n * n);
  const auto id = [&](std::size_t x, std::size_t y, std::size_t z) {
    return std::uint32_t((z * k + y) * k + x);
  };
  for (std::size_t z = 0; z < n; ++z)
    for (std::size_t y = 0; y < n; ++y)
      for (std::size_t x = 0; x < n; ++x)
        cube_tetrahedra({id(x, y, z), id(x + 1, y, z), id(x + 1, y + 1, z), id(x, y + 1, z), id(x, y, z + 1),
                         id(x + 1, y, z + 1), id(x + 1, y + 1, z + 1), id(x, y + 1, z + 1)},
                        m.tetrahedra);
  m.tetrahedron_labels.resize(m.tetrahedra.size());
  for (std::size_t i = 0; i < m.tetrahedra.size(); ++i) m.tetrahedron_labels[i] = int(1 + (i / 6) % 3);
  m.point_data.push_back({"height", {}});
  for (const auto& p : m.points) m.point_data.back().values.push_back(p.z() * 0.5);
  return m;
}

/// What the hand-made files describe: cells 0..5 tetrahedra of cube 0, cell 6 a triangle, cells
/// 7..12 tetrahedra of cube 1, cell 13 a hexahedron.
struct Cells {
  std::vector<double> xyz;
  std::vector<long long> connectivity, offsets;
  std::vector<int> types;
  std::vector<double> height;   // point data
  std::vector<int> label;       // cell data: labels
  std::vector<double> pressure; // cell data, not integers
};

static Cells test_cells() {
  Cells c;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 3; ++x) {
        c.xyz.insert(c.xyz.end(), {x * 1.5, y * 1.0 + 0.1 * x, z * 0.25}); // 0.1 x: not a float
        c.height.push_back(x + 10.0 * y + 100.0 * z);
      }
  const auto id = [](int x, int y, int z) { return std::uint32_t((z * 2 + y) * 3 + x); };
  const auto add_cube = [&](int x) {
    std::vector<Mesh::Tetrahedron> t;
    cube_tetrahedra({id(x, 0, 0), id(x + 1, 0, 0), id(x + 1, 1, 0), id(x, 1, 0), id(x, 0, 1), id(x + 1, 0, 1),
                     id(x + 1, 1, 1), id(x, 1, 1)},
                    t);
    for (const auto& q : t) {
      c.connectivity.insert(c.connectivity.end(), q.begin(), q.end());
      c.offsets.push_back(static_cast<long long>(c.connectivity.size()));
      c.types.push_back(10);
      c.label.push_back(x == 0 ? 7 : -2);
      c.pressure.push_back(0.5 + c.types.size());
    }
  };
  add_cube(0);
  c.connectivity.insert(c.connectivity.end(), {0, 1, 4}); // a triangle
  c.offsets.push_back(static_cast<long long>(c.connectivity.size()));
  c.types.push_back(5);
  c.label.push_back(99);
  c.pressure.push_back(1000);
  add_cube(1);
  for (std::uint32_t v : {id(1, 0, 0), id(2, 0, 0), id(2, 1, 0), id(1, 1, 0), id(1, 0, 1), id(2, 0, 1),
                          id(2, 1, 1), id(1, 1, 1)})
    c.connectivity.push_back(v); // a hexahedron
  c.offsets.push_back(static_cast<long long>(c.connectivity.size()));
  c.types.push_back(12);
  c.label.push_back(99);
  c.pressure.push_back(1000);
  return c;
}

/// Checks a mesh read from a file describing `test_cells()`.
static void check_test_mesh(const Mesh& m, const Cells& c, bool float32) {
  CHECK_EQUAL(m.points.size(), std::size_t(12));
  CHECK_EQUAL(m.tetrahedra.size(), std::size_t(12));
  CHECK_EQUAL(m.skipped_cells.size(), std::size_t(2));
  CHECK_EQUAL(m.skipped_cells.count("triangle") ? m.skipped_cells.at("triangle") : 0, std::size_t(1));
  CHECK_EQUAL(m.skipped_cells.count("hexahedron") ? m.skipped_cells.at("hexahedron") : 0, std::size_t(1));
  std::size_t k = 0;
  for (std::size_t i = 0; i < c.types.size(); ++i) {
    if (c.types[i] != 10) continue;
    if (k >= m.tetrahedra.size()) break;
    for (int j = 0; j < 4; ++j)
      CHECK_EQUAL(static_cast<long long>(m.tetrahedra[k][j]), c.connectivity[c.offsets[i] - 4 + j]);
    if (m.tetrahedron_labels.size() == m.tetrahedra.size()) CHECK_EQUAL(m.tetrahedron_labels[k], c.label[i]);
    if (m.cell_data.size() == 1 && m.cell_data[0].values.size() == m.tetrahedra.size())
      CHECK_EQUAL(m.cell_data[0].values[k], c.pressure[i]);
    ++k;
  }
  CHECK_EQUAL(m.tetrahedron_labels.size(), std::size_t(12));
  CHECK_EQUAL(m.cell_data.size(), std::size_t(1));
  if (m.cell_data.size() == 1) CHECK_EQUAL(m.cell_data[0].name, std::string("pressure"));
  // Float32 points: the flag, and exactly the floats of the file
  CHECK_EQUAL(m.float32_points, float32);
  const auto expected = [&](std::size_t k) {
    return float32 ? IO::internal::rounded_to_float(c.xyz[k]) : c.xyz[k];
  };
  for (std::size_t i = 0; i < m.points.size() && 3 * i + 2 < c.xyz.size(); ++i) {
    CHECK_EQUAL(m.points[i].x(), expected(3 * i));
    CHECK_EQUAL(m.points[i].y(), expected(3 * i + 1));
    CHECK_EQUAL(m.points[i].z(), expected(3 * i + 2));
  }
  CHECK_EQUAL(m.point_data.size(), std::size_t(1));
  if (m.point_data.size() == 1) {
    CHECK_EQUAL(m.point_data[0].name, std::string("height"));
    CHECK(m.point_data[0].values == c.height);
  }
}

// ------------------------------------------------------------------------------------------------
// A VTU encoder written here, independent of the writer: every combination
// ------------------------------------------------------------------------------------------------

enum class Comp { NONE, ZLIB, LZ4, LZMA };
enum class Enc { INLINE, APPENDED_RAW, APPENDED_BASE64 };

static const char* comp_name(Comp c) {
  return c == Comp::ZLIB   ? "vtkZLibDataCompressor"
         : c == Comp::LZ4  ? "vtkLZ4DataCompressor"
         : c == Comp::LZMA ? "vtkLZMADataCompressor"
                           : "";
}

static bool comp_available(Comp c) {
  switch (c) {
  case Comp::NONE:
    return true;
  case Comp::ZLIB:
#ifdef CGAL_PR_STAR_OCTREE_HAS_ZLIB
    return true;
#else
    return false;
#endif
  case Comp::LZ4:
#ifdef CGAL_PR_STAR_OCTREE_HAS_LZ4
    return true;
#else
    return false;
#endif
  case Comp::LZMA:
#ifdef CGAL_PR_STAR_OCTREE_HAS_LZMA
    return true;
#else
    return false;
#endif
  }
  return false;
}

static std::string compress(Comp c, const std::string& raw) {
  (void)c; // (without any compression library)
  (void)raw;
  std::string out;
#ifdef CGAL_PR_STAR_OCTREE_HAS_ZLIB
  if (c == Comp::ZLIB) {
    uLongf n = compressBound(raw.size());
    out.resize(n);
    compress2(reinterpret_cast<Bytef*>(&out[0]), &n, reinterpret_cast<const Bytef*>(raw.data()), raw.size(),
              6);
    out.resize(n);
  }
#endif
#ifdef CGAL_PR_STAR_OCTREE_HAS_LZ4
  if (c == Comp::LZ4) {
    out.resize(LZ4_compressBound(int(raw.size())));
    const int n = LZ4_compress_default(raw.data(), &out[0], int(raw.size()), int(out.size()));
    out.resize(std::size_t(n));
  }
#endif
#ifdef CGAL_PR_STAR_OCTREE_HAS_LZMA
  if (c == Comp::LZMA) {
    out.resize(lzma_stream_buffer_bound(raw.size()));
    std::size_t pos = 0;
    // preset 1 (1 MiB dictionary): preset 6 allocates about 94 MB per call, which took this test from
    // 3 s to 235 s under ASan; the stream is an .xz stream the same for the reader
    lzma_easy_buffer_encode(1, LZMA_CHECK_CRC64, nullptr, reinterpret_cast<const std::uint8_t*>(raw.data()),
                            raw.size(), reinterpret_cast<std::uint8_t*>(&out[0]), &pos, out.size());
    out.resize(pos);
  }
#endif
  return out;
}

static std::string base64(const std::string& bytes) {
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

struct Vtu_options {
  Comp comp = Comp::NONE;
  bool header64 = false;
  Enc enc = Enc::INLINE;
  bool big_endian = false;
  std::string conn_type = "Int64"; // Int32, Int64, UInt32, UInt64
  bool points64 = true;
  std::size_t block_size = 40; // small: several blocks and a partial last one
};

/// One value as `size` bytes in the file's byte order.
static void put_value(std::string& out, std::uint64_t bits, std::size_t size, bool big_endian) {
  for (std::size_t i = 0; i < size; ++i) {
    const std::size_t shift = 8 * (big_endian ? size - 1 - i : i);
    out += static_cast<char>((bits >> shift) & 0xff);
  }
}

/// The bytes of a data array: header (+ blocks) as the file stores them before any base64.
/// Returns {header, data}: kept apart because inline compressed data encode them separately.
static std::pair<std::string, std::string> array_bytes(const std::string& raw, const Vtu_options& o) {
  const std::size_t hs = o.header64 ? 8 : 4;
  std::string header, data;
  if (o.comp == Comp::NONE) {
    put_value(header, raw.size(), hs, o.big_endian);
    return {header, raw};
  }
  const std::size_t nb = (raw.size() + o.block_size - 1) / o.block_size;
  put_value(header, nb, hs, o.big_endian);
  put_value(header, o.block_size, hs, o.big_endian);
  put_value(header, raw.size() % o.block_size, hs, o.big_endian);
  for (std::size_t b = 0; b < nb; ++b) {
    const std::string c = compress(o.comp, raw.substr(b * o.block_size, o.block_size));
    put_value(header, c.size(), hs, o.big_endian);
    data += c;
  }
  return {header, data};
}

template <class F>
static std::string raw_values(std::size_t n, std::size_t size, bool big_endian, const F& bits) {
  std::string r;
  for (std::size_t i = 0; i < n; ++i) put_value(r, bits(i), size, big_endian);
  return r;
}

static std::uint64_t double_bits(double d) {
  std::uint64_t b;
  std::memcpy(&b, &d, 8);
  return b;
}
static std::uint64_t float_bits(double d) {
  const float f = static_cast<float>(d);
  std::uint32_t b;
  std::memcpy(&b, &f, 4);
  return b;
}

static std::string make_vtu(const Cells& c, const Vtu_options& o) {
  struct Array {
    std::string element; // the opening of the DataArray element, without format
    std::string raw;
  };
  const bool be = o.big_endian;
  const std::size_t conn_size = o.conn_type.find("64") != std::string::npos ? 8 : 4;
  std::vector<Array> arrays;
  arrays.push_back(
      {"<DataArray type=\"Float64\" Name=\"height\"",
       raw_values(c.height.size(), 8, be, [&](std::size_t i) { return double_bits(c.height[i]); })});
  arrays.push_back({"<DataArray type=\"Float32\" Name=\"velocity\" NumberOfComponents=\"3\"", // skipped
                    raw_values(c.xyz.size(), 4, be, [&](std::size_t i) { return float_bits(c.xyz[i]); })});
  arrays.push_back(
      {"<DataArray type=\"Float64\" Name=\"pressure\"",
       raw_values(c.pressure.size(), 8, be, [&](std::size_t i) { return double_bits(c.pressure[i]); })});
  arrays.push_back({"<DataArray type=\"Int32\" Name=\"CellEntityIds\"",
                    raw_values(c.label.size(), 4, be,
                               [&](std::size_t i) { return std::uint64_t(std::uint32_t(c.label[i])); })});
  arrays.push_back({std::string("<DataArray type=\"") + (o.points64 ? "Float64" : "Float32") +
                        "\" Name=\"Points\" NumberOfComponents=\"3\"",
                    raw_values(c.xyz.size(), o.points64 ? 8 : 4, be, [&](std::size_t i) {
                      return o.points64 ? double_bits(c.xyz[i]) : float_bits(c.xyz[i]);
                    })});
  arrays.push_back({"<DataArray type=\"" + o.conn_type + "\" Name=\"connectivity\"",
                    raw_values(c.connectivity.size(), conn_size, be,
                               [&](std::size_t i) { return std::uint64_t(c.connectivity[i]); })});
  arrays.push_back({"<DataArray type=\"" + o.conn_type + "\" Name=\"offsets\"",
                    raw_values(c.offsets.size(), conn_size, be,
                               [&](std::size_t i) { return std::uint64_t(c.offsets[i]); })});
  arrays.push_back(
      {"<DataArray type=\"UInt8\" Name=\"types\"",
       raw_values(c.types.size(), 1, be, [&](std::size_t i) { return std::uint64_t(c.types[i]); })});
  std::vector<std::string> elements;
  std::string appended;
  for (const Array& a : arrays) {
    const auto hd = array_bytes(a.raw, o);
    if (o.enc == Enc::INLINE) {
      // compressed: header and data encoded separately (as VTK); uncompressed: one stream
      const std::string text =
          o.comp == Comp::NONE ? base64(hd.first + hd.second) : base64(hd.first) + base64(hd.second);
      elements.push_back(a.element + " format=\"binary\">\n  " + text + "\n</DataArray>\n");
    } else {
      elements.push_back(a.element + " format=\"appended\" offset=\"" + std::to_string(appended.size()) +
                         "\"/>\n");
      appended += o.enc == Enc::APPENDED_RAW ? hd.first + hd.second
                  : o.comp == Comp::NONE     ? base64(hd.first + hd.second)
                                             : base64(hd.first) + base64(hd.second);
    }
  }
  std::string s = "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"";
  s += be ? "BigEndian" : "LittleEndian";
  s += std::string("\" header_type=\"") + (o.header64 ? "UInt64" : "UInt32") + "\"";
  if (o.comp != Comp::NONE) s += std::string(" compressor=\"") + comp_name(o.comp) + "\"";
  s += ">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"" + std::to_string(c.height.size()) +
       "\" NumberOfCells=\"" + std::to_string(c.types.size()) + "\">\n";
  s += "<PointData Scalars=\"height\">\n" + elements[0] + elements[1] + "</PointData>\n";
  s += "<CellData>\n" + elements[2] + elements[3] + "</CellData>\n";
  s += "<Points>\n" + elements[4] + "</Points>\n";
  s += "<Cells>\n" + elements[5] + elements[6] + elements[7] + "</Cells>\n";
  s += "</Piece>\n</UnstructuredGrid>\n";
  if (o.enc != Enc::INLINE)
    s += std::string("<AppendedData encoding=\"") + (o.enc == Enc::APPENDED_RAW ? "raw" : "base64") +
         "\">\n_" + appended + "\n</AppendedData>\n";
  s += "</VTKFile>\n";
  return s;
}

static void test_vtu_combinations() {
  const Cells c = test_cells();
  int files = 0;
  for (Comp comp : {Comp::NONE, Comp::ZLIB, Comp::LZ4, Comp::LZMA}) {
    if (!comp_available(comp)) {
      prstar_test::skip(std::string("VTU ") + comp_name(comp) + ": library not found at build time");
      continue;
    }
    for (bool h64 : {false, true})
      for (Enc enc : {Enc::INLINE, Enc::APPENDED_RAW, Enc::APPENDED_BASE64})
        for (bool be : {false, true})
          for (const char* ct : {"Int32", "Int64", "UInt32", "UInt64"})
            for (bool p64 : {false, true}) {
              Vtu_options o;
              o.comp = comp;
              o.header64 = h64;
              o.enc = enc;
              o.big_endian = be;
              o.conn_type = ct;
              o.points64 = p64;
              o.block_size = 40 + 8 * (files % 3); // 40, 48, 56: partial and exact last blocks
              std::ostringstream what;
              what << "VTU " << (comp == Comp::NONE ? "uncompressed" : comp_name(comp)) << ", header "
                   << (h64 ? "UInt64" : "UInt32") << ", "
                   << (enc == Enc::INLINE         ? "inline"
                       : enc == Enc::APPENDED_RAW ? "appended raw"
                                                  : "appended base64")
                   << ", " << (be ? "BigEndian" : "LittleEndian") << ", " << ct << ", "
                   << (p64 ? "Float64" : "Float32") << ", block " << o.block_size;
              prstar_test::Failure_context context(what.str());
              const std::string text = make_vtu(c, o);
              Mesh m;
              try {
                std::istringstream in(text);
                IO::read_vtu(in, m, "combination.vtu");
              } catch (const std::exception& e) {
                FAIL(e.what());
                continue;
              }
              check_test_mesh(m, c, !p64);
              ++files;
            }
  }
  int available = 0;
  for (Comp comp : {Comp::NONE, Comp::ZLIB, Comp::LZ4, Comp::LZMA}) available += comp_available(comp) ? 1 : 0;
  CHECK_EQUAL(files, available * 2 * 3 * 2 * 4 * 2);
}

// ------------------------------------------------------------------------------------------------
// Malformed compressed data
// ------------------------------------------------------------------------------------------------

template <class M = Mesh>
static void expect_read_error(const std::string& text, const std::vector<std::string>& parts,
                              const char* what) {
  prstar_test::Failure_context context(what);
  try {
    M m;
    std::istringstream in(text);
    IO::read_vtu(in, m, "bad.vtu");
    FAIL("no Read_error");
  } catch (const IO::Read_error& e) {
    const std::string w = e.what();
    for (const std::string& p : parts)
      CHECK_MSG(w.find(p) != std::string::npos, "'" << w << "' lacks '" << p << "'");
    CHECK_MSG(w.rfind("bad.vtu:", 0) == 0, w);
  } catch (const std::exception& e) {
    FAIL("not a Read_error: " << e.what());
  }
}

/// A one-array file: the points of a single tetrahedron, given as appended raw bytes.
static std::string one_tet_vtu(const std::string& points_bytes, const std::string& number_of_points = "4",
                               const char* compressor = "vtkZLibDataCompressor") {
  return std::string(
             "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" byte_order=\"LittleEndian\" "
             "header_type=\"UInt64\" compressor=\"") +
         compressor + "\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"" + number_of_points +
         "\" NumberOfCells=\"1\">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" "
         "format=\"appended\" offset=\"0\"/>\n</Points>\n<Cells>\n"
         "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2 3</DataArray>\n"
         "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">4</DataArray>\n"
         "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10</DataArray>\n</Cells>\n</Piece>\n"
         "</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_" +
         points_bytes + "\n</AppendedData>\n</VTKFile>\n";
}

static void test_malformed_compressed() {
  if (!comp_available(Comp::ZLIB)) {
    prstar_test::skip("malformed compressed VTU: zlib not found at build time");
    return;
  }
  std::string raw;
  const double p[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  for (double d : p) put_value(raw, double_bits(d), 8, false);
  Vtu_options o;
  o.comp = Comp::ZLIB;
  o.header64 = true;
  o.block_size = 32;
  const auto hd = array_bytes(raw, o); // 3 blocks: 32, 32, 32
  {                                    // the good file reads
    Mesh m;
    std::istringstream in(one_tet_vtu(hd.first + hd.second));
    IO::read_vtu(in, m, "good.vtu");
    CHECK_EQUAL(m.tetrahedra.size(), std::size_t(1));
    CHECK_EQUAL(m.points[3].z(), 1.0);
  }
  // truncated: the last block cut (the </AppendedData> closes the data early)
  expect_read_error(one_tet_vtu(hd.first + hd.second.substr(0, hd.second.size() - 5)), {"truncated"},
                    "truncated block");
  // the header lists fewer compressed bytes than the block has: corrupt/truncated zlib stream
  {
    std::string h = hd.first;
    h[24] = static_cast<char>(h[24] - 3); // compressed size of block 0
    expect_read_error(one_tet_vtu(h + hd.second), {"block 0", "zlib"}, "short compressed size");
  }
  // wrong uncompressed size: the header says 2 blocks of 32 bytes for 96 bytes of points
  {
    std::string h;
    put_value(h, 2, 8, false);
    put_value(h, 40, 8, false);
    put_value(h, 0, 8, false);
    expect_read_error(one_tet_vtu(h + hd.second), {"compressed blocks announce 80", "96 bytes"},
                      "wrong total size");
  }
  {
    // the block decompresses to 32 bytes but the header says 40 per block (and 16 last)
    std::string h;
    put_value(h, 3, 8, false);
    put_value(h, 40, 8, false);
    put_value(h, 16, 8, false);
    for (int i = 0; i < 3; ++i)
      put_value(h, std::uint64_t(static_cast<unsigned char>(hd.first[24 + 8 * i])), 8, false);
    expect_read_error(one_tet_vtu(h + hd.second), {"block 0", "fewer bytes than announced"},
                      "wrong block size");
  }
  // corrupt stream: bytes of the first block overwritten
  {
    std::string d = hd.second;
    for (std::size_t i = 2; i < 8 && i < d.size(); ++i) d[i] = static_cast<char>(0xff);
    expect_read_error(one_tet_vtu(hd.first + d), {"block 0", "at byte"}, "corrupt stream");
  }
  // a bomb: 10^12 bytes announced (NumberOfPoints to match) from 20 compressed bytes
  {
    // (a 64-bit index type: 41666666667 points must fit in it to get to the data)
    using Mesh64 = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<Mesh::Point_3, std::uint64_t>;
    const std::uint64_t n = 24ull * 41666666667ull; // 10^12 + 8 bytes
    std::string h;
    put_value(h, 1, 8, false);
    put_value(h, n, 8, false);
    put_value(h, 0, 8, false);
    put_value(h, 20, 8, false);
    const std::string points = std::to_string(n / 24);
    std::string text = one_tet_vtu(h + std::string(20, 'x'), points);
    expect_read_error<Mesh64>(text, {"decompression bomb", "1000000000008 bytes"}, "bomb, one block");
    // the same in many blocks: their sizes cannot all be in the file
    std::string h2;
    put_value(h2, n / 32768, 8, false);
    put_value(h2, 32768, 8, false);
    put_value(h2, 0, 8, false);
    expect_read_error<Mesh64>(one_tet_vtu(h2 + std::string(64, 'x'), points), {"blocks announced"},
                              "bomb, many blocks");
  }
  // a compressor this program does not know
  expect_read_error(one_tet_vtu(hd.first + hd.second, "4", "vtkZstdDataCompressor"), {"unknown compressor"},
                    "unknown compressor");
  // an lz4 header on zlib data
  if (comp_available(Comp::LZ4))
    expect_read_error(one_tet_vtu(hd.first + hd.second, "4", "vtkLZ4DataCompressor"), {"block", "LZ4"},
                      "zlib data as lz4");
}

// ------------------------------------------------------------------------------------------------
// Legacy VTK: a binary 5.1 file built here; round trips of the writer
// ------------------------------------------------------------------------------------------------

static void put_be(std::string& out, std::uint64_t bits, std::size_t size) {
  put_value(out, bits, size, true);
}

static std::string make_legacy_binary_51(const Cells& c) {
  std::string s = "# vtk DataFile Version 5.1\nhand-made\nBINARY\nDATASET UNSTRUCTURED_GRID\n";
  s += "POINTS " + std::to_string(c.height.size()) + " float\n";
  for (double d : c.xyz) put_be(s, float_bits(d), 4);
  s += "\nMETADATA\nINFORMATION 0\n\n";
  s += "CELLS " + std::to_string(c.offsets.size() + 1) + " " + std::to_string(c.connectivity.size()) +
       "\nOFFSETS vtktypeint64\n";
  put_be(s, 0, 8);
  for (long long o : c.offsets) put_be(s, std::uint64_t(o), 8);
  s += "\nCONNECTIVITY vtktypeint64\n";
  for (long long v : c.connectivity) put_be(s, std::uint64_t(v), 8);
  s += "\nCELL_TYPES " + std::to_string(c.types.size()) + "\n";
  for (int t : c.types) put_be(s, std::uint64_t(t), 4);
  s +=
      "\nPOINT_DATA " + std::to_string(c.height.size()) + "\nSCALARS height double 1\nLOOKUP_TABLE default\n";
  for (double d : c.height) put_be(s, double_bits(d), 8);
  s += "\nCELL_DATA " + std::to_string(c.types.size()) + "\nFIELD FieldData 2\npressure 1 " +
       std::to_string(c.types.size()) + " double\n";
  for (double d : c.pressure) put_be(s, double_bits(d), 8);
  s += "\ngmsh:physical 1 " + std::to_string(c.types.size()) + " int\n";
  for (int l : c.label) put_be(s, std::uint64_t(std::uint32_t(l)), 4);
  s += "\n";
  return s;
}

static void test_legacy() {
  const Cells c = test_cells();
  {
    prstar_test::Failure_context context("legacy binary 5.1, hand-made");
    Mesh m;
    try {
      IO::read_vtk(put("b51.vtk", make_legacy_binary_51(c)), m);
      check_test_mesh(m, c, true);
    } catch (const std::exception& e) {
      FAIL(e.what());
    }
    // truncated in the connectivity
    const std::string full = make_legacy_binary_51(c);
    const std::size_t cut = full.find("CONNECTIVITY") + 40;
    CHECK_THROWS(IO::Read_error, "end of file", IO::read_vtk(put("b51cut.vtk", full.substr(0, cut)), m));
  }
  // writer round trips, ascii and binary; then the 4.2 binary output is also read as bytes here
  Mesh m = lattice(2);
  m.cell_data.push_back({"volume id", {}});
  for (std::size_t i = 0; i < m.tetrahedra.size(); ++i) m.cell_data.back().values.push_back(0.25 * double(i));
  for (bool binary : {false, true}) {
    prstar_test::Failure_context context(binary ? "legacy writer binary" : "legacy writer ascii");
    const std::string f = (tmp / (binary ? "wb.vtk" : "wa.vtk")).string();
    IO::write_vtk(f, m, {}, CGAL::parameters::use_binary_mode(binary));
    Mesh r;
    IO::read_vtk(f, r);
    CHECK(r.points == m.points);
    CHECK(!r.float32_points); // a mesh of doubles stays one
    CHECK(r.tetrahedra == m.tetrahedra);
    CHECK(r.tetrahedron_labels == m.tetrahedron_labels);
    CHECK_EQUAL(r.point_data.size(), std::size_t(1));
    CHECK_EQUAL(r.cell_data.size(), std::size_t(1));
    if (r.cell_data.size() == 1) {
      CHECK_EQUAL(r.cell_data[0].name, std::string("volume id"));
      CHECK(r.cell_data[0].values == m.cell_data[0].values);
    }
    if (r.point_data.size() == 1) CHECK(r.point_data[0].values == m.point_data[0].values);
    std::ifstream in(f, std::ios::binary);
    std::string head;
    std::getline(in, head);
    std::getline(in, head);
    std::getline(in, head);
    CHECK_EQUAL(head, std::string(binary ? "BINARY" : "ASCII"));
  }
  // by extension: ascii by default
  IO::write_tetrahedral_mesh((tmp / "ext.vtk").string(), m);
  Mesh r;
  IO::read_tetrahedral_mesh((tmp / "ext.vtk").string(), r);
  CHECK(r.tetrahedra == m.tetrahedra);
}

static void test_vtu_writer() {
  Mesh m = lattice(3);
  m.cell_data.push_back({"quality", {}});
  for (std::size_t i = 0; i < m.tetrahedra.size(); ++i)
    m.cell_data.back().values.push_back(1.0 / double(i + 1));
  const std::vector<CGAL::PR_star_octree::Data_array> extra = {
      {"extra", std::vector<double>(m.points.size(), 2.5)}};
  struct Case {
    const char* name;
    std::function<void(const std::string&)> write;
    const char* must_contain;
  };
  const std::vector<Case> cases = {
      {"default.vtu", [&](const std::string& f) { IO::write_vtu(f, m, extra); },
       comp_available(Comp::ZLIB) ? "vtkZLibDataCompressor" : "format=\"binary\""},
      {"ascii.vtu",
       [&](const std::string& f) { IO::write_vtu(f, m, extra, CGAL::parameters::use_binary_mode(false)); },
       "format=\"ascii\""},
      {"raw.vtu",
       [&](const std::string& f) {
         IO::write_vtu(f, m, extra, NP::compression(IO::Compression::none).use_binary_mode(true));
       },
       "format=\"binary\">"},
      {"ext.vtu", [&](const std::string& f) { IO::write_tetrahedral_mesh(f, m); }, "format=\"binary\""}};
  for (const Case& c : cases) {
    prstar_test::Failure_context context(std::string("VTU writer ") + c.name);
    const std::string f = (tmp / c.name).string();
    c.write(f);
    std::ifstream in(f, std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    CHECK(text.find(c.must_contain) != std::string::npos);
    CHECK(text.find("<DataArray type=\"Float64\" Name=\"Points\"") != std::string::npos);
    // inline data only: VTK 9.1/9.2 read no appended data with Debian 12's current libexpat
    CHECK(text.find("<AppendedData") == std::string::npos);
    Mesh r;
    IO::read_vtu(f, r);
    CHECK(r.points == m.points);
    CHECK(!r.float32_points);
    CHECK(r.tetrahedra == m.tetrahedra);
    CHECK(r.tetrahedron_labels == m.tetrahedron_labels);
    CHECK_EQUAL(r.cell_data.size(), std::size_t(1));
    if (!r.cell_data.empty()) CHECK(r.cell_data[0].values == m.cell_data[0].values);
    const std::size_t npd = std::string(c.name) == "ext.vtu" ? 1 : 2;
    CHECK_EQUAL(r.point_data.size(), npd);
    if (r.point_data.size() == npd) {
      CHECK(r.point_data[0].values == m.point_data[0].values);
      if (npd == 2) CHECK(r.point_data[1].values == extra[0].values);
    }
  }
}

// ------------------------------------------------------------------------------------------------
// Float32 points (issue 24): read as floats with the flag set, written back as floats
// ------------------------------------------------------------------------------------------------

/// A mesh type without `float32_points`: written with doubles.
struct Doubles_only_mesh {
  using Point_3 = Mesh::Point_3;
  std::vector<Point_3> points;
  std::vector<Mesh::Tetrahedron> tetrahedra;
  std::vector<int> tetrahedron_labels;
  std::vector<CGAL::PR_star_octree::Data_array> point_data, cell_data;
};
/// A mesh type whose `float32_points` is a member function: not the flag.
struct Function_flag_mesh : Doubles_only_mesh {
  bool float32_points() const { return true; }
};
static_assert(IO::internal::has_float32_points<Mesh>::value, "the flag of Indexed_tetrahedral_mesh");
static_assert(!IO::internal::has_float32_points<Doubles_only_mesh>::value, "no flag");
static_assert(!IO::internal::has_float32_points<Function_flag_mesh>::value, "a function is not the flag");

/// One tetrahedron whose points, as text, are `coordinates` (12 numbers) of type `type`, in ascii.
static std::string ascii_vtu(const std::string& type, const std::string& coordinates) {
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\">\n<UnstructuredGrid>\n"
         "<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n<Points>\n<DataArray type=\"" +
         type + "\" NumberOfComponents=\"3\" format=\"ascii\">" + coordinates +
         "</DataArray>\n</Points>\n<Cells>\n"
         "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2 3</DataArray>\n"
         "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">4</DataArray>\n"
         "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10</DataArray>\n</Cells>\n</Piece>\n"
         "</UnstructuredGrid>\n</VTKFile>\n";
}

static std::string ascii_vtk(const std::string& type, const std::string& coordinates) {
  return "# vtk DataFile Version 4.2\nhand-made\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 " + type + "\n" +
         coordinates + "\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n";
}

static void test_float32() {
  const std::string tenths = "0 0 0 0.1 0 0 0 0.2 0 0 0 0.3";
  const double f1 = double(0.1f), f2 = double(0.2f), f3 = double(0.3f);
  // ascii: Float32 text rounded to the floats (as VTK reads it), Float64 text kept
  for (const bool vtu : {true, false}) {
    prstar_test::Failure_context context(vtu ? "ascii VTU Float32" : "ascii legacy VTK float");
    Mesh m32, m64, big;
    std::istringstream a(vtu ? ascii_vtu("Float32", tenths) : ascii_vtk("float", tenths));
    std::istringstream b(vtu ? ascii_vtu("Float64", tenths) : ascii_vtk("double", tenths));
    // a number beyond the float range: the file is read as doubles
    const std::string huge = "0 0 0 1e39 0 0 0 1 0 0 0 1";
    std::istringstream c(vtu ? ascii_vtu("Float32", huge) : ascii_vtk("float", huge));
    if (vtu) {
      IO::read_vtu(a, m32, "a.vtu");
      IO::read_vtu(b, m64, "b.vtu");
      IO::read_vtu(c, big, "c.vtu");
    } else {
      IO::read_vtk(a, m32, "a.vtk");
      IO::read_vtk(b, m64, "b.vtk");
      IO::read_vtk(c, big, "c.vtk");
    }
    CHECK(m32.float32_points);
    CHECK((m32.points == std::vector<Mesh::Point_3>{{0, 0, 0}, {f1, 0, 0}, {0, f2, 0}, {0, 0, f3}}));
    CHECK(!m64.float32_points);
    CHECK((m64.points == std::vector<Mesh::Point_3>{{0, 0, 0}, {0.1, 0, 0}, {0, 0.2, 0}, {0, 0, 0.3}}));
    CHECK(!big.float32_points);
    CHECK(big.points.size() == 4 && big.points[1].x() == 1e39);
  }
  {
    // vtktypefloat32 is float too
    Mesh m;
    std::istringstream in(ascii_vtk("vtktypefloat32", tenths));
    IO::read_vtk(in, m, "t.vtk");
    CHECK(m.float32_points && m.points.size() == 4 && m.points[1].x() == f1);
  }
  {
    // two pieces: Float32 and Float64 points make a mesh of doubles; both Float32, of floats
    std::string one = ascii_vtu("Float32", tenths);
    const std::size_t b = one.find("<Piece"), e = one.find("</Piece>") + 8;
    const std::string piece32 = one.substr(b, e - b);
    std::string piece64 = piece32;
    piece64.replace(piece64.find("Float32"), 7, "Float64");
    for (const bool mixed : {true, false}) {
      std::string text = one;
      text.insert(e, mixed ? piece64 : piece32);
      std::istringstream in(text);
      Mesh m;
      IO::read_vtu(in, m, "pieces.vtu");
      CHECK_EQUAL(m.points.size(), std::size_t(8));
      CHECK_EQUAL(m.float32_points, !mixed);
      if (m.points.size() == 8) CHECK_EQUAL(m.points[5].x(), mixed ? 0.1 : f1);
    }
  }

  // writers: a mesh with the flag set is written with 32-bit coordinates and read back the same
  Mesh m = lattice(2);
  CHECK_EQUAL(IO::internal::rounded_to_float(2.0 / 3), double(2.0f / 3));
  for (auto& p : m.points) // floats that are not short decimals, and one not exact in double text
    p = Mesh::Point_3(IO::internal::rounded_to_float(p.x() * 0.1), IO::internal::rounded_to_float(p.y() / 3),
                      IO::internal::rounded_to_float(p.z() + 1e-3));
  m.float32_points = true;
  struct Case {
    const char* name;
    std::function<void(const std::string&)> write;
    const char* must_contain;
  };
  const std::vector<Case> cases = {
      {"f32_default.vtu", [&](const std::string& f) { IO::write_vtu(f, m); },
       "<DataArray type=\"Float32\" Name=\"Points\" NumberOfComponents=\"3\" format=\"binary\">"},
      {"f32_ascii.vtu",
       [&](const std::string& f) { IO::write_vtu(f, m, {}, CGAL::parameters::use_binary_mode(false)); },
       "<DataArray type=\"Float32\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n0 0 "
       "0.001\n0.1 0 0.001\n"},
      {"f32_raw.vtu",
       [&](const std::string& f) {
         IO::write_vtu(f, m, {}, NP::compression(IO::Compression::none).use_binary_mode(true));
       },
       "type=\"Float32\" Name=\"Points\""},
      {"f32_ascii.vtk", [&](const std::string& f) { IO::write_tetrahedral_mesh(f, m); },
       "\nPOINTS 27 float\n0 0 0.001\n0.1 0 0.001\n"},
      {"f32_binary.vtk",
       [&](const std::string& f) { IO::write_vtk(f, m, {}, CGAL::parameters::use_binary_mode(true)); },
       "\nPOINTS 27 float\n"},
      {"f32_binary_51.vtk",
       [&](const std::string& f) { IO::write_vtk(f, m, {}, NP::format_version(5.1).use_binary_mode(true)); },
       "\nPOINTS 27 float\n"}};
  for (const Case& c : cases) {
    prstar_test::Failure_context context(std::string("Float32 writer ") + c.name);
    const std::string f = (tmp / c.name).string();
    c.write(f);
    std::ifstream in(f, std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    CHECK_MSG(text.find(c.must_contain) != std::string::npos, "no '" << c.must_contain << "'");
    Mesh r;
    IO::read_tetrahedral_mesh(f, r);
    CHECK(r.float32_points);
    CHECK(r.points == m.points);
    CHECK(r.tetrahedra == m.tetrahedra);
    CHECK(r.tetrahedron_labels == m.tetrahedron_labels);
    CHECK(r.point_data.size() == 1 && r.point_data[0].values == m.point_data[0].values);
  }
  {
    // the binary legacy file holds 4-byte big-endian floats: 27 x 3 x 4 bytes after the POINTS line
    std::ifstream in((tmp / "f32_binary.vtk").string(), std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const std::size_t at = text.find("\nPOINTS 27 float\n") + 17;
    CHECK(text.compare(at + 27 * 12, 7, "\nCELLS ") == 0);
  }
  // a coordinate beyond the float range cannot be written as a float: refused, no file
  Mesh too_big = m;
  too_big.points[3] = Mesh::Point_3(1e300, 0, 0);
  const std::string refused = (tmp / "refused.vtu").string();
  CHECK_THROWS(IO::Write_error, "beyond the range of 32-bit floats", IO::write_vtu(refused, too_big));
  CHECK(!fs::exists(refused));
  CHECK_THROWS(IO::Write_error, "vertex 3",
               IO::write_tetrahedral_mesh((tmp / "refused.vtk").string(), too_big));
  // a mesh type without the flag, or with a function of that name, writes doubles
  for (const bool function : {false, true}) {
    Function_flag_mesh d;
    d.points = m.points;
    d.tetrahedra = m.tetrahedra;
    const std::string f = (tmp / "doubles.vtu").string();
    if (function)
      IO::write_vtu(f, d);
    else
      IO::write_vtu(f, static_cast<const Doubles_only_mesh&>(d));
    Mesh r;
    IO::read_vtu(f, r);
    CHECK(!r.float32_points);
    CHECK(r.points == m.points);
  }
}

// ------------------------------------------------------------------------------------------------

static int bench(const std::string& file, int reps) {
  // wall time and the CPU time of the process (user + system: page faults count), the latter
  // meaningful on a shared, loaded machine
  double best = 1e300, best_cpu = 1e300;
  Mesh m;
  for (int i = 0; i < reps; ++i) {
    Mesh r;
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    IO::read_tetrahedral_mesh(file, r);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    best = std::min(best, s);
    best_cpu = std::min(best_cpu, double(std::clock() - c0) / CLOCKS_PER_SEC);
    if (i + 1 == reps) m = std::move(r);
  }
  // the decompressed bytes: the arrays of our writer (Float64 points, Int64 connectivity and
  // offsets, UInt8 types, Int32 labels, Float64 point and cell data)
  const double bytes = 24.0 * m.points.size() + (32.0 + 8 + 1) * m.tetrahedra.size() +
                       4.0 * m.tetrahedron_labels.size() + 8.0 * m.points.size() * m.point_data.size() +
                       8.0 * m.tetrahedra.size() * m.cell_data.size();
  const double file_bytes = static_cast<double>(fs::file_size(file));
  std::cout << std::fixed << std::setprecision(3) << "{\"file\": " << json_string(file)
            << ", \"vertices\": " << m.points.size() << ", \"tetrahedra\": " << m.tetrahedra.size()
            << ", \"file_MB\": " << file_bytes / 1e6 << ", \"decompressed_MB\": " << bytes / 1e6
            << ", \"best_seconds\": " << best << ", \"decompressed_MB_per_s\": " << bytes / 1e6 / best
            << ", \"best_cpu_seconds\": " << best_cpu
            << ", \"decompressed_MB_per_cpu_s\": " << bytes / 1e6 / best_cpu << "}\n";
  return 0;
}

// The shape measures of mesh_quality.h, per tetrahedron and for the whole mesh, as JSON.
static void quality(const Mesh& m, std::ostream& out) {
  namespace P = CGAL::PR_star_octree;
  auto list = [&](const char* name, auto f) {
    out << '"' << name << "\": [";
    for (std::size_t t = 0; t < m.tetrahedra.size(); ++t) {
      const auto& v = m.tetrahedra[t];
      out << (t ? ", " : "") << f(m.points[v[0]], m.points[v[1]], m.points[v[2]], m.points[v[3]]);
    }
    out << "], ";
  };
  using Point = Mesh::Point_3;
  out << std::setprecision(17) << '{';
  list("min_dihedral", [](const Point& p, const Point& q, const Point& r, const Point& s) {
    return P::min_dihedral_angle(p, q, r, s);
  });
  list("max_dihedral", [](const Point& p, const Point& q, const Point& r, const Point& s) {
    return P::max_dihedral_angle(p, q, r, s);
  });
  list("radius_ratio", [](const Point& p, const Point& q, const Point& r, const Point& s) {
    return P::radius_ratio(p, q, r, s);
  });
  const P::Mesh_quality q = P::mesh_quality(m.points, m.tetrahedra);
  out << "\"mesh\": {\"tetrahedra\": " << q.tetrahedra << ", \"min_dihedral\": " << q.min_dihedral_angle
      << ", \"max_dihedral\": " << q.max_dihedral_angle << ", \"min_radius_ratio\": " << q.min_radius_ratio
      << ", \"under_5_degrees\": " << q.under_5_degrees << ", \"under_10_degrees\": " << q.under_10_degrees
      << "}}\n";
}

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  try {
    if (mode == "--dump" && argc == 3) {
      Mesh m;
      IO::read_tetrahedral_mesh(argv[2], m);
      dump(m, std::cout);
      return 0;
    }
    if (mode == "--convert" && (argc == 4 || argc == 5)) {
      Mesh m;
      IO::read_tetrahedral_mesh(argv[2], m);
      // ascii | binary | binary-none (appended raw, uncompressed) | ascii-5.1 | binary-5.1 (legacy VTK 5.1)
      const std::string how = argc == 5 ? argv[4] : "";
      const bool binary = how.rfind("binary", 0) == 0;
      if (how == "binary-none")
        IO::write_tetrahedral_mesh(argv[3], m, NP::compression(IO::Compression::none).use_binary_mode(true));
      else if (how.size() > 4 && how.substr(how.size() - 4) == "-5.1")
        IO::write_tetrahedral_mesh(argv[3], m, NP::format_version(5.1).use_binary_mode(binary));
      else if (argc == 5)
        IO::write_tetrahedral_mesh(argv[3], m, CGAL::parameters::use_binary_mode(binary));
      else
        IO::write_tetrahedral_mesh(argv[3], m);
      return 0;
    }
    if (mode == "--lattice" && argc == 4) {
      const Mesh m = lattice(std::stoul(argv[2]));
      IO::write_tetrahedral_mesh(argv[3], m);
      std::cout << m.points.size() << " vertices, " << m.tetrahedra.size() << " tetrahedra\n";
      return 0;
    }
    if (mode == "--quality" && argc == 3) {
      Mesh m;
      IO::read_tetrahedral_mesh(argv[2], m);
      quality(m, std::cout);
      return 0;
    }
    if (mode == "--bench" && (argc == 3 || argc == 4))
      return bench(argv[2], argc == 4 ? std::atoi(argv[3]) : 3);
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  if (!mode.empty()) {
    std::cerr << "usage: test_io_vtk [--dump FILE | --convert IN OUT [ascii|binary] | --lattice N OUT | "
                 "--bench FILE [reps] | --quality FILE]\n";
    return 2;
  }
  tmp = fs::temp_directory_path() / ("test_io_vtk_" + std::to_string(::getpid()));
  fs::create_directories(tmp);
  test_vtu_combinations();
  test_malformed_compressed();
  test_legacy();
  test_vtu_writer();
  test_float32();
  test_vtu_ranges();
  fs::remove_all(tmp);
  return prstar_test::summary("test_io_vtk");
}
