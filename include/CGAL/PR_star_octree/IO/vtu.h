// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_VTU_H
#define CGAL_PR_STAR_OCTREE_IO_VTU_H

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/internal/gmsh_bytes.h>
#include <CGAL/PR_star_octree/IO/internal/vtu_reader.h>
#include <CGAL/PR_star_octree/IO/internal/vtu_writer.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <CGAL/Named_function_parameters.h>

#include <cmath>
#include <fstream>
#include <istream>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace IO {

/// \ingroup PkgPRStarOctreeIO
/// Reads a VTK XML unstructured grid from a stream; `name` is used in error messages.  See
/// `read_vtu(const std::string&, Mesh&)`.
template <class Mesh>
void read_vtu(std::istream& in, Mesh& mesh, const std::string& name = "<stream>") {
  const std::string text = internal::load_stream(in, name);
  internal::read_vtu_text(text, name, mesh);
}

/// \ingroup PkgPRStarOctreeIO
/// Reads a tetrahedral mesh from a VTK XML unstructured-grid file (`.vtu`).
///
/// Supported: `<VTKFile type="UnstructuredGrid">` with `byte_order` `LittleEndian` or
/// `BigEndian` (swapped), `header_type` `UInt32` (default) or `UInt64`; data arrays of types
/// `Int8` ... `UInt64`, `Float32`, `Float64` in the formats `ascii`, `binary` (inline base64:
/// the byte count header then the data, encoded together or as two blocks) and `appended`
/// (`<AppendedData encoding="raw">` or `encoding="base64"`, arrays located by their `offset`).
/// Compressed data (`compressor` `vtkZLibDataCompressor`, `vtkLZ4DataCompressor` or
/// `vtkLZMADataCompressor`, as ParaView, VTK and meshio write them): the block header (number of
/// blocks, block size, size of the last partial block, compressed size of each block) then the
/// blocks, in every one of these encodings; each compressor needs its library (zlib, liblz4,
/// liblzma) to have been found when the program was built, otherwise such a file is refused by
/// name.  Every announced size is checked against the file before anything is allocated: block
/// sizes against the bytes present, decompressed sizes against the compressed ones (at most the
/// largest ratio the compressor can reach), so that a header announcing terabytes is refused.
/// Several `<Piece>`s are concatenated (their vertex indices are local to each piece and they must
/// have the same point- and cell-data arrays).  The parser is this package's own and accepts
/// attributes in any order, either quote, comments, processing instructions and CDATA.
///
/// Read: the `Points` (3 components); `Cells` `connectivity`, `offsets` and `types` (any integer
/// types): the tetrahedra (type 10) are kept, in file order; the cells of other types are counted
/// in `mesh.skipped_cells` by type name (`"triangle"`, `"hexahedron"`...), and a file with cells
/// but no tetrahedron is refused.  Every one-component `PointData` array becomes a point-data
/// array named after its `Name`, in file order (arrays with more components are skipped).  In
/// `CellData`, the first one-component array named `label`, `labels`, `subdomain`,
/// `CellEntityIds`, `gmsh:physical`, `medit:ref` or `MaterialIds` whose values are all integers
/// gives `tetrahedron_labels`; every other one-component array becomes a `cell_data` array (values
/// of the tetrahedra only).
///
/// \throws Read_error on any problem (malformed XML, missing element or attribute, wrong number of
/// values, truncated binary data, corrupt or truncated compressed block, sizes that disagree, index
/// out of range, non-finite coordinate...).  `mesh` is then
/// left unchanged; it is replaced on success.
template <class Mesh>
void read_vtu(const std::string& filename, Mesh& mesh) {
  const internal::File_bytes bytes(filename); // not zero-filled, huge pages when large
  internal::read_vtu_text(bytes.view(), filename, mesh);
}

namespace internal {

/// Checks the cell-data arrays of a mesh before writing: one finite value per tetrahedron, a name.
template <class Mesh>
void check_cell_data_for_writing(const Mesh& mesh, const std::string& name) {
  for (const Point_data_array& a : mesh.cell_data) {
    if (a.name.empty()) throw Write_error(name, "a cell data array has an empty name");
    if (a.values.size() != mesh.tetrahedra.size())
      throw Write_error(name, "cell data '" + a.name + "' has " + std::to_string(a.values.size()) +
                                  " values for " + std::to_string(mesh.tetrahedra.size()) + " tetrahedra");
    for (std::size_t i = 0; i < a.values.size(); ++i)
      if (!std::isfinite(a.values[i]))
        throw Write_error(name, "cell data '" + a.name + "': value " + std::to_string(i) + " is not finite");
    if (a.name == "label" && !mesh.tetrahedron_labels.empty())
      throw Write_error(name, "a cell data array is named 'label', the name of the labels");
  }
  for (std::size_t i = 0; i < mesh.cell_data.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (mesh.cell_data[i].name == mesh.cell_data[j].name)
        throw Write_error(name, "two cell data arrays are named '" + mesh.cell_data[i].name + "'");
}

template <class Mesh>
void write_vtu_encoded(std::ostream& out, const Mesh& mesh,
                       const std::vector<Point_data_array>& extra_point_data, Vtu_encoding encoding,
                       const std::string& name) {
  check_mesh_for_writing(mesh, name);
  check_cell_data_for_writing(mesh, name);
  std::vector<const Point_data_array*> data;
  for (const auto& a : mesh.point_data) data.push_back(&a);
  for (const auto& a : extra_point_data) {
    check_point_data_for_writing(a, mesh.points.size(), name);
    data.push_back(&a);
  }
  for (std::size_t i = 0; i < data.size(); ++i) {
    if (data[i]->name.empty()) throw Write_error(name, "a point data array has an empty name");
    for (std::size_t j = 0; j < i; ++j)
      if (data[i]->name == data[j]->name)
        throw Write_error(name, "two point data arrays are named '" + data[i]->name + "'");
  }
  const std::size_t nv = mesh.points.size(), nt = mesh.tetrahedra.size();
  std::string buf;
  Vtu_array_writer w(out, buf, name, encoding);
  buf += "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
         "byte_order=\"LittleEndian\" header_type=\"UInt64\"";
  buf += w.compressor_attribute();
  buf += ">\n  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"";
  append_integer(buf, nv);
  buf += "\" NumberOfCells=\"";
  append_integer(buf, nt);
  buf += "\">\n";
  if (!data.empty()) {
    buf += "      <PointData Scalars=\"";
    vtu_escape(buf, data.front()->name);
    buf += "\">\n";
    for (const Point_data_array* a : data)
      w.write<double>("Float64", a->name, 1, nv, [&](std::size_t i) { return a->values[i]; });
    buf += "      </PointData>\n";
  }
  if (!mesh.tetrahedron_labels.empty() || !mesh.cell_data.empty()) {
    buf += "      <CellData";
    if (!mesh.tetrahedron_labels.empty()) buf += " Scalars=\"label\"";
    buf += ">\n";
    if (!mesh.tetrahedron_labels.empty())
      w.write<std::int32_t>("Int32", "label", 1, nt,
                            [&](std::size_t i) { return std::int32_t(mesh.tetrahedron_labels[i]); });
    for (const Point_data_array& a : mesh.cell_data)
      w.write<double>("Float64", a.name, 1, nt, [&](std::size_t i) { return a.values[i]; });
    buf += "      </CellData>\n";
  }
  buf += "      <Points>\n";
  w.write<double>("Float64", "Points", 3, 3 * nv, [&](std::size_t i) {
    const auto& p = mesh.points[i / 3];
    return CGAL::to_double(i % 3 == 0 ? p.x() : i % 3 == 1 ? p.y() : p.z());
  });
  buf += "      </Points>\n      <Cells>\n";
  w.write<std::int64_t>("Int64", "connectivity", 1, 4 * nt,
                        [&](std::size_t i) { return std::int64_t(mesh.tetrahedra[i / 4][i % 4]); });
  w.write<std::int64_t>("Int64", "offsets", 1, nt, [&](std::size_t i) { return std::int64_t(4 * (i + 1)); });
  w.write<std::uint8_t>("UInt8", "types", 1, nt, [](std::size_t) { return std::uint8_t(10); });
  buf += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n";
  w.finish();
  buf += "</VTKFile>\n";
  flush_buffer(out, buf, name, true);
}

template <class Mesh>
void write_vtu_file(const std::string& filename, const Mesh& mesh,
                    const std::vector<Point_data_array>& extra_point_data, Vtu_encoding encoding) {
  check_mesh_for_writing(mesh, filename);
  check_cell_data_for_writing(mesh, filename);
  for (const auto& a : extra_point_data) check_point_data_for_writing(a, mesh.points.size(), filename);
  std::ofstream out;
  open_for_writing(out, filename);
  write_vtu_encoded(out, mesh, extra_point_data, encoding, filename);
  close_written(out, filename);
}

template <class NP>
Vtu_encoding vtu_encoding_from(const NP& np) {
  const bool binary = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, CGAL::internal_np::use_binary_mode), true);
  return binary ? Vtu_encoding::APPENDED : Vtu_encoding::ASCII;
}

} // namespace internal

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to a stream as a VTK XML unstructured grid (`.vtu`): `Float64` points, `Int64`
/// connectivity and offsets, `UInt8` types (all 10), the point-data arrays of the mesh followed by
/// `extra_point_data` as `Float64` `PointData` (the first one declared as the active scalars),
/// the labels, when the mesh has some, as the `Int32` `CellData` array `label` (the active cell
/// scalars), then the cell-data arrays of the mesh as `Float64` `CellData`.
///
/// By default the arrays are appended raw binary data compressed with zlib as ParaView writes them
/// (`header_type="UInt64"`, `compressor="vtkZLibDataCompressor"`, blocks of 32 KiB; uncompressed
/// when the build has no zlib); with `CGAL::parameters::use_binary_mode(false)` they are written in
/// ascii with the shortest decimal form that reads back exactly.  Both are exact.
///
/// \tparam NamedParameters a sequence of named parameters
/// \param out the stream
/// \param mesh the mesh
/// \param extra_point_data per-vertex arrays written after those of the mesh
/// \param np `use_binary_mode` (default `true`: appended, zlib-compressed)
/// \param name the name of the stream in error messages
/// \throws Write_error when the stream fails, an array does not have one finite value per vertex
/// (per tetrahedron for cell data), two arrays have the same name, or the mesh is inconsistent.
template <class Mesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
void write_vtu(std::ostream& out, const Mesh& mesh,
               const std::vector<Point_data_array>& extra_point_data = {},
               const NamedParameters& np = CGAL::parameters::default_values(),
               const std::string& name = "<stream>") {
  internal::write_vtu_encoded(out, mesh, extra_point_data, internal::vtu_encoding_from(np), name);
}

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to a stream as a VTK XML unstructured grid in ascii (`binary == false`) or
/// uncompressed inline base64 (`binary == true`, `format="binary"`, `header_type="UInt64"`).
/// \throws Write_error as the other overload.
template <class Mesh>
void write_vtu(std::ostream& out, const Mesh& mesh, const std::vector<Point_data_array>& extra_point_data,
               bool binary, const std::string& name = "<stream>") {
  internal::write_vtu_encoded(out, mesh, extra_point_data,
                              binary ? internal::Vtu_encoding::INLINE_BASE64 : internal::Vtu_encoding::ASCII,
                              name);
}

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to the file `filename` as a VTK XML unstructured grid, by default appended and
/// zlib-compressed (ascii with `CGAL::parameters::use_binary_mode(false)`); see
/// `write_vtu(std::ostream&, const Mesh&, const std::vector<Point_data_array>&, const NamedParameters&, const
/// std::string&)`. \throws Write_error when the file cannot be written, or for the reasons given there.
template <class Mesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
void write_vtu(const std::string& filename, const Mesh& mesh,
               const std::vector<Point_data_array>& extra_point_data = {},
               const NamedParameters& np = CGAL::parameters::default_values()) {
  internal::write_vtu_file(filename, mesh, extra_point_data, internal::vtu_encoding_from(np));
}

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to the file `filename` in ascii (`binary == false`) or uncompressed inline base64
/// (`binary == true`).
/// \throws Write_error as the other overloads.
template <class Mesh>
void write_vtu(const std::string& filename, const Mesh& mesh,
               const std::vector<Point_data_array>& extra_point_data, bool binary) {
  internal::write_vtu_file(filename, mesh, extra_point_data,
                           binary ? internal::Vtu_encoding::INLINE_BASE64 : internal::Vtu_encoding::ASCII);
}

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_VTU_H
