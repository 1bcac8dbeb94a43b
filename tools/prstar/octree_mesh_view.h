// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Writing the mesh held by a PR-star octree with computed point arrays, without a second copy of
// the mesh (boundary -o, curvature -o): the writers of the formats that keep point data read the
// points and tetrahedra through a view of the octree.

#ifndef PRSTAR_OCTREE_MESH_VIEW_H
#define PRSTAR_OCTREE_MESH_VIEW_H

#include "command.h"

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>

#include <array>
#include <cstddef>
#include <iterator>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace prstar {

/// What the octree does not take of a mesh moved into it: the point and cell arrays, the names of
/// the labels.  Moved out of the mesh before the octree is built from it, kept in the user's order.
struct Mesh_arrays {
  std::vector<CGAL::PR_star_octree::Point_data_array> point_data, cell_data;
  std::map<int, std::string> label_names;

  Mesh_arrays() = default;
  explicit Mesh_arrays(Mesh& mesh)
      : point_data(std::move(mesh.point_data)), cell_data(std::move(mesh.cell_data)),
        label_names(std::move(mesh.label_names)) {
    mesh.point_data.clear();
    mesh.cell_data.clear();
    mesh.label_names.clear();
  }
};

/// `n` values computed by `get(i)`: what the writers need of a `std::vector` (size, indexing,
/// iteration), without storing the values.
template <class Get>
class Computed_range {
public:
  class iterator {
  public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = decltype(std::declval<const Get&>()(std::size_t(0)));
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = value_type;
    iterator(const Computed_range* r, std::size_t i) : r_(r), i_(i) {}
    value_type operator*() const { return r_->get_(i_); }
    iterator& operator++() {
      ++i_;
      return *this;
    }
    bool operator==(const iterator& o) const { return i_ == o.i_; }
    bool operator!=(const iterator& o) const { return i_ != o.i_; }

  private:
    const Computed_range* r_;
    std::size_t i_;
  };

  Computed_range(std::size_t n, Get get) : n_(n), get_(get) {}
  std::size_t size() const { return n_; }
  bool empty() const { return n_ == 0; }
  auto operator[](std::size_t i) const { return get_(i); }
  iterator begin() const { return iterator(this, 0); }
  iterator end() const { return iterator(this, n_); }

private:
  std::size_t n_;
  Get get_;
};

/// The mesh of `tree` as the writers see an `Indexed_tetrahedral_mesh`: the vertices in the user's
/// order, the tetrahedra in the octree's order (each one as the user gave it: the user's vertex
/// indices in the user's order), their labels, and `arrays` (point data in the user's order, cell
/// data put in the octree's order of the tetrahedra).
/// \pre `tree.has_vertex_permutation()`, and `tree.has_tetrahedron_permutation()` when there is
///      cell data
template <class Octree>
class Octree_mesh_view {
  using Index = typename Octree::Index;
  struct Point_at {
    const Octree* tree;
    const std::vector<Index>* from_original;
    typename Octree::Point_3 operator()(std::size_t v) const { return tree->point((*from_original)[v]); }
  };
  struct Tetrahedron_at {
    const Octree* tree;
    std::array<Index, 4> operator()(std::size_t t) const {
      return tree->original_tetrahedron_vertices(static_cast<Index>(t));
    }
  };
  struct Label_at {
    const Octree* tree;
    int operator()(std::size_t t) const { return tree->tetrahedron_label(static_cast<Index>(t)); }
  };
  std::vector<Index> from_original_;

public:
  using Point_3 = typename Octree::Point_3;
  using Tetrahedron = std::array<Index, 4>;

  Computed_range<Point_at> points;
  Computed_range<Tetrahedron_at> tetrahedra;
  Computed_range<Label_at> tetrahedron_labels; // empty without labels
  std::vector<CGAL::PR_star_octree::Point_data_array> point_data, cell_data;
  std::map<int, std::string> label_names;
  std::map<std::string, std::size_t> skipped_cells; // none: they were reported when reading
  bool float32_points; // the octree stores floats: the writers write 32-bit coordinates again

  Octree_mesh_view(const Octree& tree, Mesh_arrays&& arrays)
      : from_original_(tree.vertex_from_original()),
        points(tree.number_of_vertices(), Point_at{&tree, &from_original_}),
        tetrahedra(tree.number_of_tetrahedra(), Tetrahedron_at{&tree}),
        tetrahedron_labels(tree.has_tetrahedron_labels() ? tree.number_of_tetrahedra() : 0, Label_at{&tree}),
        point_data(std::move(arrays.point_data)), cell_data(std::move(arrays.cell_data)),
        label_names(std::move(arrays.label_names)), float32_points(tree.has_float_coordinates()) {
    CGAL_precondition(tree.has_vertex_permutation());
    for (auto& a : cell_data) { // one array at a time into the octree's order
      if (a.values.size() != tree.number_of_tetrahedra()) continue; // refused by the writers
      std::vector<double> ordered(a.values.size());
      for (std::size_t t = 0; t < ordered.size(); ++t)
        ordered[t] = a.values[tree.original_tetrahedron(static_cast<Index>(t))];
      a.values.swap(ordered);
    }
  }
  Octree_mesh_view(const Octree_mesh_view&) = delete; // the ranges point into the view
  Octree_mesh_view& operator=(const Octree_mesh_view&) = delete;

  /// the octree's index of the user's vertex `u`
  Index octree_vertex(std::size_t u) const { return from_original_[u]; }
};

/// Writes the mesh of `tree` with its `arrays` then `extra` (point arrays in the user's order) to
/// `out`, one of `point_data_outputs()`, through a temporary (see `write_through_temporary`): the
/// VTK writers take `extra` as their extra point data, TetGen's writes every point array as a node
/// attribute, gmsh's as a `$NodeData` view, XDMF's as a `Node` attribute.  `view.point_data` is
/// given back as it was.
template <class Octree>
void write_octree_mesh(const std::string& out, Octree_mesh_view<Octree>& view,
                       std::vector<CGAL::PR_star_octree::Point_data_array>& extra) {
  namespace IO = CGAL::PR_star_octree::IO;
  const std::string ext = IO::internal::lower_extension(out);
  write_through_temporary(out, [&](const std::string& tmp) {
    if (ext == "vtu") {
      IO::write_vtu(tmp, view, extra);
    } else if (ext == "vtk") {
      IO::write_vtk(tmp, view, extra);
    } else if (ext == "node" || ext == "ele" || ext == "msh" || ext == "xdmf" || ext == "xmf") {
      const std::size_t own = view.point_data.size();
      for (auto& a : extra) view.point_data.push_back(std::move(a));
      const auto give_back = [&] {
        for (std::size_t i = 0; i < extra.size(); ++i) extra[i] = std::move(view.point_data[own + i]);
        view.point_data.resize(own);
      };
      try {
        if (ext == "msh")
          IO::write_gmsh(tmp, view);
        else if (ext == "xdmf" || ext == "xmf")
          IO::write_xdmf(tmp, view);
        else
          IO::write_tetgen(tmp, view);
      } catch (...) {
        give_back();
        throw;
      }
      give_back();
    } else {
      throw std::runtime_error(out + ": point arrays are written to " + point_data_outputs() + " files only");
    }
  });
}

} // namespace prstar

#endif // PRSTAR_OCTREE_MESH_VIEW_H
