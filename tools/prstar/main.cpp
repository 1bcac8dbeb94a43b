// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar: the command-line tool of the PR-star octree package.  Each command lives in its
// cmd_<name>.cpp; the options, help texts, output-file rules and exit statuses they share are in
// command.h.  This file only dispatches.

#include "commands.h"

#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

namespace {

std::string main_usage(const std::vector<prstar::Command>& commands) {
  std::string s = "prstar - the PR-star octree for tetrahedral meshes\n\n"
                  "usage: prstar COMMAND [options]\n\n"
                  "commands:\n";
  for (const prstar::Command& c : commands)
    s += "  " + c.name() + std::string(c.name().size() < 11 ? 11 - c.name().size() : 1, ' ') + c.summary() +
         '\n';
  return s + "\nRun 'prstar COMMAND --help' for the options of a command.\n" + prstar::mesh_formats() +
         "Exit status: 0 success, 1 error, 2 usage error, 3 (validate) the mesh is not valid,\n"
         "4 (simplify) stopped before the target.\n";
}

bool wants_help(int argc, char** argv) {
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") return true;
  }
  return false;
}

} // namespace

int main(int argc, char** argv) {
  const std::vector<prstar::Command> commands = {prstar::demo_command(),     prstar::stats_command(),
                                                 prstar::boundary_command(), prstar::curvature_command(),
                                                 prstar::validate_command(), prstar::simplify_command(),
                                                 prstar::generate_command()};
  if (argc < 2) {
    std::cerr << main_usage(commands);
    return prstar::exit_usage;
  }
  const std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    std::cout << main_usage(commands);
    return prstar::exit_success;
  }
  for (const prstar::Command& c : commands) {
    if (name != c.name()) continue;
    if (wants_help(argc, argv)) {
      std::cout << c.help();
      return prstar::exit_success;
    }
    try {
      return c.execute(c.parse(argc, argv, 2));
    } catch (const prstar::Usage_error& e) {
      std::cerr << "prstar " << c.name() << ": " << e.what() << "\n\n" << c.help();
      return prstar::exit_usage;
    } catch (const std::bad_alloc&) {
      std::cerr << "prstar " << c.name() << ": out of memory\n";
      return prstar::exit_error;
    } catch (const std::exception& e) {
      std::cerr << "prstar " << c.name() << ": " << e.what() << '\n';
      return prstar::exit_error;
    }
  }
  std::cerr << "prstar: unknown command '" << name << "'\n\n" << main_usage(commands);
  return prstar::exit_usage;
}
