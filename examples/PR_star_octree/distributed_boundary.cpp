// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The distributed PR-star octree in a user's MPI program: every rank reads its part of a mesh
// file, the ranks build the distributed octree on their own communicator, classify the vertices,
// run a per-leaf application of their own over the ranks (the volume of the mesh and the number of
// its boundary tetrahedra), and write the result as a .pvtu for ParaView.
//
//   mpiexec -np 4 ./distributed_boundary mesh.vtu [out.pvtu]

#include <CGAL/PR_star_octree/Distributed_octree_3.h>
#include <CGAL/PR_star_octree/IO/distributed.h>
#include <CGAL/PR_star_octree/distributed_algorithms.h>
#include <CGAL/property_map.h>

#include <mpi.h>

#include <cmath>
#include <iostream>
#include <vector>

namespace PRS = CGAL::PR_star_octree;
namespace params = CGAL::PR_star_octree::parameters;
using Distributed = PRS::Distributed_octree_3<>;
using Octree = Distributed::Octree;

// The result of one leaf (and of one rank, and of all): trivially copyable, as it travels as bytes.
struct Volume_and_count {
  double volume = 0;
  std::size_t boundary_face_tetrahedra = 0;
};

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (argc < 2) {
    if (rank == 0) std::cerr << "usage: mpiexec -np N " << argv[0] << " MESH [OUT.pvtu]\n";
    MPI_Finalize();
    return 2;
  }
  // the program's own communicator: the package never uses MPI_COMM_WORLD when given one
  MPI_Comm comm;
  MPI_Comm_dup(MPI_COMM_WORLD, &comm);
  int status = 0;
  //! [main]
  try {
    PRS::Distributed_mesh_part part = PRS::IO::read_mesh_part(argv[1], params::communicator(comm));
    const Distributed tree(std::move(part), params::bucket_size(50).communicator(comm));

    // the types of the vertices this rank owns, by part index
    std::vector<PRS::Vertex_type> types(tree.number_of_owned_vertices());
    const PRS::Boundary_counts counts = PRS::compute_boundary(tree, CGAL::make_property_map(types));

    // A per-leaf application: each tetrahedron counted once, by the rank that owns its vertex of
    // smallest global id; the leaves' results added in leaf order, the ranks' in rank order.
    const Octree& octree = tree.local_octree();
    const Volume_and_count total = PRS::Distributed_leaf_executor<>().map_reduce(
        tree, PRS::TRIANGLES, 0,
        [&](int, const PRS::Leaf_topology<Octree>& local) {
          Volume_and_count r;
          const auto owned = local.tetrahedra().owned(); // the leaf's own tetrahedra
          for (Octree::Index t = owned.first; t < owned.second; ++t)
            if (tree.counts_tetrahedron(t))
              r.volume += CGAL::to_double(octree.geom_traits().compute_volume_3_object()(
                  octree.point(octree.tetrahedron(t)[0]), octree.point(octree.tetrahedron(t)[1]),
                  octree.point(octree.tetrahedron(t)[2]), octree.point(octree.tetrahedron(t)[3])));
          return r;
        },
        [](Volume_and_count& into, Volume_and_count&& r) { into.volume += r.volume; });

    if (rank == 0)
      std::cout << tree.number_of_vertices() << " vertices, " << tree.number_of_tetrahedra()
                << " tetrahedra on " << tree.number_of_ranks() << " ranks: " << counts.boundary_vertices
                << " boundary vertices, " << counts.boundary_triangles << " boundary triangles, volume "
                << total.volume << '\n';

    if (argc > 2) { // the types as a point array, ghosts given their owners' values
      std::vector<double> codes(tree.number_of_local_vertices(), 0.);
      for (std::size_t i = 0; i < types.size(); ++i) codes[i] = double(static_cast<int>(types[i]));
      tree.update_ghosts(codes);
      PRS::IO::write_pvtu(argv[2], tree, {{"vertex_type", &codes}});
    }
  } catch (const PRS::Distributed_error& e) { // raised on every rank: each ends cleanly
    if (rank == 0) std::cerr << e.what() << '\n';
    status = 1;
  }
  //! [main]
  MPI_Comm_free(&comm);
  MPI_Finalize();
  return status;
}
