// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The commands of the prstar tool, one per cmd_<name>.cpp, dispatched by main.cpp.

#ifndef PRSTAR_COMMANDS_H
#define PRSTAR_COMMANDS_H

#include "command.h"

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

} // namespace prstar

#endif // PRSTAR_COMMANDS_H
