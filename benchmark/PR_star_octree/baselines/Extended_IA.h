// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The extended IA data structure (paper Section 2.3), the global baseline of the PR-star octree:
// the indexed mesh (V, T) plus, for every tetrahedron, the four tetrahedra across its faces (TT),
// and, for every vertex, one tetrahedron of its star (VT*).  VT is extracted by walking around the
// vertex across the faces that contain it.
//
// The structure references the caller's arrays (it does not copy V and T) and stores only the
// topological overhead 4|T| + |V| indices.

#ifndef PRSTAR_BASELINES_EXTENDED_IA_H
#define PRSTAR_BASELINES_EXTENDED_IA_H

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace prstar_baselines {

template <class Index = std::uint32_t>
class Extended_IA {
public:
  using Tetrahedron = std::array<Index, 4>;
  /// across a boundary face
  static constexpr Index no_neighbor = (std::numeric_limits<Index>::max)();

  /// Builds TT and VT* from the tetrahedra of a mesh with `number_of_vertices` vertices.
  /// Throws std::runtime_error on a non-manifold face (three or more tetrahedra).
  Extended_IA(std::size_t number_of_vertices, const std::vector<Tetrahedron>& tetrahedra)
      : tets_(&tetrahedra), tt_(tetrahedra.size()), vt_star_(number_of_vertices, no_neighbor) {
    const std::size_t nv = number_of_vertices, nt = tetrahedra.size();
    // A temporary full VT (CSR), freed at the end of the construction.
    std::vector<Index> offsets(nv + 1, 0);
    for (const Tetrahedron& c : tetrahedra)
      for (Index v : c) ++offsets[v + 1];
    for (std::size_t v = 0; v < nv; ++v) offsets[v + 1] += offsets[v];
    std::vector<Index> vt(offsets[nv]);
    {
      std::vector<Index> pos(offsets.begin(), offsets.end() - 1);
      for (std::size_t t = 0; t < nt; ++t)
        for (Index v : tetrahedra[t]) vt[pos[v]++] = static_cast<Index>(t);
    }
    for (std::size_t v = 0; v < nv; ++v)
      if (offsets[v] != offsets[v + 1]) vt_star_[v] = vt[offsets[v]];
    // TT: the other tetrahedron of a face is in the star of the face's smallest vertex.
    for (std::size_t t = 0; t < nt; ++t) {
      const Tetrahedron& c = tetrahedra[t];
      for (int k = 0; k < 4; ++k) {
        const Index a = c[(k + 1) & 3], b = c[(k + 2) & 3], d = c[(k + 3) & 3];
        const Index m = (std::min)({a, b, d});
        Index found = no_neighbor;
        for (Index i = offsets[m]; i < offsets[m + 1]; ++i) {
          const Index u = vt[i];
          if (u == t) continue;
          const Tetrahedron& x = tetrahedra[u];
          int shared = 0;
          for (Index w : x) shared += (w == a) + (w == b) + (w == d);
          if (shared == 3) {
            if (found != no_neighbor)
              throw std::runtime_error("extended IA: non-manifold face in tetrahedron " + std::to_string(t));
            found = u;
          }
        }
        tt_[t][k] = found;
      }
    }
  }

  std::size_t number_of_vertices() const { return vt_star_.size(); }
  std::size_t number_of_tetrahedra() const { return tt_.size(); }
  const Tetrahedron& tetrahedron(Index t) const { return (*tets_)[t]; }
  /// the tetrahedron across the face of `t` opposite its vertex `k`, or `no_neighbor`
  Index neighbor(Index t, int k) const { return tt_[t][k]; }
  const std::array<Index, 4>& neighbors(Index t) const { return tt_[t]; }
  /// one tetrahedron incident in `v`, or `no_neighbor` for an unreferenced vertex
  Index vertex_tetrahedron(Index v) const { return vt_star_[v]; }

  /// VT: the star of `v`, by walking from VT*(v) across the faces incident in `v`.  `out` is
  /// cleared and filled (visit order); `stack` is scratch space reused between calls.  Visited
  /// tetrahedra are recognised by a per-tetrahedron stamp (query scratch, 4 bytes per
  /// tetrahedron, allocated on the first query and not counted in `overhead_bytes()`).
  void vertex_tetrahedra(Index v, std::vector<Index>& out, std::vector<Index>& stack) const {
    out.clear();
    stack.clear();
    const Index start = vt_star_[v];
    if (start == no_neighbor) return;
    if (stamp_.size() != tt_.size()) stamp_.assign(tt_.size(), 0);
    if (++generation_ == 0) { // wrapped around: reset the stamps
      std::fill(stamp_.begin(), stamp_.end(), 0);
      generation_ = 1;
    }
    stamp_[start] = generation_;
    out.push_back(start);
    stack.push_back(start);
    while (!stack.empty()) {
      const Index t = stack.back();
      stack.pop_back();
      const Tetrahedron& c = (*tets_)[t];
      const std::array<Index, 4>& n = tt_[t];
      for (int k = 0; k < 4; ++k) {
        if (c[k] == v) continue; // the face opposite v does not contain v
        const Index u = n[k];
        if (u == no_neighbor || stamp_[u] == generation_) continue;
        stamp_[u] = generation_;
        out.push_back(u);
        stack.push_back(u);
      }
    }
  }

  /// whether `v` is on the boundary: a face of its star incident in `v` has no neighbor
  bool is_boundary_vertex(Index v, std::vector<Index>& star, std::vector<Index>& stack) const {
    vertex_tetrahedra(v, star, stack);
    for (Index t : star) {
      const Tetrahedron& c = (*tets_)[t];
      for (int k = 0; k < 4; ++k)
        if (c[k] != v && tt_[t][k] == no_neighbor) return true;
    }
    return false;
  }

  /// bytes of the topological overhead (TT and VT*); V and T belong to the caller
  std::size_t overhead_bytes() const {
    return tt_.capacity() * sizeof(std::array<Index, 4>) + vt_star_.capacity() * sizeof(Index);
  }

private:
  const std::vector<Tetrahedron>* tets_;
  std::vector<std::array<Index, 4>> tt_;
  std::vector<Index> vt_star_;
  mutable std::vector<std::uint32_t> stamp_;
  mutable std::uint32_t generation_ = 0;
};

} // namespace prstar_baselines

#endif // PRSTAR_BASELINES_EXTENDED_IA_H
