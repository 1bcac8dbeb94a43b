// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_XDMF_H
#define CGAL_PR_STAR_OCTREE_IO_XDMF_H

/// \file xdmf.h
/// Reading and writing XDMF files (`.xdmf` or `.xmf`, versions 2 and 3) of tetrahedral meshes, with their
/// heavy data inline in the XML or in an HDF5 file, as ParaView, meshio and DOLFINx write them.
///
/// The HDF5 part needs the HDF5 C library: it is compiled only when the macro
/// `CGAL_PR_STAR_OCTREE_USE_HDF5` is defined (with HDF5's include folder and library; the CMake
/// target `prstar_hdf5` of this project does it, when `PRSTAR_WITH_HDF5` is on and HDF5 is found).
/// Without it, files whose data are all inline (`Format="XML"`) are still read and written, and a
/// file referring to an `.h5` file, or writing with HDF5 storage, is refused with the message
/// `FILE: this build of the package has no HDF5 support (rebuild with libhdf5-dev installed)`.
/// Define the macro in every translation unit of a program or in none.

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/Write_options.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>
#include <CGAL/PR_star_octree/IO/internal/xdmf_hdf5.h>
#include <CGAL/PR_star_octree/IO/internal/xdmf_reader.h>
#include <CGAL/PR_star_octree/IO/internal/xdmf_writer.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <CGAL/Named_function_parameters.h>

#include <filesystem>
#include <istream>
#include <string>

namespace CGAL {
namespace PR_star_octree {
namespace IO {

/// \ingroup PkgPRStarOctreeIO
/// Whether this build reads and writes XDMF heavy data in HDF5 files (the macro
/// `CGAL_PR_STAR_OCTREE_USE_HDF5` was defined).
inline constexpr bool xdmf_has_hdf5() {
  return internal::xdmf_hdf5_available();
}

/// \ingroup PkgPRStarOctreeIO
/// Reads a tetrahedral mesh from an XDMF file (`.xdmf` or `.xmf`, XDMF 2 or 3).
///
/// The grid read is the first `<Grid>` of the `<Domain>`; for a `Collection` (a temporal series,
/// as meshio's `TimeSeriesWriter` and DOLFINx write them) or a `Tree`, its first grid, recursively;
/// when that grid takes its topology and geometry from another one through `<xi:include>`, they are
/// taken from the grid its `xpointer` names by its `Name`, else from the first grid of the
/// domain that has both.  The other grids (later time steps, DOLFINx's separate mesh-tag grids) are
/// not read.
///
/// Read: `<Topology TopologyType="Tetrahedron">` (`NodesPerElement` 4, `NumberOfElements`,
/// `BaseOffset`) or `"Mixed"` (cells as XDMF type ids; the tetrahedra, type 6, are kept in file
/// order, the other cells are counted in `mesh.skipped_cells` by type name; a Mixed topology
/// without tetrahedron is refused); `<Geometry GeometryType="XYZ">` (`XY` and the other geometry
/// types are refused); `<DataItem>`s with `Format="XML"` (inline ASCII values) or `Format="HDF"`
/// (`file.h5:/path/to/dataset`, the file relative to the `.xdmf`'s folder), `NumberType` or
/// `DataType` `Float`, `Int`, `UInt`, `Char`, `UChar`, `Precision` 1, 2, 4, 8 and `Dimensions`.
/// HDF5 datasets must hold float32, float64, int32, int64, uint32 or uint64 values (their own type
/// decides, not `Precision`), of as many values as `Dimensions` announces.  A geometry of float32
/// values (an HDF5 dataset of them, or inline `Float` values of `Precision="4"`, rounded to floats)
/// sets `mesh.float32_points`; without `Precision`, inline values are read as doubles.  Scalar `<Attribute>`s
/// (`AttributeType="Scalar"`, the default): `Center="Node"` gives a point-data array,
/// `Center="Cell"` a cell-data array (values of the tetrahedra only), except the first cell
/// attribute of an integer type named `label`, `labels`, `subdomain`, `CellEntityIds`,
/// `gmsh:physical`, `medit:ref`, `MaterialIds` or `name_to_read` whose values are all `int`s, which
/// gives `tetrahedron_labels`; the other attributes (vectors, tensors, other centers) are skipped.
///
/// Before the points and tetrahedra are allocated, the sizes the file announces (the HDF5 datasets'
/// dimensions) are checked against `Memory_limit::current()`.
///
/// \throws Read_error on any problem: malformed XML, no grid, a topology that is not tetrahedral,
/// a wrong number of values, an index out of range or listed twice in a tetrahedron, a non-finite
/// coordinate, a missing `.h5` file or dataset, a dataset of the wrong shape or type, HDF5 data in a
/// build without HDF5 (see the file's documentation); `Memory_limit_error` when the mesh announced
/// is too big.  `mesh` is then left unchanged; it is replaced on success.
template <class Mesh>
void read_xdmf(const std::string& filename, Mesh& mesh) {
  const std::string text = internal::load_file(filename);
  std::string folder = std::filesystem::path(filename).parent_path().string();
  internal::read_xdmf_text(text, filename, folder, false, mesh);
}

/// \ingroup PkgPRStarOctreeIO
/// Reads an XDMF file from a stream; `name` is used in error messages.  Only inline data
/// (`Format="XML"`) can be read so: a reference to an HDF5 file is refused with a `Read_error`.  See
/// `read_xdmf(const std::string&, Mesh&)`.
template <class Mesh>
void read_xdmf(std::istream& in, Mesh& mesh, const std::string& name = "<stream>") {
  const std::string text = internal::load_stream(in, name);
  internal::read_xdmf_text(text, name, std::string(), true, mesh);
}

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to the file `filename` as XDMF 3.0: one `Uniform` grid named `mesh`, a
/// `Tetrahedron` topology (`Int`, precision 8), an `XYZ` geometry (`Float`, precision 8, or 4 with
/// float32 values when `mesh.float32_points` is set), the
/// point-data arrays as `Node` scalar attributes (`Float` 8), the labels, when the mesh has some, as
/// the `Cell` attribute `label` (`Int`, precision 4), the cell-data arrays as `Cell` scalar attributes
/// (`Float` 8).
///
/// By default the values go to the HDF5 file `<stem>.h5` beside `filename` (replaced when it
/// exists), in the datasets `/Mesh/geometry` (V x 3, float64), `/Mesh/topology` (T x 4, int64),
/// `/PointData/<i>`, `/CellData/label` (int32) and `/CellData/<i>`; with `use_binary_mode(false)`,
/// or by default in a build without HDF5, they are written inline in the XML, in the shortest
/// decimal form that reads back exactly.  Both are exact.
///
/// \tparam NamedParameters a sequence of named parameters
/// \param filename the `.xdmf` file
/// \param mesh the mesh
/// \param np the write options (`Write_options.h`)
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{use_binary_mode}
///     \cgalParamDescription{heavy data in an HDF5 file (`true`) or inline XML (`false`)}
///     \cgalParamType{Boolean}
///     \cgalParamDefault{`true` when the build has HDF5, else `false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{compression}
///     \cgalParamDescription{`Compression::none` only}
///     \cgalParamType{`CGAL::PR_star_octree::IO::Compression`}
///     \cgalParamDefault{`Compression::none`}
///   \cgalParamNEnd
///   \cgalParamNBegin{format_version}
///     \cgalParamDescription{3.0 only}
///     \cgalParamType{`double`}
///     \cgalParamDefault{3.0}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Write_error when a file cannot be written, an array does not have one finite value per
/// vertex (per tetrahedron for cell data), two arrays have the same name, the mesh is inconsistent,
/// an option is not possible, or HDF5 storage is asked of a build without HDF5.
template <class Mesh, class NamedParameters = parameters::Default_named_parameters>
void write_xdmf(const std::string& filename, const Mesh& mesh,
                const NamedParameters& np = parameters::default_values()) {
  internal::write_xdmf_file(filename, mesh, internal::write_options(np));
}

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_XDMF_H
