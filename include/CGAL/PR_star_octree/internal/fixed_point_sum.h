// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_FIXED_POINT_SUM_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_FIXED_POINT_SUM_H

// A sum of doubles that does not depend on the order of the terms: each term is cut to a multiple
// of 2^-FractionBits (exactly, for |x| >= 2^(52 - FractionBits)) and added exactly in a 128-bit
// integer; the value is rounded once.  A distributed run adds the same terms in another order and
// must give the same bits.  The sum must stay below 2^(126 - FractionBits) in magnitude.

#include <cmath>
#include <cstdint>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

template <int FractionBits>
class Fixed_point_sum {
  __extension__ typedef __int128 Integer;

public:
  void add(double x) { sum_ += static_cast<Integer>(std::ldexp(x, FractionBits)); }
  void add(const Fixed_point_sum& o) { sum_ += o.sum_; }
  double value() const { return std::ldexp(static_cast<double>(sum_), -FractionBits); }

private:
  Integer sum_ = 0;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_FIXED_POINT_SUM_H
