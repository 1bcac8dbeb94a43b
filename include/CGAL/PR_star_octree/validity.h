// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_VALIDITY_H
#define CGAL_PR_STAR_OCTREE_VALIDITY_H

/// \file validity.h
/// A validity checker for tetrahedral meshes, computed leaf by leaf on a PR-star octree:
/// orientation of every tetrahedron (exact predicate), flat tetrahedra, non-manifold triangles and
/// vertices, Euler characteristic and number of boundary components; on request, the list of the
/// elements that are wrong, in the user's numbering.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/Index_arrays_input.h>
#include <CGAL/PR_star_octree/Leaf_executor.h>
#include <CGAL/PR_star_octree/Leaf_topology.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/internal/local_complex.h>
#include <CGAL/PR_star_octree/parameters.h>

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

/// \ingroup PkgPRStarOctreeRef
/// The result of `check_validity()`.
///
/// **Orientation rule.**  A mesh is consistently oriented when all its non-flat tetrahedra, *as the
/// user listed them*, have the same sign (all positive or all negative: both conventions exist).
/// `inverted` is the size of the minority: `min(#positive, #negative)` over the non-flat
/// tetrahedra, decided with the exact `Orientation_3` of the traits.  The PR-star octree stores
/// every tetrahedron positively oriented and remembers which ones it swapped
/// (`PR_star_octree_3::is_reoriented()`), so the user's sign is recovered exactly.  The tetrahedra
/// reported as inverted (named parameter `problems_output`) are those of the minority sign; when
/// both signs count as many tetrahedra, the negatively oriented ones are reported (the octree's own
/// convention is positive).
///
/// **Unreferenced vertices** (in no tetrahedron) are counted and reported as a warning: they do not
/// make the mesh invalid (they are no defect of the tetrahedral complex, only of the vertex list).
struct Validity_result {
  bool valid = true;                     ///< no inverted, flat or non-manifold element
  std::size_t tetrahedra = 0;            ///< number of tetrahedra checked
  std::size_t positive = 0;              ///< tetrahedra positively oriented as listed by the user
  std::size_t negative = 0;              ///< tetrahedra negatively oriented as listed by the user
  std::size_t inverted = 0;              ///< `min(positive, negative)`: see the orientation rule
  std::size_t degenerate = 0;            ///< flat tetrahedra (four coplanar vertices)
  std::size_t nonmanifold_triangles = 0; ///< triangles incident in three or more tetrahedra
  std::size_t nonmanifold_vertices = 0;  ///< vertices whose link is neither a sphere nor a disc
  /// vertices in no tetrahedron: a warning, which does not make the mesh invalid
  std::size_t unreferenced_vertices = 0;
  long long euler_characteristic = 0; ///< V - E + F - T over the referenced vertices
  std::size_t boundary_triangles = 0; ///< triangles incident in one tetrahedron
  /// connected components of the boundary surface, two boundary triangles being connected when
  /// they share an edge (so two spheres touching at a vertex count twice)
  std::size_t boundary_components = 0;
};

/// \ingroup PkgPRStarOctreeRef
/// The kinds of `Validity_problem`, in the order in which `check_validity()` reports them.
enum class Validity_problem_kind : unsigned char {
  INVERTED_TETRAHEDRON = 0, ///< a tetrahedron of the minority sign (see `Validity_result`)
  FLAT_TETRAHEDRON = 1,     ///< a tetrahedron whose four vertices are coplanar
  NONMANIFOLD_TRIANGLE = 2, ///< a triangle incident in three or more tetrahedra
  NONMANIFOLD_VERTEX = 3,   ///< a vertex whose link is neither a sphere nor a disc
  UNREFERENCED_VERTEX = 4   ///< a vertex in no tetrahedron (a warning: the mesh stays valid)
};

/// \ingroup PkgPRStarOctreeRef
/// One element that `check_validity()` found wrong (named parameter `problems_output`), in the
/// user's numbering: vertices by their input index (`PR_star_octree_3::original_vertex()`),
/// tetrahedra by theirs (`PR_star_octree_3::original_tetrahedron()`; the octree's index when it
/// keeps no tetrahedron permutation, see `PR_star_octree_3::has_tetrahedron_permutation()`).
///
/// - `INVERTED_TETRAHEDRON`, `FLAT_TETRAHEDRON`: `tetrahedron` and its four `vertices` as the user
///   listed them;
/// - `NONMANIFOLD_TRIANGLE`: its three `vertices`, increasing (`vertices[3]` is `no_id`), and the
///   (three or more) `tetrahedra` incident in it, increasing;
/// - `NONMANIFOLD_VERTEX`, `UNREFERENCED_VERTEX`: the vertex in `vertices[0]` (the others are
///   `no_id`).
///
/// Problems compare by kind, then tetrahedron, then vertices: the order in which they are reported.
struct Validity_problem {
  /// no element (an unused field)
  static constexpr std::size_t no_id = (std::numeric_limits<std::size_t>::max)();
  Validity_problem_kind kind = Validity_problem_kind::INVERTED_TETRAHEDRON; ///< what is wrong
  std::size_t tetrahedron = no_id;                                          ///< the tetrahedron, or `no_id`
  std::array<std::size_t, 4> vertices{{no_id, no_id, no_id, no_id}};        ///< the vertices (see above)
  std::vector<std::size_t> tetrahedra; ///< a non-manifold triangle's tetrahedra (empty otherwise)

  /// the number of meaningful entries of `vertices`: 4, 3 or 1
  std::size_t number_of_vertices() const {
    return kind <= Validity_problem_kind::FLAT_TETRAHEDRON       ? 4
           : kind == Validity_problem_kind::NONMANIFOLD_TRIANGLE ? 3
                                                                 : 1;
  }
  /// the order of the reports: kind, tetrahedron, vertices, tetrahedra
  friend bool operator<(const Validity_problem& a, const Validity_problem& b) {
    return std::tie(a.kind, a.tetrahedron, a.vertices, a.tetrahedra) <
           std::tie(b.kind, b.tetrahedron, b.vertices, b.tetrahedra);
  }
  /// equal in every field
  friend bool operator==(const Validity_problem& a, const Validity_problem& b) {
    return std::tie(a.kind, a.tetrahedron, a.vertices, a.tetrahedra) ==
           std::tie(b.kind, b.tetrahedron, b.vertices, b.tetrahedra);
  }
};

namespace internal {

// The connected components of a set of triangles (sorted vertex ids of any integer type) joined
// through their shared edges: union-find on the triangles, grouped by edge.
template <class Id>
std::size_t count_boundary_components(const std::vector<std::array<Id, 3>>& triangles) {
  struct Edge_record {
    Id a, b;
    std::uint32_t triangle;
    bool operator<(const Edge_record& o) const {
      return std::tie(a, b, triangle) < std::tie(o.a, o.b, o.triangle);
    }
  };
  std::vector<Edge_record> edges;
  edges.reserve(3 * triangles.size());
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const auto& t = triangles[f]; // sorted vertices
    const std::uint32_t id = static_cast<std::uint32_t>(f);
    edges.push_back(Edge_record{t[0], t[1], id});
    edges.push_back(Edge_record{t[1], t[2], id});
    edges.push_back(Edge_record{t[0], t[2], id});
  }
  std::sort(edges.begin(), edges.end());
  Union_find uf;
  uf.reset(triangles.size());
  std::size_t components = triangles.size();
  for_each_group(
      edges.begin(), edges.end(),
      [](const Edge_record& x, const Edge_record& y) { return x.a == y.a && x.b == y.b; },
      [&](auto first, auto last) {
        for (auto e = first + 1; e < last; ++e)
          if (uf.unite(e->triangle, first->triangle)) --components;
      });
  return components;
}

// A tetrahedron of the octree as a problem in the user's numbering.
template <class Octree>
Validity_problem tetrahedron_problem(const Octree& tree, typename Octree::Index t,
                                     Validity_problem_kind kind) {
  Validity_problem p;
  p.kind = kind;
  p.tetrahedron =
      tree.has_tetrahedron_permutation() ? std::size_t(tree.original_tetrahedron(t)) : std::size_t(t);
  const auto c = tree.original_tetrahedron_vertices(t);
  for (int k = 0; k < 4; ++k) p.vertices[k] = c[k];
  return p;
}

// A vertex of the octree as a problem in the user's numbering.
template <class Octree>
Validity_problem vertex_problem(const Octree& tree, typename Octree::Index v, Validity_problem_kind kind) {
  Validity_problem p;
  p.kind = kind;
  p.vertices[0] = tree.original_vertex(v);
  return p;
}

// A triangle (octree vertices) and its tetrahedra as a problem in the user's numbering.
template <class Octree, class Tetrahedra>
Validity_problem triangle_problem(const Octree& tree, const std::array<typename Octree::Index, 3>& triangle,
                                  const Tetrahedra& tetrahedra) {
  Validity_problem p;
  p.kind = Validity_problem_kind::NONMANIFOLD_TRIANGLE;
  for (int k = 0; k < 3; ++k) p.vertices[k] = tree.original_vertex(triangle[k]);
  std::sort(p.vertices.begin(), p.vertices.begin() + 3);
  for (auto t : tetrahedra)
    p.tetrahedra.push_back(tree.has_tetrahedron_permutation() ? std::size_t(tree.original_tetrahedron(t))
                                                              : std::size_t(t));
  std::sort(p.tetrahedra.begin(), p.tetrahedra.end());
  return p;
}

} // namespace internal

/// \ingroup PkgPRStarOctreeRef
/// Checks the mesh of `tree` leaf by leaf (see `Validity_result`) and, on request, says which
/// elements are wrong (`Validity_problem`).  Memory beyond the octree: the local structure of the
/// largest leaf and the boundary triangles, plus the problems when `problems_output` is given.
/// \param tree the octree of the mesh
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{problems_output}
///     \cgalParamDescription{receives every problem found, as a `Validity_problem` in the user's
///     numbering, sorted (by kind, then tetrahedron or vertices): the inverted tetrahedra (the minority
///     sign, see `Validity_result`), the flat ones, the non-manifold triangles, the non-manifold and the
///     unreferenced vertices; the same list whatever the `ConcurrencyTag`, the number of threads or
///     `k_v`} \cgalParamType{an output iterator with value type `Validity_problem`}
///     \cgalParamDefault{none (nothing is collected)}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress}
///     \cgalParamDescription{called as `F(done, total)` after each leaf of each of the two passes (`total` is
///     twice the number of leaves)} \cgalParamType{a callable `F(std::size_t, std::size_t)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \tparam ConcurrencyTag `CGAL::Parallel_tag`, `CGAL::Sequential_tag` or the default
///         `CGAL::Parallel_if_available_tag` (the same result either way)
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class GT, class I,
          class NP = parameters::Default_named_parameters>
Validity_result check_validity(const PR_star_octree_3<GT, I>& tree,
                               const NP& np = parameters::default_values()) {
  using Octree = PR_star_octree_3<GT, I>;
  using Index = I;
  using Kind = Validity_problem_kind;
  auto problems_out = parameters::get_parameter(np, internal_np::problems_output);
  constexpr bool has_output =
      !std::is_same<decltype(problems_out), CGAL::internal_np::Param_not_found>::value;
  Validity_result r;
  r.tetrahedra = tree.number_of_tetrahedra();
  const internal::Progress_reporter<NP> report(np);
  const std::size_t leaves = tree.number_of_leaves();

  // Euler characteristic and non-manifold triangles: simplices counted by their owning leaf.
  const Simplex_counts counts = count_simplices<ConcurrencyTag>(
      tree, parameters::progress([&](std::size_t done, std::size_t) { report(done, 2 * leaves); }));
  r.euler_characteristic = counts.euler_characteristic();
  r.nonmanifold_triangles = counts.nonmanifold_triangles;
  r.boundary_triangles = counts.boundary_triangles;

  // Orientation of the owned tetrahedra, vertex links, boundary triangles: per leaf, gathered in
  // leaf order.
  struct Leaf_result {
    std::size_t positive = 0, negative = 0, degenerate = 0, nonmanifold_vertices = 0,
                unreferenced_vertices = 0;
    std::vector<std::array<Index, 3>> boundary;
    std::vector<Validity_problem> problems; // only with `problems_output`
  };
  std::vector<std::array<Index, 3>> boundary;
  std::vector<Validity_problem> problems;
  boundary.reserve(counts.boundary_triangles);
  auto orientation = tree.geom_traits().orientation_3_object();
  const Vertex_classifier<Octree> classifier;
  Leaf_executor<ConcurrencyTag>().map_reduce(
      tree, TRIANGLES | classifier.link_relations(), 0,
      [&](int, const Leaf_topology<Octree>& local) {
        Leaf_result lr;
        const auto owned = local.tetrahedra().owned();
        for (Index t = owned.first; t < owned.second; ++t) {
          const auto& c = local.tetrahedron(t);
          const CGAL::Orientation o =
              orientation(tree.point(c[0]), tree.point(c[1]), tree.point(c[2]), tree.point(c[3]));
          if (o == CGAL::COPLANAR) {
            ++lr.degenerate;
            if constexpr (has_output)
              lr.problems.push_back(internal::tetrahedron_problem(tree, t, Kind::FLAT_TETRAHEDRON));
          } else if ((o == CGAL::POSITIVE) != tree.is_reoriented(t)) // the user's sign
            ++lr.positive;
          else
            ++lr.negative;
        }
        for (Index v = local.vertex_begin(); v < local.vertex_end(); ++v) {
          const Vertex_type type = local.vertex_type(v);
          lr.nonmanifold_vertices += type == Vertex_type::NONMANIFOLD;
          lr.unreferenced_vertices += type == Vertex_type::UNREFERENCED;
          if constexpr (has_output) {
            if (type == Vertex_type::NONMANIFOLD)
              lr.problems.push_back(internal::vertex_problem(tree, v, Kind::NONMANIFOLD_VERTEX));
            else if (type == Vertex_type::UNREFERENCED)
              lr.problems.push_back(internal::vertex_problem(tree, v, Kind::UNREFERENCED_VERTEX));
          }
        }
        for (std::size_t f = 0; f < local.number_of_triangles(); ++f) {
          if (!local.owns_triangle(f)) continue;
          const std::size_t n = local.triangle_tetrahedra(f).size();
          if (n == 1) lr.boundary.push_back(local.triangle(f));
          if constexpr (has_output)
            if (n > 2)
              lr.problems.push_back(
                  internal::triangle_problem(tree, local.triangle(f), local.triangle_tetrahedra(f)));
        }
        return lr;
      },
      [&](Leaf_result&& lr) {
        r.positive += lr.positive;
        r.negative += lr.negative;
        r.degenerate += lr.degenerate;
        r.nonmanifold_vertices += lr.nonmanifold_vertices;
        r.unreferenced_vertices += lr.unreferenced_vertices;
        boundary.insert(boundary.end(), lr.boundary.begin(), lr.boundary.end());
        if constexpr (has_output)
          problems.insert(problems.end(), std::make_move_iterator(lr.problems.begin()),
                          std::make_move_iterator(lr.problems.end()));
      },
      [&](std::size_t done, std::size_t) { report(leaves + done, 2 * leaves); });
  r.inverted = (std::min)(r.positive, r.negative);

  if constexpr (has_output) {
    // The inverted tetrahedra: every non-flat tetrahedron of the octree is positive, so the user's
    // sign is negative exactly when it was swapped.  The minority, the negative ones on a tie.
    if (r.inverted > 0) {
      const bool negative_minority = r.negative <= r.positive;
      for (std::size_t i = 0; i < tree.number_of_tetrahedra(); ++i) {
        const Index t = static_cast<Index>(i);
        if (tree.is_reoriented(t) != negative_minority) continue;
        if (!negative_minority) { // positive as listed, unless flat
          const auto& c = tree.tetrahedron(t);
          if (orientation(tree.point(c[0]), tree.point(c[1]), tree.point(c[2]), tree.point(c[3])) ==
              CGAL::COPLANAR)
            continue;
        }
        problems.push_back(internal::tetrahedron_problem(tree, t, Kind::INVERTED_TETRAHEDRON));
      }
    }
    std::sort(problems.begin(), problems.end());
    for (Validity_problem& p : problems) *problems_out++ = std::move(p);
  }

  r.boundary_components = internal::count_boundary_components(boundary);

  r.valid =
      r.inverted == 0 && r.degenerate == 0 && r.nonmanifold_triangles == 0 && r.nonmanifold_vertices == 0;
  return r;
}

/// \ingroup PkgPRStarOctreeRef
/// Checks a mesh given as index arrays (see `make_input()`): builds its PR-star octree and calls
/// `check_validity(const PR_star_octree_3&, const NP&)`.
/// \param points the vertices
/// \param tetrahedra four vertex indices per tetrahedron
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{bucket_size}
///     \cgalParamDescription{the bucket threshold k_v of the octree}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{50}
///   \cgalParamNEnd
///   \cgalParamNBegin{problems_output}
///     \cgalParamDescription{as in `check_validity(const PR_star_octree_3&, const NP&)` (the vertices and
///     tetrahedra numbered as in `points` and `tetrahedra`)}
///     \cgalParamType{an output iterator with value type `Validity_problem`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress}
///     \cgalParamDescription{as in `check_validity(const PR_star_octree_3&, const NP&)`}
///     \cgalParamType{a callable `F(std::size_t, std::size_t)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws std::invalid_argument as the `PR_star_octree_3` constructor (index out of range,
/// a vertex twice in a tetrahedron, non-finite coordinate)
template <class PointRange, class TetrahedronRange, class NP = parameters::Default_named_parameters>
Validity_result check_validity(const PointRange& points, const TetrahedronRange& tetrahedra,
                               const NP& np = parameters::default_values()) {
  const PR_star_octree_3<> tree(
      make_input(points, tetrahedra),
      parameters::bucket_size(parameters::choose_parameter(
          parameters::get_parameter(np, internal_np::bucket_size), PR_star_octree_3<>::default_bucket_size)));
  return check_validity(tree, np);
}

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_VALIDITY_H
