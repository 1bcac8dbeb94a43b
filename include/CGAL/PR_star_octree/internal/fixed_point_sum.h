// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_FIXED_POINT_SUM_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_FIXED_POINT_SUM_H

// A sum of doubles that does not depend on the order of the terms: each term is rounded to a
// multiple of 2^-48 (one instruction) and the integers are added exactly in 128 bits; the value is
// rounded once.  A distributed run adds the same terms in another order and must give the same
// bits.  Each term must be smaller than 2^15 in magnitude (solid angles, distortions), and finite.
// The absolute error of the sum is at most 2^-49 per term (about 1.8e-15).

#include <cmath>
#include <cstdint>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

class Fixed_point_sum {
  __extension__ typedef __int128 Integer;
  static constexpr int fraction_bits = 48;

public:
  void add(double x) {
    sum_ += static_cast<Integer>(std::llrint(x * double(std::uint64_t(1) << fraction_bits)));
  }
  void add(const Fixed_point_sum& o) { sum_ += o.sum_; }
  double value() const { return std::ldexp(static_cast<double>(sum_), -fraction_bits); }

private:
  Integer sum_ = 0;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_FIXED_POINT_SUM_H
