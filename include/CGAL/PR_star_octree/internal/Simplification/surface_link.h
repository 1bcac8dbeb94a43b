// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_SURFACE_LINK_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_SURFACE_LINK_H

// The link of a vertex in the surface the simplification keeps: the boundary triangles and the
// triangles between tetrahedra of different labels around it.

#include <CGAL/PR_star_octree/internal/local_complex.h>

#include <algorithm>
#include <cstddef>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

template <class Index>
class Surface_link {
public:
  // The surface triangles around `v` of the tetrahedra `cells` (vertex arrays, with `labels`):
  // the triangles (v, x, y) in one cell only or between cells of different labels, as (x, y).
  template <class Tetrahedron>
  void operator()(const std::vector<Tetrahedron>& cells, const std::vector<int>& labels, Index v,
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

private:
  struct Face_record {
    Index x, y;
    int label;
    bool operator<(const Face_record& o) const { return std::tie(x, y, label) < std::tie(o.x, o.y, o.label); }
  };
  std::vector<Face_record> faces_;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_SIMPLIFICATION_SURFACE_LINK_H
