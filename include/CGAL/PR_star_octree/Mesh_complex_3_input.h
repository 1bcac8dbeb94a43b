// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_MESH_COMPLEX_3_INPUT_H
#define CGAL_PR_STAR_OCTREE_MESH_COMPLEX_3_INPUT_H

#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <CGAL/Mesh_3/tet_soup_to_c3t3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {

namespace internal {

// `true` when `F` can be called as `f(v)`, in which case it is used as a functor; otherwise it is
// read as a property map with `get(f, v)`.
template <class F, class Key, class = void>
struct Is_vertex_functor : std::false_type {};
template <class F, class Key>
struct Is_vertex_functor<F, Key, std::void_t<decltype(std::declval<const F&>()(std::declval<const Key&>()))>>
    : std::true_type {};

} // namespace internal

/// \ingroup PkgPRStarOctreeRef
/// \cgalModels `PRStarOctreeInputMesh`
///
/// Adapts a 3D mesh complex, such as the result of `CGAL::make_mesh_3()`
/// (`CGAL::Mesh_complex_3_in_triangulation_3`), as an indexed tetrahedral mesh.
///
/// - The tetrahedra are the cells *in the complex*, in the order of
///   `cells_in_complex_begin()`/`cells_in_complex_end()`; the other finite cells of the triangulation
///   (outside the meshed domain) are left out.  Each tetrahedron keeps the vertex order 0..3 of its
///   cell, so it has the orientation of the triangulation (positive for Mesh_3 output).
/// - The vertices are the vertices of those cells, numbered in the order in which they are first met
///   while iterating over the cells.  They are *not* the vertices of
///   `vertices_in_complex_begin()`, which are only the corners of the complex.
/// - The points are the bare points of the (weighted) triangulation points, obtained with the
///   triangulation traits' `Construct_point_3`.
///
/// The adapter computes the numbering once, at construction (linear time and memory in the number
/// of cells in the complex), and keeps handles into the complex: the complex must outlive the
/// adapter and must not be modified meanwhile.
///
/// An optional scalar field is evaluated once per vertex at construction; it is given either as a
/// functor `double(Vertex_handle)` or as a readable property map whose key type is `Vertex_handle`
/// and whose value type converts to `double`.
///
/// \tparam C3T3 a model of `MeshComplex_3InTriangulation_3`
template <class C3T3>
class Mesh_complex_3_input {
public:
  /// \name Types
  /// @{
  using Triangulation = typename C3T3::Triangulation;
  using Vertex_handle = typename Triangulation::Vertex_handle;
  using Cell_handle = typename Triangulation::Cell_handle;
  using Subdomain_index = typename C3T3::Subdomain_index;
  /// the bare (unweighted) point type of the triangulation traits
  using Point_3 = typename Triangulation::Geom_traits::Point_3;
  /// @}

  /// \name Construction
  /// @{

  /// adapts `c3t3` without a scalar field.
  explicit Mesh_complex_3_input(const C3T3& c3t3) : c3t3_(&c3t3) { build(); }

  /// adapts `c3t3` with the scalar field `field`, a functor `double(Vertex_handle)` or a readable
  /// property map with key type `Vertex_handle`, evaluated once per vertex here.
  template <class ScalarFieldOrMap>
  Mesh_complex_3_input(const C3T3& c3t3, const ScalarFieldOrMap& field) : c3t3_(&c3t3) {
    build();
    scalars_.reserve(vertices_.size());
    for (const Vertex_handle& v : vertices_) {
      if constexpr (internal::Is_vertex_functor<ScalarFieldOrMap, Vertex_handle>::value)
        scalars_.push_back(static_cast<double>(field(v)));
      else
        scalars_.push_back(static_cast<double>(get(field, v)));
    }
    has_scalars_ = true;
  }
  /// @}

  /// \name PRStarOctreeInputMesh interface
  /// @{
  std::size_t number_of_vertices() const { return vertices_.size(); }
  std::size_t number_of_tetrahedra() const { return tetrahedra_.size(); }

  /// the bare point of vertex `i`
  Point_3 point(std::size_t i) const {
    const Triangulation& tr = c3t3_->triangulation();
    return tr.geom_traits().construct_point_3_object()(tr.point(vertices_[i]));
  }

  /// the four vertex indices of tetrahedron `t`, in the vertex order of its cell
  std::array<std::size_t, 4> tetrahedron(std::size_t t) const { return tetrahedra_[t]; }

  bool has_scalar_field() const { return has_scalars_; }

  /// the scalar value of vertex `i` (0 without a scalar field)
  double scalar(std::size_t i) const { return has_scalars_ ? scalars_[i] : 0.; }

  /// the tetrahedron labels are the subdomain indices of the cells
  bool has_tetrahedron_labels() const { return true; }
  /// the subdomain index of the cell of tetrahedron `t`, as an `int`
  int tetrahedron_label(std::size_t t) const { return static_cast<int>(subdomain_index(t)); }
  /// @}

  /// \name Back to the complex
  /// @{
  const C3T3& complex() const { return *c3t3_; }
  Vertex_handle vertex_handle(std::size_t i) const { return vertices_[i]; }
  Cell_handle cell_handle(std::size_t t) const { return cells_[t]; }
  Subdomain_index subdomain_index(std::size_t t) const { return c3t3_->subdomain_index(cells_[t]); }
  /// @}

private:
  void build() {
    const std::size_t nc = static_cast<std::size_t>(c3t3_->number_of_cells_in_complex());
    cells_.reserve(nc);
    tetrahedra_.reserve(nc);
    std::unordered_map<Vertex_handle, std::size_t> index;
    index.reserve(nc / 4 + 16);
    for (auto cit = c3t3_->cells_in_complex_begin(); cit != c3t3_->cells_in_complex_end(); ++cit) {
      const Cell_handle c = cit;
      std::array<std::size_t, 4> tet;
      for (int k = 0; k < 4; ++k) {
        const Vertex_handle v = c->vertex(k);
        auto inserted = index.emplace(v, vertices_.size());
        if (inserted.second) vertices_.push_back(v);
        tet[k] = inserted.first->second;
      }
      cells_.push_back(c);
      tetrahedra_.push_back(tet);
    }
  }

  const C3T3* c3t3_;
  std::vector<Vertex_handle> vertices_;
  std::vector<Cell_handle> cells_;
  std::vector<std::array<std::size_t, 4>> tetrahedra_;
  std::vector<double> scalars_;
  bool has_scalars_ = false;
};

/// \ingroup PkgPRStarOctreeRef
/// Adapts a mesh complex (see `Mesh_complex_3_input`) without a scalar field.
///
/// (Other models of `MeshComplex_3InTriangulation_3` are adapted by constructing a
/// `Mesh_complex_3_input` directly: `make_input()` takes `Mesh_complex_3_in_triangulation_3`
/// explicitly so as to be more specialized than `make_input(points, tetrahedra)`.)
template <class Tr, class CornerIndex, class CurveIndex>
Mesh_complex_3_input<Mesh_complex_3_in_triangulation_3<Tr, CornerIndex, CurveIndex>>
make_input(const Mesh_complex_3_in_triangulation_3<Tr, CornerIndex, CurveIndex>& c3t3) {
  return Mesh_complex_3_input<Mesh_complex_3_in_triangulation_3<Tr, CornerIndex, CurveIndex>>(c3t3);
}

/// \ingroup PkgPRStarOctreeRef
/// Adapts a mesh complex (see `Mesh_complex_3_input`) with a scalar field given as a functor
/// `double(Vertex_handle)` or a vertex property map.
template <class Tr, class CornerIndex, class CurveIndex, class ScalarFieldOrMap>
Mesh_complex_3_input<Mesh_complex_3_in_triangulation_3<Tr, CornerIndex, CurveIndex>>
make_input(const Mesh_complex_3_in_triangulation_3<Tr, CornerIndex, CurveIndex>& c3t3,
           const ScalarFieldOrMap& field) {
  return Mesh_complex_3_input<Mesh_complex_3_in_triangulation_3<Tr, CornerIndex, CurveIndex>>(c3t3, field);
}

/// \ingroup PkgPRStarOctreeRef
/// Copies the cells in the complex of `c3t3` into an `Indexed_tetrahedral_mesh`, with the vertex
/// numbering and orientation of `Mesh_complex_3_input`; the tetrahedron labels are the subdomain
/// indices of the cells.
///
/// \tparam C3T3 a model of `MeshComplex_3InTriangulation_3` whose `Subdomain_index` converts to `int`
/// \tparam Index the vertex index type of the result
///
/// \throws std::overflow_error if the number of vertices does not fit in `Index`
template <class C3T3, class Index = std::uint32_t>
Indexed_tetrahedral_mesh<typename Mesh_complex_3_input<C3T3>::Point_3, Index>
c3t3_to_indexed_tetrahedral_mesh(const C3T3& c3t3) {
  using Input = Mesh_complex_3_input<C3T3>;
  Indexed_tetrahedral_mesh<typename Input::Point_3, Index> mesh;
  const Input input(c3t3);
  if (input.number_of_vertices() > static_cast<std::size_t>((std::numeric_limits<Index>::max)()))
    throw std::overflow_error("c3t3_to_indexed_tetrahedral_mesh: too many vertices for the index type");
  mesh.points.reserve(input.number_of_vertices());
  for (std::size_t i = 0; i < input.number_of_vertices(); ++i) mesh.points.push_back(input.point(i));
  mesh.tetrahedra.reserve(input.number_of_tetrahedra());
  mesh.tetrahedron_labels.reserve(input.number_of_tetrahedra());
  for (std::size_t t = 0; t < input.number_of_tetrahedra(); ++t) {
    const std::array<std::size_t, 4> c = input.tetrahedron(t);
    mesh.tetrahedra.push_back({{static_cast<Index>(c[0]), static_cast<Index>(c[1]), static_cast<Index>(c[2]),
                                static_cast<Index>(c[3])}});
    mesh.tetrahedron_labels.push_back(static_cast<int>(input.subdomain_index(t)));
  }
  return mesh;
}

/// \ingroup PkgPRStarOctreeRef
/// Builds the mesh complex of an `Indexed_tetrahedral_mesh` (e.g. the result of `simplify()`), the
/// converse of `to_indexed_tetrahedral_mesh()`: its triangulation holds the points and the
/// tetrahedra (completed by infinite cells), each cell in the complex with its label as subdomain
/// index (1 when the mesh has no labels), and the triangles between cells of different labels or
/// on the boundary in the complex as surface patches `(smaller, larger subdomain index)`, when the
/// `Surface_patch_index` can be made from such a pair.  Uses %CGAL's
/// `build_triangulation()` (`CGAL/Mesh_3/tet_soup_to_c3t3.h`).
///
/// \pre the tetrahedra are positively oriented (as `simplify()` gives them), no label is 0, and
/// the boundary of the union of the tetrahedra is a closed surface (a valid mesh)
/// \returns whether the triangulation could be built (`c3t3` is cleared otherwise)
template <class C3T3, class Point, class Index>
bool build_mesh_complex(const Indexed_tetrahedral_mesh<Point, Index>& mesh, C3T3& c3t3) {
  using Tr = typename C3T3::Triangulation;
  using Spi = typename Tr::Cell::Surface_patch_index;
  c3t3.clear();
  if (mesh.points.empty() || mesh.tetrahedra.empty()) return false;
  std::vector<typename Tr::Point> points;
  points.reserve(mesh.points.size());
  for (const auto& p : mesh.points) points.emplace_back(p.x(), p.y(), p.z());
  std::vector<std::array<int, 5>> cells;
  cells.reserve(mesh.tetrahedra.size());
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    const auto& c = mesh.tetrahedra[t];
    const int label = mesh.tetrahedron_labels.empty() ? 1 : mesh.tetrahedron_labels[t];
    if (label == 0)
      throw std::invalid_argument("build_mesh_complex: label 0 is the outside of a mesh complex");
    cells.push_back({{int(c[0]), int(c[1]), int(c[2]), int(c[3]), label}});
  }
  std::map<std::array<int, 3>, Spi> patches;
  if constexpr (std::is_constructible<Spi, std::pair<int, int>>::value) {
    // Each triangle with its two sides (0: outside); the key as build_triangulation() looks it up.
    std::map<std::array<int, 3>, std::pair<int, int>> sides;
    for (const auto& c : cells)
      for (int j = 0; j < 4; ++j) {
        std::array<int, 3> f{{c[(j + 1) % 4], c[(j + 2) % 4], c[(j + 3) % 4]}};
        std::sort(f.begin(), f.end());
        auto it = sides.emplace(f, std::make_pair(c[4], 0));
        if (!it.second) it.first->second.second = c[4];
      }
    for (const auto& s : sides) {
      const int a = s.second.first, b = s.second.second;
      if (a == b) continue;
      const std::array<int, 3>& f = s.first; // sorted: both circular orders start at the smallest
      patches[f] = Spi(std::make_pair((std::min)(a, b), (std::max)(a, b)));
      patches[std::array<int, 3>{{f[0], f[2], f[1]}}] =
          Spi(std::make_pair((std::min)(a, b), (std::max)(a, b)));
    }
  }
  std::vector<typename Tr::Vertex_handle> handles;
  if (!CGAL::build_triangulation<Tr, true>(c3t3.triangulation(), points, cells, patches, handles)) {
    c3t3.clear();
    return false;
  }
  c3t3.rescan_after_load_of_triangulation();
  return true;
}

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_MESH_COMPLEX_3_INPUT_H
