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

#include <CGAL/PR_star_octree/Leaf_executor.h>
#include <CGAL/PR_star_octree/Leaf_topology.h>
#include <CGAL/PR_star_octree/internal/local_complex.h>
#include <CGAL/PR_star_octree/parameters.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace PR_star_octree {

/// \ingroup PkgPRStarOctreeRef
/// How many vertices of each `Vertex_type` a classification found.
struct Vertex_type_counts {
  std::size_t interior_vertices = 0;
  std::size_t boundary_vertices = 0;
  std::size_t nonmanifold_vertices = 0;
  std::size_t unreferenced_vertices = 0;
  /// counts one more vertex of type `t`
  void add(Vertex_type t) {
    interior_vertices += t == Vertex_type::INTERIOR;
    boundary_vertices += t == Vertex_type::BOUNDARY;
    nonmanifold_vertices += t == Vertex_type::NONMANIFOLD;
    unreferenced_vertices += t == Vertex_type::UNREFERENCED;
  }
};

/// \ingroup PkgPRStarOctreeRef
/// What `compute_boundary()` found besides the vertex types.
struct Boundary_counts : Vertex_type_counts {
  std::size_t boundary_triangles =
      0; ///< triangles with one tetrahedron (0 without `with_boundary_triangles`)
  std::size_t boundary_tetrahedra = 0; ///< tetrahedra with at least one boundary (or non-manifold) vertex
  std::size_t boundary_face_tetrahedra = 0; ///< tetrahedra with a face on the boundary (0 without triangles)
};

/// \ingroup PkgPRStarOctreeRef
///
/// Classifies the vertices of one leaf from its vertex-tetrahedra relation only.
///
/// For a vertex `v` with star `St(v)`, the triangles of its link are the faces opposite `v` (one per
/// tetrahedron, `|t| = |St(v)|`), and the edges of its link are the triangles incident in `v`
/// (`|e|`).  In a manifold mesh `v` is interior exactly when every link edge bounds two link
/// triangles, i.e. `2|e| = 3|t|` (paper Section 7); this is the `O(1)`-per-vertex test once the local
/// structure is built.  By default the link is also checked to be a sphere or a disc (connected,
/// every link edge in at most two link triangles, the link boundary a single simple loop, Euler
/// characteristic 2 or 1): otherwise the vertex is reported `NONMANIFOLD` instead of being
/// silently misclassified.  With the named parameter `check_links(false)`, only the paper's test is
/// made (and a triangle in three or more tetrahedra is still reported): faster, but it trusts the
/// mesh to be manifold at the vertex.
template <class Octree>
class Vertex_classifier {
public:
  using Index = typename Octree::Index;

  /// \param np an optional sequence of named parameters among the ones listed below
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{check_links}
  ///     \cgalParamDescription{whether each link is checked to be a sphere or a disc (`false`: the paper's
  ///     Euler count only; see `Vertex_classifier`)} \cgalParamType{`bool`} \cgalParamDefault{`true`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  template <class NP = parameters::Default_named_parameters>
  explicit Vertex_classifier(const NP& np = parameters::default_values())
      : check_links_(
            parameters::choose_parameter(parameters::get_parameter(np, internal_np::check_links), true)) {}

  /// classifies vertex `v` (octree numbering) of the leaf of `local` (VT must have been built)
  Vertex_type classify(const Leaf_topology<Octree>& local, Index v) {
    return classify(local.tetrahedron_map(), local.vertex_tetrahedra(v), v);
  }

  /// classifies vertex `v` from its star `star` (indices into the tetrahedron array `T`)
  template <class Tetrahedra, class Star>
  Vertex_type classify(const Tetrahedra& T, const Star& star, Index v) {
    if (star.begin() == star.end()) return Vertex_type::UNREFERENCED;
    if (!link_.build(T, star, v, check_links_, /* stop at a triangle in 3+ tetrahedra */ true))
      return Vertex_type::NONMANIFOLD;
    if (check_links_ && !link_.is_sphere_or_disc()) return Vertex_type::NONMANIFOLD;
    return link_.euler_count_says_boundary() ? Vertex_type::BOUNDARY : Vertex_type::INTERIOR;
  }

  /// classifies every vertex of the leaf of `local` at once: calls `f(v, type)` for each vertex `v`
  /// of the leaf, in increasing order, with the type that `classify(local, v)` would return.  When
  /// `local` holds the relation `VERTEX_LINKS` built with the same link check as this classifier
  /// (`UNCHECKED_LINKS` exactly when `check_links(false)`), its link types are used as they are;
  /// otherwise the links of the whole leaf are gathered here, in one pass over its tetrahedra (no
  /// relation needs to have been built).
  template <class Function>
  void classify_leaf(const Leaf_topology<Octree>& local, Function f) {
    const Index vb = local.vertex_begin(), ve = local.vertex_end();
    if ((local.relations() & VERTEX_LINKS) && ((local.relations() & UNCHECKED_LINKS) == 0) == check_links_) {
      for (Index v = vb; v < ve; ++v) f(v, local.vertex_type(v));
      return;
    }
    own_.build(local.octree(), local.leaf(), VERTEX_LINKS | (check_links_ ? 0u : UNCHECKED_LINKS));
    for (Index v = vb; v < ve; ++v) f(v, own_.vertex_type(v));
  }

  /// the relation flags that give `Leaf_topology::vertex_type()` the answers of this classifier
  unsigned link_relations() const { return VERTEX_LINKS | (check_links_ ? 0u : UNCHECKED_LINKS); }

private:
  bool check_links_;
  internal::Vertex_link<Index> link_;
  Leaf_topology<Octree> own_;
};

namespace internal {

// The boundary pass, in the octree's numbering: `types[v]` for every vertex, and, with
// `with_triangles`, `on_triangle(t, k)` for every boundary triangle (the face opposite vertex `k`
// of tetrahedron `t`), each reported once, by the leaf owning its smallest vertex, in leaf order.
template <class ConcurrencyTag, class Octree, class TriangleVisitor, class NP>
void classify_vertices(const Octree& tree, bool with_triangles, std::vector<Vertex_type>& types,
                       TriangleVisitor on_triangle, const NP& np) {
  using Index = typename Octree::Index;
  types.assign(tree.number_of_vertices(), Vertex_type::UNREFERENCED);
  const Vertex_classifier<Octree> classifier(np);
  const unsigned relations = classifier.link_relations() | (with_triangles ? TRIANGLES : 0u);
  // Each leaf writes the types of its own vertices and returns its boundary triangles.
  Leaf_executor<ConcurrencyTag>().map_reduce(
      tree, relations, 0,
      [&](int, const Leaf_topology<Octree>& local) {
        for (Index v = local.vertex_begin(); v < local.vertex_end(); ++v) types[v] = local.vertex_type(v);
        std::vector<std::pair<Index, int>> triangles;
        if (!with_triangles) return triangles;
        for (std::size_t f = 0; f < local.number_of_triangles(); ++f) {
          if (!local.owns_triangle(f) || local.triangle_tetrahedra(f).size() != 1) continue;
          const Index t = *local.triangle_tetrahedra(f).begin();
          const auto& c = local.tetrahedron(t);
          const auto& tri = local.triangle(f);
          int k = 0;
          while (c[k] == tri[0] || c[k] == tri[1] || c[k] == tri[2]) ++k;
          triangles.emplace_back(t, k);
        }
        return triangles;
      },
      [&](std::vector<std::pair<Index, int>>&& triangles) {
        for (const auto& x : triangles) on_triangle(x.first, x.second);
      },
      Progress_reporter<NP>(np));
}

} // namespace internal

/// \ingroup PkgPRStarOctreeRef
///
/// Computes the boundary of the mesh of `tree` by streaming over its leaves: writes the
/// `Vertex_type` of every vertex into `vertex_type_map`, keyed by the user's vertex numbering (the
/// input order), and counts the boundary triangles and the tetrahedra touching the boundary.
///
/// \param tree the octree of the mesh
/// \param vertex_type_map receives the type of each vertex
/// \tparam VertexTypeMap a model of `WritablePropertyMap` with key `std::size_t` (the user's vertex
///         index) and value `Vertex_type`, e.g. `CGAL::make_property_map(std::vector<Vertex_type>&)`
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{check_links}
///     \cgalParamDescription{whether each link is checked to be a sphere or a disc (`false`: the paper's
///     Euler count only; see `Vertex_classifier`)} \cgalParamType{`bool`} \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{with_boundary_triangles}
///     \cgalParamDescription{whether the boundary triangles are also found (and counted)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true` (always `true` with `boundary_triangles_output`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{boundary_triangles_output}
///     \cgalParamDescription{receives each boundary triangle once, in leaf order, as a
///     `std::array<std::size_t, 3>` of user vertex indices oriented outward (its normal by the right-hand
///     rule points out of the mesh)} \cgalParamType{an output iterator} \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress}
///     \cgalParamDescription{called as `F(done, total)` after each leaf, `done` never decreasing}
///     \cgalParamType{a callable `F(std::size_t, std::size_t)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \tparam ConcurrencyTag `CGAL::Parallel_tag` (leaves processed by several threads with TBB),
///         `CGAL::Sequential_tag`, or the default `CGAL::Parallel_if_available_tag`; the results are the
///         same, in the same order
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class GT, class I, class VertexTypeMap,
          class NP = parameters::Default_named_parameters>
Boundary_counts compute_boundary(const PR_star_octree_3<GT, I>& tree, VertexTypeMap vertex_type_map,
                                 const NP& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Boundary_counts r;
  auto triangles_out = get_parameter(np, internal_np::boundary_triangles_output);
  constexpr bool has_output =
      !std::is_same<decltype(triangles_out), CGAL::internal_np::Param_not_found>::value;
  const bool with_triangles =
      has_output || choose_parameter(get_parameter(np, internal_np::with_boundary_triangles), true);

  std::vector<Vertex_type> types;
  std::vector<char> has_face(with_triangles ? tree.number_of_tetrahedra() : 0, 0);
  internal::classify_vertices<ConcurrencyTag>(
      tree, with_triangles, types,
      [&](I t, int k) {
        ++r.boundary_triangles;
        has_face[t] = 1;
        if constexpr (has_output) {
          const auto& c = tree.tetrahedron(t);
          const auto& f = internal::link_face[k];
          *triangles_out++ = std::array<std::size_t, 3>{
              {tree.original_vertex(c[f[0]]), tree.original_vertex(c[f[1]]), tree.original_vertex(c[f[2]])}};
        }
      },
      np);
  for (std::size_t v = 0; v < types.size(); ++v) {
    r.add(types[v]);
    put(vertex_type_map, static_cast<std::size_t>(tree.original_vertex(static_cast<I>(v))), types[v]);
  }
  for (const auto& c : tree.tetrahedra()) {
    bool touches = false;
    for (I v : c)
      touches = touches || types[v] == Vertex_type::BOUNDARY || types[v] == Vertex_type::NONMANIFOLD;
    r.boundary_tetrahedra += touches;
  }
  for (char x : has_face) r.boundary_face_tetrahedra += (x != 0);
  return r;
}

/// \ingroup PkgPRStarOctreeRef
/// A triangle of the surface of a labelled mesh, as `boundary_surface()` reports it: a boundary
/// triangle (a face of one tetrahedron) or an interface triangle (the common face of two
/// tetrahedra with different labels).
struct Surface_triangle {
  /// the user's vertex indices, oriented so that the normal (right-hand rule) points out of the
  /// tetrahedron labelled `inside`: out of the mesh for a boundary triangle, towards the larger
  /// label for an interface
  std::array<std::size_t, 3> vertices;
  int inside;     ///< the label of the tetrahedron of a boundary triangle; the smaller label of an interface
  int outside;    ///< the larger label of an interface; `inside` for a boundary triangle
  bool interface; ///< between two labels (`true`) or on the boundary (`false`)
};

/// \ingroup PkgPRStarOctreeRef
///
/// Writes the surface of the mesh of `tree` to `out`, leaf by leaf: every boundary triangle (in one
/// tetrahedron) and, with labels (`PR_star_octree_3::has_tetrahedron_labels()`), every triangle
/// between two tetrahedra of different labels, each once, as a `Surface_triangle` in the user's
/// vertex numbering.  The triangles come in leaf order, the same for every `ConcurrencyTag`.  A
/// triangle in three or more tetrahedra (non-manifold) is not reported.
///
/// \param tree the octree of the mesh
/// \param out an output iterator accepting `Surface_triangle`
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{progress}
///     \cgalParamDescription{called as `F(done, total)` after each leaf, `done` never decreasing}
///     \cgalParamType{a callable `F(std::size_t, std::size_t)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the output iterator past the last triangle
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class GT, class I, class OutputIterator,
          class NP = parameters::Default_named_parameters>
OutputIterator boundary_surface(const PR_star_octree_3<GT, I>& tree, OutputIterator out,
                                const NP& np = parameters::default_values()) {
  using Octree = PR_star_octree_3<GT, I>;
  const bool labelled = tree.has_tetrahedron_labels();
  // the face of tetrahedron t opposite its k-th vertex, oriented out of t
  auto face = [&](I t, const std::array<I, 3>& tri, int inside, int outside, bool interface) {
    const auto& c = tree.tetrahedron(t);
    int k = 0;
    while (c[k] == tri[0] || c[k] == tri[1] || c[k] == tri[2]) ++k;
    const auto& f = internal::link_face[k];
    return Surface_triangle{
        {{tree.original_vertex(c[f[0]]), tree.original_vertex(c[f[1]]), tree.original_vertex(c[f[2]])}},
        inside,
        outside,
        interface};
  };
  Leaf_executor<ConcurrencyTag>().map_reduce(
      tree, TRIANGLES, 0,
      [&](int, const Leaf_topology<Octree>& local) {
        std::vector<Surface_triangle> triangles;
        for (std::size_t f = 0; f < local.number_of_triangles(); ++f) {
          if (!local.owns_triangle(f)) continue;
          const auto& around = local.triangle_tetrahedra(f);
          const std::size_t n = around.size();
          if (n == 1) {
            const I t = *around.begin();
            const int l = tree.tetrahedron_label(t);
            triangles.push_back(face(t, local.triangle(f), l, l, false));
          } else if (n == 2 && labelled) {
            auto it = around.begin();
            I a = *it++, b = *it;
            int la = tree.tetrahedron_label(a), lb = tree.tetrahedron_label(b);
            if (la == lb) continue;
            if (lb < la) {
              std::swap(a, b);
              std::swap(la, lb);
            }
            triangles.push_back(face(a, local.triangle(f), la, lb, true));
          }
        }
        return triangles;
      },
      [&](std::vector<Surface_triangle>&& triangles) {
        for (const Surface_triangle& x : triangles) *out++ = x;
      },
      internal::Progress_reporter<NP>(np));
  return out;
}

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_BOUNDARY_H
