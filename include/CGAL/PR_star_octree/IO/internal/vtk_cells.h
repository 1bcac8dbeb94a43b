// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTK_CELLS_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTK_CELLS_H

// What the legacy and the XML VTK readers share: names of the cell types, the conversion of
// (offsets, connectivity, types) arrays into tetrahedra with all the checks, the names of the
// cell-data arrays read as tetrahedron labels.

#include <CGAL/PR_star_octree/IO/internal/file_bytes.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <utility>
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

/// Builds the tetrahedra of a VTK cell list from its connectivity, given in order and in chunks:
/// `end(i)` is the end of cell `i` in the connectivity (cell 0 starts at 0), `types[i]` its VTK
/// type; `ends == nullptr` stands for the offsets of cells of 4 vertices each (`end(i) = 4(i+1)`,
/// not stored).  The constructor checks the offsets and the vertex count of every tetrahedron (VTK type
/// 10), counts the cells of other types in `skipped` by type name, fills `kept` with one flag per
/// cell (1 for a tetrahedron) when some cell is not a tetrahedron (left empty otherwise) and
/// reserves the tetrahedra; a non-empty list of cells without any tetrahedron is not a tetrahedral
/// mesh: refused.  Then `operator()(values, n)` takes the connectivity chunk by chunk, checking
/// every vertex index of a tetrahedron (in `[0, nv)`, 4 distinct ones); `vertex_offset` is added to
/// them (pieces of a VTU file).  `fail(message)` must throw.
template <class Tetrahedron, class Type>
class Vtk_tetrahedra_builder {
public:
  using Index = typename Tetrahedron::value_type;
  using Fail = std::function<void(const std::string&)>;

  Vtk_tetrahedra_builder(const long long* ends, const Type* types, std::size_t nc, std::size_t nv,
                         std::size_t vertex_offset, std::vector<Tetrahedron>& tetrahedra,
                         std::vector<char>& kept, std::map<std::string, std::size_t>& skipped, Fail fail)
      : ends_(ends), types_(types), nc_(nc), nv_(nv), vertex_offset_(vertex_offset), tetrahedra_(tetrahedra),
        fail_(std::move(fail)) {
    kept.clear();
    std::size_t tets = 0;
    long long start = 0;
    for (std::size_t i = 0; i < nc; ++i) {
      if (end(i) < start) fail_("cell offsets decrease at cell " + std::to_string(i));
      if (types[i] == 10) {
        if (end(i) - start != 4)
          fail_("cell " + std::to_string(i) + " is a tetrahedron with " + std::to_string(end(i) - start) +
                " vertices instead of 4");
        ++tets;
      } else {
        if (kept.empty()) kept.assign(nc, 1);
        kept[i] = 0;
        ++skipped[vtk_cell_type_name(static_cast<long long>(types[i]))];
      }
      start = end(i);
    }
    if (nc > 0 && tets == 0)
      fail_("no tetrahedron among the " + std::to_string(nc) + " cells: cell 0 has VTK type " +
            std::to_string(static_cast<long long>(types[0])) + " (" +
            vtk_cell_type_name(static_cast<long long>(types[0])) + "), only tetrahedra (type 10) are read");
    size_ = nc == 0 ? 0 : static_cast<std::size_t>(end(nc - 1));
    tetrahedra.reserve(tetrahedra.size() + tets);
    advise_huge_pages(tetrahedra.data() + tetrahedra.size(),
                      (tetrahedra.capacity() - tetrahedra.size()) * sizeof(Tetrahedron));
  }

  /// the end of cell `i` in the connectivity
  long long end(std::size_t i) const {
    return ends_ != nullptr ? ends_[i] : 4 * static_cast<long long>(i + 1);
  }

  /// the number of connectivity entries the offsets announce
  std::size_t size() const { return size_; }

  void reserve(std::size_t) {}

  void operator()(const long long* values, std::size_t n) {
    for (std::size_t j = 0; j < n; ++j, ++pos_) {
      if (pos_ >= size_)
        fail_("the connectivity has more than the " + std::to_string(size_) + " entries announced");
      while (static_cast<unsigned long long>(end(cell_)) <= pos_) ++cell_;
      if (types_[cell_] != 10) continue;
      const long long v = values[j];
      const std::size_t k = pos_ - static_cast<std::size_t>(cell_ == 0 ? 0 : end(cell_ - 1));
      if (v < 0 || static_cast<unsigned long long>(v) >= nv_)
        fail_("cell " + std::to_string(cell_) + ": vertex index " + std::to_string(v) +
              " out of range (0-based, " + std::to_string(nv_) + " points)");
      const unsigned long long g = static_cast<unsigned long long>(v) + vertex_offset_;
      if (g > static_cast<unsigned long long>(std::numeric_limits<Index>::max()))
        fail_("vertex index " + std::to_string(g) + " does not fit in the index type of the mesh");
      t_[k] = static_cast<Index>(g);
      if (k == 3) {
        unsigned long long twice;
        if (has_repeated_vertex(t_, twice))
          fail_("cell " + std::to_string(cell_) + ": vertex index " + std::to_string(twice - vertex_offset_) +
                " listed twice");
        tetrahedra_.push_back(t_);
      }
    }
  }

  /// Checks that the whole connectivity was given.
  void finish() {
    if (pos_ != size_)
      fail_("the cell offsets end at " + std::to_string(size_) + " but the connectivity has " +
            std::to_string(pos_) + " entries");
  }

private:
  const long long* ends_;
  const Type* types_;
  std::size_t nc_, nv_, vertex_offset_;
  std::vector<Tetrahedron>& tetrahedra_;
  Fail fail_;
  std::size_t size_ = 0, pos_ = 0, cell_ = 0;
  Tetrahedron t_{};
};

/// The tetrahedra of cells given by `starts` (cell `i` is `connectivity[starts[i] .. starts[i+1]-1]`,
/// `starts.size()` is the number of cells + 1), with the checks and outputs of
/// `Vtk_tetrahedra_builder`.  `fail(message)` must throw.
template <class Tetrahedron, class Fail>
void vtk_cells_to_tetrahedra(const std::vector<long long>& starts, const std::vector<long long>& connectivity,
                             const std::vector<long long>& types, std::size_t nv, std::size_t vertex_offset,
                             std::vector<Tetrahedron>& tetrahedra, std::vector<char>& kept,
                             std::map<std::string, std::size_t>& skipped, const Fail& fail) {
  const std::size_t nc = starts.empty() ? 0 : starts.size() - 1;
  kept.clear();
  if (types.size() != nc)
    fail(std::to_string(types.size()) + " cell types for " + std::to_string(nc) + " cells");
  if (!starts.empty() && starts.front() != 0) fail("the first cell does not start at offset 0");
  if (!starts.empty() && static_cast<unsigned long long>(starts.back()) != connectivity.size())
    fail("the cell offsets end at " + std::to_string(starts.back()) + " but the connectivity has " +
         std::to_string(connectivity.size()) + " entries");
  if (nc == 0) return;
  Vtk_tetrahedra_builder<Tetrahedron, long long> b(starts.data() + 1, types.data(), nc, nv, vertex_offset,
                                                   tetrahedra, kept, skipped,
                                                   [&](const std::string& m) { fail(m); });
  b(connectivity.data(), connectivity.size());
  b.finish();
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
