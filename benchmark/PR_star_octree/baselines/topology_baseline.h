// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The scalar-field topology of scalar_topology.h computed GLOBALLY on the extended IA (the
// package's baseline structure, Extended_IA.h), built once for the whole mesh: every vertex's star
// is extracted from the IA (VT*, then a walk across the faces through the vertex, with TT), and
//   (a) its critical type comes from the connected components of its lower and upper links;
//   (b) the Forman gradient is built by ProcessLowerStars (Robins, Wood and Sheppard 2011) on its
//       lower star, in the same total order as the package, (value, user's vertex index), so that
//       the critical simplices are the package's;
//   (c) the ascending cells of the minima follow the vertex-edge pairs down (the lowest lower
//       neighbour), the descending cells of the maxima follow the triangle-tetrahedron pairs
//       through TT.
// The vertices are processed in parallel (TBB when linked), each with its own scratch space, as the
// package processes its leaves, so that both are measured on the same number of threads.
//
// The gradient's encoding is this file's own: per vertex its paired lower neighbour (the vertex
// itself for a critical vertex), and per tetrahedron one byte: bits 0-5 the pairs of the three
// triangles through its highest vertex (2 bits each, written by that vertex), bits 6-7 the pair of
// the triangle opposite it (written by the second highest vertex), each 2-bit code being 0 (critical,
// or paired with the tetrahedron on the other side), 1 or 2 (paired with the edge from the writing
// vertex to the first or the second of the triangle's two other vertices, in the order of their
// positions in the tetrahedron), 3 (paired with a tetrahedron: for bits 0-5 this one, for bits 6-7
// the one across).  The two writers of a byte may run on two threads: the bits are set with an
// atomic OR.  |V| indices + |T| bytes in all.

#ifndef PRSTAR_BASELINES_TOPOLOGY_BASELINE_H
#define PRSTAR_BASELINES_TOPOLOGY_BASELINE_H

#include "Extended_IA.h"

#include <CGAL/PR_star_octree/scalar_topology.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace prstar_baselines {
namespace topology {

using CGAL::PR_star_octree::Critical_point_counts;
using CGAL::PR_star_octree::Critical_type;

/// A 64-bit mixer (splitmix64's finaliser), for the order-independent checksums.
inline std::uint64_t mix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

/// A checksum of a simplex given by its (user's) vertex indices, whatever their order.
inline std::uint64_t simplex_hash(std::array<std::uint64_t, 4> v, int n) {
  for (int i = 1; i < n; ++i) // at most four: an insertion sort
    for (int j = i; j > 0 && v[j] < v[j - 1]; --j) std::swap(v[j], v[j - 1]);
  std::uint64_t h = mix(static_cast<std::uint64_t>(n));
  for (int i = 0; i < n; ++i) h = mix(h ^ v[i]);
  return h;
}

/// The total order of the vertices: (value, key), the key being the user's index of the vertex
/// (`key == nullptr`: the vertex's own index).
template <class Index>
struct Vertex_order {
  const double* value = nullptr;
  const Index* key = nullptr;
  Index user(Index v) const { return key ? key[v] : v; }
  bool less(Index a, Index b) const {
    const double fa = value[a], fb = value[b];
    return fa < fb || (fa == fb && user(a) < user(b));
  }
};

/// A critical simplex: its dimension and vertices (the IA's numbering, the highest first).
template <class Index>
struct Critical_cell {
  int dimension = 0;
  std::array<Index, 4> vertices{};
};

/// The gradient on the IA (see the file's comment for the encoding).
template <class Index>
struct Gradient {
  static constexpr Index none = (std::numeric_limits<Index>::max)();
  std::vector<Index> vertex_pair;               ///< per vertex; `none` for an unreferenced vertex
  std::vector<std::atomic<std::uint8_t>> codes; ///< per tetrahedron
  std::vector<Critical_cell<Index>> critical;
  std::array<std::size_t, 4> counts{{0, 0, 0, 0}};
  std::uint64_t critical_hash = 0; ///< sum of simplex_hash over the critical simplices (user's indices)
  std::size_t memory_bytes() const { return vertex_pair.capacity() * sizeof(Index) + codes.size(); }
  long long alternating_sum() const {
    return static_cast<long long>(counts[0]) - static_cast<long long>(counts[1]) +
           static_cast<long long>(counts[2]) - static_cast<long long>(counts[3]);
  }
};

/// The per-vertex work on the IA, one object per thread.
template <class Index>
class Vertex_worker {
public:
  using IA = Extended_IA<Index>;
  static constexpr Index none = IA::no_neighbor;

  /// The star of `v` from the IA: VT*(v), then across the faces through `v` (TT); visited
  /// tetrahedra are remembered in a small open-addressing set (no per-tetrahedron array).
  void extract_star(const IA& ia, Index v) {
    star_.clear();
    v_ = v;
    const Index start = ia.vertex_tetrahedron(v);
    if (start == none) return;
    if (table_.empty()) table_.assign(std::size_t(1) << bits_, none);
    visit(start);
    stack_.clear();
    stack_.push_back(start);
    while (!stack_.empty()) {
      const Index t = stack_.back();
      stack_.pop_back();
      const auto& c = ia.tetrahedron(t);
      const auto& n = ia.neighbors(t);
      for (int k = 0; k < 4; ++k)
        if (c[k] != v && n[k] != none && visit(n[k])) stack_.push_back(n[k]);
    }
    for (std::size_t s : used_) table_[s] = none;
    used_.clear();
  }
  const std::vector<Index>& star() const { return star_; }

  /// The numbers of connected components of the lower and the upper link of the last extracted
  /// vertex (0 and 0 for an unreferenced vertex).
  std::pair<unsigned, unsigned> link_components(const IA& ia, const Vertex_order<Index>& order) {
    if (star_.empty()) return {0u, 0u};
    neighbours(ia);
    const std::size_t n = nb_.size();
    is_lower_.resize(n);
    for (std::size_t i = 0; i < n; ++i) is_lower_[i] = order.less(nb_[i], v_);
    root_.resize(n);
    for (std::size_t i = 0; i < n; ++i) root_[i] = static_cast<std::uint32_t>(i);
    for (const auto& q : tet_pos_) {
      std::array<std::uint32_t, 3> p;
      int k = 0;
      for (std::uint32_t x : q)
        if (x != self_pos_) p[k++] = x;
      join(p[0], p[1]);
      join(p[0], p[2]);
      join(p[1], p[2]);
    }
    unsigned lower = 0, upper = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (find(static_cast<std::uint32_t>(i)) == i) ++(is_lower_[i] ? lower : upper);
    return {lower, upper};
  }

  /// ProcessLowerStars on the lower star of the last extracted vertex: writes its vertex pair, its
  /// bits of the tetrahedron codes, `parent[t]` (when not null) for each tetrahedron `t` whose
  /// highest vertex it is (`t` when `t` is critical, the tetrahedron across its paired triangle,
  /// `none` across the boundary), and appends its critical simplices to `critical`.
  void process_lower_star(const IA& ia, const Vertex_order<Index>& order, Gradient<Index>& g, Index* parent,
                          std::vector<Critical_cell<Index>>& critical) {
    if (star_.empty()) return;
    const Index v = v_;
    neighbours(ia);
    low_.clear();
    for (std::size_t i = 0; i < nb_.size(); ++i)
      if (order.less(nb_[i], v)) low_.push_back(static_cast<Index>(i)); // positions first
    if (low_.empty()) {                                                 // a minimum
      g.vertex_pair[v] = v;
      critical.push_back({0, {{v, none, none, none}}});
      return;
    }
    if (low_.size() >= (std::size_t(1) << 20)) throw std::length_error("a vertex with over 2^20 neighbours");
    std::sort(low_.begin(), low_.end(), [&](Index a, Index b) { return order.less(nb_[a], nb_[b]); });
    rank_.assign(nb_.size() + 1, -1); // rank_[self] = -1 too
    for (std::size_t r = 0; r < low_.size(); ++r) {
      rank_[low_[r]] = static_cast<int>(r);
      low_[r] = nb_[low_[r]]; // now the vertices
    }
    g.vertex_pair[v] = low_[0];

    // the cells other than v, keyed so that the key order is the order G (the ranks of the other
    // vertices, decreasing, compared lexicographically, a prefix first)
    cells_.clear();
    for (std::size_t r = 0; r < low_.size(); ++r) cells_.push_back({cell_key(int(r), -1, -1), none});
    for (std::size_t i = 0; i < star_.size(); ++i) {
      const Index t = star_[i];
      std::array<int, 3> r;
      int k = 0;
      for (std::uint32_t x : tet_pos_[i])
        if (x != self_pos_) r[k++] = rank_[x];
      sort3(r);
      if (r[1] >= 0) cells_.push_back({cell_key(r[0], r[1], -1), none});
      if (r[2] >= 0) {
        cells_.push_back({cell_key(r[0], r[2], -1), none});
        cells_.push_back({cell_key(r[1], r[2], -1), none});
        cells_.push_back({cell_key(r[0], r[1], r[2]), t});
      }
    }
    std::sort(cells_.begin(), cells_.end(), [](const Cell& a, const Cell& b) { return a.key < b.key; });
    cells_.erase(std::unique(cells_.begin(), cells_.end(),
                             [](const Cell& a, const Cell& b) { return a.key == b.key; }),
                 cells_.end());
    const std::size_t n = cells_.size();
    // faces and cofaces (within the lower star, v excepted)
    faces_.assign(n, {{-1, -1, -1}});
    first_coface_.assign(n + 1, 0);
    for (std::size_t c = 0; c < n; ++c) {
      const auto r = ranks(cells_[c].key);
      if (r[1] < 0) continue;
      if (r[2] < 0)
        faces_[c] = {{find_cell(cell_key(r[0], -1, -1)), find_cell(cell_key(r[1], -1, -1)), -1}};
      else
        faces_[c] = {{find_cell(cell_key(r[0], r[1], -1)), find_cell(cell_key(r[0], r[2], -1)),
                      find_cell(cell_key(r[1], r[2], -1))}};
      for (int f : faces_[c])
        if (f >= 0) ++first_coface_[static_cast<std::size_t>(f) + 1];
    }
    for (std::size_t c = 0; c < n; ++c) first_coface_[c + 1] += first_coface_[c];
    cofaces_.resize(first_coface_[n]);
    cursor_.assign(first_coface_.begin(), first_coface_.end() - 1);
    for (std::size_t c = 0; c < n; ++c)
      for (int f : faces_[c])
        if (f >= 0) cofaces_[cursor_[static_cast<std::size_t>(f)]++] = static_cast<std::int32_t>(c);
    state_.assign(n, 0);
    partner_.assign(n, -1);

    // ProcessLowerStars.  A cell's index is its rank in G, so the queues are min-heaps of indices.
    auto unpaired_faces = [&](std::int32_t c) {
      int k = 0;
      for (int f : faces_[c]) k += (f >= 0 && state_[f] == 0);
      return k;
    };
    auto push = [](std::vector<std::int32_t>& q, std::int32_t c) {
      q.push_back(c);
      std::push_heap(q.begin(), q.end(), std::greater<std::int32_t>());
    };
    auto pop = [](std::vector<std::int32_t>& q) {
      std::pop_heap(q.begin(), q.end(), std::greater<std::int32_t>());
      const std::int32_t c = q.back();
      q.pop_back();
      return c;
    };
    auto push_ready_cofaces = [&](std::int32_t c) {
      for (std::size_t k = first_coface_[c]; k < first_coface_[c + 1]; ++k) {
        const std::int32_t x = cofaces_[k];
        if (state_[x] == 0 && unpaired_faces(x) == 1) push(one_, x);
      }
    };
    zero_.clear();
    one_.clear();
    // v with its lowest edge (cell 0: the smallest key); the other edges wait in PQzero
    state_[0] = 1;
    partner_[0] = -2;
    for (std::size_t c = 1; c < n; ++c)
      if (ranks(cells_[c].key)[1] < 0) push(zero_, static_cast<std::int32_t>(c));
    push_ready_cofaces(0);
    while (!one_.empty() || !zero_.empty()) {
      while (!one_.empty()) {
        const std::int32_t a = pop(one_);
        if (state_[a] != 0) continue;
        if (unpaired_faces(a) == 0) {
          push(zero_, a);
          continue;
        }
        std::int32_t b = -1;
        for (int f : faces_[a])
          if (f >= 0 && state_[f] == 0) b = f;
        state_[a] = state_[b] = 1;
        partner_[a] = b;
        partner_[b] = a;
        push_ready_cofaces(a);
        push_ready_cofaces(b);
      }
      while (!zero_.empty()) {
        const std::int32_t c = pop(zero_);
        if (state_[c] != 0) continue;
        state_[c] = 2;
        push_ready_cofaces(c);
        break;
      }
    }

    for (std::size_t c = 0; c < n; ++c) {
      if (state_[c] != 2) continue;
      const auto r = ranks(cells_[c].key);
      Critical_cell<Index> cc;
      cc.vertices = {{v, none, none, none}};
      for (int i = 0; i < 3 && r[i] >= 0; ++i) {
        cc.vertices[i + 1] = low_[r[i]];
        cc.dimension = i + 1;
      }
      critical.push_back(cc);
    }
    // the codes: bits 0-5 of the tetrahedra whose highest vertex is v, bits 6-7 of those whose
    // second highest vertex it is
    for (std::size_t i = 0; i < star_.size(); ++i) {
      const Index t = star_[i];
      std::array<int, 4> rk; // the ranks of the corners, -1 for an upper one, -2 for v
      int upper_position = -1, uppers = 0, vp = 0;
      for (int k = 0; k < 4; ++k) {
        const std::uint32_t x = tet_pos_[i][k];
        rk[k] = x == self_pos_ ? -2 : rank_[x];
        if (x == self_pos_)
          vp = k;
        else if (rk[k] < 0)
          upper_position = k, ++uppers;
      }
      if (uppers >= 2) continue;
      std::uint8_t bits = 0;
      if (uppers == 1) {
        bits = static_cast<std::uint8_t>(triangle_code(rk, vp, upper_position, none) << 6);
      } else {
        int slot = 0;
        for (int m = 0; m < 4; ++m)
          if (m != vp) bits = static_cast<std::uint8_t>(bits | (triangle_code(rk, vp, m, t) << (2 * slot++)));
        if (parent) {
          std::array<int, 3> r3;
          int k = 0;
          for (int m = 0; m < 4; ++m)
            if (m != vp) r3[k++] = rk[m];
          sort3(r3);
          const std::int32_t c = find_cell(cell_key(r3[0], r3[1], r3[2]));
          if (state_[c] == 2) {
            parent[t] = t;
          } else { // across the paired triangle: the position of the tetrahedron's vertex off it
            const auto r = ranks(cells_[partner_[c]].key);
            int m = 0;
            while (m == vp || rk[m] == r[0] || rk[m] == r[1]) ++m;
            parent[t] = ia.neighbor(t, m);
          }
        }
      }
      if (bits) g.codes[t].fetch_or(bits, std::memory_order_relaxed);
    }
  }

private:
  struct Cell {
    std::uint64_t key;
    Index tetrahedron;
  };
  static constexpr unsigned rank_bits = 21;
  static std::uint64_t cell_key(int r0, int r1, int r2) {
    return (std::uint64_t(r0 + 1) << (2 * rank_bits)) | (std::uint64_t(r1 + 1) << rank_bits) |
           std::uint64_t(r2 + 1);
  }
  static std::array<int, 3> ranks(std::uint64_t key) {
    const std::uint64_t mask = (std::uint64_t(1) << rank_bits) - 1;
    return {{int(key >> (2 * rank_bits)) - 1, int((key >> rank_bits) & mask) - 1, int(key & mask) - 1}};
  }
  std::int32_t find_cell(std::uint64_t key) const {
    const auto it = std::lower_bound(cells_.begin(), cells_.end(), key,
                                     [](const Cell& c, std::uint64_t k) { return c.key < k; });
    return static_cast<std::int32_t>(it - cells_.begin());
  }
  static void sort3(std::array<int, 3>& r) { // decreasing
    if (r[0] < r[1]) std::swap(r[0], r[1]);
    if (r[1] < r[2]) std::swap(r[1], r[2]);
    if (r[0] < r[1]) std::swap(r[0], r[1]);
  }
  // the 2-bit code of the triangle of a tetrahedron through v (at position vp) opposite position m
  // (its other two vertices lower than v), `rk` the ranks of the corners; `self` the tetrahedron
  // whose own pair is code 3
  std::uint8_t triangle_code(const std::array<int, 4>& rk, int vp, int m, Index self) const {
    int a = -1, b = -1;
    for (int i = 0; i < 4; ++i)
      if (i != vp && i != m) (a < 0 ? a : b) = i;
    const int ra = rk[a], rb = rk[b];
    const std::int32_t f = find_cell(cell_key((std::max)(ra, rb), (std::min)(ra, rb), -1));
    const std::int32_t p = partner_[f];
    if (p < 0) return 0;
    const auto r = ranks(cells_[p].key);
    if (r[1] < 0) return r[0] == ra ? 1 : 2;      // an edge [v, c[a]] or [v, c[b]]
    if (self == none) return 3;                   // the tetrahedron across
    return cells_[p].tetrahedron == self ? 3 : 0; // this one, or the other one
  }
  void neighbours(const IA& ia) {
    if (nb_vertex_ == v_ && nb_star_ == star_.size()) return;
    nb_vertex_ = v_;
    nb_star_ = star_.size();
    nb_.clear();
    for (Index t : star_)
      for (Index u : ia.tetrahedron(t))
        if (u != v_) nb_.push_back(u);
    std::sort(nb_.begin(), nb_.end());
    nb_.erase(std::unique(nb_.begin(), nb_.end()), nb_.end());
    self_pos_ = static_cast<std::uint32_t>(nb_.size()); // v's own "position"
    tet_pos_.resize(star_.size());
    for (std::size_t i = 0; i < star_.size(); ++i) {
      const auto& c = ia.tetrahedron(star_[i]);
      for (int k = 0; k < 4; ++k) tet_pos_[i][k] = c[k] == v_ ? self_pos_ : position(c[k]);
    }
  }
  std::uint32_t position(Index u) const {
    return static_cast<std::uint32_t>(std::lower_bound(nb_.begin(), nb_.end(), u) - nb_.begin());
  }
  std::uint32_t find(std::uint32_t i) {
    while (root_[i] != i) i = root_[i] = root_[root_[i]];
    return i;
  }
  void join(std::uint32_t a, std::uint32_t b) {
    if (is_lower_[a] != is_lower_[b]) return;
    a = find(a);
    b = find(b);
    if (a != b) root_[(std::max)(a, b)] = (std::min)(a, b);
  }
  // the visited set of the star walk
  bool visit(Index t) {
    if (2 * (used_.size() + 1) > table_.size()) grow();
    const std::size_t mask = table_.size() - 1;
    std::size_t h = static_cast<std::size_t>((std::uint64_t(t) * 0x9E3779B97F4A7C15ull) >> (64 - bits_));
    while (table_[h] != none) {
      if (table_[h] == t) return false;
      h = (h + 1) & mask;
    }
    table_[h] = t;
    used_.push_back(h);
    star_.push_back(t);
    return true;
  }
  void grow() {
    for (std::size_t s : used_) table_[s] = none;
    used_.clear();
    ++bits_;
    table_.assign(std::size_t(1) << bits_, none);
    const std::vector<Index> kept(star_);
    star_.clear();
    for (Index t : kept) visit(t);
  }

  Index v_ = none, nb_vertex_ = none;
  std::size_t nb_star_ = 0;
  std::uint32_t self_pos_ = 0;                        // the position standing for v in tet_pos_
  std::vector<std::array<std::uint32_t, 4>> tet_pos_; // per star tetrahedron: its corners' positions in nb_
  std::vector<Index> star_, stack_, table_, nb_, low_;
  std::vector<std::size_t> used_;
  unsigned bits_ = 7;
  std::vector<char> is_lower_;
  std::vector<std::uint32_t> root_;
  std::vector<int> rank_;
  std::vector<Cell> cells_;
  std::vector<std::array<int, 3>> faces_;
  std::vector<std::size_t> first_coface_, cursor_;
  std::vector<std::int32_t> cofaces_, zero_, one_, partner_;
  std::vector<std::uint8_t> state_;
};

/// Runs `body(worker, accumulator, v)` for every vertex, on TBB's threads when linked; returns
/// the accumulators of the threads.
template <class Index, class Accumulator, class Body>
std::vector<Accumulator> for_each_vertex(std::size_t nv, const Body& body) {
  std::vector<Accumulator> result;
#ifdef CGAL_LINKED_WITH_TBB
  tbb::enumerable_thread_specific<std::pair<Vertex_worker<Index>, Accumulator>> local;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, 1024),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      auto& l = local.local();
                      for (std::size_t v = r.begin(); v != r.end(); ++v)
                        body(l.first, l.second, static_cast<Index>(v));
                    });
  for (auto& l : local) result.push_back(std::move(l.second));
#else
  std::pair<Vertex_worker<Index>, Accumulator> l;
  for (std::size_t v = 0; v < nv; ++v) body(l.first, l.second, static_cast<Index>(v));
  result.push_back(std::move(l.second));
#endif
  return result;
}

/// (a) The critical type of every vertex (the IA's numbering) into `types`, and the counts.
template <class Index>
Critical_point_counts critical_points(const Extended_IA<Index>& ia, const Vertex_order<Index>& order,
                                      std::vector<Critical_type>& types) {
  const auto parts = for_each_vertex<Index, Critical_point_counts>(
      ia.number_of_vertices(), [&](Vertex_worker<Index>& w, Critical_point_counts& counts, Index v) {
        w.extract_star(ia, v);
        const auto lu = w.link_components(ia, order);
        counts.add(lu.first, lu.second);
        types[v] = CGAL::PR_star_octree::classify_critical_point(lu.first, lu.second); // the convention
      });
  Critical_point_counts total;
  for (const auto& c : parts) {
    total.minima += c.minima;
    total.saddles_1 += c.saddles_1;
    total.saddles_2 += c.saddles_2;
    total.maxima += c.maxima;
    total.degenerate += c.degenerate;
    total.regular += c.regular;
    total.unreferenced += c.unreferenced;
    total.join_multiplicity += c.join_multiplicity;
    total.split_multiplicity += c.split_multiplicity;
  }
  return total;
}

/// (b) The Forman gradient; with `parent` (one index per tetrahedron) also the tetrahedron pairs
/// as parents (see `Vertex_worker::process_lower_star()`).
template <class Index>
void forman_gradient(const Extended_IA<Index>& ia, const Vertex_order<Index>& order, Gradient<Index>& g,
                     Index* parent = nullptr) {
  const std::size_t nv = ia.number_of_vertices(), nt = ia.number_of_tetrahedra();
  g.vertex_pair.assign(nv, Gradient<Index>::none);
  std::vector<std::atomic<std::uint8_t>> codes(nt);
  g.codes.swap(codes);
  using Cells = std::vector<Critical_cell<Index>>;
  auto parts = for_each_vertex<Index, Cells>(nv, [&](Vertex_worker<Index>& w, Cells& cells, Index v) {
    w.extract_star(ia, v);
    w.process_lower_star(ia, order, g, parent, cells);
  });
  g.critical.clear();
  for (auto& p : parts) g.critical.insert(g.critical.end(), p.begin(), p.end());
  g.counts = {{0, 0, 0, 0}};
  g.critical_hash = 0;
  for (const auto& c : g.critical) {
    ++g.counts[static_cast<std::size_t>(c.dimension)];
    std::array<std::uint64_t, 4> u{};
    for (int i = 0; i <= c.dimension; ++i) u[i] = order.user(c.vertices[i]);
    g.critical_hash += simplex_hash(u, c.dimension + 1);
  }
}

/// (c) The Morse cells: per vertex the minimum of its ascending cell, per tetrahedron the highest
/// vertex of the critical tetrahedron of its descending cell (`no_cell` when its path leaves the
/// domain), both in the user's indices, as the package's `Morse_complexes` without cancellation.
template <class Index>
struct Segmentation {
  static constexpr std::size_t no_cell = (std::numeric_limits<std::size_t>::max)();
  Gradient<Index> gradient;
  std::vector<std::size_t> ascending_cell, descending_cell;
  std::size_t ascending_cells = 0, descending_cells = 0, outflow_tetrahedra = 0;
};

// Every parent chain replaced by its end: a root (p[x] == x) or `none`.
template <class Index>
void resolve_chains(std::vector<Index>& p) {
  const Index none = (std::numeric_limits<Index>::max)();
  for (std::size_t x = 0; x < p.size(); ++x) {
    Index r = static_cast<Index>(x);
    std::size_t steps = 0;
    while (p[r] != none && p[r] != r) {
      r = p[r];
      if (++steps > p.size()) throw std::logic_error("a gradient path cycles");
    }
    const Index end = p[r] == none ? none : r;
    for (Index y = static_cast<Index>(x); y != r;) {
      const Index next = p[y];
      p[y] = end;
      y = next;
    }
  }
}

template <class Index>
void segmentation(const Extended_IA<Index>& ia, const Vertex_order<Index>& order, Segmentation<Index>& s) {
  const Index none = Gradient<Index>::none;
  const std::size_t nv = ia.number_of_vertices(), nt = ia.number_of_tetrahedra();
  std::vector<Index> parent(nt, none);
  forman_gradient(ia, order, s.gradient, parent.data());
  // ascending: the vertex pairs down to the minima
  std::vector<Index> down(s.gradient.vertex_pair);
  resolve_chains(down);
  s.ascending_cell.assign(nv, Segmentation<Index>::no_cell);
  s.ascending_cells = s.gradient.counts[0];
  for (std::size_t v = 0; v < nv; ++v)
    if (down[v] != none) s.ascending_cell[v] = order.user(down[v]);
  // descending: the tetrahedron pairs up to the critical tetrahedra
  std::vector<Index> critical_roots;
  for (std::size_t t = 0; t < nt; ++t)
    if (parent[t] == static_cast<Index>(t)) critical_roots.push_back(static_cast<Index>(t));
  resolve_chains(parent);
  auto highest = [&](Index t) {
    const auto& c = ia.tetrahedron(t);
    Index h = c[0];
    for (Index u : c)
      if (order.less(h, u)) h = u;
    return static_cast<std::size_t>(order.user(h));
  };
  s.descending_cell.assign(nt, Segmentation<Index>::no_cell);
  s.outflow_tetrahedra = 0;
  for (std::size_t t = 0; t < nt; ++t) {
    if (parent[t] == none)
      ++s.outflow_tetrahedra;
    else
      s.descending_cell[t] = highest(parent[t]);
  }
  std::vector<std::size_t> labels;
  for (Index t : critical_roots) labels.push_back(highest(t));
  std::sort(labels.begin(), labels.end());
  s.descending_cells = static_cast<std::size_t>(std::unique(labels.begin(), labels.end()) - labels.begin());
}

} // namespace topology
} // namespace prstar_baselines

#endif // PRSTAR_BASELINES_TOPOLOGY_BASELINE_H
