// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_QUALITY_FLOOR_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_QUALITY_FLOOR_H

// The quality floors of a change (a collapse, a flip, a move, a split): what it creates is above
// the floors, or no worse than what it replaces (the worst tetrahedron by each measure with a
// floor, and the number under a floor); and the one-number score the optimisation raises.

#include <CGAL/PR_star_octree/internal/Simplification/collapse_candidate.h>
#include <CGAL/PR_star_octree/tetrahedron_quality.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

// The quality of a tetrahedron by the three measures of the floors.
struct Tetrahedron_shape {
  double min_dihedral = 0, max_dihedral = 180, radius_ratio = 0;

  // From the outward face normals: the dihedral angle at the edge of faces k and l has the cosine
  // -n_k.n_l / (|n_k| |n_l|), so two arc cosines give both extremes (the optimisation evaluates
  // this millions of times); the radius ratio reuses the face areas.
  static Tetrahedron_shape of(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s) {
    const Vec3* P[4] = {&p, &q, &r, &s};
    Vec3 n[4];
    double len[4];
    for (int k = 0; k < 4; ++k) {
      const Vec3 &a = *P[k == 0 ? 1 : 0], &b = *P[k <= 1 ? 2 : 1], &c = *P[k <= 2 ? 3 : 2];
      n[k] = cross(minus(b, a), minus(c, a));
      if (dot(n[k], minus(*P[k], a)) > 0) n[k] = Vec3{{-n[k][0], -n[k][1], -n[k][2]}};
      len[k] = norm(n[k]);
    }
    const Vec3 a = minus(q, p), b = minus(r, p), c = minus(s, p);
    const double six_volume = std::abs(dot(a, cross(b, c)));
    if (!(six_volume > 0) || !(len[0] * len[1] * len[2] * len[3] > 0)) return Tetrahedron_shape{0, 180, 0};
    double lo = 1, hi = -1;
    for (int k = 0; k < 4; ++k)
      for (int l = k + 1; l < 4; ++l) {
        const double cs = -dot(n[k], n[l]) / (len[k] * len[l]);
        lo = (std::min)(lo, cs);
        hi = (std::max)(hi, cs);
      }
    constexpr double degrees = 180. / 3.14159265358979323846;
    auto angle = [&](double cs) { return std::acos((std::max)(-1., (std::min)(1., cs))) * degrees; };
    // Radius ratio 3 r / R: r = 3V / A, R from the circumcentre relative to p.
    const double inradius = six_volume / (len[0] + len[1] + len[2] + len[3]);
    const Vec3 bc = cross(b, c), ca = cross(c, a), ab = cross(a, b);
    const double la = dot(a, a), lb = dot(b, b), lc = dot(c, c);
    const Vec3 o{{la * bc[0] + lb * ca[0] + lc * ab[0], la * bc[1] + lb * ca[1] + lc * ab[1],
                  la * bc[2] + lb * ca[2] + lc * ab[2]}};
    const double circumradius = norm(o) / (2 * six_volume);
    return Tetrahedron_shape{angle(hi), angle(lo), (std::min)(1., 3 * inradius / circumradius)};
  }
  // One number for the optimisation, 1 for the regular tetrahedron and 0 for a flat one: the
  // worst of the three measures, each scaled to [0, 1] (70.53 degrees and 109.47 degrees from 180
  // for the dihedral angles of the regular tetrahedron).
  double score() const {
    return (std::min)({min_dihedral / 70.5288, (180 - max_dihedral) / 109.4712, radius_ratio});
  }
};

// The floors (and the ceiling) on the quality of the tetrahedra a change creates.
struct Quality_floors {
  double min_dihedral = 5, max_dihedral = 165, min_radius_ratio = 0.1;

  bool active() const { return min_dihedral > 0 || max_dihedral < 180 || min_radius_ratio > 0; }
  bool below(const Tetrahedron_shape& q) const {
    return q.min_dihedral < min_dihedral || q.max_dihedral > max_dihedral ||
           q.radius_ratio < min_radius_ratio;
  }
};

// The worst of some tetrahedra by each measure, and how many are below a floor.
struct Region_quality {
  Tetrahedron_shape worst{180, 0, 1};
  double score = 1;
  std::size_t below = 0;

  void add(const Tetrahedron_shape& q, const Quality_floors& floors) {
    worst.min_dihedral = (std::min)(worst.min_dihedral, q.min_dihedral);
    worst.max_dihedral = (std::max)(worst.max_dihedral, q.max_dihedral);
    worst.radius_ratio = (std::min)(worst.radius_ratio, q.radius_ratio);
    score = (std::min)(score, q.score());
    below += floors.below(q);
  }
  // A change from `before` to this is allowed by the floors: nothing below them, or no more
  // tetrahedra below them and no measure worse where a floor is active.
  bool allowed_after(const Region_quality& before, const Quality_floors& floors) const {
    if (below == 0) return true;
    if (below > before.below) return false;
    if (floors.min_dihedral > 0 && worst.min_dihedral < before.worst.min_dihedral) return false;
    if (floors.max_dihedral < 180 && worst.max_dihedral > before.worst.max_dihedral) return false;
    if (floors.min_radius_ratio > 0 && worst.radius_ratio < before.worst.radius_ratio) return false;
    return true;
  }
};

// The quality of cells of `mesh`, vertex `moved` at `p` (or none: `moved` out of range).
template <class Mesh, class Cells>
Region_quality region_quality(const Mesh& mesh, const Cells& cells, typename Mesh::Index moved, const Vec3& p,
                              const Quality_floors& floors) {
  Region_quality r;
  for (const auto& c : cells) {
    const Vec3* v[4];
    for (int i = 0; i < 4; ++i) v[i] = c[i] == moved ? &p : &mesh.posd[c[i]];
    r.add(Tetrahedron_shape::of(*v[0], *v[1], *v[2], *v[3]), floors);
  }
  return r;
}

template <class GeomTraits>
class Quality_floor_test {
public:
  using Candidate = Collapse_candidate<GeomTraits>;
  using Index = typename Candidate::Index;
  using Tetrahedron = typename Candidate::Tetrahedron;

  bool operator()(const Round_mesh<GeomTraits>& mesh, const Candidate& c, const Quality_floors& floors) {
    if (!floors.active()) return true;
    changed_.assign(c.new_cells.begin(), c.new_cells.begin() + static_cast<std::ptrdiff_t>(c.renamed));
    if (c.move)
      changed_.insert(changed_.end(), c.new_cells.begin() + static_cast<std::ptrdiff_t>(c.renamed),
                      c.new_cells.end());
    const Region_quality after = region_quality(mesh, changed_, c.k, c.p, floors);
    if (after.below == 0) return true;
    mesh.gather(*c.st_r, old_, old_labels_);
    if (c.move)
      for (Index t : *c.st_k)
        if (!contains(mesh.work[t], c.r)) old_.push_back(mesh.work[t]);
    return after.allowed_after(region_quality(mesh, old_, c.k, mesh.posd[c.k], floors), floors);
  }

private:
  std::vector<Tetrahedron> changed_, old_;
  std::vector<int> old_labels_;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_QUALITY_FLOOR_H
