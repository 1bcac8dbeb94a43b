// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_DISTRIBUTED_H
#define CGAL_PR_STAR_OCTREE_IO_DISTRIBUTED_H

/// \file IO/distributed.h
/// Reading a mesh into `Distributed_mesh_part`s, one per MPI rank, and writing a distributed mesh
/// (a `.pvtu` with one piece per rank, or one file gathered on rank 0).  Requires MPI.

#include <CGAL/PR_star_octree/Distributed_mesh_part.h>
#include <CGAL/PR_star_octree/Distributed_octree_3.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/IO/internal/pvtu_writer.h>
#include <CGAL/PR_star_octree/IO/internal/vtu_ranges.h>
#include <CGAL/PR_star_octree/internal/mpi_communication.h>
#include <CGAL/PR_star_octree/parameters.h>

#include <mpi.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <map>
#include <limits>
#include <memory>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace IO {

namespace internal {

// The block [first, last) of n items for rank r of p.
inline std::pair<std::uint64_t, std::uint64_t> block(std::uint64_t n, int r, int p) {
  return {n * std::uint64_t(r) / std::uint64_t(p), n * std::uint64_t(r + 1) / std::uint64_t(p)};
}

// Rank 0's `all` cut into the blocks of `counts`, one per rank.
template <class T>
std::vector<T> scatter_blocks(MPI_Comm comm, const std::vector<T>& all,
                              const std::vector<std::uint64_t>& counts) {
  using PR_star_octree::internal::checked_count;
  const int p = PR_star_octree::internal::mpi_size(comm), me = PR_star_octree::internal::mpi_rank(comm);
  std::vector<int> c(p), d(p);
  std::size_t total = 0;
  for (int i = 0; i < p; ++i) {
    c[i] = checked_count(counts[i]);
    d[i] = checked_count(total);
    total += counts[i];
  }
  std::vector<T> mine(counts[me]);
  const PR_star_octree::internal::Mpi_record_type<T> type;
  MPI_Scatterv(all.data(), c.data(), d.data(), type.get(), mine.data(), c[me], type.get(), 0, comm);
  return mine;
}

// Rank 0 reads the whole file with `read_tetrahedral_mesh()` and sends each rank its blocks.
inline Distributed_mesh_part read_on_rank_0_and_scatter(const std::string& file, MPI_Comm comm) {
  using namespace PR_star_octree::internal;
  const int p = mpi_size(comm), me = mpi_rank(comm);
  Indexed_tetrahedral_mesh<> mesh;
  run_collectively(comm, [&] {
    if (me == 0) read_tetrahedral_mesh(file, mesh);
  });
  Distributed_mesh_part part;
  // sizes and names
  std::uint64_t sizes[5] = {mesh.points.size(), mesh.tetrahedra.size(), mesh.point_data.size(),
                            mesh.tetrahedron_labels.empty() ? 0u : 1u, mesh.float32_points ? 1u : 0u};
  MPI_Bcast(sizes, 5, MPI_UINT64_T, 0, comm);
  part.float32_points = sizes[4] != 0;
  std::vector<std::uint64_t> vertex_counts(p), tet_counts(p);
  for (int r = 0; r < p; ++r) {
    const auto b = block(sizes[0], r, p), t = block(sizes[1], r, p);
    vertex_counts[r] = b.second - b.first;
    tet_counts[r] = t.second - t.first;
  }
  part.first_vertex = block(sizes[0], me, p).first;
  {
    std::vector<std::array<double, 3>> xyz;
    if (me == 0) {
      xyz.reserve(mesh.points.size());
      for (const auto& q : mesh.points) xyz.push_back({{q.x(), q.y(), q.z()}});
      std::vector<Indexed_tetrahedral_mesh<>::Point_3>().swap(mesh.points);
    }
    const auto mine = scatter_blocks(comm, xyz, vertex_counts);
    part.coordinates.reserve(3 * mine.size());
    for (const auto& q : mine) part.coordinates.insert(part.coordinates.end(), q.begin(), q.end());
  }
  for (std::uint64_t a = 0; a < sizes[2]; ++a) {
    std::string name = me == 0 ? mesh.point_data[a].name : std::string();
    std::uint64_t n = name.size();
    MPI_Bcast(&n, 1, MPI_UINT64_T, 0, comm);
    name.resize(n);
    MPI_Bcast(&name[0], checked_count(n), MPI_CHAR, 0, comm);
    part.point_array_names.push_back(name);
    part.point_arrays.push_back(
        scatter_blocks(comm, me == 0 ? mesh.point_data[a].values : std::vector<double>(), vertex_counts));
    if (me == 0) std::vector<double>().swap(mesh.point_data[a].values);
  }
  {
    std::vector<std::array<std::uint64_t, 4>> tets;
    if (me == 0) {
      tets.reserve(mesh.tetrahedra.size());
      for (const auto& c : mesh.tetrahedra) tets.push_back({{c[0], c[1], c[2], c[3]}});
      std::vector<Indexed_tetrahedral_mesh<>::Tetrahedron>().swap(mesh.tetrahedra);
    }
    part.tetrahedra = scatter_blocks(comm, tets, tet_counts);
  }
  if (sizes[3]) part.tetrahedron_labels = scatter_blocks(comm, mesh.tetrahedron_labels, tet_counts);
  if (me == 0) part.skipped_cells = mesh.skipped_cells;
  return part;
}

// Each rank reads its own byte ranges of an appended-raw .vtu: its block of points now, its block of
// cells later, in blocks, when the octree's construction asks for them (deferred tetrahedra).
inline Distributed_mesh_part read_vtu_ranges(std::shared_ptr<const Vtu_range_reader> reader, MPI_Comm comm) {
  using namespace PR_star_octree::internal;
  const int p = mpi_size(comm), me = mpi_rank(comm);
  Distributed_mesh_part part;
  const auto vb = block(reader->number_of_points(), me, p), cb = block(reader->number_of_cells(), me, p);
  part.first_vertex = vb.first;
  part.float32_points = reader->float32_points();
  part.point_array_names = reader->point_array_names();
  run_collectively(comm, [&] {
    part.point_arrays.resize(part.point_array_names.size());
    reader->read_points(vb.first, vb.second, part.coordinates, part.point_arrays);
  });
  if (reader->has_labels()) part.label_name = reader->label_array_name();
  constexpr std::uint64_t cells_per_block = std::uint64_t(1) << 18; // as the construction's rounds
  part.tetrahedron_blocks = std::size_t((cb.second - cb.first + cells_per_block - 1) / cells_per_block);
  part.deferred_labels = reader->has_labels();
  part.read_tetrahedra = [reader, cb](std::size_t k, std::vector<std::array<std::uint64_t, 4>>& tetrahedra,
                                      std::vector<int>& labels) {
    const std::uint64_t b = cb.first + k * cells_per_block, e = (std::min)(cb.second, b + cells_per_block);
    std::vector<std::uint64_t> flat, cell_ids;
    std::map<std::string, std::size_t> skipped;
    reader->read_cells(b, e, flat, cell_ids, reader->has_labels() ? &labels : nullptr, skipped);
    tetrahedra.resize(cell_ids.size());
    for (std::size_t t = 0; t < cell_ids.size(); ++t)
      for (int i = 0; i < 4; ++i) tetrahedra[t][i] = flat[4 * t + i];
  };
  return part;
}

// A point of a .pvtu piece sent to the rank that merges its copies: by global id (`GlobalPointIds`)
// or by exact coordinates.
struct Piece_point {
  double x, y, z;
  std::uint64_t id;
  std::uint64_t source; // its index on the rank that read it
  bool same(const Piece_point& o, bool by_id) const {
    return by_id ? id == o.id : (x == o.x && y == o.y && z == o.z);
  }
  static bool less(const Piece_point& a, const Piece_point& b, bool by_id) {
    if (by_id) return a.id < b.id;
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
  }
};

// A .pvtu: the ranks read its pieces (whole pieces, contiguous runs of them, any encoding), drop
// the ghost cells (`vtkGhostType` & 1), and merge the copies of the points shared by pieces: by
// `GlobalPointIds` when every piece has them (the merged vertices keep them as global ids when they
// number the vertices 0 ... n-1), else by exact coordinates.  The merged vertices are numbered in
// blocks, one per rank, as `Distributed_octree_3` takes them.
inline Distributed_mesh_part read_pvtu(const std::string& file, MPI_Comm comm) {
  using namespace PR_star_octree::internal;
  const int p = mpi_size(comm), me = mpi_rank(comm);
  std::vector<std::string> pieces;
  run_collectively(comm, [&] { pieces = read_pvtu_piece_files(file); });
  const std::size_t first_piece = pieces.size() * std::size_t(me) / std::size_t(p),
                    last_piece = pieces.size() * std::size_t(me + 1) / std::size_t(p);
  // this rank's pieces, concatenated
  std::vector<Piece_point> points;
  std::vector<std::vector<double>> arrays;
  std::vector<std::string> names;
  std::vector<std::array<std::uint64_t, 4>> tets; // in indices of `points`
  std::vector<int> labels;
  bool by_id = true, has_labels = false, float32 = true; // float32: this rank's pieces all are
  run_collectively(comm, [&] {
    for (std::size_t k = first_piece; k < last_piece; ++k) {
      Indexed_tetrahedral_mesh<> m;
      read_tetrahedral_mesh(pieces[k], m);
      float32 = float32 && m.float32_points;
      const std::uint64_t base = points.size();
      const Data_array* ids = nullptr;
      std::vector<const Data_array*> kept;
      std::vector<std::string> piece_names;
      for (const Data_array& a : m.point_data) {
        if (a.name == "GlobalPointIds")
          ids = &a;
        else if (a.name != "vtkGhostType") {
          kept.push_back(&a);
          piece_names.push_back(a.name);
        }
      }
      if (k == first_piece) {
        names = piece_names;
        arrays.resize(names.size());
        has_labels = !m.tetrahedron_labels.empty();
      } else if (piece_names != names)
        throw Read_error(pieces[k], 0, "its point arrays differ from those of " + pieces[first_piece]);
      by_id = by_id && ids != nullptr;
      for (std::size_t v = 0; v < m.points.size(); ++v) {
        const auto& q = m.points[v];
        const double id = ids ? ids->values[v] : 0.;
        if (ids && !(id >= 0 && id < 9007199254740992.))
          throw Read_error(pieces[k], 0, "GlobalPointIds of point " + std::to_string(v) + " is not an id");
        points.push_back({q.x(), q.y(), q.z(), std::uint64_t(id), points.size()});
      }
      for (std::size_t a = 0; a < kept.size(); ++a)
        arrays[a].insert(arrays[a].end(), kept[a]->values.begin(), kept[a]->values.end());
      const Data_array* ghost = nullptr;
      for (const Data_array& a : m.cell_data)
        if (a.name == "vtkGhostType") ghost = &a;
      for (std::size_t t = 0; t < m.tetrahedra.size(); ++t) {
        if (ghost && (static_cast<unsigned>(ghost->values[t]) & 1u))
          continue; // a copy of another piece's cell
        const auto& c = m.tetrahedra[t];
        tets.push_back({{base + c[0], base + c[1], base + c[2], base + c[3]}});
        if (has_labels) labels.push_back(m.tetrahedron_labels.empty() ? 0 : m.tetrahedron_labels[t]);
      }
    }
  });
  // the same merge rule and names on every rank (a rank without a piece agrees with the others)
  int local_flags[2] = {(by_id || first_piece == last_piece) ? 1 : 0, float32 ? 1 : 0}, all_flags[2] = {0, 0};
  MPI_Allreduce(local_flags, all_flags, 2, MPI_INT, MPI_MIN, comm);
  by_id = all_flags[0] != 0 && !pieces.empty();
  const bool all_float32 = all_flags[1] != 0 && !pieces.empty();
  {
    // the names and the labels of piece 0, from the rank that read it
    int root = 0;
    while (root + 1 < p && pieces.size() * std::size_t(root + 1) / std::size_t(p) == 0) ++root;
    std::uint64_t n = names.size();
    MPI_Bcast(&n, 1, MPI_UINT64_T, root, comm);
    names.resize(n);
    for (auto& name : names) {
      std::uint64_t len = name.size();
      MPI_Bcast(&len, 1, MPI_UINT64_T, root, comm);
      name.resize(len);
      MPI_Bcast(&name[0], checked_count(len), MPI_CHAR, root, comm);
    }
    int l = has_labels ? 1 : 0;
    MPI_Bcast(&l, 1, MPI_INT, root, comm);
    has_labels = l != 0;
    if (first_piece == last_piece) arrays.assign(names.size(), {});
  }
  std::uint64_t local_max = 0, max_id = 0;
  for (const auto& q : points) local_max = (std::max)(local_max, q.id);
  MPI_Allreduce(&local_max, &max_id, 1, MPI_UINT64_T, MPI_MAX, comm);
  // each point to the rank that merges its copies: by id range, or by a hash of the coordinates
  auto destination = [&](const Piece_point& q) {
    if (by_id) return int(q.id * std::uint64_t(p) / (max_id + 1));
    std::uint64_t h = 1469598103934665603ULL;
    for (double c : {q.x, q.y, q.z}) {
      std::uint64_t b;
      std::memcpy(&b, &c, sizeof b);
      h = (h ^ b) * 1099511628211ULL;
    }
    return int(h % std::uint64_t(p));
  };
  const std::size_t na = names.size();
  std::vector<Piece_point> received;
  std::vector<double> received_values;
  std::vector<std::size_t> from;
  {
    std::vector<std::vector<Piece_point>> send(p);
    std::vector<std::vector<double>> send_values(p);
    for (const auto& q : points) {
      const int r = destination(q);
      send[r].push_back(q);
      for (std::size_t a = 0; a < na; ++a) send_values[r].push_back(arrays[a][q.source]);
    }
    received = all_to_all(comm, send, &from);
    received_values = all_to_all(comm, send_values);
  }
  // merge: sort, number the distinct points in blocks of the ranks
  std::vector<std::size_t> order(received.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return Piece_point::less(received[a], received[b], by_id); });
  std::vector<std::uint64_t> merged(received.size());
  Distributed_mesh_part part;
  part.float32_points = all_float32;
  part.point_array_names = names;
  part.point_arrays.assign(na, {});
  std::uint64_t distinct = 0;
  for (std::size_t k = 0; k < order.size(); ++k)
    if (k == 0 || !received[order[k]].same(received[order[k - 1]], by_id)) ++distinct;
  std::uint64_t first = 0;
  MPI_Exscan(&distinct, &first, 1, MPI_UINT64_T, MPI_SUM, comm);
  if (me == 0) first = 0;
  part.first_vertex = first;
  std::uint64_t next = first;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t i = order[k];
    if (k == 0 || !received[i].same(received[order[k - 1]], by_id)) {
      part.coordinates.insert(part.coordinates.end(), {received[i].x, received[i].y, received[i].z});
      for (std::size_t a = 0; a < na; ++a) part.point_arrays[a].push_back(received_values[na * i + a]);
      ++next;
    }
    merged[i] = next - 1;
  }
  // the merged ids back to the ranks that read the points, in the order they sent them
  std::vector<std::vector<std::uint64_t>> reply(p);
  {
    std::size_t k = 0;
    for (int r = 0; r < p; ++r)
      for (std::size_t j = 0; j < from[r]; ++j, ++k) reply[r].push_back(merged[k]);
  }
  const std::vector<std::uint64_t> answers = all_to_all(comm, reply);
  std::vector<std::uint64_t> id_of(points.size());
  {
    std::vector<std::size_t> position(p + 1, 0);
    for (const auto& q : points) ++position[destination(q) + 1];
    for (int r = 0; r < p; ++r) position[r + 1] += position[r];
    for (const auto& q : points) id_of[q.source] = answers[position[destination(q)]++];
  }
  for (auto& c : tets)
    for (auto& v : c) v = id_of[v];
  part.tetrahedra = std::move(tets);
  part.tetrahedron_labels = std::move(labels);
  return part;
}

} // namespace internal

/// \ingroup PkgPRStarOctreeDistributed
/// Reads this rank's part of the mesh in `file` (collective: every rank calls it with the same
/// file).  A `.vtu` whose arrays are appended raw binary (as `write_tetrahedral_mesh()` writes it
/// with `compression(IO::Compression::none)`, and as VTK, ParaView and meshio write big meshes) is
/// read in parallel: each rank reads only the byte ranges of its block of points and of cells.
/// A `.pvtu` (as ParaView, VTK or `write_pvtu()` write it: any number of pieces for any number of
/// ranks) is read piece by piece by the ranks, each reading a contiguous run of pieces; the ghost
/// cells (`vtkGhostType`) are dropped and the copies of the points shared by several pieces merged,
/// by `GlobalPointIds` when the pieces have them, else by exact coordinates.  Any other file of the
/// format table is read by rank 0 and its blocks sent to the ranks.  The tetrahedra keep their
/// index among the file's tetrahedra (the pieces' in piece order) as global id.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{communicator}
///     \cgalParamDescription{the ranks that read}
///     \cgalParamType{`MPI_Comm`}
///     \cgalParamDefault{`MPI_COMM_WORLD`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Distributed_error on every rank, with the message of the rank that failed (a missing or
///         malformed file: the file, the line or element, what is wrong)
template <class NP = parameters::Default_named_parameters>
Distributed_mesh_part read_mesh_part(const std::string& file, const NP& np = parameters::default_values()) {
  const MPI_Comm comm = parameters::choose_parameter(
      parameters::get_parameter(np, PR_star_octree::internal_np::communicator), MPI_COMM_WORLD);
  std::string ext = file.size() >= 4 ? file.substr(file.size() - 4) : std::string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == "pvtu" && file.size() >= 5 && file[file.size() - 5] == '.')
    return internal::read_pvtu(file, comm);
  if (ext == ".vtu") {
    std::shared_ptr<internal::Vtu_range_reader> reader;
    PR_star_octree::internal::run_collectively(
        comm, [&] { reader = std::make_shared<internal::Vtu_range_reader>(file); });
    if (reader->ranges_supported()) return internal::read_vtu_ranges(reader, comm);
  }
  return internal::read_on_rank_0_and_scatter(file, comm);
}

/// \ingroup PkgPRStarOctreeDistributed
/// A point array of a distributed mesh to write: its name and one value per local vertex of the rank
/// (by part index, ghost vertices included, see `Distributed_octree_3::update_ghosts()`).
struct Distributed_point_array {
  std::string name;                  ///< the array's name in the file
  const std::vector<double>* values; ///< by part index
};

/// \ingroup PkgPRStarOctreeDistributed
/// Writes the distributed mesh as `file` (a `.pvtu`) plus one `.vtu` piece per rank, in the folder
/// named like `file` without its extension, as ParaView does (collective): each piece holds the
/// rank's tetrahedra (the stars of its vertices: its own, and one layer of ghost cells owned by
/// other ranks) and their vertices, with the arrays `vtkGhostType` (points and cells of other
/// ranks: 1), `GlobalPointIds` and `GlobalCellIds` (the input's numbering), the labels as cell data
/// and `point_arrays` (then the input's point arrays) as point data.  ParaView and VTK open it as
/// one mesh; removing the ghost cells leaves each tetrahedron once.  Each file is written through a
/// temporary and renamed.
/// \throws Distributed_error on every rank if a rank cannot write its piece
template <class GT>
void write_pvtu(const std::string& file, const Distributed_octree_3<GT>& tree,
                const std::vector<Distributed_point_array>& point_arrays) {
  using Octree = typename Distributed_octree_3<GT>::Octree;
  using Index = typename Octree::Index;
  namespace fs = std::filesystem;
  const MPI_Comm comm = tree.communicator();
  const Octree& octree = tree.local_octree();
  const fs::path pvtu(file);
  const std::string stem = pvtu.stem().string();
  const fs::path folder = pvtu.parent_path() / stem;
  PR_star_octree::internal::run_collectively(comm, [&] {
    if (tree.rank() == 0) {
      std::error_code ec;
      fs::create_directories(folder, ec);
      if (ec) throw Write_error(folder.string(), "cannot create the folder of the pieces: " + ec.message());
    }
  });
  const std::size_t n = octree.number_of_vertices(), nt = octree.number_of_tetrahedra();
  std::vector<double> xyz(3 * n);
  std::vector<std::int64_t> gids(n), cell_ids(nt);
  std::vector<std::uint8_t> point_ghosts(n), cell_ghosts(nt);
  std::vector<int> labels(tree.has_tetrahedron_labels() ? nt : 0);
  std::vector<std::vector<double>> arrays;
  for (Index v = 0; v < n; ++v) {
    const auto c = octree.coordinates(octree.point(v));
    for (int a = 0; a < 3; ++a) xyz[3 * v + a] = c[a];
    gids[v] = std::int64_t(tree.global_id(v));
    point_ghosts[v] = tree.owns_vertex(v) ? 0 : internal::vtk_duplicate_point;
  }
  for (Index t = 0; t < nt; ++t) {
    cell_ids[t] = std::int64_t(tree.global_tetrahedron_id(t));
    cell_ghosts[t] = tree.counts_tetrahedron(t) ? 0 : internal::vtk_duplicate_cell;
    if (!labels.empty()) labels[t] = octree.tetrahedron_label(t);
  }
  std::vector<std::string> names;
  auto add = [&](const std::string& name, const std::vector<double>& by_part) {
    std::vector<double> values(n);
    for (Index v = 0; v < n; ++v) values[v] = by_part[octree.original_vertex(v)];
    arrays.push_back(std::move(values));
    names.push_back(name);
  };
  for (const auto& a : point_arrays) add(a.name, *a.values);
  for (std::size_t a = 0; a < tree.point_array_names().size(); ++a)
    if (std::find(names.begin(), names.end(), tree.point_array_names()[a]) == names.end())
      add(tree.point_array_names()[a], tree.point_array(a));
  // non-null pointers even for an empty piece: a null pointer means "no such array"
  static const double no_double = 0;
  static const std::int64_t no_id = 0;
  static const std::uint8_t no_ghost = 0;
  static const int no_label = 0;
  internal::Vtu_piece piece;
  piece.xyz = n ? xyz.data() : &no_double;
  piece.number_of_points = n;
  // the octree's own array of tetrahedra (four 32-bit indices each, no copy), decoded if compact
  static_assert(sizeof(typename Octree::Tetrahedron) == 4 * sizeof(std::uint32_t), "32-bit local indices");
  static const std::uint32_t no_tetrahedron[4] = {0, 0, 0, 0};
  std::vector<typename Octree::Tetrahedron> decoded;
  if (octree.is_compact()) decoded.assign(octree.tetrahedra().begin(), octree.tetrahedra().end());
  piece.tetrahedra =
      nt == 0 ? no_tetrahedron
              : (octree.is_compact() ? decoded.front().data() : octree.tetrahedra().data()->data());
  piece.number_of_tetrahedra = nt;
  piece.point_ghosts = n ? point_ghosts.data() : &no_ghost;
  piece.cell_ghosts = nt ? cell_ghosts.data() : &no_ghost;
  piece.global_point_ids = n ? gids.data() : &no_id;
  piece.global_cell_ids = nt ? cell_ids.data() : &no_id;
  if (tree.has_tetrahedron_labels()) {
    piece.labels = nt ? labels.data() : &no_label;
    piece.label_name = tree.label_name();
  }
  for (std::size_t a = 0; a < arrays.size(); ++a)
    piece.point_arrays.push_back({names[a], n ? arrays[a].data() : &no_double});
  auto piece_name = [&](int r) { return stem + "_" + std::to_string(r) + ".vtu"; };
  PR_star_octree::internal::run_collectively(
      comm, [&] { internal::write_vtu_piece((folder / piece_name(tree.rank())).string(), piece); });
  PR_star_octree::internal::run_collectively(comm, [&] {
    if (tree.rank() != 0) return;
    std::vector<std::string> pieces;
    for (int r = 0; r < tree.number_of_ranks(); ++r) pieces.push_back(stem + "/" + piece_name(r));
    internal::write_pvtu(file, pieces, piece);
  });
}

/// \ingroup PkgPRStarOctreeDistributed
/// The whole mesh gathered on rank 0 (collective; the other ranks get an empty mesh), for outputs
/// small enough for one process: the vertices in the order of their global ids, the tetrahedra in
/// the order of theirs (each once, from its owner), the labels, and as point data `point_arrays`
/// then the input's point arrays.
template <class GT>
Indexed_tetrahedral_mesh<> gather_mesh(const Distributed_octree_3<GT>& tree,
                                       const std::vector<Distributed_point_array>& point_arrays) {
  using Octree = typename Distributed_octree_3<GT>::Octree;
  using Index = typename Octree::Index;
  using PR_star_octree::internal::gather_vectors;
  const MPI_Comm comm = tree.communicator();
  const Octree& octree = tree.local_octree();
  if (tree.number_of_vertices() > (std::numeric_limits<std::uint32_t>::max)())
    throw Distributed_error("gather_mesh: more than 2^32 vertices do not fit one mesh: write a .pvtu");
  std::vector<std::string> names;
  std::vector<const std::vector<double>*> sources;
  for (const auto& a : point_arrays) {
    names.push_back(a.name);
    sources.push_back(a.values);
  }
  for (std::size_t a = 0; a < tree.point_array_names().size(); ++a)
    if (std::find(names.begin(), names.end(), tree.point_array_names()[a]) == names.end()) {
      names.push_back(tree.point_array_names()[a]);
      sources.push_back(&tree.point_array(a));
    }
  Indexed_tetrahedral_mesh<> mesh;
  const std::size_t owned = tree.number_of_owned_vertices();
  {
    std::vector<std::uint64_t> ids(owned);
    for (std::size_t i = 0; i < owned; ++i) ids[i] = tree.global_vertex_id(i);
    const std::vector<std::uint64_t> all_ids = gather_vectors(comm, ids);
    auto gather_values = [&](auto get) {
      std::vector<double> mine(owned), out;
      for (std::size_t i = 0; i < owned; ++i) mine[i] = get(i);
      const std::vector<double> all = gather_vectors(comm, mine);
      if (tree.rank() == 0) {
        out.resize(all.size());
        for (std::size_t k = 0; k < all.size(); ++k) out[all_ids[k]] = all[k];
      }
      return out;
    };
    // the coordinates, by part index
    std::vector<std::array<double, 3>> by_part(owned);
    for (Index v = 0; v < octree.number_of_vertices(); ++v) {
      const std::size_t i = octree.original_vertex(v);
      if (i < owned) by_part[i] = octree.coordinates(octree.point(v));
    }
    const std::vector<double> x = gather_values([&](std::size_t i) { return by_part[i][0]; });
    const std::vector<double> y = gather_values([&](std::size_t i) { return by_part[i][1]; });
    const std::vector<double> z = gather_values([&](std::size_t i) { return by_part[i][2]; });
    for (std::size_t k = 0; k < x.size(); ++k) mesh.points.emplace_back(x[k], y[k], z[k]);
    for (std::size_t a = 0; a < names.size(); ++a) {
      std::vector<double> values = gather_values([&](std::size_t i) { return (*sources[a])[i]; });
      if (tree.rank() == 0) mesh.point_data.push_back({names[a], std::move(values)});
    }
  }
  struct Cell {
    std::uint64_t id;
    std::array<std::uint32_t, 4> vertices;
    std::int32_t label, unused;
  };
  std::vector<Cell> mine;
  for (Index t = 0; t < octree.number_of_tetrahedra(); ++t) {
    if (!tree.counts_tetrahedron(t)) continue;
    Cell c{tree.global_tetrahedron_id(t), {}, octree.tetrahedron_label(t), 0};
    for (int i = 0; i < 4; ++i) c.vertices[i] = std::uint32_t(tree.global_id(octree.tetrahedron(t)[i]));
    mine.push_back(c);
  }
  std::vector<Cell> cells = gather_vectors(comm, mine);
  std::sort(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) { return a.id < b.id; });
  for (const Cell& c : cells) {
    mesh.tetrahedra.push_back(c.vertices);
    if (tree.has_tetrahedron_labels()) mesh.tetrahedron_labels.push_back(c.label);
  }
  return mesh;
}

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_DISTRIBUTED_H
