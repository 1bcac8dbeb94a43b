// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_MEMORY_LIMIT_H
#define CGAL_PR_STAR_OCTREE_IO_MEMORY_LIMIT_H

/// \file Memory_limit.h
/// The memory the readers may plan for a mesh, checked from the counts of a file's header before
/// the arrays are allocated.

#include <CGAL/PR_star_octree/IO/Read_error.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

namespace CGAL {
namespace PR_star_octree {
namespace IO {

/// \ingroup PkgPRStarOctreeIO
/// Thrown by a reader when the mesh a file announces (its header's counts) needs more memory than
/// `Memory_limit::current()` allows, before the large arrays are allocated.  A `Read_error`:
/// `what()` names the file, the counts, the bytes needed and the limit.
class Memory_limit_error : public Read_error {
public:
  Memory_limit_error(const std::string& file, std::size_t line, const std::string& message,
                     std::size_t needed, std::size_t limit)
      : Read_error(file, line, message), needed_(needed), limit_(limit) {}
  /// the estimated bytes of the mesh
  std::size_t needed() const { return needed_; }
  /// the limit that refused it
  std::size_t limit() const { return limit_; }

private:
  std::size_t needed_, limit_;
};

/// \ingroup PkgPRStarOctreeIO
/// The number of bytes the readers of the calling thread may plan for one mesh.
///
/// By default it is the memory the system reports as available (`MemAvailable` of
/// `/proc/meminfo` on Linux: free memory plus what the page cache can give back), read when the
/// file is opened; unlimited where that is not known.  A reader refuses a file whose header
/// announces a mesh needing more (points, tetrahedra and the data arrays it will keep, at their
/// sizes in memory) with a `Memory_limit_error`, before allocating it: a machine does not swap to
/// death or call the OOM killer on a mesh it could never hold.
///
/// An object of this class sets another limit for the calling thread while it lives (limits nest):
/// \code
/// CGAL::PR_star_octree::IO::Memory_limit limit(std::size_t(64) << 30); // allow 64 GiB
/// CGAL::PR_star_octree::IO::read_tetrahedral_mesh("huge.vtu", mesh);
/// \endcode
/// `Memory_limit(Memory_limit::unlimited)` turns the check off.
class Memory_limit {
public:
  static constexpr std::size_t unlimited = (std::numeric_limits<std::size_t>::max)();

  /// sets the limit of the calling thread to `bytes` until destruction
  explicit Memory_limit(std::size_t bytes) : previous_(slot()) { slot() = bytes; }
  ~Memory_limit() { slot() = previous_; }
  Memory_limit(const Memory_limit&) = delete;
  Memory_limit& operator=(const Memory_limit&) = delete;

  /// the limit in force: the innermost `Memory_limit` object of the thread, else `available()`
  static std::size_t current() { return slot() != no_limit_set ? slot() : available(); }

  /// the memory the system reports as available, in bytes (`unlimited` when unknown)
  static std::size_t available() {
    std::ifstream meminfo("/proc/meminfo");
    std::string line;
    while (std::getline(meminfo, line)) {
      if (line.compare(0, 13, "MemAvailable:") != 0) continue;
      std::istringstream in(line.substr(13));
      unsigned long long kib = 0;
      if (in >> kib && kib < (std::numeric_limits<std::size_t>::max)() / 1024)
        return static_cast<std::size_t>(kib) * 1024;
    }
    return unlimited;
  }

private:
  static constexpr std::size_t no_limit_set = 0;
  static std::size_t& slot() {
    static thread_local std::size_t limit = no_limit_set;
    return limit;
  }
  std::size_t previous_;
};

namespace internal {

/// A byte count in the unit that shows it with three significant digits at least: "1.50 GB",
/// "842 MB", "1.02 kB", "512 bytes" (powers of 1000, as the file sizes of `ls -h --si`).
inline std::string gigabytes(std::size_t bytes) {
  const char* units[] = {"kB", "MB", "GB", "TB", "PB", "EB"};
  if (bytes < 1000) return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
  double v = static_cast<double>(bytes) / 1e3;
  int u = 0;
  while (v >= 999.995 && u < 5) {
    v /= 1e3;
    ++u;
  }
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(v < 9.995 ? 2 : v < 99.95 ? 1 : 0);
  s << v << ' ' << units[u];
  return s.str();
}

/// Throws `Memory_limit_error` when a mesh of `vertices` points (of `point_bytes` bytes each, plus
/// `vertex_arrays` doubles) and `tetrahedra` tetrahedra (of `tetrahedron_bytes` bytes each, plus
/// `tetrahedron_arrays` 8-byte values) exceeds `Memory_limit::current()`.
inline void check_memory(const std::string& file, std::size_t line, std::uint64_t vertices,
                         std::uint64_t tetrahedra, std::size_t point_bytes, std::size_t tetrahedron_bytes,
                         std::size_t vertex_arrays = 0, std::size_t tetrahedron_arrays = 0) {
  const std::size_t limit = Memory_limit::current();
  if (limit == Memory_limit::unlimited) return;
  const long double need =
      static_cast<long double>(vertices) * (point_bytes + 8 * vertex_arrays) +
      static_cast<long double>(tetrahedra) * (tetrahedron_bytes + 8 * tetrahedron_arrays);
  if (need <= static_cast<long double>(limit)) return;
  const std::size_t needed = need >= static_cast<long double>(Memory_limit::unlimited)
                                 ? Memory_limit::unlimited
                                 : static_cast<std::size_t>(need);
  throw Memory_limit_error(file, line,
                           "the mesh announced (" + std::to_string(vertices) + " vertices, " +
                               std::to_string(tetrahedra) + " tetrahedra) needs about " + gigabytes(needed) +
                               " of memory, more than the limit of " + gigabytes(limit) +
                               ": refused before reading it",
                           needed, limit);
}

/// `check_memory()`, but only when the rest of the file (`available_bytes`) can hold the
/// `announced` entries at `min_bytes` each at least: otherwise the file is truncated or its count
/// wrong, which the parser reports itself.
inline void check_memory_if_present(const std::string& file, std::size_t line, std::uint64_t vertices,
                                    std::uint64_t tetrahedra, std::size_t point_bytes,
                                    std::size_t tetrahedron_bytes, std::uint64_t announced,
                                    std::size_t min_bytes, std::size_t available_bytes) {
  if (min_bytes != 0 && announced > available_bytes / min_bytes) return;
  check_memory(file, line, vertices, tetrahedra, point_bytes, tetrahedron_bytes);
}

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_MEMORY_LIMIT_H
