// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_DISTRIBUTED_OCTREE_3_H
#define CGAL_PR_STAR_OCTREE_DISTRIBUTED_OCTREE_3_H

/// \file Distributed_octree_3.h
/// The PR-star octree over MPI: the ranks own contiguous ranges of the vertices in the octree's
/// depth-first (Morton) order, each with the stars of its vertices (ghost stars), and each builds
/// an ordinary `PR_star_octree_3` on its part.  Requires MPI.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/Distributed_mesh_part.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>
#include <CGAL/PR_star_octree/internal/mpi_communication.h>
#include <CGAL/PR_star_octree/parameters.h>

#include <mpi.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {

namespace internal {

// 21 bits of each coordinate interleaved (x lowest): the depth-first order of an octree whose
// children are numbered like `PR_star_octree_3`'s octants (bit a set above the midpoint on axis a).
inline std::uint64_t morton_key(const double* p, const double* lo, double inverse_extent) {
  constexpr std::uint64_t cells = std::uint64_t(1) << 21;
  std::uint64_t key = 0;
  for (int a = 0; a < 3; ++a) {
    double t = (p[a] - lo[a]) * inverse_extent * double(cells);
    std::uint64_t q = t <= 0 ? 0 : (t >= double(cells - 1) ? cells - 1 : static_cast<std::uint64_t>(t));
    // spread the 21 bits of q to every third bit
    q &= 0x1fffff;
    q = (q | (q << 32)) & 0x1f00000000ffffULL;
    q = (q | (q << 16)) & 0x1f0000ff0000ffULL;
    q = (q | (q << 8)) & 0x100f00f00f00f00fULL;
    q = (q | (q << 4)) & 0x10c30c30c30c30c3ULL;
    q = (q | (q << 2)) & 0x1249249249249249ULL;
    key |= q << a;
  }
  return key;
}

struct Morton_record {
  std::uint64_t key, id;
  bool operator<(const Morton_record& o) const { return key != o.key ? key < o.key : id < o.id; }
};

struct Weighted_sample {
  Morton_record record;
  double weight;
};

// A tetrahedron sent to the owners of its vertices.
// A vertex's owner and its index there (the directory's answer).
struct Owner_index {
  std::int32_t owner;
  std::uint32_t index;
};

// A tetrahedron sent to the owners of its vertices: each corner with its global id, its owner and
// its index on its owner (so that no rank has to look an id up).
struct Tetrahedron_record {
  std::array<std::uint64_t, 4> vertices;
  std::uint64_t id;
  std::array<Owner_index, 4> corners;
  std::int32_t label;
  std::int32_t unused;
};

struct Id_index {
  std::uint64_t id;
  std::uint32_t index;
  std::int32_t unused;
};

// A vector in chunks of 2^22 items, which never reallocates (no transient second copy while it
// grows) and whose big chunks (allocated alone, mapped by the system) are given back one by one
// when it is moved into a flat vector.
template <class T>
class Chunked_vector {
  static constexpr int shift = 22;
  static constexpr std::size_t chunk = std::size_t(1) << shift;

public:
  void push_back(const T& x) {
    if (chunks_.empty() || chunks_.back().size() == chunk) {
      chunks_.emplace_back();
      chunks_.back().reserve(chunk);
    }
    chunks_.back().push_back(x);
    ++size_;
  }
  std::size_t size() const { return size_; }
  const T& operator[](std::size_t i) const { return chunks_[i >> shift][i & (chunk - 1)]; }
  template <class F>
  void for_each(F f) {
    for (auto& c : chunks_)
      for (T& x : c) f(x);
  }
  // the items in one vector; each chunk freed once copied
  std::vector<T> release() {
    std::vector<T> r;
    r.reserve(size_);
    for (auto& c : chunks_) {
      r.insert(r.end(), c.begin(), c.end());
      std::vector<T>().swap(c);
    }
    chunks_.clear();
    size_ = 0;
    return r;
  }

private:
  std::vector<std::vector<T>> chunks_;
  std::size_t size_ = 0;
};

struct Id_owner {
  std::uint64_t id;
  std::int32_t owner;
  std::uint32_t index; // on the owner
};

} // namespace internal

/// \ingroup PkgPRStarOctreeDistributed
/// The PR-star octree of a mesh spread over the ranks of an MPI communicator.
///
/// The construction is collective.  The vertices are ordered by the Morton code of their position
/// in the bounding box of the whole mesh (the depth-first order of an octree of depth 21) and split
/// into contiguous ranges, one per rank, balanced by work (each vertex weighs one plus the size of
/// its star), with a parallel sample sort: no rank ever holds the whole mesh.  A rank *owns* the
/// vertices of its range; a tetrahedron lives on every rank that owns one of its vertices (the
/// PR-star rule lifted to ranks: the stars of the owned vertices are complete); the other vertices
/// of those tetrahedra are the rank's *ghost* vertices.  Each rank then builds an ordinary
/// `PR_star_octree_3` (`local_octree()`) on its owned and ghost vertices and its tetrahedra.
///
/// Numberings: global ids are 64-bit (the input's numbering of the vertices and of the cells);
/// local indices are 32-bit.  The *part index* of a local vertex is its position in the rank's
/// vertex list: the owned vertices first, in Morton order, then the ghost vertices, grouped by owner
/// rank; it is the "user's numbering" of the local octree (`local_octree().original_vertex(v)`).
/// A simplex is counted by the rank that owns its vertex of smallest global id (every tetrahedron
/// incident in it is then on that rank).
///
/// \tparam GeomTraits as for `PR_star_octree_3`
template <class GeomTraits = CGAL::Exact_predicates_inexact_constructions_kernel>
class Distributed_octree_3 {
public:
  using Geom_traits = GeomTraits;
  using Index = std::uint32_t;
  using Global_id = std::uint64_t;
  using Octree = PR_star_octree_3<GeomTraits, Index>;
  using Point_3 = typename Octree::Point_3;

  /// Builds the distributed octree from this rank's part of the mesh (collective; `part` is
  /// consumed).
  ///
  /// \param part this rank's part (see `Distributed_mesh_part`)
  /// \param np an optional sequence of named parameters among the ones listed below
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{communicator}
  ///     \cgalParamDescription{the ranks that hold the mesh}
  ///     \cgalParamType{`MPI_Comm`}
  ///     \cgalParamDefault{`MPI_COMM_WORLD`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{bucket_size}
  ///     \cgalParamDescription{k_v of the local octrees}
  ///     \cgalParamType{`std::size_t`}
  ///     \cgalParamDefault{`PR_star_octree_3::default_bucket_size`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{maximum_depth}
  ///     \cgalParamDescription{the depth bound of the local octrees}
  ///     \cgalParamType{`std::size_t`}
  ///     \cgalParamDefault{as `PR_star_octree_3`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{compact_tetrahedra}
  ///     \cgalParamDescription{the local octrees store their tetrahedra compactly (as
  ///       `PR_star_octree_3`; the same results)}
  ///     \cgalParamType{`bool`}
  ///     \cgalParamDefault{`false`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{coordinate_precision}
  ///     \cgalParamDescription{how the local octrees store the coordinates, which each rank reads as
  ///       doubles: `Coordinate_precision::float32` rounds each to the nearest `float`, as
  ///       `PR_star_octree_3` does, so the results are those of one process with the same
  ///       parameter; `Coordinate_precision::as_input` keeps floats when the parts say the file's
  ///       were (`Distributed_mesh_part::float32_points` on every rank)}
  ///     \cgalParamType{`Coordinate_precision`}
  ///     \cgalParamDefault{`Coordinate_precision::as_input`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{concurrency_tag}
  ///     \cgalParamDescription{how each rank builds its local octree}
  ///     \cgalParamType{`CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`}
  ///     \cgalParamDefault{`CGAL::Parallel_if_available_tag()`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \throws Distributed_error on every rank, with the same message, if the parts are not a mesh
  ///         (a vertex id out of range, vertex blocks that do not follow each other) or the local
  ///         octree of a rank cannot be built
  template <class NP = parameters::Default_named_parameters>
  explicit Distributed_octree_3(Distributed_mesh_part&& part, const NP& np = parameters::default_values())
      : comm_(parameters::choose_parameter(parameters::get_parameter(np, internal_np::communicator),
                                           MPI_COMM_WORLD)) {
    rank_ = internal::mpi_rank(comm_);
    size_ = internal::mpi_size(comm_);
    auto clock = std::chrono::steady_clock::now();
    auto lap = [&clock](double& s) {
      const auto now = std::chrono::steady_clock::now();
      s = std::chrono::duration<double>(now - clock).count();
      clock = now;
    };
    partition(part);
    lap(partition_seconds_);
    build_local(np);
    lap(build_seconds_);
  }

  /// \name The ranks
  /// @{
  MPI_Comm communicator() const { return comm_; }
  int rank() const { return rank_; }
  int number_of_ranks() const { return size_; }
  /// @}

  /// \name The whole mesh
  /// @{
  /// the number of vertices of the whole mesh
  Global_id number_of_vertices() const { return global_vertices_; }
  /// the number of tetrahedra of the whole mesh
  Global_id number_of_tetrahedra() const { return global_tetrahedra_; }
  /// the names of the point arrays of the input (the first is the scalar field)
  const std::vector<std::string>& point_array_names() const { return array_names_; }
  /// whether the tetrahedra have labels
  bool has_tetrahedron_labels() const { return local_->has_tetrahedron_labels(); }
  /// the name of the label array of the input
  const std::string& label_name() const { return label_name_; }
  /// @}

  /// \name This rank's part
  /// @{
  /// the octree of this rank's owned and ghost vertices and the stars of the owned ones
  const Octree& local_octree() const { return *local_; }
  /// owned plus ghost vertices
  std::size_t number_of_local_vertices() const { return gids_.size(); }
  /// the vertices this rank owns: part indices `0 ... number_of_owned_vertices() - 1`
  std::size_t number_of_owned_vertices() const { return owned_; }
  std::size_t number_of_ghost_vertices() const { return gids_.size() - owned_; }
  /// the global id of the vertex of part index `i`
  Global_id global_vertex_id(std::size_t i) const { return gids_[i]; }
  /// the rank that owns the vertex of part index `i`
  int vertex_owner(std::size_t i) const { return i < owned_ ? rank_ : ghost_owner_[i - owned_]; }
  /// the values of point array `a` at the local vertices (by part index; ghosts included)
  const std::vector<double>& point_array(std::size_t a) const { return arrays_[a]; }

  /// whether this rank owns vertex `v` of the local octree's numbering
  bool owns_vertex(Index v) const { return local_->original_vertex(v) < owned_; }
  /// the global id of vertex `v` of the local octree's numbering
  Global_id global_id(Index v) const { return gids_[local_->original_vertex(v)]; }
  /// the global id of tetrahedron `t` of the local octree's numbering
  Global_id global_tetrahedron_id(Index t) const {
    const std::size_t i = local_->original_tetrahedron(t);
    return short_tet_gids_ ? Global_id(tet_gids32_[i]) : tet_gids_[i];
  }
  /// the local vertex (local octree numbering) of smallest global id among `vertices`
  template <class Range>
  Index smallest(const Range& vertices) const {
    Index best = *vertices.begin();
    Global_id g = global_id(best);
    for (Index v : vertices) {
      const Global_id h = global_id(v);
      if (h < g) {
        g = h;
        best = v;
      }
    }
    return best;
  }
  /// whether this rank counts the simplex of local vertices `vertices` (local octree numbering):
  /// it owns the vertex of smallest global id
  template <class Range>
  bool counts_simplex(const Range& vertices) const {
    return owns_vertex(smallest(vertices));
  }
  /// whether this rank counts tetrahedron `t` (local octree numbering)
  bool counts_tetrahedron(Index t) const { return counts_simplex(local_->tetrahedron(t)); }
  /// the rank that owns the vertex of smallest global id of tetrahedron `t`
  int tetrahedron_owner(Index t) const {
    return vertex_owner(local_->original_vertex(smallest(local_->tetrahedron(t))));
  }
  /// the tetrahedra of this rank counted by another rank
  std::size_t number_of_ghost_tetrahedra() const { return ghost_tetrahedra_; }
  /// @}

  /// \name Ghost values
  /// @{
  /// Sets the values of `values` (one per local vertex, by part index) at the ghost vertices to
  /// the values their owners have (collective).
  template <class T>
  void update_ghosts(std::vector<T>& values) const {
    std::vector<std::vector<T>> send(size_);
    for (int r = 0; r < size_; ++r) {
      send[r].reserve(halo_send_[r].size());
      for (Index i : halo_send_[r]) send[r].push_back(values[i]);
    }
    bytes_ += count_bytes(send);
    const std::vector<T> received = internal::all_to_all(comm_, send);
    std::copy(received.begin(), received.end(), values.begin() + std::ptrdiff_t(owned_));
  }
  /// @}

  /// \name Cost of the distribution (this rank)
  /// @{
  double partition_seconds() const { return partition_seconds_; }
  double build_seconds() const { return build_seconds_; }
  /// bytes this rank has sent so far (construction and ghost updates)
  std::size_t bytes_sent() const { return bytes_; }
  /// @}

private:
  template <class T>
  static std::size_t count_bytes(const std::vector<std::vector<T>>& send) {
    std::size_t n = 0;
    for (const auto& s : send) n += s.size() * sizeof(T);
    return n;
  }
  template <class T>
  std::vector<T> exchange(std::vector<std::vector<T>>& send, std::vector<std::size_t>* counts = nullptr) {
    bytes_ += count_bytes(send);
    return internal::all_to_all(comm_, send, counts);
  }

  // The rank whose input block holds global vertex id g.
  int block_of(Global_id g) const {
    return int(std::upper_bound(block_start_.begin(), block_start_.end(), g) - block_start_.begin()) - 1;
  }

  // Calls f(tetrahedra, labels, first) for each block of this rank's part (first: the position of
  // the block's first tetrahedron in the part), in order.  Collective: every rank runs the same
  // number of rounds (a rank with fewer blocks gets empty ones), and a failure to read a block on
  // any rank is raised on every rank before `f` runs.
  template <class F>
  void for_each_block(Distributed_mesh_part& part, F f) {
    constexpr std::size_t block = std::size_t(1) << 18; // the transient buffers of a round: ~25 MB
    const bool deferred = static_cast<bool>(part.read_tetrahedra);
    const std::size_t mine =
        deferred ? part.tetrahedron_blocks : (part.tetrahedra.size() + block - 1) / block;
    std::uint64_t local = mine, rounds = 0;
    MPI_Allreduce(&local, &rounds, 1, MPI_UINT64_T, MPI_MAX, comm_);
    std::vector<std::array<Global_id, 4>> tets;
    std::vector<int> labels;
    std::size_t first = 0;
    for (std::size_t k = 0; k < rounds; ++k) {
      tets.clear();
      labels.clear();
      std::string error;
      if (k < mine) {
        if (deferred) {
          try {
            part.read_tetrahedra(k, tets, labels);
            if (part.deferred_labels && labels.size() != tets.size())
              error = "block " + std::to_string(k) + ": " + std::to_string(labels.size()) + " labels for " +
                      std::to_string(tets.size()) + " tetrahedra";
          } catch (const std::exception& e) {
            error = e.what();
          }
        } else {
          const std::size_t b = k * block, e = (std::min)(part.tetrahedra.size(), b + block);
          tets.assign(part.tetrahedra.begin() + std::ptrdiff_t(b),
                      part.tetrahedra.begin() + std::ptrdiff_t(e));
          if (!part.tetrahedron_labels.empty())
            labels.assign(part.tetrahedron_labels.begin() + std::ptrdiff_t(b),
                          part.tetrahedron_labels.begin() + std::ptrdiff_t(e));
        }
      }
      internal::agree_on_errors(comm_, error);
      f(tets, labels, first);
      first += tets.size();
    }
  }

  void partition(Distributed_mesh_part& part) {
    using namespace internal;
    const std::size_t nv = part.number_of_vertices();
    const bool deferred = static_cast<bool>(part.read_tetrahedra);
    // The input blocks and the global sizes.
    std::string error;
    if (part.coordinates.size() % 3 != 0) error = "the coordinates are not triples";
    for (const auto& a : part.point_arrays)
      if (error.empty() && a.size() != nv) error = "a point array does not have one value per vertex";
    if (error.empty() && part.point_arrays.size() != part.point_array_names.size())
      error = "the point arrays and their names differ in number";
    if (error.empty() && !part.tetrahedron_labels.empty() &&
        part.tetrahedron_labels.size() != part.tetrahedra.size())
      error = "the labels are not one per tetrahedron";
    const std::vector<Global_id> firsts = all_gather<Global_id>(comm_, part.first_vertex);
    const std::vector<Global_id> counts = all_gather<Global_id>(comm_, Global_id(nv));
    block_start_.assign(firsts.begin(), firsts.end());
    global_vertices_ = 0;
    for (int r = 0; r < size_; ++r) {
      if (error.empty() && firsts[r] != global_vertices_)
        error = "the vertex blocks of the ranks do not follow each other (rank " + std::to_string(r) +
                " starts at " + std::to_string(firsts[r]) + ", expected " + std::to_string(global_vertices_) +
                ")";
      global_vertices_ += counts[r];
    }
    block_start_.push_back(global_vertices_);
    agree_on_errors(comm_, error);
    array_names_ = part.point_array_names;
    label_name_ = part.label_name;
    // labels if any rank has them; floats only if every rank says so (one reduction: the maximum
    // of "has labels" and "not floats")
    int flags[2] = {(deferred ? part.deferred_labels : !part.tetrahedron_labels.empty()) ? 1 : 0,
                    part.float32_points ? 0 : 1},
        all_flags[2] = {0, 0};
    MPI_Allreduce(flags, all_flags, 2, MPI_INT, MPI_MAX, comm_);
    has_labels_ = all_flags[0] != 0;
    float32_points_ = all_flags[1] == 0;

    // The bounding box of the whole mesh.
    double lo[3], hi[3];
    {
      double box[6];
      for (double& b : box) b = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < nv; ++i)
        for (int a = 0; a < 3; ++a) {
          box[a] = (std::min)(box[a], part.coordinates[3 * i + a]);
          box[3 + a] = (std::min)(box[3 + a], -part.coordinates[3 * i + a]);
        }
      double global_box[6];
      MPI_Allreduce(box, global_box, 6, MPI_DOUBLE, MPI_MIN, comm_);
      for (int a = 0; a < 3; ++a) {
        lo[a] = global_box[a];
        hi[a] = -global_box[3 + a];
      }
    }
    double extent = 0;
    for (int a = 0; a < 3; ++a)
      if (hi[a] > lo[a]) extent = (std::max)(extent, hi[a] - lo[a]);
    const double inverse_extent = extent > 0 ? 1. / extent : 0.;

    // Pass 1 over the tetrahedra: check the vertex ids, and count the star sizes of the block's
    // vertices (each corner to the rank whose input block has it).
    std::vector<std::uint32_t> star(nv, 0);
    std::uint64_t part_tetrahedra = 0;
    Exchanger<Global_id> corners(size_); // the buffers of the rounds, kept from round to round
    for_each_block(part, [&](const std::vector<std::array<Global_id, 4>>& tets, const std::vector<int>&,
                             std::size_t first) {
      std::string bad;
      for (std::size_t t = 0; t < tets.size() && bad.empty(); ++t)
        for (Global_id g : tets[t])
          if (g >= global_vertices_) {
            bad = "tetrahedron " + std::to_string(first + t) + " of rank " + std::to_string(rank_) +
                  "'s part has vertex " + std::to_string(g) + ", but the mesh has " +
                  std::to_string(global_vertices_) + " vertices";
            break;
          }
      agree_on_errors(comm_, bad);
      for (const auto& c : tets)
        for (Global_id g : c) corners.to(block_of(g)).push_back(g);
      for (Global_id g : corners.exchange(comm_, nullptr, &bytes_)) ++star[g - part.first_vertex];
      part_tetrahedra += tets.size();
    });
    global_tetrahedra_ = sum_in_rank_order<Global_id>(comm_, part_tetrahedra);
    short_tet_gids_ = global_tetrahedra_ <= (std::numeric_limits<std::uint32_t>::max)();
    Global_id first_tetrahedron = 0;
    MPI_Exscan(&part_tetrahedra, &first_tetrahedron, 1, MPI_UINT64_T, MPI_SUM, comm_);
    if (rank_ == 0) first_tetrahedron = 0;

    // Parallel sample sort by (Morton key, id), weighted by 1 + star size.
    std::vector<Morton_record> records(nv);
    for (std::size_t i = 0; i < nv; ++i)
      records[i] = {morton_key(&part.coordinates[3 * i], lo, inverse_extent), part.first_vertex + i};
    std::vector<std::size_t> order(nv);
    for (std::size_t i = 0; i < nv; ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return records[a] < records[b]; });
    std::vector<Morton_record> splitters;
    {
      double local_weight = 0;
      for (std::size_t i = 0; i < nv; ++i) local_weight += 1. + double(star[i]);
      const std::size_t samples = (std::min)(nv, std::size_t(64) * std::size_t(size_));
      std::vector<Weighted_sample> mine;
      double w = 0, next = samples ? local_weight / double(samples) / 2 : 0;
      for (std::size_t k = 0; k < nv && mine.size() < samples; ++k) {
        const std::size_t i = order[k];
        w += 1. + double(star[i]);
        if (w >= next) {
          mine.push_back({records[i], local_weight / double(samples)});
          next += local_weight / double(samples);
        }
      }
      std::vector<Weighted_sample> all = all_gather_vectors(comm_, mine);
      std::sort(all.begin(), all.end(),
                [](const Weighted_sample& a, const Weighted_sample& b) { return a.record < b.record; });
      double total = 0;
      for (const auto& s : all) total += s.weight;
      // A splitter falls on the sample where the cumulative weight passes k/p of the total; it is
      // then moved down to the start of the coarsest octree cell (Morton prefix) that begins after
      // the previous sample, so that each rank gets whole subtrees, at the cost of at most one
      // sample's weight.
      double cumulative = 0;
      int k = 1;
      for (std::size_t j = 0; j < all.size(); ++j) {
        cumulative += all[j].weight;
        while (k < size_ && cumulative >= total * double(k) / double(size_)) {
          const std::uint64_t key = all[j].record.key, previous = j ? all[j - 1].record.key : 0;
          std::uint64_t snapped = key;
          for (int level = 21; level > 0; --level) {
            const std::uint64_t cell = key & ~((std::uint64_t(1) << (3 * level)) - 1);
            if (cell > previous || (j == 0 && cell == 0)) {
              snapped = cell;
              break;
            }
          }
          splitters.push_back(snapped == key ? all[j].record : Morton_record{snapped, 0});
          ++k;
        }
      }
      while (int(splitters.size()) < size_ - 1)
        splitters.push_back(
            {(std::numeric_limits<std::uint64_t>::max)(), (std::numeric_limits<std::uint64_t>::max)()});
    }
    std::vector<std::uint32_t>().swap(star);
    // Send each vertex to its range: the record, then x, y, z and the arrays.
    const std::size_t na = part.point_arrays.size(), values_per_vertex = 3 + na;
    std::vector<Morton_record> mine;
    std::vector<double> values;
    {
      std::vector<std::vector<Morton_record>> send(size_);
      std::vector<std::vector<double>> send_values(size_);
      for (std::size_t k = 0; k < nv; ++k) {
        const std::size_t i = order[k];
        const int r =
            int(std::upper_bound(splitters.begin(), splitters.end(), records[i]) - splitters.begin());
        send[r].push_back(records[i]);
        for (int a = 0; a < 3; ++a) send_values[r].push_back(part.coordinates[3 * i + a]);
        for (std::size_t a = 0; a < na; ++a) send_values[r].push_back(part.point_arrays[a][i]);
      }
      std::vector<Morton_record>().swap(records);
      std::vector<std::size_t>().swap(order);
      std::vector<double>().swap(part.coordinates);
      std::vector<std::vector<double>>().swap(part.point_arrays);
      mine = exchange(send);
      values = exchange(send_values);
    }
    // Each source sent its records sorted: sort the union (a merge in effect).
    owned_ = mine.size();
    {
      std::vector<std::size_t> o(owned_);
      for (std::size_t i = 0; i < owned_; ++i) o[i] = i;
      std::sort(o.begin(), o.end(), [&](std::size_t a, std::size_t b) { return mine[a] < mine[b]; });
      gids_.resize(owned_);
      coordinates_.resize(3 * owned_);
      arrays_.assign(na, std::vector<double>(owned_));
      for (std::size_t j = 0; j < owned_; ++j) {
        const std::size_t i = o[j];
        gids_[j] = mine[i].id;
        for (int a = 0; a < 3; ++a) coordinates_[3 * j + a] = values[values_per_vertex * i + a];
        for (std::size_t a = 0; a < na; ++a) arrays_[a][j] = values[values_per_vertex * i + 3 + a];
      }
    }
    std::vector<Morton_record>().swap(mine);
    std::vector<double>().swap(values);

    // The directory: each input block learns the owner of each of its vertices and its index there.
    std::vector<Owner_index> owner_of(nv, Owner_index{-1, 0});
    {
      std::vector<std::vector<Id_index>> send(size_);
      for (std::size_t i = 0; i < owned_; ++i) send[block_of(gids_[i])].push_back({gids_[i], Index(i), 0});
      std::vector<std::size_t> from;
      const std::vector<Id_index> received = exchange(send, &from);
      std::size_t k = 0;
      for (int r = 0; r < size_; ++r)
        for (std::size_t j = 0; j < from[r]; ++j, ++k)
          owner_of[received[k].id - part.first_vertex] = {r, received[k].index};
    }
    std::unordered_map<Global_id, Index> ghost_index; // global id -> ghost number
    // the buffers of the rounds, kept from round to round
    Exchanger<Owner_index> owners(size_);
    Exchanger<Tetrahedron_record> routed(size_);
    std::vector<Owner_index> corner_owner;
    std::vector<std::size_t> from, next;
    std::vector<Id_owner> ghosts;

    // Pass 2 over the tetrahedra, block by block: ask the owners of the corners from the input
    // blocks, send each tetrahedron to the owners of its vertices (once per owner); each rank stores
    // what it receives at once in local indices (owned vertices, then ghosts as they come).
    for_each_block(part, [&](const std::vector<std::array<Global_id, 4>>& tets,
                             const std::vector<int>& labels, std::size_t first) {
      corner_owner.resize(4 * tets.size());
      {
        for (const auto& c : tets)
          for (Global_id g : c) corners.to(block_of(g)).push_back(g);
        const std::vector<Global_id>& asked = corners.exchange(comm_, &from, &bytes_);
        std::size_t k = 0;
        for (int r = 0; r < size_; ++r)
          for (std::size_t j = 0; j < from[r]; ++j, ++k)
            owners.to(r).push_back(owner_of[asked[k] - part.first_vertex]);
        const std::vector<Owner_index>& answers = owners.exchange(comm_, nullptr, &bytes_);
        // the answers come back grouped by input block, in the order asked
        next.assign(size_ + 1, 0);
        for (const auto& c : tets)
          for (Global_id g : c) ++next[block_of(g) + 1];
        for (int r = 0; r < size_; ++r) next[r + 1] += next[r];
        for (std::size_t t = 0; t < tets.size(); ++t)
          for (int i = 0; i < 4; ++i) corner_owner[4 * t + i] = answers[next[block_of(tets[t][i])]++];
      }
      for (std::size_t t = 0; t < tets.size(); ++t) {
        Tetrahedron_record rec;
        rec.vertices = tets[t];
        rec.id = first_tetrahedron + first + t;
        rec.label = labels.empty() ? 0 : labels[t];
        rec.unused = 0;
        for (int i = 0; i < 4; ++i) rec.corners[i] = corner_owner[4 * t + i];
        for (int i = 0; i < 4; ++i) {
          bool first_time = true;
          for (int j = 0; j < i; ++j) first_time = first_time && rec.corners[j].owner != rec.corners[i].owner;
          if (first_time) routed.to(rec.corners[i].owner).push_back(rec);
        }
      }
      const std::vector<Tetrahedron_record>& received = routed.exchange(comm_, nullptr, &bytes_);
      for (const Tetrahedron_record& rec : received) {
        std::array<Index, 4> c;
        Global_id smallest = rec.vertices[0];
        int owner = rec.corners[0].owner;
        for (int i = 0; i < 4; ++i) {
          const Global_id g = rec.vertices[i];
          if (rec.corners[i].owner == rank_) {
            c[i] = rec.corners[i].index;
          } else {
            const auto it = ghost_index.emplace(g, Index(ghosts.size())).first;
            if (it->second == ghosts.size())
              ghosts.push_back({g, rec.corners[i].owner, rec.corners[i].index});
            c[i] = Index(owned_) + it->second; // a ghost number for now
          }
          if (g < smallest) {
            smallest = g;
            owner = rec.corners[i].owner;
          }
        }
        ghost_tetrahedra_ += owner != rank_;
        received_tetrahedra_.push_back(c);
        if (short_tet_gids_)
          tet_gids32_.push_back(std::uint32_t(rec.id));
        else
          tet_gids_.push_back(rec.id);
        if (has_labels_) received_labels_.push_back(rec.label);
      }
    });
    std::vector<Owner_index>().swap(owner_of);
    std::vector<std::array<Global_id, 4>>().swap(part.tetrahedra);
    std::vector<int>().swap(part.tetrahedron_labels);
    part.read_tetrahedra = nullptr;
    std::unordered_map<Global_id, Index>().swap(ghost_index);

    // The ghosts grouped by owner and sorted by id (the order of the ghost updates); their
    // coordinates and point values asked from their owners.
    std::vector<Index> ghost_order(ghosts.size()), ghost_rank(ghosts.size());
    for (std::size_t j = 0; j < ghosts.size(); ++j) ghost_order[j] = Index(j);
    std::sort(ghost_order.begin(), ghost_order.end(), [&](Index a, Index b) {
      return ghosts[a].owner != ghosts[b].owner ? ghosts[a].owner < ghosts[b].owner
                                                : ghosts[a].id < ghosts[b].id;
    });
    for (std::size_t j = 0; j < ghosts.size(); ++j) ghost_rank[ghost_order[j]] = Index(j);
    received_tetrahedra_.for_each([&](std::array<Index, 4>& c) {
      for (Index& v : c)
        if (v >= owned_) v = Index(owned_) + ghost_rank[v - owned_];
    });
    std::vector<Index>().swap(ghost_rank);
    {
      // each ghost asked by its index on its owner
      std::vector<std::vector<Index>> ask(size_);
      for (Index j : ghost_order) ask[ghosts[j].owner].push_back(ghosts[j].index);
      std::vector<std::size_t> from;
      const std::vector<Index> asked = exchange(ask, &from);
      halo_send_.assign(size_, {});
      std::vector<std::vector<double>> answer(size_);
      std::size_t k = 0;
      for (int r = 0; r < size_; ++r)
        for (std::size_t j = 0; j < from[r]; ++j, ++k) {
          const Index i = asked[k];
          halo_send_[r].push_back(i);
          for (int a = 0; a < 3; ++a) answer[r].push_back(coordinates_[3 * i + a]);
          for (std::size_t a = 0; a < na; ++a) answer[r].push_back(arrays_[a][i]);
        }
      const std::vector<double> got = exchange(answer);
      ghost_owner_.resize(ghosts.size());
      for (std::size_t j = 0; j < ghosts.size(); ++j) {
        const Id_owner& g = ghosts[ghost_order[j]];
        gids_.push_back(g.id);
        ghost_owner_[j] = g.owner;
        for (int a = 0; a < 3; ++a) coordinates_.push_back(got[values_per_vertex * j + a]);
        for (std::size_t a = 0; a < na; ++a) arrays_[a].push_back(got[values_per_vertex * j + 3 + a]);
      }
    }
  }

  template <class NP>
  void build_local(const NP& np) {
    using Mesh = Indexed_tetrahedral_mesh<Point_3, Index>;
    std::string error;
    try {
      if (gids_.size() > std::size_t((std::numeric_limits<Index>::max)()) ||
          received_tetrahedra_.size() > std::size_t((std::numeric_limits<Index>::max)()))
        throw std::length_error("more than 2^32 vertices or tetrahedra on one rank: use more ranks");
      Mesh mesh;
      const std::size_t n = gids_.size();
      mesh.points.reserve(n);
      for (std::size_t i = 0; i < n; ++i)
        mesh.points.emplace_back(coordinates_[3 * i], coordinates_[3 * i + 1], coordinates_[3 * i + 2]);
      std::vector<double>().swap(coordinates_);
      mesh.float32_points = float32_points_;
      mesh.tetrahedra = received_tetrahedra_.release();
      mesh.tetrahedron_labels = received_labels_.release();
      if (!arrays_.empty()) mesh.point_data.push_back({array_names_[0], arrays_[0]});
      const auto local_np =
          parameters::bucket_size(
              parameters::choose_parameter(parameters::get_parameter(np, internal_np::bucket_size),
                                           Octree::default_bucket_size))
              .maximum_depth(parameters::choose_parameter(
                  parameters::get_parameter(np, internal_np::maximum_depth), Octree::default_max_depth))
              .compact_tetrahedra(parameters::choose_parameter(
                  parameters::get_parameter(np, internal_np::compact_tetrahedra), false))
              .coordinate_precision(parameters::choose_parameter(
                  parameters::get_parameter(np, internal_np::coordinate_precision),
                  Coordinate_precision::as_input))
              .concurrency_tag(
                  parameters::choose_parameter(parameters::get_parameter(np, internal_np::concurrency_tag),
                                               CGAL::Parallel_if_available_tag()))
              .vertex_permutation(true)
              .tetrahedron_permutation(true);
      local_ = std::make_unique<Octree>(std::move(mesh), local_np);
    } catch (const std::exception& e) {
      error = e.what();
    }
    internal::agree_on_errors(comm_, error);
  }

  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
  Global_id global_vertices_ = 0, global_tetrahedra_ = 0;
  std::vector<Global_id> block_start_;
  std::vector<std::string> array_names_;
  std::string label_name_ = "label";
  bool has_labels_ = false;
  bool float32_points_ = false; // every part's `float32_points`
  std::size_t owned_ = 0;
  std::vector<Global_id> gids_;
  std::vector<std::int32_t> ghost_owner_;
  std::vector<double> coordinates_;
  std::vector<std::vector<double>> arrays_;
  // the tetrahedra received, one block per round, until the local octree takes them
  internal::Chunked_vector<std::array<Index, 4>> received_tetrahedra_;
  internal::Chunked_vector<int> received_labels_;
  // the global ids of the rank's tetrahedra (by part index), in 32 bits when they fit
  bool short_tet_gids_ = true;
  internal::Chunked_vector<std::uint32_t> tet_gids32_;
  internal::Chunked_vector<Global_id> tet_gids_;
  std::size_t ghost_tetrahedra_ = 0;
  std::vector<std::vector<Index>> halo_send_;
  std::unique_ptr<Octree> local_;
  double partition_seconds_ = 0, build_seconds_ = 0;
  mutable std::size_t bytes_ = 0;
};

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_DISTRIBUTED_OCTREE_3_H
