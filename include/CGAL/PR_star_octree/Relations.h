// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_RELATIONS_H
#define CGAL_PR_STAR_OCTREE_RELATIONS_H

/// \file Relations.h
/// The flags of the local relations a leaf can build (`Leaf_topology`, `Leaf_executor`,
/// `choose_bucket_size()`).

namespace CGAL {
namespace PR_star_octree {

/// \ingroup PkgPRStarOctreeRef
/// The local relations a `Leaf_topology` can build; combine with `|`.
enum Relations : unsigned {
  VERTEX_TETRAHEDRA = 1u,     ///< VT (Algorithm 1): the tetrahedra incident in each vertex of the leaf
  TETRAHEDRON_ADJACENCY = 2u, ///< TT (Algorithm 2): the tetrahedra across the faces of the leaf's tetrahedra
  VERTEX_VERTICES = 4u,       ///< VV: the vertices adjacent to each vertex of the leaf
  EDGES = 8u,                 ///< the edges with a vertex in the leaf, their stars in cyclic order, VE
  TRIANGLES = 16u,            ///< the triangles with a vertex in the leaf and their incident tetrahedra
  /// the kind of the link of every vertex of the leaf (`Vertex_type`: empty, sphere, disc, neither),
  /// gathered for the whole leaf in one pass over its tetrahedra (`Leaf_topology::vertex_type()`)
  VERTEX_LINKS = 32u,
  /// the leaf's tetrahedra in dense local vertex ids (`Leaf_topology::local_tetrahedron()`): the
  /// leaf's own vertices first, then the other vertices of its tetrahedra
  LOCAL_TETRAHEDRA = 64u,
  ALL_RELATIONS = 127u,
  /// not a relation but a modifier of `VERTEX_LINKS`: only the paper's Euler count on each link
  /// (`2|e| = 3|t|`), without checking that it is a sphere or a disc (faster, trusts the mesh to be
  /// manifold; a link edge in three or more link triangles is still reported `NONMANIFOLD`)
  UNCHECKED_LINKS = 128u
};

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_RELATIONS_H
