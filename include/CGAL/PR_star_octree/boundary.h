// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_BOUNDARY_H
#define CGAL_PR_STAR_OCTREE_BOUNDARY_H

/// \file boundary.h
/// Boundary determination on a PR-star octree (paper Section 7): every vertex classified as
/// interior or boundary by an Euler-type count on its link, leaf by leaf, plus the detection of
/// non-manifold vertices (link neither a sphere nor a disc).

#include <CGAL/PR_star_octree/Leaf_topology.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
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

namespace internal {

// Union-find on small local index sets.
struct Small_union_find {
  std::vector<std::uint32_t> parent;
  void reset(std::size_t n) {
    parent.resize(n);
    for (std::size_t i = 0; i < n; ++i) parent[i] = static_cast<std::uint32_t>(i);
  }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  bool unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent[a] = b;
    return true;
  }
};

} // namespace internal

/// \ingroup PkgPRStarOctreeRef
///
/// Classifies the vertices of one leaf from its vertex-tetrahedra relation only.
///
/// For a vertex `v` with star `St(v)`, the triangles of its link are the faces opposite `v` (one per
/// tetrahedron, `|t| = |St(v)|`), and the edges of its link are the triangles incident in `v`
/// (`|e|`).  In a manifold mesh `v` is interior exactly when every link edge bounds two link
/// triangles, i.e. `2|e| = 3|t|` (paper Section 7); this is the `O(1)`-per-vertex test once the local
/// structure is built.  The link is also checked to be a sphere or a disc (connected, every link
/// edge in at most two link triangles, the link boundary a single simple loop, Euler
/// characteristic 2 or 1, every link vertex a manifold point): otherwise the vertex is reported
/// `NONMANIFOLD` instead of being silently misclassified.
template <class Octree>
class Vertex_classifier {
public:
  using Index = typename Octree::Index;

  /// classifies vertex `v` of the leaf of `local` (VT must have been built)
  Vertex_type classify(const Leaf_topology<Octree>& local, Index v) {
    const auto star = local.vertex_tetrahedra(v);
    if (star.empty()) return Vertex_type::UNREFERENCED;
    const Octree& tree = local.octree();
    // Link edges: for each tetrahedron (v, a, b, c), the link triangle (a, b, c) has the three
    // edges (a,b), (b,c), (a,c).
    edges_.clear();
    for (Index t : star) {
      const auto& c = tree.tetrahedron(t);
      Index o[3];
      int n = 0;
      for (Index w : c)
        if (w != v) o[n++] = w;
      std::sort(o, o + 3);
      edges_.push_back({o[0], o[1]});
      edges_.push_back({o[1], o[2]});
      edges_.push_back({o[0], o[2]});
    }
    std::sort(edges_.begin(), edges_.end());
    // Count distinct link edges and their multiplicities.
    std::size_t distinct = 0, boundary_edges = 0;
    bool overfull = false;
    for (std::size_t i = 0; i < edges_.size();) {
      std::size_t j = i + 1;
      while (j < edges_.size() && edges_[j] == edges_[i]) ++j;
      ++distinct;
      if (j - i == 1) ++boundary_edges;
      if (j - i > 2) overfull = true;
      i = j;
    }
    const bool euler_boundary = 2 * distinct != 3 * star.size(); // the paper's test
    if (overfull) return Vertex_type::NONMANIFOLD;
    if (!is_disc_or_sphere(boundary_edges, distinct, star.size())) return Vertex_type::NONMANIFOLD;
    return euler_boundary ? Vertex_type::BOUNDARY : Vertex_type::INTERIOR;
  }

private:
  // `edges_` is sorted, each link edge at most twice.  Checks connectivity, the boundary loop,
  // the Euler characteristic, and that each link vertex has a disc or half-disc neighbourhood
  // (its link edges form a single path or cycle).
  bool is_disc_or_sphere(std::size_t boundary_edges, std::size_t link_edges, std::size_t link_triangles) {
    // Link vertices: local ids.
    verts_.clear();
    for (const auto& e : edges_) {
      verts_.push_back(e.first);
      verts_.push_back(e.second);
    }
    std::sort(verts_.begin(), verts_.end());
    verts_.erase(std::unique(verts_.begin(), verts_.end()), verts_.end());
    auto id = [&](Index x) {
      return static_cast<std::uint32_t>(std::lower_bound(verts_.begin(), verts_.end(), x) - verts_.begin());
    };
    const std::size_t nv = verts_.size();
    const long long chi = static_cast<long long>(nv) - static_cast<long long>(link_edges) +
                          static_cast<long long>(link_triangles);
    if (boundary_edges == 0 ? chi != 2 : chi != 1) return false;
    // Connected link; boundary edges form one simple loop.
    uf_.reset(nv);
    std::size_t components = nv;
    boundary_degree_.assign(nv, 0);
    std::size_t boundary_vertices = 0;
    for (std::size_t i = 0; i < edges_.size();) {
      const bool twice = i + 1 < edges_.size() && edges_[i + 1] == edges_[i];
      const std::uint32_t a = id(edges_[i].first), b = id(edges_[i].second);
      if (uf_.unite(a, b)) --components;
      if (!twice) {
        boundary_vertices += (boundary_degree_[a]++ == 0);
        boundary_vertices += (boundary_degree_[b]++ == 0);
      }
      i += twice ? 2 : 1;
    }
    if (components != 1) return false;
    if (boundary_edges == 0) return true;
    for (std::size_t i = 0; i < nv; ++i)
      if (boundary_degree_[i] != 0 && boundary_degree_[i] != 2) return false;
    // Boundary vertices all of degree 2: disjoint cycles; a single loop has as many vertices as
    // edges and is connected.
    if (boundary_vertices != boundary_edges) return false;
    uf_.reset(nv);
    std::size_t loops = boundary_vertices;
    for (std::size_t i = 0; i < edges_.size();) {
      const bool twice = i + 1 < edges_.size() && edges_[i + 1] == edges_[i];
      if (!twice && uf_.unite(id(edges_[i].first), id(edges_[i].second))) --loops;
      i += twice ? 2 : 1;
    }
    return loops == 1;
  }

  std::vector<std::pair<Index, Index>> edges_;
  std::vector<Index> verts_;
  std::vector<unsigned char> boundary_degree_;
  internal::Small_union_find uf_;
};

/// \ingroup PkgPRStarOctreeRef
/// The boundary of a tetrahedral mesh found leaf by leaf.  Vertex results are kept in a packed
/// array of two bits per vertex (octree numbering); use `PR_star_octree_3::original_vertex()` for
/// the user's numbering, or `vertex_types_in_original_order()`.
template <class Octree>
struct Boundary_result {
  using Index = typename Octree::Index;
  std::vector<Vertex_type> vertex_type;                 ///< per vertex (octree numbering)
  std::vector<std::array<Index, 3>> boundary_triangles; ///< triangles with one tetrahedron (octree numbering)
  std::size_t boundary_vertices = 0;
  std::size_t interior_vertices = 0;
  std::size_t nonmanifold_vertices = 0;
  std::size_t unreferenced_vertices = 0;
  std::size_t boundary_tetrahedra = 0; ///< tetrahedra with at least one boundary (or non-manifold) vertex
  std::size_t boundary_face_tetrahedra = 0; ///< tetrahedra with at least one face on the boundary

  bool is_boundary(Index v) const { return vertex_type[v] == Vertex_type::BOUNDARY; }
};

/// \ingroup PkgPRStarOctreeRef
/// Computes the boundary of the mesh of `tree` by streaming over its leaves: the type of every
/// vertex, the boundary triangles (each reported once, by the leaf owning its smallest vertex)
/// and the number of tetrahedra touching the boundary.
template <class Octree>
Boundary_result<Octree> compute_boundary(const Octree& tree, bool with_triangles = true) {
  using Index = typename Octree::Index;
  Boundary_result<Octree> r;
  r.vertex_type.assign(tree.number_of_vertices(), Vertex_type::UNREFERENCED);
  Vertex_classifier<Octree> classifier;
  const unsigned relations = VERTEX_TETRAHEDRA | (with_triangles ? TRIANGLES : 0u);
  for_each_leaf(tree, relations, [&](const Leaf_topology<Octree>& local) {
    for (Index v = local.vertex_begin(); v < local.vertex_end(); ++v)
      r.vertex_type[v] = classifier.classify(local, v);
    if (!with_triangles) return;
    for (std::size_t f = 0; f < local.number_of_triangles(); ++f)
      if (local.owns_triangle(f) && local.triangle_tetrahedra(f).size() == 1)
        r.boundary_triangles.push_back(local.triangle(f));
  });
  for (Vertex_type t : r.vertex_type) {
    r.boundary_vertices += t == Vertex_type::BOUNDARY;
    r.interior_vertices += t == Vertex_type::INTERIOR;
    r.nonmanifold_vertices += t == Vertex_type::NONMANIFOLD;
    r.unreferenced_vertices += t == Vertex_type::UNREFERENCED;
  }
  for (const auto& c : tree.tetrahedra()) {
    bool touches = false;
    for (Index v : c)
      touches = touches || r.vertex_type[v] == Vertex_type::BOUNDARY ||
                r.vertex_type[v] == Vertex_type::NONMANIFOLD;
    r.boundary_tetrahedra += touches;
  }
  if (with_triangles) {
    // A tetrahedron has a boundary face when one of its faces is a boundary triangle: mark them
    // through the owning leaves again (cheap: only faces, no vertex work).
    std::vector<char> has_face(tree.number_of_tetrahedra(), 0);
    for_each_leaf(tree, TRIANGLES, [&](const Leaf_topology<Octree>& local) {
      for (std::size_t f = 0; f < local.number_of_triangles(); ++f)
        if (local.owns_triangle(f) && local.triangle_tetrahedra(f).size() == 1)
          has_face[local.triangle_tetrahedra(f)[0]] = 1;
    });
    r.boundary_face_tetrahedra = static_cast<std::size_t>(std::count(has_face.begin(), has_face.end(), 1));
  }
  return r;
}

/// \ingroup PkgPRStarOctreeRef
/// The boundary flags as a bit array over the vertices in the user's original numbering
/// (`|V|` bits): `true` for boundary vertices.
template <class Octree>
std::vector<bool> boundary_bit_array(const Octree& tree, const Boundary_result<Octree>& r) {
  std::vector<bool> bits(tree.number_of_vertices(), false);
  for (std::size_t v = 0; v < bits.size(); ++v)
    if (r.vertex_type[v] == Vertex_type::BOUNDARY)
      bits[tree.original_vertex(static_cast<typename Octree::Index>(v))] = true;
  return bits;
}

/// \ingroup PkgPRStarOctreeRef
/// The boundary flags kept *in place* in a copy of the tetrahedron array (paper Section 7): each
/// vertex index `v` of the octree's `T` is written as `v` for an interior vertex and `-(v + 1)` for
/// a boundary vertex.  Decode with `decode_vertex()` and `is_encoded_boundary()`.
template <class Octree>
std::vector<std::array<std::int64_t, 4>> tetrahedra_with_boundary_signs(const Octree& tree,
                                                                        const Boundary_result<Octree>& r) {
  std::vector<std::array<std::int64_t, 4>> t(tree.number_of_tetrahedra());
  for (std::size_t i = 0; i < t.size(); ++i)
    for (int k = 0; k < 4; ++k) {
      const auto v = tree.tetrahedron(static_cast<typename Octree::Index>(i))[k];
      t[i][k] = r.vertex_type[v] == Vertex_type::BOUNDARY ? -static_cast<std::int64_t>(v) - 1
                                                          : static_cast<std::int64_t>(v);
    }
  return t;
}

/// \ingroup PkgPRStarOctreeRef
inline bool is_encoded_boundary(std::int64_t x) {
  return x < 0;
}
/// \ingroup PkgPRStarOctreeRef
inline std::int64_t decode_vertex(std::int64_t x) {
  return x < 0 ? -x - 1 : x;
}

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_BOUNDARY_H
