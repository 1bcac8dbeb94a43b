// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_LEAF_TOPOLOGY_IMPL_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_LEAF_TOPOLOGY_IMPL_H

// The construction of the relations of `CGAL::PR_star_octree::Leaf_topology` (included by
// Leaf_topology.h), on the local-complex kernel.

#include <CGAL/PR_star_octree/Leaf_topology.h>
#include <CGAL/PR_star_octree/internal/local_complex.h>

#include <algorithm>
#include <array>
#include <cstddef>

namespace CGAL {
namespace PR_star_octree {

template <class Octree>
void Leaf_topology<Octree>::build(const Octree& tree, Node_index leaf, unsigned relations) {
  tree_ = &tree;
  leaf_ = leaf;
  vb_ = tree.node(leaf).vertex_begin;
  ve_ = tree.node(leaf).vertex_end;
  // Dependencies: VV and edges are built from VT.
  if (relations & (VERTEX_VERTICES | EDGES)) relations |= VERTEX_TETRAHEDRA;
  relations_ = relations;
  plain_ = tree.tetrahedra().data();
  if (tree.is_compact()) {
    // The leaf's tetrahedra are decoded once; every relation is built from this copy.
    const auto tets = tetrahedra();
    cells_.decode(tree.compact_tetrahedra(), tets.shared(), tets.owned());
    build_with(typename internal::Leaf_cells<Index>::Reader(cells_), relations);
  } else
    build_with(plain_, relations);
}

template <class Octree>
template <class Tetrahedra>
void Leaf_topology<Octree>::build_with(const Tetrahedra& T, unsigned relations) {
  if (relations & VERTEX_TETRAHEDRA) {
    const auto tets = tetrahedra();
    internal::build_leaf_vertex_tetrahedra(T, tets.shared(), tets.owned(), vb_, ve_ - vb_, vt_offsets_, vt_,
                                           scratch_);
  }
  if (relations & (TETRAHEDRON_ADJACENCY | TRIANGLES))
    build_faces(T, relations & TETRAHEDRON_ADJACENCY, relations & TRIANGLES);
  if (relations & VERTEX_VERTICES) build_vv(T);
  if (relations & EDGES) build_edges(T);
  if (relations & (VERTEX_LINKS | LOCAL_TETRAHEDRA)) {
    const auto tets = tetrahedra();
    links_.build(T, tets.shared(), tets.owned(), vb_, ve_ - vb_, !(relations & UNCHECKED_LINKS),
                 (relations & LOCAL_TETRAHEDRA) != 0, (relations & VERTEX_LINKS) != 0);
  }
}

// Algorithm 2 and the triangles: the faces with a vertex in the leaf, paired by the kernel.
template <class Octree>
template <class Tetrahedra>
void Leaf_topology<Octree>::build_faces(const Tetrahedra& T, bool adjacency, bool triangles) {
  const auto tets = tetrahedra();
  faces_.build(T, tets, vb_, ve_);
  if (adjacency)
    tt_.assign(tets.size(), std::array<Index, 4>{
                                {unknown_neighbor, unknown_neighbor, unknown_neighbor, unknown_neighbor}});
  if (triangles) {
    triangles_.clear();
    ft_offsets_.assign(1, 0);
    ft_.clear();
  }
  faces_.for_each_triangle([&](auto a, auto b) {
    if (adjacency) {
      if (b - a == 1)
        tt_[a->local][a->k] = no_neighbor;
      else if (b - a == 2) {
        tt_[a->local][a->k] = tets[(a + 1)->local];
        tt_[(a + 1)->local][(a + 1)->k] = tets[a->local];
      } // non-manifold faces (3+ tetrahedra) keep unknown_neighbor: see triangle_tetrahedra()
    }
    if (triangles) {
      triangles_.push_back(a->v);
      for (auto r = a; r != b; ++r) ft_.push_back(tets[r->local]);
      ft_offsets_.push_back(static_cast<Index>(ft_.size()));
    }
  });
}

template <class Octree>
template <class Tetrahedra>
void Leaf_topology<Octree>::build_vv(const Tetrahedra& T) {
  const std::size_t nv = ve_ - vb_;
  vv_offsets_.assign(1, 0);
  vv_.clear();
  for (std::size_t i = 0; i < nv; ++i) {
    const Index v = static_cast<Index>(vb_ + i);
    internal::star_neighbors(T, vertex_tetrahedra(v), v, vv_, vv_.size());
    vv_offsets_.push_back(static_cast<Index>(vv_.size()));
  }
}

template <class Octree>
template <class Tetrahedra>
void Leaf_topology<Octree>::build_edges(const Tetrahedra& T) {
  // Every edge with a vertex in the leaf appears in the VT of that vertex.
  const std::size_t nv = ve_ - vb_;
  edge_records_.clear();
  for (std::size_t i = 0; i < nv; ++i) {
    const Index v = static_cast<Index>(vb_ + i);
    for (Index t : vertex_tetrahedra(v))
      for (Index w : T[t]) {
        if (w == v) continue;
        // Record the edge once: from its smaller local vertex.
        if (is_local_vertex(w) && w < v) continue;
        edge_records_.push_back(Edge_record{(std::min)(v, w), (std::max)(v, w), t});
      }
  }
  std::sort(edge_records_.begin(), edge_records_.end());

  edges_.clear();
  edge_flags_.clear();
  et_offsets_.assign(1, 0);
  et_.clear();
  el_offsets_.assign(1, 0);
  el_.clear();
  internal::for_each_group(
      edge_records_.begin(), edge_records_.end(),
      [](const Edge_record& x, const Edge_record& y) { return x.a == y.a && x.b == y.b; },
      [&](auto first, auto last) {
        star_.clear();
        for (auto r = first; r != last; ++r) star_.push_back(r->t);
        fan_.build(T, star_, first->a, first->b);
        et_.insert(et_.end(), fan_.tetrahedra().begin(), fan_.tetrahedra().end());
        el_.insert(el_.end(), fan_.link().begin(), fan_.link().end());
        edges_.push_back(Edge{first->a, first->b});
        edge_flags_.push_back(static_cast<unsigned char>((fan_.is_boundary() ? boundary_flag : 0) |
                                                         (fan_.is_nonmanifold() ? nonmanifold_flag : 0)));
        et_offsets_.push_back(static_cast<Index>(et_.size()));
        el_offsets_.push_back(static_cast<Index>(el_.size()));
      });

  // VE: the edges of each vertex of the leaf.
  vedge_offsets_.assign(nv + 1, 0);
  for (const Edge& e : edges_) {
    if (is_local_vertex(e.v0)) ++vedge_offsets_[e.v0 - vb_ + 1];
    if (is_local_vertex(e.v1)) ++vedge_offsets_[e.v1 - vb_ + 1];
  }
  for (std::size_t i = 0; i < nv; ++i) vedge_offsets_[i + 1] += vedge_offsets_[i];
  vedge_.resize(vedge_offsets_[nv]);
  scratch_.assign(vedge_offsets_.begin(), vedge_offsets_.end() - 1);
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    if (is_local_vertex(edges_[e].v0)) vedge_[scratch_[edges_[e].v0 - vb_]++] = static_cast<Index>(e);
    if (is_local_vertex(edges_[e].v1)) vedge_[scratch_[edges_[e].v1 - vb_]++] = static_cast<Index>(e);
  }
}

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_LEAF_TOPOLOGY_IMPL_H
