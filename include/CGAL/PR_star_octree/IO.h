// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_H
#define CGAL_PR_STAR_OCTREE_IO_H

/// \file
/// All the readers and writers of tetrahedral meshes, and the functions choosing one by the
/// extension of the file name.

#include <CGAL/PR_star_octree/IO/Memory_limit.h>
#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/Write_options.h>
#include <CGAL/PR_star_octree/IO/formats.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <string>

namespace CGAL {
namespace PR_star_octree {
namespace IO {

/// \ingroup PkgPRStarOctreeIO
/// The extensions `read_tetrahedral_mesh()` accepts, for messages (from the format table
/// `mesh_formats`).
inline std::string readable_extensions() {
  return mesh_format_extensions();
}

/// \ingroup PkgPRStarOctreeIO
/// The extensions `write_tetrahedral_mesh()` accepts, for messages (from the format table
/// `mesh_formats`).
inline std::string writable_extensions() {
  return mesh_format_extensions();
}

/// \ingroup PkgPRStarOctreeIO
/// Whether `read_tetrahedral_mesh()` knows the extension of `filename` (a file name or an
/// extension with its dot such as `".vtu"`; case-insensitive).
inline bool is_readable_extension(const std::string& filename) {
  return find_mesh_format(filename) != nullptr;
}

/// \ingroup PkgPRStarOctreeIO
/// Whether `write_tetrahedral_mesh()` knows the extension of `filename` (a file name or an
/// extension with its dot; case-insensitive).
inline bool is_writable_extension(const std::string& filename) {
  return find_mesh_format(filename) != nullptr;
}

namespace internal {

inline std::string unknown_extension_message(const std::string& filename) {
  const std::string e = lower_extension(filename);
  return (e.empty() ? std::string("no file extension") : "unknown file extension '." + e + "'") +
         ": supported are " + mesh_format_extensions();
}

} // namespace internal

/// \ingroup PkgPRStarOctreeIO
/// Reads a tetrahedral mesh with the reader of the format table `mesh_formats` chosen by the
/// extension of `filename` (case-insensitive): `.mesh` (`read_medit()`), `.meshb`
/// (`read_meshb()`), `.node` or `.ele` (`read_tetgen()`, both files being read), `.vtk`
/// (`read_vtk()`), `.vtu` (`read_vtu()`), `.msh` (`read_gmsh()`), `.off` or `.ts`
/// (`read_tet_off()`).
/// \throws Read_error for an unknown extension (the message lists the supported ones) and for any
/// problem of the file; `mesh` is then left unchanged.
template <class Mesh>
void read_tetrahedral_mesh(const std::string& filename, Mesh& mesh) {
  const Mesh_format<Mesh>* f = find_mesh_format<Mesh>(filename);
  if (f == nullptr) throw Read_error(filename, 0, internal::unknown_extension_message(filename));
  f->read_file(filename, mesh);
}

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` with the writer of the format table `mesh_formats` chosen by the extension of
/// `filename` (case-insensitive): `.mesh` (`write_medit()`), `.meshb` (`write_meshb()`), `.node`
/// or `.ele` (`write_tetgen()`), `.vtk` (`write_vtk()`), `.vtu` (`write_vtu()`), `.msh`
/// (`write_gmsh()`), `.off` or `.ts` (`write_tet_off()`).  The write options have the same names
/// and meanings for every format; each format accepts those of its record (`write_options_text()`)
/// and refuses the others.
/// \param filename the name of the file; its extension chooses the format
/// \param mesh the mesh
/// \param np an optional sequence of named parameters among the ones listed below
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{use_binary_mode}
///     \cgalParamDescription{binary (`true`) or text (`false`) where the format has both (`.vtk`,
///       `.vtu`, `.msh`); `.mesh`, `.node`/`.ele` and `.off`/`.ts` are text only, `.meshb` binary only}
///     \cgalParamType{Boolean}
///     \cgalParamDefault{`true` for `.vtu` (appended raw data, as ParaView writes) and `.meshb`, else
///     `false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{compression}
///     \cgalParamDescription{`Compression::zlib` or `Compression::none`: the compression of the binary
///       data (`.vtu` only; `Compression::none` is accepted by every format)}
///     \cgalParamType{`CGAL::PR_star_octree::IO::Compression`}
///     \cgalParamDefault{`Compression::zlib` for binary `.vtu` when the build has zlib, else
///     `Compression::none`}
///   \cgalParamNEnd
///   \cgalParamNBegin{format_version}
///     \cgalParamDescription{the version of the format written: 4.1 or 2.2 for `.msh`, 1 to 4 for
///       `.meshb`, 4.2 or 5.1 for `.vtk`, 1.0 for `.vtu`, 2 for `.mesh`; refused by the formats without
///       versions (`.node`/`.ele`, `.off`/`.ts`)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{4.1 for `.msh`, 4.2 for `.vtk`, the smallest that fits for `.meshb` (2 under 2 GB)}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Write_error for an unknown extension (the message lists the supported ones), an option
/// the format cannot honour, when the file cannot be written or when the mesh is inconsistent.
template <class Mesh, class NamedParameters = parameters::Default_named_parameters>
void write_tetrahedral_mesh(const std::string& filename, const Mesh& mesh,
                            const NamedParameters& np = parameters::default_values()) {
  const Mesh_format<Mesh>* f = find_mesh_format<Mesh>(filename);
  if (f == nullptr) throw Write_error(filename, internal::unknown_extension_message(filename));
  f->write_file(filename, mesh, internal::write_options(np));
}

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_H
