// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// bench_mpi: the distributed octree, phase by phase, on every rank (run by hand under mpirun, never
// as a timed test; benchmark/PR_star_octree/run_bench_mpi.sh runs the series of results/mpi.md).
//
//   mpirun -np N bench_mpi MESH [--kv K] [--out OUT.pvtu] [--threads T]
//
// Prints one JSON object (rank 0): the seconds of each phase (read, partition, build, compute:
// boundary, write), the largest over the ranks (the phase ends when the slowest rank is done:
// barriers between phases); the peak RSS of each rank (getrusage, after each phase); the owned and
// ghost vertices and tetrahedra of each rank; the bytes each rank sent.

#include <CGAL/PR_star_octree/Distributed_octree_3.h>
#include <CGAL/PR_star_octree/IO/distributed.h>
#include <CGAL/PR_star_octree/distributed_algorithms.h>
#include <CGAL/property_map.h>

#include <mpi.h>
#include <sys/resource.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace PRS = CGAL::PR_star_octree;
namespace params = CGAL::PR_star_octree::parameters;
using Distributed = PRS::Distributed_octree_3<>;

namespace {

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.; // kilobytes on Linux
}

// The values of every rank, as a JSON array (rank 0's string).
template <class T>
std::string per_rank(T value) {
  const std::vector<T> all = PRS::internal::all_gather(MPI_COMM_WORLD, value);
  std::ostringstream s;
  s << std::setprecision(6) << '[';
  for (std::size_t i = 0; i < all.size(); ++i) s << (i ? ", " : "") << all[i];
  return s.str() + ']';
}

} // namespace

int main(int argc, char** argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (argc < 2) {
    if (rank == 0)
      std::cerr << "usage: mpirun -np N bench_mpi MESH [--kv K] [--out OUT.pvtu] [--threads T]\n";
    MPI_Finalize();
    return 2;
  }
  const std::string file = argv[1];
  std::size_t kv = 50, threads = 1;
  std::string out;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--kv") kv = std::strtoull(argv[i + 1], nullptr, 10);
    if (a == "--out") out = argv[i + 1];
    if (a == "--threads") threads = std::strtoull(argv[i + 1], nullptr, 10);
  }
#ifdef CGAL_LINKED_WITH_TBB
  tbb::global_control control(tbb::global_control::max_allowed_parallelism, threads);
#endif
  std::ostringstream json;
  json << std::setprecision(6);
  auto clock = std::chrono::steady_clock::now();
  auto phase = [&](const char* name) { // the slowest rank's seconds, and every rank's peak so far
    MPI_Barrier(MPI_COMM_WORLD);
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - clock).count();
    clock = now;
    json << ", \"" << name << "_seconds\": " << s << ", \"" << name
         << "_peak_rss_mb\": " << per_rank(peak_rss_mb());
  };
  int status = 0;
  try {
    json << "{\"mesh\": \"" << file << "\", \"ranks\": " << ranks << ", \"threads\": " << threads
         << ", \"kv\": " << kv;
    PRS::Distributed_mesh_part part = PRS::IO::read_mesh_part(file);
    phase("read");
    const Distributed tree(std::move(part), params::bucket_size(kv));
    const double partition = tree.partition_seconds(), build = tree.build_seconds();
    phase("partition_and_build");
    json << ", \"partition_seconds_per_rank\": " << per_rank(partition)
         << ", \"build_seconds_per_rank\": " << per_rank(build);
    std::vector<PRS::Vertex_type> types(tree.number_of_owned_vertices());
    const PRS::Boundary_counts b = PRS::compute_boundary(tree, CGAL::make_property_map(types));
    phase("boundary");
    if (!out.empty()) {
      std::vector<double> codes(tree.number_of_local_vertices(), 0.);
      for (std::size_t i = 0; i < types.size(); ++i) codes[i] = double(static_cast<int>(types[i]));
      tree.update_ghosts(codes);
      PRS::IO::write_pvtu(out, tree, {{"vertex_type", &codes}});
      phase("write");
    }
    const std::uint64_t local_tets = tree.local_octree().number_of_tetrahedra();
    json << ", \"vertices\": " << tree.number_of_vertices()
         << ", \"tetrahedra\": " << tree.number_of_tetrahedra()
         << ", \"boundary_vertices\": " << b.boundary_vertices
         << ", \"boundary_triangles\": " << b.boundary_triangles
         << ", \"owned_vertices\": " << per_rank<std::uint64_t>(tree.number_of_owned_vertices())
         << ", \"ghost_vertices\": " << per_rank<std::uint64_t>(tree.number_of_ghost_vertices())
         << ", \"local_tetrahedra\": " << per_rank(local_tets)
         << ", \"ghost_tetrahedra\": " << per_rank<std::uint64_t>(tree.number_of_ghost_tetrahedra())
         << ", \"bytes_sent\": " << per_rank<std::uint64_t>(tree.bytes_sent())
         << ", \"peak_rss_mb\": " << per_rank(peak_rss_mb()) << "}";
    if (rank == 0) std::cout << json.str() << std::endl;
  } catch (const PRS::Distributed_error& e) {
    if (rank == 0) std::cerr << "bench_mpi: " << e.what() << '\n';
    status = 1;
  }
  MPI_Finalize();
  return status;
}
