// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_PROFILES_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_PROFILES_H

// What the policies of `simplify()` see: the profile of a candidate edge (for the cost and the
// placement) and the profile of a collapse that passed the mandatory checks (for the filter and the
// visitor).  See the concepts `PRStarOctreeCollapseCost`, `PRStarOctreeCollapsePlacement`,
// `PRStarOctreeCollapseFilter` and `PRStarOctreeSimplificationVisitor`.

#include <CGAL/PR_star_octree/internal/Simplification/collapse_candidate.h>
#include <CGAL/PR_star_octree/internal/Simplification/round_mesh.h>
#include <CGAL/PR_star_octree/internal/Simplification/strata_tests.h>
#include <CGAL/PR_star_octree/internal/simplification_constraints.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

// A candidate edge (v0, v1), v0 < v1, in the numbering of the round's octree.
template <class GeomTraits>
class Edge_profile {
public:
  using Geom_traits = GeomTraits;
  using Mesh = Round_mesh<GeomTraits>;
  using Index = typename Mesh::Index;
  using Point_3 = typename GeomTraits::Point_3;

  Edge_profile(const Mesh& mesh, const GeomTraits& gt, Index v0, Index v1)
      : mesh_(mesh), gt_(gt), v0_(v0), v1_(v1) {}

  Index v0() const { return v0_; }
  Index v1() const { return v1_; }
  const Point_3& point(Index v) const { return mesh_.pos[v]; }
  const std::vector<Point_3>& points() const { return mesh_.pos; }
  const std::array<double, 3>& coordinates(Index v) const { return mesh_.posd[v]; }
  // 3 interior, 2 surface, 1 feature curve, 0 corner
  int stratum(Index v) const { return mesh_.dimension(v); }
  // the strata allow removing `r` into `k`
  bool can_remove(Index r, Index k) const { return removable_into(mesh_, r, k); }
  bool in_leaf(Index v) const { return mesh_.in_leaf(v); }
  std::size_t input_vertex(Index v) const { return mesh_.input_vertex[v]; }
  const Geom_traits& geom_traits() const { return gt_; }

  // The plane quadrics of the input surface that v0 and v1 stand for (when computed).
  bool has_quadrics() const { return !mesh_.constraints->quadrics.empty(); }
  // The quadric error of the merged vertex at p (0 without quadrics).
  double quadric_error(const std::array<double, 3>& p) const {
    return has_quadrics() ? merged().error(p) : 0.;
  }
  // The point of [v0, v1] of smallest quadric error, as a parameter in [0, 1]; -1 when the ends
  // are not of one stratum of dimension 2 or 3 (or without quadrics).
  double optimal_parameter() const {
    const int d = stratum(v0_);
    if (!has_quadrics() || d < 2 || stratum(v1_) != d) return -1;
    return merged().best_on_segment(mesh_.posd[v0_], mesh_.posd[v1_]);
  }

private:
  Plane_quadric merged() const {
    Plane_quadric q = mesh_.constraints->quadrics[mesh_.sid[v0_]];
    q += mesh_.constraints->quadrics[mesh_.sid[v1_]];
    return q;
  }

  const Mesh& mesh_;
  const GeomTraits& gt_;
  Index v0_, v1_;
};

// A collapse of `removed()` into `kept()` that passed the mandatory checks (strata, orientation,
// links).  `Checks` provides the package's own tests, `quality_ok(c)` and `error_ok(c)`.
template <class GeomTraits, class Checks>
class Collapse_profile {
public:
  using Geom_traits = GeomTraits;
  using Candidate = Collapse_candidate<GeomTraits>;
  using Mesh = Round_mesh<GeomTraits>;
  using Index = typename Mesh::Index;
  using Point_3 = typename GeomTraits::Point_3;
  using Tetrahedron = typename Mesh::Tetrahedron;

  Collapse_profile(const Mesh& mesh, const GeomTraits& gt, const Candidate& c, Checks& checks)
      : mesh_(mesh), gt_(gt), c_(c), checks_(checks) {}

  Index removed() const { return c_.r; }
  Index kept() const { return c_.k; }
  // whether the kept vertex moves (to `kept_point()`)
  bool moves() const { return c_.move; }
  const Point_3& kept_point() const { return c_.pk; }
  const Point_3& point(Index v) const { return mesh_.pos[v]; }
  const std::array<double, 3>& coordinates(Index v) const { return mesh_.posd[v]; }
  int stratum(Index v) const { return mesh_.dimension(v); }
  std::size_t input_vertex(Index v) const { return mesh_.input_vertex[v]; }
  const Geom_traits& geom_traits() const { return gt_; }
  // The tetrahedra the collapse changes, as they will be: those of the removed vertex not on the
  // edge (renamed), and those of the kept vertex not on the edge when it moves.
  std::vector<Tetrahedron> changed_tetrahedra() const {
    const std::size_t n = c_.move ? c_.new_cells.size() : c_.renamed;
    return std::vector<Tetrahedron>(c_.new_cells.begin(),
                                    c_.new_cells.begin() + static_cast<std::ptrdiff_t>(n));
  }
  // The package's quality floor and error bound (from the named parameters of `simplify()`).
  bool above_quality_floor() const { return checks_.quality_ok(c_); }
  bool within_error_bound() const { return checks_.error_ok(c_); }

private:
  const Mesh& mesh_;
  const GeomTraits& gt_;
  const Candidate& c_;
  Checks& checks_;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_PROFILES_H
