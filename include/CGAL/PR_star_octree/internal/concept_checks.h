// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_CONCEPT_CHECKS_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_CONCEPT_CHECKS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

// Whether `NP` is a chain of named parameters (CGAL's or the package's, which derive from CGAL's).
template <class T, class Tag, class Base>
std::true_type named_parameters_test(const CGAL::Named_function_parameters<T, Tag, Base>*);
std::false_type named_parameters_test(...);
template <class NP>
struct is_named_parameters : decltype(named_parameters_test(static_cast<const NP*>(nullptr))) {};

// Detection idiom (C++17): each trait is true when the expression or nested type exists.
template <class...>
using void_t = void;

#define CGAL_PR_STAR_OCTREE_DETECT_TYPE(NAME)                                                                \
  template <class T, class = void>                                                                           \
  struct has_type_##NAME : std::false_type {};                                                               \
  template <class T>                                                                                         \
  struct has_type_##NAME<T, void_t<typename T::NAME>> : std::true_type {};

CGAL_PR_STAR_OCTREE_DETECT_TYPE(FT)
CGAL_PR_STAR_OCTREE_DETECT_TYPE(Point_3)
CGAL_PR_STAR_OCTREE_DETECT_TYPE(Orientation_3)
#undef CGAL_PR_STAR_OCTREE_DETECT_TYPE

template <class T, class = void>
struct has_orientation_3_object : std::false_type {};
template <class T>
struct has_orientation_3_object<T, void_t<decltype(std::declval<const T&>().orientation_3_object())>>
    : std::true_type {};

// The traits' coordinate functors: `compute_x_3_object()(p)`, ... convertible with `CGAL::to_double`.
template <class T, class = void>
struct has_coordinate_functors : std::false_type {};
template <class T>
struct has_coordinate_functors<T,
                               void_t<decltype(CGAL::to_double(std::declval<const T&>().compute_x_3_object()(
                                          std::declval<const typename T::Point_3&>()))),
                                      decltype(CGAL::to_double(std::declval<const T&>().compute_y_3_object()(
                                          std::declval<const typename T::Point_3&>()))),
                                      decltype(CGAL::to_double(std::declval<const T&>().compute_z_3_object()(
                                          std::declval<const typename T::Point_3&>())))>> : std::true_type {};

// `compute_squared_distance_3_object()(p, q)` convertible with `CGAL::to_double`.
template <class T, class = void>
struct has_squared_distance : std::false_type {};
template <class T>
struct has_squared_distance<
    T, void_t<decltype(CGAL::to_double(std::declval<const T&>().compute_squared_distance_3_object()(
           std::declval<const typename T::Point_3&>(), std::declval<const typename T::Point_3&>())))>>
    : std::true_type {};

template <class T, class = void>
struct point_has_coordinates : std::false_type {};
template <class T>
struct point_has_coordinates<T, void_t<decltype(CGAL::to_double(std::declval<const T&>().x())),
                                       decltype(CGAL::to_double(std::declval<const T&>().y())),
                                       decltype(CGAL::to_double(std::declval<const T&>().z()))>>
    : std::true_type {};

template <class GT, bool has_point = has_type_Point_3<GT>::value>
struct traits_has_coordinates : std::false_type {};
template <class GT>
struct traits_has_coordinates<GT, true> : has_coordinate_functors<GT> {};
template <class GT, bool has_point = has_type_Point_3<GT>::value>
struct traits_has_squared_distance : std::false_type {};
template <class GT>
struct traits_has_squared_distance<GT, true> : has_squared_distance<GT> {};

/// Checks the concept `PRStarOctreeTraits`; each failure is one readable `static_assert`.
template <class GT>
struct Check_geom_traits {
  static_assert(has_type_FT<GT>::value,
                "PR_star_octree_3: the geometric traits class must provide a nested number type FT "
                "(see the concept PRStarOctreeTraits; a CGAL kernel such as "
                "Exact_predicates_inexact_constructions_kernel is a model)");
  static_assert(has_type_Point_3<GT>::value,
                "PR_star_octree_3: the geometric traits class must provide a nested type Point_3 "
                "(see the concept PRStarOctreeTraits)");
  static_assert(traits_has_coordinates<GT>::value,
                "PR_star_octree_3: the geometric traits class must provide compute_x_3_object(), "
                "compute_y_3_object() and compute_z_3_object() giving the coordinates of a Point_3 "
                "(see the concept PRStarOctreeTraits)");
  static_assert(
      traits_has_squared_distance<GT>::value,
      "PR_star_octree_3: the geometric traits class must provide compute_squared_distance_3_object() "
      "(see the concept PRStarOctreeTraits)");
  static_assert(has_type_Orientation_3<GT>::value && has_orientation_3_object<GT>::value,
                "PR_star_octree_3: the geometric traits class must provide Orientation_3 and "
                "orientation_3_object() (an exact predicate; see the concept PRStarOctreeTraits)");
  static constexpr bool value = true;
};

template <class T, class = void>
struct has_number_of_vertices : std::false_type {};
template <class T>
struct has_number_of_vertices<T, void_t<decltype(std::size_t(std::declval<const T&>().number_of_vertices()))>>
    : std::true_type {};

template <class T, class = void>
struct has_number_of_tetrahedra : std::false_type {};
template <class T>
struct has_number_of_tetrahedra<
    T, void_t<decltype(std::size_t(std::declval<const T&>().number_of_tetrahedra()))>> : std::true_type {};

// `point(i)` returns the traits' point type, or a point with x(), y(), z().
template <class T, class Point_3, class = void>
struct has_point_access : std::false_type {};
template <class T, class Point_3>
struct has_point_access<T, Point_3, void_t<decltype(std::declval<const T&>().point(std::size_t(0)))>>
    : std::integral_constant<
          bool,
          std::is_convertible<decltype(std::declval<const T&>().point(std::size_t(0))), Point_3>::value ||
              point_has_coordinates<
                  std::decay_t<decltype(std::declval<const T&>().point(std::size_t(0)))>>::value> {};

template <class T, class = void>
struct has_tetrahedron_access : std::false_type {};
template <class T>
struct has_tetrahedron_access<T, void_t<decltype(std::declval<const T&>().tetrahedron(std::size_t(0))[3])>>
    : std::true_type {};

template <class T, class = void>
struct has_scalar_access : std::false_type {};
template <class T>
struct has_scalar_access<T, void_t<decltype(bool(std::declval<const T&>().has_scalar_field())),
                                   decltype(double(std::declval<const T&>().scalar(std::size_t(0))))>>
    : std::true_type {};

// Optional: `has_tetrahedron_labels()` and `tetrahedron_label(t)` (an `int` per tetrahedron).
template <class T, class = void>
struct has_tetrahedron_labels : std::false_type {};
template <class T>
struct has_tetrahedron_labels<
    T, void_t<decltype(bool(std::declval<const T&>().has_tetrahedron_labels())),
              decltype(int(std::declval<const T&>().tetrahedron_label(std::size_t(0))))>> : std::true_type {};

// Whether the traits make a `Point_3` from three `double`s (`Construct_point_3`): needed to store
// the coordinates as floats.
template <class GT, class = void>
struct can_construct_point_3 : std::false_type {};
template <class GT>
struct can_construct_point_3<
    GT, void_t<decltype(std::declval<const GT&>().construct_point_3_object()(0., 0., 0.))>>
    : std::is_convertible<decltype(std::declval<const GT&>().construct_point_3_object()(0., 0., 0.)),
                          typename GT::Point_3> {};

// Optional: `has_float32_points()`, whether the coordinates are 32-bit floats; otherwise, whether
// the points' `x()` is a `float`.
template <class T, class = void>
struct has_float32_points_member : std::false_type {};
template <class T>
struct has_float32_points_member<T, void_t<decltype(bool(std::declval<const T&>().has_float32_points()))>>
    : std::true_type {};
// whether `P::x()` is a `float` (false for a point without `x()`, e.g. a custom traits' point)
template <class P, class = void>
struct has_float_x_coordinate : std::false_type {};
template <class P>
struct has_float_x_coordinate<P, void_t<decltype(std::declval<const P&>().x())>>
    : std::is_same<std::decay_t<decltype(std::declval<const P&>().x())>, float> {};
template <class InputMesh>
bool input_has_float32_points(const InputMesh& input) {
  if constexpr (has_float32_points_member<InputMesh>::value)
    return input.has_float32_points();
  else
    return has_float_x_coordinate<std::decay_t<decltype(input.point(std::size_t(0)))>>::value;
}

/// Checks the concept `PRStarOctreeInputMesh` (for an octree whose points are `Point_3`).
template <class InputMesh, class Point_3>
struct Check_input_mesh {
  static_assert(has_number_of_vertices<InputMesh>::value && has_number_of_tetrahedra<InputMesh>::value,
                "PR_star_octree_3: the input mesh must provide number_of_vertices() and "
                "number_of_tetrahedra() (see the concept PRStarOctreeInputMesh; use "
                "CGAL::PR_star_octree::make_input() to adapt index arrays or a C3T3)");
  static_assert(has_point_access<InputMesh, Point_3>::value,
                "PR_star_octree_3: the input mesh must provide point(i) returning the traits' Point_3 or a "
                "point with x(), y(), z() "
                "(see the concept PRStarOctreeInputMesh)");
  static_assert(has_tetrahedron_access<InputMesh>::value,
                "PR_star_octree_3: the input mesh must provide tetrahedron(t) returning four vertex indices "
                "(see the concept PRStarOctreeInputMesh)");
  static_assert(has_scalar_access<InputMesh>::value,
                "PR_star_octree_3: the input mesh must provide has_scalar_field() and scalar(i) "
                "(see the concept PRStarOctreeInputMesh)");
  static constexpr bool value = true;
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_CONCEPT_CHECKS_H
