// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The commands of the prstar tool, one per cmd_<name>.cpp, dispatched by main.cpp.

#ifndef PRSTAR_COMMANDS_H
#define PRSTAR_COMMANDS_H

#include "command.h"

#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/internal/fixed_point_sum.h>
#include <CGAL/PR_star_octree/validity.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>

#include <string>
#include <vector>

namespace prstar {

Command demo_command();
Command stats_command();
Command boundary_command();
Command curvature_command();
Command validate_command();
Command simplify_command();
Command remesh_command();
Command generate_command();
Command convert_command();
Command info_command();
Command critical_command();
Command morse_command();

/// Builds the PR-star octree of `mesh` for each k_v and prints its statistics (a table titled
/// `name`, or JSON): shared by stats and demo (cmd_stats.cpp).
void report_statistics(Mesh mesh, const std::string& name, const std::vector<std::size_t>& kvs,
                       std::size_t max_depth, bool compact,
                       CGAL::PR_star_octree::Coordinate_precision precision, bool json,
                       Progress_bar& progress,
                       const std::string& octree_out = "", // `--octree`: the leaf boxes of the last k_v
                       // the tetrahedra read in passes from this file (the streaming construction),
                       // `mesh` then empty
                       const CGAL::PR_star_octree::IO::Vtu_tetrahedron_source* source = nullptr);

/// Values over a set of vertices: smallest, largest, and their exact sum (the same mean whatever
/// the order in which they are added, e.g. by several ranks).
struct Value_summary {
  double min = std::numeric_limits<double>::infinity(), max = -std::numeric_limits<double>::infinity();
  CGAL::PR_star_octree::internal::Fixed_point_sum sum;
  std::uint64_t count = 0;
  void add(double d) {
    min = std::min(min, d);
    max = std::max(max, d);
    sum.add(d);
    ++count;
  }
  void add(const Value_summary& o) {
    min = std::min(min, o.min);
    max = std::max(max, o.max);
    sum.add(o.sum);
    count += o.count;
  }
  double mean() const { return sum.value() / double(count); }
};

/// What curvature reports: the vertices of each type (the codes of `vertex_type_code()`: interior,
/// boundary, non-manifold, unreferenced) and, for the interior and the boundary ones, the
/// distortion and the domain's concentrated curvature.  Trivially copyable (gathered over ranks).
struct Curvature_summary {
  std::uint64_t counts[4] = {0, 0, 0, 0};
  Value_summary distortion[2], domain[2];
  void add(int code, double distortion_value, double domain_value) {
    ++counts[code];
    if (code > 1) return; // undefined (non-manifold) or absent
    distortion[code].add(distortion_value);
    domain[code].add(domain_value);
  }
  void add(const Curvature_summary& o) {
    for (int k = 0; k < 4; ++k) counts[k] += o.counts[k];
    for (int k = 0; k < 2; ++k) {
      distortion[k].add(o.distortion[k]);
      domain[k].add(o.domain[k]);
    }
  }
};

/// One row of the curvature CSV.
struct Curvature_row {
  double x, y, z;
  int code;
  double distortion, domain;
};
/// Writes the curvature CSV `csv` (one row per vertex, in the user's order, `row(v)` for v < n),
/// through a temporary: shared by one process and rank 0 of a distributed run.
void write_curvature_csv(const std::string& csv, std::size_t n,
                         const std::function<Curvature_row(std::size_t)>& row);

/// The summaries printed by boundary, curvature and validate, on one process and distributed (the
/// same text and JSON keys; cmd_boundary.cpp, cmd_curvature.cpp, cmd_validate.cpp).
/// `interfaces`: the number of triangles between two labels (-1: not computed, not reported);
/// `compact`: the octree's tetrahedra were compact, `streamed`: read in passes (a distributed
/// octree's parts are never streamed; compact with --compact)
void report_boundary(const Options& o, std::size_t nv, std::size_t nt,
                     const CGAL::PR_star_octree::Boundary_counts& b, double seconds,
                     long long interfaces = -1, bool compact = false, bool streamed = false);
void report_curvature(const Options& o, std::size_t nv, std::size_t nt, const std::string& field_name,
                      const Curvature_summary& summary, double seconds, bool compact = false,
                      bool streamed = false);
/// `problems`: the list of `check_validity()`'s `problems_output` (one process), or null (distributed:
/// the counts only); `compact`, `streamed`: the table says how the tetrahedra were stored and read
/// (the JSON keeps the keys of the Python module's `validate`).  \returns the exit status: valid or not
int report_validity(const Options& o, const CGAL::PR_star_octree::Validity_result& r, double seconds,
                    const std::vector<CGAL::PR_star_octree::Validity_problem>* problems = nullptr,
                    bool compact = false, bool streamed = false);

#ifdef PRSTAR_WITH_MPI
/// Gives stats, boundary, curvature and validate their distributed form (cmd_distributed.cpp).
void add_distributed_runs(std::vector<Command>& commands);
#endif

} // namespace prstar

#endif // PRSTAR_COMMANDS_H
