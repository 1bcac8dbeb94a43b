// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_LOCAL_SIMPLIFIER_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_LOCAL_SIMPLIFIER_H

// The rounds of the local half-edge-collapse simplification (paper Section 9): per-leaf queues on
// the PR-star octree of the current mesh, then compaction and a new octree.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/Index_arrays_input.h>
#include <CGAL/PR_star_octree/Leaf_topology.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/internal/collapse_tester.h>
#include <CGAL/PR_star_octree/internal/local_complex.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <vector>

namespace CGAL {
namespace PR_star_octree {

struct Simplification_statistics;

namespace internal {

// The rounds of the local simplification.
// The stopping criteria and the octree of a simplification (from the named parameters of `simplify()`).
struct Simplification_settings {
  double target_fraction = 0.;
  double max_edge_length = std::numeric_limits<double>::infinity();
  std::size_t bucket_size = 50;
  std::size_t max_rounds = 1000;
};

template <class GeomTraits, class Priority>
class Local_simplifier {
public:
  using Octree = PR_star_octree_3<GeomTraits>;
  using Index = typename Octree::Index;
  using Point_3 = typename GeomTraits::Point_3;
  using Tetrahedron = typename Octree::Tetrahedron;

  Local_simplifier(const Simplification_settings& options, const Priority& priority, const GeomTraits& gt)
      : options_(options), priority_(priority), gt_(gt) {}

  // `points`, `tets` (vertex indices into points), `origin` (input index of each point) are
  // simplified in place.
  // `tet_origin` (input index of each tetrahedron) follows the tetrahedra too.
  void run(std::vector<Point_3>& points, std::vector<Tetrahedron>& tets, std::vector<std::size_t>& origin,
           std::vector<std::size_t>& tet_origin, Simplification_statistics& stats) {
    tet_origin_ = &tet_origin;
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
  double length_quantile(const std::vector<Point_3>& points, const std::vector<Tetrahedron>& tets,
                         double q) const {
    auto squared_distance = gt_.compute_squared_distance_3_object();
    std::vector<double> lengths;
    const std::size_t stride = (std::max)(std::size_t(1), tets.size() / 16384);
    for (std::size_t t = 0; t < tets.size(); t += stride)
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
          lengths.push_back(
              std::sqrt(CGAL::to_double(squared_distance(points[tets[t][i]], points[tets[t][j]]))));
    if (lengths.empty()) return 0;
    const std::size_t k =
        (std::min)(lengths.size() - 1, static_cast<std::size_t>(q * double(lengths.size())));
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
    return CGAL::to_double(gt_.compute_squared_distance_3_object()(pts[a], pts[b])) < threshold_ * threshold_;
  }

  void push(const std::vector<Point_3>& pts, Index v1, Index v2) {
    queue_.push(Entry{priority_(pts, v1, v2), v1, v2});
    stats_->max_queue_size = (std::max)(stats_->max_queue_size, queue_.size());
  }

  void round(std::vector<Point_3>& points, std::vector<Tetrahedron>& tets, std::vector<std::size_t>& origin,
             double threshold) {
    threshold_ = threshold;
    const Octree tree(make_input(points, tets), options_.bucket_size, Octree::default_max_depth, gt_);
    std::vector<Vertex_type> types;
    classify_vertices<CGAL::Parallel_if_available_tag>(
        tree, false, types, [](Index, int) {}, parameters::default_values());
    const std::vector<Point_3>& pts = tree.points();
    work_ = tree.tetrahedra();
    deleted_tet_.assign(work_.size(), 0);
    deleted_vertex_.assign(pts.size(), 0);

    for (Index leaf : tree.leaves()) {
      if (removed_ >= target_) break;
      vb_ = tree.node(leaf).vertex_begin;
      ve_ = tree.node(leaf).vertex_end;
      const std::size_t nv = ve_ - vb_;
      // The stars of the leaf's vertices: VT of the round's octree without the tetrahedra deleted by
      // earlier leaves (a collapse in an earlier leaf only renames vertices of that leaf).
      local_.build(tree, leaf, VERTEX_TETRAHEDRA);
      if (stars_.size() < nv) stars_.resize(nv);
      for (std::size_t i = 0; i < nv; ++i) {
        stars_[i].clear();
        for (Index t : local_.vertex_tetrahedra(static_cast<Index>(vb_ + i)))
          if (!deleted_tet_[t]) stars_[i].push_back(t);
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
    std::vector<std::size_t> next_tet_origin;
    next_tets.reserve(work_.size());
    next_tet_origin.reserve(work_.size());
    for (std::size_t t = 0; t < work_.size(); ++t) {
      if (deleted_tet_[t]) continue;
      next_tet_origin.push_back((*tet_origin_)[tree.original_tetrahedron(static_cast<Index>(t))]);
      Tetrahedron c = work_[t];
      for (Index& v : c) v = renumber[v];
      next_tets.push_back(c);
    }
    points.swap(next_points);
    origin.swap(next_origin);
    tets.swap(next_tets);
    tet_origin_->swap(next_tet_origin);
    work_.clear();
  }

  void neighbors(Index v, std::vector<Index>& out) { star_neighbors(work_, live_star(v), v, out); }

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

  Simplification_settings options_;
  Priority priority_;
  GeomTraits gt_;
  Simplification_statistics* stats_ = nullptr;
  std::vector<std::size_t>* tet_origin_ = nullptr;
  std::size_t target_ = 0, removed_ = 0;
  double threshold_ = 0;
  Index vb_ = 0, ve_ = 0;
  std::vector<Tetrahedron> work_;
  std::vector<char> deleted_tet_, deleted_vertex_;
  std::vector<std::vector<Index>> stars_;
  std::vector<Index> st_e_, nbr_, old_v1_nbr_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue_;
  Collapse_tester<GeomTraits, Index> tester_;
  Leaf_topology<Octree> local_;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_LOCAL_SIMPLIFIER_H
