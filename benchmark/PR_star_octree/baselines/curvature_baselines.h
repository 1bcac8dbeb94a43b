// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Boundary vertices and discrete distortion computed on the global baselines (the extended IA data
// structure and CGAL's Triangulation_3), with the same solid-angle formulas as the PR-star octree,
// so that the structures are compared, not the arithmetic.

#ifndef PRSTAR_BASELINES_CURVATURE_BASELINES_H
#define PRSTAR_BASELINES_CURVATURE_BASELINES_H

#include <CGAL/PR_star_octree/distortion.h>

#include "Cgal_triangulation_baseline.h"
#include "Extended_IA.h"

#include <array>
#include <cstdint>
#include <vector>

namespace prstar_baselines {

using CGAL::PR_star_octree::Vertex_curvature;
using CGAL::PR_star_octree::Vertex_type;

// The curvature of vertex v from its star (input numbering) and its boundary flag.
template <class Points, class Tets, class Field, class Star>
Vertex_curvature curvature_from_star(const Points& points, const Tets& tets, const Field& field,
                                     std::uint32_t v, const Star& star, bool boundary) {
  double s3 = 0, s4 = 0;
  for (std::uint32_t t : star) {
    const auto& c = tets[t];
    std::array<std::array<double, 3>, 4> p;
    std::array<double, 4> f;
    int k = 0;
    for (int i = 0; i < 4; ++i) {
      const auto& q = points[c[i]];
      p[i] = {{q.x(), q.y(), q.z()}};
      f[i] = field(c[i]);
      if (c[i] == v) k = i;
    }
    const auto a = CGAL::PR_star_octree::internal::corner_solid_angles(p, f, k);
    s3 += a.first;
    s4 += a.second;
  }
  if (star.empty()) return {};
  return CGAL::PR_star_octree::internal::finish_curvature(
      s3, s4, boundary ? Vertex_type::BOUNDARY : Vertex_type::INTERIOR);
}

/// Boundary flags from the extended IA: a vertex is on the boundary when a face of its star
/// incident in it has no neighbour.
template <class Index>
std::vector<char> ia_boundary(const Extended_IA<Index>& ia) {
  std::vector<char> b(ia.number_of_vertices(), 0);
  std::vector<Index> star, stack;
  for (Index v = 0; v < ia.number_of_vertices(); ++v) b[v] = ia.is_boundary_vertex(v, star, stack);
  return b;
}

/// Distortion of every vertex on the extended IA (input numbering).
template <class Points, class Index, class Field>
std::vector<Vertex_curvature> ia_curvature(const Points& points,
                                           const std::vector<std::array<Index, 4>>& tets,
                                           const Extended_IA<Index>& ia, const Field& field) {
  std::vector<Vertex_curvature> out(points.size());
  std::vector<Index> star, stack;
  for (Index v = 0; v < points.size(); ++v) {
    ia.vertex_tetrahedra(v, star, stack);
    bool boundary = false;
    for (Index t : star)
      for (int k = 0; k < 4; ++k)
        if (tets[t][k] != v && ia.neighbor(t, k) == Extended_IA<Index>::no_neighbor) boundary = true;
    out[v] = curvature_from_star(points, tets, field, v, star, boundary);
  }
  return out;
}

/// Distortion of every vertex on CGAL's triangulation (input numbering).
template <class Points, class Tets, class Field>
std::vector<Vertex_curvature> cgal_curvature(const Points& points, const Tets& tets,
                                             const Cgal_triangulation_baseline& cgal, const Field& field) {
  std::vector<Vertex_curvature> out(points.size());
  cgal.for_each_vertex_star([&](std::uint32_t v, const std::vector<std::uint32_t>& star) {
    out[v] = curvature_from_star(points, tets, field, v, star, cgal.is_boundary_vertex(v));
  });
  return out;
}

} // namespace prstar_baselines

#endif // PRSTAR_BASELINES_CURVATURE_BASELINES_H
