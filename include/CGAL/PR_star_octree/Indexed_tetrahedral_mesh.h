// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INDEXED_TETRAHEDRAL_MESH_H
#define CGAL_PR_STAR_OCTREE_INDEXED_TETRAHEDRAL_MESH_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace PR_star_octree {

/// \ingroup PkgPRStarOctreeRef
/// A named scalar array: one value per vertex (VTK "point data", `Indexed_tetrahedral_mesh::point_data`)
/// or one value per tetrahedron (VTK "cell data", `Indexed_tetrahedral_mesh::cell_data`).
struct Data_array {
  std::string name;           ///< the name of the array (VTK's `Name`)
  std::vector<double> values; ///< one value per vertex or per tetrahedron
};

/// \ingroup PkgPRStarOctreeRef
/// \deprecated The former name of `Data_array`, which holds cell data as well as point data.
using Point_data_array = Data_array;

/// \ingroup PkgPRStarOctreeRef
/// The plain indexed representation of a tetrahedral mesh (paper Section 2.3): an array of
/// points `V` and an array of tetrahedra `T`, each given by the indices of its four vertices
/// (0-based).  Optional data: named per-vertex scalar arrays (the first one is "the" scalar field
/// used by default) and an integer label per tetrahedron (Medit reference, subdomain index).
///
/// This is what the readers of `CGAL/PR_star_octree/IO/` produce and the writers consume; it is a
/// model of `PRStarOctreeInputMesh` through `CGAL::PR_star_octree::make_input()`.
///
/// \tparam Point_3_ the point type (default: `Exact_predicates_inexact_constructions_kernel::Point_3`)
/// \tparam Index_ an unsigned integer type for vertex indices (default: 32 bits)
template <class Point_3_ = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3,
          class Index_ = std::uint32_t>
struct Indexed_tetrahedral_mesh {
  using Point_3 = Point_3_;
  using Index = Index_;
  using Tetrahedron = std::array<Index, 4>;

  std::vector<Point_3> points;
  /// whether the file stored the coordinates as 32-bit floats (VTK `Float32`, a MEDIT `.meshb` of
  /// version 1, an XDMF `Precision="4"`): `points` hold those values exactly, and the octree keeps
  /// them as floats unless asked otherwise (named parameter `coordinate_precision`); writers then
  /// write 32-bit coordinates again where the format has them
  bool float32_points = false;
  std::vector<Tetrahedron> tetrahedra;
  /// empty, or one label per tetrahedron
  std::vector<int> tetrahedron_labels;
  /// each array has `points.size()` values
  std::vector<Data_array> point_data;
  /// per-tetrahedron scalar arrays other than the labels (VTK cell data); each has
  /// `tetrahedra.size()` values
  std::vector<Data_array> cell_data;
  /// the names of the labels, when the file has them (gmsh `$PhysicalNames`): label -> name
  std::map<int, std::string> label_names;
  /// the cells of other types a reader met and did not keep, by type name (e.g. `"triangle"`),
  /// so that a caller can report them
  std::map<std::string, std::size_t> skipped_cells;

  std::size_t number_of_vertices() const { return points.size(); }
  std::size_t number_of_tetrahedra() const { return tetrahedra.size(); }

  /// the first point-data array, or `nullptr` when there is none
  const Data_array* scalar_field() const { return point_data.empty() ? nullptr : &point_data.front(); }

  /// the point-data array named `name`, or `nullptr`
  const Data_array* find_point_data(const std::string& name) const {
    for (const Data_array& a : point_data)
      if (a.name == name) return &a;
    return nullptr;
  }
};

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INDEXED_TETRAHEDRAL_MESH_H
