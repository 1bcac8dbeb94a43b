// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_TETRAHEDRON_QUALITY_H
#define CGAL_PR_STAR_OCTREE_TETRAHEDRON_QUALITY_H

/// \file tetrahedron_quality.h
/// Shape measures of one tetrahedron, in double precision: the smallest dihedral angle and the
/// radius ratio.  They measure quality; validity (the sign of the orientation) is always decided
/// by the exact `Orientation_3` of the traits, never by these.

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace PR_star_octree {

/// \ingroup PkgPRStarOctreeRef
/// The shape measures a quality floor can use (see `simplify()`).
enum class Quality_measure {
  MIN_DIHEDRAL_ANGLE, ///< the smallest of the six dihedral angles, in degrees (70.53 for a regular
                      ///< tetrahedron)
  RADIUS_RATIO        ///< three times the inradius over the circumradius (1 for a regular tetrahedron)
};

namespace internal {

using Vec3 = std::array<double, 3>;

template <class Point_3>
inline Vec3 to_vec3(const Point_3& p) {
  return Vec3{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
}
inline Vec3 minus(const Vec3& a, const Vec3& b) {
  return Vec3{{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
}
template <class Point_3>
inline Vec3 minus(const Point_3& a, const Point_3& b) {
  return minus(to_vec3(a), to_vec3(b));
}
inline double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return Vec3{{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
inline double norm(const Vec3& a) {
  return std::sqrt(dot(a, a));
}

// The measures on double coordinates (the public functions below convert their points).
inline double min_dihedral_angle(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s) {
  const Vec3* v[4] = {&p, &q, &r, &s};
  constexpr int edges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                               {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  double best = 180;
  for (const auto& e : edges) {
    // At edge (i, j), between the faces (i, j, k) and (i, j, l): with a = j - i, u = k - i,
    // w = l - i, the normals a x u and a x w make the angle
    // atan2(|a| |det(a, u, w)|, (a.a)(u.w) - (a.u)(a.w)).
    const Vec3 a = minus(*v[e[1]], *v[e[0]]);
    const Vec3 u = minus(*v[e[2]], *v[e[0]]);
    const Vec3 w = minus(*v[e[3]], *v[e[0]]);
    const double det = std::abs(dot(a, cross(u, w)));
    const double c = dot(a, a) * dot(u, w) - dot(a, u) * dot(a, w);
    best = (std::min)(best, std::atan2(norm(a) * det, c) * (180. / 3.14159265358979323846));
  }
  return best;
}

inline double radius_ratio(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s) {
  const Vec3 a = minus(q, p), b = minus(r, p), c = minus(s, p);
  const double six_volume = std::abs(dot(a, cross(b, c)));
  if (six_volume == 0) return 0;
  // Sum of the face areas (times 2).
  const double twice_area =
      norm(cross(a, b)) + norm(cross(a, c)) + norm(cross(b, c)) + norm(cross(minus(r, q), minus(s, q)));
  const double inradius = six_volume / twice_area; // 3V / A = (6V / 2) / A
  // Circumcentre relative to p: (|a|^2 (b x c) + |b|^2 (c x a) + |c|^2 (a x b)) / (2 a.(b x c)).
  const Vec3 bc = cross(b, c), ca = cross(c, a), ab = cross(a, b);
  const double la = dot(a, a), lb = dot(b, b), lc = dot(c, c);
  const Vec3 o{{la * bc[0] + lb * ca[0] + lc * ab[0], la * bc[1] + lb * ca[1] + lc * ab[1],
                la * bc[2] + lb * ca[2] + lc * ab[2]}};
  const double circumradius = norm(o) / (2 * six_volume);
  return (std::min)(1., 3 * inradius / circumradius);
}

inline double tetrahedron_quality(Quality_measure m, const Vec3& p, const Vec3& q, const Vec3& r,
                                  const Vec3& s) {
  return m == Quality_measure::RADIUS_RATIO ? radius_ratio(p, q, r, s) : min_dihedral_angle(p, q, r, s);
}

} // namespace internal

/// \ingroup PkgPRStarOctreeRef
/// The smallest dihedral angle of the tetrahedron `(p, q, r, s)`, in degrees, in `[0, 180]`
/// (0 for a flat one; the orientation does not matter).
template <class Point_3>
double min_dihedral_angle(const Point_3& p, const Point_3& q, const Point_3& r, const Point_3& s) {
  using internal::to_vec3;
  return internal::min_dihedral_angle(to_vec3(p), to_vec3(q), to_vec3(r), to_vec3(s));
}

/// \ingroup PkgPRStarOctreeRef
/// The radius ratio `3 r / R` of the tetrahedron `(p, q, r, s)` (`r` the inradius, `R` the
/// circumradius): 1 for a regular tetrahedron, 0 for a flat one.
template <class Point_3>
double radius_ratio(const Point_3& p, const Point_3& q, const Point_3& r, const Point_3& s) {
  using internal::to_vec3;
  return internal::radius_ratio(to_vec3(p), to_vec3(q), to_vec3(r), to_vec3(s));
}

/// \ingroup PkgPRStarOctreeRef
/// The measure `m` of the tetrahedron `(p, q, r, s)`: `min_dihedral_angle()` or `radius_ratio()`.
template <class Point_3>
double tetrahedron_quality(Quality_measure m, const Point_3& p, const Point_3& q, const Point_3& r,
                           const Point_3& s) {
  return m == Quality_measure::RADIUS_RATIO ? radius_ratio(p, q, r, s) : min_dihedral_angle(p, q, r, s);
}

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_TETRAHEDRON_QUALITY_H
