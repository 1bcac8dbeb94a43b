// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_CONCURRENCY_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_CONCURRENCY_H

// What a concurrency tag means here: `CGAL::Parallel_tag` (and `CGAL::Parallel_if_available_tag`
// when TBB is linked) is parallel, anything else sequential.

#include <CGAL/tags.h>

#include <type_traits>

namespace CGAL {
namespace PR_star_octree {
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

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_CONCURRENCY_H
