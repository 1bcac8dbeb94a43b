// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_LOCAL_COMPLEX_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_LOCAL_COMPLEX_H

// The local-complex kernel: the one implementation of the local topology that every part of the
// package derives from a set of tetrahedra (a leaf's list, or the stars of a mesh being simplified):
//   - grouping of sorted records (face pairing, edge grouping, boundary edges),
//   - the faces of a set of tetrahedra paired into triangles (TT, boundary and non-manifold faces),
//   - the fan of tetrahedra around an edge (its star in cyclic order, its link, its boundary wings),
//   - the link of a vertex (link vertices, edges with multiplicities, triangles; sphere/disc test),
//   - the vertex-vertex relation of a star.
// Tetrahedra are `std::array<Index, 4>`, positively oriented, looked up by index in an array `T`.

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

// For a positively oriented tetrahedron c, (c[k], c[link_face[k][0]], c[link_face[k][1]],
// c[link_face[k][2]]) is positively oriented too: each row is an even permutation putting k first.
constexpr int link_face[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

// The position of `v` in tetrahedron `c`, or -1.
template <class Tetrahedron, class Index>
inline int position(const Tetrahedron& c, Index v) {
  for (int k = 0; k < 4; ++k)
    if (c[k] == v) return k;
  return -1;
}

template <class Tetrahedron, class Index>
inline bool contains(const Tetrahedron& c, Index v) {
  return c[0] == v || c[1] == v || c[2] == v || c[3] == v;
}

// Calls `f(first, last)` for each maximal run [first, last) of consecutive elements that are
// `same()` as the run's first element (on a sorted range: each group of equal keys).
template <class Iterator, class Same, class Function>
void for_each_group(Iterator first, Iterator last, Same same, Function f) {
  while (first != last) {
    Iterator next = first;
    ++next;
    while (next != last && same(*first, *next)) ++next;
    f(first, next);
    first = next;
  }
}

// Sorts `v` and removes duplicates.
template <class Vector>
void sort_unique(Vector& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// The size of the intersection of two sorted ranges of distinct elements.
template <class Vector>
std::size_t intersection_size(const Vector& a, const Vector& b) {
  std::size_t n = 0;
  auto i = a.begin(), j = b.begin();
  while (i != a.end() && j != b.end()) {
    if (*i < *j)
      ++i;
    else if (*j < *i)
      ++j;
    else {
      ++n;
      ++i;
      ++j;
    }
  }
  return n;
}

// ---------------------------------------------------------------------------------------------
// Vertex-tetrahedra of a leaf
// ---------------------------------------------------------------------------------------------

// VT (paper Algorithm 1) of the vertices [vb, vb + nv) from the tetrahedra `shared` (a range of
// indices into T) and the contiguous range `owned` of T, in CSR form: the star of vertex vb + i is
// vt[offsets[i], offsets[i + 1]), in increasing tetrahedron order when `shared` precedes `owned`
// and is sorted.  One pass over the tetrahedra appends their corners in the leaf to `scratch` as
// (vertex slot, tetrahedron) pairs, without a branch (a corner outside the leaf is written, then
// overwritten); a counting sort of the pairs follows.  (Counting the corners outside in a dummy
// slot instead serialises the loop on that slot's counter.)
template <class Tetrahedra, class Shared, class Index>
void build_leaf_vertex_tetrahedra(const Tetrahedra& T, const Shared& shared, std::pair<Index, Index> owned,
                                  Index vb, std::size_t nv, std::vector<Index>& offsets,
                                  std::vector<Index>& vt, std::vector<Index>& scratch) {
  const std::size_t n_shared = static_cast<std::size_t>(std::distance(shared.begin(), shared.end()));
  const std::size_t n = n_shared + (owned.second - owned.first);
  scratch.resize(8 * n + nv + 2); // the pairs, then the insertion positions
  Index* corners = scratch.data();
  std::size_t m = 0;
  auto add = [&](Index t) {
    const auto& c = T[t];
    for (int k = 0; k < 4; ++k) {
      const std::size_t d = static_cast<Index>(c[k] - vb); // wraps around for c[k] < vb
      corners[2 * m] = static_cast<Index>(d);
      corners[2 * m + 1] = t;
      m += (d < nv);
    }
  };
  for (Index t : shared) add(t);
  for (Index t = owned.first; t < owned.second; ++t) add(t);
  offsets.assign(nv + 1, 0);
  for (std::size_t j = 0; j < m; ++j) ++offsets[corners[2 * j] + 1];
  for (std::size_t i = 0; i < nv; ++i) offsets[i + 1] += offsets[i];
  vt.resize(m);
  Index* pos = corners + 2 * m;
  std::copy(offsets.begin(), offsets.end() - 1, pos);
  Index* out = vt.data();
  for (std::size_t j = 0; j < m; ++j) out[pos[corners[2 * j]]++] = corners[2 * j + 1];
}

// ---------------------------------------------------------------------------------------------
// Face pairing
// ---------------------------------------------------------------------------------------------

// The faces of a set of tetrahedra, sorted by their (sorted) vertices and grouped: one group per
// triangle, holding the tetrahedra incident in it (one on the boundary, two inside, three or more
// for a non-manifold triangle).
template <class Index>
class Face_pairing {
public:
  struct Record {
    std::array<Index, 3> v; // sorted vertices of the face
    Index local;            // position of the tetrahedron in the caller's list
    int k;                  // the face is opposite vertex k of the tetrahedron
    bool operator<(const Record& o) const { return std::tie(v, local) < std::tie(o.v, o.local); }
  };

  // Collects the faces of the tetrahedra `list[i]` of `T` that have a vertex in `[vb, ve)`, sorted
  // by `Record::operator<` (a total order: a tetrahedron has each face once).  Such a face's
  // smallest vertex is below `ve`: the faces whose smallest vertex is below `vb` (those of the
  // tetrahedra shared with earlier leaves, the fewer) are sorted by their smallest vertex with a
  // stable radix sort (11-bit digits); the others are placed by their smallest vertex (a counting
  // sort, stable); then each smallest vertex's few are sorted by their other two vertices (stably:
  // ties stay in list order, the order of `local`).  The result is the order of one sort of all the
  // records, in a fraction of its time.
  template <class Tetrahedra, class List>
  void build(const Tetrahedra& T, const List& list, Index vb, Index ve) {
    const std::size_t n = static_cast<std::size_t>(ve - vb);
    records_.clear();
    local_.clear();
    counts_.assign(n + 1, 0);
    Index i = 0;
    for (auto it = list.begin(); it != list.end(); ++it, ++i) {
      const auto& c = T[*it];
      // the four vertices sorted, with their positions in the tetrahedron
      std::array<Index, 4> s{{c[0], c[1], c[2], c[3]}};
      std::array<int, 4> p{{0, 1, 2, 3}};
      for (int a = 1; a < 4; ++a)
        for (int b = a; b > 0 && s[b] < s[b - 1]; --b) {
          std::swap(s[b], s[b - 1]);
          std::swap(p[b], p[b - 1]);
        }
      unsigned in_leaf = 0;
      for (int a = 0; a < 4; ++a) in_leaf |= unsigned(vb <= s[a] && s[a] < ve) << a;
      for (int j = 0; j < 4; ++j) { // the face opposite the j-th smallest vertex, sorted
        if ((in_leaf & ~(1u << j)) == 0) continue;
        const Record r{{{s[j == 0 ? 1 : 0], s[j <= 1 ? 2 : 1], s[j <= 2 ? 3 : 2]}}, i, p[j]};
        if (r.v[0] < vb) {
          records_.push_back(r);
        } else {
          local_.push_back(r);
          ++counts_[r.v[0] - vb + 1];
        }
      }
    }
    const std::size_t shared = records_.size();
    radix_sort_by_smallest(vb);
    sort_groups_by_other_two(records_.data(), records_.data() + shared);
    for (std::size_t a = 0; a < n; ++a) counts_[a + 1] += counts_[a];
    records_.resize(shared + local_.size());
    Record* out = records_.data() + shared;
    for (const Record& r : local_) out[counts_[r.v[0] - vb]++] = r; // counts_[a]: now the end of a
    for (std::size_t a = 0, b = 0; a < n; b = counts_[a++]) sort_by_other_two(out + b, out + counts_[a]);
  }

  // Calls `f(first, last)` with the records of each triangle.
  template <class Function>
  void for_each_triangle(Function f) const {
    for_each_group(
        records_.begin(), records_.end(), [](const Record& a, const Record& b) { return a.v == b.v; }, f);
  }

  std::size_t capacity_bytes() const {
    return (records_.capacity() + local_.capacity() + scratch_.capacity()) * sizeof(Record) +
           counts_.capacity() * sizeof(std::size_t);
  }

private:
  static bool by_other_two(const Record& x, const Record& y) {
    return x.v[1] < y.v[1] || (x.v[1] == y.v[1] && x.v[2] < y.v[2]);
  }
  // sorts records of one smallest vertex, in list order, by their other two vertices, stably
  static void sort_by_other_two(Record* first, Record* last) {
    if (last - first > 64) {
      std::stable_sort(first, last, by_other_two);
      return;
    }
    for (Record* x = first + 1; x < last; ++x) { // insertion sort: stable
      if (!by_other_two(*x, *(x - 1))) continue;
      const Record r = *x;
      Record* y = x;
      do {
        *y = *(y - 1);
        --y;
      } while (y > first && by_other_two(r, *(y - 1)));
      *y = r;
    }
  }
  // the same for each run of one smallest vertex of `[first, last)`, sorted by smallest vertex
  static void sort_groups_by_other_two(Record* first, Record* last) {
    while (first < last) {
      Record* end = first + 1;
      while (end < last && end->v[0] == first->v[0]) ++end;
      sort_by_other_two(first, end);
      first = end;
    }
  }
  // Sorts `records_` (all with a smallest vertex below `bound`) by smallest vertex, stably: least
  // significant digit first, as many 11-bit digits as `bound` needs.
  void radix_sort_by_smallest(Index bound) {
    constexpr unsigned bits = 11, radix = 1u << bits;
    const std::size_t n = records_.size();
    if (n < 2) return;
    if (n <= 32) { // insertion sort: stable, faster than the passes for a few
      for (std::size_t x = 1; x < n; ++x)
        for (std::size_t y = x; y > 0 && records_[y].v[0] < records_[y - 1].v[0]; --y)
          std::swap(records_[y], records_[y - 1]);
      return;
    }
    scratch_.resize(n);
    std::size_t histogram[radix];
    for (unsigned shift = 0; shift < 8 * sizeof(Index) && (static_cast<std::uint64_t>(bound) >> shift) != 0;
         shift += bits) {
      std::fill(histogram, histogram + radix, std::size_t(0));
      for (const Record& r : records_)
        ++histogram[(static_cast<std::uint64_t>(r.v[0]) >> shift) & (radix - 1)];
      std::size_t sum = 0;
      for (std::size_t& h : histogram) sum += std::exchange(h, sum);
      for (const Record& r : records_)
        scratch_[histogram[(static_cast<std::uint64_t>(r.v[0]) >> shift) & (radix - 1)]++] = r;
      records_.swap(scratch_);
    }
  }

  std::vector<Record> records_, local_, scratch_;
  std::vector<std::size_t> counts_;
};

// ---------------------------------------------------------------------------------------------
// Edge fans
// ---------------------------------------------------------------------------------------------

// The star of an edge (v0, v1): its tetrahedra in cyclic order around it (right-hand rule around
// v0 -> v1) and its link (the vertices opposite the edge, in the same order; one more vertex than
// tetrahedra for an open fan, i.e. a boundary edge).  When the star is neither a closed cycle nor
// a single open fan, the edge is non-manifold: the tetrahedra stay in the given order and the link
// lists the two opposite vertices of each.
template <class Index>
class Edge_fan {
public:
  // Each tetrahedron of the star is a directed edge of the link polygon, from wing to wing:
  // (v0, v1, from, to) is positively oriented.
  struct Wing {
    Index t, from, to;
  };

  // `star`: the tetrahedra containing both v0 and v1 (any order; ties are broken by this order).
  template <class Tetrahedra, class Star>
  void build(const Tetrahedra& T, const Star& star, Index v0, Index v1) {
    make_wings(T, star, v0, v1);
    chain();
  }

  // Only the wings (no cyclic order): enough for `boundary_wings()`.
  template <class Tetrahedra, class Star>
  void make_wings(const Tetrahedra& T, const Star& star, Index v0, Index v1) {
    wings_.clear();
    for (Index t : star) {
      const auto& c = T[t];
      const int p0 = position(c, v0), p1 = position(c, v1);
      CGAL_precondition(v0 != v1 && p0 >= 0 && p1 >= 0); // every tetrahedron of the star holds the edge
      Index w[2];
      int pw[2], n = 0;
      for (int k = 0; k < 4; ++k)
        if (k != p0 && k != p1) {
          w[n] = c[k];
          pw[n++] = k;
        }
      // Parity of the permutation (p0, p1, pw0, pw1) of (0, 1, 2, 3).
      const int perm[4] = {p0, p1, pw[0], pw[1]};
      int inversions = 0;
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) inversions += perm[i] > perm[j];
      if (inversions % 2 == 0)
        wings_.push_back(Wing{t, w[0], w[1]});
      else
        wings_.push_back(Wing{t, w[1], w[0]});
    }
  }

  const std::vector<Wing>& wings() const { return wings_; }
  // in cyclic order (after `build()`)
  const std::vector<Index>& tetrahedra() const { return tets_; }
  const std::vector<Index>& link() const { return link_; }
  bool is_boundary() const { return open_; }
  bool is_nonmanifold() const { return nonmanifold_; }

  // The third vertices of the triangles (v0, v1, w) of the star that are incident in a single
  // tetrahedron (boundary triangles), sorted.  Valid after `make_wings()` or `build()`.
  const std::vector<Index>& boundary_wings() {
    all_.clear();
    for (const Wing& x : wings_) {
      all_.push_back(x.from);
      all_.push_back(x.to);
    }
    std::sort(all_.begin(), all_.end());
    single_.clear();
    for_each_group(
        all_.begin(), all_.end(), [](Index a, Index b) { return a == b; },
        [&](auto first, auto last) {
          if (last - first == 1) single_.push_back(*first);
        });
    return single_;
  }

private:
  // Chain the wings: start at a wing whose `from` is nobody's `to` (open fan), else at the first.
  void chain() {
    const std::size_t n = wings_.size();
    tets_.clear();
    link_.clear();
    nonmanifold_ = false;
    open_ = false;
    std::size_t start = 0;
    for (std::size_t i = 0; i < n && !open_; ++i) {
      bool is_target = false;
      for (const Wing& x : wings_) is_target = is_target || x.to == wings_[i].from;
      if (!is_target) {
        start = i;
        open_ = true;
      }
    }
    std::size_t cur = start;
    visited_.assign(n, 0);
    link_.push_back(wings_[cur].from);
    for (std::size_t step = 0; step < n; ++step) {
      visited_[cur] = 1;
      tets_.push_back(wings_[cur].t);
      const Index to = wings_[cur].to;
      if (step + 1 < n || open_) link_.push_back(to);
      std::size_t next = n;
      for (std::size_t i = 0; i < n; ++i)
        if (wings_[i].from == to) {
          if (next != n) nonmanifold_ = true; // two tetrahedra leave the same face
          next = i;
        }
      // Stuck, or back to a visited tetrahedron before the end: several fans or cycles.
      if (step + 1 < n && (next == n || visited_[next])) {
        nonmanifold_ = true;
        break;
      }
      cur = next;
    }
    if (!open_ && cur != start) nonmanifold_ = true;
    if (nonmanifold_) { // not a fan nor a cycle: keep the star in the given order
      tets_.clear();
      link_.clear();
      for (const Wing& x : wings_) {
        tets_.push_back(x.t);
        link_.push_back(x.from);
        link_.push_back(x.to);
      }
    }
  }

  std::vector<Wing> wings_;
  std::vector<Index> tets_, link_, all_, single_;
  std::vector<unsigned char> visited_;
  bool open_ = false, nonmanifold_ = false;
};

// ---------------------------------------------------------------------------------------------
// Vertex links
// ---------------------------------------------------------------------------------------------

// An open-addressing map from keys (one or two indices) to dense ids, cleared in O(1) by a
// generation stamp.
template <class Key>
class Small_map {
public:
  void reset(std::size_t n) {
    std::size_t size = 16;
    while (size < 2 * n) size *= 2;
    if (slots_.size() < size) {
      slots_.assign(size, Slot());
      generation_ = 0;
    }
    mask_ = size - 1;
    if (++generation_ == 0) {
      for (Slot& s : slots_) s.stamp = 0;
      generation_ = 1;
    }
  }
  // the id of `key`; a new key gets `next`, which is then incremented
  std::uint32_t find_or_insert(const Key& key, std::uint32_t& next) {
    std::size_t h = hash(key) & mask_;
    while (slots_[h].stamp == generation_) {
      if (slots_[h].key == key) return slots_[h].value;
      h = (h + 1) & mask_;
    }
    slots_[h] = Slot{key, next, generation_};
    return next++;
  }

private:
  // key, value and stamp side by side: one cache line per probe
  struct Slot {
    Key key{};
    std::uint32_t value = 0, stamp = 0;
  };

  static std::uint64_t mix(std::uint64_t x) { return (x * 0x9E3779B97F4A7C15ull) >> 32; }
  template <class I>
  static std::size_t hash(I x, std::enable_if_t<std::is_integral<I>::value>* = nullptr) {
    return static_cast<std::size_t>(mix(static_cast<std::uint64_t>(x)));
  }
  template <class I>
  static std::size_t hash(const std::pair<I, I>& e) {
    if constexpr (sizeof(I) <= 4)
      return static_cast<std::size_t>(
          mix(static_cast<std::uint64_t>(e.first) << 32 | static_cast<std::uint64_t>(e.second)));
    else
      return static_cast<std::size_t>(mix(static_cast<std::uint64_t>(e.first) * 0xC2B2AE3D27D4EB4Full ^
                                          static_cast<std::uint64_t>(e.second)));
  }

  std::vector<Slot> slots_;
  std::uint32_t generation_ = 0;
  std::size_t mask_ = 0;
};

// Union-find on small dense index sets.
class Union_find {
public:
  void reset(std::size_t n) {
    parent_.resize(n);
    for (std::size_t i = 0; i < n; ++i) parent_[i] = static_cast<std::uint32_t>(i);
  }
  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  bool unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent_[a] = b;
    return true;
  }

private:
  std::vector<std::uint32_t> parent_;
};

// The link of a vertex v, from its star: one link triangle per tetrahedron (the face opposite v),
// the link edges with their multiplicities (a link edge (a, b) is the triangle (v, a, b); it is in
// one link triangle when that triangle is on the boundary of the mesh, two inside, three or more
// when it is non-manifold) and, on request, the link vertices.
template <class Index>
class Vertex_link {
public:
  struct Edge {
    Index a, b;           // the two vertices, a < b
    std::uint32_t ia, ib; // their link vertex ids (when built with vertices)
    std::uint32_t count;  // the number of link triangles containing the edge
  };

  // Builds the link of `v` from its star (tetrahedron indices into `T`).  Stops early, returning
  // false, as soon as a link edge is found in three link triangles when `stop_at_nonmanifold`.
  template <class Tetrahedra, class Star>
  bool build(const Tetrahedra& T, const Star& star, Index v, bool with_vertices, bool stop_at_nonmanifold) {
    const std::size_t n = static_cast<std::size_t>(std::distance(star.begin(), star.end()));
    start(n, with_vertices);
    for (Index t : star) {
      const auto& c = T[t];
      Index o[3];
      int m = 0;
      for (int k = 0; k < 4; ++k)
        if (c[k] != v) o[m++] = c[k];
      if (!add_triangle(o, stop_at_nonmanifold)) return false;
    }
    return true;
  }

  // The same from the link triangles themselves (three vertices each, any order).
  template <class Triangles>
  bool build_from_triangles(const Triangles& triangles, bool with_vertices, bool stop_at_nonmanifold) {
    start(static_cast<std::size_t>(std::distance(triangles.begin(), triangles.end())), with_vertices);
    for (const auto& f : triangles) {
      const Index o[3] = {f[0], f[1], f[2]};
      if (!add_triangle(o, stop_at_nonmanifold)) return false;
    }
    return true;
  }

  std::size_t number_of_triangles() const { return triangles_; }
  const std::vector<Edge>& edges() const { return edges_; }
  // the link vertices, in order of first appearance (built with vertices only)
  const std::vector<Index>& vertices() const { return vertices_; }
  std::size_t number_of_boundary_edges() const {
    std::size_t n = 0;
    for (const Edge& e : edges_) n += (e.count == 1);
    return n;
  }
  // The paper's test (Section 7): in a closed link every edge bounds two triangles, 2|e| = 3|t|.
  bool euler_count_says_boundary() const { return 2 * edges_.size() != 3 * triangles_; }

  // Whether the link is a triangulated sphere or disc: Euler characteristic 2 (closed) or 1, connected,
  // every edge in at most two triangles, the boundary a single simple loop.  Needs the vertices.
  bool is_sphere_or_disc() {
    const std::size_t nv = vertices_.size();
    std::size_t boundary_edges = 0;
    for (const Edge& e : edges_) {
      if (e.count > 2) return false;
      boundary_edges += (e.count == 1);
    }
    const long long chi = static_cast<long long>(nv) - static_cast<long long>(edges_.size()) +
                          static_cast<long long>(triangles_);
    if (boundary_edges == 0 ? chi != 2 : chi != 1) return false;
    uf_.reset(nv);
    std::size_t components = nv;
    for (const Edge& e : edges_)
      if (uf_.unite(e.ia, e.ib)) --components;
    if (components != 1) return false;
    if (boundary_edges == 0) return true;
    boundary_degree_.assign(nv, 0);
    std::size_t boundary_vertices = 0;
    for (const Edge& e : edges_)
      if (e.count == 1) {
        boundary_vertices += (boundary_degree_[e.ia]++ == 0);
        boundary_vertices += (boundary_degree_[e.ib]++ == 0);
      }
    for (std::size_t i = 0; i < nv; ++i)
      if (boundary_degree_[i] != 0 && boundary_degree_[i] != 2) return false;
    // All boundary vertices of degree 2: disjoint cycles; a single loop is connected.
    if (boundary_vertices != boundary_edges) return false;
    uf_.reset(nv);
    std::size_t loops = boundary_vertices;
    for (const Edge& e : edges_)
      if (e.count == 1 && uf_.unite(e.ia, e.ib)) --loops;
    return loops == 1;
  }

private:
  void start(std::size_t n, bool with_vertices) {
    triangles_ = n;
    with_vertices_ = with_vertices;
    if (with_vertices) {
      vertex_ids_.reset(3 * n);
      vertices_.clear();
    }
    edge_ids_.reset(3 * n);
    edges_.clear();
    nv_ = 0;
  }

  // Adds the link triangle `o`; false when one of its edges is now in three triangles and `stop`.
  bool add_triangle(const Index (&o)[3], bool stop) {
    std::uint32_t id[3] = {0, 0, 0};
    if (with_vertices_)
      for (int i = 0; i < 3; ++i) {
        id[i] = vertex_ids_.find_or_insert(o[i], nv_);
        if (id[i] == vertices_.size()) vertices_.push_back(o[i]);
      }
    static const int pairs[3][2] = {{0, 1}, {1, 2}, {0, 2}};
    for (const auto& p : pairs) {
      const Index a = o[p[0]], b = o[p[1]];
      std::uint32_t next = static_cast<std::uint32_t>(edges_.size());
      const bool ordered = a < b;
      const std::uint32_t e =
          edge_ids_.find_or_insert(ordered ? std::make_pair(a, b) : std::make_pair(b, a), next);
      if (e == edges_.size())
        edges_.push_back(ordered ? Edge{a, b, id[p[0]], id[p[1]], 0} : Edge{b, a, id[p[1]], id[p[0]], 0});
      if (++edges_[e].count > 2 && stop) return false;
    }
    return true;
  }

  std::size_t triangles_ = 0;
  std::uint32_t nv_ = 0;
  bool with_vertices_ = false;
  Small_map<Index> vertex_ids_;
  Small_map<std::pair<Index, Index>> edge_ids_;
  std::vector<Edge> edges_;
  std::vector<Index> vertices_;
  std::vector<unsigned char> boundary_degree_;
  Union_find uf_;
};

// ---------------------------------------------------------------------------------------------
// The links of all the vertices of a leaf
// ---------------------------------------------------------------------------------------------

// The number of bits set.  Without a target that has the instruction (-mpopcnt, -march=...), GCC
// compiles __builtin_popcountll to a call into libgcc: 5% of `compute_boundary` in perf; the bit
// trick below is inline.
inline int popcount64(std::uint64_t x) {
#if defined(__POPCNT__) && (defined(__GNUC__) || defined(__clang__))
  return __builtin_popcountll(x);
#else
  x = x - ((x >> 1) & 0x5555555555555555ull);
  x = (x & 0x3333333333333333ull) + ((x >> 2) & 0x3333333333333333ull);
  x = (x + (x >> 4)) & 0x0F0F0F0F0F0F0F0Full;
  return static_cast<int>((x * 0x0101010101010101ull) >> 56);
#endif
}

inline int lowest_bit64(std::uint64_t x) { // x != 0
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_ctzll(x);
#else
  int n = 0;
  while (!(x & 1)) {
    x >>= 1;
    ++n;
  }
  return n;
#endif
}

// What the link of a vertex is; the values are those of `Vertex_type`.
enum class Link_kind : unsigned char {
  EMPTY = 0,  // the vertex is in no tetrahedron
  CLOSED = 1, // every link edge in two link triangles (and, when checked, the link is a sphere)
  OPEN = 2,   // a link edge in one link triangle (and, when checked, the link is a disc)
  OTHER = 3   // a link edge in three or more link triangles, or (when checked) neither sphere nor disc
};

// The links of all the vertices of a leaf at once, from the leaf's tetrahedra only: the same
// answers as `Vertex_link` (`build()` stopping at a non-manifold edge, then `is_sphere_or_disc()`
// when checked, then `euler_count_says_boundary()`) vertex by vertex, faster.
//  - The vertices of the leaf's tetrahedra get dense local ids: `v - vb` for the leaf's own
//    vertices, `nv + i` for the others (hashed once per leaf, not once per star).
//  - The link triangles of the leaf's vertices are gathered in CSR form by one counting and one
//    filling pass over the tetrahedra, as VT is.
//  - Each link with at most 64 vertices is tested on 64-bit adjacency masks of its vertices (the
//    multiplicity of an edge is "seen" and "seen twice" bits, connectivity a breadth-first search on
//    masks); a larger link goes through `Vertex_link` on the local ids.
// All of it is exact integer work: the kind of a vertex does not depend on the order of anything.
template <class Index>
class Leaf_links {
public:
  // Classifies the vertices [vb, vb + nv) from the tetrahedra `shared` (indices into T) and the
  // contiguous range `owned` of T (together: every tetrahedron incident in those vertices).
  // With `keep_tetrahedra`, the leaf's tetrahedra are also kept in local ids (see `tetrahedron()`).
  // Without `classify`, only the local ids (and the tetrahedra, when kept) are built.
  template <class Tetrahedra, class Shared>
  void build(const Tetrahedra& T, const Shared& shared, std::pair<Index, Index> owned, Index vb,
             std::size_t nv, bool check_links, bool keep_tetrahedra = false, bool classify_links = true) {
    if (keep_tetrahedra) // (a constant in the loop over the tetrahedra)
      gather<true>(T, shared, owned, vb, nv);
    else
      gather<false>(T, shared, owned, vb, nv);
    kinds_.resize(classify_links ? nv : 0);
    if (classify_links)
      for (std::size_t i = 0; i < nv; ++i) kinds_[i] = classify(i, check_links);
  }

  // the bytes held (the buffers' capacities)
  std::size_t memory_bytes() const {
    return corners_.capacity() * sizeof(Corner) + (offsets_.capacity() + pos_.capacity()) * 4 +
           triangles_.capacity() * sizeof(Triangle) + vertices_.capacity() * sizeof(Index) +
           tetrahedra_.capacity() * 16 + stamps_.capacity() * 4 + link_ids_.capacity() + kinds_.capacity();
  }

  // the kind of the link of vertex vb + i
  Link_kind kind(std::size_t i) const { return kinds_[i]; }

  // The local ids: [0, nv) for the leaf's vertices, then the other vertices of its tetrahedra.
  std::size_t number_of_ids() const { return vertices_.size(); }
  // the vertex of local id `j`
  Index vertex(std::size_t j) const { return vertices_[j]; }
  // tetrahedron `i` of the leaf (in the order of `shared`, then `owned`) in local ids (after a
  // `build()` keeping them)
  const std::array<std::uint32_t, 4>& tetrahedron(std::size_t i) const { return tetrahedra_[i]; }

private:
  using Triangle = std::array<std::uint32_t, 3>;

  // Local ids and the CSR of the link triangles of each leaf vertex: one pass over the
  // tetrahedra appends the link triangle of each corner in the leaf (branch-free, as VT), then a
  // counting sort groups them by vertex.
  template <bool keep_tetrahedra, class Tetrahedra, class Shared>
  void gather(const Tetrahedra& T, const Shared& shared, std::pair<Index, Index> owned, Index vb,
              std::size_t nv) {
    const std::size_t n_tets =
        static_cast<std::size_t>(std::distance(shared.begin(), shared.end())) + (owned.second - owned.first);
    others_.reset(3 * n_tets);
    vertices_.resize(nv);
    for (std::size_t i = 0; i < nv; ++i) vertices_[i] = static_cast<Index>(vb + i);
    const std::uint32_t base = static_cast<std::uint32_t>(nv);
    std::uint32_t n_others = 0;
    auto id = [&](Index v) -> std::uint32_t {
      const std::size_t d = static_cast<Index>(v - vb); // wraps around for v < vb
      if (d < nv) return static_cast<std::uint32_t>(d);
      const std::uint32_t j = others_.find_or_insert(v, n_others);
      if (j == vertices_.size() - nv) vertices_.push_back(v);
      return base + j;
    };
    tetrahedra_.resize(keep_tetrahedra ? n_tets : 0);
    corners_.resize(4 * n_tets + 1);
    Corner* corners = corners_.data();
    std::size_t m = 0, n = 0;
    auto add = [&](Index t) {
      const auto& c = T[t];
      const std::array<std::uint32_t, 4> l{{id(c[0]), id(c[1]), id(c[2]), id(c[3])}};
      for (int k = 0; k < 4; ++k) {
        corners[m] = Corner{l[k], {{l[link_face[k][0]], l[link_face[k][1]], l[link_face[k][2]]}}};
        m += (l[k] < base);
      }
      if constexpr (keep_tetrahedra) tetrahedra_[n++] = l;
    };
    for (Index t : shared) add(t);
    for (Index t = owned.first; t < owned.second; ++t) add(t);
    offsets_.assign(nv + 1, 0);
    for (std::size_t j = 0; j < m; ++j) ++offsets_[corners[j].vertex + 1];
    for (std::size_t i = 0; i < nv; ++i) offsets_[i + 1] += offsets_[i];
    pos_.assign(offsets_.begin(), offsets_.end() - 1);
    triangles_.resize(m);
    for (std::size_t j = 0; j < m; ++j) triangles_[pos_[corners[j].vertex]++] = corners[j].link;
  }

  Link_kind classify(std::size_t i, bool check_links) {
    const Triangle* first = triangles_.data() + offsets_[i];
    const Triangle* last = triangles_.data() + offsets_[i + 1];
    if (first == last) return Link_kind::EMPTY;
    // Link vertex ids 0..n-1, stamped per vertex.
    if (stamps_.size() < vertices_.size()) {
      stamps_.resize(vertices_.size(), 0);
      link_ids_.resize(vertices_.size(), 0);
    }
    if (++generation_ == 0) {
      std::fill(stamps_.begin(), stamps_.end(), 0);
      generation_ = 1;
    }
    std::uint32_t n = 0;
    std::uint64_t bad = 0;
    for (const Triangle* f = first; f != last; ++f) {
      std::uint32_t x[3];
      for (int j = 0; j < 3; ++j) {
        const std::uint32_t g = (*f)[j];
        if (stamps_[g] != generation_) {
          if (n == 64) return classify_large(first, last, check_links);
          stamps_[g] = generation_;
          link_ids_[g] = static_cast<unsigned char>(n);
          seen_[n] = twice_[n] = 0;
          ++n;
        }
        x[j] = link_ids_[g];
      }
      add_edge(x[0], x[1], bad);
      add_edge(x[1], x[2], bad);
      add_edge(x[0], x[2], bad);
    }
    if (bad) return Link_kind::OTHER; // an edge in three link triangles or more
    std::uint64_t open = 0;
    for (std::uint32_t a = 0; a < n; ++a) open |= seen_[a] & ~twice_[a];
    if (check_links && !is_sphere_or_disc(n, static_cast<std::size_t>(last - first), open != 0))
      return Link_kind::OTHER;
    return open ? Link_kind::OPEN : Link_kind::CLOSED;
  }

  // One more link triangle on the edge (a, b): its bit in both rows.
  void add_edge(std::uint32_t a, std::uint32_t b, std::uint64_t& bad) {
    const std::uint64_t ba = std::uint64_t(1) << b, bb = std::uint64_t(1) << a;
    bad |= twice_[a] & ba;
    twice_[a] |= seen_[a] & ba;
    twice_[b] |= seen_[b] & bb;
    seen_[a] |= ba;
    seen_[b] |= bb;
  }

  // The vertices reached from vertex `from` through the edges of the rows `adjacency`.
  static std::uint64_t reach(const std::uint64_t* adjacency, std::uint32_t from) {
    std::uint64_t reached = std::uint64_t(1) << from, frontier = reached;
    while (frontier) {
      const int a = lowest_bit64(frontier);
      frontier &= frontier - 1;
      const std::uint64_t fresh = adjacency[a] & ~reached;
      reached |= fresh;
      frontier |= fresh;
    }
    return reached;
  }

  // `Vertex_link::is_sphere_or_disc()` on the masks (every edge in at most two triangles).
  bool is_sphere_or_disc(std::uint32_t n, std::size_t triangles, bool has_boundary) {
    long long edges2 = 0;
    for (std::uint32_t a = 0; a < n; ++a) edges2 += popcount64(seen_[a]);
    const long long chi = static_cast<long long>(n) - edges2 / 2 + static_cast<long long>(triangles);
    if (!has_boundary ? chi != 2 : chi != 1) return false;
    const std::uint64_t all = n == 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << n) - 1;
    if (reach(seen_, 0) != all) return false;
    if (!has_boundary) return true;
    // The boundary edges: every boundary vertex of degree 2, and one loop through all of them.
    std::uint64_t boundary_vertices = 0;
    for (std::uint32_t a = 0; a < n; ++a) {
      open_[a] = seen_[a] & ~twice_[a];
      const int d = popcount64(open_[a]);
      if (d != 0 && d != 2) return false;
      if (d != 0) boundary_vertices |= std::uint64_t(1) << a;
    }
    return reach(open_, static_cast<std::uint32_t>(lowest_bit64(boundary_vertices))) == boundary_vertices;
  }

  Link_kind classify_large(const Triangle* first, const Triangle* last, bool check_links) {
    const Iterator_pair range{first, last};
    if (!large_.build_from_triangles(range, check_links, /* stop at non-manifold */ true))
      return Link_kind::OTHER;
    if (check_links && !large_.is_sphere_or_disc()) return Link_kind::OTHER;
    return large_.euler_count_says_boundary() ? Link_kind::OPEN : Link_kind::CLOSED;
  }

  struct Iterator_pair {
    const Triangle *first, *last;
    const Triangle* begin() const { return first; }
    const Triangle* end() const { return last; }
  };

  // a corner of a tetrahedron in the leaf: its vertex and the opposite face, in local ids
  struct Corner {
    std::uint32_t vertex;
    Triangle link;
  };

  std::vector<Corner> corners_;
  std::vector<std::uint32_t> offsets_, pos_;
  std::vector<Triangle> triangles_;
  Small_map<Index> others_;
  std::vector<Index> vertices_;
  std::vector<std::array<std::uint32_t, 4>> tetrahedra_;
  std::vector<std::uint32_t> stamps_;
  std::vector<unsigned char> link_ids_;
  std::uint32_t generation_ = 0;
  std::uint64_t seen_[64] = {}, twice_[64] = {}, open_[64] = {};
  std::vector<Link_kind> kinds_;
  Vertex_link<std::uint32_t> large_;
};

// The vertices adjacent to `v` in the tetrahedra `star` of `T`, sorted, appended to `out` from
// position `from` on (what was there before is kept).
template <class Tetrahedra, class Star, class Index>
void star_neighbors(const Tetrahedra& T, const Star& star, Index v, std::vector<Index>& out,
                    std::size_t from = 0) {
  out.resize(from);
  for (Index t : star)
    for (Index w : T[t])
      if (w != v) out.push_back(w);
  std::sort(out.begin() + from, out.end());
  out.erase(std::unique(out.begin() + from, out.end()), out.end());
}

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_LOCAL_COMPLEX_H
