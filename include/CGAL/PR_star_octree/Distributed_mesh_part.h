// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_DISTRIBUTED_MESH_PART_H
#define CGAL_PR_STAR_OCTREE_DISTRIBUTED_MESH_PART_H

/// \file Distributed_mesh_part.h
/// The part of a tetrahedral mesh one MPI rank holds before the distributed octree is built.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace PR_star_octree {

/// \ingroup PkgPRStarOctreeDistributed
/// The error of a collective operation of the distributed octree (reading, building, writing),
/// raised on every rank with the same message: the message of the first rank that failed, prefixed
/// by its rank when there are several.  Every rank can thus end cleanly (no rank waits for a failed
/// one).
class Distributed_error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// \ingroup PkgPRStarOctreeDistributed
/// The part of a mesh one rank starts from: a contiguous block of the vertices (global ids
/// `first_vertex`, `first_vertex + 1`, ...) and any tetrahedra (by global vertex ids).  Over the ranks,
/// the vertex blocks follow each other in rank order and cover the mesh; every tetrahedron is in
/// exactly one part.  `IO::read_mesh_part()` makes them from a file; a program that has its mesh
/// already spread over its ranks fills them itself.  Plain data: no MPI in this header.
struct Distributed_mesh_part {
  /// the global id of the first vertex of this part (the sum of the sizes of the parts of the
  /// ranks before)
  std::uint64_t first_vertex = 0;
  /// x, y, z of each vertex of the block
  std::vector<double> coordinates;
  /// whether the coordinates were 32-bit floats in the file (the same on every rank): the local
  /// octrees then store floats under `Coordinate_precision::as_input`, as one process does
  bool float32_points = false;
  /// the names of the point arrays (the first is the scalar field of the octree), the same on
  /// every rank
  std::vector<std::string> point_array_names;
  /// one vector per name, one value per vertex of the block
  std::vector<std::vector<double>> point_arrays;
  /// the tetrahedra of the part, by global vertex ids.  Over the ranks, in rank order, the parts'
  /// tetrahedra are the tetrahedra of the mesh: their index in that order is their global id.
  std::vector<std::array<std::uint64_t, 4>> tetrahedra;
  /// empty, or one label per tetrahedron (the same choice on every rank)
  std::vector<int> tetrahedron_labels;
  /// the name of the label array for the output (VTK cell array name)
  std::string label_name = "label";
  /// cells of other types met and not kept by this rank's reader, by type name
  std::map<std::string, std::size_t> skipped_cells;

  /// \name Deferred tetrahedra
  /// Instead of `tetrahedra` and `tetrahedron_labels` (then empty), a part may give its tetrahedra
  /// in blocks read on demand: the construction of `Distributed_octree_3` calls
  /// `read_tetrahedra(k, tetrahedra, labels)` for `k = 0 ... tetrahedron_blocks - 1`, twice (one
  /// pass counts the stars, the other sends the tetrahedra to their ranks), each time with empty
  /// vectors to fill with block `k` (labels: one per tetrahedron, when `deferred_labels`).  A rank
  /// then never holds all of its part's tetrahedra at once.  `IO::read_mesh_part()` reads an
  /// appended-raw `.vtu` this way.  An exception thrown by the function is raised on every rank
  /// (`Distributed_error`).
  /// @{
  std::size_t tetrahedron_blocks = 0;
  bool deferred_labels = false;
  std::function<void(std::size_t block, std::vector<std::array<std::uint64_t, 4>>& tetrahedra,
                     std::vector<int>& labels)>
      read_tetrahedra;
  /// @}

  /// the number of vertices of the block
  std::size_t number_of_vertices() const { return coordinates.size() / 3; }
};

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_DISTRIBUTED_MESH_PART_H
