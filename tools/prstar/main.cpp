// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar: the command-line tool of the PR-star octree package.  Each command lives in its
// cmd_<name>.cpp; the options, help texts, output-file rules and exit statuses they share are in
// command.h.  This file only dispatches.

#include "commands.h"

#include <CGAL/version.h>

#ifdef PRSTAR_WITH_MPI
#include <CGAL/PR_star_octree/internal/mpi_communication.h>
#include <mpi.h>
#endif

#include <cstdlib>
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

namespace {

int run_one_process(const std::vector<prstar::Command>& commands, int argc, char** argv);

std::string main_usage(const std::vector<prstar::Command>& commands) {
  std::string s = "prstar - the PR-star octree for tetrahedral meshes\n\n"
                  "usage: prstar COMMAND [options]\n\n"
                  "commands:\n";
  for (const prstar::Command& c : commands)
    s += "  " + c.name() + std::string(c.name().size() < 11 ? 11 - c.name().size() : 1, ' ') + c.summary() +
         '\n';
  s += "\nRun 'prstar COMMAND --help' or 'prstar help COMMAND' for the options of a command,\n"
       "'prstar --version' for the version.\n";
#ifdef PRSTAR_WITH_MPI
  s += "Under mpirun (mpirun -np N prstar COMMAND ...), stats, boundary, curvature and validate run\n"
       "distributed over the ranks, with the same options and results; -o also takes OUT.pvtu (one\n"
       "piece per rank, in the folder OUT/).\n\n";
#endif
  return s + prstar::mesh_formats() +
         "Exit status: 0 success, 1 error, 2 usage error, 3 (validate) the mesh is not valid,\n"
         "4 (simplify) stopped before the target.\n";
}

// The one-line report of a usage error, and where to read more.
void usage_error(const prstar::Command& c, const std::string& what) {
  std::cerr << "prstar " << c.name() << ": " << what << "\n"
            << "see 'prstar " << c.name() << " --help'\n";
}

std::string version() {
  std::string v = "prstar " PRSTAR_VERSION " (the PR-star octree package; CGAL " CGAL_VERSION_STR;
#ifdef PRSTAR_WITH_MPI
  v += ", MPI";
#endif
#ifdef CGAL_PR_STAR_OCTREE_USE_HDF5
  v += ", HDF5";
#endif
#ifdef CGAL_LINKED_WITH_TBB
  v += ", TBB";
#endif
  return v + ")\n";
}

bool wants_help(int argc, char** argv) {
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") return true;
  }
  return false;
}

#ifdef PRSTAR_WITH_MPI
// Whether the process was started by mpirun/mpiexec (Open MPI, MPICH, PMIx, Slurm's PMI).
bool launched_by_mpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(v)) return true;
  return false;
}

// Every rank runs this with the same arguments; rank 0 alone prints usage and errors.  An error
// every rank agrees on (a bad file: `Distributed_error`) ends each rank with exit status 1; an
// error on one rank only ends them all through MPI_Abort, never a hang.
int run_distributed(const std::vector<prstar::Command>& commands, int argc, char** argv) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  std::ostream& err = std::cerr;
  const bool speaks = rank == 0;
  const std::string name = argc >= 2 ? argv[1] : "";
  for (const prstar::Command& c : commands) {
    if (name != c.name() || wants_help(argc, argv)) continue;
    if (!c.is_distributed() && ranks > 1) {
      if (speaks)
        err << "prstar " << c.name() << ": not distributed yet: run it without mpirun (or with -np 1)\n";
      return prstar::exit_usage;
    }
    if (!c.is_distributed()) return -1; // one rank: as without mpirun
    try {
      return c.execute_distributed(c.parse(argc, argv, 2, true));
    } catch (const prstar::Usage_error& e) {
      if (speaks) usage_error(c, e.what());
      return prstar::exit_usage;
    } catch (const CGAL::PR_star_octree::Distributed_error& e) {
      if (speaks) err << "prstar " << c.name() << ": " << e.what() << '\n';
      return prstar::exit_error;
    } catch (const std::exception& e) {
      err << "prstar " << c.name() << ": rank " << rank << ": " << e.what() << '\n';
      err.flush();
      MPI_Abort(MPI_COMM_WORLD, prstar::exit_error);
    }
  }
  return -1; // help, an unknown command: as without mpirun, printed by rank 0
}
#endif

} // namespace

int main(int argc, char** argv) {
  std::vector<prstar::Command> commands = {
      prstar::demo_command(),     prstar::info_command(),     prstar::convert_command(),
      prstar::stats_command(),    prstar::boundary_command(), prstar::curvature_command(),
      prstar::validate_command(), prstar::critical_command(), prstar::morse_command(),
      prstar::simplify_command(), prstar::remesh_command(),   prstar::generate_command()};
#ifdef PRSTAR_WITH_MPI
  if (launched_by_mpirun()) {
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    prstar::add_distributed_runs(commands);
    int code = run_distributed(commands, argc, argv);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (code < 0 && rank != 0) {
      // help and usage texts: printed once, by rank 0
      std::cout.setstate(std::ios::failbit);
      std::cerr.setstate(std::ios::failbit);
    }
    if (code < 0) code = run_one_process(commands, argc, argv);
    MPI_Finalize();
    return code;
  }
#endif
  return run_one_process(commands, argc, argv);
}

namespace {

int run_one_process(const std::vector<prstar::Command>& commands, int argc, char** argv) {
  if (argc < 2) {
    std::cerr << main_usage(commands);
    return prstar::exit_usage;
  }
  const std::string name = argv[1];
  if (name == "--version" || name == "-V") {
    std::cout << version();
    return prstar::exit_success;
  }
  if (name == "help" && argc >= 3) { // prstar help COMMAND
    for (const prstar::Command& c : commands)
      if (c.name() == argv[2]) {
        std::cout << c.help();
        return prstar::exit_success;
      }
  }
  if (name == "--help" || name == "-h" || (name == "help" && argc == 2)) {
    std::cout << main_usage(commands);
    return prstar::exit_success;
  }
  std::vector<std::string> names;
  for (const prstar::Command& c : commands) names.push_back(c.name());
  if (name == "help") {
    std::cerr << "prstar help: unknown command '" << argv[2] << "'" << prstar::did_you_mean(argv[2], names)
              << "\nsee 'prstar --help'\n";
    return prstar::exit_usage;
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
      usage_error(c, e.what());
      return prstar::exit_usage;
    } catch (const std::bad_alloc&) {
      std::cerr << "prstar " << c.name() << ": out of memory\n";
      return prstar::exit_error;
    } catch (const std::exception& e) {
      std::cerr << "prstar " << c.name() << ": " << e.what() << '\n';
      return prstar::exit_error;
    }
  }
  std::cerr << "prstar: unknown command '" << name << "'" << prstar::did_you_mean(name, names)
            << "\nsee 'prstar --help'\n";
  return prstar::exit_usage;
}

} // namespace
