// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project
//
// The gmsh .msh (2.2, 4.1; ASCII, binary), Medit .meshb (versions 1-4) and TetGen .node/.ele
// readers and writers: round trips of every variant written, small hand-written files (non
// contiguous tags, several entity blocks, mixed elements, physical names, parametric nodes,
// second-order tetrahedra, the other byte order), malformed files (every truncation, wrong
// counts, lying headers, bad endianness integer, unknown versions) with bounded memory.  (The
// inputs kept from fuzzing, fuzz_regressions/msh and /meshb, are replayed by test_fuzz_regressions.)
//
// Usage: test_io_gmsh [generated_data_dir] [shared_data_dir]     the tests
//        test_io_gmsh --dump FILE          one JSON line: what the reader of FILE's extension read
//                                          (counts, labels, names, skipped cells, points, data
//                                          arrays)
//        test_io_gmsh --convert IN OUT [--msh22] [--binary] [--meshb-version V] [--interleave]
//                     [--add-data]         reads IN, writes OUT (by extension) with the options;
//                                          --interleave reorders the tetrahedra 0, n-1, 1, ...,
//                                          --add-data replaces the data arrays by 2 point-data
//                                          arrays (px, "p index") and 2 cell-data arrays (cq, ct)
//        test_io_gmsh --bench CUBES DIR    speed: a CUBES^3 x 6 tetrahedra grid written as binary
//                                          and ASCII 4.1 .msh in DIR, read back (MB/s)

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>

#include "test_harness.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <cstdint>
#include <cstdlib>
#include <ctime>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

namespace IO = CGAL::PR_star_octree::IO;
namespace P = CGAL::PR_star_octree::parameters;
using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;

// A gmsh variant written: the version and binary (true) or ASCII.
struct Gmsh_variant {
  double version;
  bool binary;
};

template <class Out>
static void write_gmsh_variant(Out&& out, const Mesh& m, const Gmsh_variant& v) {
  IO::write_gmsh(out, m, P::format_version(v.version).use_binary_mode(v.binary));
}
using Point = Mesh::Point_3;
namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// helpers
// ---------------------------------------------------------------------------------------------

static std::string tmp_dir() {
  const fs::path d = fs::temp_directory_path() / ("prstar_test_io_gmsh_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d.string();
}

static void write_file(const std::string& path, const std::string& data) {
  std::ofstream out(path, std::ios::binary);
  out.write(data.data(), static_cast<std::streamsize>(data.size()));
}

static std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// Peak resident memory of the process (kB), from /proc (0 when unavailable).
static long peak_rss_kb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::atol(line.c_str() + 6);
  return 0;
}

/// Binary writer for hand-made files, in either byte order.
struct Bytes {
  std::string s;
  bool swap = false;
  template <class T>
  Bytes& put(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (swap) std::reverse(b, b + sizeof(T));
    s.append(b, sizeof(T));
    return *this;
  }
  Bytes& i32(std::int32_t v) { return put(v); }
  Bytes& u64(std::uint64_t v) { return put(v); }
  Bytes& i64(std::int64_t v) { return put(v); }
  Bytes& f64(double v) { return put(v); }
  Bytes& f32(float v) { return put(v); }
  Bytes& text(const std::string& t) {
    s += t;
    return *this;
  }
};

static std::map<int, std::size_t> histogram(const Mesh& m) {
  std::map<int, std::size_t> h;
  for (int l : m.tetrahedron_labels) ++h[l];
  return h;
}

/// Reads `data` given as the content of a file with extension `ext` (through the file reader).
static Mesh read_as(const std::string& data, const std::string& ext) {
  static int counter = 0;
  const std::string path = tmp_dir() + "/in" + std::to_string(counter++) + ext;
  write_file(path, data);
  Mesh m;
  IO::read_tetrahedral_mesh(path, m);
  fs::remove(path);
  return m;
}

/// `data` must be refused with a Read_error naming the input and containing `text`.
static void expect_refused(const std::string& data, const std::string& ext, const std::string& text,
                           const std::string& what) {
  const std::string name = "case_" + what + ext;
  std::istringstream in(data);
  Mesh m;
  try {
    if (ext == ".msh")
      IO::read_gmsh(in, m, name);
    else
      IO::read_meshb(in, m, name);
    FAIL(what << ": accepted (" << m.points.size() << " vertices, " << m.tetrahedra.size() << " tetrahedra)");
  } catch (const IO::Read_error& e) {
    prstar_test::record_check();
    const std::string msg = e.what();
    CHECK_MSG(msg.rfind(name + ":", 0) == 0, what << ": message does not start with the name: " << msg);
    CHECK_MSG(msg.find(text) != std::string::npos, what << ": expected '" << text << "' in: " << msg);
  } catch (const std::exception& e) {
    FAIL(what << ": unexpected exception " << e.what());
  }
}

// a grid of n^3 cubes, each split into 6 tetrahedra around its main diagonal; label = 1 + (x < n/2)
static Mesh grid(int n, bool labels = true) {
  Mesh m;
  const auto id = [n](int i, int j, int k) { return std::uint32_t((k * (n + 1) + j) * (n + 1) + i); };
  m.points.reserve(std::size_t(n + 1) * (n + 1) * (n + 1));
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) m.points.push_back(Point(i * 0.5, j * 0.25 - 1, k + 0.125));
  static const int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  m.tetrahedra.reserve(std::size_t(6) * n * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& p : paths) {
          int c[3] = {i, j, k};
          Mesh::Tetrahedron t;
          t[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[p[s]];
            t[s + 1] = id(c[0], c[1], c[2]);
          }
          m.tetrahedra.push_back(t);
          if (labels) m.tetrahedron_labels.push_back(i < n / 2 ? 1 : 2);
        }
  return m;
}

// ---------------------------------------------------------------------------------------------
// modes for the interoperability script and the speed measurement
// ---------------------------------------------------------------------------------------------

static std::string json_string(const std::string& s) {
  std::string r = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') r += '\\';
    if (static_cast<unsigned char>(c) < 32) continue;
    r += c;
  }
  return r + "\"";
}

static int dump(const std::string& file) {
  Mesh m;
  try {
    IO::read_tetrahedral_mesh(file, m);
  } catch (const IO::Read_error& e) {
    std::cerr << e.what() << std::endl;
    return 1;
  }
  std::cout << "{\"vertices\": " << m.points.size() << ", \"tetrahedra\": " << m.tetrahedra.size()
            << ", \"labels\": {";
  bool first = true;
  for (const auto& h : histogram(m)) {
    std::cout << (first ? "" : ", ") << "\"" << h.first << "\": " << h.second;
    first = false;
  }
  std::cout << "}, \"label_names\": {";
  first = true;
  for (const auto& n : m.label_names) {
    std::cout << (first ? "" : ", ") << "\"" << n.first << "\": " << json_string(n.second);
    first = false;
  }
  std::cout << "}, \"skipped_cells\": {";
  first = true;
  for (const auto& s : m.skipped_cells) {
    std::cout << (first ? "" : ", ") << json_string(s.first) << ": " << s.second;
    first = false;
  }
  std::cout << "}, \"tetrahedron_labels\": [";
  for (std::size_t t = 0; t < m.tetrahedron_labels.size(); ++t)
    std::cout << (t ? ", " : "") << m.tetrahedron_labels[t];
  std::cout << "]" << std::setprecision(17);
  const auto arrays = [](const char* key, const std::vector<CGAL::PR_star_octree::Data_array>& data) {
    std::cout << ", \"" << key << "\": {";
    for (std::size_t k = 0; k < data.size(); ++k) {
      std::cout << (k ? ", " : "") << json_string(data[k].name) << ": [";
      for (std::size_t i = 0; i < data[k].values.size(); ++i)
        std::cout << (i ? ", " : "") << data[k].values[i];
      std::cout << "]";
    }
    std::cout << "}";
  };
  std::cout << ", \"points\": [";
  for (std::size_t i = 0; i < m.points.size(); ++i)
    std::cout << (i ? ", [" : "[") << m.points[i].x() << ", " << m.points[i].y() << ", " << m.points[i].z()
              << "]";
  std::cout << "]";
  arrays("point_data", m.point_data);
  arrays("cell_data", m.cell_data);
  double sum = 0;
  for (const auto& p : m.points) sum += p.x() + 2 * p.y() + 3 * p.z();
  std::cout << ", \"coordinate_checksum\": " << sum << "}" << std::endl;
  return 0;
}

/// Reorders the tetrahedra (and their labels) as 0, n - 1, 1, n - 2, ...: a mesh whose labels
/// come in two runs gets them interleaved.
static void interleave_ends(Mesh& m) {
  const std::size_t n = m.tetrahedra.size();
  Mesh r = m;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t from = k % 2 == 0 ? k / 2 : n - 1 - k / 2;
    r.tetrahedra[k] = m.tetrahedra[from];
    if (!m.tetrahedron_labels.empty()) r.tetrahedron_labels[k] = m.tetrahedron_labels[from];
  }
  m = std::move(r);
}

/// Two point-data arrays and two cell-data arrays whose values need all their 17 digits.
static void add_test_data(Mesh& m) {
  m.point_data.clear();
  m.cell_data.clear();
  CGAL::PR_star_octree::Data_array px{"px", {}}, pi{"p index", {}}, cq{"cq", {}}, ct{"ct", {}};
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    px.values.push_back(m.points[i].x() / 3 + double(i) / 7);
    pi.values.push_back(-(double(i) + 0.1) * 1.0000000000000002e-300);
  }
  for (std::size_t t = 0; t < m.tetrahedra.size(); ++t) {
    cq.values.push_back(double(t) / 3 - 0.1);
    ct.values.push_back(double(t) + 1);
  }
  m.point_data = {px, pi};
  m.cell_data = {cq, ct};
}

static int convert(int argc, char** argv) {
  const std::string in = argv[2], out = argv[3];
  Gmsh_variant options{4.1, false};
  int meshb_version = 0;
  bool add_data = false, interleave = false;
  for (int i = 4; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--msh22") options.version = 2.2;
    if (a == "--binary") options.binary = true;
    if (a == "--meshb-version" && i + 1 < argc) meshb_version = std::atoi(argv[++i]);
    if (a == "--add-data") add_data = true;
    if (a == "--interleave") interleave = true;
  }
  Mesh m;
  try {
    IO::read_tetrahedral_mesh(in, m);
    if (interleave) interleave_ends(m);
    if (add_data) add_test_data(m);
    if (IO::internal::lower_extension(out) == "msh")
      write_gmsh_variant(out, m, options);
    else if (IO::internal::lower_extension(out) == "meshb" && meshb_version != 0)
      IO::write_meshb(out, m, P::format_version(meshb_version));
    else
      IO::write_tetrahedral_mesh(out, m);
  } catch (const std::exception& e) {
    std::cerr << e.what() << std::endl;
    return 1;
  }
  return 0;
}

static int bench(int cubes, const std::string& dir) {
  Mesh m = grid(cubes);
  std::cout << "grid: " << m.points.size() << " vertices, " << m.tetrahedra.size() << " tetrahedra"
            << std::endl;
  struct Variant {
    const char* name;
    Gmsh_variant options;
  };
  const Variant variants[] = {
      {"msh41 binary", {4.1, true}}, {"msh22 binary", {2.2, true}}, {"msh41 ascii", {4.1, false}}};
  for (const Variant& v : variants) {
    const std::string file = dir + "/bench.msh";
    write_gmsh_variant(file, m, v.options);
    const double mb = double(fs::file_size(file)) / 1e6;
    double best = 1e30, best_cpu = 1e30;
    for (int rep = 0; rep < 3; ++rep) {
      Mesh r;
      const auto t0 = std::chrono::steady_clock::now();
      const std::clock_t c0 = std::clock();
      IO::read_gmsh(file, r);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      best = std::min(best, s);
      best_cpu = std::min(best_cpu, double(std::clock() - c0) / CLOCKS_PER_SEC);
      if (r.tetrahedra.size() != m.tetrahedra.size() || r.points.size() != m.points.size()) {
        std::cerr << "bench: wrong counts read back" << std::endl;
        return 1;
      }
    }
    std::cout << v.name << ": " << mb << " MB read in " << best << " s wall (best of 3) = " << mb / best
              << " MB/s; " << best_cpu << " s of CPU = " << mb / best_cpu << " MB/s" << std::endl;
    fs::remove(file);
  }
  return 0;
}

// ---------------------------------------------------------------------------------------------
// tests
// ---------------------------------------------------------------------------------------------

static void check_same(const Mesh& a, const Mesh& b, const std::string& what, bool exact_points = true) {
  prstar_test::Failure_context ctx(what);
  CHECK_EQUAL(b.points.size(), a.points.size());
  CHECK_EQUAL(b.tetrahedra.size(), a.tetrahedra.size());
  if (b.points.size() == a.points.size())
    for (std::size_t i = 0; i < a.points.size(); ++i) {
      if (exact_points) {
        if (!(a.points[i] == b.points[i])) {
          FAIL("point " << i << " differs: " << a.points[i] << " / " << b.points[i]);
          break;
        }
      } else if (CGAL::squared_distance(a.points[i], b.points[i]) > 1e-10) {
        FAIL("point " << i << " differs: " << a.points[i] << " / " << b.points[i]);
        break;
      }
    }
  if (b.tetrahedra.size() == a.tetrahedra.size()) CHECK(a.tetrahedra == b.tetrahedra);
  CHECK(a.tetrahedron_labels == b.tetrahedron_labels);
}

static Mesh labelled_mesh() {
  Mesh m = grid(3);
  // labels 7, 3, 7, 0, 12 in runs (not sorted, a 0, interleaved)
  for (std::size_t t = 0; t < m.tetrahedra.size(); ++t)
    m.tetrahedron_labels[t] = (t % 5 == 0) ? 3 : (t % 7 == 0) ? 12 : 7;
  m.tetrahedron_labels[4] = 0;
  m.points[5] = Point(0.1, 1e-300, -3.3333333333333335);
  m.label_names = {{3, "inner part"}, {7, "outer"}};
  return m;
}

static void test_round_trips() {
  const std::string dir = tmp_dir();
  const Mesh m = labelled_mesh();
  struct V {
    const char* name;
    Gmsh_variant o;
  };
  for (const V& v : {V{"41 ascii", {4.1, false}}, V{"41 binary", {4.1, true}}, V{"22 ascii", {2.2, false}},
                     V{"22 binary", {2.2, true}}}) {
    const std::string f = dir + "/rt.msh";
    write_gmsh_variant(f, m, v.o);
    Mesh r;
    IO::read_tetrahedral_mesh(f, r);
    check_same(m, r, std::string("gmsh ") + v.name);
    CHECK(r.label_names == m.label_names);
    CHECK(r.skipped_cells.empty());
    // a mesh without labels stays without labels
    Mesh nl = grid(2, false);
    write_gmsh_variant(f, nl, v.o);
    IO::read_gmsh(f, r);
    check_same(nl, r, std::string("gmsh without labels ") + v.name);
    // an empty mesh
    Mesh empty;
    write_gmsh_variant(f, empty, v.o);
    IO::read_gmsh(f, r);
    CHECK_EQUAL(r.points.size(), 0u);
    CHECK_EQUAL(r.tetrahedra.size(), 0u);
    // the stream forms agree with the file forms
    std::ostringstream out;
    write_gmsh_variant(out, m, v.o);
    CHECK(out.str() == (write_gmsh_variant(f, m, v.o), read_file(f)));
    std::istringstream in(out.str());
    IO::read_gmsh(in, r, "stream");
    check_same(m, r, std::string("gmsh stream ") + v.name);
  }
  // the default of write_tetrahedral_mesh: 4.1 ASCII
  IO::write_tetrahedral_mesh(dir + "/d.msh", m);
  CHECK(read_file(dir + "/d.msh").rfind("$MeshFormat\n4.1 0 8\n", 0) == 0);

  for (int version = 0; version <= 4; ++version) {
    const std::string f = dir + "/rt.meshb";
    if (version == 0)
      IO::write_meshb(f, m);
    else
      IO::write_meshb(f, m, P::format_version(version));
    Mesh r;
    IO::read_tetrahedral_mesh(f, r);
    check_same(m, r, "meshb version " + std::to_string(version), version != 1);
    CHECK_EQUAL(r.float32_points, version == 1);
    const std::string data = read_file(f);
    std::int32_t head[2];
    std::memcpy(head, data.data(), 8);
    CHECK_EQUAL(head[0], 1);
    CHECK_EQUAL(head[1], version == 0 ? 2 : version);
  }
  {
    // a mesh of floats: version 1 by default, read back with the flag and the same floats; as
    // doubles when a version of 64-bit reals is asked
    Mesh m32 = m;
    for (auto& p : m32.points)
      p = Point(IO::internal::rounded_to_float(p.x()), IO::internal::rounded_to_float(p.y()),
                IO::internal::rounded_to_float(p.z()));
    m32.float32_points = true;
    for (int version : {0, 2}) {
      const std::string f = dir + "/f32.meshb";
      if (version == 0)
        IO::write_tetrahedral_mesh(f, m32);
      else
        IO::write_meshb(f, m32, P::format_version(version));
      Mesh r;
      IO::read_meshb(f, r);
      check_same(m32, r, "float32 meshb version " + std::to_string(version));
      CHECK_EQUAL(r.float32_points, version == 0);
      CHECK_EQUAL(read_file(f).substr(4, 1), std::string(1, char(version == 0 ? 1 : 2)));
    }
  }
  {
    // without labels a .meshb gets reference 1 for every tetrahedron (documented)
    Mesh nl = grid(1, false), r;
    IO::write_meshb(dir + "/nl.meshb", nl);
    IO::read_meshb(dir + "/nl.meshb", r);
    CHECK_EQUAL(r.tetrahedron_labels.size(), nl.tetrahedra.size());
    CHECK(
        std::all_of(r.tetrahedron_labels.begin(), r.tetrahedron_labels.end(), [](int l) { return l == 1; }));
  }
  for (const char* ext : {".node", ".ele"}) {
    Mesh tm = m;
    tm.point_data.push_back({"temperature", std::vector<double>(tm.points.size())});
    for (std::size_t i = 0; i < tm.points.size(); ++i) tm.point_data[0].values[i] = 0.5 * double(i) - 3;
    IO::write_tetrahedral_mesh(dir + "/tg" + ext, tm);
    Mesh r;
    IO::read_tetrahedral_mesh(dir + "/tg.node", r);
    check_same(tm, r, std::string("tetgen via ") + ext);
    CHECK_EQUAL(r.point_data.size(), 1u);
    if (r.point_data.size() == 1) CHECK(r.point_data[0].values == tm.point_data[0].values);
    CHECK(read_file(dir + "/tg.ele").rfind(std::to_string(tm.tetrahedra.size()) + " 4 1\n1 ", 0) == 0);
  }
  {
    Mesh nl = grid(1, false), r;
    IO::write_tetgen(dir + "/nl.ele", nl);
    IO::read_tetgen(dir + "/nl.node", r);
    check_same(nl, r, "tetgen without labels");
    CHECK_THROWS(IO::Write_error, "'.node' or '.ele'", IO::write_tetgen(dir + "/x.tet", nl));
  }
  {
    // the Medit ASCII writer keeps the labels
    Mesh r;
    IO::write_tetrahedral_mesh(dir + "/m.mesh", m);
    IO::read_tetrahedral_mesh(dir + "/m.mesh", r);
    check_same(m, r, "medit ascii");
  }
  CHECK(IO::is_readable_extension("a.MSH") && IO::is_readable_extension("a.meshb"));
  CHECK(IO::is_writable_extension("a.msh") && IO::is_writable_extension("a.meshb") &&
        IO::is_writable_extension("a.node") && IO::is_writable_extension("a.ele"));
}

// ---- hand-written files

static const char* msh22_ascii =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
    "$PhysicalNames\n3\n2 5 \"skin\"\n3 10 \"left block\"\n3 20 \"right\"\n$EndPhysicalNames\n"
    "$Comments\nanything $Nodes here\n$EndComments\n"
    "$Nodes\n6\n"
    "10 0 0 0\n20 1 0 0\n35 0 1 0\n7 0 0 1\n100 1 1 1\n3 0.5 0.5 0.5\n"
    "$EndNodes\n$Elements\n7\n"
    "1 15 2 0 1 10\n"
    "2 1 2 0 3 10 20\n"
    "3 2 2 5 4 10 20 35\n"
    "4 4 2 10 1 10 20 35 7\n"
    "9 4 3 20 2 6 20 35 7 100\n"
    "5 4 0 20 35 7 3\n"
    "6 11 2 10 1 10 20 35 100 3 3 3 3 3 3\n"
    "$EndElements\n"
    "$NodeData\n1\n\"t\"\n1\n0\n3\n0\n1\n1\n10 1.5\n$EndNodeData\n";

static const char* msh41_ascii = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
                                 "$PhysicalNames\n2\n3 4 \"a\"\n3 9 \"b b\"\n$EndPhysicalNames\n"
                                 "$Entities\n1 0 1 3\n"
                                 "1 0 0 0 0\n"
                                 "2 0 0 0 1 1 0 1 77 0\n"
                                 "11 0 0 0 1 1 1 2 9 4 1 2\n"
                                 "12 0 0 0 1 1 1 1 4 0\n"
                                 "13 0 0 0 1 1 1 0 0\n"
                                 "$EndEntities\n"
                                 "$Nodes\n3 6 5 40\n"
                                 "0 1 0 1\n5\n0 0 0\n"
                                 "2 2 1 2\n40\n6\n1 0 0 0.5 0.5\n0 1 0 0.25 0.25\n"
                                 "3 11 0 3\n30\n31\n32\n0 0 1\n1 1 1\n0.5 0.5 0.5\n"
                                 "$EndNodes\n"
                                 "$Elements\n5 8 1 108\n"
                                 "0 1 15 1\n100 5\n"
                                 "2 2 2 2\n101 5 40 6\n102 40 6 30\n"
                                 "3 11 4 2\n103 5 40 6 30\n108 40 6 30 31\n"
                                 "3 12 4 1\n104 5 6 30 32\n"
                                 "3 13 4 2\n105 6 30 31 32\n106 5 40 31 32\n"
                                 "$EndElements\n";

static void test_hand_written() {
  {
    prstar_test::Failure_context ctx("msh 2.2 ascii");
    const Mesh m = read_as(msh22_ascii, ".msh");
    CHECK_EQUAL(m.points.size(), 6u);
    CHECK_EQUAL(m.tetrahedra.size(), 4u);
    // node tags 10 20 35 7 100 3 -> indices 0 1 2 3 4 5; the tetrahedra in the order of their
    // element tags 4 5 6 9 (the file lists 4 9 5 6)
    if (m.tetrahedra.size() == 4) {
      CHECK((m.tetrahedra[0] == Mesh::Tetrahedron{0, 1, 2, 3}));
      CHECK((m.tetrahedra[1] == Mesh::Tetrahedron{1, 2, 3, 5}));
      CHECK((m.tetrahedra[2] == Mesh::Tetrahedron{0, 1, 2, 4}));
      CHECK((m.tetrahedra[3] == Mesh::Tetrahedron{1, 2, 3, 4}));
    }
    CHECK((m.tetrahedron_labels == std::vector<int>{10, 0, 10, 20}));
    CHECK(m.point_data.empty()); // the view "t" has a value for one node only: dropped
    CHECK((m.label_names == std::map<int, std::string>{{10, "left block"}, {20, "right"}}));
    CHECK(
        (m.skipped_cells == std::map<std::string, std::size_t>{{"point", 1}, {"line", 1}, {"triangle", 1}}));
    CHECK(m.points[4] == Point(1, 1, 1));
  }
  {
    prstar_test::Failure_context ctx("msh 4.1 ascii");
    const Mesh m = read_as(msh41_ascii, ".msh");
    CHECK_EQUAL(m.points.size(), 6u);
    CHECK_EQUAL(m.tetrahedra.size(), 5u);
    // node tags 5 40 6 30 31 32 -> 0..5; the tetrahedra in the order of their element tags 103
    // 104 105 106 108 (the blocks list 103 108, 104, 105 106)
    if (m.tetrahedra.size() == 5) {
      CHECK((m.tetrahedra[0] == Mesh::Tetrahedron{0, 1, 2, 3}));
      CHECK((m.tetrahedra[1] == Mesh::Tetrahedron{0, 2, 3, 5}));
      CHECK((m.tetrahedra[2] == Mesh::Tetrahedron{2, 3, 4, 5}));
      CHECK((m.tetrahedra[3] == Mesh::Tetrahedron{0, 1, 4, 5}));
      CHECK((m.tetrahedra[4] == Mesh::Tetrahedron{1, 2, 3, 4}));
    }
    CHECK((m.tetrahedron_labels == std::vector<int>{9, 4, 0, 0, 9}));
    CHECK((m.label_names == std::map<int, std::string>{{4, "a"}, {9, "b b"}}));
    CHECK((m.skipped_cells == std::map<std::string, std::size_t>{{"point", 1}, {"triangle", 2}}));
    CHECK(m.points[2] == Point(0, 1, 0));
  }
  {
    // no physical tag at all: no labels
    const std::string s =
        "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n"
        "0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 4\n$EndElements\n";
    const Mesh m = read_as(s, ".msh");
    CHECK_EQUAL(m.tetrahedra.size(), 1u);
    CHECK(m.tetrahedron_labels.empty());
  }
  {
    // partitioned 4.1: the element blocks name partitioned entities (physical tags in
    // $PartitionedEntities; entity 5 has the tag of $Entities' volume 1, which must not be used)
    const std::string s =
        "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 0 2\n1 0 0 0 1 1 1 1 7 0\n"
        "5 0 0 0 1 1 1 1 99 0\n$EndEntities\n$PartitionedEntities\n2\n1\n5 2\n0 0 0 2\n"
        "5 3 1 1 1 0 0 0 1 1 1 1 7 0\n6 3 1 2 1 2 0 0 0 1 1 1 0 0\n$EndPartitionedEntities\n"
        "$Nodes\n1 5 1 5\n3 5 0 5\n1\n2\n3\n4\n5\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n$EndNodes\n"
        "$Elements\n2 2 1 2\n3 6 4 1\n1 1 2 3 4\n3 5 4 1\n2 2 3 4 5\n$EndElements\n";
    const Mesh m = read_as(s, ".msh");
    CHECK((m.tetrahedron_labels == std::vector<int>{0, 7}));
  }
  // binary 4.1 in both byte orders, with a sparse tag space (sorted map) and a parametric block
  for (bool swap : {false, true}) {
    prstar_test::Failure_context ctx(std::string("msh 4.1 binary, swapped ") + (swap ? "yes" : "no"));
    Bytes b;
    b.swap = swap;
    b.text("$MeshFormat\n4.1 1 8\n").i32(1).text("\n$EndMeshFormat\n$Entities\n");
    b.u64(0).u64(0).u64(0).u64(2);
    b.i32(1).f64(0).f64(0).f64(0).f64(1).f64(1).f64(1).u64(2).i32(42).i32(43).u64(0);
    b.i32(2).f64(0).f64(0).f64(0).f64(1).f64(1).f64(1).u64(0).u64(1).i32(-3);
    b.text("\n$EndEntities\n$Nodes\n");
    b.u64(2).u64(5).u64(7).u64(9000000000ull);
    b.i32(3).i32(1).i32(0).u64(3).u64(9000000000ull).u64(7).u64(100);
    b.f64(0).f64(0).f64(0).f64(1).f64(0).f64(0).f64(0).f64(1).f64(0);
    b.i32(2).i32(5).i32(1).u64(2).u64(8).u64(50);
    b.f64(0).f64(0).f64(1).f64(0.1).f64(0.2).f64(1).f64(1).f64(1).f64(0.3).f64(0.4);
    b.text("\n$EndNodes\n$Elements\n");
    b.u64(3).u64(4).u64(1).u64(4);
    b.i32(3)
        .i32(1)
        .i32(4)
        .u64(2)
        .u64(1)
        .u64(9000000000ull)
        .u64(7)
        .u64(100)
        .u64(8)
        .u64(2)
        .u64(7)
        .u64(100)
        .u64(8)
        .u64(50);
    b.i32(2).i32(5).i32(2).u64(1).u64(3).u64(8).u64(50).u64(7);
    b.i32(3).i32(2).i32(4).u64(1).u64(4).u64(50).u64(9000000000ull).u64(100).u64(8);
    b.text("\n$EndElements\n");
    const Mesh m = read_as(b.s, ".msh");
    CHECK_EQUAL(m.points.size(), 5u);
    CHECK_EQUAL(m.tetrahedra.size(), 3u);
    if (m.tetrahedra.size() == 3) {
      CHECK((m.tetrahedra[0] == Mesh::Tetrahedron{0, 1, 2, 3}));
      CHECK((m.tetrahedra[1] == Mesh::Tetrahedron{1, 2, 3, 4}));
      CHECK((m.tetrahedra[2] == Mesh::Tetrahedron{4, 0, 2, 3}));
    }
    CHECK((m.tetrahedron_labels == std::vector<int>{42, 42, 0}));
    CHECK((m.skipped_cells == std::map<std::string, std::size_t>{{"triangle", 1}}));
    if (m.points.size() == 5) CHECK(m.points[4] == Point(1, 1, 1));
  }
  // binary 2.2 in both byte orders, element headers of several types
  for (bool swap : {false, true}) {
    prstar_test::Failure_context ctx(std::string("msh 2.2 binary, swapped ") + (swap ? "yes" : "no"));
    Bytes b;
    b.swap = swap;
    b.text("$MeshFormat\n2.2 1 8\n").i32(1).text("\n$EndMeshFormat\n$Nodes\n5\n");
    const int tags[5] = {3, 1, 4, 15, 9};
    const double xyz[5][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    for (int i = 0; i < 5; ++i) b.i32(tags[i]).f64(xyz[i][0]).f64(xyz[i][1]).f64(xyz[i][2]);
    b.text("\n$EndNodes\n$Elements\n5\n");
    b.i32(2).i32(1).i32(2).i32(1).i32(6).i32(1).i32(3).i32(1).i32(4);
    b.i32(4)
        .i32(2)
        .i32(2)
        .i32(2)
        .i32(8)
        .i32(1)
        .i32(3)
        .i32(1)
        .i32(4)
        .i32(15)
        .i32(3)
        .i32(0)
        .i32(2)
        .i32(1)
        .i32(4)
        .i32(15)
        .i32(9);
    b.i32(15).i32(2).i32(1).i32(4).i32(0).i32(3).i32(5).i32(0).i32(9);
    b.text("\n$EndElements\n");
    const Mesh m = read_as(b.s, ".msh");
    CHECK_EQUAL(m.points.size(), 5u);
    CHECK_EQUAL(m.tetrahedra.size(), 2u);
    CHECK((m.tetrahedron_labels == std::vector<int>{8, 0}));
    CHECK((m.skipped_cells == std::map<std::string, std::size_t>{{"point", 2}, {"triangle", 1}}));
    if (m.tetrahedra.size() == 2) CHECK((m.tetrahedra[1] == Mesh::Tetrahedron{1, 2, 3, 4}));
  }
  // .meshb of every version in both byte orders, with a skipped keyword (Triangles) and Tetrahedra
  // before Vertices
  for (int version = 1; version <= 4; ++version)
    for (bool swap : {false, true}) {
      prstar_test::Failure_context ctx("meshb v" + std::to_string(version) + (swap ? " swapped" : ""));
      Bytes b;
      b.swap = swap;
      const auto pos = [&](std::uint64_t p) {
        if (version >= 3)
          b.i64(std::int64_t(p));
        else
          b.i32(std::int32_t(p));
      };
      const auto integer = [&](std::int64_t v) {
        if (version == 4)
          b.i64(v);
        else
          b.i32(std::int32_t(v));
      };
      const std::size_t pb = version >= 3 ? 8 : 4, ib = version == 4 ? 8 : 4, rb = version == 1 ? 4 : 8;
      b.i32(1).i32(version);
      b.i32(3);
      pos(b.s.size() + pb + 4);
      b.i32(3);
      b.i32(6); // Triangles
      pos(b.s.size() + pb + ib + 4 * ib);
      integer(1);
      integer(1), integer(2), integer(3), integer(0);
      b.i32(8);
      pos(b.s.size() + pb + ib + 2 * 5 * ib);
      integer(2);
      integer(1), integer(2), integer(3), integer(4), integer(-6);
      integer(2), integer(3), integer(4), integer(5), integer(11);
      b.i32(4);
      pos(b.s.size() + pb + ib + 5 * (3 * rb + ib));
      integer(5);
      const double xyz[5][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0.5}};
      for (const auto& p : xyz) {
        for (double c : p) {
          if (version == 1)
            b.f32(float(c));
          else
            b.f64(c);
        }
        integer(9);
      }
      b.i32(54);
      pos(0);
      const Mesh m = read_as(b.s, ".meshb");
      CHECK_EQUAL(m.float32_points, version == 1); // 32-bit reals
      CHECK_EQUAL(m.points.size(), 5u);
      CHECK_EQUAL(m.tetrahedra.size(), 2u);
      CHECK((m.tetrahedron_labels == std::vector<int>{-6, 11}));
      if (m.points.size() == 5) CHECK(m.points[4] == Point(1, 1, 0.5));
      if (m.tetrahedra.size() == 2) CHECK((m.tetrahedra[1] == Mesh::Tetrahedron{1, 2, 3, 4}));
    }
}

// ---- element blocks per label, $NodeData and $ElementData

/// `labelled_mesh()` with two point-data and two cell-data arrays whose values need 17 digits.
static Mesh mesh_with_data() {
  Mesh m = labelled_mesh();
  m.point_data.push_back({"temperature", {}});
  m.point_data.push_back({"phi 2", {}});
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    m.point_data[0].values.push_back(0.1 * double(i) - 1.0 / 3);
    m.point_data[1].values.push_back(i % 3 == 0 ? 1e-300 : -3.3333333333333335e+200 * double(i));
  }
  m.cell_data.push_back({"quality", {}});
  m.cell_data.push_back({"rank", {}});
  for (std::size_t t = 0; t < m.tetrahedra.size(); ++t) {
    m.cell_data[0].values.push_back(std::sqrt(double(t) + 0.5));
    m.cell_data[1].values.push_back(double(t % 4));
  }
  return m;
}

static std::size_t occurrences(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

static void check_same_data(const Mesh& a, const Mesh& b, const std::string& what) {
  prstar_test::Failure_context ctx(what);
  CHECK_EQUAL(b.point_data.size(), a.point_data.size());
  CHECK_EQUAL(b.cell_data.size(), a.cell_data.size());
  for (std::size_t k = 0; k < std::min(a.point_data.size(), b.point_data.size()); ++k) {
    CHECK_EQUAL(b.point_data[k].name, a.point_data[k].name);
    CHECK_MSG(b.point_data[k].values == a.point_data[k].values, "point data " << k << " differs");
  }
  for (std::size_t k = 0; k < std::min(a.cell_data.size(), b.cell_data.size()); ++k) {
    CHECK_EQUAL(b.cell_data[k].name, a.cell_data[k].name);
    CHECK_MSG(b.cell_data[k].values == a.cell_data[k].values, "cell data " << k << " differs");
  }
}

static void test_blocks_and_data() {
  const Mesh m = mesh_with_data();
  std::map<int, std::vector<std::size_t>> of_label; // the tetrahedra of each label, in order
  for (std::size_t t = 0; t < m.tetrahedra.size(); ++t) of_label[m.tetrahedron_labels[t]].push_back(t);
  CHECK_EQUAL(of_label.size(), 4u);
  struct V {
    const char* name;
    Gmsh_variant o;
  };
  for (const V& v : {V{"41 ascii", {4.1, false}}, V{"41 binary", {4.1, true}}, V{"22 ascii", {2.2, false}},
                     V{"22 binary", {2.2, true}}}) {
    prstar_test::Failure_context ctx(std::string("data ") + v.name);
    std::ostringstream out;
    write_gmsh_variant(out, m, v.o);
    const std::string s = out.str();
    std::istringstream in(s);
    Mesh r;
    IO::read_gmsh(in, r, "data");
    check_same(m, r, std::string("data ") + v.name); // vertex and tetrahedron order, labels
    check_same_data(m, r, std::string("data ") + v.name);
    CHECK(r.label_names == m.label_names);
    CHECK_EQUAL(occurrences(s, "$NodeData\n"), 2u);
    CHECK_EQUAL(occurrences(s, "$ElementData\n"), 2u);
    CHECK(s.find("\n\"temperature\"\n1\n0\n3\n0\n1\n" + std::to_string(m.points.size()) + "\n") !=
          std::string::npos);
    const std::size_t at = s.find("$Elements\n") + 10;
    if (v.o.version == 4.1 && v.o.binary) {
      std::uint64_t head[4];
      std::memcpy(head, s.data() + at, sizeof(head));
      CHECK_EQUAL(head[0], 4u); // one block per label
      CHECK_EQUAL(head[1], m.tetrahedra.size());
      CHECK_EQUAL(head[2], 1u);
      CHECK_EQUAL(head[3], m.tetrahedra.size());
    } else if (v.o.version == 4.1) {
      // one block per label: its entity's physical tag is the label, its elements are the label's
      // tetrahedra in the order of the mesh, element tag = index + 1
      std::istringstream e(s.substr(at));
      std::size_t blocks, total, min_tag, max_tag;
      e >> blocks >> total >> min_tag >> max_tag;
      CHECK_EQUAL(blocks, 4u);
      CHECK_EQUAL(total, m.tetrahedra.size());
      CHECK(min_tag == 1 && max_tag == m.tetrahedra.size());
      std::map<std::size_t, int> entity_label; // from $Entities (entity tag e + 1 holds label ...)
      for (std::size_t b = 0; b < blocks; ++b) {
        int dim, entity, type;
        std::size_t n;
        e >> dim >> entity >> type >> n;
        CHECK(dim == 3 && type == 4);
        std::vector<std::size_t> tets(n);
        std::size_t node;
        for (std::size_t i = 0; i < n; ++i) {
          e >> tets[i];
          --tets[i];
          for (int k = 0; k < 4; ++k) e >> node;
        }
        const int label = m.tetrahedron_labels[tets.empty() ? 0 : tets[0]];
        CHECK(tets == of_label[label]);
      }
      CHECK(s.find("$Entities\n0 0 0 4\n") != std::string::npos);
    } else if (!v.o.binary) {
      // 2.2: the elements in the order of the mesh, element tag = index + 1
      std::istringstream e(s.substr(at));
      std::size_t n;
      e >> n;
      std::string line;
      std::getline(e, line);
      bool in_order = true;
      for (std::size_t t = 0; t < n && std::getline(e, line); ++t)
        in_order = in_order &&
                   line.rfind(std::to_string(t + 1) + " 4 2 " + std::to_string(m.tetrahedron_labels[t]) + " ",
                              0) == 0;
      CHECK(in_order);
    }
    // the values exactly: in the ASCII files, the shortest text that reads back the same double
    if (!v.o.binary) CHECK(s.find("\n2 -3.3333333333333335e+200\n") != std::string::npos);
  }
  {
    // a mesh without labels: one block; labels already grouped: one block per label
    Mesh nl = grid(2, false), r;
    std::ostringstream out;
    write_gmsh_variant(out, nl, {4.1, false});
    CHECK(out.str().find("$Elements\n1 48 1 48\n3 1 4 48\n") != std::string::npos);
    Mesh g = grid(2);
    std::stable_sort(g.tetrahedron_labels.begin(), g.tetrahedron_labels.end());
    std::ostringstream go;
    write_gmsh_variant(go, g, {4.1, false});
    CHECK(go.str().find("$Elements\n2 48 1 48\n3 1 4 24\n1 ") != std::string::npos);
    std::istringstream gi(go.str());
    IO::read_gmsh(gi, r, "grouped");
    check_same(g, r, "grouped labels");
  }
  {
    // what the writer refuses: a name gmsh cannot quote, arrays of the wrong size, non-finite values
    Mesh bad = mesh_with_data();
    bad.point_data[0].name = "a\"b";
    std::ostringstream out;
    CHECK_THROWS(IO::Write_error, "double quote", IO::write_gmsh(out, bad));
    bad = mesh_with_data();
    bad.cell_data[1].values.pop_back();
    CHECK_THROWS(IO::Write_error, "cell data 'rank' has", IO::write_gmsh(out, bad));
    bad = mesh_with_data();
    bad.point_data[1].values[3] = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS(IO::Write_error, "not finite", IO::write_gmsh(out, bad));
    const std::string f = tmp_dir() + "/refused.msh";
    CHECK_THROWS(IO::Write_error, "not finite", IO::write_gmsh(f, bad));
    CHECK(!fs::exists(f)); // checked before the file is created
  }
  {
    // through the format table: write_tetrahedral_mesh keeps every array
    const std::string f = tmp_dir() + "/table.msh";
    IO::write_tetrahedral_mesh(f, m, P::use_binary_mode(true));
    Mesh r;
    IO::read_tetrahedral_mesh(f, r);
    check_same_data(m, r, "format table");
  }
}

// hand-written data sections: node data in any order and split over sections (the partitions of a
// view), a later time step replacing an earlier one, a 3-component view and an incomplete view
// (skipped), element data on a triangle (ignored) and on tetrahedra listed out of tag order
static const char* msh41_data =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
    "$Nodes\n1 5 1 50\n3 1 0 5\n50\n20\n30\n40\n10\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n$EndNodes\n"
    "$Elements\n3 4 1 9\n"
    "3 1 4 2\n9 50 20 30 40\n2 20 30 40 10\n"
    "2 1 2 1\n5 50 20 30\n"
    "3 2 4 1\n7 50 20 40 10\n$EndElements\n"
    "$NodeData\n1\n\"T\"\n1\n0\n3\n0\n1\n3\n10 5.5\n50 1.5\n30 3.5\n$EndNodeData\n"
    "$NodeData\n2\n\"T\"\n\"scheme\"\n1\n0\n4\n0\n1\n2\n3\n20 2.5\n40 4.5\n$EndNodeData\n"
    "$NodeData\n1\n\"U\"\n1\n0\n3\n0\n1\n5\n10 1\n20 1\n30 1\n40 1\n50 1\n$EndNodeData\n"
    "$NodeData\n1\n\"U\"\n1\n0.5\n3\n1\n1\n5\n10 -1\n20 -2\n30 -3\n40 -4\n50 -0.1\n$EndNodeData\n"
    "$NodeData\n1\n\"V\"\n1\n0\n3\n0\n3\n1\n10 1 2 3\n$EndNodeData\n"
    "$NodeData\n1\n\"partial\"\n1\n0\n3\n0\n1\n1\n10 1\n$EndNodeData\n"
    "$ElementData\n1\n\"E\"\n1\n0\n3\n0\n1\n4\n7 0.7\n5 0.5\n9 0.9\n2 0.2\n$EndElementData\n"
    "$ElementNodeData\n1\n\"skipped\"\n1\n0\n3\n0\n1\n0\n$EndElementNodeData\n";

static void test_hand_written_data() {
  {
    prstar_test::Failure_context ctx("msh 4.1 ascii data");
    const Mesh m = read_as(msh41_data, ".msh");
    CHECK_EQUAL(m.tetrahedra.size(), 3u);
    // tags 2, 7, 9 (the file lists 9, 2, 7)
    if (m.tetrahedra.size() == 3) {
      CHECK((m.tetrahedra[0] == Mesh::Tetrahedron{1, 2, 3, 4}));
      CHECK((m.tetrahedra[1] == Mesh::Tetrahedron{0, 1, 3, 4}));
      CHECK((m.tetrahedra[2] == Mesh::Tetrahedron{0, 1, 2, 3}));
    }
    CHECK_EQUAL(m.point_data.size(), 2u);
    if (m.point_data.size() == 2) {
      CHECK_EQUAL(m.point_data[0].name, std::string("T"));
      CHECK((m.point_data[0].values == std::vector<double>{1.5, 2.5, 3.5, 4.5, 5.5}));
      CHECK_EQUAL(m.point_data[1].name, std::string("U"));
      CHECK((m.point_data[1].values == std::vector<double>{-0.1, -2, -3, -4, -1}));
    }
    CHECK_EQUAL(m.cell_data.size(), 1u);
    if (m.cell_data.size() == 1) {
      CHECK_EQUAL(m.cell_data[0].name, std::string("E"));
      CHECK((m.cell_data[0].values == std::vector<double>{0.2, 0.7, 0.9}));
    }
    CHECK((m.skipped_cells == std::map<std::string, std::size_t>{{"triangle", 1}}));
  }
  {
    // a repeated element tag (2.2, an element of two physical groups): a stable sort, and the element
    // data of that tag for both
    const Mesh m =
        read_as("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n"
                "5 1 1 1\n$EndNodes\n$Elements\n3\n5 4 2 1 1 1 2 3 4\n3 4 2 2 1 2 3 4 5\n"
                "5 4 2 3 1 1 2 3 4\n$EndElements\n$ElementData\n1\n\"e\"\n1\n0\n3\n0\n1\n2\n5 0.5\n3 "
                "0.25\n$EndElementData\n",
                ".msh");
    CHECK((m.tetrahedron_labels == std::vector<int>{2, 1, 3}));
    CHECK(m.cell_data.size() == 1 && m.cell_data[0].values == std::vector<double>({0.25, 0.5, 0.5}));
  }
  // the same in binary 4.1 and 2.2, both byte orders: 4-byte tags and doubles after a text header
  for (bool swap : {false, true})
    for (int version : {41, 22}) {
      prstar_test::Failure_context ctx("binary data " + std::to_string(version) + (swap ? " swapped" : ""));
      Bytes b;
      b.swap = swap;
      const double xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
      if (version == 41) {
        b.text("$MeshFormat\n4.1 1 8\n").i32(1).text("\n$EndMeshFormat\n$Nodes\n");
        b.u64(1).u64(4).u64(1).u64(4).i32(3).i32(1).i32(0).u64(4).u64(4).u64(3).u64(2).u64(1);
        for (const auto& p : xyz) b.f64(p[0]).f64(p[1]).f64(p[2]);
        b.text("\n$EndNodes\n$Elements\n").u64(1).u64(1).u64(6).u64(6).i32(3).i32(1).i32(4).u64(1);
        b.u64(6).u64(1).u64(2).u64(3).u64(4).text("\n$EndElements\n");
      } else {
        b.text("$MeshFormat\n2.2 1 8\n").i32(1).text("\n$EndMeshFormat\n$Nodes\n4\n");
        for (int i = 0; i < 4; ++i) b.i32(4 - i).f64(xyz[i][0]).f64(xyz[i][1]).f64(xyz[i][2]);
        b.text("\n$EndNodes\n$Elements\n1\n").i32(4).i32(1).i32(0).i32(6).i32(1).i32(2).i32(3).i32(4);
        b.text("\n$EndElements\n");
      }
      b.text("$NodeData\n1\n\"w\"\n1\n0.0\n3\n0\n1\n4\n");
      for (int tag : {2, 4, 1, 3}) b.i32(tag).f64(0.25 * tag + 1e-17);
      b.text("\n$EndNodeData\n$ElementData\n1\n\"c\"\n1\n0.0\n3\n0\n1\n1\n").i32(6).f64(-7.125);
      b.text("\n$EndElementData\n$NodeData\n1\n\"vector\"\n1\n0.0\n3\n0\n3\n1\n").i32(1).f64(1).f64(2).f64(3);
      b.text("\n$EndNodeData\n");
      const Mesh m = read_as(b.s, ".msh");
      CHECK_EQUAL(m.point_data.size(), 1u);
      CHECK_EQUAL(m.cell_data.size(), 1u);
      if (m.point_data.size() == 1)
        CHECK((m.point_data[0].values ==
               std::vector<double>{1 + 1e-17, 0.75 + 1e-17, 0.5 + 1e-17, 0.25 + 1e-17}));
      if (m.cell_data.size() == 1) CHECK((m.cell_data[0].values == std::vector<double>{-7.125}));
    }
  // malformed data sections
  const std::string mesh41 = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
                             "$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n"
                             "$Elements\n2 2 1 2\n3 1 4 1\n1 1 2 3 4\n2 1 2 1\n2 1 2 3\n$EndElements\n";
  const auto nd = [](const std::string& body) {
    return "$NodeData\n1\n\"d\"\n1\n0\n" + body + "$EndNodeData\n";
  };
  const auto ed = [](const std::string& body) {
    return "$ElementData\n1\n\"d\"\n1\n0\n" + body + "$EndElementData\n";
  };
  expect_refused(mesh41 + nd("3\n0\n1\n4\n1 1\n2 2\n3 3\n5 5\n"), ".msh",
                 "$NodeData 'd': node tag 5 is not in $Nodes", "data unknown node");
  expect_refused(mesh41 + nd("3\n0\n1\n4\n1 1\n2 2\n3 3\n"), ".msh",
                 "node tag '$EndNodeData' is not an integer", "data short");
  expect_refused(mesh41 + nd("3\n0\n1\n2\n1 1\n2 2\n3 3\n"), ".msh", "expected $EndNodeData", "data long");
  expect_refused(mesh41 + nd("3\n0\n1\n2\n1 1\n2 nan\n"), ".msh",
                 "case_data nan.msh:33: value 'nan' is not finite", "data nan");
  expect_refused(mesh41 + nd("3\n0\n1\n2\n1 1\n2 x\n"), ".msh", "value 'x' is not a number", "data text");
  expect_refused(mesh41 + nd("2\n0\n1\n"), ".msh", "2 integer tags, at least 3 expected", "data int tags");
  expect_refused(mesh41 + nd("3\n0\n0\n1\n1 1\n"), ".msh", "0 components per entry", "data components");
  expect_refused(mesh41 + nd("3\n0\n1\n-1\n"), ".msh", "number of entries -1 is negative", "data negative");
  expect_refused(mesh41 + "$NodeData\n1\n\"d\n1\n0\n3\n0\n1\n0\n$EndNodeData\n", ".msh",
                 "unterminated string tag", "data quote");
  expect_refused(mesh41 + ed("3\n0\n1\n1\n3 1\n"), ".msh",
                 "$ElementData 'd': element tag 3 is not in $Elements", "data unknown element");
  expect_refused(mesh41 + ed("3\n0\n1\n1\n0 1\n"), ".msh", "element tag 0 is not in $Elements",
                 "data element 0");
  CHECK_EQUAL(read_as(mesh41 + ed("3\n0\n1\n2\n2 7\n1 1\n"), ".msh").cell_data.size(), 1u); // 2: a triangle
  expect_refused("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n" + nd("3\n0\n1\n0\n"), ".msh",
                 "$NodeData before $Nodes", "data before nodes");
  expect_refused("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n0 0 0 0\n$EndNodes\n" + ed("3\n0\n1\n0\n"),
                 ".msh", "$ElementData before $Elements", "data before elements");
  {
    Bytes b;
    b.text("$MeshFormat\n2.2 1 8\n").i32(1).text("\n$EndMeshFormat\n$Nodes\n1\n").i32(1).f64(0).f64(0).f64(0);
    b.text("\n$EndNodes\n$Elements\n0\n\n$EndElements\n");
    Bytes lie = b, zero = b, inf = b;
    lie.text("$NodeData\n1\n\"d\"\n1\n0\n3\n0\n1\n1000000000000\n").i32(1).f64(0);
    expect_refused(lie.s, ".msh", "1000000000000 entries announced, but only", "binary data lie");
    zero.text("$NodeData\n1\n\"d\"\n1\n0\n3\n0\n1\n1\n").i32(0).f64(0).text("\n$EndNodeData\n");
    expect_refused(zero.s, ".msh", "node tag 0 (tags start at 1)", "binary data tag 0");
    inf.text("$NodeData\n1\n\"d\"\n1\n0\n3\n0\n1\n1\n").i32(1).f64(std::numeric_limits<double>::infinity());
    inf.text("\n$EndNodeData\n");
    expect_refused(inf.s, ".msh", "node tag 1: the value is not finite", "binary data inf");
  }
  {
    // every truncation of a file with data is refused, but for the cuts right after a section
    std::ostringstream out;
    Mesh g = grid(1);
    g.point_data.push_back({"p", std::vector<double>(g.points.size(), 0.5)});
    g.cell_data.push_back({"c", std::vector<double>(g.tetrahedra.size(), -0.25)});
    for (const Gmsh_variant v :
         {Gmsh_variant{4.1, false}, Gmsh_variant{4.1, true}, Gmsh_variant{2.2, true}}) {
      out.str("");
      write_gmsh_variant(out, g, v);
      const std::string full = out.str();
      int wrong = 0;
      for (std::size_t n = 0; n + 1 < full.size(); ++n) {
        const std::string cut = full.substr(0, n);
        bool at_end_of_section = false;
        for (const char* end : {"$EndElements", "$EndNodeData", "$EndElementData"})
          for (const char* tail : {"", "\n"})
            at_end_of_section =
                at_end_of_section || (cut.size() >= std::strlen(end) + std::strlen(tail) &&
                                      cut.compare(cut.size() - std::strlen(tail) - std::strlen(end),
                                                  std::string::npos, std::string(end) + tail) == 0);
        std::istringstream in(cut);
        Mesh r;
        bool read = false;
        try {
          IO::read_gmsh(in, r, "cut");
          read = true;
        } catch (const IO::Read_error&) {
        } catch (...) {
          ++wrong;
        }
        if (read != at_end_of_section) ++wrong;
      }
      CHECK_MSG(wrong == 0, "version " << v.version << (v.binary ? " binary" : " ascii") << ": " << wrong
                                       << " truncations read when they should not, or the reverse");
    }
  }
}

// ---- malformed files

static void test_malformed() {
  const Mesh m = labelled_mesh();
  // every truncation of every variant is refused (or, cut in the last end marker, still read)
  struct V {
    const char* name;
    Gmsh_variant o;
  };
  for (const V& v : {V{"41 ascii", {4.1, false}}, V{"41 binary", {4.1, true}}, V{"22 ascii", {2.2, false}},
                     V{"22 binary", {2.2, true}}}) {
    std::ostringstream out;
    write_gmsh_variant(out, grid(1), v.o);
    const std::string full = out.str();
    int refused = 0, other = 0;
    for (std::size_t n = 0; n + 14 < full.size(); ++n) { // "$EndElements\n" is 13 bytes
      std::istringstream in(full.substr(0, n));
      Mesh r;
      try {
        IO::read_gmsh(in, r, "cut");
      } catch (const IO::Read_error&) {
        ++refused;
      } catch (...) {
        ++other;
      }
    }
    CHECK_MSG(other == 0, v.name << ": a truncation threw something other than Read_error");
    CHECK_EQUAL(refused, int(full.size() - 14));
  }
  {
    std::ostringstream out;
    IO::write_meshb(out, grid(1), P::format_version(3));
    const std::string full = out.str();
    int refused = 0;
    for (std::size_t n = 0; n + 12 < full.size(); ++n) { // End keyword: 4 + 8 bytes
      std::istringstream in(full.substr(0, n));
      Mesh r;
      try {
        IO::read_meshb(in, r, "cut");
      } catch (const IO::Read_error&) {
        ++refused;
      }
    }
    CHECK_EQUAL(refused, int(full.size() - 12));
  }

  const std::string head41 = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  const std::string nodes41 = "$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n";
  const std::string elems41 = "$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 4\n$EndElements\n";
  CHECK_EQUAL(read_as(head41 + nodes41 + elems41, ".msh").tetrahedra.size(), 1u);
  expect_refused("", ".msh", "empty file", "empty");
  expect_refused("solid x\n", ".msh", "not a gmsh", "not gmsh");
  expect_refused("$MeshFormat\n4.0 0 8\n$EndMeshFormat\n", ".msh", "unsupported .msh format version '4.0'",
                 "v4.0");
  expect_refused("$MeshFormat\n3 0 8\n$EndMeshFormat\n", ".msh", "unsupported", "v3");
  expect_refused("$MeshFormat\n2.2 0 4\n$EndMeshFormat\n", ".msh", "data size 4", "data size");
  expect_refused("$MeshFormat\n4.1 2 8\n$EndMeshFormat\n", ".msh", "file type 2", "file type");
  expect_refused(head41 + nodes41, ".msh", "no $Elements", "no elements");
  expect_refused(head41 + elems41 + nodes41, ".msh", "$Elements before $Nodes", "order");
  expect_refused(head41 + nodes41 + nodes41 + elems41, ".msh", "duplicate $Nodes", "dup nodes");
  expect_refused(head41 + "$Nodes\n1 4 1 4\n3 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n" + elems41,
                 ".msh", "3 nodes in the blocks, 4 announced", "node count");
  expect_refused(head41 + "$Nodes\n1 4 1 4\n3 1 0 5\n", ".msh", "more nodes than the 4 announced",
                 "block too big");
  expect_refused(head41 + "$Nodes\n1 1000000000000 1 4\n3 1 0 4\n1\n2\n", ".msh",
                 "do not fit in the index type", "10^12 nodes");
  expect_refused(head41 + "$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n3\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n" +
                     elems41,
                 ".msh", "node tag 3 defined twice", "dup tag");
  expect_refused(head41 + nodes41 + "$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 5\n$EndElements\n", ".msh",
                 "node tag 5 is not in $Nodes", "unknown node");
  expect_refused(head41 + nodes41 + "$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 3\n$EndElements\n", ".msh",
                 "listing a node twice", "repeated node");
  expect_refused(head41 + nodes41 + "$Elements\n1 2 1 1\n3 1 4 1\n1 1 2 3 4\n$EndElements\n", ".msh",
                 "1 elements in the blocks, 2 announced", "element count");
  expect_refused(head41 + nodes41 + "$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 4 5\n$EndElements\n", ".msh",
                 "expected $EndElements", "extra node");
  expect_refused(head41 + "$Nodes\n1 1 1 1\n3 1 0 1\n1\nnan 0 0\n$EndNodes\n", ".msh", "not finite", "nan");
  expect_refused(head41 + "$Comments\nno end\n", ".msh", "no $EndComments", "unterminated section");
  {
    // a lying count in a small file: refused without allocating for it (peak memory grows < 64 MB)
    const long before = peak_rss_kb();
    expect_refused(head41 + "$Nodes\n1 1000000000 1 1000000000\n3 1 0 1000000000\n1\n", ".msh",
                   "unexpected end", "10^9 nodes ascii");
    Bytes b;
    b.text("$MeshFormat\n4.1 1 8\n")
        .i32(1)
        .text("\n$EndMeshFormat\n$Nodes\n")
        .u64(1)
        .u64(1000000000000ull)
        .u64(1)
        .u64(1000000000000ull);
    expect_refused(b.s, ".msh", "do not fit", "10^12 nodes binary");
    Bytes c;
    c.text("$MeshFormat\n4.1 1 8\n")
        .i32(1)
        .text("\n$EndMeshFormat\n$Nodes\n")
        .u64(1)
        .u64(1000000000)
        .u64(1)
        .u64(1000000000);
    expect_refused(c.s, ".msh", "bytes are left", "10^9 nodes binary");
    Bytes e;
    e.text("$MeshFormat\n4.1 1 8\n")
        .i32(1)
        .text("\n$EndMeshFormat\n$Nodes\n")
        .u64(0)
        .u64(0)
        .u64(0)
        .u64(0)
        .text("\n$EndNodes\n$Elements\n");
    e.u64(1).u64(1000000000000ull).u64(1).u64(1000000000000ull).i32(3).i32(1).i32(4).u64(1000000000000ull);
    expect_refused(e.s, ".msh", "bytes are left", "10^12 elements binary");
    expect_refused("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1000000000\n1 0 0 0\n", ".msh",
                   "unexpected end", "10^9 nodes 2.2");
    Bytes mb;
    mb.i32(1).i32(2).i32(3).i32(20).i32(3).i32(4).i32(0).i32(2000000000);
    expect_refused(mb.s, ".meshb", "2000000000 vertices announced", "meshb 2e9 vertices");
    Bytes mb4;
    mb4.i32(1).i32(4).i32(3).i64(24).i32(3).i32(8).i64(0).i64(1000000000000ll);
    expect_refused(mb4.s, ".meshb", "1000000000000 tetrahedra announced", "meshb 10^12 tetrahedra");
    const long grown = peak_rss_kb() - before;
    CHECK_MSG(grown < 64 * 1024, "lying counts made the peak memory grow by " << grown << " kB");
  }
  {
    Bytes b;
    b.text("$MeshFormat\n4.1 1 8\n").i32(2).text("\n$EndMeshFormat\n");
    expect_refused(b.s, ".msh", "bad endianness integer 2", "bad endianness");
    expect_refused("$MeshFormat\n4.1 1 8\n\x01\x00", ".msh", "unexpected end of file", "short endianness");
    Bytes t;
    t.text("$MeshFormat\n2.2 1 8\n")
        .i32(1)
        .text("\n$EndMeshFormat\n$Nodes\n1\n")
        .i32(1)
        .f64(0)
        .f64(0)
        .f64(0)
        .text("\n$EndNodes\n$Elements\n1\n");
    t.i32(77).i32(1).i32(0).i32(1);
    expect_refused(t.s, ".msh", "unknown element type 77", "unknown type binary");
    // the message of a binary file names the byte offset
    expect_refused(t.s, ".msh", "byte ", "offset in message");
  }
  {
    // the message of a text file names the line
    const std::string s = head41 + "$Nodes\n1 1 1 1\n3 1 0 1\n1\n0 zero 0\n$EndNodes\n";
    expect_refused(s, ".msh", "case_line.msh:8: y coordinate 'zero'", "line");
  }
  // meshb
  expect_refused("", ".meshb", "shorter than its 8-byte header", "meshb empty");
  {
    Bytes b;
    b.i32(7).i32(2);
    expect_refused(b.s, ".meshb", "the first integer is 7", "meshb first int");
    Bytes v;
    v.i32(1).i32(5);
    expect_refused(v.s, ".meshb", "unsupported .meshb version 5", "meshb version");
    Bytes d;
    d.i32(1).i32(2).i32(3).i32(20).i32(2).i32(54).i32(0);
    expect_refused(d.s, ".meshb", "Dimension 2", "meshb dim 2");
    Bytes back;
    back.i32(1).i32(2).i32(3).i32(4).i32(3);
    expect_refused(back.s, ".meshb", "next keyword position 4", "meshb backwards");
    Bytes skip0;
    skip0.i32(1).i32(2).i32(3).i32(20).i32(3).i32(6).i32(0).i32(0);
    expect_refused(skip0.s, ".meshb", "cannot be skipped", "meshb skip 0");
    Bytes range;
    range.i32(1).i32(2).i32(3).i32(20).i32(3);
    range.i32(4).i32(0).i32(1).f64(0).f64(0).f64(0).i32(0);
    range.i32(8).i32(0).i32(1).i32(1).i32(2).i32(3).i32(4).i32(0).i32(54).i32(0);
    expect_refused(range.s, ".meshb", "vertex index 2 out of range", "meshb range");
    Bytes none;
    none.i32(1).i32(2).i32(3).i32(20).i32(3).i32(54).i32(0);
    expect_refused(none.s, ".meshb", "no Vertices", "meshb no vertices");
  }
}

int main(int argc, char** argv) {
  if (argc >= 3 && std::string(argv[1]) == "--dump") return dump(argv[2]);
  if (argc >= 4 && std::string(argv[1]) == "--convert") return convert(argc, argv);
  if (argc >= 4 && std::string(argv[1]) == "--bench") return bench(std::atoi(argv[2]), argv[3]);
  test_round_trips();
  test_hand_written();
  test_blocks_and_data();
  test_hand_written_data();
  test_malformed();
  fs::remove_all(tmp_dir());
  return prstar_test::summary("test_io_gmsh");
}
