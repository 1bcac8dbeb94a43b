// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_DISTRIBUTED_ALGORITHMS_H
#define CGAL_PR_STAR_OCTREE_DISTRIBUTED_ALGORITHMS_H

/// \file distributed_algorithms.h
/// The leaf executor over the ranks and the applications on a `Distributed_octree_3`: simplex
/// counts, boundary, curvature and distortion, validity, with the results of one process.
/// Requires MPI.

#include <CGAL/PR_star_octree/Distributed_octree_3.h>
#include <CGAL/PR_star_octree/Leaf_executor.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/distortion.h>
#include <CGAL/PR_star_octree/internal/local_complex.h>
#include <CGAL/PR_star_octree/internal/mpi_communication.h>
#include <CGAL/PR_star_octree/validity.h>

#include <mpi.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {

/// \ingroup PkgPRStarOctreeDistributed
/// The leaf executor of a `Distributed_octree_3`: each rank runs a `Leaf_executor<ConcurrencyTag>`
/// over the leaves of its local octree (its threads, if any), and the ranks' results are combined
/// in rank order.  The leaf function sees an ordinary `Leaf_topology` of the local octree; it
/// decides what its rank counts with `Distributed_octree_3::owns_vertex()` and `counts_simplex()`
/// (a simplex is counted by the owner of its vertex of smallest global id, which has all of its
/// star), so that each simplex of the mesh is counted once over the ranks.
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag>
class Distributed_leaf_executor {
public:
  /// Runs `f(state, local)` on each leaf of this rank, folds the results with `combine(R& into,
  /// R&& next)` in leaf order, then the ranks' results in rank order; every rank returns the same
  /// value (collective).  `R` must be trivially copyable (it travels between ranks as bytes).
  /// \param tree the distributed octree
  /// \param relations the relations each leaf needs (as for `Leaf_executor`)
  /// \param state_prototype copied once per thread
  /// \param f the per-leaf function `R f(State&, const Leaf_topology<Octree>&)`
  /// \param combine folds a result into another
  /// \param progress called as `progress(done, total)` with this rank's leaves
  template <class GT, class State, class Function, class Combine, class Progress = internal::No_progress>
  auto map_reduce(const Distributed_octree_3<GT>& tree, unsigned relations, const State& state_prototype,
                  Function f, Combine combine, Progress progress = Progress()) const {
    using Octree = typename Distributed_octree_3<GT>::Octree;
    using R = std::decay_t<decltype(f(std::declval<State&>(), std::declval<const Leaf_topology<Octree>&>()))>;
    static_assert(std::is_trivially_copyable<R>::value,
                  "the result of a distributed leaf function travels as bytes");
    R local{};
    Leaf_executor<ConcurrencyTag>().map_reduce(
        tree.local_octree(), relations, state_prototype, f, [&](R&& r) { combine(local, std::move(r)); },
        progress);
    const std::vector<R> all = internal::all_gather(tree.communicator(), local);
    R result = all.front();
    for (std::size_t i = 1; i < all.size(); ++i) combine(result, R(all[i]));
    return result;
  }
};

namespace internal {

struct Distributed_counts {
  std::uint64_t vertices = 0, edges = 0, triangles = 0, boundary_triangles = 0, nonmanifold_triangles = 0;
};

inline void add_counts(Distributed_counts& a, Distributed_counts&& b) {
  a.vertices += b.vertices;
  a.edges += b.edges;
  a.triangles += b.triangles;
  a.boundary_triangles += b.boundary_triangles;
  a.nonmanifold_triangles += b.nonmanifold_triangles;
}

// Puts the curvature of the owned vertices into the user's map (the values a rank computes at its
// ghosts are wrong: their stars are partial) and counts their types.
template <class CurvatureMap>
struct Count_and_put {
  using key_type = std::size_t;
  using value_type = Vertex_curvature;
  using reference = void;
  using category = boost::writable_property_map_tag;
  CurvatureMap* map;
  Vertex_type_counts* counts;
  std::size_t owned;
  friend void put(const Count_and_put& m, std::size_t i, const Vertex_curvature& c) {
    if (i >= m.owned) return;
    m.counts->add(c.type);
    put(*m.map, i, c);
  }
};

// The counts of every rank added up (collective).
inline Vertex_type_counts sum_over_ranks(MPI_Comm comm, const Vertex_type_counts& c) {
  std::uint64_t local[4] = {c.interior_vertices, c.boundary_vertices, c.nonmanifold_vertices,
                            c.unreferenced_vertices},
                global[4];
  MPI_Allreduce(local, global, 4, MPI_UINT64_T, MPI_SUM, comm);
  Vertex_type_counts r;
  r.interior_vertices = global[0];
  r.boundary_vertices = global[1];
  r.nonmanifold_vertices = global[2];
  r.unreferenced_vertices = global[3];
  return r;
}

} // namespace internal

/// \ingroup PkgPRStarOctreeDistributed
/// The numbers of vertices, edges, triangles (boundary and non-manifold ones) and tetrahedra of the
/// whole mesh, each simplex counted once, by the rank that owns its vertex of smallest global id
/// (collective; the same counts as `count_simplices()` on one process).
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class GT,
          class NP = parameters::Default_named_parameters>
Simplex_counts count_simplices(const Distributed_octree_3<GT>& tree,
                               const NP& np = parameters::default_values()) {
  using Octree = typename Distributed_octree_3<GT>::Octree;
  using Index = typename Octree::Index;
  const internal::Distributed_counts c = Distributed_leaf_executor<ConcurrencyTag>().map_reduce(
      tree, VERTEX_TETRAHEDRA | EDGES | TRIANGLES, 0,
      [&tree](int, const Leaf_topology<Octree>& local) {
        internal::Distributed_counts r;
        for (Index v = local.vertex_begin(); v < local.vertex_end(); ++v)
          r.vertices += tree.owns_vertex(v) && !local.vertex_tetrahedra(v).empty();
        for (std::size_t e = 0; e < local.number_of_edges(); ++e)
          if (local.owns_edge(e)) {
            const auto& edge = local.edge(e);
            r.edges += tree.counts_simplex(std::array<Index, 2>{{edge.v0, edge.v1}});
          }
        for (std::size_t f = 0; f < local.number_of_triangles(); ++f) {
          if (!local.owns_triangle(f) || !tree.counts_simplex(local.triangle(f))) continue;
          ++r.triangles;
          const std::size_t n = local.triangle_tetrahedra(f).size();
          r.boundary_triangles += n == 1;
          r.nonmanifold_triangles += n > 2;
        }
        return r;
      },
      internal::add_counts, internal::Progress_reporter<NP>(np));
  Simplex_counts s;
  s.vertices = c.vertices;
  s.edges = c.edges;
  s.triangles = c.triangles;
  s.boundary_triangles = c.boundary_triangles;
  s.nonmanifold_triangles = c.nonmanifold_triangles;
  s.tetrahedra = tree.number_of_tetrahedra();
  return s;
}

/// \ingroup PkgPRStarOctreeDistributed
/// The vertex types (interior, boundary, non-manifold, in no tetrahedron) of the vertices this rank
/// owns, into `vertex_type_map` (key: the part index, `0 ... number_of_owned_vertices() - 1`), and
/// the counts of the whole mesh, as `compute_boundary()` on one process (collective).  A vertex is
/// classified by its owner, which has its whole star; the tetrahedra touching the boundary are
/// counted by their owners once the ghost vertices have their owners' types.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{check_links}
///     \cgalParamDescription{as for `compute_boundary()`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress}
///     \cgalParamDescription{called as `F(done, total)` after each leaf of this rank}
///     \cgalParamType{a callable `F(std::size_t, std::size_t)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class GT, class VertexTypeMap,
          class NP = parameters::Default_named_parameters>
Boundary_counts compute_boundary(const Distributed_octree_3<GT>& tree, VertexTypeMap vertex_type_map,
                                 const NP& np = parameters::default_values()) {
  using Octree = typename Distributed_octree_3<GT>::Octree;
  using Index = typename Octree::Index;
  const Octree& octree = tree.local_octree();
  const int ranks = tree.number_of_ranks();
  std::vector<std::uint8_t> types(tree.number_of_local_vertices(), std::uint8_t(Vertex_type::UNREFERENCED));
  struct Face_mark {
    std::uint64_t tetrahedron;
    std::int32_t owner, unused;
  };
  struct Leaf_result {
    std::size_t boundary_triangles = 0;
    std::vector<Face_mark> marks;
  };
  std::size_t boundary_triangles = 0;
  std::vector<std::vector<std::uint64_t>> marks(ranks);
  const Vertex_classifier<Octree> classifier(np);
  Leaf_executor<ConcurrencyTag>().map_reduce(
      octree, classifier.link_relations() | TRIANGLES, 0,
      [&](int, const Leaf_topology<Octree>& local) {
        Leaf_result r;
        for (Index v = local.vertex_begin(); v < local.vertex_end(); ++v)
          types[octree.original_vertex(v)] = std::uint8_t(local.vertex_type(v));
        for (std::size_t f = 0; f < local.number_of_triangles(); ++f) {
          if (!local.owns_triangle(f) || local.triangle_tetrahedra(f).size() != 1 ||
              !tree.counts_simplex(local.triangle(f)))
            continue;
          ++r.boundary_triangles;
          const Index t = *local.triangle_tetrahedra(f).begin();
          r.marks.push_back({tree.global_tetrahedron_id(t), tree.tetrahedron_owner(t), 0});
        }
        return r;
      },
      [&](Leaf_result&& r) {
        boundary_triangles += r.boundary_triangles;
        for (const auto& m : r.marks) marks[m.owner].push_back(m.tetrahedron);
      },
      internal::Progress_reporter<NP>(np));
  tree.update_ghosts(types);
  // The tetrahedra with a boundary face: each marked by the owners of its boundary faces, counted
  // once by its own owner.
  std::vector<std::uint64_t> marked = internal::all_to_all(tree.communicator(), marks);
  std::sort(marked.begin(), marked.end());
  // boundary triangles, tetrahedra touching the boundary, tetrahedra with a boundary face
  std::uint64_t local[3] = {boundary_triangles, 0,
                            std::uint64_t(std::unique(marked.begin(), marked.end()) - marked.begin())};
  Vertex_type_counts owned;
  for (std::size_t i = 0; i < tree.number_of_owned_vertices(); ++i) {
    const Vertex_type t = static_cast<Vertex_type>(types[i]);
    owned.add(t);
    put(vertex_type_map, i, t);
  }
  // (one pass over the tetrahedra: consecutive ones are decoded together when compact)
  const auto tetrahedra = octree.tetrahedra();
  Index t = 0;
  for (auto it = tetrahedra.begin(); it != tetrahedra.end(); ++it, ++t) {
    if (!tree.counts_tetrahedron(t)) continue;
    bool touches = false;
    for (Index v : *it) {
      const auto type = static_cast<Vertex_type>(types[octree.original_vertex(v)]);
      touches = touches || type == Vertex_type::BOUNDARY || type == Vertex_type::NONMANIFOLD;
    }
    local[1] += touches;
  }
  std::uint64_t global[3];
  MPI_Allreduce(local, global, 3, MPI_UINT64_T, MPI_SUM, tree.communicator());
  Boundary_counts r;
  static_cast<Vertex_type_counts&>(r) = internal::sum_over_ranks(tree.communicator(), owned);
  r.boundary_triangles = global[0];
  r.boundary_tetrahedra = global[1];
  r.boundary_face_tetrahedra = global[2];
  return r;
}

/// \ingroup PkgPRStarOctreeDistributed
/// The discrete distortion of `field` and the domain curvature of the vertices this rank owns, into
/// `curvature_map` (key: the part index), bit for bit the values of `compute_curvature()` on one
/// process (each star's angles are added exactly, whatever its order); returns the counts of the
/// vertex types over the whole mesh (collective).
/// \tparam FieldMap a `ReadablePropertyMap` keyed by the part index (ghost vertices included), e.g.
///         `CGAL::make_property_map(tree.point_array(0))`
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class GT, class FieldMap,
          class CurvatureMap, class NP = parameters::Default_named_parameters>
Vertex_type_counts compute_curvature(const Distributed_octree_3<GT>& tree, const FieldMap& field,
                                     CurvatureMap curvature_map,
                                     const NP& np = parameters::default_values()) {
  Vertex_type_counts owned;
  compute_curvature<ConcurrencyTag>(
      tree.local_octree(), field,
      internal::Count_and_put<CurvatureMap>{&curvature_map, &owned, tree.number_of_owned_vertices()}, np);
  return internal::sum_over_ranks(tree.communicator(), owned);
}

/// \ingroup PkgPRStarOctreeDistributed
/// `check_validity()` over the ranks (collective): the same result as on one process.  The
/// orientations are checked by the owners of the tetrahedra; the boundary triangles (their global
/// vertex ids: a surface, much smaller than the mesh) are gathered on rank 0 for the connected
/// components.  Only the counts: the named parameter `problems_output` (the list of the problems) is
/// one-process only, refused here at compile time.
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class GT,
          class NP = parameters::Default_named_parameters>
Validity_result check_validity(const Distributed_octree_3<GT>& tree,
                               const NP& np = parameters::default_values()) {
  static_assert(std::is_same<decltype(parameters::get_parameter(np, internal_np::problems_output)),
                             CGAL::internal_np::Param_not_found>::value,
                "check_validity(Distributed_octree_3): problems_output is one-process only");
  using Octree = typename Distributed_octree_3<GT>::Octree;
  using Index = typename Octree::Index;
  const Octree& octree = tree.local_octree();
  Validity_result r;
  r.tetrahedra = tree.number_of_tetrahedra();
  const Simplex_counts counts = count_simplices<ConcurrencyTag>(tree);
  r.euler_characteristic = counts.euler_characteristic();
  r.nonmanifold_triangles = counts.nonmanifold_triangles;
  r.boundary_triangles = counts.boundary_triangles;

  using Triangle = std::array<std::uint64_t, 3>;
  struct Leaf_result {
    std::size_t positive = 0, negative = 0, degenerate = 0, nonmanifold_vertices = 0,
                unreferenced_vertices = 0;
    std::vector<Triangle> boundary;
  };
  std::uint64_t sums[5] = {0, 0, 0, 0, 0};
  std::vector<Triangle> boundary;
  auto orientation = octree.geom_traits().orientation_3_object();
  const Vertex_classifier<Octree> classifier(np);
  Leaf_executor<ConcurrencyTag>().map_reduce(
      octree, TRIANGLES | classifier.link_relations(), 0,
      [&](int, const Leaf_topology<Octree>& local) {
        Leaf_result lr;
        const auto owned = local.tetrahedra().owned();
        for (Index t = owned.first; t < owned.second; ++t) {
          if (!tree.counts_tetrahedron(t)) continue;
          const auto& c = local.tetrahedron(t); // decoded with the leaf
          const CGAL::Orientation o =
              orientation(octree.point(c[0]), octree.point(c[1]), octree.point(c[2]), octree.point(c[3]));
          if (o == CGAL::COPLANAR)
            ++lr.degenerate;
          else if ((o == CGAL::POSITIVE) != octree.is_reoriented(t))
            ++lr.positive;
          else
            ++lr.negative;
        }
        for (Index v = local.vertex_begin(); v < local.vertex_end(); ++v) {
          if (!tree.owns_vertex(v)) continue;
          lr.nonmanifold_vertices += local.vertex_type(v) == Vertex_type::NONMANIFOLD;
          lr.unreferenced_vertices += local.vertex_type(v) == Vertex_type::UNREFERENCED;
        }
        for (std::size_t f = 0; f < local.number_of_triangles(); ++f)
          if (local.owns_triangle(f) && local.triangle_tetrahedra(f).size() == 1 &&
              tree.counts_simplex(local.triangle(f))) {
            const auto& tri = local.triangle(f);
            Triangle g{{tree.global_id(tri[0]), tree.global_id(tri[1]), tree.global_id(tri[2])}};
            std::sort(g.begin(), g.end());
            lr.boundary.push_back(g);
          }
        return lr;
      },
      [&](Leaf_result&& lr) {
        sums[0] += lr.positive;
        sums[1] += lr.negative;
        sums[2] += lr.degenerate;
        sums[3] += lr.nonmanifold_vertices;
        sums[4] += lr.unreferenced_vertices;
        boundary.insert(boundary.end(), lr.boundary.begin(), lr.boundary.end());
      },
      internal::Progress_reporter<NP>(np));
  std::uint64_t global[5];
  MPI_Allreduce(sums, global, 5, MPI_UINT64_T, MPI_SUM, tree.communicator());
  r.positive = global[0];
  r.negative = global[1];
  r.degenerate = global[2];
  r.nonmanifold_vertices = global[3];
  r.unreferenced_vertices = global[4];
  r.inverted = (std::min)(r.positive, r.negative);

  // Boundary components: union-find on rank 0 over the triangles sharing an edge.
  const std::vector<Triangle> all = internal::gather_vectors(tree.communicator(), boundary);
  std::vector<Triangle>().swap(boundary);
  std::uint64_t components = 0;
  if (tree.rank() == 0) components = internal::count_boundary_components(all);
  MPI_Bcast(&components, 1, MPI_UINT64_T, 0, tree.communicator());
  r.boundary_components = components;
  r.valid =
      r.inverted == 0 && r.degenerate == 0 && r.nonmanifold_triangles == 0 && r.nonmanifold_vertices == 0;
  return r;
}

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_DISTRIBUTED_ALGORITHMS_H
