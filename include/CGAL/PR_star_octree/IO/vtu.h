// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_VTU_H
#define CGAL_PR_STAR_OCTREE_IO_VTU_H

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/internal/vtu_reader.h>
#include <CGAL/PR_star_octree/IO/internal/vtu_writer.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

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
/// Several `<Piece>`s are concatenated (their vertex indices are local to each piece and they must
/// have the same point-data arrays).  The parser is this package's own and accepts attributes in
/// any order, either quote, comments, processing instructions and CDATA.
///
/// Read: the `Points` (3 components); `Cells` `connectivity`, `offsets` and `types`, every cell
/// having to be a tetrahedron (type 10) -- any other cell is an error naming the cell and its type;
/// every one-component `PointData` array becomes a point-data array named after its `Name`, in
/// file order (arrays with more components are skipped); a one-component `CellData` array named
/// `label` or `medit:ref` gives `tetrahedron_labels` (rounded).
///
/// Not supported (clear error): compressed data (`compressor` attribute set, e.g. zlib) in binary
/// or appended arrays; other dataset types.
///
/// \throws Read_error on any problem (malformed XML, missing element or attribute, wrong number of
/// values, truncated binary data, index out of range, non-finite coordinate...).  `mesh` is then
/// left unchanged; it is replaced on success.
template <class Mesh>
void read_vtu(const std::string& filename, Mesh& mesh) {
  const std::string text = internal::load_file(filename);
  internal::read_vtu_text(text, filename, mesh);
}

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to a stream as a VTK XML unstructured grid (`.vtu`): `Float64` points, `Int64`
/// connectivity and offsets, `UInt8` types (all 10), the point-data arrays of the mesh followed by
/// `extra_point_data` as `Float64` `PointData` (the first one declared as the active scalars),
/// and the labels, when the mesh has some, as the `Int32` `CellData` array `label`.
/// With `binary == false` the arrays are written in ascii with the shortest decimal form that
/// reads back exactly; with `binary == true` they are inline base64 (`header_type="UInt64"`,
/// little-endian), exact as well.
/// \throws Write_error when the stream fails, an extra array does not have one finite value per
/// vertex, two arrays have the same name, or the mesh is inconsistent.
template <class Mesh>
void write_vtu(std::ostream& out, const Mesh& mesh,
               const std::vector<Point_data_array>& extra_point_data = {}, bool binary = false,
               const std::string& name = "<stream>") {
  internal::check_mesh_for_writing(mesh, name);
  std::vector<const Point_data_array*> data;
  for (const auto& a : mesh.point_data) data.push_back(&a);
  for (const auto& a : extra_point_data) {
    internal::check_point_data_for_writing(a, mesh.points.size(), name);
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
  buf += "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
         "byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"";
  internal::append_integer(buf, nv);
  buf += "\" NumberOfCells=\"";
  internal::append_integer(buf, nt);
  buf += "\">\n";
  if (!data.empty()) {
    buf += "      <PointData Scalars=\"";
    internal::vtu_escape(buf, data.front()->name);
    buf += "\">\n";
    for (const Point_data_array* a : data)
      internal::vtu_write_array<double>(out, buf, name, "Float64", a->name, 1, nv, binary,
                                        [&](std::size_t i) { return a->values[i]; });
    buf += "      </PointData>\n";
  }
  if (!mesh.tetrahedron_labels.empty()) {
    buf += "      <CellData Scalars=\"label\">\n";
    internal::vtu_write_array<std::int32_t>(
        out, buf, name, "Int32", "label", 1, nt, binary,
        [&](std::size_t i) { return std::int32_t(mesh.tetrahedron_labels[i]); });
    buf += "      </CellData>\n";
  }
  buf += "      <Points>\n";
  internal::vtu_write_array<double>(out, buf, name, "Float64", "Points", 3, 3 * nv, binary,
                                    [&](std::size_t i) {
                                      const auto& p = mesh.points[i / 3];
                                      return CGAL::to_double(i % 3 == 0 ? p.x() : i % 3 == 1 ? p.y() : p.z());
                                    });
  buf += "      </Points>\n      <Cells>\n";
  internal::vtu_write_array<std::int64_t>(
      out, buf, name, "Int64", "connectivity", 1, 4 * nt, binary,
      [&](std::size_t i) { return std::int64_t(mesh.tetrahedra[i / 4][i % 4]); });
  internal::vtu_write_array<std::int64_t>(out, buf, name, "Int64", "offsets", 1, nt, binary,
                                          [&](std::size_t i) { return std::int64_t(4 * (i + 1)); });
  internal::vtu_write_array<std::uint8_t>(out, buf, name, "UInt8", "types", 1, nt, binary,
                                          [](std::size_t) { return std::uint8_t(10); });
  buf += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  internal::flush_buffer(out, buf, name, true);
}

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to the file `filename` as a VTK XML unstructured grid; see
/// `write_vtu(std::ostream&, const Mesh&, const std::vector<Point_data_array>&, bool, const std::string&)`.
/// \throws Write_error when the file cannot be written, or for the reasons given there.
template <class Mesh>
void write_vtu(const std::string& filename, const Mesh& mesh,
               const std::vector<Point_data_array>& extra_point_data = {}, bool binary = false) {
  internal::check_mesh_for_writing(mesh, filename);
  for (const auto& a : extra_point_data)
    internal::check_point_data_for_writing(a, mesh.points.size(), filename);
  std::ofstream out;
  internal::open_for_writing(out, filename);
  write_vtu(out, mesh, extra_point_data, binary, filename);
  internal::close_written(out, filename);
}

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_VTU_H
