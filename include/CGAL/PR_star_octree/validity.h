// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_VALIDITY_H
#define CGAL_PR_STAR_OCTREE_VALIDITY_H

/// \file validity.h
/// A validity checker for tetrahedral meshes, computed leaf by leaf on a PR-star octree:
/// orientation of every tetrahedron (exact predicate), flat tetrahedra, non-manifold triangles and
/// vertices, Euler characteristic and number of boundary components.

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
#include <tuple>
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
/// (`PR_star_octree_3::is_reoriented()`), so the user's sign is recovered exactly.
struct Validity_result {
  bool valid = true;                     ///< no inverted, flat or non-manifold element
  std::size_t tetrahedra = 0;            ///< number of tetrahedra checked
  std::size_t positive = 0;              ///< tetrahedra positively oriented as listed by the user
  std::size_t negative = 0;              ///< tetrahedra negatively oriented as listed by the user
  std::size_t inverted = 0;              ///< `min(positive, negative)`: see the orientation rule
  std::size_t degenerate = 0;            ///< flat tetrahedra (four coplanar vertices)
  std::size_t nonmanifold_triangles = 0; ///< triangles incident in three or more tetrahedra
  std::size_t nonmanifold_vertices = 0;  ///< vertices whose link is neither a sphere nor a disc
  long long euler_characteristic = 0;    ///< V - E + F - T over the referenced vertices
  std::size_t boundary_triangles = 0;    ///< triangles incident in one tetrahedron
  /// connected components of the boundary surface, two boundary triangles being connected when
  /// they share an edge (so two spheres touching at a vertex count twice)
  std::size_t boundary_components = 0;
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

} // namespace internal

/// \ingroup PkgPRStarOctreeRef
/// Checks the mesh of `tree` leaf by leaf (see `Validity_result`).  Memory beyond the octree: the
/// local structure of the largest leaf and the boundary triangles.
/// \param tree the octree of the mesh
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
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
    std::size_t positive = 0, negative = 0, degenerate = 0, nonmanifold_vertices = 0;
    std::vector<std::array<Index, 3>> boundary;
  };
  std::vector<std::array<Index, 3>> boundary;
  boundary.reserve(counts.boundary_triangles);
  auto orientation = tree.geom_traits().orientation_3_object();
  const Vertex_classifier<Octree> classifier;
  Leaf_executor<ConcurrencyTag>().map_reduce(
      tree, TRIANGLES | classifier.link_relations(), 0,
      [&](int, const Leaf_topology<Octree>& local) {
        Leaf_result lr;
        const auto owned = local.tetrahedra().owned();
        for (Index t = owned.first; t < owned.second; ++t) {
          const auto& c = tree.tetrahedron(t);
          const CGAL::Orientation o =
              orientation(tree.point(c[0]), tree.point(c[1]), tree.point(c[2]), tree.point(c[3]));
          if (o == CGAL::COPLANAR)
            ++lr.degenerate;
          else if ((o == CGAL::POSITIVE) != tree.is_reoriented(t)) // the user's sign
            ++lr.positive;
          else
            ++lr.negative;
        }
        for (Index v = local.vertex_begin(); v < local.vertex_end(); ++v)
          lr.nonmanifold_vertices += local.vertex_type(v) == Vertex_type::NONMANIFOLD;
        for (std::size_t f = 0; f < local.number_of_triangles(); ++f)
          if (local.owns_triangle(f) && local.triangle_tetrahedra(f).size() == 1)
            lr.boundary.push_back(local.triangle(f));
        return lr;
      },
      [&](Leaf_result&& lr) {
        r.positive += lr.positive;
        r.negative += lr.negative;
        r.degenerate += lr.degenerate;
        r.nonmanifold_vertices += lr.nonmanifold_vertices;
        boundary.insert(boundary.end(), lr.boundary.begin(), lr.boundary.end());
      },
      [&](std::size_t done, std::size_t) { report(leaves + done, 2 * leaves); });
  r.inverted = (std::min)(r.positive, r.negative);

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
