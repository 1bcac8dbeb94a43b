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
/// The order in which `simplify()` collapses its candidate edges.
enum class Collapse_priority {
  EDGE_LENGTH,  ///< shortest edge first (or the `priority` functor given)
  QUADRIC_ERROR ///< smallest error first: the mean squared distance of the merged vertex to the planes of the
                ///< input surface triangles its ends stand for (Garland-Heckbert quadrics), then the shortest
};

/// \ingroup PkgPRStarOctreeRef
/// Where the vertex that survives a collapse goes.
enum class Collapse_placement {
  HALF_EDGE, ///< it stays where it is (one end is removed into the other)
  OPTIMAL    ///< at the point of the edge of smallest quadric error (the midpoint inside the volume), when
             ///< both ends are of the same stratum (both inside, or both on one smooth surface patch) and
             ///< that point passes every check; otherwise a half-edge collapse
};

/// \ingroup PkgPRStarOctreeRef
/// Why `simplify()` stopped.
enum class Simplification_stop {
  TARGET_REACHED, ///< the target fraction was removed
  NOTHING_LEFT,   ///< without a target: no edge under the length bound can be collapsed any more
  BLOCKED,        ///< before the target: a round removed nothing (see
                  ///< `Simplification_statistics::blocked_last_round`)
  MAX_ROUNDS      ///< before the target: the maximum number of rounds was reached
};

/// \ingroup PkgPRStarOctreeRef
/// The name of a `Simplification_stop` in lower case with underscores (`"target_reached"`,
/// `"nothing_left"`, `"blocked"`, `"max_rounds"`): what `prstar simplify --json` and the Python
/// module report.
inline const char* simplification_stop_name(Simplification_stop s) {
  switch (s) {
  case Simplification_stop::TARGET_REACHED:
    return "target_reached";
  case Simplification_stop::NOTHING_LEFT:
    return "nothing_left";
  case Simplification_stop::BLOCKED:
    return "blocked";
  case Simplification_stop::MAX_ROUNDS:
    return "max_rounds";
  }
  return "";
}

/// \ingroup PkgPRStarOctreeRef
/// Why `simplify()` did not collapse a candidate edge: the first check its preferred collapse failed
/// (what a collapse filter returns, and what a simplification visitor is told).
enum class Collapse_refusal {
  NONE,             ///< not refused: the collapse is done
  DIFFERENT_LEAVES, ///< only the end in another leaf could be removed
  FEATURE,          ///< a corner, or a feature vertex not moving along its feature curve
  BOUNDARY,         ///< a surface vertex not moving along the surface, or a non-manifold end
  FLIP,             ///< a tetrahedron would flip or become flat
  LINK,             ///< the link condition (of the volume, of the surface or of the feature curves)
  QUALITY,          ///< the quality floor
  ERROR,            ///< the bound on the distance to the input surface
  FILTER            ///< any other reason of a user's collapse filter
};

/// \ingroup PkgPRStarOctreeRef
/// What a run of `simplify()` did.
struct Simplification_statistics {
  std::size_t input_vertices = 0, output_vertices = 0;
  std::size_t input_tetrahedra = 0, output_tetrahedra = 0;
  std::size_t removed_tetrahedra =
      0; ///< tetrahedra deleted by the collapses (see `Optimization` for the others)
  std::size_t collapses = 0;
  std::size_t rounds = 0;                     ///< rounds of (local simplification, compaction, rebuild)
  std::vector<std::size_t> removed_per_round; ///< tetrahedra removed by each round
  std::size_t max_queue_size =
      0;              ///< the largest queue, over all leaves and rounds (the memory proxy of Table 3)
  double seconds = 0; ///< wall-clock time of the whole run, octree builds included
  /// candidate edges (shorter than the round's threshold) that were not collapsed, by reason; a
  /// candidate is counted under the first check its preferred collapse fails
  struct Blocked {
    std::size_t different_leaves = 0; ///< only the end in another leaf could be removed
    std::size_t boundary =
        0; ///< boundary condition: a surface vertex not moving along the surface, or a non-manifold end
    std::size_t flip = 0;    ///< geometric condition: a tetrahedron would flip or become flat
    std::size_t link = 0;    ///< link condition (of the volume, of the surface or of the feature curves)
    std::size_t feature = 0; ///< a corner, or a feature vertex not moving along its feature curve
    std::size_t quality = 0; ///< the quality floor
    std::size_t error = 0;   ///< the bound on the distance to the input surface
    std::size_t filter = 0;  ///< a user's collapse filter (`Collapse_refusal::FILTER`)
  } blocked;
  Blocked blocked_last_round; ///< the same counts in the last round (what stopped a `BLOCKED` run)
  /// What the optimisation passes (smoothing and flips) and the refinement (edge splits, `remesh()`)
  /// did, over all rounds; a refused move, flip or split is counted under the first check it failed
  /// (`flip`: a tetrahedron would flip or become flat, exact `Orientation_3`; `quality`: the worst
  /// tetrahedron of the region would not get better, or a floor would be crossed; `error`: the bound
  /// on the distance to the input surface, or a new crease; `link`: the new edge exists already).
  struct Optimization {
    std::size_t vertex_moves = 0;  ///< vertices moved by smoothing (interior, on the surface, along curves)
    std::size_t flips_2_3 = 0;     ///< triangles shared by two tetrahedra replaced by an edge in three
    std::size_t flips_3_2 = 0;     ///< edges in three tetrahedra removed (three tetrahedra become two)
    std::size_t flips_4_4 = 0;     ///< edges in four tetrahedra replaced by the other diagonal
    std::size_t edge_removals = 0; ///< edges in five to seven tetrahedra removed (2n - 4 new tetrahedra)
    std::size_t splits = 0;        ///< edges split at their midpoint (`remesh()`)
    std::size_t rounds = 0;        ///< rounds of optimisation only (no collapse), after the simplification
    /// tetrahedra made and deleted by the flips and splits (the collapses delete `removed_tetrahedra`:
    /// the output has `input_tetrahedra - removed_tetrahedra + tetrahedra_added - tetrahedra_deleted`)
    std::size_t tetrahedra_added = 0, tetrahedra_deleted = 0;
    Blocked refused_moves, refused_flips, refused_splits; ///< the moves, flips and splits not made
  } optimization;
  Simplification_stop stop = Simplification_stop::NOTHING_LEFT; ///< why it stopped
  double max_boundary_error = 0; ///< the bound used on the distance to the input surface (infinity: none)
};

/// \ingroup PkgPRStarOctreeRef
/// The simplified mesh and where its vertices come from.
template <class Point_3>
struct Simplification_result {
  /// positively oriented tetrahedra; the point data of the input (its scalar field) and its
  /// tetrahedron labels carried along
  Indexed_tetrahedral_mesh<Point_3> mesh;
  /// for each output vertex, the input vertex it stands for (its position too, unless the optimal placement
  /// moved it)
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
