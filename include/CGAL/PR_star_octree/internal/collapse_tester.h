// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_COLLAPSE_TESTER_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_COLLAPSE_TESTER_H

// The three conditions of a half-edge collapse (boundary, exact orientation, link), on explicit
// stars of a mesh being simplified, built on the local-complex kernel.

#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/internal/local_complex.h>
#include <CGAL/enum.h>

#include <array>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

// Tetrahedra are given by index into `tets`, which holds them positively oriented.
template <class GeomTraits, class Index>
class Collapse_tester {
public:
  using Point_3 = typename GeomTraits::Point_3;
  using Tetrahedron = std::array<Index, 4>;
  static constexpr Index omega = (std::numeric_limits<Index>::max)(); // the cone vertex of the boundary

  // St(e): the tetrahedra of `st2` containing v1.
  template <class Tets>
  static void edge_star(const Tets& tets, const std::vector<Index>& st2, Index v1, std::vector<Index>& out) {
    out.clear();
    for (Index t : st2)
      if (contains(tets[t], v1)) out.push_back(t);
  }

  // Boundary condition.  Both ends interior, or both on the boundary and `e` on the boundary (its
  // star is an open fan: some triangle (v1, v2, w) has one tetrahedron).  Non-manifold ends never.
  template <class Tets>
  bool boundary_ok(const Tets& tets, const std::vector<Index>& st_e, Index v1, Index v2, Vertex_type t1,
                   Vertex_type t2) {
    if (t1 != t2) return false;
    if (t1 == Vertex_type::INTERIOR) return true;
    if (t1 != Vertex_type::BOUNDARY) return false;
    fan_.make_wings(tets, st_e, v1, v2);
    return !fan_.boundary_wings().empty();
  }

  // Geometric condition, with the exact orientation predicate of the traits.
  // `points`: a random-access range of `Point_3` (a vector, or the octree's `points()`).
  template <class Points, class Tets>
  bool geometry_ok(const GeomTraits& gt, const Points& points, const Tets& tets,
                   const std::vector<Index>& st2, Index v1, Index v2) const {
    auto orientation = gt.orientation_3_object();
    for (Index t : st2) {
      const auto& c = tets[t];
      if (contains(c, v1)) continue; // in St(e): deleted
      const auto at = [&](int k) -> decltype(auto) { return points[c[k] == v2 ? v1 : c[k]]; };
      if (orientation(at(0), at(1), at(2), at(3)) != CGAL::POSITIVE) return false;
    }
    return true;
  }

  // Link condition Lk(v1) ∩ Lk(v2) = Lk(e) on vertices, edges and triangles, the boundary being
  // coned to the dummy vertex `omega` (Dey, Edelsbrunner, Guha, Nekhayev), so that it also
  // preserves the boundary surface.  Lk(e) is always in the intersection: comparing sizes is enough.
  template <class Tets>
  bool link_ok(const Tets& tets, const std::vector<Index>& st1, const std::vector<Index>& st2,
               const std::vector<Index>& st_e, Index v1, Index v2) {
    coned_link(tets, st1, v1, lv1_, le1_, lt1_);
    coned_link(tets, st2, v2, lv2_, le2_, lt2_);
    // Lk(e): the edges opposite e, and (w, omega) for the boundary triangles (v1, v2, w).
    fan_.make_wings(tets, st_e, v1, v2);
    ev_.clear();
    ee_.clear();
    for (const auto& w : fan_.wings()) {
      ev_.push_back(w.from);
      ev_.push_back(w.to);
      ee_.push_back(sorted(w.from, w.to));
    }
    const std::vector<Index>& single = fan_.boundary_wings();
    if (!single.empty()) ev_.push_back(omega);
    for (Index w : single) ee_.push_back(sorted(w, omega));
    sort_unique(ev_);
    sort_unique(ee_);
    return intersection_size(lv1_, lv2_) == ev_.size() && intersection_size(le1_, le2_) == ee_.size() &&
           intersection_size(lt1_, lt2_) == 0;
  }

private:
  using Edge = std::pair<Index, Index>;
  using Triangle = std::array<Index, 3>;

  static Edge sorted(Index a, Index b) { return a < b ? Edge(a, b) : Edge(b, a); }

  // The link of v (from the kernel) in the complex whose boundary is coned to omega: sorted
  // vertex, edge and triangle sets.
  template <class Tets>
  void coned_link(const Tets& tets, const std::vector<Index>& st, Index v, std::vector<Index>& lv,
                  std::vector<Edge>& le, std::vector<Triangle>& lt) {
    link_.build(tets, st, v, /* with vertices */ true, /* stop at non-manifold */ false);
    lv.assign(link_.vertices().begin(), link_.vertices().end());
    le.clear();
    lt.clear();
    for (Index t : st) {
      Triangle o;
      int n = 0;
      for (Index w : tets[t])
        if (w != v) o[n++] = w;
      std::sort(o.begin(), o.end());
      lt.push_back(o);
    }
    bool on_boundary = false;
    for (const auto& e : link_.edges()) {
      le.push_back(Edge(e.a, e.b));
      if (e.count != 1) continue;
      // the boundary triangle (v, a, b): cone it
      on_boundary = true;
      le.push_back(Edge(e.a, omega));
      le.push_back(Edge(e.b, omega));
      lt.push_back(Triangle{{e.a, e.b, omega}});
    }
    if (on_boundary) lv.push_back(omega);
    sort_unique(lv);
    sort_unique(le);
    sort_unique(lt);
  }

  Vertex_link<Index> link_;
  Edge_fan<Index> fan_;
  std::vector<Index> lv1_, lv2_, ev_;
  std::vector<Edge> le1_, le2_, ee_;
  std::vector<Triangle> lt1_, lt2_;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_COLLAPSE_TESTER_H
