// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_PARALLEL_LEAVES_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_PARALLEL_LEAVES_H

// Leaf streaming with a concurrency tag: with `CGAL::Parallel_tag` (and TBB) the leaves are
// processed by several threads, each with its own local structure and its own copy of a per-thread
// state.  The callers keep their results identical to a sequential run: each leaf writes only its
// own slots (its vertices, its position in the list of leaves), and every reduction is done
// afterwards, in leaf order.

#include <CGAL/tags.h>

#include <atomic>
#include <cstddef>
#include <mutex>
#include <type_traits>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#endif

namespace CGAL {
namespace PR_star_octree {

template <class Octree>
class Leaf_topology; // Leaf_topology.h includes this header after defining it

namespace internal {

template <class ConcurrencyTag>
constexpr bool is_parallel() {
#ifdef CGAL_LINKED_WITH_TBB
  return std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;
#else
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "CGAL::Parallel_tag needs TBB: link CGAL::TBB_support, or use CGAL::Sequential_tag or "
                "CGAL::Parallel_if_available_tag");
  return false;
#endif
}

// Calls `f(state, local, i)` for the leaf `tree.leaves()[i]` of every i, `local` holding the
// relations `relations` of that leaf, `state` a per-thread copy of `prototype`; `progress(done,
// total)` is called after each leaf, from one thread at a time.
template <class ConcurrencyTag, class Octree, class State, class Function, class Progress>
void process_leaves(const Octree& tree, unsigned relations, const State& prototype, Function f,
                    const Progress& progress) {
  const auto& leaves = tree.leaves();
  const std::size_t total = leaves.size();
  if constexpr (is_parallel<ConcurrencyTag>()) {
#ifdef CGAL_LINKED_WITH_TBB
    struct Thread_data {
      Leaf_topology<Octree> local;
      State state;
    };
    tbb::enumerable_thread_specific<Thread_data> data([&] {
      return Thread_data{Leaf_topology<Octree>(), prototype};
    });
    std::atomic<std::size_t> done{0};
    std::size_t reported = 0;
    std::mutex progress_mutex;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, total),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        Thread_data& d = data.local();
                        for (std::size_t i = r.begin(); i != r.end(); ++i) {
                          d.local.build(tree, leaves[i], relations);
                          f(d.state, static_cast<const Leaf_topology<Octree>&>(d.local), i);
                          const std::size_t n = ++done;
                          std::lock_guard<std::mutex> lock(progress_mutex);
                          if (n > reported) { // never backwards
                            reported = n;
                            progress(n, total);
                          }
                        }
                      });
#endif
  } else {
    Leaf_topology<Octree> local;
    State state = prototype;
    for (std::size_t i = 0; i < total; ++i) {
      local.build(tree, leaves[i], relations);
      f(state, static_cast<const Leaf_topology<Octree>&>(local), i);
      progress(i + 1, total);
    }
  }
}

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_PARALLEL_LEAVES_H
