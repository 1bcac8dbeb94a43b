// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_VTU_H
#define CGAL_PR_STAR_OCTREE_IO_VTU_H

/// \file vtu.h
/// Reading and writing VTK XML unstructured grids (`.vtu`).

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/Write_options.h>
#include <CGAL/PR_star_octree/IO/internal/file_bytes.h>
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
/// of the tetrahedra only).  `Float32` points (in every piece) set `mesh.float32_points`; in ascii
/// their values are rounded to the nearest floats, as VTK reads them.
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

/// What the VTK XML writer accepts: binary (inline base64 data, default) or ascii, zlib compression
/// (default when the build has zlib), version 1.0.
inline constexpr Write_support vtu_write_support{
    true, true, true, true, true, {"1.0", nullptr, nullptr, nullptr}, nullptr};

template <class Mesh>
void write_vtu_stream(std::ostream& out, const Mesh& mesh, const std::vector<Data_array>& extra_point_data,
                      const Write_options& given, const std::string& name) {
  const Write_options o = resolve_write_options(given, vtu_write_support, "VTK XML", name);
  const std::vector<const Data_array*> data = check_named_arrays_for_writing(mesh, extra_point_data, name);
  const bool float32 = write_float32_points(mesh, name);
  const std::size_t nv = mesh.points.size(), nt = mesh.tetrahedra.size();
  std::string buf;
  Vtu_array_writer w(out, buf, name, o.binary, o.compression == Compression::zlib);
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
    xml_escape(buf, data.front()->name);
    buf += "\">\n";
    for (const Data_array* a : data)
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
    for (const Data_array& a : mesh.cell_data)
      w.write<double>("Float64", a.name, 1, nt, [&](std::size_t i) { return a.values[i]; });
    buf += "      </CellData>\n";
  }
  buf += "      <Points>\n";
  const auto coordinate = [&](std::size_t i) {
    const auto& p = mesh.points[i / 3];
    return CGAL::to_double(i % 3 == 0 ? p.x() : i % 3 == 1 ? p.y() : p.z());
  };
  if (float32)
    w.write<float>("Float32", "Points", 3, 3 * nv,
                   [&](std::size_t i) { return static_cast<float>(coordinate(i)); });
  else
    w.write<double>("Float64", "Points", 3, 3 * nv, coordinate);
  buf += "      </Points>\n      <Cells>\n";
  w.write<std::int64_t>("Int64", "connectivity", 1, 4 * nt,
                        [&](std::size_t i) { return std::int64_t(mesh.tetrahedra[i / 4][i % 4]); });
  w.write<std::int64_t>("Int64", "offsets", 1, nt, [&](std::size_t i) { return std::int64_t(4 * (i + 1)); });
  w.write<std::uint8_t>("UInt8", "types", 1, nt, [](std::size_t) { return std::uint8_t(10); });
  buf += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n";
  buf += "</VTKFile>\n";
  flush_buffer(out, buf, name, true);
}

template <class Mesh>
void write_vtu_file(const std::string& filename, const Mesh& mesh,
                    const std::vector<Data_array>& extra_point_data, const Write_options& given) {
  resolve_write_options(given, vtu_write_support, "VTK XML", filename);
  check_named_arrays_for_writing(mesh, extra_point_data, filename);
  write_float32_points(mesh, filename); // its checks, before the file is created
  std::ofstream out;
  open_for_writing(out, filename);
  write_vtu_stream(out, mesh, extra_point_data, given, filename);
  close_written(out, filename);
}

} // namespace internal

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to a stream as a VTK XML unstructured grid (`.vtu`, version 1.0,
/// `header_type="UInt64"`): `Float64` points (`Float32` when `mesh.float32_points` is set),
/// `Int64` connectivity and offsets, `UInt8` types (all 10), the point-data arrays of the mesh
/// followed by `extra_point_data` as `Float64` `PointData`
/// (the first one declared as the active scalars), the labels, when the mesh has some, as the
/// `Int32` `CellData` array `label` (the active cell scalars), then the cell-data arrays of the
/// mesh as `Float64` `CellData`.
///
/// By default the arrays are binary, compressed with zlib (`compressor="vtkZLibDataCompressor"`,
/// blocks of 32 KiB; uncompressed when the build has no zlib) and base64-encoded inline
/// (`format="binary"`), as VTK writes them in its binary data mode; with `use_binary_mode(false)`
/// they are written in ascii with the shortest decimal form that reads back exactly.  Both are
/// exact.  The data are inline rather than appended because the VTK 9.1/9.2 of Debian 12
/// (ParaView 5.11 included) cannot read appended data, raw or base64, with the libexpat of Debian
/// 12's current point releases; inline data are read by every VTK version and by meshio.
///
/// \tparam NamedParameters a sequence of named parameters
/// \param out the stream
/// \param mesh the mesh
/// \param extra_point_data per-vertex arrays written after those of the mesh
/// \param np the write options (`Write_options.h`)
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{use_binary_mode}
///     \cgalParamDescription{binary (`true`: inline base64 data, little-endian) or
///       ascii (`false`)}
///     \cgalParamType{Boolean}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{compression}
///     \cgalParamDescription{`Compression::zlib` (blocks of 32 KiB, binary only) or `Compression::none`}
///     \cgalParamType{`CGAL::PR_star_octree::IO::Compression`}
///     \cgalParamDefault{`Compression::zlib` in binary when the build has zlib, else `Compression::none`}
///   \cgalParamNEnd
///   \cgalParamNBegin{format_version}
///     \cgalParamDescription{1.0 only}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1.0}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \param name the name of the stream in error messages
/// \throws Write_error when the stream fails, an array does not have one finite value per vertex
/// (per tetrahedron for cell data), two arrays have the same name, the mesh is inconsistent, or an
/// option is not possible.
template <class Mesh, class NamedParameters = parameters::Default_named_parameters>
void write_vtu(std::ostream& out, const Mesh& mesh, const std::vector<Data_array>& extra_point_data = {},
               const NamedParameters& np = parameters::default_values(),
               const std::string& name = "<stream>") {
  internal::write_vtu_stream(out, mesh, extra_point_data, internal::write_options(np), name);
}

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to the file `filename` as a VTK XML unstructured grid; see
/// `write_vtu(std::ostream&, const Mesh&, const std::vector<Data_array>&, const NamedParameters&, const
/// std::string&)`, whose options it takes.
/// \throws Write_error when the file cannot be written, or for the reasons given there.
template <class Mesh, class NamedParameters = parameters::Default_named_parameters>
void write_vtu(const std::string& filename, const Mesh& mesh,
               const std::vector<Data_array>& extra_point_data = {},
               const NamedParameters& np = parameters::default_values()) {
  internal::write_vtu_file(filename, mesh, extra_point_data, internal::write_options(np));
}

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_VTU_H
