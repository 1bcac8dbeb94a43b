// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_LEAF_TETRAHEDRA_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_LEAF_TETRAHEDRA_H

// The tetrahedra of a leaf, and the compact encoding of the listed (shared) ones.
//
// A leaf's shared tetrahedra are increasing indices owned by a few neighbouring leaves, so they
// come in clusters: the list is cut into groups, each a base index and entries stored as 16-bit
// offsets from it (a new group starts when an index is 65,536 or more past the base).  That is 2
// bytes per entry plus 8 per group instead of 4 per entry: on the lattice and TetGen meshes at
// k_v = 200, 1.8-1.9 bytes per tetrahedron instead of 3.2-3.3.

#include <CGAL/Iterator_range.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <utility>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

// A group of a leaf's shared list: the entries from the end of the previous group (or 0) to `end`
// (positions in the leaf's list) are `base + offset`.
template <class Index>
struct Leaf_list_group {
  Index base;
  Index end;
};

// A random-access iterator over the tetrahedra of a leaf: the `n_shared` encoded ones, then the
// owned range starting at `owned_begin`.  It holds everything it needs (not a pointer to a range
// object), so it outlives the range; it keeps the group of its position.
template <class Index>
class Leaf_tetrahedron_iterator {
public:
  using iterator_category = std::random_access_iterator_tag;
  using value_type = Index;
  using difference_type = std::ptrdiff_t;
  using pointer = const Index*;
  using reference = Index;
  using Group = Leaf_list_group<Index>;

  Leaf_tetrahedron_iterator() = default;
  Leaf_tetrahedron_iterator(const std::uint16_t* offsets, const Group* groups, std::size_t n_groups,
                            std::size_t n_shared, Index owned_begin, std::size_t i)
      : offsets_(offsets), groups_(groups), n_groups_(n_groups), n_shared_(n_shared),
        owned_begin_(owned_begin), i_(i), g_(find(i)) {}

  Index operator*() const {
    return i_ < n_shared_ ? static_cast<Index>(groups_[g_].base + offsets_[i_])
                          : static_cast<Index>(owned_begin_ + (i_ - n_shared_));
  }
  Index operator[](difference_type d) const { return *(*this + d); }
  Leaf_tetrahedron_iterator& operator++() {
    ++i_;
    while (g_ < n_groups_ && i_ >= groups_[g_].end) ++g_;
    return *this;
  }
  Leaf_tetrahedron_iterator operator++(int) {
    Leaf_tetrahedron_iterator c = *this;
    ++*this;
    return c;
  }
  Leaf_tetrahedron_iterator& operator--() {
    --i_;
    while (g_ > 0 && i_ < groups_[g_ - 1].end) --g_;
    return *this;
  }
  Leaf_tetrahedron_iterator operator--(int) {
    Leaf_tetrahedron_iterator c = *this;
    --*this;
    return c;
  }
  Leaf_tetrahedron_iterator& operator+=(difference_type d) {
    i_ = static_cast<std::size_t>(static_cast<difference_type>(i_) + d);
    g_ = find(i_);
    return *this;
  }
  Leaf_tetrahedron_iterator& operator-=(difference_type d) { return *this += -d; }
  friend Leaf_tetrahedron_iterator operator+(Leaf_tetrahedron_iterator a, difference_type d) {
    return a += d;
  }
  friend Leaf_tetrahedron_iterator operator+(difference_type d, Leaf_tetrahedron_iterator a) {
    return a += d;
  }
  friend Leaf_tetrahedron_iterator operator-(Leaf_tetrahedron_iterator a, difference_type d) {
    return a -= d;
  }
  friend difference_type operator-(const Leaf_tetrahedron_iterator& a, const Leaf_tetrahedron_iterator& b) {
    return static_cast<difference_type>(a.i_) - static_cast<difference_type>(b.i_);
  }
  friend bool operator==(const Leaf_tetrahedron_iterator& a, const Leaf_tetrahedron_iterator& b) {
    return a.i_ == b.i_;
  }
  friend bool operator!=(const Leaf_tetrahedron_iterator& a, const Leaf_tetrahedron_iterator& b) {
    return a.i_ != b.i_;
  }
  friend bool operator<(const Leaf_tetrahedron_iterator& a, const Leaf_tetrahedron_iterator& b) {
    return a.i_ < b.i_;
  }
  friend bool operator>(const Leaf_tetrahedron_iterator& a, const Leaf_tetrahedron_iterator& b) {
    return a.i_ > b.i_;
  }
  friend bool operator<=(const Leaf_tetrahedron_iterator& a, const Leaf_tetrahedron_iterator& b) {
    return a.i_ <= b.i_;
  }
  friend bool operator>=(const Leaf_tetrahedron_iterator& a, const Leaf_tetrahedron_iterator& b) {
    return a.i_ >= b.i_;
  }

private:
  // the group holding position i (n_groups past the shared part)
  std::size_t find(std::size_t i) const {
    if (i >= n_shared_) return n_groups_;
    return static_cast<std::size_t>(
        std::upper_bound(groups_, groups_ + n_groups_, i,
                         [](std::size_t x, const Group& g) { return x < g.end; }) -
        groups_);
  }

  const std::uint16_t* offsets_ = nullptr;
  const Group* groups_ = nullptr;
  std::size_t n_groups_ = 0, n_shared_ = 0;
  Index owned_begin_ = 0;
  std::size_t i_ = 0, g_ = 0;
};

// The tetrahedra of a leaf: the shared ones (encoded), then the owned range [first, second) of T.
template <class Index>
class Leaf_tetrahedra {
public:
  using iterator = Leaf_tetrahedron_iterator<Index>;
  using const_iterator = iterator;
  using Group = Leaf_list_group<Index>;

  Leaf_tetrahedra(const std::uint16_t* offsets, std::size_t n_shared, const Group* groups,
                  std::size_t n_groups, Index owned_begin, Index owned_end)
      : offsets_(offsets), groups_(groups), n_groups_(n_groups), n_shared_(n_shared),
        owned_begin_(owned_begin), size_(n_shared + (owned_end - owned_begin)) {}
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  Index operator[](std::size_t i) const { return begin()[static_cast<std::ptrdiff_t>(i)]; }
  iterator begin() const { return make(0); }
  iterator end() const { return make(size_); }
  // the listed (shared) part, in increasing order
  CGAL::Iterator_range<iterator> shared() const {
    return CGAL::Iterator_range<iterator>(make(0), make(n_shared_));
  }
  // the owned part: the tetrahedra [first, second) of T
  std::pair<Index, Index> owned() const {
    return {owned_begin_, static_cast<Index>(owned_begin_ + (size_ - n_shared_))};
  }

private:
  iterator make(std::size_t i) const {
    return iterator(offsets_, groups_, n_groups_, n_shared_, owned_begin_, i);
  }

  const std::uint16_t* offsets_;
  const Group* groups_;
  std::size_t n_groups_, n_shared_;
  Index owned_begin_;
  std::size_t size_;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_LEAF_TETRAHEDRA_H
