// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_SIMPLIFICATION_STATISTICS_H
#define CGAL_PR_STAR_OCTREE_SIMPLIFICATION_STATISTICS_H

/// \file Simplification_statistics.h
/// What `simplify()` returns: the simplified mesh, where its vertices come from, and what it did.

#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace PR_star_octree {

/// \ingroup PkgPRStarOctreeRef
/// What a run of `simplify()` did.
struct Simplification_statistics {
  std::size_t input_vertices = 0, output_vertices = 0;
  std::size_t input_tetrahedra = 0, output_tetrahedra = 0, removed_tetrahedra = 0;
  std::size_t collapses = 0;
  std::size_t rounds = 0;                     ///< rounds of (local simplification, compaction, rebuild)
  std::vector<std::size_t> removed_per_round; ///< tetrahedra removed by each round
  std::size_t max_queue_size =
      0;              ///< the largest queue, over all leaves and rounds (the memory proxy of Table 3)
  double seconds = 0; ///< wall-clock time of the whole run, octree builds included
  /// candidate edges (shorter than the round's threshold) that were not collapsed, by reason; a
  /// candidate is counted under the first condition it fails, in this order
  struct Blocked {
    std::size_t different_leaves = 0; ///< its two ends are in different leaves (counted once per round)
    std::size_t boundary = 0;         ///< boundary condition (or a non-manifold end)
    std::size_t flip = 0;             ///< geometric condition: a tetrahedron would flip or become flat
    std::size_t link = 0;             ///< link condition
  } blocked;
};

/// \ingroup PkgPRStarOctreeRef
/// The simplified mesh and where its vertices come from.
template <class Point_3>
struct Simplification_result {
  /// positively oriented tetrahedra; the point data of the input (its scalar field) and its
  /// tetrahedron labels carried along
  Indexed_tetrahedral_mesh<Point_3> mesh;
  /// for each output vertex, its index in the input (a half-edge collapse never moves a vertex)
  std::vector<std::size_t> input_vertex;
  /// for each output tetrahedron, its index in the input (its label, if any, is the input's)
  std::vector<std::size_t> input_tetrahedron;
  Simplification_statistics statistics;
};

/// \ingroup PkgPRStarOctreeRef
/// The three conditions of a half-edge collapse, evaluated independently (see `check_half_edge_collapse()`).
struct Collapse_check {
  bool edge_exists = false; ///< the two vertices span an edge of the mesh
  bool boundary = false;    ///< both ends interior, or both on the boundary with a boundary edge
  bool geometry = false;    ///< no tetrahedron of `St(v2) - St(e)` flips or becomes flat (exact)
  bool link = false;        ///< `Lk(v1) ∩ Lk(v2) = Lk(e)` (boundary coned to a dummy vertex)
  bool allowed() const { return edge_exists && boundary && geometry && link; }
};

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_SIMPLIFICATION_STATISTICS_H
