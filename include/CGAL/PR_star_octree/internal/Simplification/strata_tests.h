// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_STRATA_TESTS_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_STRATA_TESTS_H

// The strata rule of a half-edge collapse: a vertex is removed only into a vertex of its stratum
// or a lower one (interior 3, surface 2, feature curve 1, corner 0), a feature vertex along a
// feature edge, a surface vertex along a surface edge.

#include <CGAL/PR_star_octree/Simplification_statistics.h>
#include <CGAL/PR_star_octree/internal/Simplification/round_mesh.h>
#include <CGAL/PR_star_octree/internal/local_complex.h>

#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

// Can `r` be removed into `k` as far as the strata go (before the tests that need the stars)?
template <class Mesh>
bool removable_into(const Mesh& mesh, typename Mesh::Index r, typename Mesh::Index k) {
  const int dr = mesh.dimension(r);
  return dr > 0 && mesh.dimension(k) <= dr;
}

template <class Index>
class Strata_test {
public:
  // The collapse of r into k along the edge of star `st_e` keeps the strata: NONE, FEATURE or
  // BOUNDARY.
  template <class Mesh>
  Collapse_refusal operator()(const Mesh& mesh, const std::vector<Index>& st_e, Index r, Index k) {
    const int dr = mesh.dimension(r);
    const bool surface_edge = is_surface_edge(mesh, st_e, r, k);
    if (dr == 1 && !mesh.is_feature(r, k)) return Collapse_refusal::FEATURE;
    if (dr == 2 && !surface_edge) return Collapse_refusal::BOUNDARY;
    return Collapse_refusal::NONE;
  }

private:
  // The edge (r, k) is on the surface: a boundary triangle holds it, or two of its tetrahedra
  // have different labels.
  template <class Mesh>
  bool is_surface_edge(const Mesh& mesh, const std::vector<Index>& st_e, Index r, Index k) {
    fan_.make_wings(mesh.work, st_e, r, k);
    if (!fan_.boundary_wings().empty()) return true;
    for (Index t : st_e)
      if (mesh.label[t] != mesh.label[st_e.front()]) return true;
    return false;
  }

  Edge_fan<Index> fan_;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_STRATA_TESTS_H
