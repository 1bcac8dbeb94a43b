// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_REPEAT_COUNTER_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_REPEAT_COUNTER_H

// How many times each key was inserted since the last `clear()`: a hash table with open addressing
// and linear probing, kept at most half full.  Each slot carries the generation in which it was
// written, so that `clear()` does not touch the slots.  Used per vertex by `count_simplices()`
// (a few dozen keys each time), where sorting the keys took three times as long.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

template <class Key>
class Repeat_counter {
public:
  // Empties the table and makes room for up to `n` distinct keys.
  void clear(std::size_t n) {
    unsigned bits = 6;
    while ((std::size_t(1) << bits) < 2 * n) ++bits;
    if ((std::size_t(1) << bits) > keys_.size()) {
      keys_.assign(std::size_t(1) << bits, Key());
      counts_.assign(keys_.size(), 0);
      stamps_.assign(keys_.size(), 0);
      generation_ = 0;
    }
    shift_ = 64 - bits;
    mask_ = (std::size_t(1) << bits) - 1;
    if (++generation_ == 0) { // wrapped around: the stamps are cleared once in 2^32 calls
      std::fill(stamps_.begin(), stamps_.end(), 0u);
      generation_ = 1;
    }
    distinct_ = 0;
  }
  // Inserts `k`; returns how many times it has been inserted since `clear()`, this one included.
  // \pre at most `n` distinct keys since `clear(n)`
  std::size_t insert(const Key& k) {
    std::size_t i = static_cast<std::size_t>((hash(k) * 0x9E3779B97F4A7C15ull) >> shift_);
    while (stamps_[i] == generation_) {
      if (keys_[i] == k) return ++counts_[i];
      i = (i + 1) & mask_;
    }
    stamps_[i] = generation_;
    keys_[i] = k;
    counts_[i] = 1;
    ++distinct_;
    return 1;
  }
  // the number of distinct keys inserted since `clear()`
  std::size_t distinct() const { return distinct_; }

private:
  template <class T>
  static std::uint64_t hash(const T& k) {
    return static_cast<std::uint64_t>(k);
  }
  template <class A, class B>
  static std::uint64_t hash(const std::pair<A, B>& k) {
    return static_cast<std::uint64_t>(k.first) * 0x100000001B3ull ^ static_cast<std::uint64_t>(k.second);
  }

  std::vector<Key> keys_;
  std::vector<std::size_t> counts_;
  std::vector<std::uint32_t> stamps_;
  std::uint32_t generation_ = 0;
  unsigned shift_ = 64;
  std::size_t mask_ = 0;
  std::size_t distinct_ = 0;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_REPEAT_COUNTER_H
