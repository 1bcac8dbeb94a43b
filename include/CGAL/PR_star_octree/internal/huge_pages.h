// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_HUGE_PAGES_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_HUGE_PAGES_H

// Sizing the big arrays of a construction (V, T, the compact T, the leaf lists and their
// transients) so that Linux backs them with transparent huge pages where the system allows it
// only on request (`/sys/kernel/mm/transparent_hugepage/enabled` set to `madvise`, the default of
// many distributions).  Touching fresh memory costs a page fault per 4 KiB page otherwise: on a
// virtual machine, filling 1 GB of new memory took 2.8-4.5 s with 4 KiB pages and 1.4 s with huge
// pages, which was a third of the streaming construction of a 105M-tetrahedra mesh.  The request
// is a hint (`madvise(MADV_HUGEPAGE)` on the fresh allocation, before it is first touched): the
// values, the results and the memory limits are unchanged, and elsewhere it does nothing.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace CGAL {
namespace PR_star_octree {
namespace internal {

// Asks for huge pages on the whole pages of `[data, data + bytes)` when it spans 4 MiB or more.
inline void advise_huge_pages(const void* data, std::size_t bytes) noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t page = 4096, minimum = std::uintptr_t(4) << 20;
  if (data == nullptr || bytes < minimum) return;
  const std::uintptr_t b = (reinterpret_cast<std::uintptr_t>(data) + page - 1) & ~(page - 1);
  const std::uintptr_t e = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(page - 1);
  if (e > b) (void)::madvise(reinterpret_cast<void*>(b), e - b, MADV_HUGEPAGE); // a hint: errors ignored
#else
  (void)data;
  (void)bytes;
#endif
}

// `v.reserve(n)`, the new storage advised as above before anything is written into it.
template <class T, class A>
void reserve_huge(std::vector<T, A>& v, std::size_t n) {
  if (n <= v.capacity()) return;
  v.reserve(n);
  advise_huge_pages(v.data(), n * sizeof(T));
}

// `v.resize(n)` or `v.resize(n, value)` on storage reserved by `reserve_huge`.
template <class T, class A, class... Value>
void resize_huge(std::vector<T, A>& v, std::size_t n, const Value&... value) {
  reserve_huge(v, n);
  v.resize(n, value...);
}

// `v.assign(n, value)` on storage reserved by `reserve_huge` (fresh when `v` is too small).
template <class T, class A>
void assign_huge(std::vector<T, A>& v, std::size_t n, const T& value) {
  if (n > v.capacity()) std::vector<T, A>().swap(v);
  reserve_huge(v, n);
  v.assign(n, value);
}

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_HUGE_PAGES_H
