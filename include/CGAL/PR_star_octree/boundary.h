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
#include <stdexcept>
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

  /// `check_links = false` gives the paper's test alone (2|e| != 3|t|, and a triangle in three or
  /// more tetrahedra): faster, but it trusts the mesh to be manifold at the vertex.
  explicit Vertex_classifier(bool check_links = true) : check_links_(check_links) {}

  /// classifies vertex `v` of the leaf of `local` (VT must have been built)
  Vertex_type classify(const Leaf_topology<Octree>& local, Index v) {
    const auto star = local.vertex_tetrahedra(v);
    if (star.empty()) return Vertex_type::UNREFERENCED;
    const auto* T = local.octree().tetrahedra().data();
    // The link: vertices (local ids by a small hash map) and edges with their multiplicities.
    // For each tetrahedron (v, a, b, c), the link triangle (a, b, c) has the edges (a,b), (b,c), (a,c).
    if (check_links_) vertex_ids_.reset(3 * star.size());
    edge_ids_.reset(3 * star.size());
    link_edges_.clear();
    std::uint32_t nv = 0;
    for (Index t : star) {
      const auto& c = T[t];
      std::uint64_t o[3];
      int n = 0;
      for (int k = 0; k < 4; ++k)
        if (c[k] != v) o[n++] = c[k];
      std::uint32_t id[3] = {0, 0, 0};
      if (check_links_)
        for (int i = 0; i < 3; ++i) id[i] = vertex_ids_.find_or_insert(o[i], nv);
      const int pairs[3][2] = {{0, 1}, {1, 2}, {0, 2}};
      for (const auto& p : pairs) {
        const std::uint64_t a = o[p[0]], b = o[p[1]];
        const std::uint64_t key = a < b ? (a << 32 | b) : (b << 32 | a);
        std::uint32_t next = static_cast<std::uint32_t>(link_edges_.size());
        const std::uint32_t e = edge_ids_.find_or_insert(key, next);
        if (e == link_edges_.size()) link_edges_.push_back({id[p[0]], id[p[1]], 0});
        if (++link_edges_[e].count > 2) return Vertex_type::NONMANIFOLD; // a triangle in 3+ tetrahedra
      }
    }
    std::size_t boundary_edges = 0;
    for (const Link_edge& e : link_edges_) boundary_edges += (e.count == 1);
    const std::size_t distinct = link_edges_.size();
    const bool euler_boundary = 2 * distinct != 3 * star.size(); // the paper's test
    if (check_links_ && !is_disc_or_sphere(nv, boundary_edges, distinct, star.size()))
      return Vertex_type::NONMANIFOLD;
    return euler_boundary ? Vertex_type::BOUNDARY : Vertex_type::INTERIOR;
  }

private:
  struct Link_edge {
    std::uint32_t a, b, count;
  };

  // An open-addressing map from 64-bit keys to dense ids, cleared in O(1) by a generation stamp.
  struct Small_map {
    std::vector<std::uint64_t> keys;
    std::vector<std::uint32_t> values, stamps;
    std::uint32_t generation = 0;
    std::size_t mask = 0;
    void reset(std::size_t n) {
      std::size_t size = 16;
      while (size < 2 * n) size *= 2;
      if (keys.size() < size) {
        keys.assign(size, 0);
        values.assign(size, 0);
        stamps.assign(size, 0);
        generation = 0;
      }
      mask = size - 1;
      if (++generation == 0) {
        std::fill(stamps.begin(), stamps.end(), 0);
        generation = 1;
      }
    }
    // the id of `key`; a new key gets `next`, which is then incremented
    std::uint32_t& find_or_insert(std::uint64_t key, std::uint32_t& next) {
      std::size_t h = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 32) & mask;
      while (stamps[h] == generation) {
        if (keys[h] == key) return values[h];
        h = (h + 1) & mask;
      }
      stamps[h] = generation;
      keys[h] = key;
      values[h] = next++;
      return values[h];
    }
  };

  // Checks the Euler characteristic of the link, its connectivity, and that its boundary is a
  // single simple loop (each link edge is in at most two link triangles here).
  bool is_disc_or_sphere(std::size_t nv, std::size_t boundary_edges, std::size_t link_edges,
                         std::size_t link_triangles) {
    const long long chi = static_cast<long long>(nv) - static_cast<long long>(link_edges) +
                          static_cast<long long>(link_triangles);
    if (boundary_edges == 0 ? chi != 2 : chi != 1) return false;
    uf_.reset(nv);
    std::size_t components = nv;
    for (const Link_edge& e : link_edges_)
      if (uf_.unite(e.a, e.b)) --components;
    if (components != 1) return false;
    if (boundary_edges == 0) return true;
    boundary_degree_.assign(nv, 0);
    std::size_t boundary_vertices = 0;
    for (const Link_edge& e : link_edges_)
      if (e.count == 1) {
        boundary_vertices += (boundary_degree_[e.a]++ == 0);
        boundary_vertices += (boundary_degree_[e.b]++ == 0);
      }
    for (std::size_t i = 0; i < nv; ++i)
      if (boundary_degree_[i] != 0 && boundary_degree_[i] != 2) return false;
    // All boundary vertices of degree 2: disjoint cycles; a single loop is connected.
    if (boundary_vertices != boundary_edges) return false;
    uf_.reset(nv);
    std::size_t loops = boundary_vertices;
    for (const Link_edge& e : link_edges_)
      if (e.count == 1 && uf_.unite(e.a, e.b)) --loops;
    return loops == 1;
  }

  bool check_links_;
  Small_map vertex_ids_, edge_ids_;
  std::vector<Link_edge> link_edges_;
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
/// and the number of tetrahedra touching the boundary.  With `check_links = false`, vertices are
/// classified by the paper's count alone (see `Vertex_classifier`).
template <class Octree>
Boundary_result<Octree> compute_boundary(const Octree& tree, bool with_triangles = true,
                                         bool check_links = true) {
  using Index = typename Octree::Index;
  Boundary_result<Octree> r;
  if (tree.number_of_vertices() > 0xffffffffu)
    throw std::invalid_argument("compute_boundary: more than 2^32 vertices are not supported");
  r.vertex_type.assign(tree.number_of_vertices(), Vertex_type::UNREFERENCED);
  Vertex_classifier<Octree> classifier(check_links);
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
