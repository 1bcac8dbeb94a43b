// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_DISTORTION_H
#define CGAL_PR_STAR_OCTREE_DISTORTION_H

/// \file distortion.h
/// Discrete distortion (paper Section 8): the curvature of a scalar field f sampled at the vertices,
/// seen as a hypersurface of R^4 through the tetrahedral mesh lifted by f.

#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/internal/fixed_point_sum.h>
#include <CGAL/PR_star_octree/internal/solid_angle.h>
#include <CGAL/PR_star_octree/parameters.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {

/// \ingroup PkgPRStarOctreeRef
/// The curvature fields at one vertex.
struct Vertex_curvature {
  double solid_angle_sum_3 = 0; ///< sum over the star of the 3D solid angles at the vertex
  double solid_angle_sum_4 = 0; ///< the same for the mesh lifted by the scalar field
  /// the discrete distortion: (4 pi for an interior vertex, the real 3D sum for a boundary vertex)
  /// minus the lifted sum; 0 for unreferenced and NaN for non-manifold vertices
  double distortion = 0;
  /// the 3D concentrated curvature of the domain: (4 pi or 2 pi) minus the 3D sum
  double domain_curvature = 0;
  Vertex_type type = Vertex_type::UNREFERENCED;
};

/// \ingroup PkgPRStarOctreeRef
/// A field stored with the octree, as a model of `ReadablePropertyMap` keyed by the user's vertex
/// index (`std::size_t`) with value `double`: the scalar field of the input mesh
/// (`scalar_field_map()`) or a coordinate (`coordinate_field_map()`).  The functions of this header
/// read it in the octree's numbering directly; `get()` with a user index builds the inverse vertex
/// permutation once, on first use (that first call must not race with others: call it once before
/// sharing a map between threads).
template <class Octree>
class Octree_field_map {
public:
  using key_type = std::size_t;
  using value_type = double;
  using reference = double;
  using category = boost::readable_property_map_tag;
  using Index = typename Octree::Index;

  /// `axis` 0, 1, 2 for x, y, z; -1 for the stored scalar field
  Octree_field_map(const Octree& tree, int axis) : tree_(&tree), axis_(axis) {}
  /// the value at vertex `v` of the octree's numbering
  double at_octree_vertex(Index v) const {
    return axis_ < 0 ? tree_->scalar(v) : tree_->coordinates(tree_->point(v))[axis_];
  }
  /// the value at vertex `i` of the user's numbering
  friend double get(const Octree_field_map& m, std::size_t i) {
    if (!m.from_original_)
      m.from_original_ = std::make_shared<const std::vector<Index>>(m.tree_->vertex_from_original());
    return m.at_octree_vertex((*m.from_original_)[i]);
  }

private:
  const Octree* tree_;
  int axis_;
  mutable std::shared_ptr<const std::vector<Index>> from_original_;
};

/// \ingroup PkgPRStarOctreeRef
/// The scalar field stored in the octree (from the input mesh), as a field map.
/// \throws std::invalid_argument if the mesh has no scalar field
template <class Octree>
Octree_field_map<Octree> scalar_field_map(const Octree& tree) {
  if (!tree.has_scalar_field()) throw std::invalid_argument("the mesh has no scalar field");
  return Octree_field_map<Octree>(tree, -1);
}

/// \ingroup PkgPRStarOctreeRef
/// A linear field: coordinate `axis` (0, 1, 2 for x, y, z) of each vertex, as a field map.
template <class Octree>
Octree_field_map<Octree> coordinate_field_map(const Octree& tree, int axis) {
  if (axis < 0 || axis > 2) throw std::invalid_argument("coordinate axis must be 0, 1 or 2");
  return Octree_field_map<Octree>(tree, axis);
}

namespace internal {

// The sums of the solid angles at a vertex: the same bits whatever the order of the star.
using Angle_sum = Fixed_point_sum;

inline Vertex_curvature finish_curvature(double s3, double s4, Vertex_type type) {
  const double pi = 3.14159265358979323846;
  Vertex_curvature c;
  c.solid_angle_sum_3 = s3;
  c.solid_angle_sum_4 = s4;
  c.type = type;
  switch (type) {
  case Vertex_type::INTERIOR:
    c.distortion = 4 * pi - s4;
    c.domain_curvature = 4 * pi - s3;
    break;
  case Vertex_type::BOUNDARY:
    c.distortion = s3 - s4;
    c.domain_curvature = 2 * pi - s3;
    break;
  case Vertex_type::NONMANIFOLD:
    c.distortion = c.domain_curvature = std::numeric_limits<double>::quiet_NaN();
    break;
  case Vertex_type::UNREFERENCED:
    break;
  }
  return c;
}

// Writes the parts of a `Vertex_curvature` into separate maps (the optional ones may be absent).
template <class DistortionMap, class DomainMap, class TypeMap>
struct Curvature_split_map {
  using key_type = std::size_t;
  using value_type = Vertex_curvature;
  using reference = void;
  using category = boost::writable_property_map_tag;
  DistortionMap distortion;
  DomainMap domain;
  TypeMap types;
  friend void put(const Curvature_split_map& m, std::size_t i, const Vertex_curvature& c) {
    put(m.distortion, i, c.distortion);
    put_if_given(m.domain, i, c.domain_curvature);
    put_if_given(m.types, i, c.type);
  }

private:
  template <class V>
  static void put_if_given(const CGAL::internal_np::Param_not_found&, std::size_t, const V&) {}
  template <class Map, class V>
  static void put_if_given(const Map& map, std::size_t i, const V& v) {
    put(map, i, v);
  }
};

// The value of a field map at vertex `v` of the octree's numbering.
template <class Octree, class FieldMap>
double field_value(const Octree& tree, const FieldMap& field, typename Octree::Index v) {
  return static_cast<double>(get(field, static_cast<std::size_t>(tree.original_vertex(v))));
}
template <class Octree>
double field_value(const Octree&, const Octree_field_map<Octree>& field, typename Octree::Index v) {
  return field.at_octree_vertex(v);
}

// The curvature of vertex `v` of the leaf of `local`.  The result does not depend on the order of
// the star (a distributed run numbers the tetrahedra otherwise and must give the same bits): the
// corners' angles are added in fixed point (`Fixed_point_sum`), then rounded once.  (Each corner's
// angles are computed with the tetrahedron's vertices in the order the octree keeps, the input's
// order made positive, on every rank.)
template <class Octree, class FieldMap>
Vertex_curvature vertex_curvature(const Leaf_topology<Octree>& local, const FieldMap& field,
                                  Vertex_classifier<Octree>& classifier, typename Octree::Index v) {
  const Octree& tree = local.octree();
  Angle_sum s3, s4;
  for (auto t : local.vertex_tetrahedra(v)) {
    const auto& c = local.tetrahedron(t);
    std::array<std::array<double, 3>, 4> p;
    std::array<double, 4> f;
    int k = 0;
    for (int i = 0; i < 4; ++i) {
      p[i] = tree.coordinates(tree.point(c[i]));
      f[i] = field_value(tree, field, c[i]);
      if (c[i] == v) k = i;
    }
    const auto a = corner_solid_angles(p, f, k);
    s3.add(a.first);
    s4.add(a.second);
  }
  return finish_curvature(s3.value(), s4.value(), classifier.classify(local, v));
}

} // namespace internal

/// \ingroup PkgPRStarOctreeRef
/// The relations `compute_curvature()` builds in each leaf (what to size an automatic k_v for).
constexpr unsigned compute_curvature_relations = VERTEX_LINKS | LOCAL_TETRAHEDRA;

/// \ingroup PkgPRStarOctreeRef
/// The discrete distortion and the domain curvature of every vertex, by streaming over the leaves
/// (VT is built per leaf, then discarded), written into `curvature_map`.
///
/// \tparam FieldMap a model of `ReadablePropertyMap` with key `std::size_t` (the user's vertex
///         index) and a value convertible to `double`: `scalar_field_map()`, `coordinate_field_map()`,
///         or e.g. `CGAL::make_property_map(values)` for a `std::vector<double>` in the user's order
/// \tparam CurvatureMap a model of `WritablePropertyMap` with key `std::size_t` (the user's vertex
///         index) and value `Vertex_curvature`
/// \param tree the octree of the mesh
/// \param field the scalar field
/// \param curvature_map receives the curvature of each vertex, once per vertex, leaf after leaf
///        in the octree's order; never from two threads at once (in parallel, not necessarily from
///        the calling thread), so a map writing into a plain array needs no locking
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{progress}
///     \cgalParamDescription{called as `F(done, total)` after each leaf, `done` never decreasing}
///     \cgalParamType{a callable `F(std::size_t, std::size_t)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \tparam ConcurrencyTag `CGAL::Parallel_tag`, `CGAL::Sequential_tag` or the default
///         `CGAL::Parallel_if_available_tag`: the same values either way, bit for bit (the field
///         map is read once per vertex, from the calling thread, before the leaves; a field map of
///         the octree, `scalar_field_map()` or `coordinate_field_map()`, is read in place, from
///         several threads in parallel)
///
/// Memory: besides the octree, a copy of the field in the octree's numbering (8 bytes per vertex,
/// none for a field map of the octree) and the results of the leaves in flight; no buffer per
/// vertex.
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class GT, class I, class FieldMap,
          class CurvatureMap, class NP = parameters::Default_named_parameters>
Vertex_type_counts compute_curvature(const PR_star_octree_3<GT, I>& tree, const FieldMap& field,
                                     CurvatureMap curvature_map,
                                     const NP& np = parameters::default_values()) {
  using Octree = PR_star_octree_3<GT, I>;
  struct State {
    std::vector<internal::Angle_sum> s3, s4;
    std::vector<double> fields;
    std::vector<std::array<double, 3>> points;
  };
  Vertex_type_counts counts;
  // Each leaf returns the curvature of its own vertices; the executor's reduction, called one leaf
  // at a time in leaf order, writes them to the user's map.  So the map is never written by two
  // threads at once, and only the results of the leaves in flight are held (no per-vertex buffer:
  // that was 40 bytes per vertex, more than a third of the structure's own size on a lattice).
  struct Leaf_result {
    I first = 0; // the leaf's first vertex
    std::vector<Vertex_curvature> curvature;
  };
  // A field in the user's numbering is copied into the octree's numbering first, one read per
  // vertex (the leaves would read it at scattered places, several times per vertex).
  constexpr bool in_place = std::is_same<FieldMap, Octree_field_map<Octree>>::value;
  std::vector<double> values(in_place ? 0 : tree.number_of_vertices());
  for (std::size_t v = 0; v < values.size(); ++v)
    values[v] = internal::field_value(tree, field, static_cast<I>(v));
  auto value = [&](I v) {
    if constexpr (in_place)
      return internal::field_value(tree, field, v);
    else
      return values[v];
  };
  // The links (checked, as `Vertex_classifier` does by default) and the leaf's tetrahedra in local
  // ids: the coordinates and the field value of each vertex are read once per leaf.
  Leaf_executor<ConcurrencyTag>().map_reduce(
      tree, compute_curvature_relations, State(),
      [&](State& state, const Leaf_topology<Octree>& local) {
        const I vb = local.vertex_begin();
        const std::size_t nv = local.vertex_end() - vb;
        const std::size_t m = local.number_of_local_vertices();
        state.points.resize(m);
        state.fields.resize(m);
        for (std::size_t j = 0; j < m; ++j) {
          const I v = local.local_vertex(j);
          state.points[j] = tree.coordinates(tree.point(v));
          state.fields[j] = value(v);
        }
        // Each tetrahedron of the leaf once, for all its corners in the leaf, added exactly as in
        // `vertex_curvature()` (the same bits: `Tetrahedron_solid_angles` computes a corner's
        // angles alike whichever corners are asked).
        std::vector<internal::Angle_sum>&s3 = state.s3, &s4 = state.s4;
        s3.assign(nv, internal::Angle_sum());
        s4.assign(nv, internal::Angle_sum());
        std::array<std::array<double, 3>, 4> p;
        std::array<double, 4> f;
        const std::size_t n_tets = local.tetrahedra().size();
        for (std::size_t t = 0; t < n_tets; ++t) {
          const auto& l = local.local_tetrahedron(t);
          for (int i = 0; i < 4; ++i) {
            p[i] = state.points[l[i]];
            f[i] = state.fields[l[i]];
          }
          // The corners in the leaf share the tetrahedron's volume and edge lengths.
          unsigned corners = 0;
          for (int k = 0; k < 4; ++k)
            if (l[k] < nv) corners |= 1u << k;
          const internal::Tetrahedron_solid_angles angles(p, f, corners);
          for (int k = 0; k < 4; ++k) {
            if (!(corners >> k & 1u)) continue;
            const auto a = angles.corner(k);
            s3[l[k]].add(a.first);
            s4[l[k]].add(a.second);
          }
        }
        Leaf_result r;
        r.first = vb;
        r.curvature.resize(nv);
        for (std::size_t i = 0; i < nv; ++i)
          r.curvature[i] = internal::finish_curvature(s3[i].value(), s4[i].value(),
                                                      local.vertex_type(static_cast<I>(vb + i)));
        return r;
      },
      [&](Leaf_result&& r) {
        for (std::size_t i = 0; i < r.curvature.size(); ++i) {
          counts.add(r.curvature[i].type);
          put(curvature_map, static_cast<std::size_t>(tree.original_vertex(static_cast<I>(r.first + i))),
              r.curvature[i]);
        }
      },
      internal::Progress_reporter<NP>(np));
  return counts;
}

/// \ingroup PkgPRStarOctreeRef
/// The discrete distortion of the field `field` at every vertex, written into `distortion_map`
/// (a `WritablePropertyMap` keyed by the user's vertex index, value `double`); see
/// `compute_curvature()` for `FieldMap`.
///
/// \param tree the octree of the mesh
/// \param field the scalar field
/// \param distortion_map receives the distortion of each vertex
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{domain_curvature_map}
///     \cgalParamDescription{receives the 3D concentrated curvature of the domain at each vertex}
///     \cgalParamType{a `WritablePropertyMap` with key `std::size_t` (the user's vertex index) and value
///     `double`} \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_type_map}
///     \cgalParamDescription{receives the `Vertex_type` of each vertex}
///     \cgalParamType{a `WritablePropertyMap` with key `std::size_t` (the user's vertex index) and value
///     `Vertex_type`} \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress}
///     \cgalParamDescription{called as `F(done, total)` after each leaf, `done` never decreasing}
///     \cgalParamType{a callable `F(std::size_t, std::size_t)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \tparam ConcurrencyTag as in `compute_curvature()`
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class GT, class I, class FieldMap,
          class DistortionMap, class NP = parameters::Default_named_parameters>
Vertex_type_counts compute_discrete_distortion(const PR_star_octree_3<GT, I>& tree, const FieldMap& field,
                                               DistortionMap distortion_map,
                                               const NP& np = parameters::default_values()) {
  using parameters::get_parameter;
  const internal::Curvature_split_map<DistortionMap,
                                      decltype(get_parameter(np, internal_np::domain_curvature_map)),
                                      decltype(get_parameter(np, internal_np::vertex_type_map))>
      split{distortion_map, get_parameter(np, internal_np::domain_curvature_map),
            get_parameter(np, internal_np::vertex_type_map)};
  return compute_curvature<ConcurrencyTag>(tree, field, split, np);
}

/// \ingroup PkgPRStarOctreeRef
/// The curvature at one vertex `v` (octree numbering): builds the local structure of its leaf only.
template <class GT, class I, class FieldMap>
Vertex_curvature curvature_at(const PR_star_octree_3<GT, I>& tree, typename PR_star_octree_3<GT, I>::Index v,
                              const FieldMap& field) {
  using Octree = PR_star_octree_3<GT, I>;
  Leaf_topology<Octree> local(tree, tree.leaf_of_vertex(v), VERTEX_TETRAHEDRA);
  Vertex_classifier<Octree> classifier;
  return internal::vertex_curvature(local, field, classifier, v);
}

/// \ingroup PkgPRStarOctreeRef
/// The curvature of the vertices inside the box `box` (closed), a spatially coherent query: each
/// leaf whose box meets `box` builds its local structure once for all its vertices.  Appends
/// `(v, curvature)` pairs (octree numbering, increasing) to `out`.
template <class GT, class I, class FieldMap>
void curvature_in_box(const PR_star_octree_3<GT, I>& tree, const Bbox_3& box, const FieldMap& field,
                      std::vector<std::pair<I, Vertex_curvature>>& out) {
  using Octree = PR_star_octree_3<GT, I>;
  Leaf_topology<Octree> local;
  Vertex_classifier<Octree> classifier;
  // Descend the tree, pruning the nodes whose boxes miss `box`.
  std::vector<typename Octree::Node_index> stack{tree.root()};
  std::vector<typename Octree::Node_index> hit;
  while (!stack.empty()) {
    const auto n = stack.back();
    stack.pop_back();
    if (!CGAL::do_overlap(tree.node_bbox(n), box) || tree.node(n).number_of_vertices() == 0) continue;
    if (tree.node(n).is_leaf())
      hit.push_back(n);
    else
      for (int c = 7; c >= 0; --c) stack.push_back(tree.node(n).first_child + c);
  }
  std::sort(hit.begin(), hit.end(),
            [&](auto a, auto b) { return tree.node(a).vertex_begin < tree.node(b).vertex_begin; });
  for (auto n : hit) {
    bool built = false;
    for (I v = tree.node(n).vertex_begin; v < tree.node(n).vertex_end; ++v) {
      const std::array<double, 3> p = tree.coordinates(tree.point(v));
      if (p[0] < box.xmin() || p[0] > box.xmax() || p[1] < box.ymin() || p[1] > box.ymax() ||
          p[2] < box.zmin() || p[2] > box.zmax())
        continue;
      if (!built) {
        local.build(tree, n, VERTEX_TETRAHEDRA);
        built = true;
      }
      out.emplace_back(v, internal::vertex_curvature(local, field, classifier, v));
    }
  }
}

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_DISTORTION_H
