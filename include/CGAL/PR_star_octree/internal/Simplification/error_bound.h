// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_ERROR_BOUND_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_ERROR_BOUND_H

// The error bound of the simplification: the input surface (an AABB tree of its triangles), the
// input surface points each vertex stands for, and the test that a collapse keeps both within
// the bound of each other.

#include <CGAL/PR_star_octree/internal/Simplification/collapse_candidate.h>
#include <CGAL/PR_star_octree/internal/Simplification/surface_link.h>
#include <CGAL/PR_star_octree/internal/simplification_constraints.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

template <class GeomTraits>
class Error_bound {
public:
  using Candidate = Collapse_candidate<GeomTraits>;
  using Mesh = Round_mesh<GeomTraits>;
  using Index = typename Mesh::Index;
  using Tetrahedron = typename Mesh::Tetrahedron;
  using K = Exact_predicates_inexact_constructions_kernel; // the error bound's geometry (doubles)
  using Triangle_list = std::vector<K::Triangle_3>;
  using AABB_tree =
      CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Triangle_list::const_iterator>>>;

  // The error bound is checked with samples (the input vertices; seven points per new
  // triangle) against a margin of `error_margin` times the bound, so that what the samples miss,
  // and the points of other vertices whose nearest triangle changes, stay within the bound
  // (measured: `mesh_quality.h`).
  static constexpr double error_margin = 0.5;

  // `input_pos`: the input points (stable ids); `surface`: the input surface triangles; `bound`
  // infinite: no bound.
  void initialize(const std::vector<Vec3>& input_pos, const Surface_constraints<std::size_t>& constraints,
                  double feature_angle, double bound) {
    input_pos_ = &input_pos;
    bound_ = bound;
    covered_.assign(input_pos.size(), {});
    self_covered_.assign(input_pos.size(), 0);
    surface_.clear();
    tree_.clear();
    max_normal_cosine_ =
        feature_angle < 180 ? std::cos(feature_angle / 2 * 3.14159265358979323846 / 180) : -1.;
    if (!bounded()) return;
    auto p = [&](std::size_t v) { return point(input_pos[v]); };
    surface_.reserve(constraints.triangles.size());
    for (const auto& tri : constraints.triangles) surface_.emplace_back(p(tri[0]), p(tri[1]), p(tri[2]));
    tree_.insert(surface_.begin(), surface_.end());
    tree_.accelerate_distance_queries();
  }

  bool bounded() const { return bound_ < std::numeric_limits<double>::infinity(); }

  // A vertex made by a split (stable id `covered_.size()`): it stands for no input point.
  void add_vertex() {
    covered_.emplace_back();
    self_covered_.push_back(1);
  }

  // The point of the input surface nearest to p (p itself without a bound: no surface kept).
  Vec3 closest_point(const Vec3& p) const {
    if (!bounded() || surface_.empty()) return p;
    const K::Point_3 q = tree_.closest_point(point(p));
    return Vec3{{q.x(), q.y(), q.z()}};
  }

  // Vertex v (of the surface or a feature curve) is moved to p: its fan and the fans of its surface
  // neighbours keep the input surface points they stand for within the bound, its new triangles
  // are near the input surface and make no crease, and on a feature curve the input feature points
  // stay near the feature edges at v and at its feature neighbours.
  bool move_ok(Mesh& mesh, Index v, const Vec3& p) {
    const double tol = error_margin * bound_;
    if (!(tol < std::numeric_limits<double>::infinity())) return true;
    const double tol2 = tol * tol;
    if (tree_.squared_distance(point(p)) > tol2) return false;
    auto at = [&](Index x) { return point(x == v ? p : mesh.posd[x]); };
    mesh.gather(mesh.star(v), cells_, labels_);
    surface_link_(cells_, labels_, v, link_);
    triangles_.clear();
    for (const auto& e : link_) triangles_.emplace_back(point(p), at(e.first), at(e.second));
    if (!near_triangles(mesh.sid[v], tol2)) return false;
    for (std::size_t s : covered_[mesh.sid[v]])
      if (!near_triangles(s, tol2)) return false;
    if (!new_triangles_ok(tol2)) return false;
    affected_.clear();
    for (const auto& e : link_)
      for (Index w : {e.first, e.second})
        if (!covered_[mesh.sid[w]].empty()) affected_.push_back(w);
    sort_unique(affected_);
    for (Index w : affected_) {
      mesh.gather(mesh.star(w), cells_, labels_);
      surface_link_(cells_, labels_, w, link_);
      triangles_.clear();
      for (const auto& e : link_) triangles_.emplace_back(at(w), at(e.first), at(e.second));
      for (std::size_t s : covered_[mesh.sid[w]])
        if (!near_triangles(s, tol2)) return false;
    }
    if (mesh.dimension(v) > 1) return true;
    // The curve: the feature edges at v and at its feature neighbours, v at p.
    const double ctol2 = 0.0625 * tol2; // a quarter of the tolerance, as for collapses
    auto near_curve_of = [&](Index x, std::size_t s) {
      if (s >= input_pos_->size() || mesh.constraints->dimension[s] > 1) return true;
      const K::Point_3 q = point((*input_pos_)[s]);
      mesh.neighbors(x, nbr_);
      for (Index w : nbr_)
        if (mesh.is_feature(x, w) && CGAL::squared_distance(q, K::Segment_3(at(x), at(w))) <= ctol2)
          return true;
      return false;
    };
    if (!near_curve_of(v, mesh.sid[v])) return false;
    for (std::size_t s : covered_[mesh.sid[v]])
      if (!near_curve_of(v, s)) return false;
    mesh.neighbors(v, feature_nbr_);
    for (Index w : feature_nbr_) {
      if (!mesh.is_feature(v, w)) continue;
      for (std::size_t s : covered_[mesh.sid[w]])
        if (!near_curve_of(w, s)) return false;
    }
    return true;
  }

  // Vertex v moved: from now on its own input point is one it stands for.
  void moved(const Mesh& mesh, Index v) {
    const std::size_t s = mesh.sid[v];
    if (!bounded() || self_covered_[s] || mesh.dimension(v) > 2) return;
    self_covered_[s] = 1;
    covered_[s].push_back(s);
  }

  // Whether the collapse `c` is to be checked at all: it changes the surface.
  static bool applies(const Mesh& mesh, const Candidate& c) {
    return c.dr <= 2 || (c.move && mesh.dimension(c.k) <= 2);
  }

  // Every input surface point that r and k stand for stays within the bound of the new surface
  // around k, and the new surface triangles stay within the bound of the input surface.
  bool operator()(Mesh& mesh, const Candidate& c) {
    const double tol = error_margin * bound_;
    if (!(tol < std::numeric_limits<double>::infinity())) return true;
    const Index r = c.r, k = c.k;
    surface_link_(c.new_cells, c.new_labels, k, link_);
    const Vec3& pk = c.move ? c.p : mesh.posd[k];
    triangles_.clear();
    for (const auto& e : link_)
      triangles_.emplace_back(point(pk), point(mesh.posd[e.first]), point(mesh.posd[e.second]));
    if (triangles_.empty()) return true; // no surface left around k: nothing to compare
    const double tol2 = tol * tol;
    if (mesh.dimension(r) <= 2 && !near_triangles(mesh.sid[r], tol2)) return false;
    if (c.move && !near_triangles(mesh.sid[k], tol2)) return false;
    for (Index v : {r, k})
      for (std::size_t s : covered_[mesh.sid[v]])
        if (!near_triangles(s, tol2)) return false;
    if (!new_triangles_ok(tol2)) return false;
    if (c.move && tree_.squared_distance(point(c.p)) > tol2) return false;
    if (!neighbours_ok(mesh, c, tol2)) return false;
    return mesh.dimension(r) > 1 || curve_ok(mesh, r, k);
  }

  // After the collapse of r into k: k stands for r's input surface points too.
  void merge(const Mesh& mesh, Index r, Index k) {
    if (mesh.dimension(r) > 2 || !bounded()) return;
    std::vector<std::size_t>& cov = covered_[mesh.sid[k]];
    if (!self_covered_[mesh.sid[r]]) cov.push_back(mesh.sid[r]); // (else it is in r's list)
    cov.insert(cov.end(), covered_[mesh.sid[r]].begin(), covered_[mesh.sid[r]].end());
    std::vector<std::size_t>().swap(covered_[mesh.sid[r]]);
  }

private:
  static K::Point_3 point(const Vec3& p) { return K::Point_3(p[0], p[1], p[2]); }

  // The new triangles around k, at their centroid, edge midpoints and the midpoints between the
  // centroid and the corners, are within the bound of the input surface; and no new crease: each
  // triangle's normal within half the feature angle of the input surface's normal there.
  bool new_triangles_ok(double tol2) const {
    for (const K::Triangle_3& tri : triangles_) {
      const K::Point_3 c = CGAL::centroid(tri);
      const auto closest = tree_.closest_point_and_primitive(c);
      if (CGAL::squared_distance(c, closest.first) > tol2) return false;
      if (max_normal_cosine_ > -1) {
        const K::Vector_3 n1 = CGAL::normal(tri[0], tri[1], tri[2]);
        const K::Vector_3 n2 = CGAL::normal((*closest.second)[0], (*closest.second)[1], (*closest.second)[2]);
        const double l = std::sqrt(n1.squared_length() * n2.squared_length());
        if (!(std::abs(n1 * n2) >= max_normal_cosine_ * l)) return false;
      }
      for (int i = 0; i < 3; ++i)
        if (tree_.squared_distance(CGAL::midpoint(tri[i], tri[(i + 1) % 3])) > tol2 ||
            tree_.squared_distance(CGAL::midpoint(tri[i], c)) > tol2)
          return false;
    }
    return true;
  }

  // The input surface point of stable id `s` is within sqrt(tol2) of one of `triangles_`.
  bool near_triangles(std::size_t s, double tol2) const {
    if (s >= input_pos_->size()) return true; // a vertex made by a split
    const K::Point_3 q = point((*input_pos_)[s]);
    for (const K::Triangle_3& tri : triangles_)
      if (CGAL::squared_distance(q, tri) <= tol2) return true;
    return false;
  }

  // The points of the surface neighbours w of r (and of k when it moves), whose own fans change,
  // stay within the bound of their fans after the collapse.
  bool neighbours_ok(Mesh& mesh, const Candidate& c, double tol2) {
    const Index r = c.r, k = c.k;
    affected_.clear();
    for (Index v : {r, k}) {
      if (v == k && !c.move) continue;
      mesh.gather(mesh.star(v), cells_, labels_);
      surface_link_(cells_, labels_, v, link_);
      for (const auto& e : link_)
        for (Index w : {e.first, e.second})
          if (w != r && w != k && !covered_[mesh.sid[w]].empty()) affected_.push_back(w);
    }
    sort_unique(affected_);
    for (Index w : affected_) {
      // The star of w after the collapse: St(e) gone, r renamed k.
      cells_.clear();
      labels_.clear();
      for (Index t : mesh.star(w)) {
        if (contains(mesh.work[t], r) && contains(mesh.work[t], k)) continue;
        Tetrahedron cell = mesh.work[t];
        for (Index& x : cell)
          if (x == r) x = k;
        cells_.push_back(cell);
        labels_.push_back(mesh.label[t]);
      }
      surface_link_(cells_, labels_, w, link_);
      triangles_.clear();
      auto at = [&](Index x) { return point(x == k && c.move ? c.p : mesh.posd[x]); };
      for (const auto& e : link_) triangles_.emplace_back(at(w), at(e.first), at(e.second));
      for (std::size_t s : covered_[mesh.sid[w]])
        if (!near_triangles(s, tol2)) return false;
    }
    return true;
  }

  // The input feature vertices r and k stand for stay within a quarter of the bound of the
  // feature edges at k after the collapse.
  bool curve_ok(Mesh& mesh, Index r, Index k) {
    const double tol = 0.25 * error_margin * bound_;
    segments_.clear();
    mesh.neighbors(r, nbr_);
    for (Index w : nbr_)
      if (w != k && mesh.is_feature(r, w)) segments_.emplace_back(point(mesh.posd[k]), point(mesh.posd[w]));
    mesh.neighbors(k, nbr_);
    for (Index w : nbr_)
      if (w != r && mesh.is_feature(k, w)) segments_.emplace_back(point(mesh.posd[k]), point(mesh.posd[w]));
    auto near_curve = [&](std::size_t s) {
      if (s >= input_pos_->size() || mesh.constraints->dimension[s] > 1)
        return true; // a surface point: checked above
      const K::Point_3 q = point((*input_pos_)[s]);
      for (const K::Segment_3& e : segments_)
        if (CGAL::squared_distance(q, e) <= tol * tol) return true;
      return false;
    };
    if (!near_curve(mesh.sid[r])) return false;
    for (Index v : {r, k})
      for (std::size_t s : covered_[mesh.sid[v]])
        if (!near_curve(s)) return false;
    return true;
  }

  const std::vector<Vec3>* input_pos_ = nullptr;
  double bound_ = std::numeric_limits<double>::infinity();
  std::vector<std::vector<std::size_t>> covered_; // the input surface points a vertex stands for
  std::vector<char> self_covered_;                // its own input point is in its list (it moved), or none
  Triangle_list surface_;
  AABB_tree tree_;
  double max_normal_cosine_ = -1; // cosine of half the feature angle (-1: no bound)
  Surface_link<Index> surface_link_;
  std::vector<std::pair<Index, Index>> link_;
  Triangle_list triangles_;
  std::vector<K::Segment_3> segments_;
  std::vector<Tetrahedron> cells_;
  std::vector<int> labels_;
  std::vector<Index> affected_, nbr_, feature_nbr_;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_ERROR_BOUND_H
