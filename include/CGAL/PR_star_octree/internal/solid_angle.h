// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_SOLID_ANGLE_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_SOLID_ANGLE_H

// Solid angles in R^3 and in 3-flats of R^4, for the discrete distortion (paper Section 8).

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <utility>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

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

/// The solid angle at the origin of the cone spanned by three vectors of R^4, measured inside the
/// 3-flat that holds them: the Van Oosterom-Strackee formula with `|det[a b c]|` replaced by the
/// 3-volume spanned by a, b, c (intrinsic to the flat).
inline double solid_angle_4(const Eigen::Vector4d& a, const Eigen::Vector4d& b, const Eigen::Vector4d& c) {
  // The 3-volume of the parallelepiped spanned by a, b, c in R^4: the norm of their exterior
  // product, whose coordinates are the four 3x3 minors of [a b c] (one row left out each).  This is
  // far better conditioned than the square root of the Gram determinant (which squares the
  // condition number): thin tetrahedra give the same angle, to rounding, whatever the vertex order.
  auto minor = [&](int skip) {
    int r[3], n = 0;
    for (int i = 0; i < 4; ++i)
      if (i != skip) r[n++] = i;
    return a[r[0]] * (b[r[1]] * c[r[2]] - b[r[2]] * c[r[1]]) -
           a[r[1]] * (b[r[0]] * c[r[2]] - b[r[2]] * c[r[0]]) +
           a[r[2]] * (b[r[0]] * c[r[1]] - b[r[1]] * c[r[0]]);
  };
  const double m0 = minor(0), m1 = minor(1), m2 = minor(2), m3 = minor(3);
  const double volume = std::sqrt(m0 * m0 + m1 * m1 + m2 * m2 + m3 * m3);
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double den = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return 2. * std::atan2(volume, den);
}

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

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_SOLID_ANGLE_H
