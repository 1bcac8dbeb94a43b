// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_MESH_QUALITY_H
#define CGAL_PR_STAR_OCTREE_MESH_QUALITY_H

/// \file mesh_quality.h
/// Measures of a whole tetrahedral mesh, and of how far a simplified mesh is from its input:
/// the shape of the tetrahedra (`mesh_quality()`), the lengths of the edges against a target
/// length or a sizing field (`edge_length_quality()`), the two-sided sampled Hausdorff distance
/// between the boundary surfaces (`boundary_distance()`) and the distance between their sharp
/// edges (`sharp_edge_distance()`).  They work on plain arrays (points, tetrahedra as
/// `std::array<Index, 4>`), without an octree, so that they can judge any mesher's output, and
/// they compute the boundary and its sharp edges on their own (not with the simplifier's code).
/// Every measure is in double precision.

#include <CGAL/PR_star_octree/tetrahedron_quality.h>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {

/// \ingroup PkgPRStarOctreeRef
/// The largest dihedral angle of the tetrahedron `(p, q, r, s)`, in degrees, in `[0, 180]`
/// (180 for a flat one whose four vertices are not on a line; the orientation does not matter).
/// The companion of `min_dihedral_angle()`, with the same formula.
template <class Point_3>
double max_dihedral_angle(const Point_3& p, const Point_3& q, const Point_3& r, const Point_3& s) {
  using internal::to_vec3;
  const auto angles = internal::dihedral_angles(to_vec3(p), to_vec3(q), to_vec3(r), to_vec3(s));
  return *std::max_element(angles.begin(), angles.end());
}

/// \ingroup PkgPRStarOctreeRef
/// The shape of the tetrahedra of a mesh, as computed by `mesh_quality()`.
struct Mesh_quality {
  /// the number of tetrahedra measured
  std::size_t tetrahedra = 0;
  /// the smallest dihedral angle of any tetrahedron, in degrees (180 for no tetrahedron)
  double min_dihedral_angle = 180;
  /// the largest dihedral angle of any tetrahedron, in degrees (0 for no tetrahedron)
  double max_dihedral_angle = 0;
  /// the smallest radius ratio `3 r / R` of any tetrahedron (1 for no tetrahedron)
  double min_radius_ratio = 1;
  /// the number of tetrahedra whose smallest dihedral angle is below 5 degrees
  std::size_t under_5_degrees = 0;
  /// the number of tetrahedra whose smallest dihedral angle is below 10 degrees
  std::size_t under_10_degrees = 0;

  /// `under_5_degrees / tetrahedra` (0 for no tetrahedron)
  double share_under_5() const { return tetrahedra ? double(under_5_degrees) / double(tetrahedra) : 0.; }
  /// `under_10_degrees / tetrahedra` (0 for no tetrahedron)
  double share_under_10() const { return tetrahedra ? double(under_10_degrees) / double(tetrahedra) : 0.; }
};

/// \ingroup PkgPRStarOctreeRef
/// The smallest and largest dihedral angles, the smallest radius ratio and the number of
/// tetrahedra with a dihedral angle below 5 and 10 degrees, over the tetrahedra `tets` (each
/// a `std::array<Index, 4>` of indices into `points`; the orientation does not matter).
template <class Point_3, class Tetrahedra>
Mesh_quality mesh_quality(const std::vector<Point_3>& points, const Tetrahedra& tets) {
  Mesh_quality q;
  for (const auto& t : tets) {
    const Point_3 &p = points[t[0]], &r = points[t[1]], &s = points[t[2]], &u = points[t[3]];
    const double lo = min_dihedral_angle(p, r, s, u);
    ++q.tetrahedra;
    q.min_dihedral_angle = (std::min)(q.min_dihedral_angle, lo);
    q.max_dihedral_angle = (std::max)(q.max_dihedral_angle, max_dihedral_angle(p, r, s, u));
    q.min_radius_ratio = (std::min)(q.min_radius_ratio, radius_ratio(p, r, s, u));
    if (lo < 5) ++q.under_5_degrees;
    if (lo < 10) ++q.under_10_degrees;
  }
  return q;
}

/// \ingroup PkgPRStarOctreeRef
/// The lengths of the edges of a mesh against a target length, as computed by
/// `edge_length_quality()`: how many edges are within `[low, high]` times their target, shorter,
/// longer, and the median of length / target.
struct Edge_length_quality {
  /// the number of edges (each edge of the tetrahedra once)
  std::size_t edges = 0;
  /// the edges whose length / target is in `[low, high]`
  std::size_t in_range = 0;
  /// the edges whose length / target is below `low`
  std::size_t too_short = 0;
  /// the edges whose length / target is above `high`
  std::size_t too_long = 0;
  /// the median of length / target (the mean of the two middle values for an even number of edges;
  /// NaN for no edge)
  double median_ratio = std::numeric_limits<double>::quiet_NaN();

  /// `in_range / edges` (0 for no edge)
  double share_in_range() const { return edges ? double(in_range) / double(edges) : 0.; }
  /// `too_short / edges` (0 for no edge)
  double share_short() const { return edges ? double(too_short) / double(edges) : 0.; }
  /// `too_long / edges` (0 for no edge)
  double share_long() const { return edges ? double(too_long) / double(edges) : 0.; }
};

namespace internal {
namespace mesh_quality_impl {

// The edges of `tets` as (smaller, larger) vertex pairs packed in 64 bits, sorted, each once.
template <class Tetrahedra>
std::vector<std::uint64_t> sorted_edges(const Tetrahedra& tets) {
  std::vector<std::uint64_t> keys;
  keys.reserve(6 * tets.size());
  for (const auto& t : tets)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const std::uint64_t a = std::uint64_t(t[i]), b = std::uint64_t(t[j]);
        keys.push_back(a < b ? (a << 32) | b : (b << 32) | a);
      }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

template <class Point_3, class Tetrahedra, class Target>
Edge_length_quality edge_length_quality(const std::vector<Point_3>& points, const Tetrahedra& tets,
                                        const Target& target, double low, double high) {
  if (points.size() > (std::uint64_t(1) << 32))
    throw std::length_error("edge_length_quality: more than 2^32 vertices");
  const std::vector<std::uint64_t> edges = sorted_edges(tets);
  Edge_length_quality r;
  std::vector<double> ratios;
  ratios.reserve(edges.size());
  for (const std::uint64_t e : edges) {
    const std::size_t a = std::size_t(e >> 32), b = std::size_t(e & 0xffffffffu);
    const double dx = CGAL::to_double(points[a].x()) - CGAL::to_double(points[b].x());
    const double dy = CGAL::to_double(points[a].y()) - CGAL::to_double(points[b].y());
    const double dz = CGAL::to_double(points[a].z()) - CGAL::to_double(points[b].z());
    const double ratio = std::sqrt(dx * dx + dy * dy + dz * dz) / target(a, b);
    ratios.push_back(ratio);
    if (ratio < low)
      ++r.too_short;
    else if (ratio > high)
      ++r.too_long;
    else
      ++r.in_range;
  }
  r.edges = ratios.size();
  if (!ratios.empty()) {
    const std::size_t m = ratios.size() / 2;
    std::nth_element(ratios.begin(), ratios.begin() + std::ptrdiff_t(m), ratios.end());
    r.median_ratio = ratios[m];
    if (ratios.size() % 2 == 0) // the largest of the lower half, after nth_element
      r.median_ratio =
          (*std::max_element(ratios.begin(), ratios.begin() + std::ptrdiff_t(m)) + ratios[m]) / 2;
  }
  return r;
}

} // namespace mesh_quality_impl
} // namespace internal

/// \ingroup PkgPRStarOctreeRef
/// The lengths of the edges of the tetrahedra `tets` (each a `std::array<Index, 4>` of indices into
/// `points`) against the target length `target`: the edges within `[low, high]` times the target
/// (by default `[0.8, 1.33]`, the range that %CGAL's isotropic remeshing aims at, 4/5 and 4/3), the
/// shorter and longer ones, and the median of length / target.  A length is computed in double
/// precision as `sqrt(dx*dx + dy*dy + dz*dz)`.
template <class Point_3, class Tetrahedra>
Edge_length_quality edge_length_quality(const std::vector<Point_3>& points, const Tetrahedra& tets,
                                        double target, double low = 0.8, double high = 1.33) {
  return internal::mesh_quality_impl::edge_length_quality(
      points, tets, [target](std::size_t, std::size_t) { return target; }, low, high);
}

/// \ingroup PkgPRStarOctreeRef
/// The same against a sizing field: `sizing[v]` is the target length at vertex `v`, and the target
/// of an edge is the mean of its two ends' targets, `(sizing[a] + sizing[b]) / 2`.
template <class Point_3, class Tetrahedra>
Edge_length_quality edge_length_quality(const std::vector<Point_3>& points, const Tetrahedra& tets,
                                        const std::vector<double>& sizing, double low = 0.8,
                                        double high = 1.33) {
  return internal::mesh_quality_impl::edge_length_quality(
      points, tets, [&sizing](std::size_t a, std::size_t b) { return (sizing[a] + sizing[b]) / 2; }, low,
      high);
}

namespace internal {
namespace mesh_quality_impl {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using P3 = Kernel::Point_3;

template <class Point_3>
std::vector<P3> to_epick(const std::vector<Point_3>& points) {
  std::vector<P3> r;
  r.reserve(points.size());
  for (const Point_3& p : points)
    r.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  return r;
}

// The boundary triangles of a tetrahedral mesh: the triangles of exactly one tetrahedron, plus,
// when `labels` is given, the triangles between two tetrahedra of different labels (once).  The
// 4|T| triangles, as sorted vertex triples, are bucketed by their smallest vertex (a counting
// sort), then each bucket is sorted; the triangles come out in lexicographic order.
template <class Tetrahedra, class Label = int>
std::vector<std::array<std::size_t, 3>> boundary_triangles(const Tetrahedra& tets,
                                                           const std::vector<Label>* labels = nullptr) {
  using Index = std::decay_t<decltype(tets[0][0])>;
  struct Face {
    Index v1, v2;
    std::size_t tet;
  };
  std::size_t n = 0;
  for (const auto& t : tets)
    for (int i = 0; i < 4; ++i) n = (std::max)(n, std::size_t(t[i]) + 1);
  std::vector<std::size_t> start(n + 1, 0);
  auto sorted = [&](std::size_t t) {
    std::array<Index, 4> s{{tets[t][0], tets[t][1], tets[t][2], tets[t][3]}};
    std::sort(s.begin(), s.end());
    return s;
  };
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const std::array<Index, 4> s = sorted(t);
    start[std::size_t(s[0]) + 1] += 3; // the three faces through the smallest vertex
    ++start[std::size_t(s[1]) + 1];    // the face opposite to it
  }
  for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<Face> faces(start[n]);
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const std::array<Index, 4> s = sorted(t);
    faces[fill[std::size_t(s[1])]++] = Face{s[2], s[3], t};
    faces[fill[std::size_t(s[0])]++] = Face{s[2], s[3], t};
    faces[fill[std::size_t(s[0])]++] = Face{s[1], s[3], t};
    faces[fill[std::size_t(s[0])]++] = Face{s[1], s[2], t};
  }
  std::vector<std::array<std::size_t, 3>> result;
  for (std::size_t v = 0; v < n; ++v) {
    const auto first = faces.begin() + std::ptrdiff_t(start[v]),
               last = faces.begin() + std::ptrdiff_t(start[v + 1]);
    std::sort(first, last,
              [](const Face& a, const Face& b) { return a.v1 < b.v1 || (a.v1 == b.v1 && a.v2 < b.v2); });
    for (auto i = first; i != last;) {
      auto j = i + 1;
      while (j != last && j->v1 == i->v1 && j->v2 == i->v2) ++j;
      const bool boundary =
          j - i == 1 || (labels && j - i == 2 && (*labels)[i->tet] != (*labels)[(i + 1)->tet]);
      if (boundary) result.push_back({{v, std::size_t(i->v1), std::size_t(i->v2)}});
      i = j;
    }
  }
  return result;
}

// The angle between the two half-planes bounded by the line (a, b) that contain c and d, in
// degrees: 180 where the surface (a, b, c) + (a, b, d) is flat, small where it folds sharply.
inline double wing_angle(const P3& a, const P3& b, const P3& c, const P3& d) {
  return internal::wing_angle(to_vec3(a), to_vec3(b), to_vec3(c), to_vec3(d));
}

// The sharp edges of a boundary surface: edges of exactly two boundary triangles whose surface
// turns by more than `feature_angle` degrees (180 - wing angle > feature_angle), and the edges of
// one or of three or more boundary triangles (borders and junctions of the surface).
inline std::vector<std::array<std::size_t, 2>>
sharp_edges(const std::vector<P3>& points, const std::vector<std::array<std::size_t, 3>>& triangles,
            double feature_angle) {
  struct Edge {
    std::array<std::size_t, 2> v;
    std::size_t opposite;
  };
  std::vector<Edge> edges;
  edges.reserve(3 * triangles.size());
  for (const auto& t : triangles)
    for (int i = 0; i < 3; ++i) {
      std::size_t a = t[i], b = t[(i + 1) % 3];
      if (b < a) std::swap(a, b);
      edges.push_back(Edge{{{a, b}}, t[(i + 2) % 3]});
    }
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) { return a.v < b.v; });
  std::vector<std::array<std::size_t, 2>> result;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j].v == edges[i].v) ++j;
    const auto& v = edges[i].v;
    const bool sharp = j - i != 2 || 180. - wing_angle(points[v[0]], points[v[1]], points[edges[i].opposite],
                                                       points[edges[i + 1].opposite]) >
                                         feature_angle;
    if (sharp) result.push_back(v);
    i = j;
  }
  return result;
}

struct Bbox {
  double lo[3] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                  std::numeric_limits<double>::infinity()};
  double hi[3] = {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                  -std::numeric_limits<double>::infinity()};
  void add(const P3& p) {
    for (int i = 0; i < 3; ++i) {
      lo[i] = (std::min)(lo[i], p[i]);
      hi[i] = (std::max)(hi[i], p[i]);
    }
  }
  double diagonal() const {
    double s = 0;
    for (int i = 0; i < 3; ++i)
      if (hi[i] >= lo[i]) s += (hi[i] - lo[i]) * (hi[i] - lo[i]);
    return std::sqrt(s);
  }
};

// The number of subdivisions of a triangle's edges for the step h.
inline std::size_t subdivisions(const P3& a, const P3& b, const P3& c, double h) {
  const double l = std::sqrt(
      (std::max)({CGAL::squared_distance(a, b), CGAL::squared_distance(b, c), CGAL::squared_distance(c, a)}));
  const double n = std::ceil(l / h);
  return n < 1 ? 1 : n > 1e4 ? 10000 : std::size_t(n);
}

// The samples of a boundary surface beyond its vertices for the step h.
inline std::size_t extra_samples(const std::vector<P3>& pts,
                                 const std::vector<std::array<std::size_t, 3>>& tris, double h) {
  std::size_t n = 0;
  for (const auto& t : tris) {
    const std::size_t k = subdivisions(pts[t[0]], pts[t[1]], pts[t[2]], h);
    n += (k + 1) * (k + 2) / 2 - 3;
  }
  return n;
}

// max over the samples of surface `a` (its vertices, then for each triangle a barycentric grid of
// step h) of the distance to surface `b`.  The vertices are projected first; a grid sample p is
// projected only if it could raise the maximum: d(p, b) <= d(p, T) for any triangle T of b, such
// as the triangles where its triangle's vertices or its previous sample were projected, so p is
// skipped when one of them is within the maximum found so far (the result is the same, computed
// with fewer queries).  The projection on the nearest of them is the hint of the query.
inline double one_sided(const std::vector<P3>& pa, const std::vector<std::array<std::size_t, 3>>& ta,
                        const std::vector<P3>& pb, const std::vector<std::array<std::size_t, 3>>& tb,
                        double h) {
  if (ta.empty()) return 0;
  if (tb.empty()) return std::numeric_limits<double>::infinity();
  using Triangles = std::vector<Kernel::Triangle_3>;
  using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
  Triangles triangles;
  triangles.reserve(tb.size());
  for (const auto& t : tb) triangles.emplace_back(pb[t[0]], pb[t[1]], pb[t[2]]);
  Tree tree(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();
  const auto project = Kernel().construct_projected_point_3_object();
  double worst = 0; // squared
  // The vertices: the triangle of b where each one is projected.
  constexpr std::size_t none = std::size_t(-1);
  std::vector<std::size_t> projected(pa.size(), none);
  for (const auto& t : ta)
    for (std::size_t v : t)
      if (projected[v] == none) {
        const auto c = tree.closest_point_and_primitive(pa[v]);
        projected[v] = std::size_t(c.second - triangles.begin());
        worst = (std::max)(worst, CGAL::squared_distance(pa[v], c.first));
      }
  // The grid samples.
  for (const auto& t : ta) {
    const P3 &a = pa[t[0]], &b = pa[t[1]], &c = pa[t[2]];
    const std::size_t k = subdivisions(a, b, c, h);
    if (k < 2) continue;
    std::size_t known[4] = {projected[t[0]], projected[t[1]], projected[t[2]], none};
    for (std::size_t i = 0; i <= k; ++i)
      for (std::size_t j = 0; i + j <= k; ++j) {
        if ((i == 0 && j == 0) || i == k || j == k) continue; // the three corners
        const double s = double(i) / double(k), r = double(j) / double(k);
        const P3 p(a.x() + s * (b.x() - a.x()) + r * (c.x() - a.x()),
                   a.y() + s * (b.y() - a.y()) + r * (c.y() - a.y()),
                   a.z() + s * (b.z() - a.z()) + r * (c.z() - a.z()));
        std::size_t nearest = none;
        double bound = std::numeric_limits<double>::infinity();
        for (std::size_t q : known)
          if (q != none) {
            const double d = CGAL::squared_distance(p, triangles[q]);
            if (d < bound) {
              bound = d;
              nearest = q;
            }
          }
        if (bound <= worst) continue; // cannot raise the maximum
        const auto cp = tree.closest_point_and_primitive(
            p, {project(triangles[nearest], p), triangles.cbegin() + std::ptrdiff_t(nearest)});
        known[3] = std::size_t(cp.second - triangles.cbegin());
        worst = (std::max)(worst, CGAL::squared_distance(p, cp.first));
      }
  }
  return std::sqrt(worst);
}

// max over the vertices of the segments `sa` of the distance to the segments `sb`.
inline double segments_one_sided(const std::vector<P3>& pa, const std::vector<std::array<std::size_t, 2>>& sa,
                                 const std::vector<P3>& pb,
                                 const std::vector<std::array<std::size_t, 2>>& sb) {
  if (sa.empty()) return 0;
  if (sb.empty()) return std::numeric_limits<double>::infinity();
  using Segments = std::vector<Kernel::Segment_3>;
  using Primitive = CGAL::AABB_segment_primitive<Kernel, Segments::const_iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
  Segments segments;
  segments.reserve(sb.size());
  for (const auto& s : sb) segments.emplace_back(pb[s[0]], pb[s[1]]);
  Tree tree(segments.begin(), segments.end());
  tree.accelerate_distance_queries();
  std::vector<std::size_t> vertices;
  vertices.reserve(2 * sa.size());
  for (const auto& s : sa) vertices.insert(vertices.end(), s.begin(), s.end());
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  double worst = 0;
  for (std::size_t v : vertices) worst = (std::max)(worst, tree.squared_distance(pa[v]));
  return std::sqrt(worst);
}

} // namespace mesh_quality_impl
} // namespace internal

/// \ingroup PkgPRStarOctreeRef
/// The distance between the boundary surfaces of two tetrahedral meshes, as computed by
/// `boundary_distance()`.
struct Boundary_distance {
  /// the largest distance from a sample of the input's boundary to the output's boundary
  double input_to_output = 0;
  /// the largest distance from a sample of the output's boundary to the input's boundary
  double output_to_input = 0;
  /// the length of the diagonal of the bounding box of the input's boundary
  double diagonal = 0;
  /// the sampling step that was used (after the cap on the number of samples)
  double sampling_step = 0;
  /// the number of points sampled on the two surfaces together
  std::size_t samples = 0;

  /// the (sampled) Hausdorff distance: the larger of the two one-sided distances
  double hausdorff() const { return (std::max)(input_to_output, output_to_input); }
  /// `hausdorff() / diagonal` (0 when the diagonal is 0)
  double relative() const { return diagonal > 0 ? hausdorff() / diagonal : 0.; }
};

/// \ingroup PkgPRStarOctreeRef
/// The two-sided Hausdorff distance between the boundary surfaces of two tetrahedral meshes,
/// approximated from below by sampling: every vertex of a surface, and on each of its triangles
/// a barycentric grid whose spacing is at most `sampling_step` along the longest edge, is
/// projected on the other surface (a CGAL `AABB_tree` of its triangles).
///
/// The boundary surface of a mesh is made of the triangles of exactly one tetrahedron; with
/// `input_labels` and `output_labels` (one label per tetrahedron, or `nullptr`), also of the
/// triangles between two tetrahedra of different labels.
///
/// `sampling_step` is absolute; 0 means 0.1% of the diagonal of the input's bounding box.  The
/// step is enlarged until the two surfaces together have at most `max_samples` samples besides
/// their vertices (so that the cost stays near a second per million samples); the step used is
/// reported.  The result is exact on the vertices, and within the step of the truth elsewhere.
/// A surface that is empty when the other is not is at an infinite distance.
template <class Point_3, class TetsA, class TetsB, class Label = int>
Boundary_distance boundary_distance(const std::vector<Point_3>& input_points, const TetsA& input_tets,
                                    const std::vector<Point_3>& output_points, const TetsB& output_tets,
                                    double sampling_step = 0, std::size_t max_samples = 1000000,
                                    const std::vector<Label>* input_labels = nullptr,
                                    const std::vector<Label>* output_labels = nullptr) {
  namespace I = internal::mesh_quality_impl;
  const std::vector<I::P3> pa = I::to_epick(input_points), pb = I::to_epick(output_points);
  const auto ta = I::boundary_triangles(input_tets, input_labels);
  const auto tb = I::boundary_triangles(output_tets, output_labels);
  Boundary_distance d;
  I::Bbox box;
  for (const auto& t : ta)
    for (std::size_t v : t) box.add(pa[v]);
  d.diagonal = box.diagonal();
  double h = sampling_step > 0 ? sampling_step : 1e-3 * d.diagonal;
  if (!(h > 0)) h = 1; // a degenerate input: the vertices only
  std::size_t extra = I::extra_samples(pa, ta, h) + I::extra_samples(pb, tb, h);
  while (extra > max_samples) {
    h *= (std::max)(1.1, 0.9 * std::sqrt(double(extra) / double(max_samples)));
    extra = I::extra_samples(pa, ta, h) + I::extra_samples(pb, tb, h);
  }
  d.sampling_step = h;
  auto count_vertices = [](const std::vector<std::array<std::size_t, 3>>& tris) {
    std::vector<std::size_t> v;
    for (const auto& t : tris) v.insert(v.end(), t.begin(), t.end());
    std::sort(v.begin(), v.end());
    return std::size_t(std::unique(v.begin(), v.end()) - v.begin());
  };
  d.samples = extra + count_vertices(ta) + count_vertices(tb);
  d.input_to_output = I::one_sided(pa, ta, pb, tb, h);
  d.output_to_input = I::one_sided(pb, tb, pa, ta, h);
  return d;
}

/// \ingroup PkgPRStarOctreeRef
/// The distance between the sharp edges of the boundaries of two tetrahedral meshes, as
/// computed by `sharp_edge_distance()`.
struct Sharp_edge_distance {
  /// the largest distance from a vertex of an input sharp edge to the output's sharp edges
  double input_to_output = 0;
  /// the largest distance from a vertex of an output sharp edge to the input's sharp edges
  double output_to_input = 0;
  /// the number of sharp edges of the input's boundary
  std::size_t input_sharp_edges = 0;
  /// the number of sharp edges of the output's boundary
  std::size_t output_sharp_edges = 0;
};

/// \ingroup PkgPRStarOctreeRef
/// The sharp edges of the boundary surface of a tetrahedral mesh (the triangles of exactly one
/// tetrahedron) are its edges where the normals of the two boundary triangles make an angle
/// larger than `feature_angle_degrees` (the surface turns by more than that angle), and its edges
/// of one or of three or more boundary triangles.  Returns the largest distance from a vertex of
/// the output's sharp edges to the input's sharp edges (as segments, with a CGAL `AABB_tree`), and
/// back, with the numbers of sharp edges.  A set of sharp edges that is empty when the other is not
/// is at an infinite distance.
template <class Point_3, class TetsA, class TetsB>
Sharp_edge_distance sharp_edge_distance(const std::vector<Point_3>& input_points, const TetsA& input_tets,
                                        const std::vector<Point_3>& output_points, const TetsB& output_tets,
                                        double feature_angle_degrees = 40) {
  namespace I = internal::mesh_quality_impl;
  const std::vector<I::P3> pa = I::to_epick(input_points), pb = I::to_epick(output_points);
  const auto ea = I::sharp_edges(pa, I::boundary_triangles(input_tets), feature_angle_degrees);
  const auto eb = I::sharp_edges(pb, I::boundary_triangles(output_tets), feature_angle_degrees);
  Sharp_edge_distance d;
  d.input_sharp_edges = ea.size();
  d.output_sharp_edges = eb.size();
  d.input_to_output = I::segments_one_sided(pa, ea, pb, eb);
  d.output_to_input = I::segments_one_sided(pb, eb, pa, ea);
  return d;
}

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_MESH_QUALITY_H
