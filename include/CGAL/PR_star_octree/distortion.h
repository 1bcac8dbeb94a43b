// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_DISTORTION_H
#define CGAL_PR_STAR_OCTREE_DISTORTION_H

/// \file distortion.h
/// Discrete distortion (paper Section 8): the curvature of a scalar field f sampled at the vertices,
/// seen as a hypersurface of R^4 through the tetrahedral mesh lifted by f.

#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/number_utils.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace PR_star_octree {

/// \ingroup PkgPRStarOctreeRef
/// The solid angle at the origin of the cone spanned by the vectors `a`, `b`, `c` of R^3, by the
/// formula of Van Oosterom and Strackee: `tan(Omega / 2) = |a.(b x c)| / (|a||b||c| + (a.b)|c| +
/// (a.c)|b| + (b.c)|a|)`, evaluated with `atan2` so that it is stable for every angle in [0, 2 pi).
inline double solid_angle_3(const std::array<double, 3>& a, const std::array<double, 3>& b,
                            const std::array<double, 3>& c) {
  const double det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                     a[2] * (b[0] * c[1] - b[1] * c[0]);
  auto dot = [](const std::array<double, 3>& u, const std::array<double, 3>& v) {
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  };
  const double la = std::sqrt(dot(a, a)), lb = std::sqrt(dot(b, b)), lc = std::sqrt(dot(c, c));
  const double den = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
  return 2. * std::atan2(std::abs(det), den);
}

/// \ingroup PkgPRStarOctreeRef
/// The solid angle at the origin of the cone spanned by three vectors of R^4, measured inside the
/// 3-flat that holds them: the Van Oosterom-Strackee formula with `|det[a b c]|` replaced by the
/// square root of the Gram determinant (computed with Eigen), which is intrinsic to the flat.
inline double solid_angle_4(const Eigen::Vector4d& a, const Eigen::Vector4d& b, const Eigen::Vector4d& c) {
  Eigen::Matrix<double, 4, 3> m;
  m.col(0) = a;
  m.col(1) = b;
  m.col(2) = c;
  const Eigen::Matrix3d gram = m.transpose() * m;
  const double g = gram.determinant();
  const double volume = g > 0 ? std::sqrt(g) : 0.;
  const double la = std::sqrt(gram(0, 0)), lb = std::sqrt(gram(1, 1)), lc = std::sqrt(gram(2, 2));
  const double den = la * lb * lc + gram(0, 1) * lc + gram(0, 2) * lb + gram(1, 2) * la;
  return 2. * std::atan2(volume, den);
}

/// \ingroup PkgPRStarOctreeRef
/// The solid angles at vertex `k` of the tetrahedron `p[0..3]` of R^3 and of its lift
/// `(p[i], f[i])` to R^4.
inline std::pair<double, double> corner_solid_angles(const std::array<std::array<double, 3>, 4>& p,
                                                     const std::array<double, 4>& f, int k) {
  std::array<std::array<double, 3>, 3> e;
  Eigen::Vector4d l[3];
  int n = 0;
  for (int i = 0; i < 4; ++i) {
    if (i == k) continue;
    for (int a = 0; a < 3; ++a) e[n][a] = p[i][a] - p[k][a];
    l[n] << e[n][0], e[n][1], e[n][2], f[i] - f[k];
    ++n;
  }
  return {solid_angle_3(e[0], e[1], e[2]), solid_angle_4(l[0], l[1], l[2])};
}

/// \ingroup PkgPRStarOctreeRef
/// The curvature fields at one vertex.
struct Vertex_curvature {
  double solid_angle_sum_3 = 0; ///< sum over the star of the 3D solid angles at the vertex
  double solid_angle_sum_4 = 0; ///< the same for the mesh lifted by the scalar field
  /// the discrete distortion: (4 pi for an interior vertex, the real 3D sum for a boundary vertex)
  /// minus the lifted sum; 0 for unreferenced and NaN for non-manifold vertices
  double distortion = 0;
  /// the 3D concentrated curvature of the domain: (4 pi or 2 pi) minus the 3D sum
  double domain_curvature = 0;
  Vertex_type type = Vertex_type::UNREFERENCED;
};

namespace internal {

inline Vertex_curvature finish_curvature(double s3, double s4, Vertex_type type) {
  const double pi = 3.14159265358979323846;
  Vertex_curvature c;
  c.solid_angle_sum_3 = s3;
  c.solid_angle_sum_4 = s4;
  c.type = type;
  switch (type) {
  case Vertex_type::INTERIOR:
    c.distortion = 4 * pi - s4;
    c.domain_curvature = 4 * pi - s3;
    break;
  case Vertex_type::BOUNDARY:
    c.distortion = s3 - s4;
    c.domain_curvature = 2 * pi - s3;
    break;
  case Vertex_type::NONMANIFOLD:
    c.distortion = c.domain_curvature = std::numeric_limits<double>::quiet_NaN();
    break;
  case Vertex_type::UNREFERENCED:
    break;
  }
  return c;
}

// The curvature of the vertices [first, last) of the leaf of `local`.
template <class Octree, class Field>
void leaf_curvature(const Leaf_topology<Octree>& local, const Field& field,
                    Vertex_classifier<Octree>& classifier, typename Octree::Index first,
                    typename Octree::Index last, std::vector<Vertex_curvature>& out, std::size_t out_offset) {
  const Octree& tree = local.octree();
  for (auto v = first; v < last; ++v) {
    double s3 = 0, s4 = 0;
    for (auto t : local.vertex_tetrahedra(v)) {
      const auto& c = tree.tetrahedron(t);
      std::array<std::array<double, 3>, 4> p;
      std::array<double, 4> f;
      int k = 0;
      for (int i = 0; i < 4; ++i) {
        const auto& q = tree.point(c[i]);
        p[i] = {{CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())}};
        f[i] = field(c[i]);
        if (c[i] == v) k = i;
      }
      const auto a = corner_solid_angles(p, f, k);
      s3 += a.first;
      s4 += a.second;
    }
    out[v - out_offset] = finish_curvature(s3, s4, classifier.classify(local, v));
  }
}

} // namespace internal

/// \ingroup PkgPRStarOctreeRef
/// The discrete distortion and the domain curvature of every vertex, by streaming over the leaves
/// (VT is built per leaf, then discarded).  `field(v)` gives the scalar value of vertex `v` in the
/// octree's numbering (see `octree_scalar_field()`, `coordinate_field()`).  The result is indexed
/// in the octree's numbering.
template <class Octree, class Field>
std::vector<Vertex_curvature> compute_curvature(const Octree& tree, const Field& field) {
  std::vector<Vertex_curvature> out(tree.number_of_vertices());
  Vertex_classifier<Octree> classifier;
  for_each_leaf(tree, VERTEX_TETRAHEDRA, [&](const Leaf_topology<Octree>& local) {
    internal::leaf_curvature(local, field, classifier, local.vertex_begin(), local.vertex_end(), out, 0);
  });
  return out;
}

/// \ingroup PkgPRStarOctreeRef
/// The curvature at one vertex `v` (octree numbering): builds the local structure of its leaf only.
template <class Octree, class Field>
Vertex_curvature curvature_at(const Octree& tree, typename Octree::Index v, const Field& field) {
  Leaf_topology<Octree> local(tree, tree.leaf_of_vertex(v), VERTEX_TETRAHEDRA);
  Vertex_classifier<Octree> classifier;
  std::vector<Vertex_curvature> out(1);
  internal::leaf_curvature(local, field, classifier, v, v + 1, out, v);
  return out[0];
}

/// \ingroup PkgPRStarOctreeRef
/// The curvature of the vertices inside the box `box` (closed), a spatially coherent query: each
/// leaf whose box meets `box` builds its local structure once for all its vertices.  Appends
/// `(v, curvature)` pairs (octree numbering, increasing) to `out`.
template <class Octree, class Field>
void curvature_in_box(const Octree& tree, const Bbox_3& box, const Field& field,
                      std::vector<std::pair<typename Octree::Index, Vertex_curvature>>& out) {
  using Index = typename Octree::Index;
  Leaf_topology<Octree> local;
  Vertex_classifier<Octree> classifier;
  std::vector<Vertex_curvature> one(1);
  // Descend the tree, pruning the nodes whose boxes miss `box`.
  std::vector<typename Octree::Node_index> stack{tree.root()};
  std::vector<typename Octree::Node_index> hit;
  while (!stack.empty()) {
    const auto n = stack.back();
    stack.pop_back();
    if (!CGAL::do_overlap(tree.node_bbox(n), box) || tree.node(n).number_of_vertices() == 0) continue;
    if (tree.node(n).is_leaf())
      hit.push_back(n);
    else
      for (int c = 7; c >= 0; --c) stack.push_back(tree.node(n).first_child + c);
  }
  std::sort(hit.begin(), hit.end(),
            [&](auto a, auto b) { return tree.node(a).vertex_begin < tree.node(b).vertex_begin; });
  for (auto n : hit) {
    bool built = false;
    for (Index v = tree.node(n).vertex_begin; v < tree.node(n).vertex_end; ++v) {
      const auto& p = tree.point(v);
      const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
      if (x < box.xmin() || x > box.xmax() || y < box.ymin() || y > box.ymax() || z < box.zmin() ||
          z > box.zmax())
        continue;
      if (!built) {
        local.build(tree, n, VERTEX_TETRAHEDRA);
        built = true;
      }
      internal::leaf_curvature(local, field, classifier, v, v + 1, one, v);
      out.emplace_back(v, one[0]);
    }
  }
}

/// \ingroup PkgPRStarOctreeRef
/// The scalar field stored in the octree (from the input mesh), as a field functor.
template <class Octree>
std::function<double(typename Octree::Index)> octree_scalar_field(const Octree& tree) {
  if (!tree.has_scalar_field()) throw std::invalid_argument("the mesh has no scalar field");
  return [&tree](typename Octree::Index v) { return tree.scalar(v); };
}

/// \ingroup PkgPRStarOctreeRef
/// A linear field: coordinate `axis` (0, 1, 2 for x, y, z) of each vertex.
template <class Octree>
std::function<double(typename Octree::Index)> coordinate_field(const Octree& tree, int axis) {
  if (axis < 0 || axis > 2) throw std::invalid_argument("coordinate axis must be 0, 1 or 2");
  return [&tree, axis](typename Octree::Index v) {
    const auto& p = tree.point(v);
    return CGAL::to_double(axis == 0 ? p.x() : axis == 1 ? p.y() : p.z());
  };
}

/// \ingroup PkgPRStarOctreeRef
/// A field given in the user's original vertex numbering (any random-access range, e.g. a column
/// of point data read from a file), seen through the octree's permutation.
template <class Octree, class Values>
std::function<double(typename Octree::Index)> original_order_field(const Octree& tree, const Values& values) {
  if (static_cast<std::size_t>(std::size(values)) != tree.number_of_vertices())
    throw std::invalid_argument("the field has " + std::to_string(std::size(values)) + " values for " +
                                std::to_string(tree.number_of_vertices()) + " vertices");
  return [&tree, &values](typename Octree::Index v) {
    return static_cast<double>(std::begin(values)[tree.original_vertex(v)]);
  };
}

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_DISTORTION_H
