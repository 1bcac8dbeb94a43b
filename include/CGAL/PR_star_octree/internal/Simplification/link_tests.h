// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_LINK_TESTS_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_LINK_TESTS_H

// The link conditions of a half-edge collapse: of the volume (boundary coned to a dummy vertex),
// of the surface the simplification keeps, and of its feature curves.

#include <CGAL/PR_star_octree/internal/Simplification/surface_link.h>
#include <CGAL/PR_star_octree/internal/collapse_tester.h>
#include <CGAL/PR_star_octree/internal/local_complex.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

template <class GeomTraits, class Index>
class Link_tests {
public:
  // All three conditions for the collapse of r into k (`dr` the stratum of r).
  template <class Mesh>
  bool operator()(Mesh& mesh, const std::vector<Index>& st_r, const std::vector<Index>& st_k,
                  const std::vector<Index>& st_e, Index r, Index k, int dr) {
    if (!tester_.link_ok(mesh.work, st_k, st_r, st_e, k, r)) return false;
    if (dr <= 2 && !surface_link_ok(mesh, r, k, st_r, st_k)) return false;
    if (dr <= 1 && !curve_link_ok(mesh, r, k)) return false;
    return true;
  }

private:
  // Lk(r) ∩ Lk(k) = Lk(e) in the surface: common link vertices are the third vertices of the
  // surface triangles of e, and no link edge is common.
  template <class Mesh>
  bool surface_link_ok(const Mesh& mesh, Index r, Index k, const std::vector<Index>& st_r,
                       const std::vector<Index>& st_k) {
    mesh.gather(st_r, cells_, labels_);
    surface_link_(cells_, labels_, r, link_r_);
    mesh.gather(st_k, cells_, labels_);
    surface_link_(cells_, labels_, k, link_k_);
    auto vertices = [](const std::vector<std::pair<Index, Index>>& link, std::vector<Index>& out) {
      out.clear();
      for (const auto& e : link) {
        out.push_back(e.first);
        out.push_back(e.second);
      }
      sort_unique(out);
    };
    vertices(link_r_, lv_r_);
    vertices(link_k_, lv_k_);
    std::size_t edge_link = 0; // the surface triangles (r, k, w)
    for (const auto& e : link_r_) edge_link += e.first == k || e.second == k;
    std::sort(link_r_.begin(), link_r_.end());
    std::sort(link_k_.begin(), link_k_.end());
    return intersection_size(lv_r_, lv_k_) == edge_link && intersection_size(link_r_, link_k_) == 0;
  }

  // No feature edge (r, w) and (k, w) for the same w: the feature curves keep their topology.
  template <class Mesh>
  bool curve_link_ok(Mesh& mesh, Index r, Index k) {
    mesh.neighbors(r, nbr_);
    for (Index w : nbr_)
      if (w != k && mesh.is_feature(r, w) && mesh.is_feature(k, w)) return false;
    return true;
  }

  Collapse_tester<GeomTraits, Index> tester_;
  Surface_link<Index> surface_link_;
  std::vector<std::array<Index, 4>> cells_;
  std::vector<int> labels_;
  std::vector<std::pair<Index, Index>> link_r_, link_k_;
  std::vector<Index> lv_r_, lv_k_, nbr_;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_LINK_TESTS_H
