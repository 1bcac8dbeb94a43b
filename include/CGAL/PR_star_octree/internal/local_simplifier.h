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
#include <CGAL/PR_star_octree/Leaf_executor.h>
#include <CGAL/PR_star_octree/Leaf_topology.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/internal/collapse_tester.h>
#include <CGAL/PR_star_octree/internal/local_complex.h>
#include <CGAL/PR_star_octree/internal/simplification_constraints.h>
#include <CGAL/PR_star_octree/tetrahedron_quality.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <tuple>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {

struct Simplification_statistics;

namespace internal {

// The stopping criteria, the octree and the constraints of a simplification (from the named
// parameters of `simplify()`).
struct Simplification_settings {
  double target_fraction = 0.;
  double max_edge_length = std::numeric_limits<double>::infinity();
  std::size_t bucket_size = 50;
  std::size_t max_rounds = 1000;
  Quality_measure quality_measure = Quality_measure::MIN_DIHEDRAL_ANGLE;
  double quality_floor = 5;                                            // 0: no floor
  double feature_angle = 40;                                           // degrees; >= 180: no sharp edges
  double max_boundary_error = std::numeric_limits<double>::infinity(); // absolute
  bool quadric_priority = false;  // else the priority functor (shortest edge first by default)
  bool optimal_placement = false; // else half-edge collapses only
};

// Why a candidate edge was not collapsed.
enum class Refusal { NONE, GONE, FEATURE, BOUNDARY, FLIP, LINK, QUALITY, ERROR };

// The rounds of the local simplification.
template <class GeomTraits, class Priority>
class Local_simplifier {
public:
  using Octree = PR_star_octree_3<GeomTraits>;
  using Index = typename Octree::Index;
  using Point_3 = typename GeomTraits::Point_3;
  using Tetrahedron = typename Octree::Tetrahedron;
  using K = Exact_predicates_inexact_constructions_kernel; // the error bound's geometry (doubles)
  using Triangle_list = std::vector<K::Triangle_3>;
  using AABB_tree =
      CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Triangle_list::const_iterator>>>;

  Local_simplifier(const Simplification_settings& options, const Priority& priority, const GeomTraits& gt)
      : options_(options), priority_(priority), gt_(gt) {}

  // `points`, `tets` (vertex indices into points, positively oriented), `origin` (input index of
  // each point) and `tet_origin` (input index of each tetrahedron) are simplified in place.
  // `labels` (input numbering, or empty) are the tetrahedron labels; `constrained_vertex(o)` and
  // `constrained_edge(o1, o2)` the user's constraints, on input indices.
  template <class ConstrainedVertex, class ConstrainedEdge>
  void run(std::vector<Point_3>& points, std::vector<Tetrahedron>& tets, std::vector<std::size_t>& origin,
           std::vector<std::size_t>& tet_origin, const std::vector<int>& labels,
           ConstrainedVertex constrained_vertex, ConstrainedEdge constrained_edge,
           Simplification_statistics& stats) {
    tet_origin_ = &tet_origin;
    labels_ = &labels;
    stats_ = &stats;
    const std::size_t input_tets = tets.size();
    target_ = options_.target_fraction > 0
                  ? static_cast<std::size_t>(std::ceil(options_.target_fraction * double(input_tets)))
                  : (std::numeric_limits<std::size_t>::max)();
    removed_ = 0;
    prepare_constraints(points, tets, origin, constrained_vertex, constrained_edge);
    std::vector<std::size_t> sid(points.size()); // the stable id of each point: its index now
    for (std::size_t v = 0; v < sid.size(); ++v) sid[v] = v;

    bool all_candidates = false; // the round threshold is a length quantile until a round stalls
    stats.stop = Simplification_stop::NOTHING_LEFT;
    while (removed_ < target_) {
      if (stats.rounds >= options_.max_rounds) {
        stats.stop = Simplification_stop::MAX_ROUNDS;
        break;
      }
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
      stats.blocked_last_round = Simplification_statistics::Blocked();
      round(points, tets, origin, sid, threshold);
      stats.removed_per_round.push_back(removed_ - before);
      if (removed_ == before) {
        if (quantile && threshold < options_.max_edge_length) {
          all_candidates = true; // nothing short enough could go: try every edge under the bound
          continue;
        }
        stats.stop =
            options_.target_fraction > 0 ? Simplification_stop::BLOCKED : Simplification_stop::NOTHING_LEFT;
        break;
      }
    }
    if (removed_ >= target_) stats.stop = Simplification_stop::TARGET_REACHED;
  }

private:
  struct Entry {
    double priority;
    Index a, b; // a < b
    bool operator>(const Entry& o) const {
      return priority > o.priority || (priority == o.priority && (a > o.a || (a == o.a && b > o.b)));
    }
  };

  // ------------------------------------------------------------------------------------------
  // Constraints, on the stable ids of the vertices (their index in the first round)
  // ------------------------------------------------------------------------------------------

  template <class ConstrainedVertex, class ConstrainedEdge>
  void prepare_constraints(const std::vector<Point_3>& points, const std::vector<Tetrahedron>& tets,
                           const std::vector<std::size_t>& origin, ConstrainedVertex constrained_vertex,
                           ConstrainedEdge constrained_edge) {
    input_pos_.resize(points.size());
    for (std::size_t v = 0; v < points.size(); ++v) input_pos_[v] = coordinates(points[v]);
    std::vector<int> tet_labels;
    if (!labels_->empty()) {
      tet_labels.resize(tets.size());
      for (std::size_t t = 0; t < tets.size(); ++t) tet_labels[t] = (*labels_)[(*tet_origin_)[t]];
    }
    compute_surface_constraints(
        input_pos_, tets, tet_labels, options_.feature_angle,
        options_.quadric_priority || options_.optimal_placement,
        [&](Index v) { return constrained_vertex(origin[v]); },
        [&](Index a, Index b) { return constrained_edge(origin[a], origin[b]); }, constraints_);
    covered_.assign(points.size(), {});
    surface_.clear();
    tree_of_surface_.clear();
    max_normal_cosine_ = options_.feature_angle < 180
                             ? std::cos(options_.feature_angle / 2 * 3.14159265358979323846 / 180)
                             : -1.;
    if (!(options_.max_boundary_error < std::numeric_limits<double>::infinity())) return;
    auto p = [&](Index v) { return K::Point_3(input_pos_[v][0], input_pos_[v][1], input_pos_[v][2]); };
    surface_.reserve(constraints_.triangles.size());
    for (const auto& tri : constraints_.triangles) surface_.emplace_back(p(tri[0]), p(tri[1]), p(tri[2]));
    tree_of_surface_.insert(surface_.begin(), surface_.end());
    tree_of_surface_.accelerate_distance_queries();
  }

  Vec3 coordinates(const Point_3& p) const {
    return Vec3{{CGAL::to_double(gt_.compute_x_3_object()(p)), CGAL::to_double(gt_.compute_y_3_object()(p)),
                 CGAL::to_double(gt_.compute_z_3_object()(p))}};
  }

  int dimension(Index v) const {
    return types_[v] == Vertex_type::NONMANIFOLD ? 0 : constraints_.dimension[sid_[v]];
  }
  bool is_feature(Index a, Index b) const { return constraints_.is_feature(sid_[a], sid_[b]); }
  bool in_leaf(Index v) const { return v - vb_ < ve_ - vb_; }

  // ------------------------------------------------------------------------------------------
  // Rounds
  // ------------------------------------------------------------------------------------------

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

  void round(std::vector<Point_3>& points, std::vector<Tetrahedron>& tets, std::vector<std::size_t>& origin,
             std::vector<std::size_t>& sid, double threshold) {
    threshold_ = threshold;
    const Octree tree(make_input(points, tets), options_.bucket_size, Octree::default_max_depth, gt_);
    tree_ = &tree;
    classify_vertices<CGAL::Parallel_if_available_tag>(
        tree, false, types_, [](Index, int) {}, parameters::default_values());
    pos_ = tree.points();
    posd_.resize(pos_.size());
    sid_.resize(pos_.size());
    for (std::size_t v = 0; v < pos_.size(); ++v) {
      posd_[v] = coordinates(pos_[v]);
      sid_[v] = sid[tree.original_vertex(static_cast<Index>(v))];
    }
    work_ = tree.tetrahedra();
    label_.assign(work_.size(), 0);
    if (!labels_->empty())
      for (std::size_t t = 0; t < work_.size(); ++t)
        label_[t] = (*labels_)[(*tet_origin_)[tree.original_tetrahedron(static_cast<Index>(t))]];
    deleted_tet_.assign(work_.size(), 0);
    deleted_vertex_.assign(pos_.size(), 0);
    extras_.clear();

    // The leaves one after the other (each collapse changes the mesh the next leaves see), until
    // the target is reached.
    Leaf_executor<CGAL::Sequential_tag>().for_each(
        tree, VERTEX_TETRAHEDRA, 0, [&](int, const Leaf_topology<Octree>& local) { simplify_leaf(local); },
        internal::No_progress(), [&] { return removed_ >= target_; });
    queue_ = decltype(queue_)();
    outside_.clear();
    tree_ = nullptr;
    compact(tree, points, tets, origin, sid);
  }

  // The collapses of one leaf of the round's octree.
  void simplify_leaf(const Leaf_topology<Octree>& local) {
    vb_ = local.vertex_begin();
    ve_ = local.vertex_end();
    const std::size_t nv = ve_ - vb_;
    // The stars of the leaf's vertices: VT of the round's octree without the tetrahedra deleted
    // by earlier leaves, plus those renamed into them by earlier leaves (`extras_`).
    if (stars_.size() < nv) stars_.resize(nv);
    for (std::size_t i = 0; i < nv; ++i) {
      const Index v = static_cast<Index>(vb_ + i);
      stars_[i].clear();
      for (Index t : local.vertex_tetrahedra(v))
        if (!deleted_tet_[t]) stars_[i].push_back(t);
      auto it = extras_.find(v);
      if (it == extras_.end()) continue;
      for (Index t : it->second) // (kept: a later leaf may need the whole star of v again)
        if (!deleted_tet_[t]) stars_[i].push_back(t);
    }
    outside_.clear();
    // Candidate edges: at least one end in the leaf, short enough.
    queue_ = decltype(queue_)();
    for (Index v = vb_; v < ve_; ++v) {
      neighbors(v, nbr_);
      for (Index w : nbr_)
        if ((w > v || !in_leaf(w)) && short_enough(v, w)) push(v, w);
    }
    while (!queue_.empty() && removed_ < target_) {
      const Entry e = queue_.top();
      queue_.pop();
      if (deleted_vertex_[e.a] || deleted_vertex_[e.b]) continue;
      if (priority(e.a, e.b) != e.priority) { // the neighbourhood changed the priority: queue it again
        push(e.a, e.b);
        continue;
      }
      collapse_edge(e.a, e.b);
    }
  }

  // Compaction, in the octree's order (spatially coherent for the next round).
  void compact(const Octree& tree, std::vector<Point_3>& points, std::vector<Tetrahedron>& tets,
               std::vector<std::size_t>& origin, std::vector<std::size_t>& sid) {
    std::vector<Index> renumber(pos_.size(), Octree::no_node);
    std::vector<Point_3> next_points;
    std::vector<std::size_t> next_origin, next_sid;
    next_points.reserve(pos_.size());
    next_origin.reserve(pos_.size());
    next_sid.reserve(pos_.size());
    for (std::size_t v = 0; v < pos_.size(); ++v) {
      if (deleted_vertex_[v]) continue;
      renumber[v] = static_cast<Index>(next_points.size());
      next_points.push_back(pos_[v]);
      next_origin.push_back(origin[tree.original_vertex(static_cast<Index>(v))]);
      next_sid.push_back(sid_[v]);
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
    sid.swap(next_sid);
    tets.swap(next_tets);
    tet_origin_->swap(next_tet_origin);
    work_.clear();
    pos_.clear();
  }

  // ------------------------------------------------------------------------------------------
  // Stars
  // ------------------------------------------------------------------------------------------

  static void drop_deleted(std::vector<Index>& s, const std::vector<char>& deleted) {
    s.erase(std::remove_if(s.begin(), s.end(), [&](Index t) { return deleted[t] != 0; }), s.end());
  }

  // The current star of v, in the leaf or not (then from the leaf that holds it, cached).
  std::vector<Index>& star(Index v) {
    if (in_leaf(v)) {
      std::vector<Index>& s = stars_[v - vb_];
      drop_deleted(s, deleted_tet_);
      return s;
    }
    auto found = outside_.find(v);
    if (found != outside_.end()) {
      drop_deleted(found->second, deleted_tet_);
      return found->second;
    }
    std::vector<Index>& s = outside_[v];
    for (Index t : tree_->leaf_tetrahedra(tree_->leaf_of_vertex(v)))
      if (!deleted_tet_[t] && contains(work_[t], v)) s.push_back(t);
    auto it = extras_.find(v);
    if (it != extras_.end()) // (a tetrahedron renamed into v may also be in the list of v's leaf)
      for (Index t : it->second)
        if (!deleted_tet_[t]) s.push_back(t);
    sort_unique(s);
    return s;
  }

  void neighbors(Index v, std::vector<Index>& out) { star_neighbors(work_, star(v), v, out); }

  // ------------------------------------------------------------------------------------------
  // Priorities
  // ------------------------------------------------------------------------------------------

  bool short_enough(Index a, Index b) const {
    if (!(threshold_ < std::numeric_limits<double>::infinity())) return true;
    return CGAL::to_double(gt_.compute_squared_distance_3_object()(pos_[a], pos_[b])) <
           threshold_ * threshold_;
  }

  static double squared_length(const Vec3& a, const Vec3& b) {
    const Vec3 d = minus(a, b);
    return dot(d, d);
  }

  // Can `r` be removed into `k` as far as the strata go (the surface-edge and feature-edge tests
  // need the star and come later)?
  bool removable_into(Index r, Index k) const {
    const int dr = dimension(r);
    return dr > 0 && dimension(k) <= dr;
  }

  // Where the merged vertex goes with the optimal placement, as a parameter on (a, b); -1: no
  // move (different strata, a feature curve, or a custom priority).
  double placement(Index a, Index b) const {
    if (!options_.optimal_placement || !std::is_constructible<Point_3, double, double, double>::value)
      return -1;
    const int da = dimension(a);
    if (da < 2 || dimension(b) != da) return -1;
    Plane_quadric q = constraints_.quadrics[sid_[a]];
    q += constraints_.quadrics[sid_[b]];
    return q.best_on_segment(posd_[a], posd_[b]);
  }

  static Vec3 lerp(const Vec3& a, const Vec3& b, double t) {
    return Vec3{{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])}};
  }

  double priority(Index a, Index b) const {
    if (!options_.quadric_priority) return priority_(pos_, a, b);
    // The quadric error of the best allowed placement, plus a hundredth of the squared length so
    // that edges of no error (inside, on planes) go shortest first.
    Plane_quadric q = constraints_.quadrics[sid_[a]];
    q += constraints_.quadrics[sid_[b]];
    double best = std::numeric_limits<double>::infinity();
    const double t = placement(a, b);
    if (t >= 0) best = q.error(lerp(posd_[a], posd_[b], t));
    if (removable_into(b, a)) best = (std::min)(best, q.error(posd_[a]));
    if (removable_into(a, b)) best = (std::min)(best, q.error(posd_[b]));
    if (!(best < std::numeric_limits<double>::infinity())) best = 0;
    return best + 0.01 * squared_length(posd_[a], posd_[b]);
  }

  void push(Index a, Index b) {
    if (b < a) std::swap(a, b);
    queue_.push(Entry{priority(a, b), a, b});
    stats_->max_queue_size = (std::max)(stats_->max_queue_size, queue_.size());
  }

  // ------------------------------------------------------------------------------------------
  // One candidate edge
  // ------------------------------------------------------------------------------------------

  // Tries the collapses of the edge (a, b) allowed by the strata and the leaf, the optimal
  // placement first, and applies the first one that passes every check.
  void collapse_edge(Index a, Index b) {
    struct Candidate {
      Index r, k;
      bool move;
      Vec3 p;
    };
    Candidate candidates[3];
    int n = 0;
    const double t = (in_leaf(a) && in_leaf(b)) ? placement(a, b) : -1;
    if (t > 0 && t < 1) candidates[n++] = Candidate{b, a, true, lerp(posd_[a], posd_[b], t)};
    // half-edge collapses: remove the end of the higher stratum (with the quadric priority, on a
    // tie, the one whose removal costs less)
    bool b_first = true;
    if (options_.quadric_priority && dimension(a) == dimension(b)) {
      Plane_quadric q = constraints_.quadrics[sid_[a]];
      q += constraints_.quadrics[sid_[b]];
      b_first = q.error(posd_[a]) <= q.error(posd_[b]);
    }
    for (int pass = 0; pass < 2; ++pass) {
      const bool remove_b = (pass == 0) == b_first;
      const Index r = remove_b ? b : a, k = remove_b ? a : b;
      if (in_leaf(r) && removable_into(r, k)) candidates[n++] = Candidate{r, k, false, posd_[k]};
    }
    if (n == 0) {
      // Nothing can go: a corner or a higher stratum, or the removable end in another leaf.
      const bool elsewhere = (!in_leaf(a) && removable_into(a, b)) || (!in_leaf(b) && removable_into(b, a));
      if (elsewhere)
        count(Refusal::NONE, true);
      else
        count(Refusal::FEATURE, false);
      return;
    }
    Refusal first = Refusal::NONE;
    for (int i = 0; i < n; ++i) {
      const Refusal why = try_collapse(candidates[i].r, candidates[i].k, candidates[i].move, candidates[i].p);
      if (why == Refusal::NONE) return;
      if (why == Refusal::GONE) return; // the edge disappeared
      if (i == 0) first = why;
    }
    count(first, false);
  }

  void count(Refusal why, bool different_leaves) {
    for (Simplification_statistics::Blocked* b : {&stats_->blocked, &stats_->blocked_last_round}) {
      if (different_leaves) {
        ++b->different_leaves;
        continue;
      }
      switch (why) {
      case Refusal::FEATURE:
        ++b->feature;
        break;
      case Refusal::BOUNDARY:
        ++b->boundary;
        break;
      case Refusal::FLIP:
        ++b->flip;
        break;
      case Refusal::LINK:
        ++b->link;
        break;
      case Refusal::QUALITY:
        ++b->quality;
        break;
      case Refusal::ERROR:
        ++b->error;
        break;
      default:
        break;
      }
    }
  }

  // The surface triangles around `v` of the tetrahedra `cells` (vertex arrays, with `labels`):
  // the triangles (v, x, y) in one cell only or between cells of different labels, as (x, y).
  void surface_link(const std::vector<Tetrahedron>& cells, const std::vector<int>& labels, Index v,
                    std::vector<std::pair<Index, Index>>& out) {
    faces_.clear();
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const Tetrahedron& c = cells[i];
      const int pv = position(c, v);
      if (pv < 0) continue;
      for (int k = 0; k < 4; ++k) {
        if (k == pv) continue;
        Index x = Index(0), y = Index(0);
        bool first = true;
        for (int j = 0; j < 4; ++j)
          if (j != pv && j != k) {
            if (first)
              x = c[j];
            else
              y = c[j];
            first = false;
          }
        faces_.push_back(Face_record{(std::min)(x, y), (std::max)(x, y), labels[i]});
      }
    }
    std::sort(faces_.begin(), faces_.end());
    out.clear();
    for_each_group(
        faces_.begin(), faces_.end(),
        [](const Face_record& p, const Face_record& q) { return p.x == q.x && p.y == q.y; },
        [&](auto first, auto last) {
          if (last - first == 1 || (last - first == 2 && first->label != (first + 1)->label))
            out.emplace_back(first->x, first->y);
        });
  }

  struct Face_record {
    Index x, y;
    int label;
    bool operator<(const Face_record& o) const { return std::tie(x, y, label) < std::tie(o.x, o.y, o.label); }
  };

  void gather(const std::vector<Index>& st, std::vector<Tetrahedron>& cells, std::vector<int>& labels) const {
    cells.clear();
    labels.clear();
    for (Index t : st) {
      cells.push_back(work_[t]);
      labels.push_back(label_[t]);
    }
  }

  // The quality of the cells (vertex `moved` at `p`): the worst and the number under the floor.
  std::pair<double, std::size_t> quality(const std::vector<Tetrahedron>& cells, Index moved,
                                         const Vec3& p) const {
    double worst = std::numeric_limits<double>::infinity();
    std::size_t bad = 0;
    for (const Tetrahedron& c : cells) {
      const Vec3* v[4];
      for (int i = 0; i < 4; ++i) v[i] = c[i] == moved ? &p : &posd_[c[i]];
      const double q = tetrahedron_quality(options_.quality_measure, *v[0], *v[1], *v[2], *v[3]);
      worst = (std::min)(worst, q);
      bad += q < options_.quality_floor;
    }
    return {worst, bad};
  }

  K::Point_3 kpoint(const Vec3& p) const { return K::Point_3(p[0], p[1], p[2]); }

  // The collapse of r into k, k moving to p when `move`.
  Refusal try_collapse(Index r, Index k, bool move, const Vec3& p) {
    std::vector<Index>& st_r = star(r);
    tester_.edge_star(work_, st_r, k, st_e_);
    if (st_e_.empty()) return Refusal::GONE;
    std::vector<Index>& st_k = star(k);
    const int dr = dimension(r);

    // Strata: a feature-curve vertex moves along a feature edge, a surface vertex along the surface.
    const bool surface_edge = is_surface_edge(r, k);
    if (dr == 1 && !is_feature(r, k)) return Refusal::FEATURE;
    if (dr == 2 && !surface_edge) return Refusal::BOUNDARY;

    // Geometry: exact orientation of the new tetrahedra.
    auto orientation = gt_.orientation_3_object();
    const Point_3 pk = move ? make_point(p) : pos_[k];
    auto positive = [&](const Tetrahedron& c) {
      const Point_3* q[4];
      for (int i = 0; i < 4; ++i) q[i] = (c[i] == r || c[i] == k) ? &pk : &pos_[c[i]];
      return orientation(*q[0], *q[1], *q[2], *q[3]) == CGAL::POSITIVE;
    };
    // The new cells: St(r) - St(e) with r renamed k, and St(k) - St(e) when k moves.
    new_cells_.clear();
    new_labels_.clear();
    for (Index t : st_r) {
      if (contains(work_[t], k)) continue;
      Tetrahedron c = work_[t];
      for (Index& w : c)
        if (w == r) w = k;
      new_cells_.push_back(c);
      new_labels_.push_back(label_[t]);
    }
    const std::size_t renamed = new_cells_.size();
    for (Index t : st_k)
      if (!contains(work_[t], r) && (move || dr <= 2)) {
        new_cells_.push_back(work_[t]);
        new_labels_.push_back(label_[t]);
      }
    for (std::size_t i = 0; i < new_cells_.size(); ++i)
      if ((i < renamed || move) && !positive(new_cells_[i])) return Refusal::FLIP;

    // Topology: the link condition of the volume (boundary coned), of the surface and of the curves.
    if (!tester_.link_ok(work_, st_k, st_r, st_e_, k, r)) return Refusal::LINK;
    if (dr <= 2 && !surface_link_ok(r, k, st_r, st_k)) return Refusal::LINK;
    if (dr <= 1 && !curve_link_ok(r, k)) return Refusal::LINK;

    // Quality floor: what the collapse creates is above the floor, or no worse than what it replaces.
    if (options_.quality_floor > 0) {
      changed_cells_.assign(new_cells_.begin(), new_cells_.begin() + static_cast<std::ptrdiff_t>(renamed));
      if (move)
        changed_cells_.insert(changed_cells_.end(), new_cells_.begin() + static_cast<std::ptrdiff_t>(renamed),
                              new_cells_.end());
      const auto after = quality(changed_cells_, k, p);
      if (after.first < options_.quality_floor) {
        gather(st_r, old_cells_, old_labels_);
        if (move)
          for (Index t : st_k)
            if (!contains(work_[t], r)) old_cells_.push_back(work_[t]);
        const auto before = quality(old_cells_, k, posd_[k]);
        if (after.first < before.first || after.second > before.second) return Refusal::QUALITY;
      }
    }

    // Error bound of the surface.
    if ((dr <= 2 || (move && dimension(k) <= 2)) && !error_ok(r, k, move, p)) return Refusal::ERROR;

    apply(r, k, move, p, pk, st_r, st_k);
    return Refusal::NONE;
  }

  Point_3 make_point(const Vec3& p) const {
    if constexpr (std::is_constructible<Point_3, double, double, double>::value)
      return Point_3(p[0], p[1], p[2]);
    else
      return Point_3();
  }

  // The edge (r, k) is on the surface: a boundary triangle holds it, or two of its tetrahedra
  // have different labels.
  bool is_surface_edge(Index r, Index k) {
    fan_.make_wings(work_, st_e_, r, k);
    if (!fan_.boundary_wings().empty()) return true;
    for (Index t : st_e_)
      if (label_[t] != label_[st_e_.front()]) return true;
    return false;
  }

  // Lk(r) ∩ Lk(k) = Lk(e) in the surface: common link vertices are the third vertices of the
  // surface triangles of e, and no link edge is common.
  bool surface_link_ok(Index r, Index k, const std::vector<Index>& st_r, const std::vector<Index>& st_k) {
    gather(st_r, old_cells_, old_labels_);
    surface_link(old_cells_, old_labels_, r, link_r_);
    gather(st_k, old_cells_, old_labels_);
    surface_link(old_cells_, old_labels_, k, link_k_);
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
  bool curve_link_ok(Index r, Index k) {
    neighbors(r, nbr_);
    for (Index w : nbr_)
      if (w != k && is_feature(r, w) && is_feature(k, w)) return false;
    return true;
  }

  // Every input surface point that r and k stand for stays within the bound of the new surface
  // around k, and the new surface triangles stay within the bound of the input surface.  Both are
  // checked on samples (the input vertices; seven points per new triangle), against a margin of
  // `error_margin` times the bound, so that what the samples miss, and the points of other
  // vertices whose nearest triangle changes, stay within the bound (measured: `mesh_quality.h`).
  static constexpr double error_margin = 0.5;

  bool error_ok(Index r, Index k, bool move, const Vec3& p) {
    const double tol = error_margin * options_.max_boundary_error;
    if (!(tol < std::numeric_limits<double>::infinity())) return true;
    surface_link(new_cells_, new_labels_, k, link_k_);
    const Vec3& pk = move ? p : posd_[k];
    triangles_.clear();
    for (const auto& e : link_k_)
      triangles_.emplace_back(kpoint(pk), kpoint(posd_[e.first]), kpoint(posd_[e.second]));
    if (triangles_.empty()) return true; // no surface left around k: nothing to compare
    const double tol2 = tol * tol;
    if (dimension(r) <= 2 && !near_triangles(sid_[r], tol2)) return false;
    if (move && !near_triangles(sid_[k], tol2)) return false;
    for (std::size_t s : covered_[sid_[r]])
      if (!near_triangles(s, tol2)) return false;
    for (std::size_t s : covered_[sid_[k]])
      if (!near_triangles(s, tol2)) return false;
    // The other way: the new triangles around k, at their centroid, edge midpoints and the
    // midpoints between the centroid and the corners.
    for (const K::Triangle_3& tri : triangles_) {
      const K::Point_3 c = CGAL::centroid(tri);
      const auto closest = tree_of_surface_.closest_point_and_primitive(c);
      if (CGAL::squared_distance(c, closest.first) > tol2) return false;
      // No new crease: the triangle's normal within half the feature angle of the input
      // surface's normal there.
      if (max_normal_cosine_ > -1) {
        const K::Vector_3 n1 = CGAL::normal(tri[0], tri[1], tri[2]);
        const K::Vector_3 n2 = CGAL::normal((*closest.second)[0], (*closest.second)[1], (*closest.second)[2]);
        const double l = std::sqrt(n1.squared_length() * n2.squared_length());
        if (!(std::abs(n1 * n2) >= max_normal_cosine_ * l)) return false;
      }
      for (int i = 0; i < 3; ++i)
        if (tree_of_surface_.squared_distance(CGAL::midpoint(tri[i], tri[(i + 1) % 3])) > tol2 ||
            tree_of_surface_.squared_distance(CGAL::midpoint(tri[i], c)) > tol2)
          return false;
    }
    if (move && tree_of_surface_.squared_distance(kpoint(p)) > tol2) return false;
    if (!neighbours_error_ok(r, k, move, p, tol2)) return false;
    return dimension(r) > 1 || curve_error_ok(r, k);
  }

  // The input surface point of stable id `s` is within sqrt(tol2) of one of `triangles_`.
  bool near_triangles(std::size_t s, double tol2) const {
    const K::Point_3 q = kpoint(input_pos_[s]);
    for (const K::Triangle_3& tri : triangles_)
      if (CGAL::squared_distance(q, tri) <= tol2) return true;
    return false;
  }

  // The points of the surface neighbours w of r (and of k when it moves), whose own fans change,
  // stay within the bound of their fans after the collapse.
  bool neighbours_error_ok(Index r, Index k, bool move, const Vec3& p, double tol2) {
    affected_.clear();
    for (Index v : {r, k}) {
      if (v == k && !move) continue;
      gather(star(v), old_cells_, old_labels_);
      surface_link(old_cells_, old_labels_, v, link_r_);
      for (const auto& e : link_r_)
        for (Index w : {e.first, e.second})
          if (w != r && w != k && !covered_[sid_[w]].empty()) affected_.push_back(w);
    }
    sort_unique(affected_);
    for (Index w : affected_) {
      // The star of w after the collapse: St(e) gone, r renamed k.
      old_cells_.clear();
      old_labels_.clear();
      for (Index t : star(w)) {
        if (contains(work_[t], r) && contains(work_[t], k)) continue;
        Tetrahedron c = work_[t];
        for (Index& x : c)
          if (x == r) x = k;
        old_cells_.push_back(c);
        old_labels_.push_back(label_[t]);
      }
      surface_link(old_cells_, old_labels_, w, link_k_);
      triangles_.clear();
      auto at = [&](Index x) { return kpoint(x == k && move ? p : posd_[x]); };
      for (const auto& e : link_k_) triangles_.emplace_back(at(w), at(e.first), at(e.second));
      for (std::size_t s : covered_[sid_[w]])
        if (!near_triangles(s, tol2)) return false;
    }
    return true;
  }

  // The input feature vertices r and k stand for stay within a quarter of the bound of the
  // feature edges at k after the collapse.
  bool curve_error_ok(Index r, Index k) {
    const double tol = 0.25 * error_margin * options_.max_boundary_error;
    segments_.clear();
    neighbors(r, nbr_);
    for (Index w : nbr_)
      if (w != k && is_feature(r, w)) segments_.emplace_back(kpoint(posd_[k]), kpoint(posd_[w]));
    neighbors(k, nbr_);
    for (Index w : nbr_)
      if (w != r && is_feature(k, w)) segments_.emplace_back(kpoint(posd_[k]), kpoint(posd_[w]));
    auto near_curve = [&](std::size_t s) {
      if (constraints_.dimension[s] > 1) return true; // a surface point: checked above
      const K::Point_3 q = kpoint(input_pos_[s]);
      for (const K::Segment_3& e : segments_)
        if (CGAL::squared_distance(q, e) <= tol * tol) return true;
      return false;
    };
    if (!near_curve(sid_[r])) return false;
    for (std::size_t s : covered_[sid_[r]])
      if (!near_curve(s)) return false;
    for (std::size_t s : covered_[sid_[k]])
      if (!near_curve(s)) return false;
    return true;
  }

  // Half-edge collapse of r into k (k moved to p): delete St(e), rename r -> k in St(r) - St(e),
  // delete r.  The stars of the other vertices lose the deleted tetrahedra lazily (`star()`).
  void apply(Index r, Index k, bool move, const Vec3& p, const Point_3& pk, std::vector<Index>& st_r,
             std::vector<Index>& st_k) {
    neighbors(k, nbr_);
    old_k_nbr_.swap(nbr_);
    if (dimension(r) <= 1) { // the feature edges of r now end at k
      neighbors(r, nbr_);
      for (Index w : nbr_)
        if (w != k && is_feature(r, w)) {
          constraints_.features.erase(constraints_.edge_key(sid_[r], sid_[w]));
          constraints_.features.insert(constraints_.edge_key(sid_[k], sid_[w]));
        }
      constraints_.features.erase(constraints_.edge_key(sid_[r], sid_[k]));
    }
    for (Index t : st_e_) deleted_tet_[t] = 1;
    removed_ += st_e_.size();
    stats_->removed_tetrahedra += st_e_.size();
    ++stats_->collapses;
    for (Index t : st_r) {
      if (deleted_tet_[t]) continue;
      for (Index& w : work_[t])
        if (w == r) w = k;
      st_k.push_back(t);
      // (also when k is in the leaf: t may be in no list of k's leaf, and a later leaf may need St(k))
      extras_[k].push_back(t);
    }
    st_r.clear();
    deleted_vertex_[r] = 1;
    if (move) {
      pos_[k] = pk;
      posd_[k] = p;
    }
    if (!constraints_.quadrics.empty()) constraints_.quadrics[sid_[k]] += constraints_.quadrics[sid_[r]];
    if (dimension(r) <= 2 && options_.max_boundary_error < std::numeric_limits<double>::infinity()) {
      std::vector<std::size_t>& cov = covered_[sid_[k]];
      cov.push_back(sid_[r]);
      cov.insert(cov.end(), covered_[sid_[r]].begin(), covered_[sid_[r]].end());
      std::vector<std::size_t>().swap(covered_[sid_[r]]);
    }
    // New candidate edges: (k, w) for the neighbours w of r that were not neighbours of k (all of
    // them when k moved: their priority changed).
    neighbors(k, nbr_);
    for (Index w : nbr_) {
      if (!in_leaf(w) && !in_leaf(k)) continue;
      if (!move && std::binary_search(old_k_nbr_.begin(), old_k_nbr_.end(), w)) continue;
      if (short_enough(k, w)) push(k, w);
    }
  }

  Simplification_settings options_;
  Priority priority_;
  GeomTraits gt_;
  Simplification_statistics* stats_ = nullptr;
  std::vector<std::size_t>* tet_origin_ = nullptr;
  const std::vector<int>* labels_ = nullptr;
  std::size_t target_ = 0, removed_ = 0;
  double threshold_ = 0;
  // constraints (stable ids)
  std::vector<Vec3> input_pos_;
  Surface_constraints<std::size_t> constraints_;
  std::vector<std::vector<std::size_t>> covered_; // the input surface points a vertex stands for
  Triangle_list surface_;
  AABB_tree tree_of_surface_;
  double max_normal_cosine_ = -1; // cosine of half the feature angle (-1: no bound)
  // the round
  const Octree* tree_ = nullptr;
  std::vector<Vertex_type> types_;
  std::vector<Point_3> pos_;
  std::vector<Vec3> posd_;
  std::vector<std::size_t> sid_;
  std::vector<int> label_;
  Index vb_ = 0, ve_ = 0;
  std::vector<Tetrahedron> work_;
  std::vector<char> deleted_tet_, deleted_vertex_;
  std::vector<std::vector<Index>> stars_;
  std::unordered_map<Index, std::vector<Index>> outside_, extras_;
  std::vector<Index> st_e_, nbr_, old_k_nbr_, lv_r_, lv_k_, affected_;
  std::vector<Tetrahedron> new_cells_, changed_cells_, old_cells_;
  std::vector<int> new_labels_, old_labels_;
  std::vector<Face_record> faces_;
  std::vector<std::pair<Index, Index>> link_r_, link_k_;
  Triangle_list triangles_;
  std::vector<K::Segment_3> segments_;
  Edge_fan<Index> fan_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue_;
  Collapse_tester<GeomTraits, Index> tester_;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_LOCAL_SIMPLIFIER_H
