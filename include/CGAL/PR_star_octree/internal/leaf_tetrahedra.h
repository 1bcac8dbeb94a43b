// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_LEAF_TETRAHEDRA_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_LEAF_TETRAHEDRA_H

#include <CGAL/Iterator_range.h>

#include <cstddef>
#include <iterator>
#include <utility>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

// The tetrahedra of a leaf: `n_shared` listed indices, then the contiguous range
// [owned_begin, owned_begin + size - n_shared).  The iterators hold everything they need (not a
// pointer to the range object), so they outlive the range.
template <class Index>
class Leaf_tetrahedra {
public:
  class iterator {
  public:
    using iterator_category = std::random_access_iterator_tag;
    using value_type = Index;
    using difference_type = std::ptrdiff_t;
    using pointer = const Index*;
    using reference = Index;
    iterator() = default;
    iterator(const Index* shared, std::size_t n_shared, Index owned_begin, std::size_t i)
        : shared_(shared), n_shared_(n_shared), owned_begin_(owned_begin), i_(i) {}
    Index operator*() const { return at(i_); }
    Index operator[](difference_type d) const { return at(i_ + d); }
    iterator& operator++() {
      ++i_;
      return *this;
    }
    iterator operator++(int) {
      iterator c = *this;
      ++i_;
      return c;
    }
    iterator& operator--() {
      --i_;
      return *this;
    }
    iterator operator--(int) {
      iterator c = *this;
      --i_;
      return c;
    }
    iterator& operator+=(difference_type d) {
      i_ += d;
      return *this;
    }
    iterator& operator-=(difference_type d) {
      i_ -= d;
      return *this;
    }
    friend iterator operator+(iterator a, difference_type d) { return a += d; }
    friend iterator operator+(difference_type d, iterator a) { return a += d; }
    friend iterator operator-(iterator a, difference_type d) { return a -= d; }
    friend difference_type operator-(const iterator& a, const iterator& b) {
      return static_cast<difference_type>(a.i_) - static_cast<difference_type>(b.i_);
    }
    friend bool operator==(const iterator& a, const iterator& b) { return a.i_ == b.i_; }
    friend bool operator!=(const iterator& a, const iterator& b) { return a.i_ != b.i_; }
    friend bool operator<(const iterator& a, const iterator& b) { return a.i_ < b.i_; }
    friend bool operator>(const iterator& a, const iterator& b) { return a.i_ > b.i_; }
    friend bool operator<=(const iterator& a, const iterator& b) { return a.i_ <= b.i_; }
    friend bool operator>=(const iterator& a, const iterator& b) { return a.i_ >= b.i_; }

  private:
    Index at(std::size_t i) const {
      return i < n_shared_ ? shared_[i] : static_cast<Index>(owned_begin_ + (i - n_shared_));
    }
    const Index* shared_ = nullptr;
    std::size_t n_shared_ = 0;
    Index owned_begin_ = 0;
    std::size_t i_ = 0;
  };
  using const_iterator = iterator;

  Leaf_tetrahedra(const Index* shared, std::size_t n_shared, Index owned_begin, Index owned_end)
      : shared_(shared), n_shared_(n_shared), owned_begin_(owned_begin),
        size_(n_shared + (owned_end - owned_begin)) {}
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  Index operator[](std::size_t i) const {
    return i < n_shared_ ? shared_[i] : static_cast<Index>(owned_begin_ + (i - n_shared_));
  }
  iterator begin() const { return iterator(shared_, n_shared_, owned_begin_, 0); }
  iterator end() const { return iterator(shared_, n_shared_, owned_begin_, size_); }
  // the listed (shared) part
  CGAL::Iterator_range<const Index*> shared() const {
    return CGAL::Iterator_range<const Index*>(shared_, shared_ + n_shared_);
  }
  // the owned part: the tetrahedra [first, second) of T
  std::pair<Index, Index> owned() const {
    return {owned_begin_, static_cast<Index>(owned_begin_ + (size_ - n_shared_))};
  }

private:
  const Index* shared_;
  std::size_t n_shared_;
  Index owned_begin_;
  std::size_t size_;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_LEAF_TETRAHEDRA_H
