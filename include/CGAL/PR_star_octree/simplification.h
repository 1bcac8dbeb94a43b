// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_SIMPLIFICATION_H
#define CGAL_PR_STAR_OCTREE_SIMPLIFICATION_H

/// \file simplification.h
/// Local half-edge-collapse simplification of a tetrahedral mesh on a PR-star octree (paper
/// Section 9): every leaf collapses the short edges whose two ends it indexes, with a local
/// priority queue; then the mesh is compacted and the octree rebuilt, round after round.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/Index_arrays_input.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>
#include <CGAL/PR_star_octree/Leaf_topology.h>
#include <CGAL/PR_star_octree/boundary.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {

/// \ingroup PkgPRStarOctreeRef
/// The default priority of a half-edge collapse: the squared length of the edge (shortest first).
///
/// A priority is a functor `double operator()(const std::vector<Point_3>& points, Index v1, Index v2)`
/// called for the collapse of `v2` into `v1` (current numbering of the round); smaller values are
/// collapsed first.  It is evaluated when the edge enters a leaf's queue and again when it leaves it:
/// if the value changed (a priority depending on the neighbourhood, e.g. a quadric error), the edge is
/// queued again with the new value.
struct Edge_length_priority {
  template <class Point_3, class Index>
  double operator()(const std::vector<Point_3>& points, Index v1, Index v2) const {
    return CGAL::to_double(CGAL::squared_distance(points[v1], points[v2]));
  }
};

/// \ingroup PkgPRStarOctreeRef
/// The stopping criteria and the octree of `simplify()`.  At least one of `target_fraction` and
/// `max_edge_length` must be set.
struct Simplification_options {
  /// stop once this fraction of the input tetrahedra is removed (in `(0, 1)`; 0: no target)
  double target_fraction = 0.;
  /// collapse only edges shorter than this (infinity: no bound)
  double max_edge_length = std::numeric_limits<double>::infinity();
  /// the bucket threshold `k_v` of the octree; `PR_star_octree_3<>::infinite_bucket_size` gives the
  /// global algorithm (one leaf, one queue)
  std::size_t bucket_size = PR_star_octree_3<>::default_bucket_size;
  /// an upper bound on the number of rounds
  std::size_t max_rounds = 1000;
};

/// \ingroup PkgPRStarOctreeRef
/// What a run of `simplify()` did.
struct Simplification_statistics {
  std::size_t input_vertices = 0, output_vertices = 0;
  std::size_t input_tetrahedra = 0, output_tetrahedra = 0, removed_tetrahedra = 0;
  std::size_t collapses = 0;
  std::size_t rounds = 0;         ///< rounds of (local simplification, compaction, rebuild)
  std::vector<std::size_t> removed_per_round; ///< tetrahedra removed by each round
  std::size_t max_queue_size = 0; ///< the largest queue, over all leaves and rounds (the memory proxy of Table 3)
  double seconds = 0;             ///< wall-clock time of the whole run, octree builds included
  /// candidate edges (shorter than the round's threshold) that were not collapsed, by reason; a
  /// candidate is counted under the first condition it fails, in this order
  struct Blocked {
    std::size_t different_leaves = 0; ///< its two ends are in different leaves (counted once per round)
    std::size_t boundary = 0;         ///< boundary condition (or a non-manifold end)
    std::size_t flip = 0;             ///< geometric condition: a tetrahedron would flip or become flat
    std::size_t link = 0;             ///< link condition
  } blocked;
};

/// \ingroup PkgPRStarOctreeRef
/// The simplified mesh and where its vertices come from.
template <class Point_3>
struct Simplification_result {
  /// positively oriented tetrahedra; the point data of the input (its scalar field) carried along
  Indexed_tetrahedral_mesh<Point_3> mesh;
  /// for each output vertex, its index in the input (a half-edge collapse never moves a vertex)
  std::vector<std::size_t> input_vertex;
  Simplification_statistics statistics;
};

/// \ingroup PkgPRStarOctreeRef
/// The three conditions of a half-edge collapse, evaluated independently (see `check_half_edge_collapse()`).
struct Collapse_check {
  bool edge_exists = false; ///< the two vertices span an edge of the mesh
  bool boundary = false;    ///< both ends interior, or both on the boundary with a boundary edge
  bool geometry = false;    ///< no tetrahedron of `St(v2) - St(e)` flips or becomes flat (exact)
  bool link = false;        ///< `Lk(v1) ∩ Lk(v2) = Lk(e)` (boundary coned to a dummy vertex)
  bool allowed() const { return edge_exists && boundary && geometry && link; }
};

namespace internal {

// The collapse conditions on explicit stars.  Tetrahedra are given by index into `tets`, which
// holds them positively oriented.
template <class GeomTraits, class Index>
class Collapse_tester {
public:
  using Point_3 = typename GeomTraits::Point_3;
  using Tetrahedron = std::array<Index, 4>;
  static constexpr Index omega = (std::numeric_limits<Index>::max)(); // the cone vertex of the boundary

  // St(e): the tetrahedra of `st2` containing v1.
  static void edge_star(const std::vector<Tetrahedron>& tets, const std::vector<Index>& st2, Index v1,
                        std::vector<Index>& out) {
    out.clear();
    for (Index t : st2)
      if (contains(tets[t], v1)) out.push_back(t);
  }

  // Boundary condition.  Both ends interior, or both on the boundary and `e` on the boundary (its
  // star is an open fan: some triangle (v1, v2, w) has one tetrahedron).  Non-manifold ends never.
  bool boundary_ok(const std::vector<Tetrahedron>& tets, const std::vector<Index>& st_e, Index v1, Index v2,
                   Vertex_type t1, Vertex_type t2) {
    if (t1 != t2) return false;
    if (t1 == Vertex_type::INTERIOR) return true;
    if (t1 != Vertex_type::BOUNDARY) return false;
    edge_wings(tets, st_e, v1, v2);
    return !single_wings_.empty();
  }

  // Geometric condition, with the exact orientation predicate of the traits.
  bool geometry_ok(const GeomTraits& gt, const std::vector<Point_3>& points, const std::vector<Tetrahedron>& tets,
                   const std::vector<Index>& st2, Index v1, Index v2) const {
    auto orientation = gt.orientation_3_object();
    for (Index t : st2) {
      const Tetrahedron& c = tets[t];
      if (contains(c, v1)) continue; // in St(e): deleted
      const Point_3* p[4];
      for (int k = 0; k < 4; ++k) p[k] = &points[c[k] == v2 ? v1 : c[k]];
      if (orientation(*p[0], *p[1], *p[2], *p[3]) != CGAL::POSITIVE) return false;
    }
    return true;
  }

  // Link condition Lk(v1) ∩ Lk(v2) = Lk(e) on vertices, edges and triangles, the boundary being
  // coned to the dummy vertex `omega` (Dey, Edelsbrunner, Guha, Nekhayev), so that it also
  // preserves the boundary surface.  Lk(e) is always in the intersection: comparing sizes is enough.
  bool link_ok(const std::vector<Tetrahedron>& tets, const std::vector<Index>& st1, const std::vector<Index>& st2,
               const std::vector<Index>& st_e, Index v1, Index v2) {
    vertex_link(tets, st1, v1, lv1_, le1_, lt1_);
    vertex_link(tets, st2, v2, lv2_, le2_, lt2_);
    // Lk(e): the edges opposite e, and (omega, w) for the boundary triangles (v1, v2, w).
    ev_.clear();
    ee_.clear();
    for (Index t : st_e) {
      Index o[2];
      int n = 0;
      for (Index w : tets[t])
        if (w != v1 && w != v2) o[n++] = w;
      ev_.push_back(o[0]);
      ev_.push_back(o[1]);
      ee_.push_back(sorted(o[0], o[1]));
    }
    edge_wings(tets, st_e, v1, v2);
    if (!single_wings_.empty()) ev_.push_back(omega);
    for (Index w : single_wings_) ee_.push_back(sorted(w, omega));
    unique(ev_);
    unique(ee_);
    return intersection_size(lv1_, lv2_) == ev_.size() && intersection_size(le1_, le2_) == ee_.size() &&
           intersection_size(lt1_, lt2_) == 0;
  }

  static bool contains(const Tetrahedron& c, Index v) { return c[0] == v || c[1] == v || c[2] == v || c[3] == v; }

private:
  using Edge = std::pair<Index, Index>;
  using Triangle = std::array<Index, 3>;

  static Edge sorted(Index a, Index b) { return a < b ? Edge(a, b) : Edge(b, a); }
  template <class V>
  static void unique(V& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  }
  template <class V>
  static std::size_t intersection_size(const V& a, const V& b) {
    std::size_t n = 0;
    auto i = a.begin(), j = b.begin();
    while (i != a.end() && j != b.end()) {
      if (*i < *j)
        ++i;
      else if (*j < *i)
        ++j;
      else {
        ++n;
        ++i;
        ++j;
      }
    }
    return n;
  }

  // The wings of e: the third vertex of every triangle (v1, v2, w) of St(e), with multiplicity;
  // those seen once are on the boundary.
  void edge_wings(const std::vector<Tetrahedron>& tets, const std::vector<Index>& st_e, Index v1, Index v2) {
    wings_.clear();
    for (Index t : st_e)
      for (Index w : tets[t])
        if (w != v1 && w != v2) wings_.push_back(w);
    std::sort(wings_.begin(), wings_.end());
    single_wings_.clear();
    for (std::size_t i = 0; i < wings_.size();) {
      std::size_t j = i + 1;
      while (j < wings_.size() && wings_[j] == wings_[i]) ++j;
      if (j - i == 1) single_wings_.push_back(wings_[i]);
      i = j;
    }
  }

  // The link of v in the complex whose boundary is coned to omega: sorted vertex, edge and
  // triangle sets.
  void vertex_link(const std::vector<Tetrahedron>& tets, const std::vector<Index>& st, Index v,
                   std::vector<Index>& lv, std::vector<Edge>& le, std::vector<Triangle>& lt) {
    lv.clear();
    le.clear();
    lt.clear();
    faces_.clear();
    for (Index t : st) {
      Triangle o;
      int n = 0;
      for (Index w : tets[t])
        if (w != v) o[n++] = w;
      std::sort(o.begin(), o.end());
      lv.insert(lv.end(), o.begin(), o.end());
      le.push_back(Edge(o[0], o[1]));
      le.push_back(Edge(o[1], o[2]));
      le.push_back(Edge(o[0], o[2]));
      lt.push_back(o);
      // the triangles of St(v) incident in v, as the pair of their other vertices
      faces_.push_back(Edge(o[0], o[1]));
      faces_.push_back(Edge(o[1], o[2]));
      faces_.push_back(Edge(o[0], o[2]));
    }
    std::sort(faces_.begin(), faces_.end());
    bool on_boundary = false;
    for (std::size_t i = 0; i < faces_.size();) {
      std::size_t j = i + 1;
      while (j < faces_.size() && faces_[j] == faces_[i]) ++j;
      if (j - i == 1) { // boundary triangle (v, a, b): cone it
        on_boundary = true;
        const Index a = faces_[i].first, b = faces_[i].second;
        le.push_back(Edge(a, omega));
        le.push_back(Edge(b, omega));
        lt.push_back(Triangle{{a, b, omega}});
      }
      i = j;
    }
    if (on_boundary) lv.push_back(omega);
    unique(lv);
    unique(le);
    unique(lt);
  }

  std::vector<Index> lv1_, lv2_, ev_, wings_, single_wings_;
  std::vector<Edge> le1_, le2_, ee_, faces_;
  std::vector<Triangle> lt1_, lt2_;
};

// The rounds of the local simplification.
template <class GeomTraits, class Priority>
class Local_simplifier {
public:
  using Octree = PR_star_octree_3<GeomTraits>;
  using Index = typename Octree::Index;
  using Point_3 = typename GeomTraits::Point_3;
  using Tetrahedron = typename Octree::Tetrahedron;

  Local_simplifier(const Simplification_options& options, const Priority& priority, const GeomTraits& gt)
      : options_(options), priority_(priority), gt_(gt) {}

  // `points`, `tets` (vertex indices into points), `origin` (input index of each point) are
  // simplified in place.
  void run(std::vector<Point_3>& points, std::vector<Tetrahedron>& tets, std::vector<std::size_t>& origin,
           Simplification_statistics& stats) {
    const std::size_t input_tets = tets.size();
    target_ = options_.target_fraction > 0
                  ? static_cast<std::size_t>(std::ceil(options_.target_fraction * double(input_tets)))
                  : (std::numeric_limits<std::size_t>::max)();
    removed_ = 0;
    stats_ = &stats;
    bool all_candidates = false; // the round threshold is a length quantile until a round stalls
    while (removed_ < target_ && stats.rounds < options_.max_rounds) {
      double threshold = options_.max_edge_length;
      bool quantile = false;
      if (options_.target_fraction > 0 && !all_candidates) {
        const double q = double(target_ - removed_) / double((std::max)(tets.size(), std::size_t(1)));
        if (q < 1) {
          threshold = (std::min)(threshold, length_quantile(points, tets, q));
          quantile = true;
        }
      }
      ++stats.rounds;
      const std::size_t before = removed_;
      round(points, tets, origin, threshold);
      stats.removed_per_round.push_back(removed_ - before);
      if (removed_ == before) {
        if (quantile && threshold < options_.max_edge_length) {
          all_candidates = true; // nothing short enough could go: try every edge under the bound
          continue;
        }
        break;
      }
    }
  }

private:
  struct Entry {
    double priority;
    Index v1, v2;
    bool operator>(const Entry& o) const {
      return priority > o.priority || (priority == o.priority && (v1 > o.v1 || (v1 == o.v1 && v2 > o.v2)));
    }
  };

  // A deterministic sample of edge lengths (at most ~100K) and its q-quantile.
  static double length_quantile(const std::vector<Point_3>& points, const std::vector<Tetrahedron>& tets, double q) {
    std::vector<double> lengths;
    const std::size_t stride = (std::max)(std::size_t(1), tets.size() / 16384);
    for (std::size_t t = 0; t < tets.size(); t += stride)
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
          lengths.push_back(std::sqrt(CGAL::to_double(CGAL::squared_distance(points[tets[t][i]], points[tets[t][j]]))));
    if (lengths.empty()) return 0;
    const std::size_t k = (std::min)(lengths.size() - 1, static_cast<std::size_t>(q * double(lengths.size())));
    std::nth_element(lengths.begin(), lengths.begin() + k, lengths.end());
    // strictly shorter than the threshold: take the next representable value
    return std::nextafter(lengths[k], std::numeric_limits<double>::infinity());
  }

  std::vector<Index>& live_star(Index v) {
    std::vector<Index>& s = stars_[v - vb_];
    s.erase(std::remove_if(s.begin(), s.end(), [this](Index t) { return deleted_tet_[t] != 0; }), s.end());
    return s;
  }

  bool short_enough(const std::vector<Point_3>& pts, Index a, Index b) const {
    if (!(threshold_ < std::numeric_limits<double>::infinity())) return true;
    return CGAL::to_double(CGAL::squared_distance(pts[a], pts[b])) < threshold_ * threshold_;
  }

  void push(const std::vector<Point_3>& pts, Index v1, Index v2) {
    queue_.push(Entry{priority_(pts, v1, v2), v1, v2});
    stats_->max_queue_size = (std::max)(stats_->max_queue_size, queue_.size());
  }

  void round(std::vector<Point_3>& points, std::vector<Tetrahedron>& tets, std::vector<std::size_t>& origin,
             double threshold) {
    threshold_ = threshold;
    const Octree tree(make_input(points, tets), options_.bucket_size, Octree::default_max_depth, gt_);
    const std::vector<Vertex_type> types = compute_boundary(tree, false).vertex_type;
    const std::vector<Point_3>& pts = tree.points();
    work_ = tree.tetrahedra();
    deleted_tet_.assign(work_.size(), 0);
    deleted_vertex_.assign(pts.size(), 0);

    for (Index leaf : tree.leaves()) {
      if (removed_ >= target_) break;
      vb_ = tree.node(leaf).vertex_begin;
      ve_ = tree.node(leaf).vertex_end;
      const std::size_t nv = ve_ - vb_;
      if (stars_.size() < nv) stars_.resize(nv);
      for (std::size_t i = 0; i < nv; ++i) stars_[i].clear();
      for (Index t : tree.leaf_tetrahedra(leaf)) {
        if (deleted_tet_[t]) continue;
        for (Index v : work_[t])
          if (v - vb_ < nv) stars_[v - vb_].push_back(t);
      }
      // Candidate edges: both ends in the leaf and short enough.
      queue_ = decltype(queue_)();
      for (Index v = vb_; v < ve_; ++v) {
        neighbors(v, nbr_);
        for (Index w : nbr_) {
          if (w <= v || !short_enough(pts, v, w)) continue;
          if (w < ve_)
            push(pts, v, w);
          else
            ++stats_->blocked.different_leaves; // counted by the leaf of the smaller end only
        }
      }
      while (!queue_.empty() && removed_ < target_) {
        const Entry e = queue_.top();
        queue_.pop();
        if (deleted_vertex_[e.v1] || deleted_vertex_[e.v2]) continue;
        std::vector<Index>& st2 = live_star(e.v2);
        tester_.edge_star(work_, st2, e.v1, st_e_);
        if (st_e_.empty()) continue; // the edge disappeared
        const double p = priority_(pts, e.v1, e.v2);
        if (p != e.priority) { // the neighbourhood changed the priority: queue it again
          push(pts, e.v1, e.v2);
          continue;
        }
        std::vector<Index>& st1 = live_star(e.v1);
        if (!tester_.boundary_ok(work_, st_e_, e.v1, e.v2, types[e.v1], types[e.v2])) {
          ++stats_->blocked.boundary;
          continue;
        }
        if (!tester_.geometry_ok(gt_, pts, work_, st2, e.v1, e.v2)) {
          ++stats_->blocked.flip;
          continue;
        }
        if (!tester_.link_ok(work_, st1, st2, st_e_, e.v1, e.v2)) {
          ++stats_->blocked.link;
          continue;
        }
        collapse(pts, st1, st2, e.v1, e.v2);
      }
    }
    queue_ = decltype(queue_)();

    // Compaction, in the octree's order (spatially coherent for the next round).
    std::vector<Index> renumber(pts.size(), Octree::no_node);
    std::vector<Point_3> next_points;
    std::vector<std::size_t> next_origin;
    next_points.reserve(pts.size());
    next_origin.reserve(pts.size());
    for (std::size_t v = 0; v < pts.size(); ++v) {
      if (deleted_vertex_[v]) continue;
      renumber[v] = static_cast<Index>(next_points.size());
      next_points.push_back(pts[v]);
      next_origin.push_back(origin[tree.original_vertex(static_cast<Index>(v))]);
    }
    std::vector<Tetrahedron> next_tets;
    next_tets.reserve(work_.size());
    for (std::size_t t = 0; t < work_.size(); ++t) {
      if (deleted_tet_[t]) continue;
      Tetrahedron c = work_[t];
      for (Index& v : c) v = renumber[v];
      next_tets.push_back(c);
    }
    points.swap(next_points);
    origin.swap(next_origin);
    tets.swap(next_tets);
    work_.clear();
  }

  void neighbors(Index v, std::vector<Index>& out) {
    out.clear();
    for (Index t : live_star(v))
      for (Index w : work_[t])
        if (w != v) out.push_back(w);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }

  // Half-edge collapse of v2 into v1: delete St(e), St(v1) = St(v1) ∪ St(v2) - St(e), v2 -> v1 in
  // the tetrahedra left in St(v2), delete v2.  The stars of the other vertices of the leaf lose
  // the deleted tetrahedra lazily (`live_star()`).
  void collapse(const std::vector<Point_3>& pts, std::vector<Index>& st1, std::vector<Index>& st2, Index v1,
                Index v2) {
    neighbors(v1, nbr_);
    old_v1_nbr_.swap(nbr_);
    for (Index t : st_e_) deleted_tet_[t] = 1;
    removed_ += st_e_.size();
    stats_->removed_tetrahedra += st_e_.size();
    ++stats_->collapses;
    for (Index t : st2) {
      if (deleted_tet_[t]) continue;
      for (Index& w : work_[t])
        if (w == v2) w = v1;
      st1.push_back(t);
    }
    st2.clear();
    deleted_vertex_[v2] = 1;
    live_star(v1);
    // New candidate edges: (v1, w) for the neighbours w of v2 that were not neighbours of v1.
    neighbors(v1, nbr_);
    for (Index w : nbr_) {
      if (w - vb_ >= ve_ - vb_) continue; // outside the leaf
      if (std::binary_search(old_v1_nbr_.begin(), old_v1_nbr_.end(), w)) continue;
      if (!short_enough(pts, v1, w)) continue;
      if (v1 < w)
        push(pts, v1, w);
      else
        push(pts, w, v1);
    }
  }

  Simplification_options options_;
  Priority priority_;
  GeomTraits gt_;
  Simplification_statistics* stats_ = nullptr;
  std::size_t target_ = 0, removed_ = 0;
  double threshold_ = 0;
  Index vb_ = 0, ve_ = 0;
  std::vector<Tetrahedron> work_;
  std::vector<char> deleted_tet_, deleted_vertex_;
  std::vector<std::vector<Index>> stars_;
  std::vector<Index> st_e_, nbr_, old_v1_nbr_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue_;
  Collapse_tester<GeomTraits, Index> tester_;
};

} // namespace internal

/// \ingroup PkgPRStarOctreeRef
///
/// Simplifies a tetrahedral mesh by half-edge collapses on a PR-star octree (paper Section 9).
///
/// Each round builds the PR-star octree of the current mesh with `options.bucket_size` and
/// visits its leaves in depth-first order.  A leaf queues the edges whose two ends it indexes and
/// that are shorter than the round's threshold, by `priority` (shortest first by default), and
/// collapses them one by one: the edge `e = (v1, v2)`, `v1 < v2`, is collapsed into `v1` (`v2` is
/// removed, `v1` does not move and keeps its scalar value) when
/// - *boundary condition*: both ends are interior, or both are on the boundary and `e` is a
///   boundary edge (a non-manifold end is never collapsed);
/// - *geometric condition*: no tetrahedron of `St(v2) - St(e)` flips or becomes flat when `v2`
///   moves to `v1`, decided with the traits' exact `Orientation_3`;
/// - *link condition*: `Lk(v1) ∩ Lk(v2) = Lk(e)` as simplicial complexes (vertices, edges,
///   triangles), the boundary being coned to a dummy vertex so that the boundary surface keeps its
///   topology too.
/// Then the mesh is compacted and the octree rebuilt.  Rounds go on while one removes a tetrahedron
/// and the target is not met.
///
/// The round's threshold is `options.max_edge_length`; with a target fraction it is also bounded by
/// the `q`-quantile of the current edge lengths (sampled), `q` being the fraction of the current
/// tetrahedra still to remove, so that short edges all over the mesh go first; when such a round
/// removes nothing, the next ones take every edge under `options.max_edge_length`.
///
/// `InputMesh` is a model of `PRStarOctreeInputMesh` (see `make_input()`); its scalar field, if
/// any, is the output's point-data array "scalar".
///
/// \throws std::invalid_argument when neither a target in `(0, 1)` nor a finite positive length
/// bound is given, and as the `PR_star_octree_3` constructor for a bad input.
template <class GeomTraits = Exact_predicates_inexact_constructions_kernel, class InputMesh,
          class Priority = Edge_length_priority>
Simplification_result<typename GeomTraits::Point_3>
simplify(const InputMesh& input, const Simplification_options& options, const Priority& priority = Priority(),
         const GeomTraits& gt = GeomTraits()) {
  using Octree = PR_star_octree_3<GeomTraits>;
  using Point_3 = typename GeomTraits::Point_3;
  if (!(options.target_fraction >= 0 && options.target_fraction < 1))
    throw std::invalid_argument("simplify: the target fraction must be in [0, 1)");
  if (!(options.max_edge_length > 0))
    throw std::invalid_argument("simplify: the maximum edge length must be positive");
  if (options.target_fraction == 0 && !(options.max_edge_length < std::numeric_limits<double>::infinity()))
    throw std::invalid_argument("simplify: give a target fraction or a maximum edge length");
  if (options.bucket_size == 0) throw std::invalid_argument("simplify: the bucket size k_v must be at least 1");

  const auto start = std::chrono::steady_clock::now();
  Simplification_result<Point_3> result;
  Simplification_statistics& s = result.statistics;

  // Validated, oriented copy of the input (the octree does both).
  std::vector<Point_3> points;
  std::vector<typename Octree::Tetrahedron> tets;
  std::vector<std::size_t> origin;
  {
    const Octree tree(input, options.bucket_size, Octree::default_max_depth, gt);
    points = tree.points();
    tets = tree.tetrahedra();
    origin.resize(points.size());
    for (std::size_t v = 0; v < points.size(); ++v) origin[v] = tree.original_vertex(static_cast<typename Octree::Index>(v));
  }
  s.input_vertices = points.size();
  s.input_tetrahedra = tets.size();

  internal::Local_simplifier<GeomTraits, Priority> simplifier(options, priority, gt);
  simplifier.run(points, tets, origin, s);

  s.output_vertices = points.size();
  s.output_tetrahedra = tets.size();
  result.mesh.points = std::move(points);
  result.mesh.tetrahedra.assign(tets.begin(), tets.end());
  if (input.has_scalar_field()) {
    Point_data_array a{"scalar", std::vector<double>(origin.size())};
    for (std::size_t v = 0; v < origin.size(); ++v) a.values[v] = static_cast<double>(input.scalar(origin[v]));
    result.mesh.point_data.push_back(std::move(a));
  }
  result.input_vertex = std::move(origin);
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

/// \ingroup PkgPRStarOctreeRef
/// Simplifies an `Indexed_tetrahedral_mesh`: every point-data array (names kept) is carried along,
/// the tetrahedron labels are dropped.
template <class GeomTraits = Exact_predicates_inexact_constructions_kernel, class P, class I,
          class Priority = Edge_length_priority>
Simplification_result<typename GeomTraits::Point_3>
simplify(const Indexed_tetrahedral_mesh<P, I>& mesh, const Simplification_options& options,
         const Priority& priority = Priority(), const GeomTraits& gt = GeomTraits()) {
  auto result = simplify<GeomTraits>(make_input(mesh.points, mesh.tetrahedra), options, priority, gt);
  for (const Point_data_array& a : mesh.point_data) {
    Point_data_array b{a.name, std::vector<double>(result.input_vertex.size())};
    for (std::size_t v = 0; v < b.values.size(); ++v) b.values[v] = a.values[result.input_vertex[v]];
    result.mesh.point_data.push_back(std::move(b));
  }
  return result;
}

/// \ingroup PkgPRStarOctreeRef
/// Evaluates the three conditions of the half-edge collapse of `v2` into `v1` (octree numbering)
/// independently, with the same code as `simplify()` (for tests and diagnostics; `O(|T|)` for
/// the vertex types).
template <class Octree>
Collapse_check check_half_edge_collapse(const Octree& tree, typename Octree::Index v1, typename Octree::Index v2) {
  using Index = typename Octree::Index;
  Collapse_check r;
  internal::Collapse_tester<typename Octree::Geom_traits, Index> tester;
  std::vector<Index> st1, st2, st_e;
  vertex_star(tree, v1, std::back_inserter(st1));
  vertex_star(tree, v2, std::back_inserter(st2));
  tester.edge_star(tree.tetrahedra(), st2, v1, st_e);
  r.edge_exists = !st_e.empty();
  if (!r.edge_exists) return r;
  const std::vector<Vertex_type> types = compute_boundary(tree, false).vertex_type;
  r.boundary = tester.boundary_ok(tree.tetrahedra(), st_e, v1, v2, types[v1], types[v2]);
  r.geometry = tester.geometry_ok(tree.geom_traits(), tree.points(), tree.tetrahedra(), st2, v1, v2);
  r.link = tester.link_ok(tree.tetrahedra(), st1, st2, st_e, v1, v2);
  return r;
}

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_SIMPLIFICATION_H
