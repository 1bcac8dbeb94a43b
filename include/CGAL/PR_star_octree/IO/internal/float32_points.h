// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_FLOAT32_POINTS_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_FLOAT32_POINTS_H

// Points stored as 32-bit floats (issue 24): the `float32_points` flag of a mesh, as the readers set
// it and the writers read it, for any mesh type (a mesh without the flag is a mesh of doubles).

#include <CGAL/PR_star_octree/IO/Read_error.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {

/// Whether `Mesh` has a non-static data member `float32_points` convertible to `bool`, as
/// `Indexed_tetrahedral_mesh` has (a member function of that name does not count): the readers set
/// it when the file stored the coordinates as 32-bit floats, and the writers then write 32-bit
/// coordinates where the format has them.  A mesh type without it is read and written as doubles.
template <class Mesh, class = void>
struct has_float32_points : std::false_type {};

template <class Mesh>
struct has_float32_points<
    Mesh, std::enable_if_t<std::is_member_object_pointer<decltype(&Mesh::float32_points)>::value>>
    : std::is_convertible<decltype(std::declval<const Mesh&>().float32_points), bool> {};

/// The `float32_points` flag of `mesh`; false for a mesh type without it.
template <class Mesh>
bool mesh_float32_points(const Mesh& mesh) {
  if constexpr (has_float32_points<Mesh>::value) {
    return static_cast<bool>(mesh.float32_points);
  } else {
    (void)mesh;
    return false;
  }
}

/// Sets the `float32_points` flag of `mesh` (nothing for a mesh type without it).
template <class Mesh>
void set_float32_points(Mesh& mesh, bool value) {
  if constexpr (has_float32_points<Mesh>::value) {
    mesh.float32_points = value;
  } else {
    (void)mesh;
    (void)value;
  }
}

/// `v` rounded to the nearest float, as a double.  Through a volatile float: GCC 12.2's SLP
/// vectorizer drops the two conversions of `double(float(v))` applied to the coordinates of points
/// in a loop (at -O2 and -O3: the values come back unrounded), a volatile store it cannot drop.
inline double rounded_to_float(double v) {
  volatile float f = static_cast<float>(v);
  return f;
}

/// Whether a finite `v` rounds to a finite float (|v| at most `FLT_MAX` once rounded).
inline bool fits_float(double v) {
  return std::isfinite(static_cast<float>(v));
}

/// The points `[first, end)` of `points` rounded to 32-bit floats, when all their coordinates fit
/// in a float: what a reader does with the decimal text of an array the file types as 32-bit floats
/// (as VTK does).  Returns false, the points unchanged, when a coordinate is out of the float range
/// (the file is then read as doubles).
template <class Points>
bool round_points_to_float(Points& points, std::size_t first) {
  using Point_3 = typename Points::value_type;
  for (std::size_t i = first; i < points.size(); ++i) {
    const Point_3& p = points[i];
    if (!fits_float(CGAL::to_double(p.x())) || !fits_float(CGAL::to_double(p.y())) ||
        !fits_float(CGAL::to_double(p.z())))
      return false;
  }
  const auto f = [](const auto& c) { return rounded_to_float(CGAL::to_double(c)); };
  for (std::size_t i = first; i < points.size(); ++i) {
    const Point_3& p = points[i];
    points[i] = Point_3(f(p.x()), f(p.y()), f(p.z()));
  }
  return true;
}

/// Whether a writer writes the coordinates of `mesh` as 32-bit floats: when its flag is set.  Each
/// coordinate is then rounded to the nearest float (exact for the points a reader read as floats);
/// throws `Write_error` when one is beyond the float range.
template <class Mesh>
bool write_float32_points(const Mesh& mesh, const std::string& name) {
  if (!mesh_float32_points(mesh)) return false;
  for (std::size_t i = 0; i < mesh.points.size(); ++i) {
    const auto& p = mesh.points[i];
    if (!fits_float(CGAL::to_double(p.x())) || !fits_float(CGAL::to_double(p.y())) ||
        !fits_float(CGAL::to_double(p.z())))
      throw Write_error(name, "vertex " + std::to_string(i) +
                                  " has a coordinate beyond the range of 32-bit floats, and the mesh has "
                                  "float32_points set");
  }
  return true;
}

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_FLOAT32_POINTS_H
