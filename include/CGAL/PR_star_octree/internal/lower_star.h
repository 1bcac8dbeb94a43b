// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_LOWER_STAR_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_LOWER_STAR_H

// The per-vertex work of the scalar-field topology (scalar_topology.h): the lower and upper links
// of a vertex (its critical type) and the discrete gradient of its lower star (Robins, Wood and
// Sheppard 2011, ProcessLowerStars), both from the star of the vertex alone.

#include <CGAL/PR_star_octree/internal/local_complex.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

// The total order of the vertices: the field value, then the user's vertex index (simulation of
// simplicity), so that no two vertices compare equal.
template <class Octree>
class Field_order {
public:
  using Index = typename Octree::Index;

  Field_order() = default;
  // `value(v)` gives the field at vertex `v` of the octree's numbering.
  template <class ValueAt>
  Field_order(const Octree& tree, const ValueAt& value) : tree_(&tree), values_(tree.number_of_vertices()) {
    for (std::size_t v = 0; v < values_.size(); ++v) {
      const double x = static_cast<double>(value(static_cast<Index>(v)));
      if (!std::isfinite(x))
        throw std::invalid_argument("the scalar field is not finite at vertex " +
                                    std::to_string(tree.original_vertex(static_cast<Index>(v))));
      values_[v] = x == 0 ? 0.0 : x; // -0 is 0
    }
  }
  const Octree& octree() const { return *tree_; }
  double value(Index v) const { return values_[v]; }
  std::size_t key(Index v) const { return static_cast<std::size_t>(tree_->original_vertex(v)); }
  bool less(Index a, Index b) const {
    const double fa = values_[a], fb = values_[b];
    return fa < fb || (fa == fb && key(a) < key(b));
  }

private:
  const Octree* tree_ = nullptr;
  std::vector<double> values_;
};

// What the links of one vertex say: the numbers of connected components of its lower and upper
// links, a representative of each component (the lowest vertex of each lower component, the
// highest of each upper component, in the field order), and the lowest lower and highest upper
// neighbours (the steepest descent and ascent along the edges).
template <class Index>
struct Link_result {
  unsigned lower_components = 0, upper_components = 0;
  std::vector<Index> lower_representatives, upper_representatives;
  Index lowest_lower = Index(-1), highest_upper = Index(-1);
};

// The scratch space of the per-vertex work, one per thread.
template <class Octree>
class Lower_star_processor {
public:
  using Index = typename Octree::Index;
  static constexpr Index none = Index(-1);

  // A simplex of the lower star of v other than v: v and 1, 2 or 3 lower neighbours, given by
  // their ranks among the lower neighbours (rank 0 is the lowest), in decreasing order.
  struct Cell {
    std::uint8_t dimension = 0;                   // 1, 2, 3
    std::uint8_t state = 0;                       // 0 unclassified, 1 paired, 2 critical
    std::array<std::uint32_t, 3> rank{{0, 0, 0}}; // decreasing; unused ones 0
    std::int32_t partner = -1;                    // the cell it is paired with (-2: v itself)
    Index tetrahedron = none;                     // a tetrahedron: its index
    // G as one integer: the ranks plus one, 21 bits each, 0 where absent (a prefix comes first)
    std::uint64_t g = 0;
    void set_key() {
      g = 0;
      for (int i = 0; i < 3; ++i) g = (g << 21) | (i < dimension ? std::uint64_t(rank[i]) + 1 : 0);
    }
  };
  // the ranks of a cell fit in 21 bits
  static constexpr std::size_t max_lower_neighbours = (std::size_t(1) << 21) - 2;

  // The link analysis of `v`, whose star is `star` (tetrahedron indices).
  template <class Star>
  const Link_result<Index>& analyse_links(const Field_order<Octree>& order, Index v, const Star& star) {
    collect_neighbours(order.octree(), v, star);
    const std::size_t n = nb_.size();
    lower_.resize(n);
    for (std::size_t i = 0; i < n; ++i) lower_[i] = order.less(nb_[i], v);
    uf_.reset(n);
    for (const auto& e : link_edges_)
      if (lower_[e.first] == lower_[e.second]) uf_.unite(e.first, e.second);
    link_.lower_components = link_.upper_components = 0;
    link_.lower_representatives.clear();
    link_.upper_representatives.clear();
    link_.lowest_lower = link_.highest_upper = none;
    // the representative of each component: its extreme vertex in the field order
    rep_.assign(n, none);
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t r = uf_.find(static_cast<std::uint32_t>(i));
      Index& rep = rep_[r];
      if (rep == none || (lower_[i] ? order.less(nb_[i], rep) : order.less(rep, nb_[i]))) rep = nb_[i];
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (uf_.find(static_cast<std::uint32_t>(i)) != i) continue;
      if (lower_[i]) {
        ++link_.lower_components;
        link_.lower_representatives.push_back(rep_[i]);
        if (link_.lowest_lower == none || order.less(rep_[i], link_.lowest_lower))
          link_.lowest_lower = rep_[i];
      } else {
        ++link_.upper_components;
        link_.upper_representatives.push_back(rep_[i]);
        if (link_.highest_upper == none || order.less(link_.highest_upper, rep_[i]))
          link_.highest_upper = rep_[i];
      }
    }
    return link_;
  }

  // Whether the link of the vertex of the last `analyse_links()` is a closed surface: every link
  // edge in two link triangles (asked for the vertices that are not regular only).
  bool link_is_closed() {
    sorted_edges_.clear();
    for (const auto& e : link_edges_)
      sorted_edges_.push_back(e.first < e.second ? e : std::make_pair(e.second, e.first));
    std::sort(sorted_edges_.begin(), sorted_edges_.end());
    for (std::size_t i = 0; i < sorted_edges_.size();) {
      std::size_t j = i;
      while (j < sorted_edges_.size() && sorted_edges_[j] == sorted_edges_[i]) ++j;
      if (j - i != 2) return false;
      i = j;
    }
    return true;
  }

  // ProcessLowerStars on the lower star of `v`.  Calls `critical(dimension, vertices, cofacets)`
  // for each critical simplex (vertices: v first, then its other vertices in decreasing field
  // order; cofacets: for a triangle, the tetrahedra of the star containing it), writes the corner
  // byte of `v` in each tetrahedron of its star (`gradient[4 t + i]`, `i` the position of `v` in
  // tetrahedron `t`) and, for each tetrahedron whose highest vertex is `v`, `parent(t, p)`: `p` the
  // tetrahedron across the triangle `t` is paired with, `t` itself when `t` is critical, `none`
  // when that triangle is on the boundary (or in three or more tetrahedra).
  template <class Star, class Critical, class Parent>
  void process_lower_star(const Field_order<Octree>& order, Index v, const Star& star, std::uint8_t* gradient,
                          Critical&& critical, Parent&& parent) {
    const Octree& tree = order.octree();
    if (star.size() == 0) return; // not a vertex of the mesh
    collect_neighbours(tree, v, star);
    // the lower neighbours, by increasing field order: their ranks
    low_.clear();
    for (Index u : nb_)
      if (order.less(u, v)) low_.push_back(u);
    std::sort(low_.begin(), low_.end(), [&](Index a, Index b) { return order.less(a, b); });
    if (low_.empty()) {
      const std::array<Index, 4> c{{v, none, none, none}};
      critical(0, c, std::array<Index, 2>{{none, none}});
      for (auto t : star) gradient[4 * static_cast<std::size_t>(t) + position(tree.tetrahedron(t), v)] = 0;
      return;
    }
    if (low_.size() > max_lower_neighbours)
      throw std::length_error("a vertex with more than 2 million lower neighbours");
    rank_of_nb_.assign(nb_.size(), -1);
    for (std::size_t r = 0; r < low_.size(); ++r) rank_of_nb_[neighbour_id(low_[r])] = static_cast<int>(r);
    auto rank_at = [&](std::size_t k, int position) { // of the vertex of star tetrahedron k
      return rank_of_nb_[static_cast<std::size_t>(star_ids_[k][position])];
    };
    // the cells: edges (one per lower neighbour, cell id = rank), triangles, tetrahedra
    cells_.clear();
    for (std::size_t r = 0; r < low_.size(); ++r) {
      Cell c;
      c.dimension = 1;
      c.rank[0] = static_cast<std::uint32_t>(r);
      c.set_key();
      cells_.push_back(c);
    }
    triangle_records_.clear();
    std::size_t star_k = 0;
    for (auto t : star) {
      std::array<int, 3> r;
      int k = 0;
      for (int i = 0; i < 4; ++i)
        if (star_ids_[star_k][i] >= 0) r[k++] = rank_at(star_k, i);
      ++star_k;
      std::sort(r.begin(), r.end(), std::greater<int>());
      for (int a = 0; a < 3; ++a)
        for (int b = a + 1; b < 3; ++b)
          if (r[b] >= 0) triangle_records_.emplace_back(key(r[a], r[b]), t);
      if (r[2] >= 0) {
        Cell c;
        c.dimension = 3;
        c.rank = {{static_cast<std::uint32_t>(r[0]), static_cast<std::uint32_t>(r[1]),
                   static_cast<std::uint32_t>(r[2])}};
        c.tetrahedron = t;
        c.set_key();
        cells_.push_back(c);
      }
    }
    // the triangles (sorted keys) with the tetrahedra of the star around each (two inside, one on
    // the boundary, more if non-manifold)
    std::sort(triangle_records_.begin(), triangle_records_.end());
    triangle_keys_.clear();
    triangle_tets_.clear();
    for (std::size_t i = 0; i < triangle_records_.size();) {
      std::size_t j = i;
      while (j < triangle_records_.size() && triangle_records_[j].first == triangle_records_[i].first) ++j;
      triangle_keys_.push_back(triangle_records_[i].first);
      triangle_tets_.push_back(
          {{triangle_records_[i].second, j - i > 1 ? triangle_records_[i + 1].second : none,
            static_cast<Index>(j - i)}});
      i = j;
    }
    const std::size_t first_triangle = low_.size();
    // cells_: edges, tetrahedra; the triangles go between them: rebuild in that order
    std::vector<Cell>& tets = tets_;
    tets.assign(cells_.begin() + static_cast<std::ptrdiff_t>(first_triangle), cells_.end());
    cells_.resize(first_triangle);
    for (std::uint64_t k : triangle_keys_) {
      Cell c;
      c.dimension = 2;
      c.rank[0] = static_cast<std::uint32_t>(k >> 32);
      c.rank[1] = static_cast<std::uint32_t>(k & 0xffffffffu);
      c.set_key();
      cells_.push_back(c);
    }
    const std::size_t first_tet = cells_.size();
    cells_.insert(cells_.end(), tets.begin(), tets.end());
    const std::size_t n = cells_.size();
    // faces (within the lower star, other than v) and cofaces
    faces_.assign(n, {{-1, -1, -1}});
    coface_offsets_.assign(n + 1, 0);
    for (std::size_t c = first_triangle; c < n; ++c) {
      const Cell& cell = cells_[c];
      if (cell.dimension == 2) {
        faces_[c] = {{static_cast<int>(cell.rank[0]), static_cast<int>(cell.rank[1]), -1}};
      } else {
        faces_[c] = {{triangle_id(cell.rank[0], cell.rank[1], first_triangle),
                      triangle_id(cell.rank[0], cell.rank[2], first_triangle),
                      triangle_id(cell.rank[1], cell.rank[2], first_triangle)}};
      }
      for (int f : faces_[c])
        if (f >= 0) ++coface_offsets_[static_cast<std::size_t>(f) + 1];
    }
    for (std::size_t c = 0; c < n; ++c) coface_offsets_[c + 1] += coface_offsets_[c];
    cofaces_.resize(coface_offsets_[n]);
    fill_.assign(coface_offsets_.begin(), coface_offsets_.end() - 1);
    for (std::size_t c = first_triangle; c < n; ++c)
      for (int f : faces_[c])
        if (f >= 0) cofaces_[fill_[static_cast<std::size_t>(f)]++] = static_cast<std::int32_t>(c);

    // ProcessLowerStars: v with its lowest edge, then the two queues, by increasing G (the
    // lexicographic order of the decreasing ranks).
    // (binary heaps on reused buffers, smallest G on top)
    auto greater_g = [this](std::int32_t a, std::int32_t b) { return less_g(b, a); };
    auto push = [&](std::vector<std::int32_t>& q, std::int32_t c) {
      q.push_back(c);
      std::push_heap(q.begin(), q.end(), greater_g);
    };
    auto pop = [&](std::vector<std::int32_t>& q) {
      std::pop_heap(q.begin(), q.end(), greater_g);
      const std::int32_t c = q.back();
      q.pop_back();
      return c;
    };
    std::vector<std::int32_t>&pq_zero = queue_zero_, &pq_one = queue_one_;
    pq_zero.clear();
    pq_one.clear();
    cells_[0].state = 1;
    cells_[0].partner = -2;
    for (std::int32_t e = 1; e < static_cast<std::int32_t>(first_triangle); ++e) push(pq_zero, e);
    auto push_cofaces = [&](std::int32_t c) {
      for (std::size_t k = coface_offsets_[c]; k < coface_offsets_[c + 1]; ++k) {
        const std::int32_t g = cofaces_[k];
        if (cells_[g].state == 0 && unclassified_faces(g) == 1) push(pq_one, g);
      }
    };
    push_cofaces(0);
    for (;;) {
      while (!pq_one.empty()) {
        const std::int32_t a = pop(pq_one);
        if (cells_[a].state != 0) continue;
        const int k = unclassified_faces(a);
        if (k == 0) {
          push(pq_zero, a);
        } else if (k == 1) {
          std::int32_t b = -1;
          for (int f : faces_[a])
            if (f >= 0 && cells_[f].state == 0) b = f;
          cells_[a].state = cells_[b].state = 1;
          cells_[a].partner = b;
          cells_[b].partner = a;
          push_cofaces(a);
          push_cofaces(b);
        }
      }
      std::int32_t g = -1;
      while (!pq_zero.empty() && g < 0) {
        const std::int32_t c = pop(pq_zero);
        if (cells_[c].state == 0) g = c;
      }
      if (g < 0) break;
      cells_[g].state = 2;
      push_cofaces(g);
    }

    // the critical cells
    for (std::size_t c = 0; c < n; ++c) {
      if (cells_[c].state != 2) continue;
      const Cell& cell = cells_[c];
      std::array<Index, 4> vs{{v, none, none, none}};
      for (int i = 0; i < cell.dimension; ++i) vs[i + 1] = low_[cell.rank[i]];
      std::array<Index, 2> cofacets{{none, none}};
      if (cell.dimension == 2) {
        const auto& around = triangle_tets_[c - first_triangle];
        const std::size_t k = static_cast<std::size_t>(around[2]);
        if (k <= 2) cofacets = {{around[0], around[1]}}; // none for a non-manifold triangle
        if (k == 2) { // in the field order of their fourth vertices: the same for any numbering
          auto fourth = [&](Index t) {
            for (Index u : tree.tetrahedron(t))
              if (u != vs[0] && u != vs[1] && u != vs[2]) return u;
            return none;
          };
          if (order.less(fourth(cofacets[1]), fourth(cofacets[0]))) std::swap(cofacets[0], cofacets[1]);
        }
      }
      critical(cell.dimension, vs, cofacets);
    }
    // the corner bytes of v and the parents of the tetrahedra whose highest vertex is v
    star_k = 0;
    for (auto t : star) {
      const auto& tv = tree.tetrahedron(t);
      const std::size_t sk = star_k++;
      const int i = position(tv, v);
      std::uint8_t byte = 0;
      // the vertex-edge pair of v: its lowest lower neighbour
      int slot = 0;
      for (int j = 0; j < 4; ++j) {
        if (j == i) continue;
        ++slot;
        if (tv[j] == low_[0]) byte = static_cast<std::uint8_t>(slot);
      }
      // the three triangles of t through v: the one opposite position m in slot s
      int s = 0;
      for (int m = 0; m < 4; ++m) {
        if (m == i) continue;
        int a = -1, b = -1; // the two other positions, a < b
        for (int j = 0; j < 4; ++j)
          if (j != i && j != m) (a < 0 ? a : b) = j;
        const int ra = rank_at(sk, a), rb = rank_at(sk, b);
        std::uint8_t code = 0;
        if (ra >= 0 && rb >= 0) {
          const std::int32_t f = triangle_id((std::max)(ra, rb), (std::min)(ra, rb), first_triangle);
          const std::int32_t p = cells_[f].partner;
          if (p >= 0 && cells_[p].dimension == 1)
            code = static_cast<int>(cells_[p].rank[0]) == ra ? 1 : 2;
          else if (p >= 0 && cells_[p].dimension == 3 && cells_[p].tetrahedron == t)
            code = 3;
        }
        byte = static_cast<std::uint8_t>(byte | (code << (2 + 2 * s)));
        ++s;
      }
      gradient[4 * static_cast<std::size_t>(t) + i] = byte;
    }
    for (std::size_t c = first_tet; c < n; ++c) {
      const Cell& cell = cells_[c];
      const Index t = cell.tetrahedron;
      if (cell.state == 2) {
        parent(t, t);
        continue;
      }
      // the tetrahedron across the triangle it is paired with: none on the boundary or when the
      // triangle is non-manifold
      const auto& around = triangle_tets_[static_cast<std::size_t>(cell.partner) - first_triangle];
      parent(t, around[2] == 2 ? (around[0] == t ? around[1] : around[0]) : none);
    }
  }

  // V - E + F - T of the simplices whose smallest vertex, in the octree's numbering (not the field
  // order), is `v`: counted apart from the lower star, so that the Euler characteristic it adds up
  // to checks the gradient's critical simplices.
  template <class Star>
  long long euler_at_smallest(const Octree& tree, Index v, const Star& star) {
    if (star.size() == 0) return 0;
    collect_neighbours(tree, v, star);
    long long chi = 1;
    for (Index u : nb_) chi -= (u > v);
    sorted_edges_.clear();
    for (const auto& e : link_edges_)
      if (nb_[e.first] > v && nb_[e.second] > v)
        sorted_edges_.push_back(e.first < e.second ? e : std::make_pair(e.second, e.first));
    std::sort(sorted_edges_.begin(), sorted_edges_.end());
    chi += static_cast<long long>(std::unique(sorted_edges_.begin(), sorted_edges_.end()) -
                                  sorted_edges_.begin());
    for (auto t : star) {
      const auto& tv = tree.tetrahedron(t);
      chi -= (tv[0] >= v && tv[1] >= v && tv[2] >= v && tv[3] >= v);
    }
    return chi;
  }

private:
  static std::uint64_t key(int hi, int lo) {
    return (static_cast<std::uint64_t>(hi) << 32) | static_cast<std::uint64_t>(lo);
  }
  template <class T>
  static int position(const T& tv, Index v) {
    for (int i = 0; i < 4; ++i)
      if (tv[i] == v) return i;
    return 0;
  }
  std::size_t slot_of(Index u) const {
    return static_cast<std::size_t>((static_cast<std::uint64_t>(u) * 0x9E3779B97F4A7C15ull) >>
                                    (64 - slot_bits_));
  }
  std::size_t neighbour_id(Index u) const {
    const std::size_t mask = slot_key_.size() - 1;
    std::size_t k = slot_of(u);
    while (slot_key_[k] != u) k = (k + 1) & mask;
    return slot_id_[k];
  }
  int insert_neighbour(Index u) {
    const std::size_t mask = slot_key_.size() - 1;
    std::size_t k = slot_of(u);
    for (;; k = (k + 1) & mask) {
      if (slot_key_[k] == u) return static_cast<int>(slot_id_[k]);
      if (slot_key_[k] == none) break;
    }
    slot_key_[k] = u;
    slot_id_[k] = static_cast<std::uint32_t>(nb_.size());
    used_slots_.push_back(static_cast<std::uint32_t>(k));
    nb_.push_back(u);
    return static_cast<int>(slot_id_[k]);
  }

  std::int32_t triangle_id(int hi, int lo, std::size_t first_triangle) const {
    const auto it = std::lower_bound(triangle_keys_.begin(), triangle_keys_.end(), key(hi, lo));
    return static_cast<std::int32_t>(first_triangle + static_cast<std::size_t>(it - triangle_keys_.begin()));
  }
  int unclassified_faces(std::int32_t c) const {
    int k = 0;
    for (int f : faces_[c]) k += (f >= 0 && cells_[f].state == 0);
    return k;
  }
  // G(a) < G(b): the decreasing rank sequences compared lexicographically, a prefix first
  bool less_g(std::int32_t a, std::int32_t b) const { return cells_[a].g < cells_[b].g; }
  // the neighbours of v (in the order met) and the link edges (pairs of neighbour ids, one per link triangle
  // side, duplicates kept)
  template <class Star>
  void collect_neighbours(const Octree& tree, Index v, const Star& star) {
    if (v == collected_ && star.size() == collected_size_)
      return; // the links and the lower star of one vertex
    collected_ = v;
    collected_size_ = star.size();
    // the table at most a quarter full
    int bits = 4;
    while ((std::size_t(1) << bits) < 4 * 3 * static_cast<std::size_t>(star.size())) ++bits;
    if (bits > slot_bits_) {
      slot_bits_ = bits;
      slot_key_.assign(std::size_t(1) << bits, none);
      slot_id_.assign(std::size_t(1) << bits, 0);
    } else {
      for (std::uint32_t k : used_slots_) slot_key_[k] = none;
    }
    used_slots_.clear();
    nb_.clear();
    link_edges_.clear();
    star_ids_.clear();
    for (auto t : star) {
      std::array<std::uint32_t, 3> o;
      std::array<int, 4> ids;
      int k = 0;
      for (int i = 0; i < 4; ++i) {
        const Index u = tree.tetrahedron(t)[i];
        ids[i] = u == v ? -1 : insert_neighbour(u);
        if (u != v) o[k++] = static_cast<std::uint32_t>(ids[i]);
      }
      star_ids_.push_back(ids);
      link_edges_.emplace_back(o[0], o[1]);
      link_edges_.emplace_back(o[0], o[2]);
      link_edges_.emplace_back(o[1], o[2]);
    }
  }

  std::vector<Index> nb_, low_, rep_;
  std::vector<std::array<int, 4>>
      star_ids_; // per star tetrahedron: the neighbour id at each position (-1: v)
  Index collected_ = none;
  std::size_t collected_size_ = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> link_edges_, sorted_edges_;
  std::vector<char> lower_;
  std::vector<int> rank_of_nb_;
  Union_find uf_; // local_complex.h
  Link_result<Index> link_;
  std::vector<Cell> cells_, tets_;
  std::vector<std::uint64_t> triangle_keys_;
  std::vector<std::pair<std::uint64_t, Index>> triangle_records_;
  std::vector<std::array<Index, 3>> triangle_tets_; // two tetrahedra of the star and their number
  // the neighbours' ids: an open-addressing table (vertex -> id in nb_), grown, never shrunk
  std::vector<Index> slot_key_;
  std::vector<std::uint32_t> slot_id_, used_slots_;
  int slot_bits_ = 0;
  std::vector<std::array<int, 3>> faces_;
  std::vector<std::size_t> coface_offsets_, fill_;
  std::vector<std::int32_t> cofaces_;
  std::vector<std::int32_t> queue_zero_, queue_one_;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_LOWER_STAR_H
