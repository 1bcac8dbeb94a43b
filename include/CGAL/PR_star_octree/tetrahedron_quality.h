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

// The angle between the two half-planes bounded by the line (a, b) that contain c and d, in
// degrees: the dihedral angle of the tetrahedron (a, b, c, d) at its edge (a, b); 180 where the
// surface (a, b, c) + (a, b, d) is flat.  With e = b - a, u = c - a, w = d - a, the normals e x u
// and e x w make the angle atan2(|e| |det(e, u, w)|, (e.e)(u.w) - (e.u)(e.w)).
inline double wing_angle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 e = minus(b, a), u = minus(c, a), w = minus(d, a);
  const double det = std::abs(dot(e, cross(u, w)));
  const double cs = dot(e, e) * dot(u, w) - dot(e, u) * dot(e, w);
  return std::atan2(norm(e) * det, cs) * (180. / 3.14159265358979323846);
}

// The six dihedral angles of the tetrahedron (p, q, r, s), in degrees.
inline std::array<double, 6> dihedral_angles(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s) {
  return {{wing_angle(p, q, r, s), wing_angle(p, r, q, s), wing_angle(p, s, q, r), wing_angle(q, r, p, s),
           wing_angle(q, s, p, r), wing_angle(r, s, p, q)}};
}

// The measures on double coordinates (the public functions below convert their points).
inline double min_dihedral_angle(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s) {
  const auto angles = dihedral_angles(p, q, r, s);
  return *std::min_element(angles.begin(), angles.end());
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
