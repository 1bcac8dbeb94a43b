// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_POINT_RANGE_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_POINT_RANGE_H

// The points of the octree as a random-access range of `Point_3` values: made from the stored
// floats, or copies of the stored points (`PR_star_octree_3::points()`).

#include <boost/iterator/iterator_facade.hpp>

#include <cstddef>
#include <iterator>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

template <class Octree>
class Point_range {
public:
  using Point_3 = typename Octree::Point_3;
  using value_type = Point_3;
  using size_type = std::size_t;

  class const_iterator
      : public boost::iterator_facade<const_iterator, Point_3, std::random_access_iterator_tag, Point_3> {
  public:
    const_iterator() = default;
    const_iterator(const Octree* tree, std::size_t i) : tree_(tree), i_(i) {}

  private:
    friend class boost::iterator_core_access;
    Point_3 dereference() const { return tree_->point(static_cast<typename Octree::Index>(i_)); }
    bool equal(const const_iterator& other) const { return i_ == other.i_; }
    void increment() { ++i_; }
    void decrement() { --i_; }
    void advance(std::ptrdiff_t n) { i_ = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i_) + n); }
    std::ptrdiff_t distance_to(const const_iterator& other) const {
      return static_cast<std::ptrdiff_t>(other.i_) - static_cast<std::ptrdiff_t>(i_);
    }
    const Octree* tree_ = nullptr;
    std::size_t i_ = 0;
  };
  using iterator = const_iterator;

  explicit Point_range(const Octree& tree) : tree_(&tree) {}
  std::size_t size() const { return tree_->number_of_vertices(); }
  bool empty() const { return size() == 0; }
  Point_3 operator[](std::size_t i) const { return tree_->point(static_cast<typename Octree::Index>(i)); }
  const_iterator begin() const { return const_iterator(tree_, 0); }
  const_iterator end() const { return const_iterator(tree_, size()); }

private:
  const Octree* tree_;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_POINT_RANGE_H
