// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_LEAF_TOPOLOGY_H
#define CGAL_PR_STAR_OCTREE_LEAF_TOPOLOGY_H

/// \file Leaf_topology.h
/// Local topological relations of one leaf of a PR-star octree (paper Section 6), rebuilt from the
/// leaf's vertex range and tetrahedron list only, and the streaming visitor over all leaves.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/Relations.h>
#include <CGAL/PR_star_octree/internal/local_complex.h>
#include <CGAL/PR_star_octree/parameters.h>
#include <CGAL/Iterator_range.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {

/// \ingroup PkgPRStarOctreeRef
/// What the link of a vertex is.
enum class Vertex_type : unsigned char {
  UNREFERENCED = 0, ///< in no tetrahedron
  INTERIOR = 1,     ///< link is a triangulated sphere
  BOUNDARY = 2,     ///< link is a triangulated disc
  NONMANIFOLD = 3   ///< link is neither (pinched vertex, non-manifold edge or face, several sheets)
};

/// \ingroup PkgPRStarOctreeRef
/// The integer code of a vertex type in the files and arrays the package's tools write (the point
/// array `boundary` of `prstar boundary`, the Python module, the ParaView plugin): 0 interior,
/// 1 boundary, 2 non-manifold, 3 in no tetrahedron.
inline int vertex_type_code(Vertex_type t) {
  switch (t) {
  case Vertex_type::INTERIOR:
    return 0;
  case Vertex_type::BOUNDARY:
    return 1;
  case Vertex_type::NONMANIFOLD:
    return 2;
  default:
    return 3;
  }
}

static_assert(static_cast<int>(Vertex_type::UNREFERENCED) == static_cast<int>(internal::Link_kind::EMPTY) &&
                  static_cast<int>(Vertex_type::INTERIOR) == static_cast<int>(internal::Link_kind::CLOSED) &&
                  static_cast<int>(Vertex_type::BOUNDARY) == static_cast<int>(internal::Link_kind::OPEN) &&
                  static_cast<int>(Vertex_type::NONMANIFOLD) == static_cast<int>(internal::Link_kind::OTHER),
              "Vertex_type and internal::Link_kind must have the same values");

/// \ingroup PkgPRStarOctreeRef
///
/// The local topological data structure of one leaf `n` of a `PR_star_octree_3`, built from the
/// vertex range `[vertex_begin, vertex_end)` of `n` and its list of tetrahedra only.  Every relation
/// is exact for the simplices that have at least one vertex in the leaf (their stars are all in the
/// leaf's list).  All indices are in the octree's numbering; map them back with
/// `PR_star_octree_3::original_vertex()` and `original_tetrahedron()`.
///
/// Edges and triangles are *owned* by the leaf holding their smallest vertex: over a traversal of
/// all leaves, reporting only owned simplices reports each exactly once.
///
/// An object can be rebuilt for leaf after leaf: its buffers are reused, so the memory is bounded
/// by the largest leaf, not by the mesh.
template <class Octree>
class Leaf_topology {
public:
  using Index = typename Octree::Index;
  using Node_index = typename Octree::Node_index;
  using Tetrahedron = typename Octree::Tetrahedron;
  /// a contiguous read-only range of indices (valid until the next `build()`)
  using Index_range = CGAL::Iterator_range<const Index*>;

  /// adjacency across a face with a single tetrahedron (on the boundary of the mesh)
  static constexpr Index no_neighbor = (std::numeric_limits<Index>::max)();
  /// adjacency across a face with no vertex in the leaf: not reconstructed locally
  static constexpr Index unknown_neighbor = (std::numeric_limits<Index>::max)() - 1;

  struct Edge {
    Index v0, v1; ///< `v0 < v1`
  };

  Leaf_topology() = default;
  Leaf_topology(const Octree& tree, Node_index leaf, unsigned relations = ALL_RELATIONS) {
    build(tree, leaf, relations);
  }

  /// (Re)builds the relations `relations` (a combination of `Relations`) for leaf `leaf`.
  void build(const Octree& tree, Node_index leaf, unsigned relations);

  /// \name The leaf
  /// @{
  const Octree& octree() const { return *tree_; }
  Node_index leaf() const { return leaf_; }
  unsigned relations() const { return relations_; }
  Index vertex_begin() const { return vb_; }
  Index vertex_end() const { return ve_; }
  bool is_local_vertex(Index v) const { return vb_ <= v && v < ve_; }
  /// the tetrahedra of the leaf (its list); "local tetrahedron `i`" is `tetrahedra()[i]`
  typename Octree::Leaf_tetrahedra tetrahedra() const { return tree_->leaf_tetrahedra(leaf_); }
  /// the vertices of tetrahedron `t` of the leaf's list, as `Octree::tetrahedron(t)`, but without
  /// decoding again when the octree's tetrahedra are compact (the leaf's are decoded once by `build()`)
  /// \pre `t` is in `tetrahedra()`
  const Tetrahedron& tetrahedron(Index t) const { return tree_->is_compact() ? cells_[t] : plain_[t]; }
  /// the leaf's tetrahedra indexed by their index in T: `tetrahedron_map()[t]` is `tetrahedron(t)`
  /// (the array argument of the kernels that take one)
  struct Tetrahedron_map {
    const Leaf_topology* topology;
    const Tetrahedron& operator[](Index t) const { return topology->tetrahedron(t); }
  };
  Tetrahedron_map tetrahedron_map() const { return Tetrahedron_map{this}; }
  /// @}

  /// \name Vertex-tetrahedra (VT)
  /// @{
  /// the tetrahedra incident in `v` (a vertex of the leaf), in increasing index order
  Index_range vertex_tetrahedra(Index v) const { return csr(vt_offsets_, vt_, v - vb_); }
  /// @}

  /// \name Tetrahedron-tetrahedra (TT)
  /// @{
  /// the tetrahedra across the faces of local tetrahedron `i` (`[k]` is across the face opposite
  /// vertex `k`): a tetrahedron index, `no_neighbor` on the mesh boundary, or `unknown_neighbor`
  /// when the face has no vertex in the leaf
  const std::array<Index, 4>& tetrahedron_adjacency(std::size_t i) const { return tt_[i]; }
  /// @}

  /// \name Vertex-vertices (VV)
  /// @{
  /// the vertices adjacent to `v` (a vertex of the leaf), in increasing order
  Index_range vertex_vertices(Index v) const { return csr(vv_offsets_, vv_, v - vb_); }
  /// @}

  /// \name Edges
  /// @{
  /// the edges with at least one vertex in the leaf, sorted by `(v0, v1)`
  std::size_t number_of_edges() const { return edges_.size(); }
  const Edge& edge(std::size_t e) const { return edges_[e]; }
  /// whether the leaf owns edge `e` (its smaller vertex is in the leaf)
  bool owns_edge(std::size_t e) const { return is_local_vertex(edges_[e].v0); }
  /// the star of edge `e`: its tetrahedra in cyclic order around it (right-hand rule around
  /// `v0 -> v1`); for a boundary edge the fan runs from one boundary face to the other
  Index_range edge_tetrahedra(std::size_t e) const { return csr(et_offsets_, et_, e); }
  /// the link of edge `e`: the vertices opposite it, in the same cyclic order (one more vertex than
  /// tetrahedra when the edge is on the boundary)
  Index_range edge_link(std::size_t e) const { return csr(el_offsets_, el_, e); }
  /// whether the star of edge `e` is an open fan (the edge is on the boundary of the mesh)
  bool is_boundary_edge(std::size_t e) const { return edge_flags_[e] & boundary_flag; }
  /// whether the star of edge `e` is neither a closed cycle nor an open fan (non-manifold)
  bool is_nonmanifold_edge(std::size_t e) const { return edge_flags_[e] & nonmanifold_flag; }
  /// the edges incident in `v` (a vertex of the leaf), as edge ids
  Index_range vertex_edges(Index v) const { return csr(vedge_offsets_, vedge_, v - vb_); }
  /// @}

  /// \name Triangles
  /// @{
  /// the triangles with at least one vertex in the leaf, vertices sorted, triangles sorted
  std::size_t number_of_triangles() const { return triangles_.size(); }
  const std::array<Index, 3>& triangle(std::size_t f) const { return triangles_[f]; }
  bool owns_triangle(std::size_t f) const { return is_local_vertex(triangles_[f][0]); }
  /// the tetrahedra incident in triangle `f`: one on the boundary, two inside, more if non-manifold
  Index_range triangle_tetrahedra(std::size_t f) const { return csr(ft_offsets_, ft_, f); }
  /// @}

  /// \name Vertex links (`VERTEX_LINKS`) and local ids (`LOCAL_TETRAHEDRA`)
  /// @{
  /// the kind of the link of vertex `v` of the leaf (`VERTEX_LINKS` must have been built; checked
  /// to be a sphere or a disc unless `UNCHECKED_LINKS` was given)
  Vertex_type vertex_type(Index v) const { return static_cast<Vertex_type>(links_.kind(v - vb_)); }
  /// the number of local vertex ids: `[0, vertex_end() - vertex_begin())` are the leaf's vertices
  /// in order, the others are the other vertices of the leaf's tetrahedra (`VERTEX_LINKS` or
  /// `LOCAL_TETRAHEDRA` must have been built)
  std::size_t number_of_local_vertices() const { return links_.number_of_ids(); }
  /// the vertex (octree numbering) of local id `j`
  Index local_vertex(std::size_t j) const { return links_.vertex(j); }
  /// local tetrahedron `i` (`tetrahedra()[i]`) in local vertex ids, its vertices in the same order as
  /// in the octree (`LOCAL_TETRAHEDRA` must have been built)
  const std::array<std::uint32_t, 4>& local_tetrahedron(std::size_t i) const { return links_.tetrahedron(i); }
  /// @}

  /// \name Links (computed on demand from VT)
  /// @{
  /// the link of vertex `v` of the leaf: the face `(a, b, c)` opposite `v` in each tetrahedron of
  /// its star, ordered so that `(v, a, b, c)` is positively oriented
  template <class OutputIterator>
  OutputIterator vertex_link(Index v, OutputIterator out) const {
    for (Index t : vertex_tetrahedra(v)) {
      const Tetrahedron& c = tetrahedron(t);
      const int k = internal::position(c, v);
      const auto& f = internal::link_face[k];
      *out++ = std::array<Index, 3>{{c[f[0]], c[f[1]], c[f[2]]}};
    }
    return out;
  }
  /// @}

  /// the bytes held by this local structure (its buffers' capacities)
  std::size_t memory_bytes() const {
    auto b = [](const auto& v) {
      return v.capacity() * sizeof(typename std::decay_t<decltype(v)>::value_type);
    };
    return b(vt_offsets_) + b(vt_) + b(tt_) + b(vv_offsets_) + b(vv_) + b(edges_) + b(edge_flags_) +
           b(et_offsets_) + b(et_) + b(el_offsets_) + b(el_) + b(vedge_offsets_) + b(vedge_) + b(triangles_) +
           b(ft_offsets_) + b(ft_) + faces_.capacity_bytes() + b(edge_records_) + b(scratch_) + b(star_) +
           links_.memory_bytes() + cells_.memory_bytes();
  }

private:
  static constexpr unsigned char boundary_flag = 1, nonmanifold_flag = 2;

  static Index_range csr(const std::vector<Index>& offsets, const std::vector<Index>& data, std::size_t i) {
    return Index_range(data.data() + offsets[i], data.data() + offsets[i + 1]);
  }

  template <class Tetrahedra>
  void build_with(const Tetrahedra& T, unsigned relations);
  template <class Tetrahedra>
  void build_faces(const Tetrahedra& T, bool adjacency, bool triangles);
  template <class Tetrahedra>
  void build_vv(const Tetrahedra& T);
  template <class Tetrahedra>
  void build_edges(const Tetrahedra& T);

  struct Edge_record {
    Index a, b, t;
    bool operator<(const Edge_record& o) const { return std::tie(a, b, t) < std::tie(o.a, o.b, o.t); }
  };

  const Octree* tree_ = nullptr;
  Node_index leaf_ = 0;
  unsigned relations_ = 0;
  Index vb_ = 0, ve_ = 0;
  const Tetrahedron* plain_ = nullptr; // the octree's plain array, or
  internal::Leaf_cells<Index> cells_;  // the leaf's tetrahedra decoded from the compact one

  std::vector<Index> vt_offsets_, vt_;
  std::vector<std::array<Index, 4>> tt_;
  std::vector<Index> vv_offsets_, vv_;
  std::vector<Edge> edges_;
  std::vector<unsigned char> edge_flags_;
  std::vector<Index> et_offsets_, et_, el_offsets_, el_, vedge_offsets_, vedge_;
  std::vector<std::array<Index, 3>> triangles_;
  std::vector<Index> ft_offsets_, ft_;
  internal::Face_pairing<Index> faces_;
  internal::Edge_fan<Index> fan_;
  std::vector<Edge_record> edge_records_;
  std::vector<Index> scratch_, star_;
  internal::Leaf_links<Index> links_;
};

} // namespace PR_star_octree
} // namespace CGAL

#include <CGAL/PR_star_octree/internal/Leaf_topology_impl.h>

namespace CGAL {
namespace PR_star_octree {

// ---------------------------------------------------------------------------------------------
// Streaming and random access
// ---------------------------------------------------------------------------------------------

/// \ingroup PkgPRStarOctreeRef
/// The star of vertex `v` (VT), by random access: finds the leaf of `v` and scans its list.
/// Appends tetrahedron indices in increasing order to `out`.
template <class GT, class I, class OutputIterator>
OutputIterator vertex_star(const PR_star_octree_3<GT, I>& tree, typename PR_star_octree_3<GT, I>::Index v,
                           OutputIterator out) {
  tree.for_each_leaf_tetrahedron(tree.leaf_of_vertex(v), [&](I t, const auto& c) {
    if (c[0] == v || c[1] == v || c[2] == v || c[3] == v) *out++ = t;
  });
  return out;
}

/// \ingroup PkgPRStarOctreeRef
/// The tetrahedra across the four faces of tetrahedron `t` (TT), by random access:
/// `[k]` is across the face opposite vertex `k`, or `Leaf_topology<Octree>::no_neighbor`.
template <class GT, class I>
std::array<I, 4> tetrahedron_neighbors(const PR_star_octree_3<GT, I>& tree,
                                       typename PR_star_octree_3<GT, I>::Index t) {
  using Octree = PR_star_octree_3<GT, I>;
  using Index = I;
  std::array<Index, 4> result;
  const auto c = tree.tetrahedron(t);
  for (int k = 0; k < 4; ++k) {
    result[k] = Leaf_topology<Octree>::no_neighbor;
    const Index a = c[(k + 1) & 3], b = c[(k + 2) & 3], d = c[(k + 3) & 3];
    // Both tetrahedra of the face are in the star of its vertex a, hence in a's leaf.
    tree.for_each_leaf_tetrahedron(tree.leaf_of_vertex(a), [&](Index u, const auto& x) {
      if (u == t) return true;
      int shared = 0;
      for (Index w : x) shared += (w == a) + (w == b) + (w == d);
      if (shared == 3) result[k] = u;
      return shared != 3; // (stop at the first one)
    });
  }
  return result;
}

/// \ingroup PkgPRStarOctreeRef
/// Counts of the simplices of the mesh obtained by local processing only.
struct Simplex_counts {
  std::size_t vertices = 0; ///< referenced vertices (in at least one tetrahedron)
  std::size_t edges = 0;
  std::size_t triangles = 0;
  std::size_t boundary_triangles = 0;    ///< triangles with one incident tetrahedron
  std::size_t nonmanifold_triangles = 0; ///< triangles with three or more incident tetrahedra
  std::size_t tetrahedra = 0;
  /// V - E + F - T over the referenced vertices
  long long euler_characteristic() const {
    return static_cast<long long>(vertices) - static_cast<long long>(edges) +
           static_cast<long long>(triangles) - static_cast<long long>(tetrahedra);
  }
};

} // namespace PR_star_octree
} // namespace CGAL

// The leaf executor, `for_each_leaf()` and `count_simplices()`.
#include <CGAL/PR_star_octree/Leaf_executor.h>

#endif // CGAL_PR_STAR_OCTREE_LEAF_TOPOLOGY_H
