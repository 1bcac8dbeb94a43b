// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTK_CELLS_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTK_CELLS_H

// What the legacy and the XML VTK readers share: names of the cell types, the conversion of
// (offsets, connectivity, types) arrays into tetrahedra with all the checks, the names of the
// cell-data arrays read as tetrahedron labels.

#include <CGAL/PR_star_octree/IO/internal/text.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {

inline const char* vtk_cell_type_name(long long type) {
  switch (type) {
  case 0:
    return "empty cell";
  case 1:
    return "vertex";
  case 2:
    return "poly-vertex";
  case 3:
    return "line";
  case 4:
    return "poly-line";
  case 5:
    return "triangle";
  case 6:
    return "triangle strip";
  case 7:
    return "polygon";
  case 8:
    return "pixel";
  case 9:
    return "quad";
  case 10:
    return "tetrahedron";
  case 11:
    return "voxel";
  case 12:
    return "hexahedron";
  case 13:
    return "wedge";
  case 14:
    return "pyramid";
  case 15:
    return "pentagonal prism";
  case 16:
    return "hexagonal prism";
  case 21:
    return "quadratic edge";
  case 22:
    return "quadratic triangle";
  case 23:
    return "quadratic quad";
  case 24:
    return "quadratic tetrahedron";
  case 25:
    return "quadratic hexahedron";
  case 26:
    return "quadratic wedge";
  case 27:
    return "quadratic pyramid";
  case 42:
    return "polyhedron";
  default:
    return "unknown cell type";
  }
}

/// Cell-data arrays with one of these names (the first one in the file whose values are all
/// integers) are read as tetrahedron labels: ours and meshio's `label`/`labels`, `subdomain`,
/// VTK's `CellEntityIds`, meshio's `gmsh:physical` and `medit:ref`, deal.II's `MaterialIds`.
inline bool is_vtk_label_array_name(const std::string& name) {
  return name == "label" || name == "labels" || name == "subdomain" || name == "CellEntityIds" ||
         name == "gmsh:physical" || name == "medit:ref" || name == "MaterialIds";
}

/// Whether every value is an integer in the range of `int` (a label array).
inline bool vtk_integer_valued(const std::vector<double>& values) {
  for (double v : values)
    if (!(v == std::floor(v) && v >= double(std::numeric_limits<int>::min()) &&
          v <= double(std::numeric_limits<int>::max())))
      return false;
  return true;
}

/// Appends to `tetrahedra` the tetrahedra among the cells given by `starts` (cell `i` is
/// `connectivity[starts[i] .. starts[i+1]-1]`, `starts.size()` is the number of cells + 1),
/// checking that every tetrahedron (VTK type 10) has 4 distinct vertex indices in `[0, nv)`;
/// `vertex_offset` is added to the indices (pieces of a VTU file).  The cells of other types are
/// counted in `skipped` by type name; `kept` receives one flag per cell (1 for a tetrahedron) when
/// some cell was skipped, and is left empty when every cell is a tetrahedron.  A non-empty list of
/// cells without any tetrahedron is not a tetrahedral mesh: refused.  `fail(message)` must throw.
template <class Tetrahedron, class Fail>
void vtk_cells_to_tetrahedra(const std::vector<long long>& starts, const std::vector<long long>& connectivity,
                             const std::vector<long long>& types, std::size_t nv, std::size_t vertex_offset,
                             std::vector<Tetrahedron>& tetrahedra, std::vector<char>& kept,
                             std::map<std::string, std::size_t>& skipped, const Fail& fail) {
  using Index = typename Tetrahedron::value_type;
  const std::size_t nc = starts.empty() ? 0 : starts.size() - 1;
  kept.clear();
  if (types.size() != nc)
    fail(std::to_string(types.size()) + " cell types for " + std::to_string(nc) + " cells");
  if (!starts.empty() && starts.front() != 0) fail("the first cell does not start at offset 0");
  if (!starts.empty() && static_cast<unsigned long long>(starts.back()) != connectivity.size())
    fail("the cell offsets end at " + std::to_string(starts.back()) + " but the connectivity has " +
         std::to_string(connectivity.size()) + " entries");
  std::size_t first_other = nc;
  for (std::size_t i = 0; i < nc; ++i) {
    if (starts[i + 1] < starts[i]) fail("cell offsets decrease at cell " + std::to_string(i));
    if (types[i] != 10) {
      if (first_other == nc) {
        first_other = i;
        kept.assign(nc, 1);
      }
      kept[i] = 0;
      ++skipped[vtk_cell_type_name(types[i])];
      continue;
    }
    if (starts[i + 1] - starts[i] != 4)
      fail("cell " + std::to_string(i) + " is a tetrahedron with " +
           std::to_string(starts[i + 1] - starts[i]) + " vertices instead of 4");
    Tetrahedron t;
    for (int k = 0; k < 4; ++k) {
      const long long v = connectivity[static_cast<std::size_t>(starts[i]) + k];
      if (v < 0 || static_cast<unsigned long long>(v) >= nv)
        fail("cell " + std::to_string(i) + ": vertex index " + std::to_string(v) +
             " out of range (0-based, " + std::to_string(nv) + " points)");
      const unsigned long long g = static_cast<unsigned long long>(v) + vertex_offset;
      if (g > static_cast<unsigned long long>(std::numeric_limits<Index>::max()))
        fail("vertex index " + std::to_string(g) + " does not fit in the index type of the mesh");
      t[k] = static_cast<Index>(g);
    }
    unsigned long long twice;
    if (has_repeated_vertex(t, twice))
      fail("cell " + std::to_string(i) + ": vertex index " + std::to_string(twice - vertex_offset) +
           " listed twice");
    tetrahedra.push_back(t);
  }
  if (nc > 0 && first_other == 0 && kept.size() == nc) {
    bool any = false;
    for (char k : kept) any = any || k;
    if (!any)
      fail("no tetrahedron among the " + std::to_string(nc) + " cells: cell 0 has VTK type " +
           std::to_string(types[0]) + " (" + vtk_cell_type_name(types[0]) +
           "), only tetrahedra (type 10) are read");
  }
}

/// Keeps the values of the cells flagged in `kept` (all of them when `kept` is empty).
template <class T>
void vtk_keep_cells(std::vector<T>& values, const std::vector<char>& kept) {
  if (kept.empty()) return;
  std::size_t j = 0;
  for (std::size_t i = 0; i < values.size() && i < kept.size(); ++i)
    if (kept[i]) values[j++] = values[i];
  values.resize(j);
}

/// Converts label values (read as doubles) to ints; `fail(message)` must throw.
template <class Fail>
void vtk_labels_to_int(const std::vector<double>& values, std::vector<int>& labels, const Fail& fail) {
  labels.reserve(labels.size() + values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double r = std::round(values[i]);
    if (!(r >= double(std::numeric_limits<int>::min()) && r <= double(std::numeric_limits<int>::max())))
      fail("label of cell " + std::to_string(i) + " is out of the int range");
    labels.push_back(static_cast<int>(r));
  }
}

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTK_CELLS_H
