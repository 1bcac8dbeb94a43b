// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_CONSTRAINTS_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_CONSTRAINTS_H

// What the simplifier must keep, computed once on the input mesh: its surface (the boundary
// triangles and the triangles between tetrahedra of different labels), the sharp edges of that
// surface (feature curves), the dimension of the stratum of each vertex (3 interior, 2 surface,
// 1 feature curve, 0 corner), and the plane quadrics of the surface.

#include <CGAL/PR_star_octree/internal/local_complex.h>
#include <CGAL/PR_star_octree/tetrahedron_quality.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

// A symmetric plane quadric: sum of w (n.p + d)^2 over planes, stored as the upper triangle of
// the 4x4 matrix, and the sum of the weights (the error is reported as a weighted mean squared
// distance, a length squared).
struct Plane_quadric {
  std::array<double, 10> q{}; // a00 a01 a02 a11 a12 a22 b0 b1 b2 c
  double weight = 0;

  void add_plane(const Vec3& n, double d, double w) {
    q[0] += w * n[0] * n[0];
    q[1] += w * n[0] * n[1];
    q[2] += w * n[0] * n[2];
    q[3] += w * n[1] * n[1];
    q[4] += w * n[1] * n[2];
    q[5] += w * n[2] * n[2];
    q[6] += w * n[0] * d;
    q[7] += w * n[1] * d;
    q[8] += w * n[2] * d;
    q[9] += w * d * d;
    weight += w;
  }
  Plane_quadric& operator+=(const Plane_quadric& o) {
    for (int i = 0; i < 10; ++i) q[i] += o.q[i];
    weight += o.weight;
    return *this;
  }
  // The (unnormalised) sum of weighted squared distances at p.
  double raw(const Vec3& p) const {
    const double x = p[0], y = p[1], z = p[2];
    return q[0] * x * x + 2 * q[1] * x * y + 2 * q[2] * x * z + q[3] * y * y + 2 * q[4] * y * z +
           q[5] * z * z + 2 * (q[6] * x + q[7] * y + q[8] * z) + q[9];
  }
  double error(const Vec3& p) const { return weight > 0 ? (std::max)(0., raw(p) / weight) : 0.; }
  // The point of the segment [a, b] where the error is smallest, as a parameter in [0, 1]
  // (0.5 when the error is constant along it, e.g. no plane).
  double best_on_segment(const Vec3& a, const Vec3& b) const {
    // e(t) = raw(a + t (b - a)) is quadratic: e(t) = e(0) + t (e(1) - e(-1)) / 2 + t^2 (e(1) + e(-1) - 2
    // e(0)) / 2
    const Vec3 m{{2 * a[0] - b[0], 2 * a[1] - b[1], 2 * a[2] - b[2]}};
    const double e0 = raw(a), e1 = raw(b), em = raw(m);
    const double curvature = (e1 + em - 2 * e0) / 2, slope = (e1 - em) / 2;
    const double scale = std::abs(e0) + std::abs(e1) + std::abs(em);
    if (!(curvature > 1e-12 * scale)) return 0.5;
    return (std::min)(1., (std::max)(0., -slope / (2 * curvature)));
  }
};

// The surface, its features and the stratum of every vertex of a mesh (`tets` positively
// oriented, `labels` one per tetrahedron or empty).
template <class Index>
struct Surface_constraints {
  std::vector<unsigned char> dimension;        // per vertex: 3 interior, 2 surface, 1 feature curve, 0 corner
  std::unordered_set<std::uint64_t> features;  // feature edges, keys of `edge_key()`
  std::vector<std::array<Index, 3>> triangles; // the surface triangles
  std::vector<Plane_quadric> quadrics;         // per vertex (empty unless asked)
  std::uint64_t n = 0;                         // a bound on the vertex ids (for the keys)

  std::uint64_t edge_key(std::uint64_t a, std::uint64_t b) const { return a < b ? a * n + b : b * n + a; }
  bool is_feature(std::uint64_t a, std::uint64_t b) const { return features.count(edge_key(a, b)) != 0; }
};

// `feature_angle` in degrees: a surface edge is sharp when its two surface triangles deviate
// from flat by more than it.  `constrained_vertex(v)` and `constrained_edge(a, b)` add the
// user's constraints (corners and feature edges).
template <class Tetrahedra, class Index, class ConstrainedVertex, class ConstrainedEdge>
void compute_surface_constraints(const std::vector<Vec3>& points, const Tetrahedra& tets,
                                 const std::vector<int>& labels, double feature_angle, bool with_quadrics,
                                 ConstrainedVertex constrained_vertex, ConstrainedEdge constrained_edge,
                                 Surface_constraints<Index>& out) {
  const std::size_t nv = points.size();
  out.n = std::uint64_t(1) << 32; // (not nv: remeshing adds vertices)
  out.dimension.assign(nv, 3);
  out.features.clear();
  out.triangles.clear();
  std::vector<unsigned char> corner(nv, 0);

  // Faces: sorted vertex triple, the tetrahedron, and the face's index in it.
  struct Face {
    std::array<Index, 3> v;
    Index t;
    int k;
  };
  std::vector<Face> faces;
  faces.reserve(4 * tets.size());
  std::size_t t = 0;
  for (auto it = tets.begin(); it != tets.end(); ++it, ++t) { // (iterators decode in one pass)
    const auto c = *it;
    for (int k = 0; k < 4; ++k) {
      Face f;
      for (int i = 0; i < 3; ++i) f.v[i] = c[link_face[k][i]];
      std::sort(f.v.begin(), f.v.end());
      f.t = static_cast<Index>(t);
      f.k = k;
      faces.push_back(f);
    }
  }
  std::sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) { return a.v < b.v; });
  // Patches: the surface triangles with a key, the pair of labels on its sides (-1: outside).
  std::vector<std::pair<int, int>> patch;
  auto label = [&](Index t) { return labels.empty() ? 0 : labels[t]; };
  for_each_group(
      faces.begin(), faces.end(), [](const Face& a, const Face& b) { return a.v == b.v; },
      [&](auto first, auto last) {
        const auto count = last - first;
        if (count > 2) { // a non-manifold triangle: its vertices stay
          for (Index v : first->v) corner[v] = 1;
          return;
        }
        const int la = label(first->t), lb = count == 2 ? label((first + 1)->t) : -1;
        if (count == 2 && la == lb) return;
        // oriented as seen from the first tetrahedron (outward normal)
        const auto& c = tets[first->t];
        out.triangles.push_back(std::array<Index, 3>{
            {c[link_face[first->k][0]], c[link_face[first->k][2]], c[link_face[first->k][1]]}});
        patch.emplace_back((std::min)(la, lb), (std::max)(la, lb));
      });
  std::vector<Face>().swap(faces);

  // Surface edges: each with its triangles.
  struct Edge_record {
    Index a, b, tri;
  };
  std::vector<Edge_record> edges;
  edges.reserve(3 * out.triangles.size());
  for (std::size_t i = 0; i < out.triangles.size(); ++i)
    for (int j = 0; j < 3; ++j) {
      Index a = out.triangles[i][j], b = out.triangles[i][(j + 1) % 3];
      if (b < a) std::swap(a, b);
      edges.push_back(Edge_record{a, b, static_cast<Index>(i)});
    }
  std::sort(edges.begin(), edges.end(), [](const Edge_record& x, const Edge_record& y) {
    return std::tie(x.a, x.b, x.tri) < std::tie(y.a, y.b, y.tri);
  });
  auto third = [&](Index tri, Index a, Index b) {
    for (Index w : out.triangles[tri])
      if (w != a && w != b) return w;
    return a;
  };
  auto add_feature = [&](Index a, Index b) { out.features.insert(out.edge_key(a, b)); };
  for_each_group(
      edges.begin(), edges.end(),
      [](const Edge_record& x, const Edge_record& y) { return x.a == y.a && x.b == y.b; },
      [&](auto first, auto last) {
        const Index a = first->a, b = first->b;
        if (constrained_edge(a, b) || last - first != 2 || patch[first->tri] != patch[(first + 1)->tri]) {
          add_feature(a, b);
          return;
        }
        if (!(feature_angle < 180)) return; // no sharp edges
        // The angle between the half-planes (a, b, c) and (a, b, d): 180 degrees on a flat surface.
        const double angle = wing_angle(points[a], points[b], points[third(first->tri, a, b)],
                                        points[third((first + 1)->tri, a, b)]);
        if (180 - angle > feature_angle) add_feature(a, b);
      });

  // Strata.
  std::vector<unsigned> feature_degree(nv, 0);
  for (const auto& tri : out.triangles)
    for (Index v : tri) out.dimension[v] = 2;
  for (std::uint64_t key : out.features) {
    ++feature_degree[key / out.n];
    ++feature_degree[key % out.n];
  }
  for (std::size_t v = 0; v < nv; ++v) {
    if (out.dimension[v] == 2 && feature_degree[v] > 0) out.dimension[v] = feature_degree[v] == 2 ? 1 : 0;
    if (corner[v] || constrained_vertex(static_cast<Index>(v))) out.dimension[v] = 0;
  }

  // Plane quadrics of the surface triangles, weighted by their area.
  out.quadrics.clear();
  if (!with_quadrics) return;
  out.quadrics.assign(nv, Plane_quadric());
  for (const auto& tri : out.triangles) {
    const Vec3 n = cross(minus(points[tri[1]], points[tri[0]]), minus(points[tri[2]], points[tri[0]]));
    const double twice_area = norm(n);
    if (!(twice_area > 0)) continue;
    const Vec3 unit{{n[0] / twice_area, n[1] / twice_area, n[2] / twice_area}};
    const double d = -dot(unit, points[tri[0]]);
    for (Index v : tri) out.quadrics[v].add_plane(unit, d, twice_area / 2);
  }
}

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_CONSTRAINTS_H
