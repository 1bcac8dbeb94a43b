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
Command generate_command();

/// Builds the PR-star octree of `mesh` for each k_v and prints its statistics (a table titled
/// `name`, or JSON): shared by stats and demo (cmd_stats.cpp).
void report_statistics(Mesh mesh, const std::string& name, const std::vector<std::size_t>& kvs,
                       std::size_t max_depth, bool json, Progress_bar& progress,
                       const std::string& octree_out = ""); // `--octree`: the leaf boxes of the last k_v

/// The distortions of the manifold vertices: smallest, largest, and their exact sum (the same mean
/// whatever the order in which they are added, e.g. by several ranks).
struct Distortion_summary {
  double min = std::numeric_limits<double>::infinity(), max = -std::numeric_limits<double>::infinity();
  CGAL::PR_star_octree::internal::Fixed_point_sum sum;
  std::uint64_t count = 0;
  void add(double d) {
    min = std::min(min, d);
    max = std::max(max, d);
    sum.add(d);
    ++count;
  }
  void add(const Distortion_summary& o) {
    min = std::min(min, o.min);
    max = std::max(max, o.max);
    sum.add(o.sum);
    count += o.count;
  }
  double mean() const { return sum.value() / double(count); }
};

/// The summaries printed by boundary, curvature and validate, on one process and distributed (the
/// same text and JSON keys; cmd_boundary.cpp, cmd_curvature.cpp, cmd_validate.cpp).
void report_boundary(const Options& o, std::size_t nv, std::size_t nt,
                     const CGAL::PR_star_octree::Boundary_counts& b, double seconds);
void report_curvature(const Options& o, std::size_t nv, std::size_t nt, const std::string& field_name,
                      const std::size_t counts[4], const Distortion_summary& summary, double seconds);
/// `problems`: the list of `check_validity()`'s `problems_output` (one process), or null (distributed:
/// the counts only).  \returns the exit status: valid or not
int report_validity(const Options& o, const CGAL::PR_star_octree::Validity_result& r, double seconds,
                    const std::vector<CGAL::PR_star_octree::Validity_problem>* problems = nullptr);

#ifdef PRSTAR_WITH_MPI
/// Gives stats, boundary, curvature and validate their distributed form (cmd_distributed.cpp).
void add_distributed_runs(std::vector<Command>& commands);
#endif

} // namespace prstar

#endif // PRSTAR_COMMANDS_H
