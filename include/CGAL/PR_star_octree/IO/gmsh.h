// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_GMSH_H
#define CGAL_PR_STAR_OCTREE_IO_GMSH_H

/// \file
/// Reading and writing gmsh `.msh` files (versions 2.2 and 4.1, ASCII and binary).

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/internal/gmsh_reader.h>
#include <CGAL/PR_star_octree/IO/internal/gmsh_writer.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <fstream>
#include <istream>
#include <ostream>
#include <string>

namespace CGAL {
namespace PR_star_octree {
namespace IO {

/// \ingroup PkgPRStarOctreeIO
/// The version of the `.msh` format written by `write_gmsh()`.
enum class Gmsh_version {
  msh22, ///< the legacy format 2.2 (physical and elementary tags on each element)
  msh41  ///< the current format 4.1 (entities, node and element blocks); gmsh's default
};

/// \ingroup PkgPRStarOctreeIO
/// How `write_gmsh()` writes: version 4.1 in ASCII by default (as gmsh does).
struct Gmsh_write_options {
  Gmsh_version version = Gmsh_version::msh41; ///< the format version
  bool binary = false;                        ///< binary (machine byte order) instead of ASCII
};

/// \ingroup PkgPRStarOctreeIO
/// Reads a tetrahedral mesh from a gmsh `.msh` file held by a stream; `name` is used in error
/// messages.  See `read_gmsh(const std::string&, Mesh&)`.
template <class Mesh>
void read_gmsh(std::istream& in, Mesh& mesh, const std::string& name = "<stream>") {
  const std::string data = internal::load_stream(in, name);
  internal::Gmsh_reader<Mesh>(data, name).read(mesh);
}

/// \ingroup PkgPRStarOctreeIO
/// Reads a tetrahedral mesh from a gmsh `.msh` file: format 2.2 (2.0 and 2.1 are read alike) or
/// 4.1, ASCII or binary (in either byte order, as announced by the file's endianness integer).
///
/// - Nodes: every node of `$Nodes` becomes a point, in the order of the file; node tags may be
///   any positive integers (not necessarily contiguous or sorted; 4.1 node blocks of any entity).
/// - Elements: tetrahedra (type 4) are kept in the order of the file.  Higher-order tetrahedra
///   (types 11, 29, 30, 31) are kept as their 4 corner nodes (the other nodes stay unreferenced
///   points).  Every other element type is skipped and counted in `mesh.skipped_cells` by name
///   (`"point"`, `"line"`, `"triangle"`, `"quadrangle"`, `"hexahedron"`, `"prism"`, `"pyramid"`,
///   `"triangle6"`...; `"type N"` for a type this reader does not know, ASCII files only).
/// - Labels: the physical tag of each tetrahedron goes to `tetrahedron_labels`: in 4.1 the first
///   physical tag of its volume entity in `$Entities`, in 2.2 the first tag of the element.  A
///   tetrahedron without physical tag gets 0 (so does one whose physical tag is 0); when no
///   tetrahedron has a non-zero physical tag, `tetrahedron_labels` is left empty.  A 2.2 file
///   repeats an element that belongs to several physical groups: it is then read several times.
///   In a partitioned 4.1 file, the physical tags of the volumes come from `$PartitionedEntities`.
/// - `$PhysicalNames` of dimension 3 go to `mesh.label_names` (physical tag -> name).
/// - Other sections (`$NodeData`, `$ElementData`, `$Periodic`, `$PartitionedEntities`...) are
///   skipped up to their end marker.
///
/// \throws Read_error on any problem: `FILE:LINE: message` for an ASCII file, `FILE: byte N:
/// message` for a binary one (unsupported version, bad endianness integer, truncated data, counts
/// that disagree with the data or announce more than the file can hold, unknown node tag, a
/// tetrahedron listing a node twice, non-finite coordinate...).  Nothing is allocated for a
/// count before the bytes backing it have been checked.  `mesh` is left unchanged on error and
/// replaced on success.
template <class Mesh>
void read_gmsh(const std::string& filename, Mesh& mesh) {
  const internal::File_bytes data(filename);
  internal::Gmsh_reader<Mesh>(data.view(), filename).read(mesh);
}

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to a stream in the gmsh `.msh` format; `name` is used in error messages.  See
/// `write_gmsh(const std::string&, const Mesh&, const Gmsh_write_options&)`.
template <class Mesh>
void write_gmsh(std::ostream& out, const Mesh& mesh, const Gmsh_write_options& options = Gmsh_write_options(),
                const std::string& name = "<stream>") {
  internal::check_mesh_for_writing(mesh, name);
  if (options.version == Gmsh_version::msh41)
    internal::write_gmsh_41(out, mesh, options.binary, name);
  else
    internal::write_gmsh_22(out, mesh, options.binary, name);
}

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to the gmsh file `filename`, in version 4.1 ASCII unless `options` asks for 2.2
/// and/or binary.
///
/// Nodes are tagged 1..n in the order of `mesh.points` and tetrahedra 1..m in the order of
/// `mesh.tetrahedra`.  Each distinct label gets a volume entity (tags 1, 2, ... in order of first
/// appearance) whose physical tag is the label (label 0: no physical tag); in 4.1 consecutive
/// tetrahedra with the same label form one element block, in 2.2 each element carries its
/// physical tag and its entity.  `$PhysicalNames` lists the labels that have a name in
/// `mesh.label_names`.  Without labels, all tetrahedra are in one volume without physical tag.
/// Point data and cell data are not written.  Binary 2.2 files need fewer than 2^31 vertices and
/// tetrahedra.  gmsh expects positive physical tags.
/// \throws Write_error when the file cannot be written or the mesh is inconsistent.
template <class Mesh>
void write_gmsh(const std::string& filename, const Mesh& mesh,
                const Gmsh_write_options& options = Gmsh_write_options()) {
  internal::check_mesh_for_writing(mesh, filename);
  std::ofstream out;
  internal::open_for_writing(out, filename);
  write_gmsh(out, mesh, options, filename);
  internal::close_written(out, filename);
}

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_GMSH_H
