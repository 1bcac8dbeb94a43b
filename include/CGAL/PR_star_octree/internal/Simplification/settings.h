// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_SETTINGS_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_SETTINGS_H

// The numeric settings of a simplification (from the named parameters of `simplify()`), and why a
// candidate edge was not collapsed.

#include <CGAL/PR_star_octree/Simplification_statistics.h>
#include <CGAL/PR_star_octree/tetrahedron_quality.h>

#include <cstddef>
#include <limits>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

// The stopping criteria, the octree and the constraints of a simplification.
struct Simplification_settings {
  double target_fraction = 0.;
  double max_edge_length = std::numeric_limits<double>::infinity();
  std::size_t bucket_size = 50;
  std::size_t max_rounds = 1000;
  double min_dihedral = 5;             // degrees; 0: no floor
  double max_dihedral = 165;           // degrees; 180: no ceiling
  double min_radius_ratio = 0.1;       // 0: no floor
  std::size_t optimization_rounds = 2; // optimisation-only rounds after the collapses; 0: no optimisation
  bool remesh = false;                 // remesh() (splits, collapses to the sizing, flips, smoothing)
  std::size_t remesh_iterations = 5;
  double feature_angle = 40;                                           // degrees; >= 180: no sharp edges
  double max_boundary_error = std::numeric_limits<double>::infinity(); // absolute
  bool with_quadrics = false; // the plane quadrics of the surface are computed (quadric cost or placement)
};

// Why a candidate edge was not collapsed: a public refusal, or the edge is gone.
struct Refusal {
  Collapse_refusal why = Collapse_refusal::NONE;
  bool gone = false; // the edge disappeared (not a refusal)

  static Refusal edge_gone() { return Refusal{Collapse_refusal::NONE, true}; }
  bool accepted() const { return why == Collapse_refusal::NONE && !gone; }
};

// Adds a refusal to the counts of a `Simplification_statistics::Blocked`.
inline void count_refusal(Collapse_refusal why, Simplification_statistics::Blocked& b) {
  switch (why) {
  case Collapse_refusal::DIFFERENT_LEAVES:
    ++b.different_leaves;
    break;
  case Collapse_refusal::FEATURE:
    ++b.feature;
    break;
  case Collapse_refusal::BOUNDARY:
    ++b.boundary;
    break;
  case Collapse_refusal::FLIP:
    ++b.flip;
    break;
  case Collapse_refusal::LINK:
    ++b.link;
    break;
  case Collapse_refusal::QUALITY:
    ++b.quality;
    break;
  case Collapse_refusal::ERROR:
    ++b.error;
    break;
  case Collapse_refusal::FILTER:
    ++b.filter;
    break;
  default:
    break;
  }
}

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_SETTINGS_H
