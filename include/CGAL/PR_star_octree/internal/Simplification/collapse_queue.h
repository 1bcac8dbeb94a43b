// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_COLLAPSE_QUEUE_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_COLLAPSE_QUEUE_H

// The priority queue of the candidate edges of a leaf: smallest cost first, ties broken by the
// vertex indices (so that the order is deterministic).

#include <cstddef>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

template <class Index>
class Collapse_queue {
public:
  struct Entry {
    double cost;
    Index a, b; // a < b
    bool operator>(const Entry& o) const {
      return cost > o.cost || (cost == o.cost && (a > o.a || (a == o.a && b > o.b)));
    }
  };

  void clear() { queue_ = Queue(); }
  bool empty() const { return queue_.empty(); }
  std::size_t size() const { return queue_.size(); }
  // The edge (a, b) with its cost (a and b in any order).
  void push(Index a, Index b, double cost) {
    if (b < a) std::swap(a, b);
    queue_.push(Entry{cost, a, b});
  }
  Entry pop() {
    const Entry e = queue_.top();
    queue_.pop();
    return e;
  }

private:
  using Queue = std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>>;
  Queue queue_;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_COLLAPSE_QUEUE_H
