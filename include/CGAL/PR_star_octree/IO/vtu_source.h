// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_VTU_SOURCE_H
#define CGAL_PR_STAR_OCTREE_IO_VTU_SOURCE_H

/// \file vtu_source.h
/// The tetrahedra of a `.vtu` file as a `PRStarOctreeTetrahedronSource`, for the streaming
/// construction of `PR_star_octree_3`.

#include <CGAL/PR_star_octree/IO/Memory_limit.h>
#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/internal/vtu_ranges.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>
#include <CGAL/PR_star_octree/internal/huge_pages.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <future>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace IO {

/// \ingroup PkgPRStarOctreeIO
/// \cgalModels `PRStarOctreeTetrahedronSource`
///
/// Reads a `.vtu` file by ranges (one `<Piece>`, every array appended raw, no compressor: what
/// `prstar generate` and `write_vtu(..., use_binary_mode(true).compression(Compression::none))`
/// write): `read_vertices()` gives its points and point data, `for_each_chunk()` its tetrahedra
/// (VTK type 10; the other cells are skipped and counted) and their labels, chunk by chunk, the file
/// read again at every pass.  The values are those of `read_vtu()`.
class Vtu_tetrahedron_source {
public:
  /// Reads the header of `file`; `chunk` is the number of cells read at a time (two chunks are
  /// held at once).  \throws Read_error when it is missing or malformed; std::invalid_argument
  /// when `chunk` is 0
  explicit Vtu_tetrahedron_source(const std::string& file, std::size_t chunk = std::size_t(1) << 19)
      : reader_(file), chunk_(chunk) {
    if (chunk == 0) throw std::invalid_argument("Vtu_tetrahedron_source: the chunk size must be at least 1");
  }

  /// whether the file can be read by ranges; when not, `reason()` says why and it must be read whole
  bool supported() const { return reader_.ranges_supported(); }
  const std::string& reason() const { return reader_.reason(); }
  std::uint64_t number_of_vertices() const { return reader_.number_of_points(); }
  std::uint64_t number_of_cells() const { return reader_.number_of_cells(); }

  /// the number of tetrahedra (VTK type 10) of the file, counted in its array of cell types (so
  /// the construction does not read the whole connectivity to count them).  When every cell is a
  /// tetrahedron and the offsets are those of consecutive tetrahedra (4, 8, 12...: what `prstar
  /// generate` writes), checked here once, the passes of `for_each_chunk()` that follow read the
  /// connectivity (and the labels) alone.  \throws Read_error for bad data
  std::uint64_t number_of_tetrahedra() const {
    const auto summary = reader_.summarize_cells();
    in_order_ = summary.only_tetrahedra_in_order;
    return summary.tetrahedra;
  }

  /// The points, the point-data arrays and `float32_points` of the file, as a mesh without
  /// tetrahedra (read in chunks: no transient copy of the whole).  \throws Memory_limit_error,
  /// before reading, when the octree that the streaming construction builds from the file (its
  /// points and point data, about 8 bytes per cell and the labels) would exceed
  /// `Memory_limit::current()`; Read_error for bad data
  Indexed_tetrahedral_mesh<> read_vertices() const {
    Indexed_tetrahedral_mesh<> mesh;
    const std::uint64_t nv = reader_.number_of_points();
    internal::check_memory(reader_.file(), reader_.piece_line(), nv, reader_.number_of_cells(),
                           sizeof(Indexed_tetrahedral_mesh<>::Point_3), 8, reader_.point_array_names().size(),
                           reader_.has_labels() ? 1 : 0);
    PR_star_octree::internal::reserve_huge(mesh.points, static_cast<std::size_t>(nv));
    const std::vector<std::string>& names = reader_.point_array_names();
    for (const std::string& name : names) {
      mesh.point_data.push_back({name, {}});
      PR_star_octree::internal::reserve_huge(mesh.point_data.back().values, static_cast<std::size_t>(nv));
    }
    std::vector<double> xyz;
    std::vector<std::vector<double>> arrays(names.size());
    for (std::uint64_t b = 0; b < nv; b += vertex_chunk) {
      const std::uint64_t e = (std::min)(nv, b + vertex_chunk);
      xyz.clear();
      for (auto& a : arrays) a.clear();
      reader_.read_points(b, e, xyz, arrays);
      for (std::size_t i = 0; i + 2 < xyz.size(); i += 3)
        mesh.points.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
      for (std::size_t a = 0; a < arrays.size(); ++a)
        mesh.point_data[a].values.insert(mesh.point_data[a].values.end(), arrays[a].begin(), arrays[a].end());
    }
    mesh.float32_points = reader_.float32_points();
    return mesh;
  }

  /// calls `f(vertices, labels, n)` for consecutive chunks of tetrahedra (see
  /// `PRStarOctreeTetrahedronSource`); the next chunk is read by another thread while `f` runs on
  /// this one.  \throws Read_error for bad data
  template <class F>
  void for_each_chunk(F f) const {
    struct Chunk {
      std::vector<std::uint64_t> tets, ids;
      std::vector<int> labels;
      std::map<std::string, std::size_t> skipped; // summed over the chunks this buffer held
    };
    const std::uint64_t nc = reader_.number_of_cells();
    const bool with_labels = reader_.has_labels();
    const std::uint64_t chunk = chunk_;
    const bool in_order = in_order_;
    const auto read = [this, nc, chunk, with_labels, in_order](Chunk* c, std::uint64_t b) {
      c->tets.clear();
      c->ids.clear();
      c->labels.clear();
      std::vector<int>* labels = with_labels ? &c->labels : nullptr;
      if (in_order)
        reader_.read_tetrahedra(b, (std::min)(nc, b + chunk), c->tets, labels);
      else
        reader_.read_cells(b, (std::min)(nc, b + chunk), c->tets, c->ids, labels, c->skipped);
    };
    Chunk chunks[2];
    if (nc > 0) read(&chunks[0], 0);
    for (std::uint64_t b = 0, i = 0; b < nc; b += chunk, i ^= 1) {
      std::future<void> next; // waits for the read in its destructor, also when `f` throws
      if (b + chunk < nc) next = std::async(std::launch::async, read, &chunks[i ^ 1], b + chunk);
      const Chunk& c = chunks[i];
      f(static_cast<const std::uint64_t*>(c.tets.data()),
        with_labels ? static_cast<const int*>(c.labels.data()) : static_cast<const int*>(nullptr),
        c.tets.size() / 4);
      if (next.valid()) next.get();
    }
    skipped_ = std::move(chunks[0].skipped);
    for (const auto& s : chunks[1].skipped) skipped_[s.first] += s.second;
  }

  /// the cells other than tetrahedra met by the last pass, by type name
  const std::map<std::string, std::size_t>& skipped_cells() const { return skipped_; }

private:
  static constexpr std::uint64_t vertex_chunk = std::uint64_t(1) << 20;
  internal::Vtu_range_reader reader_;
  std::size_t chunk_;
  mutable bool in_order_ = false; // set by number_of_tetrahedra()
  mutable std::map<std::string, std::size_t> skipped_;
};

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_VTU_SOURCE_H
