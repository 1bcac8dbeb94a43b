// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_OPTIMIZER_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_OPTIMIZER_H

// The local improvement of the mesh of a round, leaf by leaf: topological flips (2-3, and the
// removal of an edge in three to seven tetrahedra, which is 3-2 and 4-4 among others), vertex
// smoothing (interior, on the input surface, along feature curves) and, for remeshing, edge splits.
// Every change is checked with the exact `Orientation_3` of the traits, keeps the strata (flips
// never touch the surface or a label interface; moves stay on their stratum), the quality floors
// and the error bound.

#include <CGAL/PR_star_octree/Simplification_statistics.h>
#include <CGAL/PR_star_octree/internal/Simplification/collapse_candidate.h>
#include <CGAL/PR_star_octree/internal/Simplification/error_bound.h>
#include <CGAL/PR_star_octree/internal/Simplification/quality_floor.h>
#include <CGAL/PR_star_octree/internal/Simplification/round_mesh.h>
#include <CGAL/PR_star_octree/internal/Simplification/settings.h>
#include <CGAL/PR_star_octree/internal/simplification_constraints.h>
#include <CGAL/enum.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

// The volume of each label (all 0 without labels) of the tetrahedra not deleted.
template <class Mesh>
std::map<int, double> label_volumes(const Mesh& mesh) {
  std::map<int, double> v;
  for (std::size_t t = 0; t < mesh.work.size(); ++t) {
    if (mesh.deleted_tet[t]) continue;
    const auto& c = mesh.work[t];
    const Vec3 &p = mesh.posd[c[0]], &q = mesh.posd[c[1]], &r = mesh.posd[c[2]], &s = mesh.posd[c[3]];
    v[mesh.label[t]] += dot(minus(q, p), cross(minus(r, p), minus(s, p))) / 6;
  }
  return v;
}

// The area of the surface of each label: its boundary triangles and those it shares with another
// label (each side counts it).
template <class Tetrahedra>
std::map<int, double> label_surface_areas(const std::vector<Vec3>& points, const Tetrahedra& tets,
                                          const std::vector<int>& labels) {
  struct Face {
    std::array<std::size_t, 3> v;
    int label;
    bool operator<(const Face& o) const { return v < o.v; }
  };
  std::vector<Face> faces;
  faces.reserve(4 * tets.size());
  std::size_t t = 0;
  for (auto it = tets.begin(); it != tets.end(); ++it, ++t) { // (iterators decode in one pass)
    const auto c = *it;
    for (int k = 0; k < 4; ++k) {
      Face f{{{std::size_t(c[(k + 1) % 4]), std::size_t(c[(k + 2) % 4]), std::size_t(c[(k + 3) % 4])}},
             labels.empty() ? 0 : labels[t]};
      std::sort(f.v.begin(), f.v.end());
      faces.push_back(f);
    }
  }
  std::sort(faces.begin(), faces.end());
  std::map<int, double> area;
  auto add = [&](const Face& f) {
    area[f.label] +=
        0.5 * norm(cross(minus(points[f.v[1]], points[f.v[0]]), minus(points[f.v[2]], points[f.v[0]])));
  };
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i;
    while (j < faces.size() && faces[j].v == faces[i].v) ++j;
    if (j - i == 1)
      add(faces[i]);
    else if (j - i == 2 && faces[i].label != faces[i + 1].label) {
      add(faces[i]);
      add(faces[i + 1]);
    }
    i = j;
  }
  return area;
}

template <class GeomTraits>
class Local_optimizer {
public:
  using Mesh = Round_mesh<GeomTraits>;
  using Index = typename Mesh::Index;
  using Point_3 = typename Mesh::Point_3;
  using Tetrahedron = typename Mesh::Tetrahedron;
  using Stats = Simplification_statistics::Optimization;

  // A tetrahedron whose score is under this is worth a flip or a move when only the bad ones are
  // improved (simplification): about 25 degrees of smallest dihedral angle, 140 of largest, or a
  // radius ratio of 0.35.
  static constexpr double bad_score = 0.35;

  // What the optimiser works on (the round driver's state).
  struct Context {
    Mesh* mesh = nullptr;
    Surface_constraints<std::size_t>* constraints = nullptr;
    Error_bound<GeomTraits>* error = nullptr;
    std::vector<std::size_t>* input_tet = nullptr; // the input tetrahedron of each tetrahedron
    std::vector<double>* sizing = nullptr;         // the target edge length by stable id (remeshing)
    Stats* stats = nullptr;
    Quality_floors floors;
    GeomTraits gt;
    // The offset from the input surface, along its outward normal, at which the surface vertices
    // of each label give it its input volume back (the volume lost or gained over its area, summed
    // over the rounds); empty: no label drifted.
    std::map<int, double> drift;
    long long change = 0; // tetrahedra added minus tetrahedra removed by flips and splits
  };

  explicit Local_optimizer(Context& context) : c_(context) {}

  // Flips around the bad tetrahedra of the leaf (all of them with `all`), then smooths the leaf's
  // vertices (those with a bad tetrahedron around, or all).
  void optimize_leaf(bool all) {
    Mesh& mesh = *c_.mesh;
    // The tetrahedra around the leaf's vertices, worst first.
    bad_.clear();
    for (Index v = mesh.vb; v < mesh.ve; ++v) {
      if (mesh.deleted_vertex[v]) continue;
      for (Index t : mesh.star(v)) {
        const double s = score(mesh.work[t]);
        if (s < bad_score) bad_.emplace_back(s, t);
      }
    }
    std::sort(bad_.begin(), bad_.end());
    bad_.erase(std::unique(bad_.begin(), bad_.end()), bad_.end());
    for (const auto& st : bad_)
      if (!mesh.deleted_tet[st.second]) improve_tetrahedron(st.second);
    for (Index v = mesh.vb; v < mesh.ve; ++v)
      if (!mesh.deleted_vertex[v]) smooth(v, all || (!c_.drift.empty() && mesh.dimension(v) == 2));
  }

  // Splits, longest first, the edges with an end in the leaf longer than 4/3 of their target.
  void split_long_edges() {
    Mesh& mesh = *c_.mesh;
    std::priority_queue<std::pair<double, std::pair<Index, Index>>> queue;
    auto push_if_long = [&](Index a, Index b) {
      const double r = relative_length(a, b);
      if (r > 4. / 3) queue.push({r, {a, b}});
    };
    for (Index v = mesh.vb; v < mesh.ve; ++v) {
      if (mesh.deleted_vertex[v]) continue;
      mesh.neighbors(v, nbr_);
      for (Index w : nbr_)
        if (w > v || !mesh.in_leaf(w)) push_if_long(v, w);
    }
    while (!queue.empty()) {
      const auto e = queue.top();
      queue.pop();
      const Index a = e.second.first, b = e.second.second;
      if (mesh.deleted_vertex[a] || mesh.deleted_vertex[b]) continue;
      const Index m = split(a, b);
      if (m == none) continue;
      mesh.neighbors(m, nbr_);
      for (Index w : nbr_)
        if (mesh.in_leaf(w)) push_if_long(w, m);
    }
  }

  // The length of the edge (a, b) over its target (the mean of its ends').
  double relative_length(Index a, Index b) const {
    const Mesh& mesh = *c_.mesh;
    const double h = 0.5 * ((*c_.sizing)[mesh.sid[a]] + (*c_.sizing)[mesh.sid[b]]);
    return norm(minus(mesh.posd[a], mesh.posd[b])) / h;
  }

private:
  static constexpr Index none = (std::numeric_limits<Index>::max)();

  struct Plan {
    std::vector<Index> old;
    std::vector<Tetrahedron> cells;
    double score = -1;
    int kind = 0; // 2: 2-3, 3: 3-2, 4: 4-4, 5: edge removal of 5 to 7
  };

  double score(const Tetrahedron& c, Index moved = none, const Vec3* p = nullptr) const {
    const Mesh& mesh = *c_.mesh;
    const Vec3* v[4];
    for (int i = 0; i < 4; ++i) v[i] = c[i] == moved ? p : &mesh.posd[c[i]];
    // An inverted or flat tetrahedron (in doubles) is worse than any valid one.
    if (!(dot(minus(*v[1], *v[0]), cross(minus(*v[2], *v[0]), minus(*v[3], *v[0]))) > 0)) return -1;
    return Tetrahedron_shape::of(*v[0], *v[1], *v[2], *v[3]).score();
  }

  bool positive(const Tetrahedron& c, Index moved = none, const Point_3* p = nullptr) const {
    const Mesh& mesh = *c_.mesh;
    const Point_3* q[4];
    for (int i = 0; i < 4; ++i) q[i] = c[i] == moved ? p : &mesh.pos[c[i]];
    return c_.gt.orientation_3_object()(*q[0], *q[1], *q[2], *q[3]) == CGAL::POSITIVE;
  }

  // Whether `tuple` is an even permutation of the vertices of `stored`.
  static bool even_permutation(const Tetrahedron& stored, const std::array<Index, 4>& tuple) {
    int pos[4] = {0, 0, 0, 0};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        if (stored[j] == tuple[i]) pos[i] = j;
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) inversions += pos[i] > pos[j];
    return inversions % 2 == 0;
  }

  bool has_edge(Index a, Index b) {
    c_.mesh->neighbors(a, tmp_);
    return std::binary_search(tmp_.begin(), tmp_.end(), b);
  }

  void refuse(Simplification_statistics::Blocked& b, Collapse_refusal why) { count_refusal(why, b); }

  // The best flip among the removals of the edges of t and the 2-3 flips of its faces, if it
  // raises the worst score of its region.
  void improve_tetrahedron(Index t) {
    Mesh& mesh = *c_.mesh;
    const Tetrahedron c = mesh.work[t];
    Plan best;
    Collapse_refusal first = Collapse_refusal::NONE;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        if (!mesh.in_leaf(c[i]) && !mesh.in_leaf(c[j])) continue;
        const Collapse_refusal why = edge_removal(c[i], c[j], plan_);
        if (why == Collapse_refusal::NONE) {
          if (plan_.score > best.score) std::swap(best, plan_);
        } else if (first == Collapse_refusal::NONE)
          first = why;
      }
    for (int i = 0; i < 4; ++i) {
      const Collapse_refusal why = face_flip(t, i, plan_);
      if (why == Collapse_refusal::NONE) {
        if (plan_.score > best.score) std::swap(best, plan_);
      } else if (first == Collapse_refusal::NONE)
        first = why;
    }
    if (best.score < 0) {
      if (first != Collapse_refusal::NONE) refuse(c_.stats->refused_flips, first);
      return;
    }
    apply(best);
  }

  Region_quality region(const std::vector<Index>& tets) {
    cells_.clear();
    for (Index t : tets) cells_.push_back(c_.mesh->work[t]);
    return region_quality(*c_.mesh, cells_, none, origin_, c_.floors);
  }

  // The removal of the edge (a, b) (inside one label, not on the surface, in 3 to 7 tetrahedra):
  // the triangulation of its ring that maximises the worst score (dynamic programming over the
  // polygon), two tetrahedra per triangle.
  Collapse_refusal edge_removal(Index a, Index b, Plan& plan) {
    Mesh& mesh = *c_.mesh;
    if (mesh.is_feature(a, b)) return Collapse_refusal::FEATURE;
    st_e_.clear();
    for (Index t : mesh.star(a))
      if (contains(mesh.work[t], b)) st_e_.push_back(t);
    const std::size_t n = st_e_.size();
    if (n < 3) return Collapse_refusal::BOUNDARY;
    if (n > 7) return Collapse_refusal::QUALITY; // (not tried: too many tetrahedra around)
    for (Index t : st_e_)
      if (mesh.label[t] != mesh.label[st_e_[0]]) return Collapse_refusal::BOUNDARY;
    // The ring, oriented so that (a, b, r_i, r_i+1) is positive.
    pairs_.clear();
    for (Index t : st_e_) {
      std::array<Index, 2> o{};
      int k = 0;
      for (Index w : mesh.work[t])
        if (w != a && w != b) o[k++] = w;
      if (!even_permutation(mesh.work[t], {{a, b, o[0], o[1]}})) std::swap(o[0], o[1]);
      pairs_.push_back(o);
    }
    // (each tetrahedron once: an open fan, the edge on the boundary, or a pinched one fails)
    ring_.assign(1, pairs_[0][0]);
    ring_.push_back(pairs_[0][1]);
    used_.assign(n, 0);
    used_[0] = 1;
    for (std::size_t step = 1; step < n; ++step) {
      std::size_t next = n;
      for (std::size_t i = 0; i < n; ++i)
        if (!used_[i] && pairs_[i][0] == ring_.back()) next = i;
      if (next == n) return Collapse_refusal::BOUNDARY;
      used_[next] = 1;
      if (step + 1 < n)
        ring_.push_back(pairs_[next][1]);
      else if (pairs_[next][1] != ring_[0])
        return Collapse_refusal::BOUNDARY;
    }
    const double before = region(st_e_).score;
    // The best triangulation, first with any diagonal; the existing edges between ring vertices
    // (no new edge may be one) are looked for only when it would be better.
    exists_.assign(n * n, 0);
    triangulate(a, b, n);
    if (!(best_[n - 1] > before)) return Collapse_refusal::QUALITY;
    bool any = false;
    for (std::size_t i = 0; i < n; ++i) {
      mesh.neighbors(ring_[i], tmp_);
      for (std::size_t k = 0; k < n; ++k)
        if (k != i && (k + 1) % n != i && (i + 1) % n != k &&
            std::binary_search(tmp_.begin(), tmp_.end(), ring_[k])) {
          exists_[i * n + k] = 1;
          any = true;
        }
    }
    if (any) triangulate(a, b, n);
    if (!(best_[n - 1] >= 0)) return Collapse_refusal::LINK;
    if (!(best_[n - 1] > before)) return Collapse_refusal::QUALITY;
    plan.old = st_e_;
    plan.cells.clear();
    std::vector<std::pair<std::size_t, std::size_t>> todo{{0, n - 1}};
    while (!todo.empty()) {
      const auto ij = todo.back();
      todo.pop_back();
      if (ij.second - ij.first < 2) continue;
      const std::size_t k = apex_[ij.first * n + ij.second];
      plan.cells.push_back(Tetrahedron{{ring_[ij.first], ring_[k], ring_[ij.second], b}});
      plan.cells.push_back(Tetrahedron{{ring_[ij.first], ring_[ij.second], ring_[k], a}});
      todo.push_back({ij.first, k});
      todo.push_back({k, ij.second});
    }
    plan.kind = n == 3 ? 3 : n == 4 ? 4 : 5;
    return finish(plan, before);
  }

  // best_[i n + j]: the best worst score of the triangulations of the polygon r_i..r_j of the ring
  // of the edge (a, b) (i < j; -1: none, every one using an existing edge), its apex in apex_.
  void triangulate(Index a, Index b, std::size_t n) {
    auto diagonal_ok = [&](std::size_t i, std::size_t k) {
      const bool side = k == i + 1 || (i == 0 && k == n - 1);
      return side || !exists_[i * n + k];
    };
    best_.assign(n * n, std::numeric_limits<double>::infinity());
    apex_.assign(n * n, 0);
    for (std::size_t len = 2; len < n; ++len)
      for (std::size_t i = 0; i + len < n; ++i) {
        const std::size_t j = i + len;
        double value = -1;
        std::size_t arg = 0;
        if (diagonal_ok(i, j))
          for (std::size_t k = i + 1; k < j; ++k) {
            if (!diagonal_ok(i, k) || !diagonal_ok(k, j)) continue;
            const double s = (std::min)({best_[i * n + k], best_[k * n + j],
                                         score(Tetrahedron{{ring_[i], ring_[k], ring_[j], b}}),
                                         score(Tetrahedron{{ring_[i], ring_[j], ring_[k], a}})});
            if (s > value) {
              value = s;
              arg = k;
            }
          }
        best_[i * n + j] = value;
        apex_[i * n + j] = arg;
      }
  }

  // The 2-3 flip of the face of t opposite its vertex `i`, shared with another tetrahedron of the
  // same label.
  Collapse_refusal face_flip(Index t, int i, Plan& plan) {
    Mesh& mesh = *c_.mesh;
    const Tetrahedron& c = mesh.work[t];
    const Index d = c[i];
    Index f[3];
    int k = 0;
    for (int j = 0; j < 4; ++j)
      if (j != i) f[k++] = c[j];
    if (!mesh.in_leaf(d) && !mesh.in_leaf(f[0]) && !mesh.in_leaf(f[1]) && !mesh.in_leaf(f[2]))
      return Collapse_refusal::DIFFERENT_LEAVES;
    Index other = none;
    for (Index u : mesh.star(f[0]))
      if (u != t && contains(mesh.work[u], f[1]) && contains(mesh.work[u], f[2])) other = u;
    if (other == none || mesh.label[other] != mesh.label[t]) return Collapse_refusal::BOUNDARY;
    const Tetrahedron& o = mesh.work[other];
    Index e = o[0];
    int pe = 0;
    for (int j = 0; j < 4; ++j)
      if (!contains(c, o[j])) {
        e = o[j];
        pe = j;
      }
    if (has_edge(d, e)) return Collapse_refusal::LINK;
    // (x, y, z, e) positive: o with e moved last (3 - pe transpositions).
    std::array<Index, 3> xyz{};
    k = 0;
    for (int j = 0; j < 4; ++j)
      if (j != pe) xyz[k++] = o[j];
    if ((3 - pe) % 2 == 1) std::swap(xyz[0], xyz[1]);
    plan.old.assign({t, other});
    const double before = region(plan.old).score;
    plan.cells.assign({Tetrahedron{{d, e, xyz[0], xyz[1]}}, Tetrahedron{{d, e, xyz[1], xyz[2]}},
                       Tetrahedron{{d, e, xyz[2], xyz[0]}}});
    plan.kind = 2;
    return finish(plan, before);
  }

  // The checks common to the flips: better in doubles, positive (exact), the floors.
  Collapse_refusal finish(Plan& plan, double before) {
    const Region_quality after = region_quality(*c_.mesh, plan.cells, none, origin_, c_.floors);
    if (!(after.score > before)) return Collapse_refusal::QUALITY;
    for (const Tetrahedron& c : plan.cells)
      if (!positive(c)) return Collapse_refusal::FLIP;
    if (!after.allowed_after(region(plan.old), c_.floors)) return Collapse_refusal::QUALITY;
    plan.score = after.score - before;
    return Collapse_refusal::NONE;
  }

  void apply(const Plan& plan) {
    Mesh& mesh = *c_.mesh;
    const int lab = mesh.label[plan.old[0]];
    const std::size_t input = (*c_.input_tet)[plan.old[0]];
    for (Index t : plan.old) mesh.deleted_tet[t] = 1;
    for (const Tetrahedron& c : plan.cells) {
      mesh.add_tetrahedron(c, lab);
      c_.input_tet->push_back(input);
    }
    c_.change += static_cast<long long>(plan.cells.size()) - static_cast<long long>(plan.old.size());
    Stats& s = *c_.stats;
    s.tetrahedra_added += plan.cells.size();
    s.tetrahedra_deleted += plan.old.size();
    (plan.kind == 2   ? s.flips_2_3
     : plan.kind == 3 ? s.flips_3_2
     : plan.kind == 4 ? s.flips_4_4
                      : s.edge_removals)++;
  }

  // Smoothing of v: towards the volume-weighted circumcentres of its star (optimal Delaunay
  // triangulation) or the centroid of its neighbours inside; the centroid of its surface
  // neighbours put back onto the input surface on the surface; the middle of its curve neighbours
  // on a feature curve.  Each target is tried whole, then half and a quarter of the way.
  void smooth(Index v, bool all) {
    Mesh& mesh = *c_.mesh;
    const int dim = mesh.dimension(v);
    if (dim == 0) return;
    if (dim <= 2 && !c_.error->bounded()) return; // no input surface to stay on
    star_ = mesh.star(v);
    cells_.clear();
    for (Index t : star_) cells_.push_back(mesh.work[t]);
    const Region_quality before = region_quality(mesh, cells_, none, origin_, c_.floors);
    if (!all && before.score >= bad_score) return;
    const Vec3 x = mesh.posd[v];
    targets_.clear();
    mesh.neighbors(v, nbr_);
    if (nbr_.empty()) return;
    if (dim == 3) {
      Vec3 sum{{0, 0, 0}};
      double weight = 0;
      for (const Tetrahedron& c : cells_) {
        const Vec3 *q[3], *p0 = &x;
        int k = 0;
        for (Index w : c)
          if (w != v) q[k++] = &mesh.posd[w];
        const Vec3 a = minus(*q[0], *p0), b = minus(*q[1], *p0), d = minus(*q[2], *p0);
        const double six_volume = std::abs(dot(a, cross(b, d)));
        if (!(six_volume > 0)) continue;
        const Vec3 bd = cross(b, d), da = cross(d, a), ab = cross(a, b);
        const double la = dot(a, a), lb = dot(b, b), ld = dot(d, d);
        // volume * circumcentre (relative to x) = (la bd + lb da + ld ab) / 12 (signs cancel)
        const double sgn = dot(a, cross(b, d)) > 0 ? 1 : -1;
        for (int i = 0; i < 3; ++i) sum[i] += sgn * (la * bd[i] + lb * da[i] + ld * ab[i]) / 12;
        weight += six_volume / 6;
      }
      if (weight > 0)
        targets_.push_back(Vec3{{x[0] + sum[0] / weight, x[1] + sum[1] / weight, x[2] + sum[2] / weight}});
      Vec3 centroid{{0, 0, 0}};
      for (Index w : nbr_)
        for (int i = 0; i < 3; ++i) centroid[i] += mesh.posd[w][i] / double(nbr_.size());
      targets_.push_back(centroid);
      // Sliver perturbation: away from the face opposite v in its worst tetrahedron, by a quarter
      // of that tetrahedron's mean edge length (a sliver's four vertices are nearly coplanar).
      const Tetrahedron* worst = nullptr;
      double worst_score = bad_score;
      for (const Tetrahedron& c : cells_) {
        const double sc = score(c);
        if (sc < worst_score) {
          worst_score = sc;
          worst = &c;
        }
      }
      if (worst != nullptr) {
        const Vec3* f[3];
        int k = 0;
        for (Index w : *worst)
          if (w != v) f[k++] = &mesh.posd[w];
        Vec3 n = cross(minus(*f[1], *f[0]), minus(*f[2], *f[0]));
        if (dot(n, minus(x, *f[0])) < 0) n = Vec3{{-n[0], -n[1], -n[2]}};
        const double ln = norm(n);
        double mean = 0;
        for (int i = 0; i < 3; ++i) mean += (norm(minus(*f[i], x)) + norm(minus(*f[(i + 1) % 3], *f[i]))) / 6;
        if (ln > 0)
          targets_.push_back(Vec3{{x[0] + 0.25 * mean * n[0] / ln, x[1] + 0.25 * mean * n[1] / ln,
                                   x[2] + 0.25 * mean * n[2] / ln}});
      }
    } else if (dim == 2) {
      mesh.gather(star_, cells_, labels_);
      surface_link_(cells_, labels_, v, link_);
      surface_nbr_.clear();
      for (const auto& e : link_) {
        surface_nbr_.push_back(e.first);
        surface_nbr_.push_back(e.second);
      }
      sort_unique(surface_nbr_);
      if (surface_nbr_.empty()) return;
      Vec3 centroid{{0, 0, 0}};
      for (Index w : surface_nbr_)
        for (int i = 0; i < 3; ++i) centroid[i] += mesh.posd[w][i] / double(surface_nbr_.size());
      targets_.push_back(centroid);
      volume_offset(v);
      if (norm(offset_) > 0) targets_.push_back(x); // the volume correction alone

    } else {
      surface_nbr_.clear();
      for (Index w : nbr_)
        if (mesh.is_feature(v, w)) surface_nbr_.push_back(w);
      if (surface_nbr_.size() != 2) return; // an end or a branching of the curves: fixed
      const Vec3 &p = mesh.posd[surface_nbr_[0]], &q = mesh.posd[surface_nbr_[1]];
      const Vec3 mid{{0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2])}};
      // the point of the curve p - x - q nearest to the middle of p and q
      auto nearest_on = [&](const Vec3& s0, const Vec3& s1) {
        const Vec3 d = minus(s1, s0);
        const double l = dot(d, d);
        const double t = l > 0 ? (std::max)(0., (std::min)(1., dot(minus(mid, s0), d) / l)) : 0;
        return lerp(s0, s1, t);
      };
      const Vec3 u = nearest_on(x, p), w = nearest_on(x, q);
      targets_.push_back(norm(minus(u, mid)) <= norm(minus(w, mid)) ? u : w);
    }
    cells_.clear();
    for (Index t : star_) cells_.push_back(mesh.work[t]);
    Collapse_refusal first = Collapse_refusal::NONE;
    for (const Vec3& target : targets_)
      for (double step : {1., 0.5, 0.25}) {
        Vec3 p = lerp(x, target, step);
        if (dim == 2) {
          p = c_.error->closest_point(p);
          for (int i = 0; i < 3; ++i) p[i] += offset_[i];
        }
        if (norm(minus(p, x)) == 0) continue;
        const Collapse_refusal why = try_move(v, p, before);
        if (why == Collapse_refusal::NONE) return;
        if (first == Collapse_refusal::NONE) first = why;
      }
    if (first != Collapse_refusal::NONE) refuse(c_.stats->refused_moves, first);
  }

  // The move of the surface vertex v (stratum 2) that gives its labels their volume back: each
  // label's drift along its outward normal at v (both labels' on an interface).
  void volume_offset(Index v) {
    offset_ = Vec3{{0, 0, 0}};
    if (c_.drift.empty()) return;
    Mesh& mesh = *c_.mesh;
    normals_.clear();
    for (Index t : star_) {
      const Tetrahedron& c = mesh.work[t];
      for (int k = 0; k < 4; ++k) {
        if (c[k] == v) continue;
        // the face opposite c[k], which holds v: on the surface when no other tetrahedron of the
        // star of the same label has it
        std::array<Index, 3> f{};
        int m = 0;
        for (int j = 0; j < 4; ++j)
          if (j != k) f[m++] = c[j];
        bool inner = false;
        for (Index u : star_)
          if (u != t && mesh.label[u] == mesh.label[t] && contains(mesh.work[u], f[0]) &&
              contains(mesh.work[u], f[1]) && contains(mesh.work[u], f[2]))
            inner = true;
        if (inner) continue;
        Vec3 n = cross(minus(mesh.posd[f[1]], mesh.posd[f[0]]), minus(mesh.posd[f[2]], mesh.posd[f[0]]));
        if (dot(n, minus(mesh.posd[c[k]], mesh.posd[f[0]])) > 0) n = Vec3{{-n[0], -n[1], -n[2]}};
        auto it = std::find_if(normals_.begin(), normals_.end(),
                               [&](const auto& e) { return e.first == mesh.label[t]; });
        if (it == normals_.end())
          normals_.emplace_back(mesh.label[t], n);
        else
          for (int i = 0; i < 3; ++i) it->second[i] += n[i];
      }
    }
    if (normals_.empty() || normals_.size() > 2) return;
    for (const auto& e : normals_) {
      const auto d = c_.drift.find(e.first);
      const double l = norm(e.second);
      if (d == c_.drift.end() || !(l > 0)) continue;
      for (int i = 0; i < 3; ++i) offset_[i] += d->second * e.second[i] / l;
    }
  }

  Collapse_refusal try_move(Index v, const Vec3& p, const Region_quality& before) {
    Mesh& mesh = *c_.mesh;
    const Region_quality after = region_quality(mesh, cells_, v, p, c_.floors);
    if (!(after.score >= before.score) || !after.allowed_after(before, c_.floors))
      return Collapse_refusal::QUALITY;
    const Point_3 q = make_point<Point_3>(p);
    for (const Tetrahedron& c : cells_)
      if (!positive(c, v, &q)) return Collapse_refusal::FLIP;
    if (mesh.dimension(v) <= 2 && !c_.error->move_ok(mesh, v, p)) return Collapse_refusal::ERROR;
    mesh.pos[v] = q;
    mesh.posd[v] = p;
    c_.error->moved(mesh, v);
    ++c_.stats->vertex_moves;
    return Collapse_refusal::NONE;
  }

  // The split of the edge (a, b) at its midpoint: the new vertex, or `none` when refused.
  Index split(Index a, Index b) {
    Mesh& mesh = *c_.mesh;
    st_e_.clear();
    for (Index t : mesh.star(a))
      if (contains(mesh.work[t], b)) st_e_.push_back(t);
    if (st_e_.empty()) return none;
    const Vec3 mid = lerp(mesh.posd[a], mesh.posd[b], 0.5);
    const Point_3 pm = make_point<Point_3>(mid);
    const Index m = static_cast<Index>(mesh.pos.size()); // the index it will have
    split_cells_.clear();
    for (Index t : st_e_)
      for (Index gone : {b, a}) {
        Tetrahedron c = mesh.work[t];
        for (Index& w : c)
          if (w == gone) w = m;
        split_cells_.push_back(c);
      }
    for (const Tetrahedron& c : split_cells_)
      if (!positive(c, m, &pm)) {
        refuse(c_.stats->refused_splits, Collapse_refusal::FLIP);
        return none;
      }
    const Region_quality after = region_quality(mesh, split_cells_, m, mid, c_.floors);
    const Region_quality before = region(st_e_);
    if (after.below > 0 &&
        !after.allowed_after(Region_quality{before.worst, before.score, after.below}, c_.floors)) {
      refuse(c_.stats->refused_splits, Collapse_refusal::QUALITY);
      return none;
    }
    // Where the new vertex is: the faces around the edge in one tetrahedron are on the boundary,
    // those between two labels on an interface.
    faces_.clear();
    for (Index t : st_e_)
      for (Index w : mesh.work[t])
        if (w != a && w != b) faces_.emplace_back(w, mesh.label[t]);
    std::sort(faces_.begin(), faces_.end());
    std::size_t boundary_faces = 0;
    bool interface = false;
    for (std::size_t i = 0; i < faces_.size();) {
      std::size_t j = i;
      while (j < faces_.size() && faces_[j].first == faces_[i].first) ++j;
      if (j - i == 1)
        ++boundary_faces;
      else if (faces_[i].second != faces_[j - 1].second)
        interface = true;
      i = j;
    }
    Surface_constraints<std::size_t>& sc = *c_.constraints;
    const bool feature = mesh.is_feature(a, b);
    const int dim = feature ? 1 : (boundary_faces > 0 || interface) ? 2 : 3;
    const Vertex_type type = boundary_faces > 2   ? Vertex_type::NONMANIFOLD
                             : boundary_faces > 0 ? Vertex_type::BOUNDARY
                                                  : Vertex_type::INTERIOR;
    const std::size_t s = sc.dimension.size();
    sc.dimension.push_back(static_cast<unsigned char>(dim));
    if (!sc.quadrics.empty()) sc.quadrics.emplace_back();
    c_.error->add_vertex();
    c_.sizing->push_back(0.5 * ((*c_.sizing)[mesh.sid[a]] + (*c_.sizing)[mesh.sid[b]]));
    if (feature) {
      sc.features.erase(sc.edge_key(mesh.sid[a], mesh.sid[b]));
      sc.features.insert(sc.edge_key(mesh.sid[a], s));
      sc.features.insert(sc.edge_key(s, mesh.sid[b]));
    }
    mesh.add_vertex(pm, mid, s, mesh.input_vertex[a], type);
    for (std::size_t i = 0; i < st_e_.size(); ++i) {
      const Index t = st_e_[i];
      mesh.deleted_tet[t] = 1;
      for (int h = 0; h < 2; ++h) {
        mesh.add_tetrahedron(split_cells_[2 * i + h], mesh.label[t]);
        c_.input_tet->push_back((*c_.input_tet)[t]);
      }
    }
    c_.change += static_cast<long long>(st_e_.size());
    c_.stats->tetrahedra_added += 2 * st_e_.size();
    c_.stats->tetrahedra_deleted += st_e_.size();
    ++c_.stats->splits;
    return m;
  }

  Context& c_;
  Vec3 origin_{{0, 0, 0}};
  Plan plan_;
  std::vector<std::pair<double, Index>> bad_;
  std::vector<Index> nbr_, tmp_, st_e_, star_, ring_, surface_nbr_;
  std::vector<std::array<Index, 2>> pairs_;
  std::vector<char> exists_, used_;
  std::vector<double> best_;
  std::vector<std::size_t> apex_;
  std::vector<Tetrahedron> cells_, split_cells_;
  std::vector<int> labels_;
  std::vector<Vec3> targets_;
  Vec3 offset_{{0, 0, 0}};
  std::vector<std::pair<int, Vec3>> normals_;
  std::vector<std::pair<Index, int>> faces_;
  std::vector<std::pair<Index, Index>> link_;
  Surface_link<Index> surface_link_;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_OPTIMIZER_H
