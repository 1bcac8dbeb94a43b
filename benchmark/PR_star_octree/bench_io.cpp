// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// bench_io: reading speed of the binary formats on a large lattice (issue 12's target: a
// 100M-tetrahedra zlib VTU and binary .msh read at >= 300 MB/s of decoded data), and with --text
// of the text formats (issue 10's target: >= 100 MB/s of file text).
//
// usage: bench_io --cells N [--reps R] [--keep] [--text] DIR
//   makes a jittered N x N x N Kuhn lattice (6 N^3 tetrahedra, a scalar field, two labels), writes it
//   to DIR as lattice.vtu (appended zlib, ParaView's default) and lattice.msh (gmsh 4.1 binary), then
//   reads each file R times (default 3), each read in a forked child: best wall and CPU seconds, the
//   decoded bytes (the arrays as the writers lay them out: VTU Float64 points, Int64 connectivity
//   and offsets, UInt8 types, Int32 labels, Float64 scalars; .msh 8-byte tags and Float64
//   coordinates per node, 8-byte tag and 4 node tags per tetrahedron), decoded MB per second, and
//   the child's peak RSS.  The files are removed at the end unless --keep.
//   --text: instead, writes the lattice in every text format (Medit .mesh, TetGen .node/.ele,
//   legacy VTK ASCII, gmsh 2.2 and 4.1 ASCII, tet-OFF, ascii VTU) and reads each the same way:
//   best wall and CPU seconds, MB of file text per second, peak RSS.
//   Prints a Markdown table on stdout.

#include <CGAL/PR_star_octree/IO.h>

#include "bench_util.h"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace {

using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;
namespace fs = std::filesystem;

Mesh lattice(std::size_t n) {
  Mesh m;
  const std::size_t side = n + 1;
  m.points.reserve(side * side * side);
  CGAL::PR_star_octree::Data_array scalar{"scalar", {}};
  scalar.values.reserve(side * side * side);
  for (std::size_t z = 0; z < side; ++z)
    for (std::size_t y = 0; y < side; ++y)
      for (std::size_t x = 0; x < side; ++x) {
        const bool inner = x > 0 && x < n && y > 0 && y < n && z > 0 && z < n;
        const double j = inner ? 0.15 * (double((x * 7 + y * 13 + z * 5) % 11) / 10. - 0.5) : 0.;
        const double px = double(x) + j, py = double(y) - j, pz = double(z) + 0.5 * j;
        m.points.emplace_back(px, py, pz);
        scalar.values.push_back(px * px / double(side) + py - pz);
      }
  m.point_data.push_back(std::move(scalar));
  auto id = [side](std::size_t x, std::size_t y, std::size_t z) {
    return static_cast<std::uint32_t>(x + side * (y + side * z));
  };
  const int paths[6][2] = {{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}};
  m.tetrahedra.reserve(6 * n * n * n);
  m.tetrahedron_labels.reserve(6 * n * n * n);
  for (std::size_t z = 0; z < n; ++z)
    for (std::size_t y = 0; y < n; ++y)
      for (std::size_t x = 0; x < n; ++x) {
        std::uint32_t c[8];
        for (int b = 0; b < 8; ++b) c[b] = id(x + (b & 1), y + ((b >> 1) & 1), z + ((b >> 2) & 1));
        for (const auto& p : paths) {
          m.tetrahedra.push_back({{c[0], c[p[0]], c[p[1]], c[7]}});
          m.tetrahedron_labels.push_back(2 * x < n ? 1 : 2);
        }
      }
  return m;
}

struct Read_result {
  bool ok = false;
  std::size_t peak_rss_bytes = 0;
  std::size_t vertices = 0, tetrahedra = 0;
  double wall = 0, cpu = 0;
};

Read_result read_once(const std::string& file) {
  return prstar_bench::in_child<Read_result>([&] {
    Read_result r;
    Mesh m;
    const double t0 = prstar_bench::now();
    const std::clock_t c0 = std::clock();
    CGAL::PR_star_octree::IO::read_tetrahedral_mesh(file, m);
    r.wall = prstar_bench::now() - t0;
    r.cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
    r.vertices = m.points.size();
    r.tetrahedra = m.tetrahedra.size();
    r.ok = true;
    return r;
  });
}

/// The text formats: each written by the library's writer, then read `reps` times.
int text_formats(std::size_t cells, int reps, bool keep, const std::string& dir) {
  namespace IO = CGAL::PR_star_octree::IO;
  struct Text_file {
    std::string name, label;
    std::vector<std::string> parts; // the files read (a TetGen mesh is two)
  };
  const std::vector<Text_file> files = {
      {dir + "/lattice.mesh", "Medit .mesh", {dir + "/lattice.mesh"}},
      {dir + "/lattice.node", "TetGen .node/.ele", {dir + "/lattice.node", dir + "/lattice.ele"}},
      {dir + "/lattice.vtk", "legacy VTK ASCII", {dir + "/lattice.vtk"}},
      {dir + "/lattice22.msh", "gmsh 2.2 ASCII", {dir + "/lattice22.msh"}},
      {dir + "/lattice41.msh", "gmsh 4.1 ASCII", {dir + "/lattice41.msh"}},
      {dir + "/lattice.off", "tet-OFF", {dir + "/lattice.off"}},
      {dir + "/lattice_ascii.vtu", "VTU ascii", {dir + "/lattice_ascii.vtu"}}};
  std::size_t nv = 0, nt = 0;
  {
    const double t0 = prstar_bench::now();
    const Mesh m = lattice(cells);
    nv = m.points.size();
    nt = m.tetrahedra.size();
    std::cerr << "lattice: " << nv << " vertices, " << nt << " tetrahedra (" << prstar_bench::now() - t0
              << " s)\n";
    IO::write_medit(files[0].name, m);
    IO::write_tetgen(files[1].name, m);
    IO::write_vtk(files[2].name, m);
    IO::write_gmsh(files[3].name, m, CGAL::PR_star_octree::parameters::format_version(2.2));
    IO::write_gmsh(files[4].name, m);
    IO::write_tet_off(files[5].name, m);
    IO::write_vtu(files[6].name, m, {}, CGAL::parameters::use_binary_mode(false));
  }
  std::cout << "| file | format | vertices | tetrahedra | file MB | read s (best of " << reps
            << ") | read CPU s | MB/s of file text (wall) | MB/s (CPU) | peak RSS MB |\n"
            << "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Text_file& f : files) {
    double bytes = 0;
    for (const std::string& part : f.parts) bytes += double(fs::file_size(part));
    Read_result best;
    best.wall = best.cpu = 1e300;
    for (int r = 0; r < reps; ++r) {
      const Read_result x = read_once(f.name);
      if (!x.ok || x.tetrahedra != nt || x.vertices != nv) {
        std::cerr << f.name << ": read failed or wrong counts\n";
        return 1;
      }
      best.wall = std::min(best.wall, x.wall);
      best.cpu = std::min(best.cpu, x.cpu);
      best.peak_rss_bytes = std::max(best.peak_rss_bytes, x.peak_rss_bytes);
    }
    char line[512];
    std::snprintf(line, sizeof line, "| %s | %s | %zu | %zu | %.0f | %.2f | %.2f | %.0f | %.0f | %.0f |\n",
                  prstar_bench::base_name(f.name).c_str(), f.label.c_str(), nv, nt, bytes / 1e6, best.wall,
                  best.cpu, bytes / 1e6 / best.wall, bytes / 1e6 / best.cpu,
                  double(best.peak_rss_bytes) / 1e6);
    std::cout << line << std::flush;
  }
  if (!keep)
    for (const Text_file& f : files)
      for (const std::string& part : f.parts) fs::remove(part);
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  std::size_t cells = 0;
  int reps = 3;
  bool keep = false, text = false;
  std::string dir;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--cells" && i + 1 < argc)
      cells = static_cast<std::size_t>(std::atoll(argv[++i]));
    else if (a == "--reps" && i + 1 < argc)
      reps = std::max(1, std::atoi(argv[++i]));
    else if (a == "--keep")
      keep = true;
    else if (a == "--text")
      text = true;
    else if (!a.empty() && a[0] != '-' && dir.empty())
      dir = a;
    else {
      dir.clear();
      break;
    }
  }
  if (cells == 0 || dir.empty()) {
    std::cerr << "usage: bench_io --cells N [--reps R] [--keep] [--text] DIR\n";
    return 2;
  }
  fs::create_directories(dir);
  if (text) return text_formats(cells, reps, keep, dir);
  const std::string vtu = dir + "/lattice.vtu", msh = dir + "/lattice.msh";
  std::size_t nv = 0, nt = 0;
  double write_vtu_s = 0, write_msh_s = 0;
  {
    const double t0 = prstar_bench::now();
    const Mesh m = lattice(cells);
    nv = m.points.size();
    nt = m.tetrahedra.size();
    std::cerr << "lattice: " << nv << " vertices, " << nt << " tetrahedra (" << prstar_bench::now() - t0
              << " s)\n";
    double t = prstar_bench::now();
    CGAL::PR_star_octree::IO::write_vtu(vtu, m);
    write_vtu_s = prstar_bench::now() - t;
    t = prstar_bench::now();
    CGAL::PR_star_octree::IO::write_gmsh(msh, m, CGAL::parameters::use_binary_mode(true));
    write_msh_s = prstar_bench::now() - t;
  }
  const double vtu_bytes = 32.0 * double(nv) + (32.0 + 8 + 1 + 4) * double(nt);
  const double msh_bytes = 32.0 * double(nv) + 40.0 * double(nt);
  std::cout << "| file | vertices | tetrahedra | file MB | decoded MB | write s | read s (best of " << reps
            << ") | read CPU s | decoded MB/s (wall) | decoded MB/s (CPU) | peak RSS MB |\n"
            << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  const struct {
    const std::string& file;
    double bytes, write;
  } files[] = {{vtu, vtu_bytes, write_vtu_s}, {msh, msh_bytes, write_msh_s}};
  for (const auto& f : files) {
    Read_result best;
    best.wall = best.cpu = 1e300;
    for (int r = 0; r < reps; ++r) {
      const Read_result x = read_once(f.file);
      if (!x.ok || x.tetrahedra != nt || x.vertices != nv) {
        std::cerr << f.file << ": read failed or wrong counts\n";
        return 1;
      }
      best.wall = std::min(best.wall, x.wall);
      best.cpu = std::min(best.cpu, x.cpu);
      best.peak_rss_bytes = std::max(best.peak_rss_bytes, x.peak_rss_bytes);
    }
    char line[512];
    std::snprintf(line, sizeof line,
                  "| %s | %zu | %zu | %.0f | %.0f | %.2f | %.2f | %.2f | %.0f | %.0f | %.0f |\n",
                  prstar_bench::base_name(f.file).c_str(), nv, nt, double(fs::file_size(f.file)) / 1e6,
                  f.bytes / 1e6, f.write, best.wall, best.cpu, f.bytes / 1e6 / best.wall,
                  f.bytes / 1e6 / best.cpu, double(best.peak_rss_bytes) / 1e6);
    std::cout << line << std::flush;
  }
  if (!keep) {
    fs::remove(vtu);
    fs::remove(msh);
  }
  return 0;
}
