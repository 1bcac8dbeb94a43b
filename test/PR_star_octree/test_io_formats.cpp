// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project
//
// The format table (CGAL/PR_star_octree/IO/formats.h):
// - the README's "### Mesh formats" table has exactly the rows the table gives (the test fails on
//   any difference and prints the rows expected; `--markdown` prints them to paste);
// - the table itself: unique names, keys and extensions; the dispatch by extension finds each
//   format, in any case; every folder of fuzz_regressions/ is the key of a format;
// - every format through its record: a round trip with the default options, `compression(none)`
//   accepted everywhere, and every option a format cannot honour refused with a Write_error that
//   says so; the options that are honoured change the bytes written as documented.
//
// Usage: test_io_formats README.md     the tests
//        test_io_formats --markdown    the rows of the README table

#include <CGAL/PR_star_octree/IO.h>

#include "test_harness.h"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#ifndef PRSTAR_FUZZ_REGRESSIONS
#define PRSTAR_FUZZ_REGRESSIONS "fuzz_regressions"
#endif

namespace IO = CGAL::PR_star_octree::IO;
namespace NP = CGAL::PR_star_octree::parameters;
using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;
namespace fs = std::filesystem;

// ------------------------------------------------------------------------------------------------
// The README table
// ------------------------------------------------------------------------------------------------

static std::vector<std::string> markdown_rows() {
  std::vector<std::string> rows = {
      "| format | extension | read | write | labels | point data | cell data | encodings | write options |",
      "|---|---|---|---|---|---|---|---|---|"};
  for (const auto& f : IO::mesh_formats<Mesh>) {
    std::string ext;
    for (const char* e : f.extensions)
      if (e != nullptr) ext += (ext.empty() ? "`." : ", `.") + std::string(e) + "`";
    rows.push_back(std::string("| ") + f.name + " | " + ext + " | " + f.read + " | " + f.write + " | " +
                   f.labels + " | " + f.point_data + " | " + f.cell_data + " | " + f.encodings + " | " +
                   IO::write_options_text(*f.write_options) + " |");
  }
  return rows;
}

// The lines of the first table after the heading "### Mesh formats".
static std::vector<std::string> readme_rows(const std::string& readme) {
  std::ifstream in(readme);
  CHECK_MSG(in.good(), "cannot open " << readme);
  std::vector<std::string> rows;
  std::string line;
  bool in_section = false;
  while (std::getline(in, line)) {
    if (!in_section) {
      in_section = line == "### Mesh formats";
      continue;
    }
    if (line.rfind("#", 0) == 0) break; // the next heading
    if (line.rfind("|", 0) == 0)
      rows.push_back(line);
    else if (!rows.empty())
      break; // the end of the table
  }
  CHECK_MSG(in_section, readme << ": no '### Mesh formats' section");
  return rows;
}

static void test_readme(const std::string& readme) {
  const std::vector<std::string> expected = markdown_rows(), actual = readme_rows(readme);
  bool same = expected.size() == actual.size();
  for (std::size_t i = 0; i < std::min(expected.size(), actual.size()); ++i)
    if (expected[i] != actual[i]) {
      same = false;
      std::cerr << "README row " << i + 1 << ":\n  README:  " << actual[i] << "\n  table:   " << expected[i]
                << "\n";
    }
  CHECK_MSG(same, readme << ": the '### Mesh formats' table differs from IO/formats.h (" << actual.size()
                         << " rows for " << expected.size()
                         << "); run 'test_io_formats --markdown' for the rows to paste");
}

// ------------------------------------------------------------------------------------------------
// The table
// ------------------------------------------------------------------------------------------------

static std::string upper(std::string s) {
  for (char& c : s) c = char(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
  return s;
}

static void test_table() {
  std::set<std::string> names, keys, extensions;
  for (const auto& f : IO::mesh_formats<Mesh>) {
    CHECK_MSG(names.insert(f.name).second, "two formats are named " << f.name);
    CHECK_MSG(keys.insert(f.key).second, "two formats have the key " << f.key);
    CHECK(f.extensions[0] != nullptr);
    CHECK(f.read_file != nullptr && f.read_stream != nullptr && f.write_file != nullptr && f.write_options);
    for (const char* e : f.extensions) {
      if (e == nullptr) continue;
      CHECK_MSG(extensions.insert(e).second, "two formats have the extension ." << e);
      CHECK(IO::find_mesh_format<Mesh>(std::string("dir.x/a.") + e) == &f);
      CHECK(IO::find_mesh_format<Mesh>("A." + upper(e)) == &f);
      CHECK(IO::is_readable_extension(std::string(".") + e) &&
            IO::is_writable_extension(std::string("x.") + e));
      CHECK(IO::readable_extensions().find(std::string(".") + e) != std::string::npos);
    }
  }
  CHECK(IO::find_mesh_format<Mesh>("x.ply") == nullptr && IO::find_mesh_format<Mesh>("vtu") == nullptr &&
        IO::find_mesh_format<Mesh>("dir.vtu/file") == nullptr);
  CHECK_EQUAL(IO::mesh_format_extensions(),
              std::string(".vtu, .vtk, .node/.ele, .mesh, .meshb, .msh, .off/.ts, .xdmf/.xmf"));
  CHECK_EQUAL(IO::mesh_format_extensions(true), std::string(".vtu, .vtk, .node/.ele, .msh, .xdmf/.xmf"));
  // the fuzz regression inputs are kept per format key (replayed by test_fuzz_regressions)
  const fs::path root = PRSTAR_FUZZ_REGRESSIONS;
  if (fs::is_directory(root)) {
    for (const auto& e : fs::directory_iterator(root))
      if (e.is_directory())
        CHECK_MSG(keys.count(e.path().filename().string()) == 1,
                  e.path() << " is not the key of a format of IO/formats.h");
  } else {
    prstar_test::skip("no fuzz_regressions folder");
  }
}

// ------------------------------------------------------------------------------------------------
// Write options, through the records
// ------------------------------------------------------------------------------------------------

static fs::path tmp;

static Mesh small_mesh() {
  Mesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  m.tetrahedra = {{0, 1, 2, 3}, {1, 2, 3, 4}};
  m.tetrahedron_labels = {3, 7};
  m.point_data.push_back({"phi", {0.5, 1, 2, 3, 4}});
  return m;
}

static std::string file_text(const std::string& f) {
  std::ifstream in(f, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

static void test_write_options() {
  const Mesh m = small_mesh();
  for (const auto& f : IO::mesh_formats<Mesh>) {
    prstar_test::Failure_context context(f.name);
    const std::string file = (tmp / (std::string("w.") + f.extensions[0])).string();
    const auto& s = *f.write_options;
    // the defaults, and compression(none) accepted everywhere: the mesh comes back
    for (int none = 0; none < 2; ++none) {
      if (none)
        IO::write_tetrahedral_mesh(file, m, NP::compression(IO::Compression::none));
      else
        IO::write_tetrahedral_mesh(file, m);
      Mesh r;
      f.read_file(file, r);
      CHECK(r.points == m.points);
      CHECK(r.tetrahedra == m.tetrahedra);
      if (std::string(f.labels) != "–") CHECK(r.tetrahedron_labels == m.tetrahedron_labels);
      if (f.point_data_kept != IO::Point_data_kept::none) {
        CHECK_EQUAL(r.point_data.size(), std::size_t(1));
        if (!r.point_data.empty()) CHECK(r.point_data[0].values == m.point_data[0].values);
      }
    }
    // binary or text: what is possible works, the rest is refused
    for (const bool binary : {false, true}) {
      const bool possible = binary ? s.binary : s.ascii;
      if (possible && binary && std::string(f.key) == "xdmf" && !IO::xdmf_has_hdf5()) {
        CHECK_THROWS(IO::Write_error, "no HDF5 support",
                     IO::write_tetrahedral_mesh(file, m, CGAL::parameters::use_binary_mode(binary)));
      } else if (possible) {
        IO::write_tetrahedral_mesh(file, m, CGAL::parameters::use_binary_mode(binary));
        Mesh r;
        f.read_file(file, r);
        CHECK(r.tetrahedra == m.tetrahedra);
      } else {
        CHECK_THROWS(IO::Write_error, "is not possible",
                     IO::write_tetrahedral_mesh(file, m, CGAL::parameters::use_binary_mode(binary)));
      }
    }
    // compression: zlib only where the record says so, and only in binary
    if (!s.zlib) {
      CHECK_THROWS(IO::Write_error, "only compression(none) is possible",
                   IO::write_tetrahedral_mesh(file, m, NP::compression(IO::Compression::zlib)));
    } else {
      CHECK_THROWS(
          IO::Write_error, "compression needs use_binary_mode(true)",
          IO::write_tetrahedral_mesh(file, m, NP::compression(IO::Compression::zlib).use_binary_mode(false)));
    }
    // versions: each one listed is written, an unknown one is refused with the list
    for (const char* v : s.versions) {
      if (v == nullptr) break;
      const double version = std::stod(v);
      IO::write_tetrahedral_mesh(file, m, NP::format_version(version));
      Mesh r;
      f.read_file(file, r);
      CHECK(r.tetrahedra == m.tetrahedra);
    }
    CHECK_THROWS(IO::Write_error, s.versions[0] ? s.versions[0] : "no version",
                 IO::write_tetrahedral_mesh(file, m, NP::format_version(9.9)));
    fs::remove(file);
    if (std::string(f.key) == "tetgen") fs::remove(tmp / "w.ele");
  }

  // the options honoured change the bytes as documented
  const std::string msh = (tmp / "o.msh").string();
  IO::write_tetrahedral_mesh(msh, m, NP::format_version(2.2).use_binary_mode(true));
  CHECK(file_text(msh).rfind("$MeshFormat\n2.2 1 8\n", 0) == 0);
  IO::write_tetrahedral_mesh(msh, m);
  CHECK(file_text(msh).rfind("$MeshFormat\n4.1 0 8\n", 0) == 0);
  const std::string meshb = (tmp / "o.meshb").string();
  for (int version = 1; version <= 4; ++version) {
    IO::write_tetrahedral_mesh(meshb, m, NP::format_version(version));
    const std::string d = file_text(meshb);
    std::int32_t head[2] = {0, 0};
    if (d.size() >= 8) std::memcpy(head, d.data(), 8);
    CHECK_EQUAL(head[1], version);
  }
  const std::string vtk = (tmp / "o.vtk").string();
  IO::write_tetrahedral_mesh(vtk, m, CGAL::parameters::use_binary_mode(true));
  CHECK(file_text(vtk).find("\nBINARY\n") != std::string::npos);
  IO::write_tetrahedral_mesh(vtk, m);
  CHECK(file_text(vtk).find("\nASCII\n") != std::string::npos);
  const std::string vtu = (tmp / "o.vtu").string();
  IO::write_tetrahedral_mesh(vtu, m, CGAL::parameters::use_binary_mode(false));
  CHECK(file_text(vtu).find("format=\"binary\"") == std::string::npos &&
        file_text(vtu).find("format=\"ascii\"") != std::string::npos);
  IO::write_tetrahedral_mesh(vtu, m, NP::compression(IO::Compression::none));
  CHECK(file_text(vtu).find("compressor=") == std::string::npos &&
        file_text(vtu).find("format=\"binary\"") != std::string::npos &&
        file_text(vtu).find("<AppendedData") == std::string::npos);
  if (IO::internal::compression_available(IO::Compression::zlib)) {
    IO::write_tetrahedral_mesh(vtu, m);
    CHECK(file_text(vtu).find("compressor=\"vtkZLibDataCompressor\"") != std::string::npos);
  } else {
    CHECK_THROWS(IO::Write_error, "zlib was not found",
                 IO::write_tetrahedral_mesh(vtu, m, NP::compression(IO::Compression::zlib)));
  }
  // the per-format functions take the same options as the dispatcher
  std::ostringstream gmsh_stream;
  IO::write_gmsh(gmsh_stream, m, NP::format_version(2.2));
  CHECK(gmsh_stream.str().rfind("$MeshFormat\n2.2 0 8\n", 0) == 0);
  CHECK_THROWS(IO::Write_error, "is not possible",
               IO::write_medit(msh, m, CGAL::parameters::use_binary_mode(true)));
  CHECK_THROWS(IO::Write_error, "1, 2, 3, 4", IO::write_meshb(meshb, m, NP::format_version(5)));
  CHECK_THROWS(IO::Write_error, "cannot be written (4.1, 2.2)",
               IO::write_gmsh(msh, m, NP::format_version(3)));
}

// ------------------------------------------------------------------------------------------------
// Float32 points (issue 24), through every record: the formats that have 32-bit coordinates write
// them for a mesh with `float32_points` set and read them back with the flag; the others write the
// same values as decimal doubles, read without the flag; a mesh of doubles stays one everywhere
// ------------------------------------------------------------------------------------------------

static void test_float32_points() {
  Mesh m32 = small_mesh();
  m32.points[1] = Mesh::Point_3(IO::internal::rounded_to_float(0.1), IO::internal::rounded_to_float(1.0 / 3),
                                IO::internal::rounded_to_float(-2.2));
  m32.float32_points = true;
  const std::set<std::string> typed = {"vtu", "vtk", "meshb", "xdmf"}; // the formats of 32-bit coordinates
  for (const auto& f : IO::mesh_formats<Mesh>) {
    for (const bool float32 : {true, false}) {
      for (const bool binary : {false, true}) {
        const auto& s = *f.write_options;
        if (!(binary ? s.binary : s.ascii)) continue;
        if (binary && std::string(f.key) == "xdmf" && !IO::xdmf_has_hdf5()) continue;
        prstar_test::Failure_context context(std::string(f.name) + (float32 ? ", float32" : ", doubles") +
                                             (binary ? ", binary" : ", text"));
        Mesh m = m32;
        m.float32_points = float32;
        const std::string file = (tmp / (std::string("f32.") + f.extensions[0])).string();
        IO::write_tetrahedral_mesh(file, m, CGAL::parameters::use_binary_mode(binary));
        Mesh r;
        f.read_file(file, r);
        CHECK(r.points == m.points); // exact either way
        CHECK(r.tetrahedra == m.tetrahedra);
        CHECK_EQUAL(r.float32_points, float32 && typed.count(f.key) == 1);
        fs::remove(file);
        if (std::string(f.key) == "tetgen") fs::remove(tmp / "f32.ele");
        if (std::string(f.key) == "xdmf") fs::remove(tmp / "f32.h5");
      }
    }
  }
  // .meshb: version 1 by default for a mesh of floats, 2 for one of doubles; an explicit version wins
  const std::string meshb = (tmp / "f32.meshb").string();
  const auto version_written = [&] {
    const std::string d = file_text(meshb);
    std::int32_t head[2] = {0, 0};
    if (d.size() >= 8) std::memcpy(head, d.data(), 8);
    return head[1];
  };
  IO::write_meshb(meshb, m32);
  CHECK_EQUAL(version_written(), 1);
  for (int version = 1; version <= 4; ++version) {
    IO::write_meshb(meshb, m32, NP::format_version(version));
    CHECK_EQUAL(version_written(), version);
    Mesh r;
    IO::read_meshb(meshb, r);
    CHECK(r.points == m32.points);
    CHECK_EQUAL(r.float32_points, version == 1);
  }
  Mesh m64 = m32;
  m64.float32_points = false;
  IO::write_meshb(meshb, m64);
  CHECK_EQUAL(version_written(), 2);
  // text formats with a type: the shortest decimal text of each float
  const std::string vtk = (tmp / "f32.vtk").string();
  IO::write_vtk(vtk, m32);
  CHECK(file_text(vtk).find("POINTS 5 float\n0 0 0\n0.1 0.33333334 -2.2\n") != std::string::npos);
  const std::string xdmf = (tmp / "f32.xdmf").string();
  IO::write_xdmf(xdmf, m32, CGAL::parameters::use_binary_mode(false));
  CHECK(file_text(xdmf).find("DataType=\"Float\" Precision=\"4\" Dimensions=\"5 3\" Format=\"XML\">\n"
                             "          0 0 0\n          0.1 0.33333334 -2.2\n") != std::string::npos);
}

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--markdown") {
    for (const std::string& row : markdown_rows()) std::cout << row << "\n";
    return 0;
  }
  if (argc != 2) {
    std::cerr << "usage: test_io_formats README.md | --markdown\n";
    return 2;
  }
  tmp = fs::temp_directory_path() / ("prstar_test_io_formats_" + std::to_string(::getpid()));
  fs::create_directories(tmp);
  test_readme(argv[1]);
  test_table();
  test_write_options();
  test_float32_points();
  fs::remove_all(tmp);
  return prstar_test::summary("test_io_formats");
}
