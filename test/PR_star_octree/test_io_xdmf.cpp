// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project
//
// The XDMF reader and writer (CGAL/PR_star_octree/IO/xdmf.h):
// - round trips, inline XML and HDF5, bit for bit (awkward doubles, labels, point and cell data,
//   names to escape), the default storage, the write options;
// - hand-written files as XDMF 2, meshio, DOLFINx and ParaView write them: Tetrahedron and Mixed
//   topologies, BaseOffset, temporal collections with xi:include, labels by name and type, vector
//   attributes skipped;
// - malformed files (XML, counts, indices, topology and geometry types) and, with HDF5, .h5 files
//   missing, of the wrong shape or type, or announcing a huge dataset (refused by the memory check);
//   without HDF5, the "no HDF5 support" errors.
//
// Usage: test_io_xdmf SCRATCH_DIR                       the tests
//        test_io_xdmf --dump FILE                       what the reader read, as JSON (interop_xdmf.py)
//        test_io_xdmf --convert IN OUT [xml|hdf]        reads IN (any format), writes OUT

#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/IO/xdmf.h>

#include "test_harness.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace IO = CGAL::PR_star_octree::IO;
using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;
namespace fs = std::filesystem;

static fs::path tmp;

static std::string put(const std::string& name, const std::string& content) {
  const fs::path p = tmp / name;
  std::ofstream out(p, std::ios::binary);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  return p.string();
}

// ------------------------------------------------------------------------------------------------
// --dump and --convert (interop_xdmf.py)
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

static std::string num(double x) {
  if (x == 0 && std::signbit(x)) return "-0.0"; // not "-0", an integer for JSON readers
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

static void dump(const Mesh& m, std::ostream& out) {
  out << "{\"points\": [";
  for (std::size_t i = 0; i < m.points.size(); ++i)
    out << (i ? ", " : "") << "[" << num(m.points[i].x()) << ", " << num(m.points[i].y()) << ", "
        << num(m.points[i].z()) << "]";
  out << "], \"tetrahedra\": [";
  for (std::size_t i = 0; i < m.tetrahedra.size(); ++i) {
    const auto& t = m.tetrahedra[i];
    out << (i ? ", " : "") << "[" << t[0] << ", " << t[1] << ", " << t[2] << ", " << t[3] << "]";
  }
  out << "], \"labels\": [";
  for (std::size_t i = 0; i < m.tetrahedron_labels.size(); ++i)
    out << (i ? ", " : "") << m.tetrahedron_labels[i];
  const auto arrays = [&](const std::vector<CGAL::PR_star_octree::Data_array>& v) {
    out << "{";
    for (std::size_t k = 0; k < v.size(); ++k) {
      out << (k ? ", " : "") << json_string(v[k].name) << ": [";
      for (std::size_t i = 0; i < v[k].values.size(); ++i) out << (i ? ", " : "") << num(v[k].values[i]);
      out << "]";
    }
    out << "}";
  };
  out << "], \"point_data\": ";
  arrays(m.point_data);
  out << ", \"cell_data\": ";
  arrays(m.cell_data);
  out << ", \"skipped_cells\": {";
  bool first = true;
  for (const auto& kv : m.skipped_cells) {
    out << (first ? "" : ", ") << json_string(kv.first) << ": " << kv.second;
    first = false;
  }
  out << "}}\n";
}

// ------------------------------------------------------------------------------------------------
// Round trips
// ------------------------------------------------------------------------------------------------

static Mesh awkward_mesh() {
  Mesh m;
  const double third = 1.0 / 3.0;
  m.points = {{0.1, -0.0, third},
              {1e-300, 5e-324, 1e300},
              {-2.5, 0.30000000000000004, 7},
              {1, 2, 3},
              {std::nextafter(1.0, 2.0), -1e-10, 123456789.123456789}};
  m.tetrahedra = {{0, 1, 2, 3}, {1, 2, 3, 4}, {4, 3, 0, 1}};
  m.tetrahedron_labels = {3, -7, 2147483647};
  m.point_data.push_back({"phi", {0.5, third, -1e-310, 4, 5}});
  m.point_data.push_back({"a<b&\"c\" 'd'", {1, 2, 3, 4, 5}});
  m.cell_data.push_back({"quality", {0.25, third, 1e20}});
  m.cell_data.push_back({"gmsh:physical", {1.5, 2, 3}}); // a label name, but not integers: cell data
  return m;
}

static bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

static void check_same(const Mesh& r, const Mesh& m) {
  CHECK_EQUAL(r.points.size(), m.points.size());
  bool bits = r.points.size() == m.points.size();
  for (std::size_t i = 0; bits && i < m.points.size(); ++i)
    bits = same_bits(r.points[i].x(), m.points[i].x()) && same_bits(r.points[i].y(), m.points[i].y()) &&
           same_bits(r.points[i].z(), m.points[i].z());
  CHECK_MSG(bits, "the coordinates are not the same bits");
  CHECK(r.tetrahedra == m.tetrahedra);
  CHECK(r.tetrahedron_labels == m.tetrahedron_labels);
  const auto same_arrays = [](const std::vector<CGAL::PR_star_octree::Data_array>& a,
                              const std::vector<CGAL::PR_star_octree::Data_array>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t k = 0; k < a.size(); ++k) {
      if (a[k].name != b[k].name || a[k].values.size() != b[k].values.size()) return false;
      for (std::size_t i = 0; i < a[k].values.size(); ++i)
        if (!same_bits(a[k].values[i], b[k].values[i])) return false;
    }
    return true;
  };
  CHECK_MSG(same_arrays(r.point_data, m.point_data), "point data differ");
  CHECK_MSG(same_arrays(r.cell_data, m.cell_data), "cell data differ");
  CHECK(r.skipped_cells.empty());
}

static std::string file_text(const std::string& f) {
  std::ifstream in(f, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// `awkward_mesh()` with float coordinates (the values beyond the float range replaced; -0 and a
/// subnormal float kept) and `float32_points` set.
static Mesh float32_mesh() {
  Mesh m = awkward_mesh();
  m.points[1] = Mesh::Point_3(1e-30, 5e-40, 1e30);
  for (auto& p : m.points)
    p = Mesh::Point_3(IO::internal::rounded_to_float(p.x()), IO::internal::rounded_to_float(p.y()),
                      IO::internal::rounded_to_float(p.z()));
  m.float32_points = true;
  return m;
}

static void test_float32_round_trips() {
  const Mesh m = float32_mesh();
  for (const bool hdf : {false, true}) {
    if (hdf && !IO::xdmf_has_hdf5()) continue;
    prstar_test::Failure_context c(hdf ? "float32, HDF5" : "float32, inline XML");
    const std::string f = (tmp / (hdf ? "f32_heavy.xdmf" : "f32_inline.xdmf")).string();
    IO::write_xdmf(f, m, CGAL::parameters::use_binary_mode(hdf));
    const std::string text = file_text(f);
    CHECK(
        text.find("<Geometry GeometryType=\"XYZ\">\n        <DataItem DataType=\"Float\" Precision=\"4\"") !=
        std::string::npos);
    Mesh r;
    IO::read_xdmf(f, r); // (HDF5: the flag comes from the dataset's type, float32)
    CHECK(r.float32_points);
    check_same(r, m);
    // a mesh of doubles stays one
    Mesh d = m;
    d.float32_points = false;
    IO::write_xdmf(f, d, CGAL::parameters::use_binary_mode(hdf));
    CHECK(file_text(f).find("Precision=\"8\" Dimensions=\"5 3\"") != std::string::npos);
    IO::read_xdmf(f, r);
    CHECK(!r.float32_points);
    check_same(r, d);
  }
}

static void test_round_trips() {
  const Mesh m = awkward_mesh();
  // inline XML
  {
    prstar_test::Failure_context c("inline XML");
    const std::string f = (tmp / "inline.xdmf").string();
    IO::write_xdmf(f, m, CGAL::parameters::use_binary_mode(false));
    CHECK(!fs::exists(tmp / "inline.h5"));
    CHECK(file_text(f).find("Format=\"XML\"") != std::string::npos);
    Mesh r;
    IO::read_xdmf(f, r);
    check_same(r, m);
    // through the format table and a stream
    Mesh r2;
    IO::read_tetrahedral_mesh(f, r2);
    check_same(r2, m);
    std::ifstream in(f);
    Mesh r3;
    IO::read_xdmf(in, r3, "the stream");
    check_same(r3, m);
  }
  // HDF5
  const std::string f = (tmp / "heavy.xdmf").string();
  if (IO::xdmf_has_hdf5()) {
    prstar_test::Failure_context c("HDF5");
    IO::write_xdmf(f, m);
    CHECK(fs::exists(tmp / "heavy.h5"));
    const std::string text = file_text(f);
    CHECK(text.find("heavy.h5:/Mesh/geometry") != std::string::npos &&
          text.find("heavy.h5:/Mesh/topology") != std::string::npos &&
          text.find("Name=\"label\"") != std::string::npos &&
          text.find("Format=\"XML\"") == std::string::npos);
    Mesh r;
    IO::read_xdmf(f, r);
    check_same(r, m);
    // read from another working folder: the .h5 is found beside the .xdmf
    const fs::path here = fs::current_path();
    fs::current_path("/");
    Mesh r2;
    IO::read_tetrahedral_mesh(f, r2);
    fs::current_path(here);
    check_same(r2, m);
    // the other extension, through the dispatcher: its .h5 beside it
    IO::write_tetrahedral_mesh((tmp / "other.xmf").string(), m);
    CHECK(fs::exists(tmp / "other.h5"));
    Mesh rx;
    IO::read_tetrahedral_mesh((tmp / "other.xmf").string(), rx);
    check_same(rx, m);
    // the same mesh written again over the files, through the dispatcher
    IO::write_tetrahedral_mesh(f, m, CGAL::parameters::use_binary_mode(true));
    Mesh r3;
    IO::read_xdmf(f, r3);
    check_same(r3, m);
    // written through a temporary and renamed (as prstar writes its outputs): the .xdmf names the
    // final .h5
    IO::internal::write_xdmf_file((tmp / "t.tmp.xdmf").string(), m, {}, (tmp / "t.tmp.h5").string(),
                                  "final.h5");
    fs::rename(tmp / "t.tmp.xdmf", tmp / "final.xdmf");
    fs::rename(tmp / "t.tmp.h5", tmp / "final.h5");
    Mesh r5;
    IO::read_xdmf((tmp / "final.xdmf").string(), r5);
    check_same(r5, m);
    // a stream cannot follow the .h5
    std::ifstream in(f);
    Mesh r4;
    CHECK_THROWS(IO::Read_error, "cannot be read from a stream", IO::read_xdmf(in, r4, "the stream"));
  } else {
    prstar_test::skip("HDF5 round trips (no HDF5 in this build)");
    CHECK_THROWS(
        IO::Write_error,
        "heavy.xdmf: this build of the package has no HDF5 support (rebuild with libhdf5-dev installed)",
        IO::write_xdmf(f, m, CGAL::parameters::use_binary_mode(true)));
    IO::write_xdmf(f, m); // the default without HDF5: inline
    CHECK(file_text(f).find("Format=\"XML\"") != std::string::npos);
    Mesh r;
    IO::read_xdmf(f, r);
    check_same(r, m);
  }
  // options refused, empty mesh, mesh without data
  CHECK_THROWS(IO::Write_error, "only compression(none)",
               IO::write_xdmf(f, m, CGAL::PR_star_octree::parameters::compression(IO::Compression::zlib)));
  CHECK_THROWS(IO::Write_error, "cannot be written (3.0)",
               IO::write_xdmf(f, m, CGAL::PR_star_octree::parameters::format_version(2.0)));
  IO::write_xdmf(f, m, CGAL::PR_star_octree::parameters::format_version(3.0).use_binary_mode(false));
  for (const bool binary : {false, true}) {
    if (binary && !IO::xdmf_has_hdf5()) continue;
    Mesh plain;
    plain.points = m.points;
    plain.tetrahedra = m.tetrahedra;
    IO::write_xdmf(f, plain, CGAL::parameters::use_binary_mode(binary));
    Mesh r;
    IO::read_xdmf(f, r);
    check_same(r, plain);
    Mesh empty;
    IO::write_xdmf(f, empty, CGAL::parameters::use_binary_mode(binary));
    r = m;
    IO::read_xdmf(f, r);
    CHECK(r.points.empty() && r.tetrahedra.empty() && r.point_data.empty());
  }
  Mesh bad = m;
  bad.tetrahedra[0][0] = 9;
  CHECK_THROWS(IO::Write_error, "out of range", IO::write_xdmf(f, bad));
  bad = m;
  bad.cell_data[0].values.pop_back();
  CHECK_THROWS(IO::Write_error, "cell data 'quality' has 2 values", IO::write_xdmf(f, bad));
}

// ------------------------------------------------------------------------------------------------
// Hand-written files
// ------------------------------------------------------------------------------------------------

static const char* points5 = "0 0 0  1 0 0  0 1 0  0 0 1  1 1 1";

static std::string xdmf3(const std::string& grid_content) {
  return "<?xml version=\"1.0\"?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"3.0\" "
         "xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n<Domain>\n<Grid Name=\"mesh\" "
         "GridType=\"Uniform\">\n" +
         grid_content + "</Grid>\n</Domain>\n</Xdmf>\n";
}

static std::string geometry5() {
  return std::string("<Geometry GeometryType=\"XYZ\"><DataItem Dimensions=\"5 3\" Format=\"XML\">") +
         points5 + "</DataItem></Geometry>\n";
}

static Mesh read_text(const std::string& name, const std::string& text) {
  Mesh m;
  IO::read_xdmf(put(name, text), m);
  return m;
}

static void test_hand_written() {
  {
    prstar_test::Failure_context c("XDMF 2 with NumberType, Type and BaseOffset");
    const Mesh m = read_text(
        "v2.xdmf",
        "<Xdmf Version=\"2.0\"><Domain><Grid Name=\"g\">"
        "<Topology Type=\"Tetrahedron\" NumberOfElements=\"2\" BaseOffset=\"1\">"
        "<DataItem Dimensions=\"2 4\" NumberType=\"Int\" Precision=\"4\" Format=\"XML\">1 2 3 4 2 3 4 "
        "5</DataItem>"
        "</Topology><Geometry Type=\"XYZ\"><DataItem Dimensions=\"15\" NumberType=\"Float\" "
        "Precision=\"4\">" +
            std::string(points5) +
            "</DataItem></Geometry>"
            "<Attribute Name=\"T\" Center=\"Node\"><DataItem Dimensions=\"5 1\">1 2 3 4 "
            "5</DataItem></Attribute>"
            "<Attribute Name=\"v\" AttributeType=\"Vector\" Center=\"Node\"><DataItem Dimensions=\"5 3\">" +
            points5 +
            "</DataItem></Attribute>"
            "<Attribute Name=\"g\" Center=\"Grid\"><DataItem Dimensions=\"1\">7</DataItem></Attribute>"
            "</Grid></Domain></Xdmf>");
    CHECK_EQUAL(m.points.size(), std::size_t(5));
    CHECK(m.float32_points); // a Float geometry of Precision 4
    CHECK((m.tetrahedra == std::vector<Mesh::Tetrahedron>{{0, 1, 2, 3}, {1, 2, 3, 4}}));
    CHECK_EQUAL(m.point_data.size(), std::size_t(1));
    CHECK(m.point_data.size() == 1 && m.point_data[0].name == "T" && m.point_data[0].values[4] == 5);
  }
  {
    prstar_test::Failure_context c("inline geometry of Precision 4, 8 and none");
    for (const char* precision : {" Precision=\"4\"", " Precision=\"8\"", ""}) {
      const Mesh m =
          read_text("precision.xdmf",
                    xdmf3(std::string("<Topology TopologyType=\"Tetrahedron\"><DataItem DataType=\"Int\" "
                                      "Format=\"XML\">0 1 2 3 1 2 3 4</DataItem></Topology>\n") +
                          "<Geometry GeometryType=\"XYZ\"><DataItem Dimensions=\"5 3\" "
                          "DataType=\"Float\"" +
                          precision + " Format=\"XML\">0 0 0 0.1 0 0 0 0.2 0 0 0 0.3 1 1 1" +
                          "</DataItem></Geometry>\n"));
      const bool f32 = precision[0] != 0 && precision[12] == '4';
      CHECK_EQUAL(m.float32_points, f32); // without Precision: read as doubles
      CHECK(m.points.size() == 5 && m.points[1].x() == (f32 ? double(0.1f) : 0.1) &&
            m.points[3].z() == (f32 ? double(0.3f) : 0.3));
    }
  }
  {
    prstar_test::Failure_context c("DOLFINx-like: NodesPerElement, no NumberOfElements, name_to_read");
    const Mesh m = read_text(
        "dolfinx.xdmf", xdmf3("<Topology TopologyType=\"Tetrahedron\" NodesPerElement=\"4\">"
                              "<DataItem Dimensions=\"2 4\" NumberType=\"Int\" Format=\"XML\">0 1 2 3 1 2 3 "
                              "4</DataItem></Topology>\n" +
                              geometry5() +
                              "<Attribute Name=\"q\" AttributeType=\"Scalar\" Center=\"Cell\"><DataItem "
                              "Dimensions=\"2\" Format=\"XML\">0.5 1.5</DataItem></Attribute>\n"
                              "<Attribute Name=\"name_to_read\" AttributeType=\"Scalar\" Center=\"Cell\">"
                              "<DataItem Dimensions=\"2 1\" DataType=\"Int\" Format=\"XML\">4 9</DataItem>"
                              "</Attribute>\n"));
    CHECK_EQUAL(m.tetrahedra.size(), std::size_t(2));
    CHECK((m.tetrahedron_labels == std::vector<int>{4, 9}));
    CHECK(m.cell_data.size() == 1 && m.cell_data[0].name == "q" && m.cell_data[0].values[1] == 1.5);
  }
  {
    prstar_test::Failure_context c("a Float label array is cell data");
    const Mesh m = read_text("float_label.xdmf",
                             xdmf3("<Topology TopologyType=\"Tetrahedron\"><DataItem Dimensions=\"1 4\" "
                                   "DataType=\"Int\" Format=\"XML\">0 1 2 3</DataItem></Topology>\n" +
                                   geometry5() +
                                   "<Attribute Name=\"label\" Center=\"Cell\"><DataItem Dimensions=\"1\" "
                                   "Format=\"XML\">3</DataItem></Attribute>\n"));
    CHECK(m.tetrahedron_labels.empty());
    CHECK(m.cell_data.size() == 1 && m.cell_data[0].name == "label");
  }
  {
    prstar_test::Failure_context c("Mixed topology");
    // a tetrahedron, a triangle, a poly-line of 3, a polygon of 4, a tetrahedron, a polyhedron of 2
    // faces, a hexahedron
    const std::string mixed = "6 0 1 2 3  4 0 1 2  2 3 0 1 2  3 4 0 1 2 3  6 1 2 3 4  16 2 3 0 1 2 3 1 2 3  "
                              "9 0 1 2 3 4 0 1 2";
    const Mesh m = read_text(
        "mixed.xdmf",
        xdmf3("<Topology TopologyType=\"Mixed\" NumberOfElements=\"7\"><DataItem Dimensions=\"44\" "
              "DataType=\"Int\" Format=\"XML\">" +
              mixed + "</DataItem></Topology>\n" + geometry5() +
              "<Attribute Name=\"gmsh:physical\" Center=\"Cell\"><DataItem Dimensions=\"7\" DataType=\"Int\" "
              "Format=\"XML\">10 11 12 13 14 15 16</DataItem></Attribute>\n"
              "<Attribute Name=\"w\" Center=\"Cell\"><DataItem Dimensions=\"7\" Format=\"XML\">0 1 2 3 4 5 "
              "6</DataItem></Attribute>\n"));
    CHECK((m.tetrahedra == std::vector<Mesh::Tetrahedron>{{0, 1, 2, 3}, {1, 2, 3, 4}}));
    CHECK((m.tetrahedron_labels == std::vector<int>{10, 14}));
    CHECK(m.cell_data.size() == 1 && m.cell_data[0].values == std::vector<double>({0, 4}));
    CHECK_EQUAL(m.skipped_cells.size(), std::size_t(5));
    CHECK(m.skipped_cells.count("triangle") == 1 && m.skipped_cells.count("polyhedron") == 1 &&
          m.skipped_cells.count("hexahedron") == 1 && m.skipped_cells.count("poly-line") == 1 &&
          m.skipped_cells.count("polygon") == 1);
  }
  {
    prstar_test::Failure_context c("temporal collection with xi:include (meshio's TimeSeriesWriter)");
    const std::string text =
        "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2003/XInclude\"><Domain>"
        "<Grid Name=\"TimeSeries\" GridType=\"Collection\" CollectionType=\"Temporal\">"
        "<Grid><xi:include xpointer=\"xpointer(//Grid[@Name=&quot;mesh&quot;]/*[self::Topology or "
        "self::Geometry])\" /><Time Value=\"0.0\" />"
        "<Attribute Name=\"phi\" AttributeType=\"Scalar\" Center=\"Node\"><DataItem Dimensions=\"5\" "
        "Format=\"XML\">0 1 2 3 4</DataItem></Attribute></Grid>"
        "<Grid><xi:include xpointer=\"xpointer(//Grid[@Name=&quot;mesh&quot;]/*[self::Topology or "
        "self::Geometry])\" /><Time Value=\"1.0\" />"
        "<Attribute Name=\"phi\" AttributeType=\"Scalar\" Center=\"Node\"><DataItem Dimensions=\"5\" "
        "Format=\"XML\">9 9 9 9 9</DataItem></Attribute></Grid></Grid>"
        "<Grid Name=\"other\" GridType=\"Uniform\"><Geometry GeometryType=\"XYZ\"><DataItem Dimensions=\"4 "
        "3\" "
        "Format=\"XML\">0 0 0 1 0 0 0 1 0 0 0 1</DataItem></Geometry><Topology TopologyType=\"Tetrahedron\">"
        "<DataItem Dimensions=\"1 4\" DataType=\"Int\" Format=\"XML\">0 1 2 3</DataItem></Topology></Grid>"
        "<Grid Name=\"mesh\" GridType=\"Uniform\">" +
        geometry5() +
        "<Topology TopologyType=\"Tetrahedron\" NumberOfElements=\"2\"><DataItem Dimensions=\"2 4\" "
        "DataType=\"Int\" Format=\"XML\">0 1 2 3 1 2 3 4</DataItem></Topology></Grid></Domain></Xdmf>";
    const Mesh m = read_text("series.xdmf", text);
    CHECK_EQUAL(m.points.size(), std::size_t(5));
    CHECK_EQUAL(m.tetrahedra.size(), std::size_t(2));
    CHECK(m.point_data.size() == 1 && m.point_data[0].values == std::vector<double>({0, 1, 2, 3, 4}));
  }
}

// ------------------------------------------------------------------------------------------------
// Malformed files
// ------------------------------------------------------------------------------------------------

static void expect_error(const std::string& name, const std::string& text, const std::string& what) {
  prstar_test::Failure_context c(name);
  const std::string f = put(name, text);
  Mesh m;
  m.points.push_back({9, 9, 9});
  CHECK_THROWS(IO::Read_error, what, IO::read_xdmf(f, m));
  CHECK_EQUAL(m.points.size(), std::size_t(1)); // left unchanged
  // the stream reader says the same (it cannot follow .h5 files)
  std::istringstream in(text);
  Mesh s;
  try {
    IO::read_xdmf(in, s, name);
    FAIL("the stream reader accepted " << name);
  } catch (const IO::Read_error& e) {
    CHECK(std::string(e.what()).rfind(name, 0) == 0);
  }
}

static std::string tet_topology(const std::string& values, const std::string& extra = "") {
  return "<Topology TopologyType=\"Tetrahedron\"" + extra + "><DataItem DataType=\"Int\" Format=\"XML\">" +
         values + "</DataItem></Topology>\n";
}

static void test_malformed() {
  const std::string good = xdmf3(tet_topology("0 1 2 3") + geometry5());
  {
    Mesh m;
    IO::read_xdmf(put("good.xdmf", good), m);
    CHECK_EQUAL(m.tetrahedra.size(), std::size_t(1));
  }
  expect_error("truncated.xdmf", good.substr(0, good.find("</Grid>")), "is not closed");
  expect_error("truncated_tag.xdmf", good.substr(0, good.find("Format=\"XML\">0 1")),
               "unterminated tag <DataItem>");
  expect_error("not_xdmf.xdmf", "<VTKFile/>", "not an XDMF file");
  expect_error("no_domain.xdmf", "<Xdmf/>", "without a <Domain>");
  expect_error("no_grid.xdmf", "<Xdmf><Domain/></Xdmf>", "without a <Grid>");
  expect_error("no_topology.xdmf", xdmf3(geometry5()), "without a <Topology>");
  expect_error("ne_larger.xdmf", xdmf3(tet_topology("0 1 2 3", " NumberOfElements=\"5\"") + geometry5()),
               "NumberOfElements=\"5\" but the data hold 4 values");
  expect_error("dims_larger.xdmf",
               xdmf3("<Topology TopologyType=\"Tetrahedron\"><DataItem Dimensions=\"3 4\" DataType=\"Int\" "
                     "Format=\"XML\">0 1 2 3</DataItem></Topology>" +
                     geometry5()),
               "4 values, 12 expected");
  expect_error("huge_dims.xdmf",
               xdmf3("<Topology TopologyType=\"Tetrahedron\"><DataItem Dimensions=\"100000000000000 4\" "
                     "DataType=\"Int\" Format=\"XML\">0 1 2 3</DataItem></Topology>" +
                     geometry5()),
               "4 values, 400000000000000 expected");
  expect_error("more_values.xdmf",
               xdmf3("<Topology TopologyType=\"Tetrahedron\"><DataItem Dimensions=\"1 4\" DataType=\"Int\" "
                     "Format=\"XML\">0 1 2 3 4</DataItem></Topology>" +
                     geometry5()),
               "more values than the 4 expected");
  expect_error("index_range.xdmf", xdmf3(tet_topology("0 1 2 5") + geometry5()),
               "cell 0: vertex index 5 out of range (0-based, 5 points)");
  expect_error("index_negative.xdmf", xdmf3(tet_topology("0 1 -2 3") + geometry5()),
               "vertex index -2 out of range");
  expect_error("base_offset.xdmf", xdmf3(tet_topology("0 1 2 3", " BaseOffset=\"1\"") + geometry5()),
               "vertex index 0 out of range (BaseOffset 1");
  expect_error("repeated.xdmf", xdmf3(tet_topology("0 1 1 3") + geometry5()), "vertex index 1 listed twice");
  expect_error("index_float.xdmf", xdmf3(tet_topology("0 1 2 3.5") + geometry5()), "'3.5' is not an integer");
  expect_error("float_topology.xdmf",
               xdmf3("<Topology TopologyType=\"Tetrahedron\"><DataItem Format=\"XML\">0 1 2 "
                     "3</DataItem></Topology>" +
                     geometry5()),
               "floating-point values");
  expect_error("not_multiple.xdmf", xdmf3(tet_topology("0 1 2 3 4") + geometry5()), "not a multiple of 4");
  expect_error("npe.xdmf", xdmf3(tet_topology("0 1 2 3", " NodesPerElement=\"10\"") + geometry5()),
               "NodesPerElement=\"10\"");
  expect_error(
      "hexahedron.xdmf",
      xdmf3("<Topology TopologyType=\"Hexahedron\"><DataItem DataType=\"Int\" Format=\"XML\">0 1 2 3 4 0 "
            "1 2</DataItem></Topology>" +
            geometry5()),
      "TopologyType 'Hexahedron' is not a tetrahedral mesh");
  expect_error(
      "mixed_no_tet.xdmf",
      xdmf3("<Topology TopologyType=\"Mixed\"><DataItem DataType=\"Int\" Format=\"XML\">4 0 1 2 4 1 2 "
            "3</DataItem></Topology>" +
            geometry5()),
      "no tetrahedron among the 2 cells");
  expect_error(
      "mixed_truncated.xdmf",
      xdmf3("<Topology TopologyType=\"Mixed\"><DataItem DataType=\"Int\" Format=\"XML\">6 0 1 2 3 6 1 "
            "2</DataItem></Topology>" +
            geometry5()),
      "ends inside cell 1");
  expect_error(
      "mixed_type.xdmf",
      xdmf3("<Topology TopologyType=\"Mixed\"><DataItem DataType=\"Int\" Format=\"XML\">6 0 1 2 3 77 1 "
            "2</DataItem></Topology>" +
            geometry5()),
      "cell 1: unknown XDMF cell type 77");
  expect_error("mixed_count.xdmf",
               xdmf3("<Topology TopologyType=\"Mixed\" NumberOfElements=\"3\"><DataItem DataType=\"Int\" "
                     "Format=\"XML\">6 0 1 2 3</DataItem></Topology>" +
                     geometry5()),
               "NumberOfElements=\"3\" but the Mixed topology holds 1 cells");
  expect_error(
      "xy.xdmf",
      xdmf3(tet_topology("0 1 2 3") +
            "<Geometry GeometryType=\"XY\"><DataItem Dimensions=\"4 2\" Format=\"XML\">0 0 1 0 0 1 1 "
            "1</DataItem></Geometry>"),
      "GeometryType 'XY': two-dimensional points");
  expect_error("xyz_dims.xdmf",
               xdmf3(tet_topology("0 1 2 3") +
                     "<Geometry><DataItem Dimensions=\"6 2\" Format=\"XML\">0 0 1 0 0 1 1 1 0 0 0 "
                     "0</DataItem></Geometry>"),
               "2 coordinates per point");
  expect_error("coord_nan.xdmf",
               xdmf3(tet_topology("0 1 2 3") +
                     "<Geometry><DataItem Dimensions=\"4 3\" Format=\"XML\">0 0 0 1 0 0 0 nan 0 0 0 "
                     "1</DataItem></Geometry>"),
               "value 7 'nan' is not");
  expect_error("binary_format.xdmf",
               xdmf3(tet_topology("0 1 2 3") +
                     "<Geometry><DataItem Dimensions=\"4 3\" Format=\"Binary\">x.bin</DataItem></Geometry>"),
               "Format 'Binary' is not supported");
  expect_error("hyperslab.xdmf",
               xdmf3(tet_topology("0 1 2 3") +
                     "<Geometry><DataItem ItemType=\"HyperSlab\" Dimensions=\"4 3\">x</DataItem></Geometry>"),
               "ItemType 'HyperSlab' is not supported");
  expect_error("bad_reference.xdmf",
               xdmf3(tet_topology("0 1 2 3") +
                     "<Geometry><DataItem Dimensions=\"4 3\" Format=\"HDF\">nocolon</DataItem></Geometry>"),
               "is not FILE.h5:/path/to/dataset");
  expect_error("collection_empty.xdmf", "<Xdmf><Domain><Grid GridType=\"Collection\"/></Domain></Xdmf>",
               "without a <Grid> inside");
  expect_error("point_attribute.xdmf",
               xdmf3(tet_topology("0 1 2 3") + geometry5() +
                     "<Attribute Name=\"p\" Center=\"Node\"><DataItem Dimensions=\"4\" Format=\"XML\">1 2 3 "
                     "4</DataItem></Attribute>"),
               "attribute 'p': 4 values, 5 expected");
  expect_error(
      "duplicate_attribute.xdmf",
      xdmf3(
          tet_topology("0 1 2 3") + geometry5() +
          "<Attribute Name=\"p\" Center=\"Node\"><DataItem Format=\"XML\">1 2 3 4 5</DataItem></Attribute>"
          "<Attribute Name=\"p\" Center=\"Node\"><DataItem Format=\"XML\">1 2 3 4 5</DataItem></Attribute>"),
      "two point attributes are named 'p'");
  // the memory limit: the mesh announced does not fit
  {
    IO::Memory_limit limit(100);
    expect_error("memory.xdmf", good, "refused before reading it");
  }
  // an HDF5 reference: stream mode refuses it; without HDF5 the file reader too
  const std::string h5ref = xdmf3(tet_topology("0 1 2 3") +
                                  "<Geometry><DataItem Dimensions=\"5 3\" Format=\"HDF\">missing.h5:/Mesh/"
                                  "geometry</DataItem></Geometry>");
  {
    std::istringstream in(h5ref);
    Mesh m;
    CHECK_THROWS(IO::Read_error,
                 "the values are in the HDF5 file 'missing.h5', which cannot be read from a stream",
                 IO::read_xdmf(in, m, "s"));
  }
  const std::string missing = put("missing_h5.xdmf", h5ref);
  Mesh m;
  if (IO::xdmf_has_hdf5())
    CHECK_THROWS(IO::Read_error, "missing.h5' (of missing.h5:/Mesh/geometry): no such file",
                 IO::read_xdmf(missing, m));
  else
    CHECK_THROWS(IO::Read_error,
                 missing +
                     ": this build of the package has no HDF5 support (rebuild with libhdf5-dev installed)",
                 IO::read_xdmf(missing, m));
}

// ------------------------------------------------------------------------------------------------
// HDF5 files of the wrong shape or type
// ------------------------------------------------------------------------------------------------

#ifdef CGAL_PR_STAR_OCTREE_USE_HDF5
// Writes a dataset of `dims` of HDF5 type `type` (memory type `mem`, values `data`, or none written:
// a chunked dataset whose chunks are never allocated).
static void h5_dataset(hid_t file, const char* path, std::vector<hsize_t> dims, hid_t type, hid_t mem,
                       const void* data) {
  const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
  const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  if (data == nullptr) {
    std::vector<hsize_t> chunk(dims.size(), 1);
    chunk.back() = dims.back();
    H5Pset_chunk(dcpl, static_cast<int>(chunk.size()), chunk.data());
  }
  const hid_t d = H5Dcreate2(file, path, type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
  CHECK(d >= 0);
  if (data != nullptr) CHECK(H5Dwrite(d, mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0);
  H5Dclose(d);
  H5Pclose(dcpl);
  H5Sclose(space);
}

static std::string h5_xdmf(const std::string& stem, const std::string& geometry_dims,
                           const std::string& topology_dims) {
  return xdmf3("<Topology TopologyType=\"Tetrahedron\"><DataItem Dimensions=\"" + topology_dims +
               "\" DataType=\"Int\" Format=\"HDF\">" + stem +
               ".h5:/t</DataItem></Topology>\n"
               "<Geometry GeometryType=\"XYZ\"><DataItem Dimensions=\"" +
               geometry_dims + "\" Format=\"HDF\">" + stem + ".h5:/g</DataItem></Geometry>\n");
}

static void test_hdf5_files() {
  const double g[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  const float gf[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  const std::int32_t t32[8] = {0, 1, 2, 3, 1, 2, 3, 4};
  const std::uint64_t tu64[8] = {0, 1, 2, 3, 1, 2, 3, 4};
  const std::int16_t t16[8] = {0, 1, 2, 3, 1, 2, 3, 4};
  const std::int32_t bad[4] = {0, 1, 2, 7};
  const auto make = [&](const std::string& stem, const auto& fill) {
    const hid_t f =
        H5Fcreate((tmp / (stem + ".h5")).string().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    CHECK(f >= 0);
    fill(f);
    H5Fclose(f);
  };
  // float32 points, int32 and uint64 indices: read
  make("f32", [&](hid_t f) {
    h5_dataset(f, "/g", {5, 3}, H5T_IEEE_F32LE, H5T_NATIVE_FLOAT, gf);
    h5_dataset(f, "/t", {2, 4}, H5T_STD_U64BE, H5T_NATIVE_UINT64, tu64);
  });
  {
    Mesh m;
    IO::read_xdmf(put("f32.xdmf", h5_xdmf("f32", "5 3", "2 4")), m);
    CHECK(m.points.size() == 5 && m.tetrahedra.size() == 2 && m.points[4].z() == 1.0);
    CHECK(m.float32_points); // a float32 dataset
  }
  make("ok32", [&](hid_t f) {
    h5_dataset(f, "/g", {15}, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, g);
    h5_dataset(f, "/t", {2, 4}, H5T_STD_I32LE, H5T_NATIVE_INT32, t32);
  });
  {
    Mesh m;
    IO::read_xdmf(put("ok32.xdmf", h5_xdmf("ok32", "5 3", "8")), m);
    CHECK(m.points.size() == 5 && m.tetrahedra.size() == 2);
    CHECK(!m.float32_points); // a float64 dataset
    // without the first '/' of the dataset path, as some writers put it
    std::string text = h5_xdmf("ok32", "5 3", "8");
    text.replace(text.find("ok32.h5:/g"), 10, "ok32.h5:g");
    Mesh m2;
    IO::read_xdmf(put("noslash.xdmf", text), m2);
    CHECK(m2.points == m.points);
  }
  const auto error = [&](const std::string& stem, const std::string& gd, const std::string& td,
                         const std::string& what) {
    prstar_test::Failure_context c(stem);
    Mesh m;
    CHECK_THROWS(IO::Read_error, what, IO::read_xdmf(put(stem + ".xdmf", h5_xdmf(stem, gd, td)), m));
  };
  // the shape announced by Dimensions differs from the dataset's
  make("shape", [&](hid_t f) {
    h5_dataset(f, "/g", {5, 3}, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, g);
    h5_dataset(f, "/t", {2, 4}, H5T_STD_I32LE, H5T_NATIVE_INT32, t32);
  });
  error("shape", "6 3", "2 4",
        "shape.h5:/g has dimensions 5 x 3 (15 values), Dimensions=\"6 3\" announces 18");
  error("shape", "5 3", "3 4", "has dimensions 2 x 4 (8 values)");
  // points of 2 coordinates
  make("two", [&](hid_t f) {
    h5_dataset(f, "/g", {5, 2}, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, g);
    h5_dataset(f, "/t", {2, 4}, H5T_STD_I32LE, H5T_NATIVE_INT32, t32);
  });
  {
    Mesh m;
    CHECK_THROWS(IO::Read_error, "the geometry has 10 values, not a multiple of 3",
                 IO::read_xdmf(put("two.xdmf", xdmf3("<Topology TopologyType=\"Tetrahedron\"><DataItem "
                                                     "DataType=\"Int\" Format=\"HDF\">two.h5:/t</DataItem></"
                                                     "Topology><Geometry><DataItem Format=\"HDF\">two.h5:/g</"
                                                     "DataItem></Geometry>")),
                               m));
  }
  // an int16 topology, float topology
  make("types", [&](hid_t f) {
    h5_dataset(f, "/g", {5, 3}, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, g);
    h5_dataset(f, "/t", {2, 4}, H5T_STD_I16LE, H5T_NATIVE_INT16, t16);
    h5_dataset(f, "/tf", {2, 4}, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, g);
  });
  error("types", "5 3", "2 4", "integers of 2 bytes (int32, int64, uint32 or uint64 only)");
  {
    Mesh m;
    std::string text = h5_xdmf("types", "5 3", "2 4");
    text.replace(text.find("types.h5:/t<"), 12, "types.h5:/tf<");
    CHECK_THROWS(IO::Read_error, "the topology has floating-point values",
                 IO::read_xdmf(put("tf.xdmf", text), m));
  }
  // an index out of range in the .h5
  make("range", [&](hid_t f) {
    h5_dataset(f, "/g", {5, 3}, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, g);
    h5_dataset(f, "/t", {1, 4}, H5T_STD_I32LE, H5T_NATIVE_INT32, bad);
  });
  error("range", "5 3", "1 4", "cell 0: vertex index 7 out of range");
  // a missing dataset, a group instead of a dataset, a text file named .h5
  make("nodata", [&](hid_t f) {
    h5_dataset(f, "/g", {5, 3}, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, g);
    H5Gclose(H5Gcreate2(f, "/t", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  });
  error("nodata", "5 3", "2 4", "nodata.h5:/t: '/t' is not a dataset");
  {
    Mesh m;
    std::string text = h5_xdmf("nodata", "5 3", "2 4");
    text.replace(text.find("nodata.h5:/t<"), 13, "nodata.h5:/x/y<");
    CHECK_THROWS(IO::Read_error, "no dataset '/x/y' in the HDF5 file",
                 IO::read_xdmf(put("nods.xdmf", text), m));
  }
  put("text.h5", "not an HDF5 file\n");
  error("text", "5 3", "2 4", "is not an HDF5 file");
  // a huge dataset announced (chunks never written: a tiny file): refused by the memory check
  make("huge", [&](hid_t f) {
    h5_dataset(f, "/g", {1000000000ull, 3}, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, nullptr);
    h5_dataset(f, "/t", {1000000000ull, 4}, H5T_STD_I64LE, H5T_NATIVE_INT64, nullptr);
  });
  CHECK(fs::file_size(tmp / "huge.h5") < 100000);
  {
    IO::Memory_limit limit(std::size_t(1) << 32);
    Mesh m;
    CHECK_THROWS(IO::Memory_limit_error, "(1000000000 vertices, 1000000000 tetrahedra)",
                 IO::read_xdmf(put("huge.xdmf", h5_xdmf("huge", "1000000000 3", "1000000000 4")), m));
  }
}
#endif

int main(int argc, char** argv) {
  if (argc >= 3 && std::string(argv[1]) == "--dump") {
    try {
      Mesh m;
      IO::read_tetrahedral_mesh(argv[2], m);
      dump(m, std::cout);
      return 0;
    } catch (const std::exception& e) {
      std::cerr << e.what() << "\n";
      return 1;
    }
  }
  if (argc >= 4 && std::string(argv[1]) == "--convert") {
    try {
      Mesh m;
      IO::read_tetrahedral_mesh(argv[2], m);
      if (argc >= 5)
        IO::write_tetrahedral_mesh(argv[3], m,
                                   CGAL::parameters::use_binary_mode(std::string(argv[4]) == "hdf"));
      else
        IO::write_tetrahedral_mesh(argv[3], m);
      return 0;
    } catch (const std::exception& e) {
      std::cerr << e.what() << "\n";
      return 1;
    }
  }
  tmp = argc >= 2 ? fs::path(argv[1]) : fs::temp_directory_path() / "prstar_test_io_xdmf";
  fs::remove_all(tmp);
  fs::create_directories(tmp);
  tmp = fs::absolute(tmp);
  std::cout << "test_io_xdmf: HDF5 " << (IO::xdmf_has_hdf5() ? "yes" : "no") << "\n";
  test_round_trips();
  test_float32_round_trips();
  test_hand_written();
  test_malformed();
#ifdef CGAL_PR_STAR_OCTREE_USE_HDF5
  test_hdf5_files();
#else
  prstar_test::skip("HDF5 files of the wrong shape or type (no HDF5 in this build)");
#endif
  return prstar_test::summary("test_io_xdmf");
}
