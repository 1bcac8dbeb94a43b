// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_STATISTICS_H
#define CGAL_PR_STAR_OCTREE_STATISTICS_H

#include <CGAL/PR_star_octree/bucket_size.h>

#include <cstddef>
#include <map>

namespace CGAL {
namespace PR_star_octree {

/// \ingroup PkgPRStarOctreeRef
/// Bytes really used by a `PR_star_octree_3` (vector capacities times element sizes).
struct Memory_bytes {
  std::size_t points = 0;          ///< V: coordinates
  std::size_t scalars = 0;         ///< V: the optional scalar field
  std::size_t labels = 0;          ///< T: the optional tetrahedron labels
  std::size_t tetrahedra = 0;      ///< T: four indices per tetrahedron
  std::size_t nodes = 0;           ///< N: the octree nodes and the list of leaves
  std::size_t leaf_tetrahedra = 0; ///< the shared parts of the leaf lists: (chi - 1) |T| indices
  std::size_t permutations = 0;    ///< new -> original numbering of V and T (when kept)
  std::size_t reorientation = 0;   ///< one bit per tetrahedron: listed negatively oriented

  /// the topological overhead of the PR-star octree: nodes and leaf lists
  std::size_t index() const { return nodes + leaf_tetrahedra; }
  /// the indexed mesh it is built on: V and T
  std::size_t mesh() const { return points + scalars + tetrahedra + labels; }
  std::size_t total() const { return index() + mesh() + permutations + reorientation; }
  /// `total()` less the numbering permutations: what the same octree holds when built with
  /// `vertex_permutation(false)` and `tetrahedron_permutation(false)`, the configuration of
  /// `prstar stats`
  std::size_t without_permutations() const { return total() - permutations; }
};

/// \ingroup PkgPRStarOctreeRef
/// The storage statistics of paper Table 1, plus what the construction noticed about the mesh.
///
/// The cost model counts machine words, in multiples of |V| (paper Section 5):
/// - PR-star overhead `chi |T| + 7 |N|`, total `(4 + chi) |T| + 3 |V| + 7 |N|` (the paper's model,
///   with full leaf lists; `bytes` is what this implementation really holds);
/// - extended IA overhead `4 |T| + |V|`, total `8 |T| + 4 |V|`.
struct Statistics {
  std::size_t vertices = 0;
  std::size_t tetrahedra = 0;
  std::size_t bucket_size = 0;           ///< k_v
  bool infinite_bucket_size = false;     ///< k_v = infinity (a single leaf)
  bool automatic_bucket_size = false;    ///< k_v was chosen by the octree (see `bucket_size_choice`)
  Bucket_size_choice bucket_size_choice; ///< what the automatic k_v was chosen from
  std::size_t max_depth = 0;             ///< the depth bound
  std::size_t nodes = 0;                 ///< |N|
  std::size_t leaves = 0;                ///< |N_leaf|
  std::size_t empty_leaves = 0;
  std::size_t depth = 0;
  std::size_t max_leaf_vertices = 0;
  std::size_t max_leaf_tetrahedra = 0;
  std::size_t leaf_tetrahedra_entries = 0; ///< sum of the leaf list sizes, owned ranges included = chi |T|
  double chi = 0;                          ///< average number of leaves per tetrahedron

  std::size_t depth_limited_leaves = 0;  ///< leaves over k_v because the depth bound was reached
  std::size_t coincident_leaves = 0;     ///< leaves over k_v because all their points coincide
  std::size_t duplicate_vertices = 0;    ///< vertices at the same position as an earlier one
  std::size_t unreferenced_vertices = 0; ///< vertices in no tetrahedron
  std::size_t reoriented_tetrahedra = 0; ///< negatively oriented as listed (fixed internally)
  std::size_t degenerate_tetrahedra = 0; ///< zero volume (exact orientation test)

  double prstar_overhead_per_vertex = 0;
  double prstar_total_per_vertex = 0;
  double ia_overhead_per_vertex = 0;
  double ia_total_per_vertex = 0;

  Memory_bytes bytes;
  bool float32_coordinates = false; ///< the coordinates are stored as 32-bit floats (`Coordinate_precision`)
  bool compact_tetrahedra =
      false; ///< the tetrahedra are stored compactly (named parameter `compact_tetrahedra`)
  /// the bytes held per tetrahedron (`bytes.total() / tetrahedra`; 0 without tetrahedra): the one
  /// figure of compactness that `prstar stats` and the benchmarks report
  double bytes_per_tetrahedron() const {
    return tetrahedra ? static_cast<double>(bytes.total()) / static_cast<double>(tetrahedra) : 0.;
  }
  /// `bytes.without_permutations() / tetrahedra` (0 without tetrahedra): the figure of
  /// `bytes_per_tetrahedron()` for the octree without its numbering permutations, which
  /// `prstar stats` and the benchmarks report whatever permutations the structure measured kept
  double bytes_per_tetrahedron_without_permutations() const {
    return tetrahedra ? static_cast<double>(bytes.without_permutations()) / static_cast<double>(tetrahedra)
                      : 0.;
  }

  /// the number of tetrahedra of each label (empty when the mesh has no labels)
  std::map<int, std::size_t> subdomains;

  /// fills `chi` and the four cost-model figures from the counts
  void compute_cost_model() {
    const double V = static_cast<double>(vertices), T = static_cast<double>(tetrahedra),
                 N = static_cast<double>(nodes);
    chi = tetrahedra ? static_cast<double>(leaf_tetrahedra_entries) / T : 0.;
    if (vertices == 0) return;
    prstar_overhead_per_vertex = (chi * T + 7 * N) / V;
    prstar_total_per_vertex = ((4 + chi) * T + 3 * V + 7 * N) / V;
    ia_overhead_per_vertex = (4 * T + V) / V;
    ia_total_per_vertex = (8 * T + 4 * V) / V;
  }
};

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_STATISTICS_H
