// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_GMSH_H
#define CGAL_PR_STAR_OCTREE_IO_GMSH_H

/// \file
/// Reading and writing gmsh `.msh` files (versions 2.2 and 4.1, ASCII and binary).

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/Write_options.h>
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

namespace internal {

/// What the gmsh writer accepts: ASCII (default) or binary, versions 4.1 (default) and 2.2.
inline constexpr Write_support gmsh_write_support{
    true, true, false, false, false, {"4.1", "2.2", nullptr, nullptr}, nullptr};

/// Writes a checked mesh with resolved options.
template <class Mesh>
void write_gmsh_checked(std::ostream& out, const Mesh& mesh, const Write_options& o,
                        const std::string& name) {
  if (version_tenths(o.version) == 41)
    write_gmsh_41(out, mesh, o.binary, name);
  else
    write_gmsh_22(out, mesh, o.binary, name);
}

template <class Mesh>
void write_gmsh_stream(std::ostream& out, const Mesh& mesh, const Write_options& given,
                       const std::string& name) {
  const Write_options o = resolve_write_options(given, gmsh_write_support, "gmsh .msh", name);
  check_mesh_for_gmsh(mesh, o.binary, name);
  write_gmsh_checked(out, mesh, o, name);
}

template <class Mesh>
void write_gmsh_file(const std::string& filename, const Mesh& mesh, const Write_options& given) {
  const Write_options o = resolve_write_options(given, gmsh_write_support, "gmsh .msh", filename);
  check_mesh_for_gmsh(mesh, o.binary, filename); // before the file is created
  std::ofstream out;
  open_for_writing(out, filename);
  write_gmsh_checked(out, mesh, o, filename);
  close_written(out, filename);
}

} // namespace internal

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
/// - Elements: tetrahedra (type 4) are kept in the order of their element tags: the order of the
///   file when the tags increase along it (files of gmsh, of meshio, of `write_gmsh()`), otherwise
///   a stable sort by tag (equal tags keep the order of the file), so that a file of `write_gmsh()`,
///   whose 4.1 element blocks group the tetrahedra by label, gives back the tetrahedra in the
///   order of the mesh written.  Higher-order tetrahedra
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
/// - `$NodeData` and `$ElementData`: each view (its name is the first string tag) of scalars (one
///   component) becomes an array of `mesh.point_data` (one value per node, by node tag) or
///   `mesh.cell_data` (one value per tetrahedron, by element tag), in order of first appearance.
///   Sections of the same view and time step are merged (the partitions of a view); a section of
///   another time step replaces what the view had, so the last time step of the file is kept.
///   Views of several components, views without a name, and views that do not give a value to
///   every node (every tetrahedron) are skipped.  `$ElementData` entries of elements that are not
///   tetrahedra are ignored; an element tag above every tag of `$Elements`, a node tag not in
///   `$Nodes`, a non-finite value or a data section before `$Nodes` (`$Elements`) is an error.
///   The entries of a binary file are a 4-byte tag and 8-byte values, as gmsh writes them.
/// - Other sections (`$ElementNodeData`, `$Periodic`, `$Comments`...) are skipped up to their end
///   marker.
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
/// `write_gmsh(const std::string&, const Mesh&, const NamedParameters&)`, whose options it takes.
template <class Mesh, class NamedParameters = parameters::Default_named_parameters>
void write_gmsh(std::ostream& out, const Mesh& mesh, const NamedParameters& np = parameters::default_values(),
                const std::string& name = "<stream>") {
  internal::write_gmsh_stream(out, mesh, internal::write_options(np), name);
}

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to the gmsh file `filename`, in version 4.1 ASCII unless `np` asks for 2.2
/// and/or binary.
///
/// Nodes are tagged 1..n in the order of `mesh.points` and tetrahedra 1..m in the order of
/// `mesh.tetrahedra` (element tag = tetrahedron index + 1, whatever the order of the elements in
/// the file).  Each distinct label gets a volume entity (tags 1, 2, ... in order of first
/// appearance) whose physical tag is the label (label 0: no physical tag).  In 4.1, each entity
/// has exactly one element block, with its tetrahedra in the order of the mesh (the blocks are in
/// entity order, so the file lists the tetrahedra grouped by label; their tags give the order of
/// the mesh back, see `read_gmsh()`); in 2.2 the elements are in the order of the mesh, each with
/// its physical tag and its entity.  `$PhysicalNames` lists the labels that have a name in
/// `mesh.label_names`.  Without labels, all tetrahedra are in one volume without physical tag.
///
/// Each array of `mesh.point_data` is written as a `$NodeData` view and each array of
/// `mesh.cell_data` as an `$ElementData` view: the array name as the view name, time 0, time step
/// 0, one component, one entry per node (per tetrahedron, in the order of the elements in the
/// file), the values exact (the shortest decimal text that reads back the same double, or the 8
/// bytes).  Names must not hold a double quote or a line break.  (meshio 5.0 ignores the element
/// tags of data sections: it reads an `$ElementData` view in the order of the elements in the
/// file, which is right, but refuses the binary ones whose tags do not run 1, 2, ... in that
/// order, i.e. 4.1 binary files with cell data whose labels are not already grouped.)
///
/// Binary 2.2 files, and binary files with point or cell data (their tags have 4 bytes), need
/// fewer than 2^31 vertices and tetrahedra.  gmsh expects positive physical tags.
/// \param filename the name of the file
/// \param mesh the mesh
/// \param np the write options (`Write_options.h`)
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{use_binary_mode}
///     \cgalParamDescription{binary (`true`, machine byte order, as gmsh writes it) or ASCII (`false`)}
///     \cgalParamType{Boolean}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{format_version}
///     \cgalParamDescription{4.1 (entities, node and element blocks) or 2.2 (physical and elementary
///       tags on each element)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{4.1}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Write_error when the file cannot be written, the mesh is inconsistent (indices out of
/// range, data arrays of the wrong size, non-finite values, names that cannot be written) or an
/// option is not possible; the mesh is checked before the file is created.
template <class Mesh, class NamedParameters = parameters::Default_named_parameters>
void write_gmsh(const std::string& filename, const Mesh& mesh,
                const NamedParameters& np = parameters::default_values()) {
  internal::write_gmsh_file(filename, mesh, internal::write_options(np));
}

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_GMSH_H
