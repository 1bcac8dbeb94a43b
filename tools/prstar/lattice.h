// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A generator for huge meshes: a jittered Kuhn lattice streamed straight to a binary VTU.

#ifndef PRSTAR_LATTICE_H
#define PRSTAR_LATTICE_H

#include <cstddef>
#include <functional>
#include <ostream>

namespace prstar {

/// The lattice of `cells`^3 unit cubes, each cut into the 6 tetrahedra of its Kuhn subdivision
/// around the diagonal from (0,0,0) to (1,1,1), all positively oriented, vertices jittered
/// inside a cube of side 0.2 (the boundary vertices stay on the boundary planes; no tetrahedron can
/// flip), with the point array `scalar` = x^2 / (cells + 1) + y - z.
struct Lattice {
  std::size_t cells = 0;
  std::size_t number_of_vertices() const { return (cells + 1) * (cells + 1) * (cells + 1); }
  std::size_t number_of_tetrahedra() const { return 6 * cells * cells * cells; }
};

/// Writes the lattice as a VTK XML UnstructuredGrid with raw appended binary data (Float64 points
/// and scalar, Int32 connectivity and offsets where they fit and Int64 otherwise, UInt8 types,
/// UInt64 headers), streaming: memory
/// does not grow with the lattice.  `progress(done, total)` is called as it goes.  Appended, unlike
/// the package's `.vtu` writer, so that `IO::read_mesh_part()` reads each rank's byte ranges.
void write_lattice_vtu(std::ostream& out, const Lattice& lattice,
                       const std::function<void(std::size_t, std::size_t)>& progress);

} // namespace prstar

#endif // PRSTAR_LATTICE_H
