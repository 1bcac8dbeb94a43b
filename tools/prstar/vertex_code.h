// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The code of a vertex type in the point arrays and CSV files the prstar tool writes.

#ifndef PRSTAR_VERTEX_CODE_H
#define PRSTAR_VERTEX_CODE_H

#include <CGAL/PR_star_octree/boundary.h>

namespace prstar {

/// 0 interior, 1 boundary, 2 non-manifold, 3 in no tetrahedron.
inline double vertex_type_code(CGAL::PR_star_octree::Vertex_type t) {
  using CGAL::PR_star_octree::Vertex_type;
  switch (t) {
  case Vertex_type::INTERIOR:
    return 0;
  case Vertex_type::BOUNDARY:
    return 1;
  case Vertex_type::NONMANIFOLD:
    return 2;
  default:
    return 3;
  }
}

} // namespace prstar

#endif // PRSTAR_VERTEX_CODE_H
