// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_PVTU_WRITER_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_PVTU_WRITER_H

// A distributed mesh as VTK XML files: one `.vtu` piece per part (e.g. per MPI rank, each written
// by its own process) and the `.pvtu` that lists them, with VTK's ghost and global-id arrays.  No
// MPI here: the caller decides who writes what.  The pieces are written as inline base64 binary
// data streamed through a small buffer (a piece can be gigabytes: nothing is copied whole), every
// file through a temporary name renamed at the end.

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/internal/file_bytes.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>
#include <CGAL/PR_star_octree/IO/internal/vtu_writer.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <fstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#endif

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {

/// One piece of a distributed tetrahedral mesh, as views of the caller's arrays (nothing is
/// copied).  A null pointer means "no such array" (except `xyz` and `tetrahedra`, required when
/// their count is not 0, and the arrays of `point_arrays` and `cell_arrays`, which exist by being
/// listed and may be null when there are no values).  Beware that `std::vector::data()` may be
/// null for an empty vector: a piece without points or cells must still give non-null pointers
/// (any address: nothing is read) for the ghost, id and label arrays the other pieces have, or
/// VTK's `.pvtu` reader reports them missing (an error, though it reads the mesh).
struct Vtu_piece {
  const double* xyz = nullptr; ///< 3 coordinates per point
  std::size_t number_of_points = 0;
  const std::uint32_t* tetrahedra = nullptr; ///< 4 local point indices per tetrahedron
  std::size_t number_of_tetrahedra = 0;
  /// `vtkGhostType` of the points: `vtkDataSetAttributes::DUPLICATEPOINT` (1) for a point owned
  /// by another piece, 0 for an owned point
  const std::uint8_t* point_ghosts = nullptr;
  /// `vtkGhostType` of the cells: `vtkDataSetAttributes::DUPLICATECELL` (1) for a cell owned by
  /// another piece, 0 for an owned cell
  const std::uint8_t* cell_ghosts = nullptr;
  const std::int64_t* global_point_ids = nullptr; ///< the numbering of the whole mesh (`GlobalPointIds`)
  const std::int64_t* global_cell_ids = nullptr;  ///< the numbering of the whole mesh (`GlobalCellIds`)
  const int* labels = nullptr;                    ///< one per tetrahedron, an `Int32` cell array
  std::string label_name = "label";               ///< the name of the label array
  /// `Float64` arrays, one value per point / per tetrahedron
  std::vector<std::pair<std::string, const double*>> point_arrays, cell_arrays;
};

/// The `vtkGhostType` values used here (`vtkDataSetAttributes::PointGhostTypes`, `CellGhostTypes`).
constexpr std::uint8_t vtk_duplicate_point = 1;
constexpr std::uint8_t vtk_duplicate_cell = 1;

/// One data array of a piece, in the order of the file.
struct Pvtu_array {
  enum Section { point_data, cell_data, points, cells };
  enum Source { raw, connectivity, offsets, types };
  Section section;
  const char* type; ///< VTK's name of the type: "Float64", "Int64"...
  std::string name;
  std::size_t components;
  std::size_t value_size; ///< bytes per value
  std::size_t values;     ///< number of values (components included)
  Source source;          ///< `raw`: the bytes of `data`; otherwise computed from the tetrahedra
  const void* data;
  bool id_type = false; ///< `IdType="1"`: VTK reads it as a `vtkIdTypeArray` (global ids)
};

/// The arrays of `p` in file order (`PointData`, `CellData`, `Points`, `Cells`); checks the
/// pointers and the names (throws `Write_error` naming `file`).
inline std::vector<Pvtu_array> pvtu_arrays(const Vtu_piece& p, const std::string& file) {
  static_assert(sizeof(int) == 4, "labels are written as the raw bytes of Int32");
  const std::size_t nv = p.number_of_points, nt = p.number_of_tetrahedra;
  if (p.xyz == nullptr && nv != 0)
    throw Write_error(file, "no coordinates for " + std::to_string(nv) + " points");
  if (p.tetrahedra == nullptr && nt != 0)
    throw Write_error(file, "no vertex indices for " + std::to_string(nt) + " tetrahedra");
  std::vector<Pvtu_array> a;
  const auto add = [&](Pvtu_array::Section s, const char* type, const std::string& name, std::size_t size,
                       std::size_t n, const void* data) {
    if (name.empty()) throw Write_error(file, "a data array has an empty name");
    for (const Pvtu_array& b : a)
      if (b.section == s && b.name == name)
        throw Write_error(file, "two " + std::string(s == Pvtu_array::point_data ? "point" : "cell") +
                                    "-data arrays are named '" + name + "'");
    if (data == nullptr && n != 0) throw Write_error(file, "the data array '" + name + "' has no values");
    a.push_back({s, type, name, 1, size, n, Pvtu_array::raw, data});
  };
  const auto ids = [&] { a.back().id_type = true; };
  if (p.global_point_ids != nullptr) {
    add(Pvtu_array::point_data, "Int64", "GlobalPointIds", 8, nv, p.global_point_ids);
    ids();
  }
  if (p.point_ghosts != nullptr) add(Pvtu_array::point_data, "UInt8", "vtkGhostType", 1, nv, p.point_ghosts);
  for (const auto& x : p.point_arrays) add(Pvtu_array::point_data, "Float64", x.first, 8, nv, x.second);
  if (p.global_cell_ids != nullptr) {
    add(Pvtu_array::cell_data, "Int64", "GlobalCellIds", 8, nt, p.global_cell_ids);
    ids();
  }
  if (p.cell_ghosts != nullptr) add(Pvtu_array::cell_data, "UInt8", "vtkGhostType", 1, nt, p.cell_ghosts);
  if (p.labels != nullptr) add(Pvtu_array::cell_data, "Int32", p.label_name, 4, nt, p.labels);
  for (const auto& x : p.cell_arrays) add(Pvtu_array::cell_data, "Float64", x.first, 8, nt, x.second);
  a.push_back({Pvtu_array::points, "Float64", "Points", 3, 8, 3 * nv, Pvtu_array::raw, p.xyz});
  a.push_back({Pvtu_array::cells, "Int64", "connectivity", 1, 8, 4 * nt, Pvtu_array::connectivity, nullptr});
  a.push_back({Pvtu_array::cells, "Int64", "offsets", 1, 8, nt, Pvtu_array::offsets, nullptr});
  a.push_back({Pvtu_array::cells, "UInt8", "types", 1, 1, nt, Pvtu_array::types, nullptr});
  return a;
}

/// The attributes `GlobalIds="..."` and `Scalars="..."` of `PointData`/`CellData` (or of their
/// `P` forms) for the arrays of `section`.
inline void pvtu_section_attributes(std::string& buf, Pvtu_array::Section section, const Vtu_piece& p) {
  if (section == Pvtu_array::point_data && p.global_point_ids != nullptr)
    buf += " GlobalIds=\"GlobalPointIds\"";
  if (section == Pvtu_array::cell_data && p.global_cell_ids != nullptr) buf += " GlobalIds=\"GlobalCellIds\"";
  if (section == Pvtu_array::cell_data && p.labels != nullptr) {
    buf += " Scalars=\"";
    xml_escape(buf, p.label_name);
    buf += '"';
  }
}

/// `<DataArray ...>` (`format="binary"`, left open for the data when `inline_data`) or
/// `<PDataArray .../>` of `a`.
inline void pvtu_array_element(std::string& buf, const Pvtu_array& a, const char* indent, const char* tag,
                               bool inline_data) {
  buf += indent;
  buf += '<';
  buf += tag;
  buf += " type=\"";
  buf += a.type;
  if (a.id_type) buf += "\" IdType=\"1";
  buf += "\" Name=\"";
  xml_escape(buf, a.name);
  buf += '"';
  if (a.components != 1) {
    buf += " NumberOfComponents=\"";
    append_integer(buf, a.components);
    buf += '"';
  }
  buf += inline_data ? " format=\"binary\">\n" : "/>\n";
}

/// The section elements and their arrays, from `arrays` (in file order): for a piece, each
/// `DataArray` with its data written by `write_data(a)`; for the `.pvtu` (`write_data` null), the
/// `PDataArray`s.
inline void pvtu_sections(std::string& buf, const std::vector<Pvtu_array>& arrays, const Vtu_piece& p,
                          const std::function<void(const Pvtu_array&)>* write_data) {
  static const char* const names[] = {"PointData", "CellData", "Points", "Cells"};
  const bool parallel = write_data == nullptr;
  const char* indent = parallel ? "      " : "        ";
  const std::string prefix = parallel ? "P" : "";
  for (int s = Pvtu_array::point_data; s <= Pvtu_array::cells; ++s) {
    const auto section = static_cast<Pvtu_array::Section>(s);
    if (parallel && section == Pvtu_array::cells) break; // the .pvtu has no PCells
    const bool any =
        std::any_of(arrays.begin(), arrays.end(), [&](const Pvtu_array& a) { return a.section == section; });
    if (!any) continue;
    buf += parallel ? "    <" : "      <";
    buf += prefix + names[s];
    pvtu_section_attributes(buf, section, p);
    buf += ">\n";
    for (const Pvtu_array& a : arrays) {
      if (a.section != section) continue;
      pvtu_array_element(buf, a, indent, parallel ? "PDataArray" : "DataArray", !parallel);
      if (!parallel) {
        buf += "          ";
        (*write_data)(a);
        buf += "\n        </DataArray>\n";
      }
    }
    buf += parallel ? "    </" : "      </";
    buf += prefix + names[s];
    buf += ">\n";
  }
}

inline const char* host_byte_order() {
  return host_is_little_endian() ? "LittleEndian" : "BigEndian";
}

/// Writes through `tmp`, renamed `file` when `write(out)` succeeded: `file` is either left as it
/// was or complete.  Errors name `file`.
template <class Write>
void pvtu_write_through_temporary(const std::string& file, const Write& write) {
  std::error_code ec;
  if (std::filesystem::is_directory(std::filesystem::path(file), ec))
    throw Write_error(file, "is a directory, not a file");
  long pid = 0;
#if defined(__unix__) || defined(__APPLE__)
  pid = static_cast<long>(::getpid());
#endif
  const std::size_t dot = file.find_last_of('.'), slash = file.find_last_of("/\\");
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  const std::string mark = ".prstar-tmp-" + std::to_string(pid);
  const std::string tmp = has_ext ? file.substr(0, dot) + mark + file.substr(dot) : file + mark;
  try {
    errno = 0;
    std::ofstream out(tmp, std::ios::out | std::ios::binary | std::ios::trunc);
    if (!out)
      throw Write_error(file, std::string("cannot open the file for writing") +
                                  (errno != 0 ? std::string(": ") + std::strerror(errno) : std::string()));
    write(out);
    out.flush();
    if (!out) throw Write_error(file, "error while writing");
    out.close();
    if (out.fail()) throw Write_error(file, "error while closing the file");
    std::filesystem::rename(tmp, file, ec);
    if (ec) throw Write_error(file, "cannot replace the file: " + ec.message());
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
}

/// Writes `n` values of `T` made by `get(i)` (in the host's byte order) to `stream`.
template <class T, class Get>
void pvtu_stream_values(Vtu_base64_stream& stream, std::size_t n, const Get& get) {
  std::string chunk;
  chunk.reserve(std::size_t(1) << 15);
  for (std::size_t i = 0; i < n;) {
    chunk.clear();
    const std::size_t end = std::min(n, i + (std::size_t(1) << 15) / sizeof(T));
    for (; i < end; ++i) append_binary<T>(chunk, get(i));
    stream.write(chunk.data(), chunk.size());
  }
}

/// Writes one piece of a distributed mesh as a VTK XML unstructured grid (version 1.0,
/// `header_type="UInt64"`, the byte order of this machine, inline base64 binary data as
/// `Vtu_array_writer` writes them, one stream per array): `Float64`
/// points, `Int64` connectivity and offsets, `UInt8` types (10); `PointData`: `GlobalPointIds`
/// (`Int64`, the `GlobalIds` attribute), `vtkGhostType` (`UInt8`), the `Float64` point arrays;
/// `CellData`: `GlobalCellIds` (`Int64`, `GlobalIds`), `vtkGhostType` (`UInt8`), the labels
/// (`Int32`, the active scalars), the `Float64` cell arrays; each only when given.  The data are
/// streamed from the caller's arrays (at most 64 KiB more in memory), to a temporary file renamed
/// `file` at the end.
/// \throws Write_error when the file cannot be written, a vertex index is out of range, a
/// coordinate or a `Float64` value is not finite, an array has no values or an empty or repeated
/// name (`file` is then unchanged).
inline void write_vtu_piece(const std::string& file, const Vtu_piece& piece) {
  const std::vector<Pvtu_array> arrays = pvtu_arrays(piece, file);
  const std::size_t nv = piece.number_of_points, nt = piece.number_of_tetrahedra;
  // Everything that can be refused is checked before the file is opened.
  for (const Pvtu_array& a : arrays) {
    if (a.source != Pvtu_array::raw || a.type[0] != 'F') continue;
    const double* v = static_cast<const double*>(a.data);
    for (std::size_t i = 0; i < a.values; ++i)
      if (!std::isfinite(v[i]))
        throw Write_error(file,
                          a.section == Pvtu_array::points
                              ? "point " + std::to_string(i / 3) + " has a non-finite coordinate"
                              : "the value " + std::to_string(i) + " of '" + a.name + "' is not finite");
  }
  for (std::size_t i = 0; i < 4 * nt; ++i)
    if (piece.tetrahedra[i] >= nv)
      throw Write_error(file, "tetrahedron " + std::to_string(i / 4) + " has the vertex index " +
                                  std::to_string(piece.tetrahedra[i]) + " (" + std::to_string(nv) +
                                  " points)");
  pvtu_write_through_temporary(file, [&](std::ofstream& out) {
    std::string buf;
    buf += "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"";
    buf += host_byte_order();
    buf += "\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"";
    append_integer(buf, nv);
    buf += "\" NumberOfCells=\"";
    append_integer(buf, nt);
    buf += "\">\n";
    const std::function<void(const Pvtu_array&)> write_data = [&](const Pvtu_array& a) {
      Vtu_base64_stream stream(out, buf, file);
      std::string header;
      append_binary<std::uint64_t>(header, std::uint64_t(a.values) * a.value_size);
      stream.write(header.data(), header.size());
      switch (a.source) {
      case Pvtu_array::raw: // the caller's bytes, as they are (the host's byte order)
        stream.write(static_cast<const char*>(a.data), a.values * a.value_size);
        break;
      case Pvtu_array::connectivity:
        pvtu_stream_values<std::int64_t>(stream, a.values,
                                         [&](std::size_t i) { return std::int64_t(piece.tetrahedra[i]); });
        break;
      case Pvtu_array::offsets:
        pvtu_stream_values<std::int64_t>(stream, a.values,
                                         [](std::size_t i) { return std::int64_t(4 * (i + 1)); });
        break;
      case Pvtu_array::types:
        pvtu_stream_values<std::uint8_t>(stream, a.values, [](std::size_t) { return std::uint8_t(10); });
        break;
      }
      stream.finish();
    };
    pvtu_sections(buf, arrays, piece, &write_data);
    buf += "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
    flush_buffer(out, buf, file, true);
  });
}

/// Writes the `.pvtu` of a mesh written as pieces by `write_vtu_piece()`: `PUnstructuredGrid`
/// with `GhostLevel="1"` when `layout` has a ghost array (else 0), `PPointData`/`PCellData`
/// listing the arrays `layout` has (its pointers not null; its counts are not used) with their
/// types and `GlobalIds`/`Scalars` attributes, `PPoints`, and one `<Piece Source="..."/>` per name
/// of `piece_files`, as given (names relative to the folder of `file`).  Written to a temporary
/// file renamed `file` at the end.
/// \throws Write_error as `write_vtu_piece()` for the names of the arrays and when the file
/// cannot be written (`file` is then unchanged).
inline void write_pvtu(const std::string& file, const std::vector<std::string>& piece_files,
                       const Vtu_piece& layout) {
  // Only which arrays exist matters: stand-ins for the counts and the required pointers.
  Vtu_piece p = layout;
  p.number_of_points = p.number_of_tetrahedra = 0;
  const std::vector<Pvtu_array> arrays = pvtu_arrays(p, file);
  pvtu_write_through_temporary(file, [&](std::ofstream& out) {
    std::string buf;
    buf += "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"";
    buf += host_byte_order();
    buf += "\" header_type=\"UInt64\">\n  <PUnstructuredGrid GhostLevel=\"";
    buf += layout.point_ghosts != nullptr || layout.cell_ghosts != nullptr ? '1' : '0';
    buf += "\">\n";
    pvtu_sections(buf, arrays, p, nullptr);
    for (const std::string& s : piece_files) {
      buf += "    <Piece Source=\"";
      xml_escape(buf, s);
      buf += "\"/>\n";
      flush_buffer(out, buf, file);
    }
    buf += "  </PUnstructuredGrid>\n</VTKFile>\n";
    flush_buffer(out, buf, file, true);
  });
}

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_PVTU_WRITER_H
