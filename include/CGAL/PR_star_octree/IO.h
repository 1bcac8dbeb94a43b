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
#include <CGAL/PR_star_octree/IO/gmsh.h>
#include <CGAL/PR_star_octree/IO/medit.h>
#include <CGAL/PR_star_octree/IO/meshb.h>
#include <CGAL/PR_star_octree/IO/tet_off.h>
#include <CGAL/PR_star_octree/IO/tetgen.h>
#include <CGAL/PR_star_octree/IO/vtk.h>
#include <CGAL/PR_star_octree/IO/vtu.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <string>

namespace CGAL {
namespace PR_star_octree {
namespace IO {
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
/// The extensions `read_tetrahedral_mesh()` accepts, for messages.
inline const char* readable_extensions() {
  return ".mesh, .node/.ele, .vtk, .vtu, .off/.ts, .msh, .meshb";
}

/// \ingroup PkgPRStarOctreeIO
/// The extensions `write_tetrahedral_mesh()` accepts, for messages.
inline const char* writable_extensions() {
  return ".mesh, .vtu, .vtk, .off/.ts, .msh, .meshb, .node/.ele";
}

/// \ingroup PkgPRStarOctreeIO
/// Whether `read_tetrahedral_mesh()` knows the extension of `filename` (a file name or an
/// extension with its dot such as `".vtu"`; case-insensitive).
inline bool is_readable_extension(const std::string& filename) {
  const std::string e = internal::lower_extension(filename);
  return e == "mesh" || e == "node" || e == "ele" || e == "vtk" || e == "vtu" || e == "off" || e == "ts" ||
         e == "msh" || e == "meshb";
}

/// \ingroup PkgPRStarOctreeIO
/// Whether `write_tetrahedral_mesh()` knows the extension of `filename` (a file name or an
/// extension with its dot; case-insensitive).
inline bool is_writable_extension(const std::string& filename) {
  const std::string e = internal::lower_extension(filename);
  return e == "mesh" || e == "vtu" || e == "vtk" || e == "off" || e == "ts" || e == "msh" || e == "meshb" ||
         e == "node" || e == "ele";
}

/// \ingroup PkgPRStarOctreeIO
/// Reads a tetrahedral mesh with the reader chosen by the extension of `filename`
/// (case-insensitive): `.mesh` (`read_medit()`), `.node` or `.ele` (`read_tetgen()`, both files
/// being read), `.vtk` (`read_vtk()`), `.vtu` (`read_vtu()`), `.off` or `.ts` (`read_tet_off()`),
/// `.msh` (`read_gmsh()`), `.meshb` (`read_meshb()`).
/// \throws Read_error for an unknown extension (the message lists the supported ones) and for any
/// problem of the file; `mesh` is then left unchanged.
template <class Mesh>
void read_tetrahedral_mesh(const std::string& filename, Mesh& mesh) {
  const std::string e = internal::lower_extension(filename);
  if (e == "mesh")
    read_medit(filename, mesh);
  else if (e == "node" || e == "ele")
    read_tetgen(filename, mesh);
  else if (e == "vtk")
    read_vtk(filename, mesh);
  else if (e == "vtu")
    read_vtu(filename, mesh);
  else if (e == "off" || e == "ts")
    read_tet_off(filename, mesh);
  else if (e == "msh")
    read_gmsh(filename, mesh);
  else if (e == "meshb")
    read_meshb(filename, mesh);
  else
    throw Read_error(filename, 0,
                     (e.empty() ? std::string("no file extension") : "unknown file extension '." + e + "'") +
                         ": supported are " + readable_extensions());
}

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` with the writer chosen by the extension of `filename` (case-insensitive):
/// `.mesh` (`write_medit()`), `.vtu` (`write_vtu()`: appended and zlib-compressed, ascii with
/// `CGAL::parameters::use_binary_mode(false)`), `.vtk` (`write_vtk()`: legacy 4.2, ASCII, binary with
/// `CGAL::parameters::use_binary_mode(true)`), `.off` or `.ts` (`write_tet_off()`),
/// `.msh` (`write_gmsh()`: 4.1 ASCII), `.meshb` (`write_meshb()`), `.node` or `.ele` (`write_tetgen()`).
/// \throws Write_error for an unknown extension (the message lists the supported ones), when the
/// file cannot be written or when the mesh is inconsistent.
template <class Mesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
void write_tetrahedral_mesh(const std::string& filename, const Mesh& mesh,
                            const NamedParameters& np = CGAL::parameters::default_values()) {
  const std::string e = internal::lower_extension(filename);
  if (e == "mesh")
    write_medit(filename, mesh);
  else if (e == "vtu")
    write_vtu(filename, mesh, {}, np);
  else if (e == "vtk")
    write_vtk(filename, mesh, {}, np);
  else if (e == "off" || e == "ts")
    write_tet_off(filename, mesh);
  else if (e == "msh")
    write_gmsh(filename, mesh);
  else if (e == "meshb")
    write_meshb(filename, mesh);
  else if (e == "node" || e == "ele")
    write_tetgen(filename, mesh);
  else
    throw Write_error(filename,
                      (e.empty() ? std::string("no file extension") : "unknown file extension '." + e + "'") +
                          ": writable are " + writable_extensions());
}

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_H
