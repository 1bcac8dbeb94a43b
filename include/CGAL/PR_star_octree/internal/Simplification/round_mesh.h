// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_ROUND_MESH_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_ROUND_MESH_H

// The mesh of one round of the simplification, in the numbering of the round's octree, as the
// collapses change it: positions, tetrahedra (deleted ones flagged), labels, vertex types and
// strata, and the current stars of the vertices (those of the leaf being simplified, and those of
// other leaves on demand).

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/Leaf_topology.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/internal/local_complex.h>
#include <CGAL/PR_star_octree/internal/simplification_constraints.h>
#include <CGAL/PR_star_octree/tetrahedron_quality.h>

#include <algorithm>
#include <cstddef>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

// The coordinates of a point, as doubles.
template <class GeomTraits>
Vec3 to_vec3(const GeomTraits& gt, const typename GeomTraits::Point_3& p) {
  return Vec3{{CGAL::to_double(gt.compute_x_3_object()(p)), CGAL::to_double(gt.compute_y_3_object()(p)),
               CGAL::to_double(gt.compute_z_3_object()(p))}};
}

template <class GeomTraits>
struct Round_mesh {
  using Octree = PR_star_octree_3<GeomTraits>;
  using Index = typename Octree::Index;
  using Point_3 = typename GeomTraits::Point_3;
  using Tetrahedron = typename Octree::Tetrahedron;

  const Octree* tree = nullptr;
  Surface_constraints<std::size_t>* constraints = nullptr; // on stable ids
  std::vector<Vertex_type> types;
  std::vector<Point_3> pos;
  std::vector<Vec3> posd;                // pos as doubles
  std::vector<std::size_t> sid;          // the stable id of each vertex (its index in the first round)
  std::vector<std::size_t> input_vertex; // the input index of each vertex
  std::vector<int> label;                // per tetrahedron (0 without labels)
  std::vector<Tetrahedron> work;         // the tetrahedra, renamed by the collapses
  std::vector<char> deleted_tet, deleted_vertex;
  Index vb = 0, ve = 0; // the vertex range of the leaf being simplified

  bool in_leaf(Index v) const { return v - vb < ve - vb; }
  // The stratum of v: 3 interior, 2 surface, 1 feature curve, 0 corner (and non-manifold).
  int dimension(Index v) const {
    return types[v] == Vertex_type::NONMANIFOLD ? 0 : constraints->dimension[sid[v]];
  }
  bool is_feature(Index a, Index b) const { return constraints->is_feature(sid[a], sid[b]); }

  // The stars of the leaf's vertices: VT of the round's octree without the tetrahedra deleted by
  // earlier leaves, plus those renamed into them by earlier leaves (`extras`).
  void enter_leaf(const Leaf_topology<Octree>& local) {
    vb = local.vertex_begin();
    ve = local.vertex_end();
    const std::size_t nv = ve - vb;
    if (stars_.size() < nv) stars_.resize(nv);
    for (std::size_t i = 0; i < nv; ++i) {
      const Index v = static_cast<Index>(vb + i);
      stars_[i].clear();
      for (Index t : local.vertex_tetrahedra(v))
        if (!deleted_tet[t]) stars_[i].push_back(t);
      auto it = extras_.find(v);
      if (it == extras_.end()) continue;
      for (Index t : it->second) // (kept: a later leaf may need the whole star of v again)
        if (!deleted_tet[t]) stars_[i].push_back(t);
    }
    outside_.clear();
  }

  // The current star of v, in the leaf or not (then from the leaf that holds it, cached; a vertex
  // made in this round has its whole star in `extras_`).
  std::vector<Index>& star(Index v) {
    if (in_leaf(v)) {
      std::vector<Index>& s = stars_[v - vb];
      drop_deleted(s);
      return s;
    }
    auto found = outside_.find(v);
    if (found != outside_.end()) {
      drop_deleted(found->second);
      return found->second;
    }
    std::vector<Index>& s = outside_[v];
    if (std::size_t(v) < tree->number_of_vertices())
      for (Index t : tree->leaf_tetrahedra(tree->leaf_of_vertex(v)))
        if (!deleted_tet[t] && contains(work[t], v)) s.push_back(t);
    auto it = extras_.find(v);
    if (it != extras_.end()) // (a tetrahedron renamed into v may also be in the list of v's leaf)
      for (Index t : it->second)
        if (!deleted_tet[t]) s.push_back(t);
    sort_unique(s);
    return s;
  }

  void neighbors(Index v, std::vector<Index>& out) { star_neighbors(work, star(v), v, out); }

  // Tetrahedron t was renamed into v: remembered for v's star in later leaves.
  void add_to_star(Index v, Index t) { extras_[v].push_back(t); }

  // A new vertex (a split), of stable id `stable` (the constraints know it), standing for the
  // point data of input vertex `input`.
  Index add_vertex(const Point_3& p, const Vec3& pd, std::size_t stable, std::size_t input,
                   Vertex_type type) {
    pos.push_back(p);
    posd.push_back(pd);
    sid.push_back(stable);
    input_vertex.push_back(input);
    types.push_back(type);
    deleted_vertex.push_back(0);
    return static_cast<Index>(pos.size() - 1);
  }

  // A new tetrahedron (a split or a flip), in the stars of its vertices, now and in later leaves.
  Index add_tetrahedron(const Tetrahedron& c, int lab) {
    const Index t = static_cast<Index>(work.size());
    work.push_back(c);
    label.push_back(lab);
    deleted_tet.push_back(0);
    for (Index v : c) {
      extras_[v].push_back(t);
      if (in_leaf(v)) {
        stars_[v - vb].push_back(t);
        continue;
      }
      auto found = outside_.find(v);
      if (found != outside_.end()) found->second.push_back(t);
    }
    return t;
  }

  // The cells and labels of the tetrahedra `st`.
  void gather(const std::vector<Index>& st, std::vector<Tetrahedron>& cells, std::vector<int>& labels) const {
    cells.clear();
    labels.clear();
    for (Index t : st) {
      cells.push_back(work[t]);
      labels.push_back(label[t]);
    }
  }

  // Forgets the round (the octree is about to go).
  void end_round() {
    outside_.clear();
    extras_.clear();
    tree = nullptr;
  }

private:
  void drop_deleted(std::vector<Index>& s) const {
    s.erase(std::remove_if(s.begin(), s.end(), [&](Index t) { return deleted_tet[t] != 0; }), s.end());
  }

  std::vector<std::vector<Index>> stars_;
  std::unordered_map<Index, std::vector<Index>> outside_, extras_;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_ROUND_MESH_H
