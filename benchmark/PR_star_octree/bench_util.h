// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the benchmark drivers share: clocks, repetitions, a forked child per measurement (so that
// its peak RSS is its own), and small command-line helpers.

#ifndef PRSTAR_BENCH_UTIL_H
#define PRSTAR_BENCH_UTIL_H

#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/Statistics.h>
#include <CGAL/PR_star_octree/bucket_size.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace prstar_bench {

inline double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// A field of /proc/self/status, in KiB (Linux).
inline std::size_t status_kib(const char* key) {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind(key, 0) == 0) return std::stoull(line.substr(std::strlen(key)));
  return 0;
}

/// The minimum time of `reps` runs of `f` after one warm-up run.
template <class F>
double best_of(int reps, F&& f) {
  double best = std::numeric_limits<double>::infinity();
  for (int r = 0; r <= reps; ++r) {
    const double t0 = now();
    f();
    const double t = now() - t0;
    if (r > 0) best = std::min(best, t);
  }
  return best;
}

/// Runs `job()` in a forked child with a fresh peak-RSS counter and returns its result (a
/// trivially copyable struct with members `ok` and `peak_rss_bytes`), sent back through a pipe.
/// `ok` is false when the child failed.
template <class Result, class Job>
Result in_child(Job&& job) {
  static_assert(std::is_trivially_copyable<Result>::value, "the result crosses a pipe");
  int fd[2];
  if (pipe(fd) != 0) return Result{};
  std::cout.flush();
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    { std::ofstream("/proc/self/clear_refs") << "5"; } // reset the peak RSS (Linux >= 4.0)
    const std::size_t base = status_kib("VmRSS:");
    Result r{};
    try {
      r = job();
      r.peak_rss_bytes = (status_kib("VmHWM:") - base) * 1024;
      r.ok = true;
    } catch (const std::exception& e) {
      std::cerr << "  failed: " << e.what() << '\n';
      r.ok = false;
    }
    if (write(fd[1], &r, sizeof r) != static_cast<ssize_t>(sizeof r)) _exit(1);
    _exit(0);
  }
  close(fd[1]);
  Result r{};
  if (read(fd[0], &r, sizeof r) != static_cast<ssize_t>(sizeof r)) r.ok = false;
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFSIGNALED(status)) {
    std::cerr << "  failed: the child was killed by signal " << WTERMSIG(status) << '\n';
    r.ok = false;
  }
  return r;
}

constexpr std::size_t infinite_kv = (std::numeric_limits<std::size_t>::max)();

constexpr std::size_t automatic_kv = CGAL::PR_star_octree::automatic_bucket_size;

inline std::string kv_name(std::size_t kv) {
  return kv == infinite_kv ? "inf" : kv == automatic_kv ? "auto" : std::to_string(kv);
}

/// "auto,10,20,inf" -> {automatic_kv, 10, 20, infinite_kv}
inline std::vector<std::size_t> parse_kv_list(const std::string& s) {
  std::vector<std::size_t> r;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = s.find(',', start);
    const std::string item = s.substr(start, comma - start);
    r.push_back(item == "inf" ? infinite_kv : item == "auto" ? automatic_kv : std::stoull(item));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return r;
}

/// The bytes per tetrahedron of an octree as `prstar stats` reports them (without the numbering
/// permutations, which a benchmark keeps when its queries answer in the input numbering) and their
/// breakdown, the same in every benchmark (issue 24, item 5).
struct Bytes_per_tetrahedron {
  double total = 0;        ///< `Statistics::bytes_per_tetrahedron_without_permutations()`
  double tetrahedra = 0;   ///< T (plain or compact)
  double points = 0;       ///< V's coordinates
  double leaf_lists = 0;   ///< the shared parts of the leaf lists
  double nodes = 0;        ///< nodes and the list of leaves
  double other = 0;        ///< scalars, labels, the reorientation bits
  double permutations = 0; ///< the numbering permutations the measured octree kept (not in `total`)

  Bytes_per_tetrahedron() = default;
  explicit Bytes_per_tetrahedron(const CGAL::PR_star_octree::Statistics& s) {
    if (s.tetrahedra == 0) return;
    const double t = double(s.tetrahedra);
    const auto& b = s.bytes;
    total = s.bytes_per_tetrahedron_without_permutations();
    tetrahedra = double(b.tetrahedra) / t;
    points = double(b.points) / t;
    leaf_lists = double(b.leaf_tetrahedra) / t;
    nodes = double(b.nodes) / t;
    other = double(b.scalars + b.labels + b.reorientation) / t;
    permutations = double(b.permutations) / t;
  }
  /// "T 5.14 + V 4.40 + lists 0.83 + nodes 0.10 + other 1.39"
  std::string breakdown() const {
    char text[160];
    std::snprintf(text, sizeof text, "T %.2f + V %.2f + lists %.2f + nodes %.2f + other %.2f", tetrahedra,
                  points, leaf_lists, nodes, other);
    return text;
  }
  /// the CSV columns of `csv_header()`
  std::string csv() const {
    char text[200];
    std::snprintf(text, sizeof text, "%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f", total, tetrahedra, points,
                  leaf_lists, nodes, other, permutations);
    return text;
  }
  static const char* csv_header() {
    return "bytes_per_tet,bpt_tetrahedra,bpt_points,bpt_leaf_lists,bpt_nodes,bpt_other,bpt_permutations_kept";
  }
};

/// Writes `text` to `path`; false (with a message) when it cannot.
inline bool write_text_file(const std::string& path, const std::string& text) {
  std::ofstream f(path);
  f << text;
  if (!f) {
    std::cerr << path << ": cannot write\n";
    return false;
  }
  return true;
}

/// Reads a mesh file with the package's readers; false (with the reader's message) when it cannot.
template <class Mesh>
bool read_mesh_file(const std::string& file, Mesh& mesh) {
  try {
    CGAL::PR_star_octree::IO::read_tetrahedral_mesh(file, mesh);
  } catch (const std::exception& e) {
    std::cerr << e.what() << '\n';
    return false;
  }
  return true;
}

inline std::string base_name(const std::string& p) {
  const std::size_t s = p.find_last_of('/');
  return s == std::string::npos ? p : p.substr(s + 1);
}

} // namespace prstar_bench

#endif // PRSTAR_BENCH_UTIL_H
