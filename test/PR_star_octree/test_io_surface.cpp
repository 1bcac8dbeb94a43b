// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project
//
// The triangle surface writers (IO/surface.h): the boundary of a box made of two labelled
// regions, with their interface, written in every format and mode into DIR (with expected.json,
// what interop_surface.py compares the files read back by VTK and meshio with); byte-level checks
// of the binary STL and PLY, the stream and file forms alike, the extension table, refused options,
// inconsistent surfaces and the system's reason of a failed open or write.
//
// Usage: test_io_surface DIR

#include <CGAL/PR_star_octree/IO/surface.h>

#include "test_harness.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace IO = CGAL::PR_star_octree::IO;
namespace P = CGAL::PR_star_octree::parameters;
using Surface = CGAL::PR_star_octree::Triangle_surface<>;
using Point = Surface::Point_3;

namespace {

// The box [0,1]^3 cut at x = 1/2 into region 1 (left) and region 2 (right), mapped to coordinates
// that have no short decimal form: its 22 boundary triangles oriented outward of the region they
// bound (the interface: outward of region 1), label_inside, label_outside, interface per triangle,
// a real and an integer array per point, the names of the labels.
Surface two_region_box() {
  Surface s;
  const auto map = [](double x, double y, double z) {
    return Point(x * 1.1 + 0.1, y / 3 - 0.2, z * 0.7 + 1e-3 / 7);
  };
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) s.points.push_back(map(i * 0.5, j, k));
  const auto id = [](int i, int j, int k) { return std::uint32_t(4 * i + 2 * j + k); };
  std::vector<int> inside, outside, interface;
  // a quad a b c d (a cycle), split into 2 triangles whose normals point along `out`
  const auto quad = [&](std::array<std::uint32_t, 4> q, std::array<double, 3> out, int in, int ou) {
    const auto d = [&](std::uint32_t a, std::uint32_t b, int c) {
      return CGAL::to_double(s.points[b].cartesian(c)) - CGAL::to_double(s.points[a].cartesian(c));
    };
    const double u[3] = {d(q[0], q[1], 0), d(q[0], q[1], 1), d(q[0], q[1], 2)};
    const double v[3] = {d(q[0], q[2], 0), d(q[0], q[2], 1), d(q[0], q[2], 2)};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    if (n[0] * out[0] + n[1] * out[1] + n[2] * out[2] < 0) std::swap(q[1], q[3]);
    for (const auto& tri : {Surface::Triangle{q[0], q[1], q[2]}, Surface::Triangle{q[0], q[2], q[3]}}) {
      s.triangles.push_back(tri);
      inside.push_back(in);
      outside.push_back(ou);
      interface.push_back(ou != 0 ? 1 : 0);
    }
  };
  quad({id(0, 0, 0), id(0, 1, 0), id(0, 1, 1), id(0, 0, 1)}, {-1, 0, 0}, 1, 0);
  quad({id(2, 0, 0), id(2, 1, 0), id(2, 1, 1), id(2, 0, 1)}, {1, 0, 0}, 2, 0);
  for (int i = 0; i < 2; ++i) {
    const int region = i + 1;
    for (int j = 0; j < 2; ++j) // y = j
      quad({id(i, j, 0), id(i + 1, j, 0), id(i + 1, j, 1), id(i, j, 1)}, {0, j == 0 ? -1.0 : 1.0, 0}, region,
           0);
    for (int k = 0; k < 2; ++k) // z = k
      quad({id(i, 0, k), id(i + 1, 0, k), id(i + 1, 1, k), id(i, 1, k)}, {0, 0, k == 0 ? -1.0 : 1.0}, region,
           0);
  }
  quad({id(1, 0, 0), id(1, 1, 0), id(1, 1, 1), id(1, 0, 1)}, {1, 0, 0}, 1, 2);
  s.cell_int_data = {{"label_inside", inside}, {"label_outside", outside}, {"interface", interface}};
  CGAL::PR_star_octree::Data_array distance{"distance", {}};
  CGAL::PR_star_octree::Int_array type{"boundary_type", {}};
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    distance.values.push_back(i == 3 ? -2.5e-300 : std::sqrt(double(i) + 0.5) / 3);
    type.values.push_back(i / 4 == 1 ? 2 : -1 - int(i % 3));
  }
  s.point_data = {distance};
  s.point_int_data = {type};
  s.label_names = {{0, "outside"}, {1, "left part"}, {2, "right <&> part"}};
  return s;
}

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void append_json_double(std::ostringstream& o, double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof(buf), v);
  o << std::string(buf, r.ptr);
}

// What interop_surface.py compares the files with.
void write_expected(const Surface& s, const std::string& path) {
  std::ostringstream o;
  o << "{\n\"points\": [";
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    o << (i ? ", " : "") << '[';
    for (int c = 0; c < 3; ++c) {
      o << (c ? ", " : "");
      append_json_double(o, CGAL::to_double(s.points[i].cartesian(c)));
    }
    o << ']';
  }
  o << "],\n\"triangles\": [";
  for (std::size_t i = 0; i < s.triangles.size(); ++i)
    o << (i ? ", " : "") << '[' << s.triangles[i][0] << ", " << s.triangles[i][1] << ", " << s.triangles[i][2]
      << ']';
  o << "],\n\"point_data\": {";
  for (std::size_t a = 0; a < s.point_data.size(); ++a) {
    o << (a ? ", " : "") << '"' << s.point_data[a].name << "\": [";
    for (std::size_t i = 0; i < s.point_data[a].values.size(); ++i) {
      o << (i ? ", " : "");
      append_json_double(o, s.point_data[a].values[i]);
    }
    o << ']';
  }
  const auto ints = [&](const std::vector<CGAL::PR_star_octree::Int_array>& arrays) {
    for (std::size_t a = 0; a < arrays.size(); ++a) {
      o << (a ? ", " : "") << '"' << arrays[a].name << "\": [";
      for (std::size_t i = 0; i < arrays[a].values.size(); ++i) o << (i ? ", " : "") << arrays[a].values[i];
      o << ']';
    }
  };
  o << "},\n\"point_int_data\": {";
  ints(s.point_int_data);
  o << "},\n\"cell_int_data\": {";
  ints(s.cell_int_data);
  o << "},\n\"label_names\": {";
  bool first = true;
  for (const auto& l : s.label_names) {
    o << (first ? "" : ", ") << '"' << l.first << "\": \"" << l.second << '"';
    first = false;
  }
  o << "}\n}\n";
  std::ofstream f(path);
  f << o.str();
  CHECK_MSG(bool(f), "cannot write " << path);
}

void test_extensions() {
  CHECK_EQUAL(IO::surface_extensions(), std::string(".off, .stl, .ply, .obj, .vtp, .mesh"));
  for (const char* f : {"a.off", "B.STL", "x/y.z/c.Ply", "d.obj", ".vtp", "e.mesh"})
    CHECK_MSG(IO::is_surface_extension(f), f);
  for (const char* f : {"a.vtu", "ply", "a.meshb", "dir.stl/file", "a.stl.gz", ""})
    CHECK_MSG(!IO::is_surface_extension(f), f);
  const Surface s = two_region_box();
  CHECK_THROWS(std::invalid_argument, ".off, .stl, .ply, .obj, .vtp, .mesh", IO::write_surface("out.vtu", s));
  CHECK_THROWS(std::invalid_argument, "out: unknown", IO::write_surface("out", s));
  CHECK(!std::filesystem::exists("out.vtu"));
}

void test_refused(const std::string& dir) {
  const Surface good = two_region_box();
  const std::string f = dir + "/refused.ply";
  CHECK_THROWS(IO::Write_error, "text only",
               IO::write_surface(dir + "/r.off", good, P::use_binary_mode(true)));
  CHECK_THROWS(IO::Write_error, "text only",
               IO::write_surface(dir + "/r.obj", good, P::use_binary_mode(true)));
  CHECK_THROWS(IO::Write_error, "text only",
               IO::write_surface(dir + "/r.mesh", good, P::use_binary_mode(true)));
  CHECK_THROWS(IO::Write_error, "not compressed",
               IO::write_surface(f, good, P::compression(IO::Compression::zlib)));
  CHECK_THROWS(IO::Write_error, "version", IO::write_surface(dir + "/r.stl", good, P::format_version(2)));
  CHECK_THROWS(IO::Write_error, "version 3", IO::write_surface(dir + "/r.mesh", good, P::format_version(3)));
  Surface s = good;
  s.triangles[3][1] = 12;
  CHECK_THROWS(IO::Write_error, "triangle 3 has vertex index 12 out of range", IO::write_surface(f, s));
  s = good;
  s.points[5] = Point(0, std::numeric_limits<double>::infinity(), 0);
  CHECK_THROWS(IO::Write_error, "vertex 5 has a non-finite coordinate", IO::write_surface(f, s));
  s = good;
  s.point_data[0].values.pop_back();
  CHECK_THROWS(IO::Write_error, "'distance' has 11 values for 12 vertices", IO::write_surface(f, s));
  s = good;
  s.point_data[0].values[2] = std::nan("");
  CHECK_THROWS(IO::Write_error, "not finite", IO::write_surface(f, s));
  s = good;
  s.cell_int_data[1].values.push_back(0);
  CHECK_THROWS(IO::Write_error, "'label_outside' has 23 values for 22 triangles", IO::write_surface(f, s));
  s = good;
  s.point_int_data[0].name = "distance";
  CHECK_THROWS(IO::Write_error, "two point data arrays are named 'distance'", IO::write_surface(f, s));
  s = good;
  s.cell_int_data[2].name = "";
  CHECK_THROWS(IO::Write_error, "empty name", IO::write_surface(f, s));
  s = good;
  s.label_names[3] = "two\nlines";
  CHECK_THROWS(IO::Write_error, "label 3 is not one line", IO::write_surface(f, s));
  s = good;
  s.cell_int_data[0].name = "label inside";
  CHECK_THROWS(IO::Write_error, "PLY property names cannot contain spaces", IO::write_surface(f, s));
  try { // VTK names may have spaces
    IO::write_surface(dir + "/spaces.vtp", s);
    CHECK(true);
  } catch (const std::exception& e) {
    FAIL("spaces in a .vtp array name: " << e.what());
  }
  s = good;
  s.point_data[0].name = "x";
  CHECK_THROWS(IO::Write_error, "'x' is a PLY property", IO::write_surface(f, s));
  CHECK(!std::filesystem::exists(f));
}

// The system's reason in the message of a failed open and of a failed write.
void test_os_errors(const std::string& dir) {
  const Surface s = two_region_box();
  CHECK_THROWS(IO::Write_error,
               "no_such_folder/a.stl: cannot open the file for writing: No such file or directory",
               IO::write_surface(dir + "/no_such_folder/a.stl", s));
  std::filesystem::create_directories(dir + "/folder.ply");
  CHECK_THROWS(IO::Write_error, "is a directory", IO::write_surface(dir + "/folder.ply", s));
  if (!std::filesystem::exists("/dev/full")) {
    prstar_test::skip("/dev/full: no device to test a full disk");
    return;
  }
  const std::string full = dir + "/full.vtp";
  std::error_code ec;
  std::filesystem::remove(full, ec);
  std::filesystem::create_symlink("/dev/full", full, ec);
  if (ec) {
    prstar_test::skip("cannot link /dev/full: " + ec.message());
    return;
  }
  CHECK_THROWS(IO::Write_error, "full.vtp: error while writing: No space left on device",
               IO::write_surface(full, s, P::use_binary_mode(false)));
  std::filesystem::remove(full, ec);
}

// The files of every format and mode, for interop_surface.py; the stream form writes the same bytes.
void test_files(const std::string& dir) {
  const Surface s = two_region_box();
  write_expected(s, dir + "/expected.json");
  struct Variant {
    const char* file;
    int binary; // -1: the default
    bool zlib;
  };
  const Variant variants[] = {{"box.off", -1, false},        {"box_binary.stl", -1, false},
                              {"box_ascii.stl", 0, false},   {"box_binary.ply", -1, false},
                              {"box_ascii.ply", 0, false},   {"box.obj", -1, false},
                              {"box_binary.vtp", -1, false}, {"box_raw.vtp", 1, false},
                              {"box_ascii.vtp", 0, false},   {"box.mesh", -1, false}};
  for (const Variant& v : variants) {
    prstar_test::Failure_context context(v.file);
    const std::string path = dir + "/" + v.file;
    std::ostringstream stream;
    const std::string ext = std::filesystem::path(path).extension().string();
    try {
      if (v.binary < 0) {
        IO::write_surface(path, s);
        IO::write_surface(stream, s, ext);
      } else if (v.binary == 1) {
        IO::write_surface(path, s, P::compression(IO::Compression::none).use_binary_mode(true));
        IO::write_surface(stream, s, ext, P::compression(IO::Compression::none).use_binary_mode(true));
      } else {
        IO::write_surface(path, s, P::use_binary_mode(false));
        IO::write_surface(stream, s, ext.substr(1), P::use_binary_mode(false));
      }
    } catch (const std::exception& e) {
      FAIL("unexpected exception: " << e.what());
      continue;
    }
    const std::string bytes = file_text(path);
    CHECK(!bytes.empty());
    CHECK(bytes == stream.str());
  }
  const std::size_t nt = s.triangles.size(), nv = s.points.size();
  // binary STL: 80 bytes, the count, 50 bytes per triangle, the first normal (-1, 0, 0)
  const std::string stl = file_text(dir + "/box_binary.stl");
  CHECK_EQUAL(stl.size(), 84 + 50 * nt);
  if (stl.size() == 84 + 50 * nt) {
    CHECK(stl.compare(0, 5, "solid") != 0);
    std::uint32_t count;
    std::memcpy(&count, stl.data() + 80, 4);
    CHECK_EQUAL(count, nt);
    float n[3];
    std::memcpy(n, stl.data() + 84, 12);
    CHECK_EQUAL(n[0], -1.0f);
    CHECK_EQUAL(n[1], 0.0f);
    CHECK_EQUAL(n[2], 0.0f);
    float a;
    std::memcpy(&a, stl.data() + 84 + 12, 4);
    CHECK_EQUAL(a, float(CGAL::to_double(s.points[s.triangles[0][0]].x())));
  }
  // binary PLY: the header, then 3 doubles + 1 double + 1 int per vertex, 1 + 3 * 4 + 3 * 4 per face
  const std::string ply = file_text(dir + "/box_binary.ply");
  const std::string header =
      "ply\nformat binary_little_endian 1.0\n"
      "comment written by the PR-star octree package (CGAL)\n"
      "comment label 0 outside\ncomment label 1 left part\ncomment label 2 right <&> part\n"
      "element vertex 12\nproperty double x\nproperty double y\nproperty double z\n"
      "property double distance\nproperty int boundary_type\n"
      "element face 22\nproperty list uchar int vertex_indices\n"
      "property int label_inside\nproperty int label_outside\nproperty int interface\n"
      "end_header\n";
  CHECK(ply.compare(0, header.size(), header) == 0);
  CHECK_EQUAL(ply.size(), header.size() + nv * 36 + nt * 25);
  if (ply.size() == header.size() + nv * 36 + nt * 25) {
    double y;
    std::memcpy(&y, ply.data() + header.size() + 36 * 5 + 8, 8);
    CHECK(y == CGAL::to_double(s.points[5].y()));
  }
  const std::string off = file_text(dir + "/box.off");
  CHECK(off.compare(0, 12, "OFF\n12 22 0\n") == 0);
  const std::string mesh = file_text(dir + "/box.mesh");
  CHECK(mesh.find("\nTriangles\n22\n") != std::string::npos);
  CHECK(mesh.find("\nEnd\n") != std::string::npos);
}

// An empty surface (no point, no triangle) in every format and mode: accepted, and the stream form
// writes what the file form writes.
void test_empty(const std::string& dir) {
  const Surface empty;
  for (const IO::Surface_format& f : IO::surface_formats)
    for (bool binary : {false, true}) {
      if (binary && !f.write_options->binary) continue;
      const std::string path = dir + "/empty" + (binary ? "_binary." : ".") + f.extension;
      prstar_test::Failure_context context(path);
      std::ostringstream stream;
      try {
        IO::write_surface(path, empty, P::use_binary_mode(binary));
        IO::write_surface(stream, empty, f.extension, P::use_binary_mode(binary));
        CHECK(file_text(path) == stream.str());
        CHECK(!stream.str().empty());
      } catch (const std::exception& e) {
        FAIL("unexpected exception: " << e.what());
      }
    }
  CHECK_EQUAL(file_text(dir + "/empty_binary.stl").size(), std::size_t(84));
}

} // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: test_io_surface DIR\n";
    return 2;
  }
  const std::string dir = argv[1];
  std::filesystem::create_directories(dir);
  test_extensions();
  test_refused(dir);
  test_os_errors(dir);
  test_files(dir);
  test_empty(dir);
  return prstar_test::summary("test_io_surface");
}
