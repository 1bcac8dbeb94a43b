// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_LEAF_EXECUTOR_H
#define CGAL_PR_STAR_OCTREE_LEAF_EXECUTOR_H

/// \file Leaf_executor.h
/// The leaf executor: the one place that knows how the leaves of a PR-star octree are scheduled.
/// Every leaf-streaming algorithm of the package (boundary, distortion and curvature, validity,
/// `count_simplices()`, the rounds of `simplify()`) runs its per-leaf work through it.

#include <CGAL/PR_star_octree/Leaf_topology.h>
#include <CGAL/PR_star_octree/internal/concurrency.h>
#include <CGAL/PR_star_octree/internal/repeat_counter.h>
#include <CGAL/PR_star_octree/parameters.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <mutex>
#include <type_traits>
#include <utility>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>
#endif

namespace CGAL {
namespace PR_star_octree {

namespace internal {

// A progress callback that does nothing.
struct No_progress {
  void operator()(std::size_t, std::size_t) const {}
};

// A stop predicate that never stops.
struct Never_stop {
  bool operator()() const { return false; }
};

} // namespace internal

/// \ingroup PkgPRStarOctreeRef
/// A contiguous part of the leaves of an octree: the leaves at positions `[first, last)` of
/// `PR_star_octree_3::leaves()` (depth-first order, so a part is a union of whole subtrees' leaves
/// and owns a contiguous range of vertices).  `last` is clamped to the number of leaves.
struct Leaf_range {
  std::size_t first = 0;                                        ///< the first leaf position
  std::size_t last = (std::numeric_limits<std::size_t>::max)(); ///< one past the last leaf position
};

/// \ingroup PkgPRStarOctreeRef
///
/// Runs a per-leaf function over the leaves of a `PR_star_octree_3`: for each leaf, in depth-first
/// order, builds the local relations a leaf function asks for (`Relations`, vertex links included),
/// calls the function with a per-thread state and the leaf's `Leaf_topology`, and hands what it
/// returned to a reduction, called one leaf at a time **in leaf order**.  So a reduction sees the
/// same sequence of leaf results whatever the thread count, and an algorithm built on it gives
/// identical results, bit for bit, with `CGAL::Sequential_tag` and `CGAL::Parallel_tag`.
///
/// With `CGAL::Parallel_tag` (and TBB), the leaves are processed by every thread of the current TBB
/// task arena in chunks of consecutive leaves, through a pipeline whose last stage (the reduction)
/// is serial and in order: only a bounded number of chunks is in flight, so the memory of the leaf
/// results waiting to be reduced does not grow with the mesh.  Each thread owns one `Leaf_topology`
/// (its buffers reused from leaf to leaf) and one copy of the state.
///
/// The executor covers a `Leaf_range` of the leaves (all of them by default): the part of a
/// partition of the leaves that this process or rank runs.  It is the only place of the package
/// that knows how leaves are scheduled; another executor (over MPI ranks, say) provides the same
/// `for_each()` and `map_reduce()`.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` (needs TBB) or
///         `CGAL::Parallel_if_available_tag` (parallel when TBB is linked)
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag>
class Leaf_executor {
public:
  /// the concurrency tag
  using Concurrency_tag = ConcurrencyTag;

  /// an executor over all the leaves
  Leaf_executor() = default;
  /// an executor over the leaves `range` only
  explicit Leaf_executor(Leaf_range range) : range_(range) {}

  /// the leaves it runs over
  Leaf_range leaf_range() const { return range_; }
  /// whether the leaves are processed by several threads
  static constexpr bool is_parallel() { return internal::is_parallel<ConcurrencyTag>(); }

  /// Calls `f(state, leaf)` for each leaf of the range, where `leaf` is a
  /// `const Leaf_topology<Octree>&` holding the relations `relations` of that leaf and `state` is
  /// the calling thread's copy of `state_prototype` (`State` must be copy-constructible); `f`
  /// returns a leaf result `R` (movable).  Then calls `reduce(std::move(r))` with each leaf's result
  /// `r`, one at a time, in leaf order, and `progress(done, total)` after each leaf (`done` never
  /// decreases; `total` is the number of leaves of the range).
  ///
  /// `stop()` (optional) is asked before each leaf is started (sequentially; in parallel, before
  /// each chunk of leaves): once it returns `true`, no further leaf is started, and the leaves
  /// already started are finished and reduced.  In parallel, `stop()`, the reduction and `progress`
  /// may each be called from any thread (never two calls of the same one at once).
  template <class Octree, class State, class LeafFunction, class Reduce,
            class Progress = internal::No_progress, class Stop = internal::Never_stop>
  void map_reduce(const Octree& tree, unsigned relations, const State& state_prototype, LeafFunction&& f,
                  Reduce&& reduce, const Progress& progress = Progress(), const Stop& stop = Stop()) const {
    run(tree, relations, state_prototype, f, &reduce, progress, stop);
  }

  /// Calls `f(state, leaf)` for each leaf of the range, as `map_reduce()` but with no leaf result
  /// (`f` returns `void`).  With `CGAL::Parallel_tag`, `f` is called from several threads at once:
  /// it may write only to places no other leaf writes (its own vertices, say).
  template <class Octree, class State, class LeafFunction, class Progress = internal::No_progress,
            class Stop = internal::Never_stop>
  void for_each(const Octree& tree, unsigned relations, const State& state_prototype, LeafFunction&& f,
                const Progress& progress = Progress(), const Stop& stop = Stop()) const {
    run(tree, relations, state_prototype, f, static_cast<internal::No_progress*>(nullptr), progress, stop);
  }

private:
  // `reduce` is null for `for_each()`.
  template <class Octree, class State, class LeafFunction, class Reduce, class Progress, class Stop>
  void run(const Octree& tree, unsigned relations, const State& prototype, LeafFunction& f, Reduce* reduce,
           const Progress& progress, const Stop& stop) const {
    using Local = Leaf_topology<Octree>;
    using Result = decltype(f(std::declval<State&>(), std::declval<const Local&>()));
    constexpr bool has_result = !std::is_void<Result>::value;
    const auto& leaves = tree.leaves();
    const std::size_t last = (std::min)(range_.last, leaves.size());
    const std::size_t first = (std::min)(range_.first, last);
    const std::size_t total = last - first;
    if constexpr (is_parallel()) {
#ifdef CGAL_LINKED_WITH_TBB
      struct Thread_data {
        Local local;
        State state;
      };
      tbb::enumerable_thread_specific<Thread_data> data([&] { return Thread_data{Local(), prototype}; });
      // Chunks of consecutive leaves: about 64 per thread, each at most 64 leaves; a few per thread in
      // flight.
      const std::size_t threads =
          static_cast<std::size_t>((std::max)(1, tbb::this_task_arena::max_concurrency()));
      const std::size_t chunk =
          (std::max<std::size_t>)(1, (std::min<std::size_t>)(64, total / (64 * threads)));
      const std::size_t tokens = 4 * threads;
      struct Chunk {
        std::size_t begin = 0, end = 0;
        std::vector<std::conditional_t<has_result, Result, char>> results;
      };
      std::vector<Chunk> pool(tokens);
      std::vector<Chunk*> free_chunks;
      for (Chunk& c : pool) free_chunks.push_back(&c);
      std::mutex free_mutex;
      std::size_t next = first, done = 0;
      tbb::parallel_pipeline(
          tokens,
          tbb::make_filter<void,
                           Chunk*>(tbb::filter_mode::serial_in_order, [&](tbb::flow_control& fc) -> Chunk* {
            if (next == last || stop()) {
              fc.stop();
              return nullptr;
            }
            Chunk* c;
            {
              std::lock_guard<std::mutex> lock(free_mutex);
              c = free_chunks.back();
              free_chunks.pop_back();
            }
            c->begin = next;
            c->end = next = (std::min)(last, next + chunk);
            return c;
          }) & tbb::make_filter<Chunk*, Chunk*>(tbb::filter_mode::parallel, [&](Chunk* c) {
            Thread_data& d = data.local();
            c->results.clear();
            for (std::size_t i = c->begin; i != c->end; ++i) {
              d.local.build(tree, leaves[i], relations);
              if constexpr (has_result)
                c->results.push_back(f(d.state, static_cast<const Local&>(d.local)));
              else
                f(d.state, static_cast<const Local&>(d.local));
            }
            return c;
          }) & tbb::make_filter<Chunk*, void>(tbb::filter_mode::serial_in_order, [&](Chunk* c) {
            for (std::size_t i = c->begin; i != c->end; ++i) {
              if constexpr (has_result) (*reduce)(std::move(c->results[i - c->begin]));
              progress(++done, total);
            }
            if constexpr (has_result) c->results.clear();
            std::lock_guard<std::mutex> lock(free_mutex);
            free_chunks.push_back(c);
          }));
#endif
    } else {
      Local local;
      State state = prototype;
      for (std::size_t i = first; i != last && !stop(); ++i) {
        local.build(tree, leaves[i], relations);
        if constexpr (has_result)
          (*reduce)(f(state, static_cast<const Local&>(local)));
        else
          f(state, static_cast<const Local&>(local));
        progress(i - first + 1, total);
      }
    }
    (void)reduce;
  }

  Leaf_range range_;
};

/// \ingroup PkgPRStarOctreeRef
/// Streams over the leaves of `tree` in depth-first order: for each leaf, builds the local
/// relations `relations` (a combination of `Relations`), calls `f(const Leaf_topology<Octree>&)`,
/// and discards them (the buffers are reused for the next leaf).  A shorthand for
/// `Leaf_executor<ConcurrencyTag>().for_each()` with no state.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (the default: `f` is called from the calling
///         thread, leaf after leaf), `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag` (`f`
///         is called from several threads at once)
/// \param tree the octree
/// \param relations the relations to build (a combination of `Relations`)
/// \param f called with each leaf's `Leaf_topology`
/// \param np an optional sequence of named parameters among the ones
///        listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{progress}
///     \cgalParamDescription{called as `F(done, total)` after each leaf}
///     \cgalParamType{a callable `F(std::size_t, std::size_t)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class ConcurrencyTag = CGAL::Sequential_tag, class GT, class I, class Function,
          class NP = parameters::Default_named_parameters>
void for_each_leaf(const PR_star_octree_3<GT, I>& tree, unsigned relations, Function&& f,
                   const NP& np = parameters::default_values()) {
  using Local = Leaf_topology<PR_star_octree_3<GT, I>>;
  Leaf_executor<ConcurrencyTag>().for_each(
      tree, relations, 0, [&f](int, const Local& local) { f(local); }, internal::Progress_reporter<NP>(np));
}

/// \ingroup PkgPRStarOctreeRef
/// The relations `count_simplices()` builds in each leaf (what to size an automatic k_v for).
constexpr unsigned count_simplices_relations = VERTEX_TETRAHEDRA;

/// \ingroup PkgPRStarOctreeRef
/// Counts vertices, edges, triangles (and boundary triangles) and tetrahedra by streaming over the
/// leaves: each simplex is counted by the leaf owning its smallest vertex, from that vertex's star
/// (the relation VT only: the edges and triangles are not built).
/// \tparam ConcurrencyTag `CGAL::Parallel_tag`, `CGAL::Sequential_tag` or the default
///         `CGAL::Parallel_if_available_tag` (the same counts either way)
/// \param tree the octree
/// \param np an optional sequence of named parameters among the ones
///        listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{progress}
///     \cgalParamDescription{called as `F(done, total)` after each leaf}
///     \cgalParamType{a callable `F(std::size_t, std::size_t)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class GT, class I,
          class NP = parameters::Default_named_parameters>
Simplex_counts count_simplices(const PR_star_octree_3<GT, I>& tree,
                               const NP& np = parameters::default_values()) {
  using Local = Leaf_topology<PR_star_octree_3<GT, I>>;
  using Index = typename PR_star_octree_3<GT, I>::Index;
  Simplex_counts s;
  s.tetrahedra = tree.number_of_tetrahedra();
  // A triangle (v, a, b), a < b, as one 64-bit integer where indices have 32 bits, else as the pair.
  using Triangle_key = std::conditional_t<(sizeof(Index) <= 4), std::uint64_t, std::pair<Index, Index>>;
  const auto triangle_key = [](Index a, Index b) {
    if constexpr (sizeof(Index) <= 4)
      return (std::uint64_t(a) << 32) | std::uint64_t(b);
    else
      return std::make_pair(a, b);
  };
  // For each vertex v of the leaf, the edges (v, w) and triangles (v, a, b) with v the smallest
  // vertex are exactly those of the tetrahedra of v's star whose other vertices are greater than v:
  // listed from the star into hash tables, each distinct edge is counted once, and a triangle's
  // number of insertions is its number of tetrahedra (1: on the boundary, 3 or more:
  // non-manifold).  VT holds a fifth of the bytes per tetrahedron of the triangles
  // (bench_bucket_size --calibrate).
  Leaf_executor<ConcurrencyTag>().map_reduce(
      tree, count_simplices_relations, 0,
      [&triangle_key](int, const Local& local) {
        Simplex_counts c;
        internal::Repeat_counter<Index> edges;
        internal::Repeat_counter<Triangle_key> triangles;
        for (Index v = local.vertex_begin(); v < local.vertex_end(); ++v) {
          const auto star = local.vertex_tetrahedra(v);
          const auto n = static_cast<std::size_t>(std::distance(star.begin(), star.end()));
          if (n == 0) continue;
          ++c.vertices;
          edges.clear(3 * n); // at most three of each per tetrahedron
          triangles.clear(3 * n);
          std::size_t shared = 0; // triangles of two tetrahedra or more
          for (Index t : star) {
            const auto& q = local.tetrahedron(t);
            Index o[3];
            int m = 0;
            for (int k = 0; k < 4; ++k)
              if (q[k] > v) o[m++] = q[k];
            for (int i = 0; i < m; ++i) {
              edges.insert(o[i]);
              for (int j = i + 1; j < m; ++j) {
                const std::size_t r =
                    triangles.insert(triangle_key((std::min)(o[i], o[j]), (std::max)(o[i], o[j])));
                shared += (r == 2);
                c.nonmanifold_triangles += (r == 3);
              }
            }
          }
          c.edges += edges.distinct();
          c.triangles += triangles.distinct();
          c.boundary_triangles += triangles.distinct() - shared;
        }
        return c;
      },
      [&s](Simplex_counts&& c) {
        s.vertices += c.vertices;
        s.edges += c.edges;
        s.triangles += c.triangles;
        s.boundary_triangles += c.boundary_triangles;
        s.nonmanifold_triangles += c.nonmanifold_triangles;
      },
      internal::Progress_reporter<NP>(np));
  return s;
}

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_LEAF_EXECUTOR_H
