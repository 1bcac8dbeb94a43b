// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_FORMATS_H
#define CGAL_PR_STAR_OCTREE_IO_FORMATS_H

/// \file formats.h
/// The table of the mesh file formats: one record per format (name, extensions, reader, writer,
/// what it keeps, its encodings, its write options).  The choice by extension
/// (`read_tetrahedral_mesh()`, `write_tetrahedral_mesh()`), the extension lists of messages, the
/// command-line tool, the fuzz targets and the table of the README all come from it: adding a
/// format means adding its record here, its reader and writer header, and its tests.

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/Write_options.h>
#include <CGAL/PR_star_octree/IO/gmsh.h>
#include <CGAL/PR_star_octree/IO/medit.h>
#include <CGAL/PR_star_octree/IO/meshb.h>
#include <CGAL/PR_star_octree/IO/tet_off.h>
#include <CGAL/PR_star_octree/IO/tetgen.h>
#include <CGAL/PR_star_octree/IO/vtk.h>
#include <CGAL/PR_star_octree/IO/vtu.h>
#include <CGAL/PR_star_octree/IO/xdmf.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <cstddef>
#include <istream>
#include <string>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace IO {

/// \ingroup PkgPRStarOctreeIO
/// Which point-data arrays a format's writer keeps.
enum class Point_data_kept {
  none,        ///< no point data
  first_array, ///< the first array only (the scalar field), unnamed
  all_arrays   ///< every array, in order
};

/// \ingroup PkgPRStarOctreeIO
/// One record of the format table `mesh_formats`: a file format of tetrahedral meshes, its reader
/// and writer for meshes of type `Mesh`, and what it keeps.  The text fields are the cells of the
/// README's table of mesh formats (the test `io_formats_readme` checks that they agree).
template <class Mesh>
struct Mesh_format {
  const char* name;          ///< the name of the format, e.g. `"VTK XML"`
  const char* extensions[2]; ///< its file extensions, lower case, without the dot (`nullptr` when unused)
  const char* key;           ///< a short identifier: the fuzz target `fuzz_<key>` and its regression folder
  const char* read;          ///< what is read (versions)
  const char* write;         ///< what is written
  const char* labels;        ///< how tetrahedron labels are kept (`"–"`: not kept)
  const char* point_data;    ///< how point data are kept
  Point_data_kept point_data_kept; ///< which point-data arrays the writer keeps
  const char* cell_data;           ///< how cell data are kept
  const char* encodings;           ///< the encodings read
  /// what the writer accepts as named parameters (`use_binary_mode`, `compression`,
  /// `format_version`) and its defaults; see `write_options_text()`
  const internal::Write_support* write_options;
  /// reads the file named (for TetGen: the `.node` or the `.ele`, both being read)
  void (*read_file)(const std::string& filename, Mesh& mesh);
  /// reads a stream (for TetGen: the `.node` text, a NUL byte, the `.ele` text); the name is used
  /// in messages
  void (*read_stream)(std::istream& in, Mesh& mesh, const std::string& name);
  /// writes the file named, with the write options read from named parameters
  void (*write_file)(const std::string& filename, const Mesh& mesh, const internal::Write_options& options);
};

/// \ingroup PkgPRStarOctreeIO
/// The format table: every format the package reads and writes, in the order of the README's table.
template <class Mesh = Indexed_tetrahedral_mesh<>>
inline constexpr Mesh_format<Mesh> mesh_formats[] = {
    // name, extensions, key, read, write, labels, point data (text, kept), cell data, encodings,
    // write options, file reader, stream reader, file writer
    {"VTK XML",
     {"vtu", nullptr},
     "vtu",
     "yes",
     "yes",
     "as `.vtk`",
     "yes",
     Point_data_kept::all_arrays,
     "yes",
     "ASCII, inline base64, appended raw/base64; zlib, LZ4, LZMA blocks, UInt32/UInt64 headers; both byte "
     "orders; Int32/Int64/UInt32/UInt64 ids",
     &internal::vtu_write_support,
     &read_vtu<Mesh>,
     [](std::istream& in, Mesh& m, const std::string& n) { read_vtu(in, m, n); },
     [](const std::string& f, const Mesh& m, const internal::Write_options& o) {
       internal::write_vtu_file(f, m, {}, o);
     }},
    {"VTK legacy",
     {"vtk", nullptr},
     "vtk",
     "yes (4.x, 5.x)",
     "yes",
     "cell array `label`, `CellEntityIds`, `gmsh:physical`, `medit:ref`, ...",
     "`SCALARS`, `FIELD`",
     Point_data_kept::all_arrays,
     "yes",
     "ASCII, binary (big-endian)",
     &internal::vtk_write_support,
     &read_vtk<Mesh>,
     [](std::istream& in, Mesh& m, const std::string& n) { read_vtk(in, m, n); },
     [](const std::string& f, const Mesh& m, const internal::Write_options& o) {
       internal::write_vtk_file(f, m, {}, o);
     }},
    {"TetGen",
     {"node", "ele"},
     "tetgen",
     "yes",
     "yes",
     "region attribute",
     "node attributes",
     Point_data_kept::all_arrays,
     "–",
     "ASCII, 0- or 1-based",
     &internal::tetgen_write_support,
     &read_tetgen<Mesh>,
     &internal::read_tetgen_joined<Mesh>,
     &internal::write_tetgen_file<Mesh>},
    {"Medit",
     {"mesh", nullptr},
     "medit",
     "yes",
     "yes",
     "tetrahedron references",
     "–",
     Point_data_kept::none,
     "–",
     "ASCII",
     &internal::medit_write_support,
     &read_medit<Mesh>,
     [](std::istream& in, Mesh& m, const std::string& n) { read_medit(in, m, n); },
     &internal::write_medit_file<Mesh>},
    {"Medit binary",
     {"meshb", nullptr},
     "meshb",
     "yes (versions 1–4)",
     "yes",
     "tetrahedron references",
     "–",
     Point_data_kept::none,
     "–",
     "32/64-bit reals and integers, both byte orders",
     &internal::meshb_write_support,
     &read_meshb<Mesh>,
     [](std::istream& in, Mesh& m, const std::string& n) { read_meshb(in, m, n); },
     &internal::write_meshb_file<Mesh>},
    {"gmsh",
     {"msh", nullptr},
     "msh",
     "yes (2.2, 4.1)",
     "yes",
     "physical tags, `$PhysicalNames`",
     "`$NodeData`",
     Point_data_kept::all_arrays,
     "`$ElementData`",
     "ASCII, binary",
     &internal::gmsh_write_support,
     &read_gmsh<Mesh>,
     [](std::istream& in, Mesh& m, const std::string& n) { read_gmsh(in, m, n); },
     &internal::write_gmsh_file<Mesh>},
    {"tet-OFF",
     {"off", "ts"},
     "tet_off",
     "yes",
     "yes",
     "–",
     "one scalar",
     Point_data_kept::first_array,
     "–",
     "ASCII",
     &internal::tet_off_write_support,
     &read_tet_off<Mesh>,
     [](std::istream& in, Mesh& m, const std::string& n) { read_tet_off(in, m, n); },
     &internal::write_tet_off_file<Mesh>},
    {"XDMF",
     {"xdmf", "xmf"},
     "xdmf",
     "yes (2, 3; the first grid; `Tetrahedron`, `Mixed`)",
     "yes (3.0; heavy data in `<stem>.h5`, or inline XML)",
     "integer `Cell` attribute named as in `.vtk`, or `name_to_read`",
     "`Node` scalar attributes",
     Point_data_kept::all_arrays,
     "`Cell` scalar attributes",
     "inline XML; HDF5 datasets of float32/64, int32/64, uint32/64 (when the build has HDF5)",
     &internal::xdmf_write_support,
     [](const std::string& f, Mesh& m) { read_xdmf(f, m); },
     [](std::istream& in, Mesh& m, const std::string& n) { read_xdmf(in, m, n); },
     [](const std::string& f, const Mesh& m, const internal::Write_options& o) {
       internal::write_xdmf_file(f, m, o);
     }},
};

/// \ingroup PkgPRStarOctreeIO
/// The write options of a format in words, as in the README's table, e.g. `use_binary_mode`
/// `false` (default) or `true`; `format_version` 4.1 (default) or 2.2.
inline std::string write_options_text(const internal::Write_support& s) {
  std::string r = "`use_binary_mode`: ";
  if (s.ascii && s.binary)
    r += s.binary_by_default ? "`true` (default), `false`" : "`false` (default), `true`";
  else
    r += s.binary ? "`true` only" : "`false` only";
  if (s.zlib)
    r += s.zlib_by_default ? "; `compression`: zlib (default in binary), none"
                           : "; `compression`: none (default), zlib";
  if (s.versions[0] != nullptr) {
    r += "; `format_version`: ";
    for (std::size_t i = 0; i < 4 && s.versions[i] != nullptr; ++i) {
      r += (i == 0 ? "" : ", ") + std::string(s.versions[i]);
      if (i == 0 && s.default_version == nullptr) r += " (default)";
    }
    if (s.default_version != nullptr) r += std::string(" (default: ") + s.default_version + ")";
  }
  return r;
}

namespace internal {

/// The extension of a file name, lower case, without the dot (empty when there is none).
inline std::string lower_extension(const std::string& filename) {
  const std::size_t dot = filename.find_last_of('.');
  const std::size_t slash = filename.find_last_of("/\\");
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return std::string();
  return to_lower(filename.substr(dot + 1));
}

} // namespace internal

/// \ingroup PkgPRStarOctreeIO
/// The record of `mesh_formats` whose extensions include the one of `filename` (a file name, or an
/// extension with its dot such as `".vtu"`; case-insensitive), or `nullptr`.
template <class Mesh = Indexed_tetrahedral_mesh<>>
const Mesh_format<Mesh>* find_mesh_format(const std::string& filename) {
  const std::string e = internal::lower_extension(filename);
  if (e.empty()) return nullptr;
  for (const Mesh_format<Mesh>& f : mesh_formats<Mesh>)
    for (const char* x : f.extensions)
      if (x != nullptr && e == x) return &f;
  return nullptr;
}

/// \ingroup PkgPRStarOctreeIO
/// The extensions of the format table, for messages: `.vtu, .vtk, .node/.ele, ...`.  Every format
/// is read and written, so these are the extensions of both `read_tetrahedral_mesh()` and
/// `write_tetrahedral_mesh()`; with `keeping_point_data`, only the formats that keep every
/// point-data array (`Point_data_kept::all_arrays`).
inline std::string mesh_format_extensions(bool keeping_point_data = false) {
  std::string r;
  for (const auto& f : mesh_formats<>) {
    if (keeping_point_data && f.point_data_kept != Point_data_kept::all_arrays) continue;
    r += r.empty() ? "." : ", .";
    r += f.extensions[0];
    if (f.extensions[1] != nullptr) r += std::string("/.") + f.extensions[1];
  }
  return r;
}

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_FORMATS_H
