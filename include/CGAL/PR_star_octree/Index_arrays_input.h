// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INDEX_ARRAYS_INPUT_H
#define CGAL_PR_STAR_OCTREE_INDEX_ARRAYS_INPUT_H

#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>
#include <CGAL/PR_star_octree/internal/concept_checks.h>

#include <array>
#include <stdexcept>
#include <string>
#include <cstddef>
#include <iterator>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace PR_star_octree {

/// \ingroup PkgPRStarOctreeRef
/// Tag standing for "no scalar field" in `Index_arrays_input`.
struct No_scalar_field {};

/// \ingroup PkgPRStarOctreeRef
/// \cgalModels `PRStarOctreeInputMesh`
///
/// Adapts plain index arrays: any random-access range of points, any random-access range of
/// tetrahedra (each a random-access container of four integer vertex indices, 0-based) and,
/// optionally, a random-access range with one scalar per vertex.  The ranges are referenced,
/// not copied: they must outlive the adapter.
///
/// \tparam PointRange random-access range whose value type has `x()`, `y()`, `z()`
/// \tparam TetrahedronRange random-access range of 4-index arrays (`std::array<I,4>`, `std::vector<I>`, ...)
/// \tparam ScalarRange random-access range of values convertible to `double`, or `No_scalar_field`
template <class PointRange, class TetrahedronRange, class ScalarRange = No_scalar_field>
class Index_arrays_input {
public:
  using Point_3 = typename std::decay<decltype(*std::begin(std::declval<const PointRange&>()))>::type;

  Index_arrays_input(const PointRange& points, const TetrahedronRange& tetrahedra)
      : points_(&points), tetrahedra_(&tetrahedra), scalars_(nullptr) {}

  Index_arrays_input(const PointRange& points, const TetrahedronRange& tetrahedra, const ScalarRange& scalars)
      : points_(&points), tetrahedra_(&tetrahedra), scalars_(&scalars) {}

  std::size_t number_of_vertices() const { return static_cast<std::size_t>(std::size(*points_)); }
  std::size_t number_of_tetrahedra() const { return static_cast<std::size_t>(std::size(*tetrahedra_)); }

  /// point `i` (a reference into the range, or a value for a range of values)
  decltype(auto) point(std::size_t i) const { return std::begin(*points_)[i]; }

  /// the four vertex indices of tetrahedron `t`, in the element type of the range (a negative
  /// index stays negative, so that the octree reports it as such)
  auto tetrahedron(std::size_t t) const {
    const auto& c = std::begin(*tetrahedra_)[t];
    using I = typename std::decay<decltype(*std::begin(c))>::type;
    auto it = std::begin(c);
    return std::array<I, 4>{{it[0], it[1], it[2], it[3]}};
  }

  bool has_scalar_field() const {
    if constexpr (std::is_same<ScalarRange, No_scalar_field>::value)
      return false;
    else
      return scalars_ != nullptr;
  }

  double scalar(std::size_t i) const {
    if constexpr (std::is_same<ScalarRange, No_scalar_field>::value) {
      (void)i;
      return 0.;
    } else {
      return static_cast<double>(std::begin(*scalars_)[i]);
    }
  }

  /// whether labels were given (`set_tetrahedron_labels()`)
  bool has_tetrahedron_labels() const { return labels_ != nullptr; }
  /// the label of tetrahedron `t` (0 without labels)
  int tetrahedron_label(std::size_t t) const { return labels_ ? (*labels_)[t] : 0; }
  /// references one label per tetrahedron (e.g. subdomain indices); must outlive the adapter
  /// \throws std::invalid_argument if there is not one label per tetrahedron
  void set_tetrahedron_labels(const std::vector<int>& labels) {
    if (labels.size() != number_of_tetrahedra())
      throw std::invalid_argument("make_input: " + std::to_string(labels.size()) + " labels for " +
                                  std::to_string(number_of_tetrahedra()) + " tetrahedra");
    labels_ = &labels;
  }

  /// whether the coordinates are 32-bit floats: `set_float32_points()`, or points whose `x()` is a
  /// `float` (the octree then stores floats by default, see `Coordinate_precision`)
  bool has_float32_points() const { return float32_ || internal::has_float_x_coordinate<Point_3>::value; }
  /// says that the coordinates are 32-bit floats held in wider numbers (e.g. read from a `Float32` file)
  void set_float32_points(bool b) { float32_ = b; }

private:
  const PointRange* points_;
  const TetrahedronRange* tetrahedra_;
  const ScalarRange* scalars_;
  const std::vector<int>* labels_ = nullptr;
  bool float32_ = false;
};

/// \ingroup PkgPRStarOctreeRef
/// Adapts index arrays without a scalar field.
template <class PointRange, class TetrahedronRange>
Index_arrays_input<PointRange, TetrahedronRange> make_input(const PointRange& points,
                                                            const TetrahedronRange& tetrahedra) {
  return Index_arrays_input<PointRange, TetrahedronRange>(points, tetrahedra);
}

/// \ingroup PkgPRStarOctreeRef
/// Adapts index arrays with one scalar per vertex.
template <class PointRange, class TetrahedronRange, class ScalarRange>
Index_arrays_input<PointRange, TetrahedronRange, ScalarRange>
make_input(const PointRange& points, const TetrahedronRange& tetrahedra, const ScalarRange& scalars) {
  return Index_arrays_input<PointRange, TetrahedronRange, ScalarRange>(points, tetrahedra, scalars);
}

/// \ingroup PkgPRStarOctreeRef
/// Adapts an `Indexed_tetrahedral_mesh`; its first point-data array, if any, is the scalar field,
/// its tetrahedron labels, if any, are the labels, and its `float32_points` says whether the
/// coordinates are 32-bit floats.
template <class P, class I>
Index_arrays_input<std::vector<P>, std::vector<std::array<I, 4>>, std::vector<double>>
make_input(const Indexed_tetrahedral_mesh<P, I>& mesh) {
  using Result = Index_arrays_input<std::vector<P>, std::vector<std::array<I, 4>>, std::vector<double>>;
  const Point_data_array* s = mesh.scalar_field();
  Result r = s ? Result(mesh.points, mesh.tetrahedra, s->values) : Result(mesh.points, mesh.tetrahedra);
  if (!mesh.tetrahedron_labels.empty()) r.set_tetrahedron_labels(mesh.tetrahedron_labels);
  r.set_float32_points(mesh.float32_points);
  return r;
}

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INDEX_ARRAYS_INPUT_H
