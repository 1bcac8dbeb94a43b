// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_PR_STAR_OCTREE_3_IMPL_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_PR_STAR_OCTREE_3_IMPL_H

// The construction and the statistics of `CGAL::PR_star_octree_3` (included by PR_star_octree.h).

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/internal/concurrency.h>
#include <CGAL/PR_star_octree/internal/huge_pages.h>

#include <atomic>
#include <bitset>
#include <mutex>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

namespace CGAL {

namespace PR_star_octree {
namespace internal {

// The errors of a bad tetrahedron (`t` in the user's numbering), the same from every construction.
template <class V>
std::invalid_argument vertex_out_of_range(std::size_t t, V v, std::size_t nv) {
  return std::invalid_argument("PR_star_octree_3: tetrahedron " + std::to_string(t) + " has vertex index " +
                               std::to_string(v) + " out of range [0, " + std::to_string(nv) + ")");
}
template <class V>
std::invalid_argument vertex_listed_twice(std::size_t t, V v) {
  return std::invalid_argument("PR_star_octree_3: tetrahedron " + std::to_string(t) + " lists vertex " +
                               std::to_string(v) + " twice");
}

// Calls `f(begin, end)` on consecutive blocks of [0, n) whose boundaries are multiples of `grain`
// (so that blocks never share a 64-bit word of a bit array when `grain` is a multiple of 64): with
// several threads when `ConcurrencyTag` is parallel.
template <class ConcurrencyTag, class F>
void for_each_block(std::size_t n, std::size_t grain, const F& f) {
  if constexpr (is_parallel<ConcurrencyTag>()) {
#ifdef CGAL_LINKED_WITH_TBB
    const std::size_t blocks = (n + grain - 1) / grain;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        f(r.begin() * grain, (std::min)(n, r.end() * grain));
                      });
#endif
  } else {
    f(std::size_t(0), n);
  }
}

// The width in bits of a digit of `radix_sort_in_place()`.
constexpr int radix_sort_digit_bits = 10;

// The number of parts of `parallel_bucket_permutation()` in `radix_sort_in_place()`: fixed, so that
// the order of equal keys is the same for any number of threads.
constexpr std::size_t radix_sort_parts = 4;

// Moves the elements of the ranges [head[d], end[d]) (one per value d of `digit`, each as long as
// the number of elements of value d in their union) so that each holds its own: a round gives each
// of the `parts` parts a stripe of every range, where it places what it can as the sequential
// American flag pass does, parts in parallel with `ConcurrencyTag`; then every range puts its
// placed elements first (ranges in parallel) and keeps the others for the next round (the scheme of
// Cho et al., "PARADIS: an efficient parallel algorithm for in-place radix sort", VLDB 2015).  What
// four rounds leave is placed by one thread.  A part only touches its own stripes, so the result
// depends on `parts`, not on the threads.
template <class ConcurrencyTag, class Digit, class Swap>
void parallel_bucket_permutation(std::vector<std::size_t>& head, const std::vector<std::size_t>& end,
                                 const Digit& digit, const Swap& swap, std::size_t parts) {
  const std::size_t radix = end.size();
  std::vector<std::size_t> part_head, part_end; // the parts' stripes (none with one part)
  if (parts > 1) {
    part_head.resize(parts * radix);
    part_end.resize(parts * radix);
  }
  const auto place_part = [&](std::size_t p) {
    std::size_t* h = part_head.data() + p * radix;
    const std::size_t* t = part_end.data() + p * radix;
    for (std::size_t d = 0; d < radix; ++d)
      for (; h[d] < t[d]; ++h[d]) { // what stays at h[d] is in place, or has no room left in this part
        const std::size_t i = h[d];
        for (std::size_t x = digit(i); x != d && h[x] < t[x]; x = digit(i)) swap(i, h[x]++);
      }
  };
  const auto gather_range = [&](std::size_t d) { // the placed elements first
    std::size_t l = head[d], r = end[d];
    for (;;) {
      while (l < r && digit(l) == d) ++l;
      while (l < r && digit(r - 1) != d) --r;
      if (l == r) break;
      swap(l++, --r);
    }
    head[d] = l;
  };
  for (int round = 0; round < 4 && parts > 1; ++round) {
    std::size_t left = 0;
    for (std::size_t d = 0; d < radix; ++d) left += end[d] - head[d];
    if (left < (std::size_t(1) << 14)) break;
    for (std::size_t d = 0; d < radix; ++d) {
      const std::size_t size = end[d] - head[d];
      for (std::size_t p = 0; p < parts; ++p) {
        part_head[p * radix + d] = head[d] + size * p / parts;
        part_end[p * radix + d] = head[d] + size * (p + 1) / parts;
      }
    }
    if constexpr (is_parallel<ConcurrencyTag>()) {
#ifdef CGAL_LINKED_WITH_TBB
      tbb::parallel_for(std::size_t(0), parts, place_part);
      tbb::parallel_for(std::size_t(0), radix, gather_range);
#endif
    } else {
      for (std::size_t p = 0; p < parts; ++p) place_part(p);
      for (std::size_t d = 0; d < radix; ++d) gather_range(d);
    }
  }
  for (std::size_t d = 0; d < radix; ++d) // the rest, on one thread
    for (; head[d] < end[d]; ++head[d]) {
      const std::size_t i = head[d];
      for (std::size_t x = digit(i); x != d; x = digit(i)) swap(i, head[x]++);
    }
}

// Sorts the elements `[b, e)` in place by `key(i)` (an unsigned integer below 2^(shift + 10)),
// moving them only with `swap(i, j)`: an in-place most-significant-digit radix sort (American flag
// sort) on digits of 10 bits, from bit `shift` down to bit 0, and insertion sort below 64 elements.
// Equal keys end up in an order that depends only on the initial order, the same for any number of
// threads and for either `ConcurrencyTag`: the top digit of a range of at least 2^16 elements is
// placed by `parallel_bucket_permutation()` in `radix_sort_parts` parts, and its buckets are sorted
// independently, in parallel with `ConcurrencyTag`.  `counts`, when given, holds the number of
// elements of each value of the top digit (the caller counted them in a pass of its own).
template <class ConcurrencyTag, class Key, class Swap>
void radix_sort_in_place(std::size_t b, std::size_t e, int shift, const Key& key, const Swap& swap,
                         bool top = true, const std::vector<std::size_t>* counts = nullptr) {
  constexpr int bits = radix_sort_digit_bits;
  constexpr std::size_t radix = std::size_t(1) << bits;
  if (e - b < 64) { // insertion sort on the whole key
    for (std::size_t i = b + 1; i < e; ++i)
      for (std::size_t j = i; j > b && key(j) < key(j - 1); --j) swap(j, j - 1);
    return;
  }
  const auto digit = [&](std::size_t i) { return static_cast<std::size_t>((key(i) >> shift) & (radix - 1)); };
  std::vector<std::size_t> head(radix + 1, 0);
  if (counts != nullptr)
    std::copy(counts->begin(), counts->begin() + radix, head.begin() + 1);
  else
    for (std::size_t i = b; i < e; ++i) ++head[digit(i) + 1];
  head[0] = b;
  for (std::size_t d = 0; d < radix; ++d) head[d + 1] += head[d];
  const std::vector<std::size_t> first(head.begin(), head.end());
  const std::vector<std::size_t> end(first.begin() + 1, first.end());
  head.pop_back();
  const bool parted = top && e - b >= (std::size_t(1) << 16);
  parallel_bucket_permutation<ConcurrencyTag>(head, end, digit, swap, parted ? radix_sort_parts : 1);
  if (shift == 0) return;
  const int next = (std::max)(shift - bits, 0);
  const auto recurse = [&](std::size_t d) {
    if (first[d + 1] - first[d] > 1)
      radix_sort_in_place<CGAL::Sequential_tag>(first[d], first[d + 1], next, key, swap, false);
  };
  if constexpr (is_parallel<ConcurrencyTag>()) {
#ifdef CGAL_LINKED_WITH_TBB
    if (top) {
      tbb::parallel_for(std::size_t(0), radix, recurse);
      return;
    }
#endif
  }
  for (std::size_t d = 0; d < radix; ++d) recurse(d);
}

} // namespace internal
} // namespace PR_star_octree

// ---------------------------------------------------------------------------------------------
// Construction
// ---------------------------------------------------------------------------------------------

template <class GT, class I>
void PR_star_octree_3<GT, I>::check_sizes(std::size_t nv, std::size_t nt) const {
  const std::size_t index_max = static_cast<std::size_t>(no_node) - 1;
  if (nv > index_max || nt > index_max || 4 * nt > index_max)
    throw std::invalid_argument("PR_star_octree_3: the mesh (" + std::to_string(nv) + " vertices, " +
                                std::to_string(nt) + " tetrahedra) does not fit the " +
                                std::to_string(8 * sizeof(I)) + "-bit index type");
}

// The copying path: V, the scalars, the labels and T (validated) in the input's order.
template <class GT, class I>
template <class InputMesh>
void PR_star_octree_3<GT, I>::copy_input(const InputMesh& input) {
  const std::size_t nv = input.number_of_vertices();
  const std::size_t nt = input.number_of_tetrahedra();
  check_sizes(nv, nt);
  PR_star_octree::internal::reserve_huge(points_, nv);
  for (std::size_t i = 0; i < nv; ++i) points_.push_back(convert_point(input.point(i)));
  input_float32_ = PR_star_octree::internal::input_has_float32_points(input);
  if (input.has_scalar_field()) {
    has_scalar_ = true;
    PR_star_octree::internal::resize_huge(scalars_, nv);
    for (std::size_t i = 0; i < nv; ++i) scalars_[i] = static_cast<double>(input.scalar(i));
  }
  PR_star_octree::internal::resize_huge(tetrahedra_, nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const auto c = input.tetrahedron(t);
    Tetrahedron& r = tetrahedra_[t];
    for (int k = 0; k < 4; ++k) {
      const auto v = c[k];
      // (also rejects the negative indices of a signed index type)
      if (!(v >= 0) || static_cast<std::size_t>(v) >= nv)
        throw PR_star_octree::internal::vertex_out_of_range(t, v, nv);
      r[k] = static_cast<Index>(v);
    }
  }
  if constexpr (PR_star_octree::internal::has_tetrahedron_labels<InputMesh>::value) {
    if (input.has_tetrahedron_labels()) {
      has_labels_ = true;
      labels_.resize(nt);
      for (std::size_t t = 0; t < nt; ++t) labels_[t] = static_cast<int>(input.tetrahedron_label(t));
    }
  }
}

// The lean path: the arrays are moved in.
template <class GT, class I>
void PR_star_octree_3<GT, I>::take_mesh(PR_star_octree::Indexed_tetrahedral_mesh<Point_3, Index>&& mesh) {
  points_ = std::move(mesh.points);
  tetrahedra_ = std::move(mesh.tetrahedra);
  input_float32_ = mesh.float32_points;
  mesh.points.clear();
  mesh.tetrahedra.clear();
  const std::size_t nv = points_.size(), nt = tetrahedra_.size();
  if (!mesh.point_data.empty()) {
    scalars_ = std::move(mesh.point_data.front().values);
    mesh.point_data.erase(mesh.point_data.begin());
    has_scalar_ = true;
  }
  if (!mesh.tetrahedron_labels.empty()) {
    labels_ = std::move(mesh.tetrahedron_labels);
    mesh.tetrahedron_labels.clear();
    has_labels_ = true;
  }
  check_sizes(nv, nt);
  if (has_scalar_ && scalars_.size() != nv)
    throw std::invalid_argument("PR_star_octree_3: the scalar field has " + std::to_string(scalars_.size()) +
                                " values for " + std::to_string(nv) + " vertices");
  if (has_labels_ && labels_.size() != nt)
    throw std::invalid_argument("PR_star_octree_3: " + std::to_string(labels_.size()) + " labels for " +
                                std::to_string(nt) + " tetrahedra");
  // (the vertex indices are checked by build_in_place(), in parallel)
}

template <class GT, class I>
void PR_star_octree_3<GT, I>::set_labels_uniform_if_possible() {
  if (!has_labels_ || labels_.empty()) return;
  if (std::all_of(labels_.begin(), labels_.end(), [&](int l) { return l == labels_.front(); })) {
    uniform_label_ = labels_.front(); // one subdomain: one value, not |T|
    std::vector<int>().swap(labels_);
  }
}

// Common to both paths: `points_`, `scalars_`, `labels_` and `tetrahedra_` hold the input, in its
// order and numbering (indices in range); they are re-indexed in place.
// The k_v (when automatic) and whether the coordinates are stored as floats.
template <class GT, class I>
void PR_star_octree_3<GT, I>::choose_storage(std::size_t nv, std::size_t nt) {
  if (bucket_size_ == automatic_bucket_size) {
    choice_ = PR_star_octree::choose_bucket_size(nv, nt, bucket_relations_);
    bucket_size_ = choice_.bucket_size;
    automatic_ = true;
  }
  if (!can_store_floats && precision_ == PR_star_octree::Coordinate_precision::float32)
    throw std::invalid_argument("PR_star_octree_3: coordinate_precision float32 needs the traits' "
                                "Construct_point_3 from three doubles");
  float_coordinates_ =
      can_store_floats && (precision_ == PR_star_octree::Coordinate_precision::float32 ||
                           (precision_ == PR_star_octree::Coordinate_precision::as_input && input_float32_));
}

template <class GT, class I>
template <class ConcurrencyTag>
void PR_star_octree_3<GT, I>::build_in_place() {
  const std::size_t nv = points_.size(), nt = tetrahedra_.size();
  choose_storage(nv, nt);
  using PR_star_octree::internal::for_each_block;
  // Vertex indices out of range, then repeated vertices in a tetrahedron (in the user's numbering,
  // for the message): the first tetrahedron at fault is reported, whatever the number of threads.
  {
    constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();
    std::atomic<std::size_t> out_of_range{none}, repeated{none};
    const auto lower = [](std::atomic<std::size_t>& a, std::size_t t) {
      for (std::size_t cur = a.load(); t < cur && !a.compare_exchange_weak(cur, t);) {
      }
    };
    for_each_block<ConcurrencyTag>(nt, 1 << 16, [&](std::size_t b, std::size_t e) {
      for (std::size_t t = b; t < e; ++t) {
        const Tetrahedron& r = tetrahedra_[t];
        if (static_cast<std::size_t>((std::max)((std::max)(r[0], r[1]), (std::max)(r[2], r[3]))) >= nv) {
          lower(out_of_range, t);
        } else if (r[0] == r[1] || r[0] == r[2] || r[0] == r[3] || r[1] == r[2] || r[1] == r[3] ||
                   r[2] == r[3]) {
          lower(repeated, t);
        }
      }
    });
    if (out_of_range.load() != none) {
      const std::size_t t = out_of_range.load();
      Index first = 0;
      for (Index x : tetrahedra_[t])
        if (static_cast<std::size_t>(x) >= nv) {
          first = x;
          break;
        }
      throw PR_star_octree::internal::vertex_out_of_range(t, first, nv);
    }
    if (repeated.load() != none) {
      const std::size_t t = repeated.load();
      const Tetrahedron& r = tetrahedra_[t];
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
          if (r[i] == r[j]) throw PR_star_octree::internal::vertex_listed_twice(t, r[i]);
    }
  }

  std::vector<Index> from_original = build_vertices<ConcurrencyTag>();

  // 3. T re-indexed, sorted, oriented; then the leaf lists.
  sort_and_orient_tetrahedra<ConcurrencyTag>(from_original);
  std::vector<Index>().swap(from_original);
  set_labels_uniform_if_possible();
  build_leaf_lists<ConcurrencyTag>();
  if (compact_) {
    compact_tetrahedra_.assign(tetrahedra_.data(), tetrahedra_.size(), number_of_vertices());
    std::vector<Tetrahedron>().swap(tetrahedra_);
  }
}

// Steps 0 to 2 of the construction, common to the in-place and the streaming ones: V (floats if
// asked), the bounding cube, the PR split, V and the scalars gathered in the new order.  Returns
// the new index of each input vertex.
template <class GT, class I>
template <class ConcurrencyTag>
std::vector<I> PR_star_octree_3<GT, I>::build_vertices() {
  const std::size_t nv = points_.size();
  using PR_star_octree::internal::for_each_block;
  // 0. Coordinates stored as floats: converted first (nothing changes for an input of floats), so
  // that the octree and the orientations are those of the stored values.
  if (float_coordinates_) to_float<ConcurrencyTag>();

  // 1. Bounding cube (and finite coordinates), block by block: the minima and maxima do not depend on
  // the blocks, and the first vertex with a non-finite coordinate is reported.
  std::array<double, 3> lo{{0, 0, 0}}, hi{{0, 0, 0}};
  {
    constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();
    std::atomic<std::size_t> non_finite{none};
    std::mutex box_mutex;
    bool first_block = true;
    for_each_block<ConcurrencyTag>(nv, 1 << 16, [&](std::size_t b, std::size_t e) {
      std::array<double, 3> l{{0, 0, 0}}, h{{0, 0, 0}};
      for (std::size_t i = b; i < e; ++i) {
        const std::array<double, 3> c = stored_coordinates(i);
        if (!(std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]))) {
          for (std::size_t cur = non_finite.load(); i < cur && !non_finite.compare_exchange_weak(cur, i);) {
          }
          return;
        }
        for (int a = 0; a < 3; ++a) {
          if (i == b || c[a] < l[a]) l[a] = c[a];
          if (i == b || c[a] > h[a]) h[a] = c[a];
        }
      }
      if (b == e) return;
      std::lock_guard<std::mutex> lock(box_mutex);
      for (int a = 0; a < 3; ++a) {
        if (first_block || l[a] < lo[a]) lo[a] = l[a];
        if (first_block || h[a] > hi[a]) hi[a] = h[a];
      }
      first_block = false;
    });
    if (non_finite.load() != none)
      throw std::invalid_argument("PR_star_octree_3: vertex " + std::to_string(non_finite.load()) +
                                  " has a non-finite coordinate");
  }
  double side = (std::max)({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  if (!(side > 0)) side = 1.; // empty mesh, a single point or all points coincident
  for (int a = 0; a < 3; ++a) {
    root_lo_[a] = lo[a];
    root_hi_[a] = lo[a] + side;
    if (root_hi_[a] < hi[a]) root_hi_[a] = hi[a]; // rounding: the cube must contain every point
  }

  // 2. PR split of the vertices, depth first: `order[new] = original`; V re-indexed in place.
  std::vector<Index> order;
  PR_star_octree::internal::resize_huge(order, nv);
  std::iota(order.begin(), order.end(), Index(0));
  split_vertices<ConcurrencyTag>(order);
  // V and the scalars are gathered into new arrays (one at a time): random reads but sequential
  // writes, much faster than following the cycles of `order` in place, for a transient |V| points.
  const auto gather = [&](auto& a) {
    std::remove_reference_t<decltype(a)> g;
    PR_star_octree::internal::resize_huge(g, a.size());
    for_each_block<ConcurrencyTag>(a.size(), 1 << 14, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) g[i] = a[order[i]];
    });
    a.swap(g);
  };
  if (float_coordinates_)
    gather(float_points_);
  else
    gather(points_);
  if (has_scalar_) gather(scalars_);
  std::vector<Index> from_original;
  PR_star_octree::internal::resize_huge(from_original, nv);
  for_each_block<ConcurrencyTag>(nv, 1 << 14, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) from_original[order[i]] = static_cast<Index>(i);
  });
  if (keep_vertex_permutation_)
    vertex_to_original_ = std::move(order);
  else
    std::vector<Index>().swap(order);

  return from_original;
}

// The streaming construction: V as in place, then the tetrahedra from `source`, read once to check
// and count them by smallest vertex (and size their compact records), then once per slab of
// smallest vertices, whose tetrahedra are placed in a buffer by counting (in the source's order
// within each vertex), oriented exactly and appended to the compact array.  The plain T is never
// whole in memory: the peak is the compact T, V and one slab of plain tetrahedra (at most a sixth
// of T, or 2^20 tetrahedra).
template <class GT, class I>
template <class ConcurrencyTag, class TetrahedronSource>
void PR_star_octree_3<GT, I>::build_streaming(const TetrahedronSource& source) {
  using PR_star_octree::internal::for_each_block;
  const std::size_t nv = points_.size();
  compact_ = true;
  keep_tetrahedron_permutation_ = false;
  // Pass 1: the tetrahedra checked (in the user's numbering, for the messages) and counted: the
  // automatic k_v needs |T| before V is split.  A source that knows its number of tetrahedra
  // saves this pass: they are checked in pass 2.
  const auto check = [nv](const std::uint64_t* c, std::size_t t) {
    for (int k = 0; k < 4; ++k)
      if (c[k] >= nv) throw PR_star_octree::internal::vertex_out_of_range(t, c[k], nv);
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        if (c[a] == c[b]) throw PR_star_octree::internal::vertex_listed_twice(t, c[a]);
  };
  constexpr bool counted = PR_star_octree::internal::has_number_of_tetrahedra<TetrahedronSource>::value;
  std::size_t nt = 0;
  has_labels_ = false;
  if constexpr (counted) {
    nt = static_cast<std::size_t>(source.number_of_tetrahedra());
  } else {
    source.for_each_chunk([&](const std::uint64_t* v, const int* labels, std::size_t n) {
      for (std::size_t i = 0; i < n; ++i, ++nt) check(v + 4 * i, nt);
      if (labels != nullptr) has_labels_ = true;
    });
  }
  check_sizes(nv, nt);
  choose_storage(nv, nt);
  std::vector<Index> from_original = build_vertices<ConcurrencyTag>();

  // Pass 2: counts by smallest vertex (new numbering) and the bytes of the records.
  std::vector<Index> first;
  PR_star_octree::internal::assign_huge(first, nv + 1, Index(0));
  std::size_t bytes = 0, seen = 0;
  const auto changed = [&]() {
    return std::invalid_argument(
        "PR_star_octree_3: the tetrahedron source gave other tetrahedra on another pass");
  };
  const auto renumber = [&](const std::uint64_t* c) {
    if ((std::max)((std::max)(c[0], c[1]), (std::max)(c[2], c[3])) >= nv) throw changed();
    return Tetrahedron{{from_original[c[0]], from_original[c[1]], from_original[c[2]], from_original[c[3]]}};
  };
  const auto smallest = [](const Tetrahedron& c) {
    return (std::min)((std::min)(c[0], c[1]), (std::min)(c[2], c[3]));
  };
  source.for_each_chunk([&](const std::uint64_t* v, const int* labels, std::size_t n) {
    if constexpr (counted) {
      for (std::size_t i = 0; i < n; ++i) check(v + 4 * i, seen + i);
      if (labels != nullptr) has_labels_ = true;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const Tetrahedron c = renumber(v + 4 * i);
      ++first[smallest(c)];
      bytes += compact_tetrahedra_.record_length(c);
    }
    seen += n;
  });
  if (seen != nt) {
    if (counted)
      throw std::invalid_argument("PR_star_octree_3: the tetrahedron source gave " + std::to_string(seen) +
                                  " tetrahedra, not the " + std::to_string(nt) + " it counted");
    throw changed();
  }
  compact_tetrahedra_.start(first.data(), nv, nt, bytes);
  std::size_t sum = 0; // first[v]: the position of the first tetrahedron of v
  for (std::size_t v = 0; v <= nv; ++v) {
    const std::size_t c = first[v];
    first[v] = static_cast<Index>(sum);
    sum += c;
  }
  if (has_labels_) PR_star_octree::internal::assign_huge(labels_, nt, 0);
  PR_star_octree::internal::assign_huge(reoriented_, (nt + 63) / 64, std::uint64_t(0));

  // Passes 3...: the slabs, cut where the tetrahedra of the smallest vertices reach equal parts
  // of T (a slab is its part and at most the star of one vertex more): |T| / slab_tetrahedra of
  // them rounded up, or by default min(6, |T| / 2^20 rounded up).
  const std::size_t per_slab = slab_tetrahedra_ > 0 ? slab_tetrahedra_ : std::size_t(1) << 20;
  std::size_t slabs = (std::max)(std::size_t(1), (nt + per_slab - 1) / per_slab);
  if (slab_tetrahedra_ == 0) slabs = (std::min)(slabs, std::size_t(6));
  // The slabs' first vertices, cut first so that the buffer is allocated once, at the largest
  // slab (growing it from one slab to the next held two buffers at once, for a copy).
  std::vector<std::size_t> cuts{0};
  std::size_t largest = 0;
  for (std::size_t vb = 0, s = 1; vb < nv; ++s) {
    // the part ends at the s-th of `slabs` equal parts of T (nt * s / slabs without overflow)
    const std::size_t target = s >= slabs ? nt : nt / slabs * s + nt % slabs * s / slabs;
    std::size_t ve = vb + 1;
    while (ve < nv && first[ve] < target) ++ve;
    largest = (std::max)(largest, std::size_t(first[ve] - first[vb]));
    cuts.push_back(ve);
    vb = ve;
  }
  std::vector<Tetrahedron> buffer;
  PR_star_octree::internal::reserve_huge(buffer, largest);
  std::vector<Index> cursor;
  std::atomic<std::size_t> degenerate{0};
  for (std::size_t s = 0; s + 1 < cuts.size(); ++s) {
    const std::size_t vb = cuts[s], ve = cuts[s + 1];
    const std::size_t tb = first[vb], te = first[ve];
    if (te > tb) {
      buffer.resize(te - tb);
      cursor.assign(first.begin() + vb, first.begin() + ve);
      source.for_each_chunk([&](const std::uint64_t* v, const int* labels, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) {
          const Tetrahedron c = renumber(v + 4 * i);
          const std::size_t m = smallest(c);
          if (m < vb || m >= ve) continue;
          const std::size_t p = cursor[m - vb]++;
          if (p >= first[m + 1]) throw changed();
          buffer[p - tb] = c;
          if (has_labels_) labels_[p] = labels != nullptr ? labels[i] : 0;
        }
      });
      for (std::size_t m = vb; m < ve; ++m)
        if (cursor[m - vb] != first[m + 1]) throw changed();
      // Positive orientation, exactly; blocks aligned on the words of `reoriented_` (each word is
      // written by one block; the words before `tb` keep the previous slab's bits).
      const std::size_t ab = tb - tb % 64;
      for_each_block<ConcurrencyTag>(te - ab, 64 * 1024, [&](std::size_t b, std::size_t e) {
        auto orientation = gt_.orientation_3_object();
        std::size_t flat = 0;
        for (std::size_t g = (std::max)(ab + b, tb); g < ab + e; ++g) {
          Tetrahedron& c = buffer[g - tb];
          const CGAL::Orientation o = orientation(point(c[0]), point(c[1]), point(c[2]), point(c[3]));
          if (o == CGAL::NEGATIVE) {
            std::swap(c[2], c[3]);
            reoriented_[g >> 6] |= std::uint64_t(1) << (g & 63);
          } else if (o == CGAL::COPLANAR)
            ++flat;
        }
        degenerate += flat;
      });
      compact_tetrahedra_.append(buffer.data(), buffer.size());
    }
  }
  compact_tetrahedra_.finish();
  std::vector<Tetrahedron>().swap(buffer);
  std::vector<Index>().swap(cursor);
  std::vector<Index>().swap(first);
  std::vector<Index>().swap(from_original);
  degenerate_tetrahedra_ = degenerate.load();
  for (std::uint64_t w : reoriented_)
    reoriented_count_ += static_cast<std::size_t>(std::bitset<64>(w).count());
  if (reoriented_count_ == 0) std::vector<std::uint64_t>().swap(reoriented_);
  set_labels_uniform_if_possible();
  build_leaf_lists<ConcurrencyTag>();
}

// V converted to floats, each coordinate rounded to the nearest one, in the input order, and the
// points freed (a transient 12 bytes per vertex more than V).  The floats are stored before they
// are read back as doubles: GCC 12 at -O2 drops the round trip `double(float(x))` when it
// vectorizes two coordinates together.  The first vertex whose finite coordinate overflows a
// float is reported.
template <class GT, class I>
template <class ConcurrencyTag>
void PR_star_octree_3<GT, I>::to_float() {
  constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();
  std::atomic<std::size_t> overflow{none};
  PR_star_octree::internal::resize_huge(float_points_, points_.size());
  PR_star_octree::internal::for_each_block<ConcurrencyTag>(
      points_.size(), 1 << 14, [&](std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i) {
          const std::array<double, 3> c = coordinates(points_[i]);
          std::array<float, 3>& f = float_points_[i];
          for (int a = 0; a < 3; ++a) f[a] = static_cast<float>(c[a]);
          for (int a = 0; a < 3; ++a)
            if (std::isfinite(c[a]) && !std::isfinite(f[a]))
              for (std::size_t cur = overflow.load(); i < cur && !overflow.compare_exchange_weak(cur, i);) {
              }
        }
      });
  if (overflow.load() != none) {
    std::vector<std::array<float, 3>>().swap(float_points_);
    throw std::invalid_argument("PR_star_octree_3: vertex " + std::to_string(overflow.load()) +
                                " has a coordinate beyond the range of a 32-bit float (coordinate_precision "
                                "float32)");
  }
  std::vector<Point_3>().swap(points_);
}

template <class GT, class I>
template <class ConcurrencyTag>
void PR_star_octree_3<GT, I>::split_vertices(std::vector<Index>& order) {
  struct Item {
    Node_index node;
    std::array<double, 3> lo, hi;
    std::size_t depth;
  };
  const std::size_t nv = order.size();
  nodes_.clear();
  leaves_.clear();
  nodes_.push_back(Node{0, static_cast<Index>(nv), 0, 0, 0, 0, 0, 0, no_node, no_node});
  std::vector<Item> stack{Item{0, root_lo_, root_hi_, 0}};
  // Stable counting sort of order[b, e) by octant of the box [lo, hi) (bit a set when coordinate a
  // >= midpoint): `start[c]` is where octant c begins, relative to b.  `buffer` and `code` are the
  // caller's scratch.
  const auto sort_by_octant = [&](Index b, Index e, const std::array<double, 3>& lo,
                                  const std::array<double, 3>& hi, std::array<std::size_t, 9>& start,
                                  std::vector<Index>& buffer, std::vector<unsigned char>& code) {
    const std::size_t count = e - b;
    const std::array<double, 3> mid = center(lo, hi);
    PR_star_octree::internal::resize_huge(code, count);
    start.fill(0);
    for (std::size_t i = 0; i < count; ++i) {
      const unsigned c = octant(stored_coordinates(order[b + i]), mid);
      code[i] = static_cast<unsigned char>(c);
      ++start[c + 1];
    }
    for (int c = 0; c < 8; ++c) start[c + 1] += start[c];
    PR_star_octree::internal::resize_huge(buffer, count);
    std::array<std::size_t, 8> pos;
    std::copy(start.begin(), start.begin() + 8, pos.begin());
    for (std::size_t i = 0; i < count; ++i) buffer[pos[code[i]]++] = order[b + i];
    std::copy(buffer.begin(), buffer.begin() + count, order.begin() + b);
  };

  // The vertices of a leaf in the order a finer split would give them (depth first, octants 0 to
  // 7, down to groups of `leaf_order_group` vertices or the depth bound), without making nodes:
  // vertices close in space get close indices, which shortens the differences of the compact
  // tetrahedra and keeps a leaf's relations close in memory.  Depends on the positions only, as the
  // split does (ties, at the finest level, keep the input order).
  constexpr std::size_t leaf_order_group = 8;
  const auto order_leaf = [&](Index b, Index e, const Item& leaf, std::vector<Index>& buffer,
                              std::vector<unsigned char>& code) {
    std::vector<Item> sub{Item{0, leaf.lo, leaf.hi, leaf.depth}};
    std::vector<std::pair<Index, Index>> ranges{{b, e}};
    while (!sub.empty()) {
      const Item it = sub.back();
      const std::pair<Index, Index> r = ranges.back();
      sub.pop_back();
      ranges.pop_back();
      if (static_cast<std::size_t>(r.second - r.first) <= leaf_order_group || it.depth >= max_depth_)
        continue;
      std::array<std::size_t, 9> start;
      sort_by_octant(r.first, r.second, it.lo, it.hi, start, buffer, code);
      for (unsigned c = 8; c-- > 0;) {
        if (start[c + 1] - start[c] <= leaf_order_group) continue;
        Item child{0, it.lo, it.hi, it.depth + 1};
        child_box(c, child.lo, child.hi);
        sub.push_back(child);
        ranges.emplace_back(static_cast<Index>(r.first + start[c]),
                            static_cast<Index>(r.first + start[c + 1]));
      }
    }
  };

  std::vector<Index> buffer;
  std::vector<unsigned char> code;
  std::vector<Item> to_order; // the leaves whose vertices are put in the finer order, afterwards
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    const Index b = nodes_[item.node].vertex_begin, e = nodes_[item.node].vertex_end;
    const std::size_t count = e - b;
    bool split = count > bucket_size_;
    if (split && item.depth >= max_depth_) {
      split = false;
      ++depth_limited_leaves_;
    }
    bool coincident = false;
    if (split) { // points that all coincide can never be separated: stop and report
      const std::array<double, 3> p0 = stored_coordinates(order[b]);
      bool all_same = true;
      for (Index i = b + 1; i < e && all_same; ++i) all_same = (stored_coordinates(order[i]) == p0);
      if (all_same) {
        split = false;
        coincident = true;
        ++coincident_leaves_;
      }
    }
    if (!split) {
      leaves_.push_back(item.node);
      depth_ = (std::max)(depth_, item.depth);
      if (!coincident && count > leaf_order_group) to_order.push_back(item);
      continue;
    }

    std::array<std::size_t, 9> start;
    sort_by_octant(b, e, item.lo, item.hi, start, buffer, code);
    const Node_index first = static_cast<Node_index>(nodes_.size());
    if (static_cast<std::size_t>(first) + 8 >= static_cast<std::size_t>(no_node))
      throw std::invalid_argument("PR_star_octree_3: too many octree nodes for the index type");
    nodes_[item.node].first_child = first;
    for (unsigned c = 0; c < 8; ++c)
      nodes_.push_back(Node{static_cast<Index>(b + start[c]), static_cast<Index>(b + start[c + 1]), 0, 0, 0,
                            0, 0, 0, no_node, item.node});
    // Push the children in reverse so that child 0 is visited first: leaves come out depth first.
    for (unsigned c = 8; c-- > 0;) {
      Item child{static_cast<Node_index>(first + c), item.lo, item.hi, item.depth + 1};
      child_box(c, child.lo, child.hi);
      stack.push_back(child);
    }
  }
  std::vector<Index>().swap(buffer);
  // Each leaf orders its own vertex range: in parallel, the same order for any number of threads.
  PR_star_octree::internal::for_each_block<ConcurrencyTag>(
      to_order.size(), 16, [&](std::size_t lb, std::size_t le) {
        std::vector<Index> leaf_buffer;
        std::vector<unsigned char> leaf_code;
        for (std::size_t l = lb; l < le; ++l) {
          const Node& nd = nodes_[to_order[l].node];
          order_leaf(nd.vertex_begin, nd.vertex_end, to_order[l], leaf_buffer, leaf_code);
        }
      });
  nodes_.shrink_to_fit();
  leaves_.shrink_to_fit();
}

template <class GT, class I>
template <class ConcurrencyTag>
void PR_star_octree_3<GT, I>::sort_and_orient_tetrahedra(const std::vector<Index>& from_original) {
  const std::size_t nv = number_of_vertices();
  const std::size_t nt = tetrahedra_.size();
  using PR_star_octree::internal::for_each_block;

  // The sort key of a tetrahedron is its smallest vertex (below nv); the top digit of the radix
  // sort takes the key's highest bits.
  using PR_star_octree::internal::radix_sort_digit_bits;
  const auto key = [&](std::size_t t) {
    const Tetrahedron& c = tetrahedra_[t];
    return static_cast<std::uint64_t>((std::min)((std::min)(c[0], c[1]), (std::min)(c[2], c[3])));
  };
  int width = 0;
  while (width < 64 && (std::uint64_t(nv > 0 ? nv - 1 : 0) >> width) != 0) ++width;
  const int top_shift = (std::max)(width - radix_sort_digit_bits, 0);

  // New vertex numbering, in place, and the histogram of the top digit (which the radix sort
  // would otherwise count in a pass of its own, on one thread): integer sums, the same for any
  // number of threads.
  std::vector<std::size_t> top_counts(std::size_t(1) << radix_sort_digit_bits, 0);
  std::mutex top_counts_mutex;
  for_each_block<ConcurrencyTag>(nt, 1 << 16, [&](std::size_t b, std::size_t e) {
    std::vector<std::size_t> local(top_counts.size(), 0);
    for (std::size_t t = b; t < e; ++t) {
      for (Index& v : tetrahedra_[t]) v = from_original[v];
      ++local[static_cast<std::size_t>(key(t) >> top_shift) & (local.size() - 1)];
    }
    std::lock_guard<std::mutex> lock(top_counts_mutex);
    for (std::size_t d = 0; d < local.size(); ++d) top_counts[d] += local[d];
  });

  // Locality: T sorted by smallest vertex, in place (radix sort), the labels and the permutation
  // to the user's numbering (when kept) moved along.
  std::vector<Index> perm;
  if (keep_tetrahedron_permutation_) {
    PR_star_octree::internal::resize_huge(perm, nt);
    std::iota(perm.begin(), perm.end(), Index(0));
  }
  {
    const bool with_labels = !labels_.empty(), with_perm = !perm.empty();
    const auto swap = [&](std::size_t i, std::size_t j) {
      std::swap(tetrahedra_[i], tetrahedra_[j]);
      if (with_labels) std::swap(labels_[i], labels_[j]);
      if (with_perm) std::swap(perm[i], perm[j]);
    };
    PR_star_octree::internal::radix_sort_in_place<ConcurrencyTag>(0, nt, top_shift, key, swap, true,
                                                                  &top_counts);
  }
  tetrahedron_to_original_ = std::move(perm);

  // Positive orientation with the exact predicate; blocks of 64 tetrahedra own their word of
  // `reoriented_`, and the counts are summed afterwards, so any number of threads gives the same.
  reoriented_.assign((nt + 63) / 64, 0);
  std::vector<std::uint32_t> word_degenerate(reoriented_.size(), 0);
  for_each_block<ConcurrencyTag>(nt, 64 * 1024, [&](std::size_t b, std::size_t e) {
    auto orientation = gt_.orientation_3_object();
    for (std::size_t t = b; t < e; ++t) {
      Tetrahedron& c = tetrahedra_[t];
      const CGAL::Orientation o = orientation(point(c[0]), point(c[1]), point(c[2]), point(c[3]));
      if (o == CGAL::NEGATIVE) {
        std::swap(c[2], c[3]);
        reoriented_[t >> 6] |= std::uint64_t(1) << (t & 63);
      } else if (o == CGAL::COPLANAR)
        ++word_degenerate[t >> 6];
    }
  });
  for (std::uint64_t w : reoriented_)
    reoriented_count_ += static_cast<std::size_t>(std::bitset<64>(w).count());
  for (std::uint32_t d : word_degenerate) degenerate_tetrahedra_ += d;
  if (reoriented_count_ == 0) std::vector<std::uint64_t>().swap(reoriented_); // all as given: no bits
}

template <class GT, class I>
template <class ConcurrencyTag>
void PR_star_octree_3<GT, I>::build_leaf_lists() {
  // T plain (the in-place construction) or already compact (the streaming one)
  const bool from_compact = tetrahedra_.empty() && !compact_tetrahedra_.empty();
  const std::size_t nv = number_of_vertices(),
                    nt = from_compact ? compact_tetrahedra_.size() : tetrahedra_.size();
  // f(t, c) for the tetrahedra t of [b, e), decoded in one pass when compact
  const auto for_each_in = [&](std::size_t b, std::size_t e, auto&& f) {
    if (b >= e) return;
    if (!from_compact) {
      for (std::size_t t = b; t < e; ++t) f(t, tetrahedra_[t]);
      return;
    }
    typename PR_star_octree::internal::Compact_tetrahedra<Index>::Cursor cursor(compact_tetrahedra_, b);
    for (std::size_t t = b; t < e; ++t, ++cursor) f(t, *cursor);
  };
  const std::size_t nl = leaves_.size();
  std::vector<Index> leaf_of; // position of the leaf in `leaves_`
  PR_star_octree::internal::resize_huge(leaf_of, nv);
  for (std::size_t l = 0; l < nl; ++l) {
    const Node& nd = nodes_[leaves_[l]];
    std::fill(leaf_of.begin() + nd.vertex_begin, leaf_of.begin() + nd.vertex_end, static_cast<Index>(l));
  }
  // The distinct leaves of a tetrahedron, in increasing order.
  auto distinct_leaves = [&](const Tetrahedron& c, std::array<Index, 4>& out) {
    std::array<Index, 4> l{{leaf_of[c[0]], leaf_of[c[1]], leaf_of[c[2]], leaf_of[c[3]]}};
    std::sort(l.begin(), l.end());
    int k = 0;
    for (int i = 0; i < 4; ++i)
      if (i == 0 || l[i] != l[i - 1]) out[k++] = l[i];
    return k;
  };
  // The owner of a tetrahedron is the leaf of its smallest vertex, i.e. its first distinct leaf:
  // as T is sorted by smallest vertex, each leaf owns a contiguous range of T, found by binary
  // search.  The other leaves list it explicitly, in increasing order: T is cut into chunks (one
  // per task), each counting and then filling its own part of every list, so any number of
  // threads gives the same lists.
  const auto smallest = [&](const Tetrahedron& c) {
    return (std::min)((std::min)(c[0], c[1]), (std::min)(c[2], c[3]));
  };
  std::vector<std::size_t> owned(nl + 1, nt);
  if (from_compact) { // the leaves' vertex ranges are consecutive: running sums of the counts
    std::size_t sum = 0;
    for (std::size_t l = 0; l < nl; ++l) {
      owned[l] = sum;
      const Node& nd = nodes_[leaves_[l]];
      for (Index v = nd.vertex_begin; v < nd.vertex_end; ++v) sum += compact_tetrahedra_.count(v);
    }
  } else {
    for (std::size_t l = 0; l < nl; ++l) {
      const Index vb = nodes_[leaves_[l]].vertex_begin;
      owned[l] = static_cast<std::size_t>(
          std::partition_point(tetrahedra_.begin(), tetrahedra_.end(),
                               [&](const Tetrahedron& c) { return smallest(c) < vb; }) -
          tetrahedra_.begin());
    }
  }
  const std::size_t chunks = PR_star_octree::internal::is_parallel<ConcurrencyTag>()
                                 ? (std::min)(std::size_t(16), (std::max)(std::size_t(1), nt >> 16))
                                 : std::size_t(1);
  const std::size_t chunk_size = chunks ? (nt + chunks - 1) / chunks : nt;
  std::vector<Index> count(chunks * nl, 0); // [chunk][leaf]
  PR_star_octree::internal::for_each_block<ConcurrencyTag>(chunks, 1, [&](std::size_t cb, std::size_t ce) {
    std::array<Index, 4> ls;
    for (std::size_t c = cb; c < ce; ++c)
      for_each_in(c * chunk_size, (std::min)(nt, (c + 1) * chunk_size),
                  [&](std::size_t, const Tetrahedron& tet) {
                    const int k = distinct_leaves(tet, ls);
                    for (int i = 1; i < k; ++i) ++count[c * nl + ls[i]];
                  });
  });
  std::size_t total = 0;
  for (Index n : count) total += n;
  if (total >= static_cast<std::size_t>(no_node))
    throw std::invalid_argument("PR_star_octree_3: the leaf lists do not fit the index type");
  total = 0; // count becomes the position where each chunk writes into each list
  std::vector<std::size_t> shared(nl + 1, 0);
  for (std::size_t l = 0; l < nl; ++l) {
    shared[l] = total;
    for (std::size_t c = 0; c < chunks; ++c) {
      const std::size_t n = count[c * nl + l];
      count[c * nl + l] = static_cast<Index>(total);
      total += n;
    }
  }
  shared[nl] = total;
  std::vector<Index> list(total);
  for (std::size_t l = 0; l < nl; ++l) {
    Node& nd = nodes_[leaves_[l]];
    nd.owned_begin = static_cast<Index>(owned[l]);
    nd.owned_end = static_cast<Index>(owned[l + 1]);
    nd.shared_begin = static_cast<Index>(shared[l]);
    nd.shared_end = static_cast<Index>(shared[l + 1]);
  }
  PR_star_octree::internal::for_each_block<ConcurrencyTag>(chunks, 1, [&](std::size_t cb, std::size_t ce) {
    std::array<Index, 4> ls;
    for (std::size_t c = cb; c < ce; ++c)
      for_each_in(c * chunk_size, (std::min)(nt, (c + 1) * chunk_size),
                  [&](std::size_t t, const Tetrahedron& tet) {
                    const int k = distinct_leaves(tet, ls);
                    CGAL_assertion(t >= owned[ls[0]] && t < owned[ls[0] + 1]);
                    for (int i = 1; i < k; ++i) list[count[c * nl + ls[i]]++] = static_cast<Index>(t);
                  });
  });
  std::vector<Index>().swap(count);

  // The compact encoding, leaf by leaf: a new group when an index is 2^16 or more past the base.
  const auto for_each_group = [&](std::size_t l, auto f) { // f(group position in leaf, first entry)
    const std::size_t b = shared[l], e = shared[l + 1];
    std::size_t g = 0;
    for (std::size_t i = b; i < e; ++i)
      if (i == b || list[i] - list[g] > 0xFFFF) {
        g = i;
        f(i);
      }
  };
  std::vector<Index> groups(nl + 1, 0);
  PR_star_octree::internal::for_each_block<ConcurrencyTag>(nl, 1024, [&](std::size_t lb, std::size_t le) {
    for (std::size_t l = lb; l < le; ++l) for_each_group(l, [&](std::size_t) { ++groups[l + 1]; });
  });
  for (std::size_t l = 0; l < nl; ++l) groups[l + 1] += groups[l];
  PR_star_octree::internal::resize_huge(leaf_offsets_, total);
  PR_star_octree::internal::resize_huge(leaf_groups_, groups[nl]);
  PR_star_octree::internal::for_each_block<ConcurrencyTag>(nl, 1024, [&](std::size_t lb, std::size_t le) {
    for (std::size_t l = lb; l < le; ++l) {
      Node& nd = nodes_[leaves_[l]];
      nd.group_begin = groups[l];
      nd.group_end = groups[l + 1];
      std::size_t g = groups[l];
      for_each_group(l, [&](std::size_t first) {
        if (g > groups[l]) leaf_groups_[g - 1].end = static_cast<Index>(first - shared[l]);
        leaf_groups_[g++] = {list[first], 0};
      });
      if (g > groups[l]) leaf_groups_[g - 1].end = static_cast<Index>(shared[l + 1] - shared[l]);
      std::size_t start = shared[l];
      for (std::size_t k = groups[l]; k < groups[l + 1]; ++k) {
        const std::size_t end = shared[l] + leaf_groups_[k].end;
        for (std::size_t i = start; i < end; ++i)
          leaf_offsets_[i] = static_cast<std::uint16_t>(list[i] - leaf_groups_[k].base);
        start = end;
      }
    }
  });
}

// ---------------------------------------------------------------------------------------------
// Statistics
// ---------------------------------------------------------------------------------------------

template <class GT, class I>
typename PR_star_octree_3<GT, I>::Statistics PR_star_octree_3<GT, I>::statistics() const {
  Statistics s;
  s.vertices = number_of_vertices();
  s.float32_coordinates = float_coordinates_;
  s.tetrahedra = number_of_tetrahedra();
  s.compact_tetrahedra = compact_;
  s.bucket_size = bucket_size_;
  s.automatic_bucket_size = automatic_;
  s.bucket_size_choice = choice_;
  s.infinite_bucket_size = (bucket_size_ == infinite_bucket_size);
  s.max_depth = max_depth_;
  s.nodes = nodes_.size();
  s.leaves = leaves_.size();
  s.depth = depth_;
  s.depth_limited_leaves = depth_limited_leaves_;
  s.coincident_leaves = coincident_leaves_;
  s.reoriented_tetrahedra = reoriented_count_;
  s.degenerate_tetrahedra = degenerate_tetrahedra_;
  s.leaf_tetrahedra_entries = leaf_offsets_.size() + number_of_tetrahedra();
  for (Node_index n : leaves_) {
    const Node& nd = nodes_[n];
    if (nd.vertex_begin == nd.vertex_end) ++s.empty_leaves;
    s.max_leaf_vertices = (std::max)(s.max_leaf_vertices, nd.number_of_vertices());
    s.max_leaf_tetrahedra = (std::max)(s.max_leaf_tetrahedra, nd.number_of_tetrahedra());
  }

  // Unreferenced and duplicate vertices (coincident points always share a leaf).
  std::vector<bool> referenced(number_of_vertices(), false);
  for (const Tetrahedron c : tetrahedra())
    for (Index v : c) referenced[v] = true;
  s.unreferenced_vertices = static_cast<std::size_t>(std::count(referenced.begin(), referenced.end(), false));
  std::vector<std::array<double, 3>> xyz;
  for (Node_index n : leaves_) {
    const Node& nd = nodes_[n];
    xyz.clear();
    for (Index v = nd.vertex_begin; v < nd.vertex_end; ++v) xyz.push_back(coordinates(point(v)));
    std::sort(xyz.begin(), xyz.end());
    for (std::size_t i = 1; i < xyz.size(); ++i)
      if (xyz[i] == xyz[i - 1]) ++s.duplicate_vertices;
  }

  s.compute_cost_model();

  s.bytes.points =
      points_.capacity() * sizeof(Point_3) + float_points_.capacity() * sizeof(std::array<float, 3>);
  s.bytes.scalars = scalars_.capacity() * sizeof(double);
  s.bytes.labels = labels_.capacity() * sizeof(int);
  for (int l : labels_) ++s.subdomains[l];
  if (has_labels_ && labels_.empty() && number_of_tetrahedra() > 0)
    s.subdomains[uniform_label_] = number_of_tetrahedra();
  s.bytes.tetrahedra =
      compact_ ? compact_tetrahedra_.memory_bytes() : tetrahedra_.capacity() * sizeof(Tetrahedron);
  s.bytes.nodes = nodes_.capacity() * sizeof(Node) + leaves_.capacity() * sizeof(Node_index);
  s.bytes.leaf_tetrahedra =
      leaf_offsets_.capacity() * sizeof(std::uint16_t) +
      leaf_groups_.capacity() * sizeof(PR_star_octree::internal::Leaf_list_group<Index>);
  s.bytes.permutations =
      (vertex_to_original_.capacity() + tetrahedron_to_original_.capacity()) * sizeof(Index);
  s.bytes.reorientation = reoriented_.capacity() * sizeof(std::uint64_t);
  return s;
}

} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_PR_STAR_OCTREE_3_IMPL_H
