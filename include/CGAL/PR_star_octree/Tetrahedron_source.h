// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_TETRAHEDRON_SOURCE_H
#define CGAL_PR_STAR_OCTREE_TETRAHEDRON_SOURCE_H

/// \file Tetrahedron_source.h
/// A model of `PRStarOctreeTetrahedronSource` over tetrahedra in memory.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace PR_star_octree {

/// \ingroup PkgPRStarOctreeRef
/// \cgalModels `PRStarOctreeTetrahedronSource`
///
/// The tetrahedra of a random-access range (each a random-access container of four integer vertex
/// indices), and optionally one label each, given in chunks to the streaming construction of
/// `PR_star_octree_3`.  The range is referenced, not copied: it must outlive the source.  A negative
/// index is given as a huge one, so that the octree refuses it as out of range.
template <class TetrahedronRange>
class Tetrahedron_range_source {
public:
  /// \param tetrahedra the tetrahedra
  /// \param labels `nullptr`, or one label per tetrahedron
  /// \param chunk the number of tetrahedra given at a time
  /// \throws std::invalid_argument if there is not one label per tetrahedron, or `chunk == 0`
  explicit Tetrahedron_range_source(const TetrahedronRange& tetrahedra,
                                    const std::vector<int>* labels = nullptr,
                                    std::size_t chunk = std::size_t(1) << 16)
      : tetrahedra_(&tetrahedra), labels_(labels), chunk_(chunk) {
    if (chunk == 0)
      throw std::invalid_argument("Tetrahedron_range_source: the chunk size must be at least 1");
    if (labels != nullptr && labels->size() != size())
      throw std::invalid_argument("Tetrahedron_range_source: " + std::to_string(labels->size()) +
                                  " labels for " + std::to_string(size()) + " tetrahedra");
  }

  /// calls `f(vertices, labels, n)` for consecutive chunks of `n` tetrahedra: `vertices` holds 4
  /// indices per tetrahedron, `labels` one label each or is `nullptr`
  template <class F>
  void for_each_chunk(F f) const {
    std::vector<std::uint64_t> buffer;
    const std::size_t n = size();
    for (std::size_t b = 0; b < n; b += chunk_) {
      const std::size_t e = (std::min)(n, b + chunk_);
      buffer.resize(4 * (e - b));
      for (std::size_t t = b; t < e; ++t) {
        const auto& c = std::begin(*tetrahedra_)[t];
        auto it = std::begin(c);
        for (std::size_t k = 0; k < 4; ++k) buffer[4 * (t - b) + k] = static_cast<std::uint64_t>(it[k]);
      }
      f(static_cast<const std::uint64_t*>(buffer.data()),
        labels_ != nullptr ? static_cast<const int*>(labels_->data() + b) : static_cast<const int*>(nullptr),
        e - b);
    }
  }

  /// the number of tetrahedra (so the construction does not count them in a pass of its own)
  std::size_t number_of_tetrahedra() const { return size(); }

private:
  std::size_t size() const { return static_cast<std::size_t>(std::size(*tetrahedra_)); }
  const TetrahedronRange* tetrahedra_;
  const std::vector<int>* labels_;
  std::size_t chunk_;
};

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_TETRAHEDRON_SOURCE_H
