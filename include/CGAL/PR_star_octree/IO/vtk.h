// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_VTK_H
#define CGAL_PR_STAR_OCTREE_IO_VTK_H

/// \file vtk.h
/// Reading and writing legacy VTK `.vtk` files (ASCII and binary).

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/Write_options.h>
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
/// type name; a file with cells but no tetrahedron is refused.  `POINTS n float` (or
/// `vtktypefloat32`) sets `mesh.float32_points`, ASCII values being rounded to floats as VTK does.
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

namespace internal {

/// What the legacy VTK writer accepts: ASCII (default) or binary, versions 4.2 (default) and 5.1.
inline constexpr Write_support vtk_write_support{
    true, true, false, false, false, {"4.2", "5.1", nullptr, nullptr}, nullptr};

template <class Mesh>
void write_vtk_options(std::ostream& out, const Mesh& mesh, const std::vector<Data_array>& extra_point_data,
                       const Write_options& given, const std::string& name) {
  const Write_options o = resolve_write_options(given, vtk_write_support, "legacy VTK", name);
  write_vtk_stream(out, mesh, extra_point_data, o.binary, version_tenths(o.version) == 51, name);
}

template <class Mesh>
void write_vtk_file(const std::string& filename, const Mesh& mesh,
                    const std::vector<Data_array>& extra_point_data, const Write_options& given) {
  resolve_write_options(given, vtk_write_support, "legacy VTK", filename);
  check_named_arrays_for_writing(mesh, extra_point_data, filename);
  write_float32_points(mesh, filename); // its checks, before the file is created
  std::ofstream out;
  open_for_writing(out, filename);
  write_vtk_options(out, mesh, extra_point_data, given, filename);
  close_written(out, filename);
}

} // namespace internal

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to a stream as a legacy VTK file, version 4.2 (`DATASET UNSTRUCTURED_GRID`,
/// `CELLS n 5n` of tetrahedra, `CELL_TYPES` 10), readable by VTK 5 to 9, ParaView and meshio, or
/// version 5.1 (`CELLS n+1 4n` then `OFFSETS` and `CONNECTIVITY` arrays of `vtktypeint64`, VTK 9):
/// points in `double` (`float` when `mesh.float32_points` is set, in ASCII with the shortest text
/// that reads back as the same float), the point-data arrays of the mesh then `extra_point_data` as
/// `POINT_DATA` (the first one as `SCALARS`, the others in a `FIELD`, all `double`), the labels as the
/// `CELL_DATA` `SCALARS label int`, the cell-data arrays as `double` arrays; names with blanks are
/// `%XX`-escaped.  ASCII (shortest exact decimal form) by default, binary (big-endian; 32-bit
/// cell indices in 4.2, 64-bit in 5.1) with `use_binary_mode(true)`.
/// \tparam NamedParameters a sequence of named parameters
/// \param out the stream
/// \param mesh the mesh
/// \param extra_point_data per-vertex arrays written after those of the mesh
/// \param np the write options (`Write_options.h`)
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{use_binary_mode}
///     \cgalParamDescription{binary (`true`, big-endian) or ASCII (`false`)}
///     \cgalParamType{Boolean}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{format_version}
///     \cgalParamDescription{4.2 (`CELLS` records) or 5.1 (`OFFSETS` and `CONNECTIVITY`)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{4.2}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \param name the name of the stream in error messages
/// \throws Write_error when the stream fails, the mesh or an array is inconsistent (an array
/// without one finite value per vertex, or per tetrahedron for cell data, two arrays with the same
/// name), or an option is not possible.
template <class Mesh, class NamedParameters = parameters::Default_named_parameters>
void write_vtk(std::ostream& out, const Mesh& mesh, const std::vector<Data_array>& extra_point_data = {},
               const NamedParameters& np = parameters::default_values(),
               const std::string& name = "<stream>") {
  internal::write_vtk_options(out, mesh, extra_point_data, internal::write_options(np), name);
}

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to the file `filename` as a legacy VTK file; see
/// `write_vtk(std::ostream&, const Mesh&, const std::vector<Data_array>&, const NamedParameters&, const
/// std::string&)`, whose options it takes.
/// \throws Write_error when the file cannot be written, or for the reasons given there.
template <class Mesh, class NamedParameters = parameters::Default_named_parameters>
void write_vtk(const std::string& filename, const Mesh& mesh,
               const std::vector<Data_array>& extra_point_data = {},
               const NamedParameters& np = parameters::default_values()) {
  internal::write_vtk_file(filename, mesh, extra_point_data, internal::write_options(np));
}

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_VTK_H
