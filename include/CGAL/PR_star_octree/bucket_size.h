// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_BUCKET_SIZE_H
#define CGAL_PR_STAR_OCTREE_BUCKET_SIZE_H

/// \file bucket_size.h
/// The automatic bucket threshold k_v: chosen from the mesh, the relations the leaves will build and
/// the cache of the machine by a cost model measured on real meshes (`choose_bucket_size()`).

#include <CGAL/PR_star_octree/Relations.h>

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>

#if defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#endif

namespace CGAL {
namespace PR_star_octree {

/// \ingroup PkgPRStarOctreeRef
/// The value of the named parameter `bucket_size` that asks the octree to choose k_v itself with
/// `choose_bucket_size()` (the default of the `PR_star_octree_3` constructors).
constexpr std::size_t automatic_bucket_size = (std::numeric_limits<std::size_t>::max)() - 1;

/// \ingroup PkgPRStarOctreeRef
/// A bucket threshold chosen by `choose_bucket_size()` and what it was chosen from.
struct Bucket_size_choice {
  std::size_t bucket_size = 0;           ///< the chosen k_v
  std::size_t cache_bytes = 0;           ///< the per-core cache the leaves are sized for
  unsigned relations = 0;                ///< the relations the leaves were sized for (`Relations`)
  double tetrahedra_per_vertex = 0;      ///< |T| / |V| of the mesh
  double leaf_bytes_per_tetrahedron = 0; ///< the model's working set per listed tetrahedron
  double estimated_leaf_bytes = 0;       ///< the model's working set of a full leaf at the chosen k_v
  bool limited_by_mesh_size = false;     ///< k_v was lowered to keep enough leaves for the threads
};

/// \ingroup PkgPRStarOctreeRef
/// The size of the cache a leaf's relations should fit in: the level-2 cache of one core, as the
/// operating system reports it (`sysconf(_SC_LEVEL2_CACHE_SIZE)`, else
/// `/sys/devices/system/cpu/cpu0/cache/index2/size`), 1 MiB when it reports nothing.  The environment
/// variable `PRSTAR_CACHE_BYTES` overrides it (a positive number of bytes).
inline std::size_t cache_bytes_per_core() {
  if (const char* env = std::getenv("PRSTAR_CACHE_BYTES")) {
    char* end = nullptr;
    const unsigned long long v = std::strtoull(env, &end, 10);
    if (end != env && *end == '\0' && v > 0) return static_cast<std::size_t>(v);
  }
#if defined(_SC_LEVEL2_CACHE_SIZE)
  const long s = ::sysconf(_SC_LEVEL2_CACHE_SIZE);
  if (s > 0) return static_cast<std::size_t>(s);
#endif
  std::ifstream f("/sys/devices/system/cpu/cpu0/cache/index2/size");
  std::string text;
  if (f >> text && !text.empty()) {
    std::size_t v = 0, i = 0;
    for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i) v = 10 * v + std::size_t(text[i] - '0');
    const char unit = i < text.size() ? text[i] : ' ';
    if (unit == 'K') v <<= 10;
    if (unit == 'M') v <<= 20;
    if (v > 0) return v;
  }
  return std::size_t(1) << 20;
}

namespace internal {

// The model's working set of a leaf per tetrahedron of its list, for each relation: the bytes held by
// `Leaf_topology` after building that relation alone for the leaf listing the most tetrahedra, per
// listed tetrahedron (`bench_bucket_size --calibrate` at k_v = 256, 1024, 4096 on a Mesh_3 torus, a
// TetGen torus, a TetGen fandisk and a lattice: the largest value over the twelve, rounded up;
// benchmark/PR_star_octree/results/bucket_size.md).
inline double leaf_bytes_per_tetrahedron(unsigned relations) {
  // VT, TT, VV, edges, triangles, links, local tetrahedra
  constexpr double bytes[7] = {47, 166, 61, 246, 240, 109, 124};
  double b = 0;
  for (int i = 0; i < 7; ++i)
    if (relations & (1u << i)) b += bytes[i];
  return b;
}

} // namespace internal

/// \ingroup PkgPRStarOctreeRef
/// The relations the automatic k_v is sized for when nothing says which: the boundary's and the
/// validity check's (links and triangles).
constexpr unsigned default_bucket_size_relations = VERTEX_LINKS | TRIANGLES;

/// \ingroup PkgPRStarOctreeRef
/// Chooses the bucket threshold k_v of a mesh of `number_of_vertices` vertices and
/// `number_of_tetrahedra` tetrahedra whose leaves will build `relations` (a combination of
/// `Relations`).
///
/// The cost model, measured with `bench_bucket_size` on Mesh_3, TetGen and lattice meshes of 0.5M to
/// 3M tetrahedra (benchmark/PR_star_octree/results/bucket_size.md): the time of a leaf-streaming
/// application falls as k_v grows, because fewer tetrahedra are listed in several leaves (chi falls)
/// and fewer leaves are set up, until a leaf's relations outgrow the caches, where it rises again;
/// on a core with 1 MiB of level-2 cache the turn comes when a leaf's relations hold about 8 to 15 MB.
/// So k_v is the largest power of two whose full leaf is estimated to hold at most 8 times
/// `cache_bytes`: a full leaf lists at most about 1.5 |T| / |V| tetrahedra per vertex of k_v
/// (measured 0.4 to 1.5), each costing the bytes per listed tetrahedron of the relations built
/// (`Bucket_size_choice::leaf_bytes_per_tetrahedron`: 47 for VT, 246 for the edges, ...).  k_v is
/// kept within [64, 4096], and at most |V| / 16 (rounded down to a power of two, at least 64) so
/// that a small mesh still has leaves for several threads.
///
/// \param number_of_vertices |V|
/// \param number_of_tetrahedra |T|
/// \param relations the relations the leaves will build (a combination of `Relations`; 0 or none of them:
///        `default_bucket_size_relations`)
/// \param cache_bytes the cache to size the leaves for; 0 for `cache_bytes_per_core()`
inline Bucket_size_choice choose_bucket_size(std::size_t number_of_vertices, std::size_t number_of_tetrahedra,
                                             unsigned relations = default_bucket_size_relations,
                                             std::size_t cache_bytes = 0) {
  constexpr std::size_t min_bucket_size = 64, max_bucket_size = 4096;
  constexpr double cache_factor = 8;
  constexpr double leaf_tetrahedra_per_vertex = 1.5;
  Bucket_size_choice c;
  c.cache_bytes = cache_bytes ? cache_bytes : cache_bytes_per_core();
  c.relations = relations & unsigned(ALL_RELATIONS);
  if (c.relations == 0) c.relations = default_bucket_size_relations;
  c.tetrahedra_per_vertex =
      number_of_vertices ? double(number_of_tetrahedra) / double(number_of_vertices) : 0.;
  c.leaf_bytes_per_tetrahedron = internal::leaf_bytes_per_tetrahedron(c.relations);
  const double per_vertex =
      (std::max)(1., leaf_tetrahedra_per_vertex * c.tetrahedra_per_vertex * c.leaf_bytes_per_tetrahedron);
  std::size_t k = min_bucket_size;
  while (2 * k <= max_bucket_size && double(2 * k) * per_vertex <= cache_factor * double(c.cache_bytes))
    k *= 2;
  std::size_t cap = min_bucket_size;
  while (2 * cap <= number_of_vertices / 16) cap *= 2;
  if (cap < k) {
    k = cap;
    c.limited_by_mesh_size = true;
  }
  c.bucket_size = k;
  c.estimated_leaf_bytes = double(k) * per_vertex;
  return c;
}

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_BUCKET_SIZE_H
