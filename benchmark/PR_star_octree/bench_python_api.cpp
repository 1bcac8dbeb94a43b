// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// bench_python_api: the C++ side of the Python module's benchmark (bench_python.py, issue 21).
//
// usage: bench_python_api POINTS.npy TETS.npy [--surface] [--kv N] [--threads N]
//
// Reads a C-order '<f8' (n, 3) points array and a C-order '<i8' (m, 4) tetrahedra array (what
// numpy.save writes for the float64/int64 arrays of the driver), then, timed, does with the C++ API
// exactly what `prstar.Octree(points, tets, bucket_size=kv)` + `prstar.boundary(tree, surface=...)`
// do in python/src/module.cpp: the octree built from the arrays (Index_arrays_input, the module's
// named parameters: both permutations kept, maximum depth 32), `compute_boundary` into one uint8
// code per vertex in the user's order, and with --surface `boundary_surface` into a vector.
// Prints one JSON line: the times, the counts, checksums of the results (compared with the Python
// side's by the driver), the peak RSS (VmHWM) and the RSS after loading the arrays.
//
// The arrays are read straight into their vectors (no intermediate buffer), so that the RSS after
// loading is the arrays, as after numpy.load in the Python process.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/Index_arrays_input.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/parameters.h>

#include <boost/property_map/property_map.hpp>

#include <sys/resource.h>

#include "bench_util.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <array>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace PSO = CGAL::PR_star_octree;
namespace params = CGAL::PR_star_octree::parameters;
using Octree = CGAL::PR_star_octree_3<>;
using prstar_bench::now;
using prstar_bench::status_kib;

// The CPU seconds of the process (all threads, user + system): less sensitive than the wall clock
// to the other processes of a shared machine.
double cpu_seconds() {
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// A point as numpy stores a row of an (n, 3) float64 array; the octree takes any type with x(), y(),
// z() (PR_star_octree_3::convert_point), as the module's Numpy_input reads doubles from the array.
struct Xyz {
  double c[3];
  double x() const { return c[0]; }
  double y() const { return c[1]; }
  double z() const { return c[2]; }
};
static_assert(sizeof(Xyz) == 3 * sizeof(double), "a row of the array");

// The header of a .npy file (format versions 1 to 3): its dtype, order and shape.
struct Npy_header {
  std::string descr;
  bool fortran_order = false;
  std::vector<std::size_t> shape;
};

// The value of `key` in the header's Python dict literal, as text (up to the next ',' at depth 0).
std::string dict_value(const std::string& h, const std::string& key, const std::string& file) {
  const std::size_t k = h.find("'" + key + "'");
  if (k == std::string::npos) throw std::runtime_error(file + ": .npy header without '" + key + "'");
  std::size_t p = h.find(':', k);
  if (p == std::string::npos) throw std::runtime_error(file + ": bad .npy header");
  ++p;
  while (p < h.size() && h[p] == ' ') ++p;
  int depth = 0;
  std::size_t e = p;
  for (; e < h.size(); ++e) {
    if (h[e] == '(') ++depth;
    if (h[e] == ')') --depth;
    if (depth == 0 && (h[e] == ',' || h[e] == '}')) break;
  }
  return h.substr(p, e - p);
}

Npy_header read_header(std::FILE* f, const std::string& file) {
  unsigned char magic[8];
  if (std::fread(magic, 1, 8, f) != 8 || magic[0] != 0x93 || std::string(magic + 1, magic + 6) != "NUMPY")
    throw std::runtime_error(file + ": not a .npy file");
  const int major = magic[6];
  std::size_t len = 0;
  if (major == 1) {
    unsigned char l[2];
    if (std::fread(l, 1, 2, f) != 2) throw std::runtime_error(file + ": truncated .npy header");
    len = l[0] | (std::size_t(l[1]) << 8);
  } else if (major == 2 || major == 3) {
    unsigned char l[4];
    if (std::fread(l, 1, 4, f) != 4) throw std::runtime_error(file + ": truncated .npy header");
    len = l[0] | (std::size_t(l[1]) << 8) | (std::size_t(l[2]) << 16) | (std::size_t(l[3]) << 24);
  } else {
    throw std::runtime_error(file + ": .npy format version " + std::to_string(major) + " not supported");
  }
  std::string h(len, '\0');
  if (std::fread(&h[0], 1, len, f) != len) throw std::runtime_error(file + ": truncated .npy header");
  Npy_header r;
  std::string d = dict_value(h, "descr", file);
  if (d.size() < 2 || (d.front() != '\'' && d.front() != '"'))
    throw std::runtime_error(file + ": descr " + d + " is not a simple dtype (a structured array?)");
  r.descr = d.substr(1, d.size() - 2);
  const std::string fo = dict_value(h, "fortran_order", file);
  if (fo != "False" && fo != "True") throw std::runtime_error(file + ": bad fortran_order " + fo);
  r.fortran_order = fo == "True";
  const std::string s = dict_value(h, "shape", file); // "(n, 3)", "(n,)", "()"
  for (std::size_t i = 0; i < s.size();) {
    if (s[i] >= '0' && s[i] <= '9') {
      std::size_t e = i;
      while (e < s.size() && s[e] >= '0' && s[e] <= '9') ++e;
      r.shape.push_back(std::stoull(s.substr(i, e - i)));
      i = e;
    } else {
      ++i;
    }
  }
  return r;
}

// Reads FILE, which must hold a C-order (rows, columns) array of dtype `descr`, into `out` (rows of
// `Row`, `columns` elements of `Element` each), straight into the vector.
template <class Row>
void read_npy(const std::string& file, const char* descr, std::size_t columns, std::vector<Row>& out) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(file.c_str(), "rb"), &std::fclose);
  if (!f) throw std::runtime_error(file + ": cannot open");
  const Npy_header h = read_header(f.get(), file);
  std::string shape = "(";
  for (std::size_t k = 0; k < h.shape.size(); ++k) shape += (k ? ", " : "") + std::to_string(h.shape[k]);
  shape += h.shape.size() == 1 ? ",)" : ")";
  const std::string expected =
      std::string("a C-order '") + descr + "' array of shape (n, " + std::to_string(columns) + ")";
  if (h.descr != descr || h.fortran_order || h.shape.size() != 2 || h.shape[1] != columns)
    throw std::runtime_error(file + ": dtype '" + h.descr + "', " + (h.fortran_order ? "Fortran" : "C") +
                             " order, shape " + shape + "; expected " + expected);
  out.resize(h.shape[0]);
  const std::size_t bytes = out.size() * sizeof(Row);
  if (bytes && std::fread(out.data(), 1, bytes, f.get()) != bytes)
    throw std::runtime_error(file + ": truncated data (" + shape + " announced)");
  char extra;
  if (std::fread(&extra, 1, 1, f.get()) != 0) throw std::runtime_error(file + ": data past the array");
}

// 0 interior, 1 boundary, 2 non-manifold, 3 in no tetrahedron: the module's codes (module.cpp).
std::uint8_t vertex_code(PSO::Vertex_type t) {
  switch (t) {
  case PSO::Vertex_type::INTERIOR:
    return 0;
  case PSO::Vertex_type::BOUNDARY:
    return 1;
  case PSO::Vertex_type::NONMANIFOLD:
    return 2;
  default:
    return 3;
  }
}

struct Code_map { // user vertex -> code, as the module's
  using key_type = std::size_t;
  using value_type = PSO::Vertex_type;
  using reference = value_type;
  using category = boost::writable_property_map_tag;
  std::uint8_t* codes;
  friend void put(const Code_map& m, std::size_t v, PSO::Vertex_type t) { m.codes[v] = vertex_code(t); }
};

int usage() {
  std::cerr << "usage: bench_python_api POINTS.npy TETS.npy [--surface] [--kv N] [--threads N]\n";
  return 2;
}

} // namespace

int main(int argc, char** argv) {
  std::vector<std::string> files;
  bool surface = false;
  std::size_t kv = 50, threads = 0;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--surface")
        surface = true;
      else if (a == "--kv" && i + 1 < argc)
        kv = std::stoull(argv[++i]);
      else if (a == "--threads" && i + 1 < argc)
        threads = std::stoull(argv[++i]);
      else if (!a.empty() && a[0] == '-')
        return usage();
      else
        files.push_back(a);
    }
  } catch (const std::exception&) {
    return usage();
  }
  if (files.size() != 2 || kv == 0) return usage();

#ifdef CGAL_LINKED_WITH_TBB
  // as the module's Compute_scope: no limit unless asked
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
#endif

  std::vector<Xyz> points;
  std::vector<std::array<std::int64_t, 4>> tets;
  try {
    read_npy(files[0], "<f8", 3, points);
    read_npy(files[1], "<i8", 4, tets);
  } catch (const std::exception& e) {
    std::cerr << "bench_python_api: " << e.what() << '\n';
    return 1;
  }
  const std::size_t input_bytes = points.size() * sizeof(Xyz) + tets.size() * sizeof(tets[0]);
  const std::size_t rss_after_load = status_kib("VmRSS:");

  try {
    // --- timed: what prstar.Octree(...) and prstar.boundary(...) do
    const double c0 = cpu_seconds(), t0 = now();
    const Octree tree(PSO::make_input(points, tets), params::bucket_size(kv)
                                                         .maximum_depth(Octree::default_max_depth)
                                                         .vertex_permutation(true)
                                                         .tetrahedron_permutation(true));
    const double t1 = now(), c1 = cpu_seconds();
    std::vector<std::uint8_t> codes(tree.number_of_vertices(), 3);
    std::vector<PSO::Surface_triangle> triangles;
    const PSO::Boundary_counts b = PSO::compute_boundary(tree, Code_map{codes.data()});
    if (surface) PSO::boundary_surface(tree, std::back_inserter(triangles));
    const double t2 = now(), c2 = cpu_seconds();
    // --- end of the timed part; the peak is read before the checksums
    const std::size_t peak = status_kib("VmHWM:");

    // order-dependent checksums of the results (the driver compares them with the Python side's)
    std::uint64_t code_sum = 0, tri_sum = 0, interfaces = 0;
    for (std::size_t v = 0; v < codes.size(); ++v) code_sum += std::uint64_t(codes[v]) * (v + 1);
    for (std::size_t i = 0; i < triangles.size(); ++i) {
      for (int k = 0; k < 3; ++k) tri_sum += std::uint64_t(triangles[i].vertices[k]) * (3 * i + k + 1);
      interfaces += triangles[i].interface;
    }

    std::cout.precision(9);
    std::cout << "{\"side\": \"cpp\", \"surface\": " << (surface ? "true" : "false") << ", \"kv\": " << kv
              << ", \"threads\": " << threads << ", \"build_s\": " << (t1 - t0)
              << ", \"boundary_s\": " << (t2 - t1) << ", \"total_s\": " << (t2 - t0)
              << ", \"build_cpu_s\": " << (c1 - c0) << ", \"boundary_cpu_s\": " << (c2 - c1)
              << ", \"total_cpu_s\": " << (c2 - c0)
              << ", \"counts\": {\"vertices\": " << tree.number_of_vertices()
              << ", \"tetrahedra\": " << tree.number_of_tetrahedra()
              << ", \"interior_vertices\": " << b.interior_vertices
              << ", \"boundary_vertices\": " << b.boundary_vertices
              << ", \"nonmanifold_vertices\": " << b.nonmanifold_vertices
              << ", \"unreferenced_vertices\": " << b.unreferenced_vertices
              << ", \"boundary_triangles\": " << b.boundary_triangles
              << ", \"boundary_tetrahedra\": " << b.boundary_tetrahedra
              << ", \"boundary_face_tetrahedra\": " << b.boundary_face_tetrahedra;
    if (surface)
      std::cout << ", \"surface_triangles\": " << triangles.size()
                << ", \"interface_triangles\": " << interfaces;
    std::cout << "}, \"code_checksum\": " << code_sum << ", \"triangle_checksum\": " << tri_sum
              << ", \"input_bytes\": " << input_bytes << ", \"rss_after_load_kib\": " << rss_after_load
              << ", \"peak_rss_kib\": " << peak << "}" << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "bench_python_api: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
