// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_ROUND_DRIVER_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_ROUND_DRIVER_H

// The rounds of the local half-edge-collapse simplification (paper Section 9): per-leaf queues on
// the PR-star octree of the current mesh, then compaction and a new octree.  The cost, the
// placement, the filter and the visitor are policies (see `simplify()`); the strata, orientation
// and link conditions are not.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/Index_arrays_input.h>
#include <CGAL/PR_star_octree/Leaf_executor.h>
#include <CGAL/PR_star_octree/Simplification_statistics.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/internal/Simplification/collapse_candidate.h>
#include <CGAL/PR_star_octree/internal/Simplification/collapse_queue.h>
#include <CGAL/PR_star_octree/internal/Simplification/compaction.h>
#include <CGAL/PR_star_octree/internal/Simplification/error_bound.h>
#include <CGAL/PR_star_octree/internal/Simplification/link_tests.h>
#include <CGAL/PR_star_octree/internal/Simplification/optimizer.h>
#include <CGAL/PR_star_octree/internal/Simplification/profiles.h>
#include <CGAL/PR_star_octree/internal/Simplification/quality_floor.h>
#include <CGAL/PR_star_octree/internal/Simplification/round_mesh.h>
#include <CGAL/PR_star_octree/internal/Simplification/settings.h>
#include <CGAL/PR_star_octree/internal/Simplification/strata_tests.h>
#include <CGAL/PR_star_octree/internal/collapse_tester.h>
#include <CGAL/PR_star_octree/internal/simplification_constraints.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

template <class GeomTraits, class Cost, class Placement, class Filter, class Visitor>
class Local_simplifier {
public:
  using Octree = PR_star_octree_3<GeomTraits>;
  using Index = typename Octree::Index;
  using Point_3 = typename GeomTraits::Point_3;
  using Mesh = Round_mesh<GeomTraits>;
  using Candidate = Collapse_candidate<GeomTraits>;
  using Profile = Collapse_profile<GeomTraits, Local_simplifier>;

  Local_simplifier(const Simplification_settings& settings, const Cost& cost, const Placement& placement,
                   const Filter& filter, Visitor& visitor, const GeomTraits& gt)
      : settings_(settings), cost_(cost), placement_(placement), filter_(filter), visitor_(visitor),
        gt_(gt), floors_{settings.min_dihedral, settings.max_dihedral, settings.min_radius_ratio},
        optimizer_(context_) {
    context_.mesh = &mesh_;
    context_.constraints = &constraints_;
    context_.error = &error_;
    context_.input_tet = &input_tet_;
    context_.sizing = &sizing_;
    context_.floors = floors_;
    context_.gt = gt_;
  }

  // Simplifies the mesh of `tree` (the octree of the input, destroyed on the way); `labels` (input
  // numbering, or empty) are the tetrahedron labels; `constrained_vertex(o)` and
  // `constrained_edge(o1, o2)` the user's constraints on input indices.  The result is in `out`.
  template <class ConstrainedVertex, class ConstrainedEdge>
  void run(std::optional<Octree>& tree, const std::vector<int>& labels, ConstrainedVertex constrained_vertex,
           ConstrainedEdge constrained_edge, Simplification_statistics& stats,
           Compact_mesh<GeomTraits>& out) {
    labels_ = &labels;
    stats_ = &stats;
    context_.stats = &stats.optimization;
    const std::size_t input_tets = tree->number_of_tetrahedra();
    target_ = settings_.target_fraction > 0
                  ? static_cast<std::size_t>(std::ceil(settings_.target_fraction * double(input_tets)))
                  : (std::numeric_limits<std::size_t>::max)();
    removed_ = 0;
    start_from(*tree, out);
    prepare_constraints(*tree, constrained_vertex, constrained_edge);
    bool all_candidates = false; // the round threshold is a length quantile until a round stalls
    stats.stop = Simplification_stop::NOTHING_LEFT;
    while (!target_reached()) {
      if (stats.rounds >= settings_.max_rounds) {
        stats.stop = Simplification_stop::MAX_ROUNDS;
        break;
      }
      double threshold = settings_.max_edge_length;
      bool quantile = false;
      if (settings_.target_fraction > 0 && !all_candidates) {
        const std::size_t nt = stats.rounds == 0 ? tree->number_of_tetrahedra() : out.tetrahedra.size();
        const double q = double(target_ - removed_) / double((std::max)(nt, std::size_t(1)));
        if (q < 1) {
          threshold =
              (std::min)(threshold, stats.rounds == 0 ? length_quantile(tree->points(), tree->tetrahedra(), q)
                                                      : length_quantile(out.points, out.tetrahedra, q));
          quantile = true;
        }
      }
      if (stats.rounds > 0) { // the octree of the current mesh
        tree.reset();
        tree.emplace(make_input(out.points, out.tetrahedra),
                     parameters::bucket_size(settings_.bucket_size).geom_traits(gt_));
      }
      ++stats.rounds;
      const std::size_t before = removed_;
      stats.blocked_last_round = Simplification_statistics::Blocked();
      visitor_.on_round_started(stats.rounds, tree->number_of_vertices(), tree->number_of_tetrahedra());
      round(*tree, threshold, out,
            settings_.optimization_rounds > 0 ? Leaf_work::COLLAPSE_AND_IMPROVE : Leaf_work::COLLAPSE);
      stats.removed_per_round.push_back(removed_ - before);
      visitor_.on_round_finished(stats.rounds, removed_ - before);
      if (removed_ == before) {
        if (quantile && threshold < settings_.max_edge_length) {
          all_candidates = true; // nothing short enough could go: try every edge under the bound
          continue;
        }
        stats.stop =
            settings_.target_fraction > 0 ? Simplification_stop::BLOCKED : Simplification_stop::NOTHING_LEFT;
        break;
      }
    }
    if (target_reached()) stats.stop = Simplification_stop::TARGET_REACHED;
    if (stats.rounds == 0) { // nothing done: the input as the octree has it
      out.points.assign(tree->points().begin(), tree->points().end());
      out.tetrahedra.assign(tree->tetrahedra().begin(), tree->tetrahedra().end());
      for (std::size_t v = 0; v < out.input_vertex.size(); ++v)
        out.input_vertex[v] = tree->original_vertex(static_cast<Index>(v));
      for (std::size_t t = 0; t < out.input_tetrahedron.size(); ++t)
        out.input_tetrahedron[t] = tree->original_tetrahedron(static_cast<Index>(t));
    }
    // Rounds of flips and smoothing only, on the octree of the simplified mesh.
    tree.reset(); // (the last collapse round's octree is not needed any more)
    for (std::size_t i = 0; i < settings_.optimization_rounds; ++i) {
      const Octree octree(make_input(out.points, out.tetrahedra),
                          parameters::bucket_size(settings_.bucket_size).geom_traits(gt_));
      ++stats.optimization.rounds;
      round(octree, 0, out, Leaf_work::IMPROVE);
    }
  }

  // Remeshes the mesh of `tree` (as `run()`) towards the target edge lengths `sizing` (input
  // numbering): rounds of splits, collapses, flips and smoothing leaf by leaf.
  template <class ConstrainedVertex, class ConstrainedEdge>
  void run_remesh(std::optional<Octree>& tree, const std::vector<int>& labels, std::vector<double> sizing,
                  ConstrainedVertex constrained_vertex, ConstrainedEdge constrained_edge,
                  Simplification_statistics& stats, Compact_mesh<GeomTraits>& out) {
    labels_ = &labels;
    stats_ = &stats;
    context_.stats = &stats.optimization;
    target_ = (std::numeric_limits<std::size_t>::max)();
    removed_ = 0;
    start_from(*tree, out);
    prepare_constraints(*tree, constrained_vertex, constrained_edge);
    sizing_.resize(sizing.size()); // by stable id: the index in the first round's octree
    for (std::size_t v = 0; v < sizing.size(); ++v)
      sizing_[v] = sizing[tree->original_vertex(static_cast<Index>(v))];
    stats.stop = Simplification_stop::NOTHING_LEFT;
    for (std::size_t i = 0; i < settings_.remesh_iterations; ++i) {
      if (i > 0) {
        tree.reset();
        tree.emplace(make_input(out.points, out.tetrahedra),
                     parameters::bucket_size(settings_.bucket_size).geom_traits(gt_));
      }
      ++stats.rounds;
      const auto& o = stats.optimization;
      const std::size_t changes_before = stats.collapses + o.splits + o.vertex_moves + o.flips_2_3 +
                                         o.flips_3_2 + o.flips_4_4 + o.edge_removals;
      const std::size_t removed_before = removed_;
      stats.blocked_last_round = Simplification_statistics::Blocked();
      round(*tree, 0, out, Leaf_work::REMESH);
      stats.removed_per_round.push_back(removed_ - removed_before);
      if (stats.collapses + o.splits + o.vertex_moves + o.flips_2_3 + o.flips_3_2 + o.flips_4_4 +
              o.edge_removals ==
          changes_before)
        break;
      if (i + 1 == settings_.remesh_iterations) stats.stop = Simplification_stop::MAX_ROUNDS;
    }
    if (stats.rounds == 0) { // no iteration asked: the input as the octree has it
      out.points.assign(tree->points().begin(), tree->points().end());
      out.tetrahedra.assign(tree->tetrahedra().begin(), tree->tetrahedra().end());
      for (std::size_t v = 0; v < out.input_vertex.size(); ++v)
        out.input_vertex[v] = tree->original_vertex(static_cast<Index>(v));
      for (std::size_t t = 0; t < out.input_tetrahedron.size(); ++t)
        out.input_tetrahedron[t] = tree->original_tetrahedron(static_cast<Index>(t));
    }
  }

  // The package's own tests, for the filter (see `Collapse_profile`).
  bool quality_ok(const Candidate& c) { return quality_(mesh_, c, floors_); }
  bool error_ok(const Candidate& c) {
    return !Error_bound<GeomTraits>::applies(mesh_, c) || error_(mesh_, c);
  }

private:
  // What a leaf does in a round.
  enum class Leaf_work { COLLAPSE, COLLAPSE_AND_IMPROVE, IMPROVE, REMESH };

  // The target is met, counting the tetrahedra flips added or removed.
  bool target_reached() const {
    if (target_ == (std::numeric_limits<std::size_t>::max)()) return false; // no target
    return static_cast<long long>(removed_) - context_.change >= static_cast<long long>(target_);
  }

  // The numbering of the input octree as a compact mesh without arrays (the first round uses it).
  void start_from(const Octree& tree, Compact_mesh<GeomTraits>& out) {
    const std::size_t nv = tree.number_of_vertices(), nt = tree.number_of_tetrahedra();
    out.input_vertex.resize(nv);
    out.sid.resize(nv);
    for (std::size_t v = 0; v < nv; ++v) {
      out.input_vertex[v] = v;
      out.sid[tree.original_vertex(static_cast<Index>(v))] = v;
    }
    out.input_tetrahedron.resize(nt);
    for (std::size_t t = 0; t < nt; ++t) out.input_tetrahedron[t] = t;
  }

  // The constraints, on the stable ids of the vertices (their index in the first round).
  template <class ConstrainedVertex, class ConstrainedEdge>
  void prepare_constraints(const Octree& tree, ConstrainedVertex constrained_vertex,
                           ConstrainedEdge constrained_edge) {
    input_pos_.resize(tree.number_of_vertices());
    for (std::size_t v = 0; v < input_pos_.size(); ++v) input_pos_[v] = to_vec3(gt_, tree.points()[v]);
    std::vector<int> tet_labels;
    if (!labels_->empty()) {
      tet_labels.resize(tree.number_of_tetrahedra());
      for (std::size_t t = 0; t < tet_labels.size(); ++t)
        tet_labels[t] = (*labels_)[tree.original_tetrahedron(static_cast<Index>(t))];
    }
    auto original = [&](std::size_t v) { return std::size_t(tree.original_vertex(static_cast<Index>(v))); };
    compute_surface_constraints(
        input_pos_, tree.tetrahedra(), tet_labels, settings_.feature_angle, settings_.with_quadrics,
        [&](std::size_t v) { return constrained_vertex(original(v)); },
        [&](std::size_t a, std::size_t b) { return constrained_edge(original(a), original(b)); },
        constraints_);
    error_.initialize(input_pos_, constraints_, settings_.feature_angle, settings_.max_boundary_error);
    // The labels' volumes and surface areas of the input, to give the labels their volume back.
    input_volumes_.clear();
    surface_offset_.clear();
    label_areas_ = label_surface_areas(input_pos_, tree.tetrahedra(), tet_labels);
    std::size_t t = 0;
    for (auto it = tree.tetrahedra().begin(); t < tree.number_of_tetrahedra(); ++it, ++t) {
      const auto c = *it;
      const Vec3 &p = input_pos_[c[0]], &q = input_pos_[c[1]], &r = input_pos_[c[2]], &s = input_pos_[c[3]];
      input_volumes_[tet_labels.empty() ? 0 : tet_labels[t]] +=
          dot(minus(q, p), cross(minus(r, p), minus(s, p))) / 6;
    }
  }

  // The offset of each label's surface from the input surface that gives it its volume back (see
  // `Local_optimizer`), corrected by the drift of the volume where it is over a hundredth of a
  // percent; with an error bound only (the surface may not move without).
  void measure_drift() {
    context_.drift.clear();
    if (settings_.optimization_rounds == 0 && !settings_.remesh) return;
    if (!error_.bounded()) return;
    for (const auto& lv : label_volumes(mesh_)) {
      const auto v0 = input_volumes_.find(lv.first);
      const auto a = label_areas_.find(lv.first);
      if (v0 == input_volumes_.end() || a == label_areas_.end() || !(a->second > 0)) continue;
      // (accumulated: the moves put the surface vertices at this offset from the input surface)
      double& offset = surface_offset_[lv.first];
      if (std::abs(v0->second - lv.second) > 1e-4 * std::abs(v0->second))
        offset += (v0->second - lv.second) / a->second;
      if (offset != 0) context_.drift[lv.first] = offset;
    }
  }

  // A deterministic sample of edge lengths (at most ~100K) and its q-quantile.
  template <class Points, class Tetrahedra>
  double length_quantile(const Points& points, const Tetrahedra& tets, double q) const {
    auto squared_distance = gt_.compute_squared_distance_3_object();
    std::vector<double> lengths;
    const std::size_t stride = (std::max)(std::size_t(1), tets.size() / 16384);
    for (std::size_t t = 0; t < tets.size(); t += stride) {
      const auto c = tets[t];
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
          lengths.push_back(std::sqrt(CGAL::to_double(squared_distance(points[c[i]], points[c[j]]))));
    }
    if (lengths.empty()) return 0;
    const std::size_t k =
        (std::min)(lengths.size() - 1, static_cast<std::size_t>(q * double(lengths.size())));
    std::nth_element(lengths.begin(), lengths.begin() + k, lengths.end());
    // strictly shorter than the threshold: take the next representable value
    return std::nextafter(lengths[k], std::numeric_limits<double>::infinity());
  }

  // The mesh of the round, in the numbering of its octree.
  void load_round(const Octree& tree, const Compact_mesh<GeomTraits>& cur) {
    mesh_.tree = &tree;
    mesh_.constraints = &constraints_;
    classify_vertices<CGAL::Parallel_if_available_tag>(
        tree, false, mesh_.types, [](Index, int) {}, parameters::default_values());
    mesh_.pos.assign(tree.points().begin(), tree.points().end());
    const std::size_t nv = mesh_.pos.size(), nt = tree.number_of_tetrahedra();
    mesh_.posd.resize(nv);
    mesh_.sid.resize(nv);
    mesh_.input_vertex.resize(nv);
    for (std::size_t v = 0; v < nv; ++v) {
      const std::size_t o = tree.original_vertex(static_cast<Index>(v));
      mesh_.posd[v] = to_vec3(gt_, mesh_.pos[v]);
      mesh_.sid[v] = cur.sid[o];
      mesh_.input_vertex[v] = cur.input_vertex[o];
    }
    mesh_.work.assign(tree.tetrahedra().begin(), tree.tetrahedra().end());
    input_tet_.resize(nt);
    mesh_.label.assign(nt, 0);
    for (std::size_t t = 0; t < nt; ++t) {
      input_tet_[t] = cur.input_tetrahedron[tree.original_tetrahedron(static_cast<Index>(t))];
      if (!labels_->empty()) mesh_.label[t] = (*labels_)[input_tet_[t]];
    }
    mesh_.deleted_tet.assign(nt, 0);
    mesh_.deleted_vertex.assign(nv, 0);
  }

  void round(const Octree& tree, double threshold, Compact_mesh<GeomTraits>& out, Leaf_work work) {
    threshold_ = threshold;
    load_round(tree, out);
    measure_drift();
    // The leaves one after the other (each change changes the mesh the next leaves see), until
    // the target is reached.
    Leaf_executor<CGAL::Sequential_tag>().for_each(
        tree, VERTEX_TETRAHEDRA, 0,
        [&](int, const Leaf_topology<Octree>& local) {
          mesh_.enter_leaf(local);
          switch (work) {
          case Leaf_work::COLLAPSE:
            simplify_leaf();
            break;
          case Leaf_work::COLLAPSE_AND_IMPROVE:
            simplify_leaf();
            optimizer_.optimize_leaf(false);
            break;
          case Leaf_work::IMPROVE:
            optimizer_.optimize_leaf(false);
            break;
          case Leaf_work::REMESH:
            optimizer_.split_long_edges();
            simplify_leaf();
            optimizer_.optimize_leaf(true);
            break;
          }
        },
        internal::No_progress(), [&] { return work != Leaf_work::IMPROVE && target_reached(); });
    queue_.clear();
    mesh_.end_round();
    compact(mesh_, input_tet_, out);
  }

  // The collapses of the leaf of the round's octree the mesh is in.
  void simplify_leaf() {
    // Candidate edges: at least one end in the leaf, short enough.
    queue_.clear();
    for (Index v = mesh_.vb; v < mesh_.ve; ++v) {
      mesh_.neighbors(v, nbr_);
      for (Index w : nbr_)
        if ((w > v || !mesh_.in_leaf(w)) && short_enough(v, w)) push(v, w);
    }
    while (!queue_.empty() && !target_reached()) {
      const auto e = queue_.pop();
      if (mesh_.deleted_vertex[e.a] || mesh_.deleted_vertex[e.b]) continue;
      if (cost(e.a, e.b) != e.cost) { // the neighbourhood changed the cost: queue it again
        push(e.a, e.b);
        continue;
      }
      collapse_edge(e.a, e.b);
    }
  }

  bool short_enough(Index a, Index b) const {
    if (settings_.remesh) return optimizer_.relative_length(a, b) < 0.8;
    if (!(threshold_ < std::numeric_limits<double>::infinity())) return true;
    return CGAL::to_double(gt_.compute_squared_distance_3_object()(mesh_.pos[a], mesh_.pos[b])) <
           threshold_ * threshold_;
  }

  double cost(Index a, Index b) const { return cost_(Edge_profile<GeomTraits>(mesh_, gt_, a, b)); }

  void push(Index a, Index b) {
    if (b < a) std::swap(a, b);
    queue_.push(a, b, cost(a, b));
    stats_->max_queue_size = (std::max)(stats_->max_queue_size, queue_.size());
  }

  // Tries the collapses of the edge (a, b) allowed by the strata and the leaf, the placement's
  // point first, and applies the first one that passes every check.
  void collapse_edge(Index a, Index b) {
    const Edge_profile<GeomTraits> edge(mesh_, gt_, a, b);
    struct Option {
      Index r, k;
      bool move;
      Vec3 p;
    };
    Option options[3];
    int n = 0;
    if (mesh_.in_leaf(a) && mesh_.in_leaf(b))
      if (const std::optional<Point_3> p = placement_(edge))
        options[n++] = Option{b, a, true, to_vec3(gt_, *p)};
    const bool b_first = placement_.remove_v1_first(edge);
    for (int pass = 0; pass < 2; ++pass) {
      const bool remove_b = (pass == 0) == b_first;
      const Index r = remove_b ? b : a, k = remove_b ? a : b;
      if (mesh_.in_leaf(r) && removable_into(mesh_, r, k)) options[n++] = Option{r, k, false, mesh_.posd[k]};
    }
    if (n == 0) { // a corner or a higher stratum, or the removable end in another leaf
      const bool elsewhere = (!mesh_.in_leaf(a) && removable_into(mesh_, a, b)) ||
                             (!mesh_.in_leaf(b) && removable_into(mesh_, b, a));
      refused(edge, elsewhere ? Collapse_refusal::DIFFERENT_LEAVES : Collapse_refusal::FEATURE);
      return;
    }
    Collapse_refusal first = Collapse_refusal::NONE;
    for (int i = 0; i < n; ++i) {
      const Refusal why = try_collapse(options[i].r, options[i].k, options[i].move, options[i].p);
      if (why.accepted() || why.gone) return;
      if (i == 0) first = why.why;
    }
    refused(edge, first);
  }

  // Remeshing: the collapse would make an edge longer than 4/3 of its target.
  bool creates_long_edge(const Candidate& c) {
    mesh_.neighbors(c.r, long_nbr_);
    for (Index w : long_nbr_) {
      if (w == c.k) continue;
      const double h = 0.5 * (sizing_[mesh_.sid[c.k]] + sizing_[mesh_.sid[w]]);
      if (norm(minus(c.p, mesh_.posd[w])) > 4. / 3 * h) return true;
    }
    return false;
  }

  void refused(const Edge_profile<GeomTraits>& edge, Collapse_refusal why) {
    count_refusal(why, stats_->blocked);
    count_refusal(why, stats_->blocked_last_round);
    visitor_.on_refused(edge, why);
  }

  // The collapse of r into k, k moving to p when `move`: the mandatory checks, then the filter.
  Refusal try_collapse(Index r, Index k, bool move, const Vec3& p) {
    Candidate& c = candidate_;
    c.r = r;
    c.k = k;
    c.move = move;
    c.p = p;
    c.st_r = &mesh_.star(r);
    Collapse_tester<GeomTraits, Index>::edge_star(mesh_.work, *c.st_r, k, c.st_e);
    if (c.st_e.empty()) return Refusal::edge_gone();
    c.st_k = &mesh_.star(k);
    c.dr = mesh_.dimension(r);
    // Strata: a feature-curve vertex moves along a feature edge, a surface vertex along the surface.
    const Collapse_refusal strata = strata_(mesh_, c.st_e, r, k);
    if (strata != Collapse_refusal::NONE) return Refusal{strata};
    // (remeshing: the cheap length check before the orientation and link tests)
    if (settings_.remesh && creates_long_edge(c)) return Refusal{Collapse_refusal::QUALITY};
    // Geometry: exact orientation of the new tetrahedra.
    c.pk = move ? make_point<Point_3>(p) : mesh_.pos[k];
    c.make_new_cells(mesh_);
    if (!c.positive(gt_, mesh_)) return Refusal{Collapse_refusal::FLIP};
    // Topology: the link condition of the volume (boundary coned), of the surface and of the curves.
    if (!links_(mesh_, *c.st_r, *c.st_k, c.st_e, r, k, c.dr)) return Refusal{Collapse_refusal::LINK};
    const Profile profile(mesh_, gt_, c, *this);
    const Collapse_refusal filtered = filter_(profile);
    if (filtered != Collapse_refusal::NONE) return Refusal{filtered};
    visitor_.on_collapse(profile);
    apply(c);
    return Refusal();
  }

  // Half-edge collapse of r into k (k moved to p): delete St(e), rename r -> k in St(r) - St(e),
  // delete r.  The stars of the other vertices lose the deleted tetrahedra lazily (`star()`).
  void apply(Candidate& c) {
    const Index r = c.r, k = c.k;
    mesh_.neighbors(k, nbr_);
    old_k_nbr_.swap(nbr_);
    if (mesh_.dimension(r) <= 1) { // the feature edges of r now end at k
      mesh_.neighbors(r, nbr_);
      for (Index w : nbr_)
        if (w != k && mesh_.is_feature(r, w)) {
          constraints_.features.erase(constraints_.edge_key(mesh_.sid[r], mesh_.sid[w]));
          constraints_.features.insert(constraints_.edge_key(mesh_.sid[k], mesh_.sid[w]));
        }
      constraints_.features.erase(constraints_.edge_key(mesh_.sid[r], mesh_.sid[k]));
    }
    for (Index t : c.st_e) mesh_.deleted_tet[t] = 1;
    removed_ += c.st_e.size();
    stats_->removed_tetrahedra += c.st_e.size();
    ++stats_->collapses;
    for (Index t : *c.st_r) {
      if (mesh_.deleted_tet[t]) continue;
      for (Index& w : mesh_.work[t])
        if (w == r) w = k;
      c.st_k->push_back(t);
      // (also when k is in the leaf: t may be in no list of k's leaf, and a later leaf may need St(k))
      mesh_.add_to_star(k, t);
    }
    c.st_r->clear();
    mesh_.deleted_vertex[r] = 1;
    if (c.move) {
      mesh_.pos[k] = c.pk;
      mesh_.posd[k] = c.p;
      error_.moved(mesh_, k);
    }
    if (!constraints_.quadrics.empty())
      constraints_.quadrics[mesh_.sid[k]] += constraints_.quadrics[mesh_.sid[r]];
    error_.merge(mesh_, r, k);
    // New candidate edges: (k, w) for the neighbours w of r that were not neighbours of k (all of
    // them when k moved: their cost changed).
    mesh_.neighbors(k, nbr_);
    for (Index w : nbr_) {
      if (!mesh_.in_leaf(w) && !mesh_.in_leaf(k)) continue;
      if (!c.move && std::binary_search(old_k_nbr_.begin(), old_k_nbr_.end(), w)) continue;
      if (short_enough(k, w)) push(k, w);
    }
  }

  Simplification_settings settings_;
  Cost cost_;
  Placement placement_;
  Filter filter_;
  Visitor& visitor_;
  GeomTraits gt_;
  Simplification_statistics* stats_ = nullptr;
  const std::vector<int>* labels_ = nullptr;
  std::size_t target_ = 0, removed_ = 0;
  double threshold_ = 0;
  std::vector<Vec3> input_pos_; // the input points, by stable id
  Surface_constraints<std::size_t> constraints_;
  Error_bound<GeomTraits> error_;
  Mesh mesh_;
  std::vector<std::size_t> input_tet_; // the input index of each tetrahedron of the round
  Candidate candidate_;
  std::vector<Index> nbr_, old_k_nbr_;
  Collapse_queue<Index> queue_;
  Strata_test<Index> strata_;
  Link_tests<GeomTraits, Index> links_;
  Quality_floor_test<GeomTraits> quality_;
  Quality_floors floors_;
  std::vector<double> sizing_; // remeshing: the target edge length by stable id
  std::vector<Index> long_nbr_;
  std::map<int, double> input_volumes_, label_areas_, surface_offset_;
  typename Local_optimizer<GeomTraits>::Context context_;
  Local_optimizer<GeomTraits> optimizer_;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_ROUND_DRIVER_H
