// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_SOLID_ANGLE_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_SOLID_ANGLE_H

// Solid angles in R^3 and in 3-flats of R^4, for the discrete distortion (paper Section 8).

#include <array>
#include <cmath>
#include <utility>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

/// The solid angles at the corners of one tetrahedron `p[0..3]` of R^3 and of its lift
/// `(p[i], f[i])` to R^4, by the formula of Van Oosterom and Strackee: at a corner whose edges are
/// `a`, `b`, `c`, `tan(Omega / 2) = V / (|a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|)`, evaluated
/// with `atan2` so that it is stable for every angle in [0, 2 pi).  `V` is `|det[a b c]|` in R^3
/// and, in R^4, the 3-volume spanned by the lifted edges (the norm of their exterior product, whose
/// coordinates are the four 3x3 minors: far better conditioned than the square root of the Gram
/// determinant, which squares the condition number).
///
/// `V` is six times the volume of the tetrahedron at every corner, and each edge's length is shared
/// by the two corners it joins: both are computed once per tetrahedron, `V` from the edges of
/// vertex 0, each length from the edge oriented from its lower to its higher vertex.  A corner's
/// angles are therefore the same bits whichever corners are asked for (`corners`, a mask of bits
/// `1 << k`), so that a leaf that asks for all four corners of a tetrahedron at once and a query of
/// one vertex's star agree exactly.
class Tetrahedron_solid_angles {
public:
  Tetrahedron_solid_angles(const std::array<std::array<double, 3>, 4>& p, const std::array<double, 4>& f,
                           unsigned corners) {
    for (int e = 0; e < 6; ++e) {
      const int i = edge_vertex[e][0], j = edge_vertex[e][1];
      for (int a = 0; a < 3; ++a) d_[e][a] = p[j][a] - p[i][a];
      d_[e][3] = f[j] - f[i];
      if (((corners >> i) | (corners >> j)) & 1u) {
        const double q = d_[e][0] * d_[e][0] + d_[e][1] * d_[e][1] + d_[e][2] * d_[e][2];
        length3_[e] = std::sqrt(q);
        length4_[e] = std::sqrt(q + d_[e][3] * d_[e][3]);
      }
    }
    // The four 3x3 minors of the lifted edges of vertex 0 (edges 0, 1, 2), one row left out each;
    // the one without the field's row is the determinant of R^3.
    const auto& a = d_[0];
    const auto& b = d_[1];
    const auto& c = d_[2];
    auto minor = [&](int r0, int r1, int r2) {
      return a[r0] * (b[r1] * c[r2] - b[r2] * c[r1]) - a[r1] * (b[r0] * c[r2] - b[r2] * c[r0]) +
             a[r2] * (b[r0] * c[r1] - b[r1] * c[r0]);
    };
    const double m3 = minor(0, 1, 2), m2 = minor(0, 1, 3), m1 = minor(0, 2, 3), m0 = minor(1, 2, 3);
    volume3_ = std::abs(m3);
    volume4_ = std::sqrt(m0 * m0 + m1 * m1 + m2 * m2 + m3 * m3);
  }

  /// The solid angles at corner `k` (one of the corners asked for) in R^3 and in R^4.
  std::pair<double, double> corner(int k) const {
    // The edges from k to the three other vertices, as the canonical edges and their signs
    // (negating is exact).
    int e[3];
    double s[3];
    int n = 0;
    for (int x = 0; x < 4; ++x) {
      if (x == k) continue;
      e[n] = edge_index[k][x];
      s[n] = x > k ? 1. : -1.;
      ++n;
    }
    auto dot3 = [&](int u, int v) {
      const auto& du = d_[e[u]];
      const auto& dv = d_[e[v]];
      return s[u] * s[v] * (du[0] * dv[0] + du[1] * dv[1] + du[2] * dv[2]);
    };
    const double ab = dot3(0, 1), ac = dot3(0, 2), bc = dot3(1, 2);
    const double ab4 = ab + s[0] * s[1] * (d_[e[0]][3] * d_[e[1]][3]);
    const double ac4 = ac + s[0] * s[2] * (d_[e[0]][3] * d_[e[2]][3]);
    const double bc4 = bc + s[1] * s[2] * (d_[e[1]][3] * d_[e[2]][3]);
    const double la = length3_[e[0]], lb = length3_[e[1]], lc = length3_[e[2]];
    const double ma = length4_[e[0]], mb = length4_[e[1]], mc = length4_[e[2]];
    const double den3 = la * lb * lc + ab * lc + ac * lb + bc * la;
    const double den4 = ma * mb * mc + ab4 * mc + ac4 * mb + bc4 * ma;
    return {2. * std::atan2(volume3_, den3), 2. * std::atan2(volume4_, den4)};
  }

private:
  static constexpr int edge_vertex[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  static constexpr int edge_index[4][4] = {{-1, 0, 1, 2}, {0, -1, 3, 4}, {1, 3, -1, 5}, {2, 4, 5, -1}};
  std::array<std::array<double, 4>, 6> d_;
  std::array<double, 6> length3_{}, length4_{};
  double volume3_, volume4_;
};

/// The solid angles at vertex `k` of the tetrahedron `p[0..3]` of R^3 and of its lift
/// `(p[i], f[i])` to R^4 (the same bits as `Tetrahedron_solid_angles` gives for corner `k`).
inline std::pair<double, double> corner_solid_angles(const std::array<std::array<double, 3>, 4>& p,
                                                     const std::array<double, 4>& f, int k) {
  return Tetrahedron_solid_angles(p, f, 1u << k).corner(k);
}

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_SOLID_ANGLE_H
