// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_COLLAPSE_CANDIDATE_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_COLLAPSE_CANDIDATE_H

// One candidate half-edge collapse of r into k (k moved to p, or not), with the tetrahedra it
// creates, and its geometric condition: no new tetrahedron flips or becomes flat (exact
// `Orientation_3` of the traits).

#include <CGAL/PR_star_octree/internal/Simplification/round_mesh.h>
#include <CGAL/PR_star_octree/internal/local_complex.h>
#include <CGAL/enum.h>

#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

template <class GeomTraits>
struct Collapse_candidate {
  using Mesh = Round_mesh<GeomTraits>;
  using Index = typename Mesh::Index;
  using Point_3 = typename Mesh::Point_3;
  using Tetrahedron = typename Mesh::Tetrahedron;

  Index r = 0, k = 0;                 // r is removed into k
  bool move = false;                  // k moves to p
  Vec3 p{{0, 0, 0}};                  // where k ends up
  Point_3 pk;                         // the same, as a point of the traits
  int dr = 3;                         // the stratum of r
  std::vector<Index>* st_r = nullptr; // the stars of r and k (the mesh's)
  std::vector<Index>* st_k = nullptr;
  std::vector<Index> st_e; // the star of the edge
  // The new cells: St(r) - St(e) with r renamed k (the first `renamed`), then St(k) - St(e) when k
  // moves or r is on the surface (for the surface link around k).
  std::vector<Tetrahedron> new_cells;
  std::vector<int> new_labels;
  std::size_t renamed = 0;

  // The new cells of the collapse.
  void make_new_cells(const Mesh& mesh) {
    new_cells.clear();
    new_labels.clear();
    for (Index t : *st_r) {
      if (contains(mesh.work[t], k)) continue;
      Tetrahedron c = mesh.work[t];
      for (Index& w : c)
        if (w == r) w = k;
      new_cells.push_back(c);
      new_labels.push_back(mesh.label[t]);
    }
    renamed = new_cells.size();
    for (Index t : *st_k)
      if (!contains(mesh.work[t], r) && (move || dr <= 2)) {
        new_cells.push_back(mesh.work[t]);
        new_labels.push_back(mesh.label[t]);
      }
  }

  // Geometric condition: the new cells that change are positively oriented.
  bool positive(const GeomTraits& gt, const Mesh& mesh) const {
    auto orientation = gt.orientation_3_object();
    for (std::size_t i = 0; i < new_cells.size(); ++i) {
      if (i >= renamed && !move) continue;
      const Tetrahedron& c = new_cells[i];
      const Point_3* q[4];
      for (int j = 0; j < 4; ++j) q[j] = (c[j] == r || c[j] == k) ? &pk : &mesh.pos[c[j]];
      if (orientation(*q[0], *q[1], *q[2], *q[3]) != CGAL::POSITIVE) return false;
    }
    return true;
  }
};

// The point at parameter t of the segment [a, b].
inline Vec3 lerp(const Vec3& a, const Vec3& b, double t) {
  return Vec3{{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])}};
}

// A point of the traits from its coordinates (when the point type allows it).
template <class Point_3>
Point_3 make_point(const Vec3& p) {
  if constexpr (std::is_constructible<Point_3, double, double, double>::value)
    return Point_3(p[0], p[1], p[2]);
  else
    return Point_3();
}

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_COLLAPSE_CANDIDATE_H
