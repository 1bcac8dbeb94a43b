// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_COMPACTION_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_COMPACTION_H

// The end of a round: the surviving vertices and tetrahedra of the round's mesh, in the octree's
// order (spatially coherent for the next round), with their input indices and stable ids.

#include <CGAL/PR_star_octree/internal/Simplification/round_mesh.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

// The mesh between rounds: points, tetrahedra, the input index of each, the stable id of each point.
template <class GeomTraits>
struct Compact_mesh {
  using Mesh = Round_mesh<GeomTraits>;
  std::vector<typename Mesh::Point_3> points;
  std::vector<typename Mesh::Tetrahedron> tetrahedra;
  std::vector<std::size_t> input_vertex, input_tetrahedron, sid;
};

// `input_tetrahedron[t]`: the input index of tetrahedron t of the round's octree.
template <class GeomTraits>
void compact(Round_mesh<GeomTraits>& mesh, const std::vector<std::size_t>& input_tetrahedron,
             Compact_mesh<GeomTraits>& out) {
  using Index = typename Round_mesh<GeomTraits>::Index;
  const Index none = Round_mesh<GeomTraits>::Octree::no_node;
  std::vector<Index> renumber(mesh.pos.size(), none);
  out.points.clear();
  out.input_vertex.clear();
  out.sid.clear();
  out.points.reserve(mesh.pos.size());
  out.input_vertex.reserve(mesh.pos.size());
  out.sid.reserve(mesh.pos.size());
  for (std::size_t v = 0; v < mesh.pos.size(); ++v) {
    if (mesh.deleted_vertex[v]) continue;
    renumber[v] = static_cast<Index>(out.points.size());
    out.points.push_back(mesh.pos[v]);
    out.input_vertex.push_back(mesh.input_vertex[v]);
    out.sid.push_back(mesh.sid[v]);
  }
  out.tetrahedra.clear();
  out.input_tetrahedron.clear();
  out.tetrahedra.reserve(mesh.work.size());
  out.input_tetrahedron.reserve(mesh.work.size());
  for (std::size_t t = 0; t < mesh.work.size(); ++t) {
    if (mesh.deleted_tet[t]) continue;
    out.input_tetrahedron.push_back(input_tetrahedron[t]);
    auto c = mesh.work[t];
    for (Index& v : c) v = renumber[v];
    out.tetrahedra.push_back(c);
  }
  mesh.work.clear();
  mesh.pos.clear();
}

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_COMPACTION_H
