// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_QUALITY_FLOOR_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_QUALITY_FLOOR_H

// The quality floor of a collapse: what it creates is above the floor, or no worse than what it
// replaces (the worst tetrahedron, and the number under the floor).

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

template <class GeomTraits>
class Quality_floor_test {
public:
  using Candidate = Collapse_candidate<GeomTraits>;
  using Index = typename Candidate::Index;
  using Tetrahedron = typename Candidate::Tetrahedron;

  // `floor` 0: no floor.
  bool operator()(const Round_mesh<GeomTraits>& mesh, const Candidate& c, Quality_measure measure,
                  double floor) {
    if (!(floor > 0)) return true;
    changed_.assign(c.new_cells.begin(), c.new_cells.begin() + static_cast<std::ptrdiff_t>(c.renamed));
    if (c.move)
      changed_.insert(changed_.end(), c.new_cells.begin() + static_cast<std::ptrdiff_t>(c.renamed),
                      c.new_cells.end());
    const auto after = quality(mesh, changed_, c.k, c.p, measure, floor);
    if (!(after.first < floor)) return true;
    mesh.gather(*c.st_r, old_, old_labels_);
    if (c.move)
      for (Index t : *c.st_k)
        if (!contains(mesh.work[t], c.r)) old_.push_back(mesh.work[t]);
    const auto before = quality(mesh, old_, c.k, mesh.posd[c.k], measure, floor);
    return !(after.first < before.first || after.second > before.second);
  }

private:
  // The quality of the cells (vertex `moved` at `p`): the worst and the number under the floor.
  static std::pair<double, std::size_t> quality(const Round_mesh<GeomTraits>& mesh,
                                                const std::vector<Tetrahedron>& cells, Index moved,
                                                const Vec3& p, Quality_measure measure, double floor) {
    double worst = std::numeric_limits<double>::infinity();
    std::size_t bad = 0;
    for (const Tetrahedron& c : cells) {
      const Vec3* v[4];
      for (int i = 0; i < 4; ++i) v[i] = c[i] == moved ? &p : &mesh.posd[c[i]];
      const double q = tetrahedron_quality(measure, *v[0], *v[1], *v[2], *v[3]);
      worst = (std::min)(worst, q);
      bad += q < floor;
    }
    return {worst, bad};
  }

  std::vector<Tetrahedron> changed_, old_;
  std::vector<int> old_labels_;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_QUALITY_FLOOR_H
