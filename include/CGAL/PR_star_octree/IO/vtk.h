// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_VTK_H
#define CGAL_PR_STAR_OCTREE_IO_VTK_H

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/internal/vtk_legacy.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>
#include <CGAL/Named_function_parameters.h>

#include <fstream>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace IO {

/// \ingroup PkgPRStarOctreeIO
/// Reads a legacy VTK file (ASCII or binary) from a stream; `name` is used in error messages.  See
/// `read_vtk(const std::string&, Mesh&)`.
template <class Mesh>
void read_vtk(std::istream& in, Mesh& mesh, const std::string& name = "<stream>") {
  const std::string text = internal::load_stream(in, name);
  internal::read_vtk_text(text, name, mesh);
}

/// \ingroup PkgPRStarOctreeIO
/// Reads a tetrahedral mesh from a legacy VTK file (`.vtk`), ASCII or BINARY.
///
/// Expected: the header `# vtk DataFile Version x.y`, a title line, `ASCII` or `BINARY`,
/// `DATASET UNSTRUCTURED_GRID`, `POINTS n type`, the cells either as `CELLS n size` followed by
/// records `4 a b c d` (up to version 5.0) or as `CELLS nOffsets nConnectivity` followed by
/// `OFFSETS type` and `CONNECTIVITY type` arrays (version 5.1), and `CELL_TYPES n`.  In a binary
/// file the values of each section follow its keyword line as big-endian binary numbers of the
/// type named (`int` for the 4.x `CELLS` records and for `CELL_TYPES`), whatever the machine.
/// The tetrahedra (type 10) are kept; cells of other types are counted in `mesh.skipped_cells` by
/// type name; a file with cells but no tetrahedron is refused.
///
/// `POINT_DATA`: every one-component `SCALARS` array (`LOOKUP_TABLE` line optional) and every
/// one-component array of a `FIELD` becomes a point-data array, in file order (`%XX` escapes of
/// names decoded); arrays with several components, `VECTORS`, `NORMALS`, `TENSORS`,
/// `TEXTURE_COORDINATES`, `COLOR_SCALARS`, lookup tables, ids and `METADATA` blocks are skipped
/// (in ASCII their values are still checked to be numbers).  `CELL_DATA`: the first one-component
/// array named `label`, `labels`, `subdomain`, `CellEntityIds`, `gmsh:physical`, `medit:ref` or
/// `MaterialIds` with integer values gives `tetrahedron_labels`, the other one-component arrays
/// become `cell_data` (values of the tetrahedra only).  Keywords are case-insensitive; comments
/// are not part of the format.
///
/// \throws Read_error on any problem (other dataset, no tetrahedron, count mismatch, truncated
/// data, binary data of an unsupported type, index out of range, non-finite coordinate or point-data
/// value...). `mesh` is then left unchanged; it is replaced on success.
template <class Mesh>
void read_vtk(const std::string& filename, Mesh& mesh) {
  const internal::File_bytes bytes(filename); // not zero-filled, huge pages when large
  internal::read_vtk_text(bytes.view(), filename, mesh);
}

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to a stream as a legacy VTK file, version 4.2 (`DATASET UNSTRUCTURED_GRID`,
/// `CELLS n 5n` of tetrahedra, `CELL_TYPES` 10), readable by VTK 5 to 9, ParaView and meshio:
/// points in `double`, the point-data arrays of the mesh then `extra_point_data` as `POINT_DATA`
/// `SCALARS` (`double`), the labels as the `CELL_DATA` `SCALARS label int`, the cell-data arrays as
/// `SCALARS` (`double`); names with blanks are `%XX`-escaped.  ASCII (shortest exact decimal form)
/// by default, binary (big-endian, 32-bit cell indices) with `CGAL::parameters::use_binary_mode(true)`.
/// \tparam NamedParameters a sequence of named parameters
/// \param out the stream
/// \param mesh the mesh
/// \param extra_point_data per-vertex arrays written after those of the mesh
/// \param np `use_binary_mode` (default `false`)
/// \param name the name of the stream in error messages
/// \throws Write_error when the stream fails or the mesh or an array is inconsistent.
template <class Mesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
void write_vtk(std::ostream& out, const Mesh& mesh,
               const std::vector<Point_data_array>& extra_point_data = {},
               const NamedParameters& np = CGAL::parameters::default_values(),
               const std::string& name = "<stream>") {
  const bool binary = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, CGAL::internal_np::use_binary_mode), false);
  internal::write_vtk_stream(out, mesh, extra_point_data, binary, name);
}

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to the file `filename` as a legacy VTK file; see
/// `write_vtk(std::ostream&, const Mesh&, const std::vector<Point_data_array>&, const NamedParameters&, const
/// std::string&)`. \throws Write_error when the file cannot be written, or for the reasons given there.
template <class Mesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
void write_vtk(const std::string& filename, const Mesh& mesh,
               const std::vector<Point_data_array>& extra_point_data = {},
               const NamedParameters& np = CGAL::parameters::default_values()) {
  internal::check_mesh_for_writing(mesh, filename);
  for (const auto& a : extra_point_data)
    internal::check_point_data_for_writing(a, mesh.points.size(), filename);
  std::ofstream out;
  internal::open_for_writing(out, filename);
  write_vtk(out, mesh, extra_point_data, np, filename);
  internal::close_written(out, filename);
}

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_VTK_H
