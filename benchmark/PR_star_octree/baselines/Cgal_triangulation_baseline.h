// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef PRSTAR_BASELINES_CGAL_TRIANGULATION_BASELINE_H
#define PRSTAR_BASELINES_CGAL_TRIANGULATION_BASELINE_H

// Baseline for the benchmarks: the local topological relations of a tetrahedral mesh answered by
// a plain CGAL `Triangulation_3<Epick>` whose cells are exactly the input tetrahedra (not a
// Delaunay triangulation of the points).  The triangulation data structure is built directly
// from the index arrays:
//
//   1. one TDS vertex per input vertex used by a tetrahedron, one TDS cell per tetrahedron,
//      positively oriented with the exact `CGAL::orientation` (vertices 0 and 1 swapped when the
//      input tetrahedron is negative; a flat tetrahedron is an error);
//   2. the cells are paired across their shared faces (faces bucketed by their smallest vertex);
//      a face shared by three or more tetrahedra, or two tetrahedra on the same side of their
//      common face, is an error;
//   3. every boundary face (one tetrahedron) is coned to the infinite vertex, and the infinite
//      cells are glued to each other across the boundary edges; an edge on more than two
//      boundary faces, or a boundary vertex whose boundary faces do not form a single fan
//      (a pinched vertex), is an error.
//
// Each vertex and cell carries its input index as `info()`: queries take and return input
// indices, so their results compare directly to other structures.  The info fields are part of
// the measured memory.
//
// After the build, the `cell()` of a vertex on the boundary of the mesh is an infinite cell and
// that of an interior vertex a finite one: `is_boundary_vertex()` reads that in O(1).
//
// Note on validity: CGAL's global `Triangulation_data_structure_3::is_valid()` checks the Euler
// relation of a combinatorial 3-sphere, which holds when the boundary of the mesh is one sphere.
// For a domain with a torus boundary or several boundary components the coned complex is still
// a consistent pseudo-manifold (every cell and every finite vertex is valid, the local queries
// are exact) but its Euler characteristic differs, so that global check fails by design.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace prstar_baselines {

class Cgal_triangulation_baseline {
public:
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point_3 = Kernel::Point_3;
  using Index = std::uint32_t;
  using Tetrahedron = std::array<Index, 4>;

  using Vertex_base = CGAL::Triangulation_vertex_base_with_info_3<Index, Kernel>;
  using Cell_base = CGAL::Triangulation_cell_base_with_info_3<Index, Kernel>;
  using Tds = CGAL::Triangulation_data_structure_3<Vertex_base, Cell_base>;
  using Triangulation = CGAL::Triangulation_3<Kernel, Tds>;
  using Vertex = Tds::Vertex;
  using Cell = Tds::Cell;
  using Vertex_handle = Triangulation::Vertex_handle;
  using Cell_handle = Triangulation::Cell_handle;

  /// the `info()` of the infinite vertex and of the infinite cells; the neighbor returned by
  /// `tetrahedron_neighbors()` across a boundary face
  static constexpr Index no_index = std::numeric_limits<Index>::max();

  /// Heap bytes of the structure, by part.
  struct Memory {
    std::size_t vertices = 0;   ///< vertex container: blocks of the Compact_container
    std::size_t cells = 0;      ///< cell container (finite and infinite cells)
    std::size_t index_maps = 0; ///< input index -> handle maps and the per-tetrahedron swap bits
    std::size_t object = 0;     ///< sizeof(*this)
    std::size_t total() const { return vertices + cells + index_maps + object; }
  };

  /// Builds the triangulation whose finite cells are `tets` (0-based indices into `points`).
  /// Throws `std::runtime_error` on invalid or non-manifold input (see the file comment).
  Cgal_triangulation_baseline(const std::vector<Point_3>& points, const std::vector<Tetrahedron>& tets) {
    build(points, tets);
  }

  Cgal_triangulation_baseline(const Cgal_triangulation_baseline&) = delete;
  Cgal_triangulation_baseline& operator=(const Cgal_triangulation_baseline&) = delete;

  const Triangulation& triangulation() const { return tr_; }

  /// the number of input vertices (used or not by a tetrahedron)
  std::size_t number_of_input_vertices() const { return vertex_handles_.size(); }
  /// the number of finite vertices of the triangulation (input vertices used by a tetrahedron)
  std::size_t number_of_vertices() const { return tr_.number_of_vertices(); }
  std::size_t number_of_finite_cells() const { return cell_handles_.size(); }
  std::size_t number_of_infinite_cells() const { return tr_.tds().number_of_cells() - cell_handles_.size(); }

  /// the TDS vertex of input vertex `v`, or a null handle when no tetrahedron uses `v`
  Vertex_handle vertex_handle(Index v) const { return vertex_handles_[v]; }
  /// the TDS cell of input tetrahedron `t`
  Cell_handle cell_handle(Index t) const { return cell_handles_[t]; }
  /// whether the cell of `t` has its vertices 0 and 1 swapped with respect to the input
  bool is_swapped(Index t) const { return swapped_[t]; }

  /// VT: writes the input indices of the tetrahedra incident in vertex `v` to `out` (in the
  /// order of `Triangulation_3::finite_incident_cells()`); nothing for an unused vertex.
  template <class OutputIterator>
  OutputIterator vertex_tetrahedra(Index v, OutputIterator out) const {
    const Vertex_handle vh = vertex_handles_[v];
    if (vh == Vertex_handle()) return out;
    tr_.finite_incident_cells(vh, Info_writer<OutputIterator>{&out});
    return out;
  }

  /// VT for all vertices in input order: calls `f(v, const std::vector<Index>& tetrahedra)` with a
  /// reused buffer (empty for a vertex used by no tetrahedron).
  template <class F>
  void for_each_vertex_star(F f) const {
    std::vector<Index> star;
    star.reserve(128);
    for (Index v = 0; v < vertex_handles_.size(); ++v) {
      star.clear();
      const Vertex_handle vh = vertex_handles_[v];
      if (vh != Vertex_handle()) {
        auto out = std::back_inserter(star);
        tr_.finite_incident_cells(vh, Info_writer<decltype(out)>{&out});
      }
      f(v, static_cast<const std::vector<Index>&>(star));
    }
  }

  /// TT: the tetrahedra adjacent to `t` across the face opposite its `k`-th vertex in the input
  /// order, as input indices; `no_index` across a boundary face.
  std::array<Index, 4> tetrahedron_neighbors(Index t) const {
    const Cell_handle c = cell_handles_[t];
    const bool sw = swapped_[t];
    std::array<Index, 4> result;
    for (int k = 0; k < 4; ++k) result[k] = c->neighbor(local_index(sw, k))->info();
    return result;
  }

  /// The star of the edge `(a, b)` (input vertex indices): its tetrahedra in cyclic order by the
  /// right-hand rule around `a -> b`, walked with the `Cell_circulator` of `Triangulation_3`.
  /// An interior edge gives a closed cycle, started at its smallest tetrahedron; a boundary edge
  /// gives the fan from one boundary face to the other (the circulator's infinite cells are
  /// dropped).  Empty when `(a, b)` is not an edge of the mesh.  `on_boundary`, when given, is
  /// set to whether the edge is on the boundary.  Finding the edge (`Tds::is_edge()`) costs the
  /// star of `a`; `for_each_edge_star()` is the bulk path.
  std::vector<Index> edge_star(Index a, Index b, bool* on_boundary = nullptr) const {
    std::vector<Index> star;
    const Vertex_handle va = vertex_handles_[a], vb = vertex_handles_[b];
    Cell_handle c;
    int i = 0, j = 0;
    if (va == Vertex_handle() || vb == Vertex_handle() || a == b || !tr_.tds().is_edge(va, vb, c, i, j)) {
      if (on_boundary) *on_boundary = false;
      return star;
    }
    const bool open = circulate(c, i, j, star);
    if (on_boundary) *on_boundary = open;
    return star;
  }

  /// The stars of all the edges of the mesh, each once (`Triangulation_3::finite_edges()`):
  /// calls `f(a, b, const std::vector<Index>& star, bool on_boundary)` with `a < b` and the star
  /// ordered as `edge_star(a, b)`, with a reused buffer.
  template <class F>
  void for_each_edge_star(F f) const {
    std::vector<Index> star;
    star.reserve(32);
    for (auto e = tr_.finite_edges_begin(), end = tr_.finite_edges_end(); e != end; ++e) {
      const Cell_handle c = e->first;
      int i = e->second, j = e->third;
      if (c->vertex(i)->info() > c->vertex(j)->info()) std::swap(i, j);
      star.clear();
      const bool open = circulate(c, i, j, star);
      f(c->vertex(i)->info(), c->vertex(j)->info(), static_cast<const std::vector<Index>&>(star), open);
    }
  }

  /// whether vertex `v` is on the boundary of the mesh (adjacent to the infinite vertex); O(1)
  bool is_boundary_vertex(Index v) const {
    const Vertex_handle vh = vertex_handles_[v];
    return vh != Vertex_handle() && tr_.is_infinite(vh->cell());
  }

  /// Heap bytes: the vertex and cell Compact_containers (capacity plus the two sentinel
  /// elements of each block and the block table, following the container's growth policy), the
  /// index maps and the swap bits.
  Memory memory() const {
    Memory m;
    m.vertices = compact_container_bytes(tr_.tds().vertices().capacity(), sizeof(Vertex));
    m.cells = compact_container_bytes(tr_.tds().cells().capacity(), sizeof(Cell));
    m.index_maps = vertex_handles_.capacity() * sizeof(Vertex_handle) +
                   cell_handles_.capacity() * sizeof(Cell_handle) + (swapped_.capacity() + 7) / 8;
    m.object = sizeof(*this);
    return m;
  }
  std::size_t memory_bytes() const { return memory().total(); }

private:
  // An output iterator writing the `info()` of cell handles to another output iterator.
  template <class Out>
  struct Info_writer {
    using iterator_category = std::output_iterator_tag;
    using value_type = void;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = void;
    Out* out;
    Info_writer& operator*() { return *this; }
    Info_writer& operator++() { return *this; }
    Info_writer operator++(int) { return *this; }
    Info_writer& operator=(Cell_handle c) {
      *(*out)++ = c->info();
      return *this;
    }
  };

  // A face of a finite cell, recorded in the bucket of its smallest vertex.
  struct Face_record {
    Index b, c; // the two other vertices, b < c
    Index code; // 4 * tetrahedron + local index of the opposite vertex
  };
  // A boundary edge of an infinite cell.
  struct Edge_record {
    Index a, b;     // a < b
    Index cell;     // position in the list of infinite cells
    unsigned local; // local index of the facet (inf, a, b) in that cell
  };

  static int local_index(bool swapped, int k) { return (swapped && k < 2) ? 1 - k : k; }

  static std::size_t compact_container_bytes(std::size_t capacity, std::size_t element) {
    // CGAL::Compact_container grows by blocks of 14, 30, 46, ... elements, each allocated with
    // two extra sentinel elements, and keeps a (pointer, size) pair per block.
    std::size_t blocks = 0, total = 0, block_size = CGAL_INIT_COMPACT_CONTAINER_BLOCK_SIZE;
    while (total < capacity) {
      total += block_size;
      block_size += CGAL_INCREMENT_COMPACT_CONTAINER_BLOCK_SIZE;
      ++blocks;
    }
    return (capacity + 2 * blocks) * element + blocks * sizeof(std::pair<void*, std::size_t>);
  }

  // Parity of the ordering of a cell's vertex indices once the vertex at `local` is replaced by
  // a symbol larger than all: two cells sharing that face are consistently oriented (on both
  // sides of it) iff their parities differ.
  static bool face_parity(Tetrahedron w, int local) {
    w[local] = no_index;
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) inversions += w[i] > w[j];
    return inversions & 1;
  }

  Tetrahedron local_vertices(const std::vector<Tetrahedron>& tets, Index t) const {
    Tetrahedron w = tets[t];
    if (swapped_[t]) std::swap(w[0], w[1]);
    return w;
  }

  // Walks around the edge (c->vertex(i), c->vertex(j)) and writes its finite cells to `star`
  // (see edge_star); returns whether the edge is on the boundary.
  bool circulate(Cell_handle c, int i, int j, std::vector<Index>& star) const {
    const std::size_t begin = star.size();
    // Cell_circulator::operator++ turns by the right-hand rule around vertex(i) -> vertex(j)
    // (the self-test checks it geometrically).
    Triangulation::Cell_circulator cc = tr_.incident_cells(c, i, j), done = cc;
    do {
      star.push_back(cc->info());
      ++cc;
    } while (cc != done);
    const auto first = star.begin() + static_cast<std::ptrdiff_t>(begin);
    const std::size_t n = star.size() - begin;
    std::size_t start = n;
    for (std::size_t p = 0; p < n; ++p)
      if (first[p] == no_index && first[(p + 1) % n] != no_index) {
        start = (p + 1) % n;
        break;
      }
    if (start == n) { // closed cycle
      std::rotate(first, std::min_element(first, star.end()), star.end());
      return false;
    }
    std::rotate(first, first + static_cast<std::ptrdiff_t>(start), star.end());
    star.erase(std::remove(star.begin() + static_cast<std::ptrdiff_t>(begin), star.end(), no_index),
               star.end());
    return true;
  }

  [[noreturn]] static void fail(const std::string& message) {
    throw std::runtime_error("Cgal_triangulation_baseline: " + message);
  }

  void build(const std::vector<Point_3>& points, const std::vector<Tetrahedron>& tets);
  void create_vertices_and_cells(const std::vector<Point_3>& points, const std::vector<Tetrahedron>& tets);
  std::vector<Index> pair_finite_cells(const std::vector<Tetrahedron>& tets);
  void cone_boundary(const std::vector<Index>& boundary_faces);

  Triangulation tr_;
  std::vector<Vertex_handle> vertex_handles_; // per input vertex
  std::vector<Cell_handle> cell_handles_;     // per input tetrahedron
  std::vector<bool> swapped_;                 // per input tetrahedron: vertices 0 and 1 swapped
};

inline void Cgal_triangulation_baseline::build(const std::vector<Point_3>& points,
                                               const std::vector<Tetrahedron>& tets) {
  if (tets.empty()) fail("no tetrahedra");
  // Face codes are 4 * tetrahedron + local index in 32 bits.
  if (tets.size() >= (std::size_t(1) << 30)) fail("too many tetrahedra (at most 2^30 - 1)");
  if (points.size() >= no_index) fail("too many points");
  create_vertices_and_cells(points, tets);
  const std::vector<Index> boundary_faces = pair_finite_cells(tets);
  if (boundary_faces.empty()) fail("the mesh has no boundary face");
  cone_boundary(boundary_faces);
}

inline void Cgal_triangulation_baseline::create_vertices_and_cells(const std::vector<Point_3>& points,
                                                                   const std::vector<Tetrahedron>& tets) {
  const std::size_t nv = points.size(), nt = tets.size();
  std::vector<bool> used(nv, false);
  for (std::size_t t = 0; t < nt; ++t) {
    const Tetrahedron& w = tets[t];
    for (int k = 0; k < 4; ++k) {
      if (w[k] >= nv)
        fail("tetrahedron " + std::to_string(t) + " has vertex index " + std::to_string(w[k]) +
             " >= " + std::to_string(nv) + " points");
      for (int l = 0; l < k; ++l)
        if (w[k] == w[l])
          fail("tetrahedron " + std::to_string(t) + " repeats vertex " + std::to_string(w[k]));
      used[w[k]] = true;
    }
  }

  Tds& tds = tr_.tds();
  tds.clear(); // drops the infinite vertex made by the Triangulation_3 constructor
  const Vertex_handle inf = tds.create_vertex();
  inf->info() = no_index;
  tr_.set_infinite_vertex(inf);
  tds.set_dimension(3); // before set_adjacency(), whose preconditions read it

  vertex_handles_.assign(nv, Vertex_handle());
  for (std::size_t v = 0; v < nv; ++v) {
    if (!used[v]) continue;
    const Vertex_handle vh = tds.create_vertex();
    vh->set_point(points[v]);
    vh->info() = static_cast<Index>(v);
    vertex_handles_[v] = vh;
  }

  cell_handles_.resize(nt);
  swapped_.assign(nt, false);
  for (std::size_t t = 0; t < nt; ++t) {
    Tetrahedron w = tets[t];
    const CGAL::Orientation o = CGAL::orientation(points[w[0]], points[w[1]], points[w[2]], points[w[3]]);
    if (o == CGAL::COPLANAR)
      fail("tetrahedron " + std::to_string(t) + " is flat (its four points are coplanar)");
    if (o == CGAL::NEGATIVE) {
      std::swap(w[0], w[1]);
      swapped_[t] = true;
    }
    const Cell_handle c = tds.create_cell(vertex_handles_[w[0]], vertex_handles_[w[1]], vertex_handles_[w[2]],
                                          vertex_handles_[w[3]]);
    c->info() = static_cast<Index>(t);
    for (int k = 0; k < 4; ++k) vertex_handles_[w[k]]->set_cell(c);
    cell_handles_[t] = c;
  }
}

// Pairs the finite cells across their shared faces; returns the boundary faces as codes
// 4 * tetrahedron + local index.
inline std::vector<Cgal_triangulation_baseline::Index>
Cgal_triangulation_baseline::pair_finite_cells(const std::vector<Tetrahedron>& tets) {
  const std::size_t nv = vertex_handles_.size(), nt = tets.size();
  // Counting sort of the faces by their smallest vertex.
  std::vector<Index> offsets(nv + 1, 0);
  for (std::size_t t = 0; t < nt; ++t) {
    const Tetrahedron& w = tets[t];
    const Index lo = std::min(std::min(w[0], w[1]), std::min(w[2], w[3]));
    Index second = no_index;
    for (int k = 0; k < 4; ++k)
      if (w[k] != lo) second = std::min(second, w[k]);
    offsets[lo + 1] += 3;     // the three faces containing the smallest vertex
    offsets[second + 1] += 1; // the face opposite it
  }
  for (std::size_t v = 0; v < nv; ++v) offsets[v + 1] += offsets[v];
  std::vector<Face_record> faces(offsets[nv]);
  {
    std::vector<Index> fill(offsets.begin(), offsets.end() - 1);
    for (std::size_t t = 0; t < nt; ++t) {
      const Tetrahedron w = local_vertices(tets, static_cast<Index>(t));
      for (int i = 0; i < 4; ++i) {
        Index f[3];
        int n = 0;
        for (int k = 0; k < 4; ++k)
          if (k != i) f[n++] = w[k];
        if (f[0] > f[1]) std::swap(f[0], f[1]);
        if (f[1] > f[2]) std::swap(f[1], f[2]);
        if (f[0] > f[1]) std::swap(f[0], f[1]);
        faces[fill[f[0]]++] = Face_record{f[1], f[2], static_cast<Index>(4 * t + i)};
      }
    }
  }

  Tds& tds = tr_.tds();
  std::vector<Index> boundary;
  for (std::size_t v = 0; v < nv; ++v) {
    const auto first = faces.begin() + offsets[v], last = faces.begin() + offsets[v + 1];
    std::sort(first, last, [](const Face_record& x, const Face_record& y) {
      return x.b < y.b || (x.b == y.b && (x.c < y.c || (x.c == y.c && x.code < y.code)));
    });
    for (auto r = first; r != last;) {
      auto s = r + 1;
      while (s != last && s->b == r->b && s->c == r->c) ++s;
      const std::ptrdiff_t m = s - r;
      if (m == 1) {
        boundary.push_back(r->code);
      } else if (m == 2) {
        const Index t0 = r->code / 4, t1 = (r + 1)->code / 4;
        const int i0 = static_cast<int>(r->code % 4), i1 = static_cast<int>((r + 1)->code % 4);
        if (face_parity(local_vertices(tets, t0), i0) == face_parity(local_vertices(tets, t1), i1))
          fail("tetrahedra " + std::to_string(t0) + " and " + std::to_string(t1) +
               " lie on the same side of their common face (" + std::to_string(v) + ", " +
               std::to_string(r->b) + ", " + std::to_string(r->c) + "): overlapping or duplicated");
        tds.set_adjacency(cell_handles_[t0], i0, cell_handles_[t1], i1);
      } else {
        fail("non-manifold face (" + std::to_string(v) + ", " + std::to_string(r->b) + ", " +
             std::to_string(r->c) + ") shared by " + std::to_string(m) + " tetrahedra");
      }
      r = s;
    }
  }
  return boundary;
}

// Cones the boundary faces to the infinite vertex and glues the infinite cells together.
inline void Cgal_triangulation_baseline::cone_boundary(const std::vector<Index>& boundary_faces) {
  Tds& tds = tr_.tds();
  const Vertex_handle inf = tr_.infinite_vertex();
  std::vector<Cell_handle> infinite_cells;
  infinite_cells.reserve(boundary_faces.size());
  std::vector<Edge_record> edges;
  edges.reserve(3 * boundary_faces.size());
  std::vector<Index> boundary_face_count(vertex_handles_.size(), 0);

  for (const Index code : boundary_faces) {
    const Cell_handle c = cell_handles_[code / 4];
    const int i = static_cast<int>(code % 4);
    // Replace the opposite vertex by the infinite one and swap two others: the infinite cell is
    // oriented consistently with c, on the other side of their common face.
    std::array<Vertex_handle, 4> w = {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)};
    w[i] = inf;
    std::swap(w[(i + 1) & 3], w[(i + 2) & 3]);
    const Cell_handle n = tds.create_cell(w[0], w[1], w[2], w[3]);
    n->info() = no_index;
    tds.set_adjacency(c, i, n, i);
    const Index id = static_cast<Index>(infinite_cells.size());
    infinite_cells.push_back(n);
    for (int k = 0; k < 4; ++k) {
      if (k == i) continue;
      w[k]->set_cell(n); // a boundary vertex points to an infinite cell
      ++boundary_face_count[w[k]->info()];
      Index e[2];
      int m = 0;
      for (int l = 0; l < 4; ++l)
        if (l != i && l != k) e[m++] = w[l]->info();
      if (e[0] > e[1]) std::swap(e[0], e[1]);
      edges.push_back(Edge_record{e[0], e[1], id, static_cast<unsigned>(k)});
    }
  }
  inf->set_cell(infinite_cells.front());

  std::sort(edges.begin(), edges.end(), [](const Edge_record& x, const Edge_record& y) {
    return x.a < y.a || (x.a == y.a && (x.b < y.b || (x.b == y.b && x.cell < y.cell)));
  });
  for (std::size_t r = 0; r < edges.size();) {
    std::size_t s = r + 1;
    while (s < edges.size() && edges[s].a == edges[r].a && edges[s].b == edges[r].b) ++s;
    if (s - r != 2)
      fail("non-manifold boundary: edge (" + std::to_string(edges[r].a) + ", " + std::to_string(edges[r].b) +
           ") is on " + std::to_string(s - r) + " boundary faces");
    tds.set_adjacency(infinite_cells[edges[r].cell], static_cast<int>(edges[r].local),
                      infinite_cells[edges[r + 1].cell], static_cast<int>(edges[r + 1].local));
    r = s;
  }

  // Each boundary vertex must see its boundary faces as one fan: walk around the edge
  // (infinite vertex, v) through the infinite cells and count them.
  for (std::size_t v = 0; v < vertex_handles_.size(); ++v) {
    if (boundary_face_count[v] == 0) continue;
    const Vertex_handle vh = vertex_handles_[v];
    const Cell_handle c = vh->cell();
    Triangulation::Cell_circulator cc = tr_.incident_cells(c, c->index(inf), c->index(vh)), done = cc;
    Index count = 0;
    do {
      ++count;
      ++cc;
    } while (cc != done && count <= boundary_face_count[v]);
    if (count != boundary_face_count[v])
      fail("non-manifold boundary: the " + std::to_string(boundary_face_count[v]) +
           " boundary faces at vertex " + std::to_string(v) + " form several fans (pinched vertex)");
  }
}

} // namespace prstar_baselines

#endif // PRSTAR_BASELINES_CGAL_TRIANGULATION_BASELINE_H
