// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_H
#define CGAL_PR_STAR_OCTREE_H

/// \file PR_star_octree.h
/// The PR-star octree: a PR octree on the vertices of a tetrahedral mesh whose leaves also list the
/// tetrahedra incident in their vertices (their star).

#include <CGAL/Bbox_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/number_utils.h>

#include <CGAL/PR_star_octree/Index_arrays_input.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>
#include <CGAL/PR_star_octree/Statistics.h>
#include <CGAL/PR_star_octree/bucket_size.h>
#include <CGAL/PR_star_octree/internal/compact_tetrahedra.h>
#include <CGAL/PR_star_octree/internal/concept_checks.h>
#include <CGAL/PR_star_octree/internal/leaf_tetrahedra.h>
#include <CGAL/PR_star_octree/internal/point_range.h>
#include <CGAL/PR_star_octree/parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {

/// \ingroup PkgPRStarOctreeRef
///
/// The PR-star octree of a tetrahedral mesh (Weiss, Fellegara, De Floriani, Velloso, ACM SIGSPATIAL GIS
/// 2011; paper Section 4).
///
/// It holds three things:
/// - the vertex array `V` (points, optional scalar), re-indexed by a depth-first walk of the leaves,
///   so that every node owns the contiguous range `[vertex_begin, vertex_end)`;
/// - the tetrahedron array `T`, re-indexed for locality (sorted by smallest vertex) and positively
///   oriented (negatively oriented input tetrahedra get two vertices swapped, decided with the
///   exact `Orientation_3` of the traits; the user's order is kept and given back on request);
/// - a PR octree `N` on the vertices with bucket threshold `k_v`: a node is split into eight
///   children when it holds more than `k_v` vertices.  Boxes are half-open (a point on a splitting
///   plane goes to the upper child), so every vertex lies in exactly one leaf, and the shape of the
///   tree depends only on the point set, never on the input order.  Each leaf lists, in one flat
///   array, the tetrahedra incident in its vertices: a tetrahedron sits in 1 to 4 leaves.
///
/// The permutations from the new to the original vertex and tetrahedron numbering are kept, so
/// every result can be reported in the user's numbering.
///
/// Nodes that still hold more than `k_v` vertices at the depth bound, or whose vertices all
/// coincide (duplicate points), are not split further; they are counted in the statistics.
/// `k_v = infinite_bucket_size` gives a single leaf: the global baseline.
///
/// \tparam GeomTraits a model of `PRStarOctreeTraits` (default:
/// `Exact_predicates_inexact_constructions_kernel`) \tparam IndexType an unsigned integer type for vertex,
/// tetrahedron and node indices (default: 32 bits)
template <class GeomTraits = Exact_predicates_inexact_constructions_kernel, class IndexType = std::uint32_t>
class PR_star_octree_3 {
  static_assert(std::is_integral<IndexType>::value && std::is_unsigned<IndexType>::value,
                "PR_star_octree_3: IndexType must be an unsigned integer type");
  static_assert(PR_star_octree::internal::Check_geom_traits<GeomTraits>::value, "");

public:
  /// \name Types
  /// @{
  using Geom_traits = GeomTraits;
  using Point_3 = typename Geom_traits::Point_3;
  using Index = IndexType;
  /// four vertex indices, positively oriented
  using Tetrahedron = std::array<Index, 4>;
  using Node_index = Index;
  using Statistics = PR_star_octree::Statistics;

  /// A node of the octree: its vertex range and, for a leaf, its tetrahedra.
  ///
  /// The tetrahedra of a leaf come in two parts.  Those whose smallest vertex is in the leaf (the
  /// leaf *owns* them) form the contiguous range `[owned_begin, owned_end)` of `T`, because `T` is
  /// sorted by smallest vertex; they are not listed.  The others (smallest vertex in another leaf)
  /// are listed, entries `[shared_begin, shared_end)` of one array for all the leaves, so the lists
  /// hold `(chi - 1) |T|` entries instead of `chi |T|`.  They are stored compactly: each leaf's list
  /// is cut into groups (`[group_begin, group_end)`), each a base index and 16-bit offsets from it.
  struct Node {
    Index vertex_begin; ///< first vertex of the node (depth-first numbering)
    Index vertex_end;   ///< one past the last vertex of the node
    Index owned_begin;  ///< first tetrahedron owned by the leaf (empty range for internal nodes)
    Index owned_end;    ///< one past the last tetrahedron owned by the leaf
    Index shared_begin; ///< the leaf's listed tetrahedra: its entries in the shared list
    Index shared_end;
    Index group_begin; ///< the groups of its entries (compact encoding)
    Index group_end;
    Node_index first_child; ///< the eight children are contiguous; `no_node` for a leaf
    Node_index parent;      ///< `no_node` for the root
    bool is_leaf() const { return first_child == no_node; }
    std::size_t number_of_vertices() const { return vertex_end - vertex_begin; }
    /// the number of tetrahedra incident in the leaf's vertices (0 for internal nodes)
    std::size_t number_of_tetrahedra() const {
      return (owned_end - owned_begin) + (shared_end - shared_begin);
    }
  };

  /// The tetrahedra of a leaf in increasing index order: the listed shared ones, then the owned
  /// range (see `Node`).  A random-access range of `Index` values whose iterators stay valid after
  /// the range object is gone (as long as the octree lives).
  using Leaf_tetrahedra = PR_star_octree::internal::Leaf_tetrahedra<Index>;
  /// @}

  static constexpr Node_index no_node = (std::numeric_limits<Index>::max)();
  /// whether the coordinates can be stored as floats: the traits' `Construct_point_3` makes a
  /// `Point_3` from three `double`s
  static constexpr bool can_store_floats =
      PR_star_octree::internal::can_construct_point_3<Geom_traits>::value;
  /// `k_v = infinity`: a single leaf, the global baseline
  static constexpr std::size_t infinite_bucket_size = (std::numeric_limits<std::size_t>::max)();
  /// `k_v` chosen by the octree from the mesh (`CGAL::PR_star_octree::choose_bucket_size()`)
  static constexpr std::size_t automatic_bucket_size = PR_star_octree::automatic_bucket_size;
  /// the default of the named parameter `bucket_size`: `automatic_bucket_size`
  static constexpr std::size_t default_bucket_size = automatic_bucket_size;
  static constexpr std::size_t default_max_depth = 32;

  /// \name Creation
  /// @{

  /// Builds the PR-star octree of `input`, a model of `PRStarOctreeInputMesh`
  /// (see `CGAL::PR_star_octree::make_input()`).  The points, tetrahedra, scalars and labels are
  /// copied; `input` is not changed.
  ///
  /// \param input the mesh
  /// \param np an optional sequence of named parameters among the ones listed below (see
  ///        `CGAL::PR_star_octree::parameters`)
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{bucket_size}
  ///     \cgalParamDescription{the bucket threshold `k_v` (at least 1), `infinite_bucket_size`, or
  ///     `automatic_bucket_size`: chosen from the number of vertices and tetrahedra, the relations of
  ///     `bucket_size_relations` and the cache by `CGAL::PR_star_octree::choose_bucket_size()` (the
  ///     choice is reported by `bucket_size()` and `statistics()`)}
  ///     \cgalParamType{`std::size_t`}
  ///     \cgalParamDefault{`automatic_bucket_size`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{bucket_size_relations}
  ///     \cgalParamDescription{the relations (a combination of `CGAL::PR_star_octree::Relations`) the
  ///     leaves will build, for the automatic `k_v`: the larger their working set, the smaller the leaves}
  ///     \cgalParamType{`unsigned`}
  ///     \cgalParamDefault{`CGAL::PR_star_octree::default_bucket_size_relations` (links and triangles)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{maximum_depth}
  ///     \cgalParamDescription{the depth bound that stops splitting (duplicate or extremely close points)}
  ///     \cgalParamType{`std::size_t`}
  ///     \cgalParamDefault{`default_max_depth` (32)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{geom_traits}
  ///     \cgalParamDescription{an instance of the geometric traits class}
  ///     \cgalParamType{`GeomTraits`}
  ///     \cgalParamDefault{`GeomTraits()`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{vertex_permutation}
  ///     \cgalParamDescription{whether the new -> original vertex numbering is kept (one index per vertex;
  ///     without it the octree's numbering stands for the user's, see `has_vertex_permutation()`)}
  ///     \cgalParamType{`bool`}
  ///     \cgalParamDefault{`true`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{tetrahedron_permutation}
  ///     \cgalParamDescription{whether the new -> original tetrahedron numbering is kept (one index per
  ///     tetrahedron; without it `original_tetrahedron()` is not available, `original_tetrahedron_vertices()`
  ///     and everything per vertex still are)} \cgalParamType{`bool`} \cgalParamDefault{`true`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{compact_tetrahedra}
  ///     \cgalParamDescription{whether the tetrahedron array is stored compactly: 5-6 bytes per tetrahedron
  ///     instead of 16 (32-bit indices), every tetrahedron kept exactly (see `tetrahedra()`); access by index
  ///     then decodes, so `tetrahedron()` costs more, while the leaf topology decodes each leaf once}
  ///     \cgalParamType{`bool`}
  ///     \cgalParamDefault{`false`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{concurrency_tag}
  ///     \cgalParamDescription{`CGAL::Parallel_tag` builds with several threads (TBB), `CGAL::Sequential_tag`
  ///     with one; the octree is the same.  (A constructor cannot take an explicit template argument: this is
  ///     how the construction gets the `ConcurrencyTag` that the algorithms take as their first template
  ///     parameter.)} \cgalParamType{`CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
  ///     `CGAL::Parallel_if_available_tag`} \cgalParamDefault{`CGAL::Parallel_if_available_tag()`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \throws std::invalid_argument if a tetrahedron has a vertex index out of range or twice, or if
  ///         the mesh does not fit in `IndexType`, or on a non-finite coordinate, or `bucket_size == 0`.
  template <class InputMesh, class NP = parameters::Default_named_parameters>
  explicit PR_star_octree_3(const InputMesh& input, const NP& np = parameters::default_values())
      : gt_(parameters::choose_parameter(parameters::get_parameter(np, internal_np::geom_traits),
                                         Geom_traits())) {
    static_assert(PR_star_octree::internal::is_named_parameters<NP>::value,
                  "PR_star_octree_3: the second argument is a chain of named parameters, e.g. "
                  "CGAL::PR_star_octree::parameters::bucket_size(50).maximum_depth(20)");
    read_parameters(np);
    static_assert(PR_star_octree::internal::Check_input_mesh<InputMesh, Point_3>::value, "");
    check_bucket_size();
    copy_input(input);
    build_with(np);
  }

  /// Builds the PR-star octree of `mesh` without copying it (lean construction, for big meshes):
  /// its points, tetrahedra, first point-data array (the scalar field) and labels are moved into the
  /// octree and reordered there (T and the labels in place, V and the scalar field through one
  /// transient copy); they are removed from `mesh`, whose other arrays (other point data, cell
  /// data, label names) are left as they were.  The peak memory of the construction is about the
  /// final structure plus one copy of V.  Named parameters as in the other constructor.
  ///
  /// \throws std::invalid_argument as the other constructor, or if the scalar field or the labels
  ///         do not have one value per vertex or tetrahedron; `mesh` has then lost its moved arrays.
  template <class NP = parameters::Default_named_parameters>
  explicit PR_star_octree_3(PR_star_octree::Indexed_tetrahedral_mesh<Point_3, Index>&& mesh,
                            const NP& np = parameters::default_values())
      : gt_(parameters::choose_parameter(parameters::get_parameter(np, internal_np::geom_traits),
                                         Geom_traits())) {
    read_parameters(np);
    check_bucket_size();
    take_mesh(std::move(mesh));
    build_with(np);
  }

  /// Builds the PR-star octree without ever holding the plain tetrahedron array (streaming
  /// construction, for meshes whose plain form does not fit in memory): `vertices` gives the
  /// points, the scalar field (its first point-data array) and `float32_points`, moved in as by the
  /// lean constructor, and must have no tetrahedra; the tetrahedra come from `tetrahedra`, a model
  /// of `PRStarOctreeTetrahedronSource`, read several times: once to check and count them (not
  /// when the source has `number_of_tetrahedra()`), once to count them by smallest vertex, then
  /// once per slab of smallest vertices (by default min(6, |T| / 2^20 rounded up) slabs of equal
  /// parts of T; see `slab_tetrahedra`), each slab placed, oriented and encoded.  The tetrahedra are stored
  /// compactly (`compact_tetrahedra(true)` is implied), no tetrahedron permutation is kept, and the
  /// tetrahedra of a smallest vertex keep the source's order.  The named parameters are those of the
  /// other constructors (`parameters::default_values()` for none).
  ///
  /// \throws std::invalid_argument as the lean constructor, if `vertices` has tetrahedra or labels, or
  ///         if the source gives other tetrahedra on another pass; what the source throws (e.g.
  ///         `IO::Read_error`) goes through.
  template <class TetrahedronSource, class NP>
  PR_star_octree_3(PR_star_octree::Indexed_tetrahedral_mesh<Point_3, Index>&& vertices,
                   const TetrahedronSource& tetrahedra, const NP& np)
      : gt_(parameters::choose_parameter(parameters::get_parameter(np, internal_np::geom_traits),
                                         Geom_traits())) {
    read_parameters(np);
    check_bucket_size();
    if (!vertices.tetrahedra.empty() || !vertices.tetrahedron_labels.empty())
      throw std::invalid_argument("PR_star_octree_3: the streaming construction takes the tetrahedra and "
                                  "their labels from the source, not from the mesh");
    take_mesh(std::move(vertices));
    using Tag = typename internal_np::Lookup_named_param_def<PR_star_octree::internal_np::concurrency_tag_t,
                                                             NP, CGAL::Parallel_if_available_tag>::type;
    build_streaming<Tag>(tetrahedra);
  }
  /// @}

  /// \name The mesh (new numbering)
  /// @{
  std::size_t number_of_vertices() const { return points_.size() + float_points_.size(); } // (one is empty)
  std::size_t number_of_tetrahedra() const {
    return compact_ ? compact_tetrahedra_.size() : tetrahedra_.size();
  }
  /// the points: a random-access range of `Point_3` values (made from the stored floats when
  /// `has_float_coordinates()`)
  using Point_range = PR_star_octree::internal::Point_range<PR_star_octree_3>;
  Point_range points() const { return Point_range(*this); }
  /// point `v`, by value (made by the traits' `Construct_point_3` from the stored floats when
  /// `has_float_coordinates()`)
  Point_3 point(Index v) const {
    if constexpr (can_store_floats) {
      if (float_coordinates_) {
        const std::array<float, 3>& f = float_points_[v];
        return gt_.construct_point_3_object()(double(f[0]), double(f[1]), double(f[2]));
      }
    }
    return points_[v];
  }
  /// whether the coordinates are stored as 32-bit floats (12 bytes per vertex): named parameter
  /// `coordinate_precision`, by default when the input's coordinates are 32-bit floats
  bool has_float_coordinates() const { return float_coordinates_; }
  /// the range of tetrahedra (random access, `Tetrahedron` values; the view refers to the octree)
  using Tetrahedra_view = PR_star_octree::internal::Tetrahedra_view<Index>;
  /// the tetrahedra: a random-access range of `Tetrahedron` values whose iterators decode
  /// consecutive tetrahedra in one pass; `data()` is the plain array, `nullptr` when
  /// `is_compact()`
  Tetrahedra_view tetrahedra() const {
    return compact_ ? Tetrahedra_view(compact_tetrahedra_)
                    : Tetrahedra_view(tetrahedra_.data(), tetrahedra_.size());
  }
  /// tetrahedron `t` (in the compact form, decoded: a few records are skipped)
  Tetrahedron tetrahedron(Index t) const { return compact_ ? compact_tetrahedra_[t] : tetrahedra_[t]; }
  /// whether the tetrahedra are stored compactly (named parameter `compact_tetrahedra`)
  bool is_compact() const { return compact_; }
  /// the compact tetrahedron array (empty unless `is_compact()`)
  const PR_star_octree::internal::Compact_tetrahedra<Index>& compact_tetrahedra() const {
    return compact_tetrahedra_;
  }
  bool has_scalar_field() const { return has_scalar_; }
  /// one value per vertex (new numbering), or empty
  const std::vector<double>& scalars() const { return scalars_; }
  /// whether the input mesh gave one label per tetrahedron (e.g. subdomain indices)
  bool has_tetrahedron_labels() const { return has_labels_; }
  /// the label of tetrahedron `t` (new numbering), or 0 without labels (a mesh whose tetrahedra
  /// all have the same label stores it once)
  int tetrahedron_label(Index t) const { return labels_.empty() ? uniform_label_ : labels_[t]; }
  double scalar(Index v) const { return scalars_[v]; }
  const Geom_traits& geom_traits() const { return gt_; }
  /// the Cartesian coordinates of `p` as `double`s, through the traits' `Compute_x_3`,
  /// `Compute_y_3` and `Compute_z_3`
  std::array<double, 3> coordinates(const Point_3& p) const {
    return {{CGAL::to_double(gt_.compute_x_3_object()(p)), CGAL::to_double(gt_.compute_y_3_object()(p)),
             CGAL::to_double(gt_.compute_z_3_object()(p))}};
  }
  /// @}

  /// \name The octree
  /// @{
  std::size_t bucket_size() const { return bucket_size_; }
  /// whether `k_v` was chosen by the octree (`bucket_size` was `automatic_bucket_size`)
  bool has_automatic_bucket_size() const { return automatic_; }
  /// the choice of `k_v` and what it was made from (meaningful when `has_automatic_bucket_size()`)
  const PR_star_octree::Bucket_size_choice& bucket_size_choice() const { return choice_; }
  std::size_t max_depth() const { return max_depth_; }
  /// the depth of the deepest leaf (0 for a single leaf)
  std::size_t depth() const { return depth_; }
  Node_index root() const { return 0; }
  const std::vector<Node>& nodes() const { return nodes_; }
  const Node& node(Node_index n) const { return nodes_[n]; }
  std::size_t number_of_nodes() const { return nodes_.size(); }
  /// the leaves in depth-first order (their vertex ranges are consecutive)
  const std::vector<Node_index>& leaves() const { return leaves_; }
  std::size_t number_of_leaves() const { return leaves_.size(); }
  /// the tetrahedra incident in the vertices of leaf `n` (its star): the listed ones in increasing
  /// index order, then the owned range
  Leaf_tetrahedra leaf_tetrahedra(Node_index n) const {
    const Node& nd = nodes_[n];
    return Leaf_tetrahedra(leaf_offsets_.data() + nd.shared_begin, nd.shared_end - nd.shared_begin,
                           leaf_groups_.data() + nd.group_begin, nd.group_end - nd.group_begin,
                           nd.owned_begin, nd.owned_end);
  }
  /// calls `f(t, c)` for each tetrahedron `t` of leaf `n` (in the order of `leaf_tetrahedra(n)`), `c`
  /// its vertices, decoding the compact form in one pass; stops early when `f` returns `false` (if it
  /// returns a `bool`)
  template <class Function>
  void for_each_leaf_tetrahedron(Node_index n, Function f) const {
    auto call = [&f](Index t, const Tetrahedron& c) -> bool {
      if constexpr (std::is_same<decltype(f(t, c)), bool>::value)
        return f(t, c);
      else {
        f(t, c);
        return true;
      }
    };
    const Leaf_tetrahedra tets = leaf_tetrahedra(n);
    if (!compact_) {
      for (Index t : tets)
        if (!call(t, tetrahedra_[t])) return;
      return;
    }
    typename PR_star_octree::internal::Compact_tetrahedra<Index>::Cursor c(compact_tetrahedra_, 0);
    for (Index t : tets) {
      c.seek(t);
      if (!call(t, *c)) return;
    }
  }
  /// the number of listed (shared) entries of all leaves: `(chi - 1) |T|`
  std::size_t number_of_shared_entries() const { return leaf_offsets_.size(); }
  /// the vertex range of node `n`
  std::pair<Index, Index> vertex_range(Node_index n) const {
    return {nodes_[n].vertex_begin, nodes_[n].vertex_end};
  }
  /// the leaf whose range holds vertex `v` (`O(log |N_leaf|)`)
  Node_index leaf_of_vertex(Index v) const {
    auto it = std::upper_bound(leaves_.begin(), leaves_.end(), v,
                               [this](Index x, Node_index n) { return x < nodes_[n].vertex_begin; });
    CGAL_assertion(it != leaves_.begin());
    return *(it - 1);
  }
  /// the depth of node `n`
  std::size_t depth(Node_index n) const {
    std::size_t d = 0;
    for (; nodes_[n].parent != no_node; n = nodes_[n].parent) ++d;
    return d;
  }
  /// the cube of the root: the bounding box of the points, extended to a cube
  Bbox_3 bbox() const { return node_bbox(root()); }
  /// the box of node `n`: half-open, except on the upper faces of the root
  Bbox_3 node_bbox(Node_index n) const {
    std::vector<unsigned> path;
    for (Node_index c = n; nodes_[c].parent != no_node; c = nodes_[c].parent)
      path.push_back(static_cast<unsigned>(c - nodes_[nodes_[c].parent].first_child));
    std::array<double, 3> lo = root_lo_, hi = root_hi_;
    for (auto it = path.rbegin(); it != path.rend(); ++it) child_box(*it, lo, hi);
    return Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
  }
  /// the leaf whose box contains `p` (descends from the root; `p` outside the root box is clamped)
  Node_index locate(const Point_3& p) const {
    const std::array<double, 3> c = coordinates(p);
    std::array<double, 3> lo = root_lo_, hi = root_hi_;
    Node_index n = root();
    while (!nodes_[n].is_leaf()) {
      const unsigned code = octant(c, center(lo, hi));
      child_box(code, lo, hi);
      n = nodes_[n].first_child + code;
    }
    return n;
  }
  /// @}

  /// \name Back to the user's numbering
  /// @{
  /// whether the new -> original vertex numbering was kept (named parameter `vertex_permutation`,
  /// default `true`); without it, the octree's numbering stands for the user's: every result "in
  /// the user's numbering" is then in the octree's
  bool has_vertex_permutation() const { return keep_vertex_permutation_; }
  /// the original index of vertex `v` (`v` itself without `has_vertex_permutation()`)
  Index original_vertex(Index v) const { return keep_vertex_permutation_ ? vertex_to_original_[v] : v; }
  /// whether the new -> original tetrahedron numbering was kept (named parameter
  /// `tetrahedron_permutation`, default `true`)
  bool has_tetrahedron_permutation() const { return keep_tetrahedron_permutation_; }
  /// the original index of tetrahedron `t`
  /// \pre `has_tetrahedron_permutation()`
  Index original_tetrahedron(Index t) const {
    CGAL_precondition(has_tetrahedron_permutation());
    return tetrahedron_to_original_[t];
  }
  /// new -> original vertex indices (a permutation of `[0, |V|)`; empty without
  /// `has_vertex_permutation()`)
  const std::vector<Index>& vertex_permutation() const { return vertex_to_original_; }
  /// new -> original tetrahedron indices (empty without `has_tetrahedron_permutation()`)
  const std::vector<Index>& tetrahedron_permutation() const { return tetrahedron_to_original_; }
  /// whether tetrahedron `t` was negatively oriented as the user listed it
  bool is_reoriented(Index t) const {
    return !reoriented_.empty() && ((reoriented_[t >> 6] >> (t & 63)) & 1u);
  }
  /// tetrahedron `t` as the user gave it: original vertex indices, original vertex order
  std::array<Index, 4> original_tetrahedron_vertices(Index t) const {
    Tetrahedron c = tetrahedron(t);
    if (is_reoriented(t)) std::swap(c[2], c[3]);
    for (Index& v : c) v = original_vertex(v);
    return c;
  }
  /// original -> new vertex indices (computed, `O(|V|)`)
  std::vector<Index> vertex_from_original() const {
    if (keep_vertex_permutation_) return inverse(vertex_to_original_);
    std::vector<Index> identity(number_of_vertices());
    std::iota(identity.begin(), identity.end(), Index(0));
    return identity;
  }
  /// original -> new tetrahedron indices (computed, `O(|T|)`; empty without
  /// `has_tetrahedron_permutation()`)
  std::vector<Index> tetrahedron_from_original() const { return inverse(tetrahedron_to_original_); }
  /// @}

  /// \name Statistics
  /// @{
  /// the storage statistics of paper Table 1 and the bytes used (see `PR_star_octree::Statistics`)
  Statistics statistics() const;
  /// @}

private:
  // The subdivision of a box [lo, hi) into octants, the one definition used by the construction,
  // `node_bbox()` and `locate()`: octant `c` is the upper half along axis `a` when bit `a` of `c`
  // is set, the lower half otherwise, cut at `center()`.
  static double midpoint(double lo, double hi) { return lo + (hi - lo) * 0.5; }
  static std::array<double, 3> center(const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
    return {{midpoint(lo[0], hi[0]), midpoint(lo[1], hi[1]), midpoint(lo[2], hi[2])}};
  }
  // the octant of a box of center `mid` that holds `p` (half-open: a point on the cut goes up)
  static unsigned octant(const std::array<double, 3>& p, const std::array<double, 3>& mid) {
    return unsigned(p[0] >= mid[0]) | (unsigned(p[1] >= mid[1]) << 1) | (unsigned(p[2] >= mid[2]) << 2);
  }
  // [lo, hi) becomes its octant `c`
  static void child_box(unsigned c, std::array<double, 3>& lo, std::array<double, 3>& hi) {
    const std::array<double, 3> mid = center(lo, hi);
    for (int a = 0; a < 3; ++a) ((c >> a) & 1u ? lo[a] : hi[a]) = mid[a];
  }

  // An input point as a `Point_3`: converted, or made from its `x()`, `y()`, `z()` by the traits'
  // `Construct_point_3`.
  template <class P>
  Point_3 convert_point(const P& p) const {
    if constexpr (std::is_convertible<P, Point_3>::value)
      return Point_3(p);
    else
      return gt_.construct_point_3_object()(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                            CGAL::to_double(p.z()));
  }

  // The coordinates of stored point `i` (in the order of the moment) as `double`s.
  std::array<double, 3> stored_coordinates(std::size_t i) const {
    if (float_coordinates_) {
      const std::array<float, 3>& f = float_points_[i];
      return {{double(f[0]), double(f[1]), double(f[2])}};
    }
    return coordinates(points_[i]);
  }

  static std::vector<Index> inverse(const std::vector<Index>& perm) {
    std::vector<Index> inv(perm.size());
    for (std::size_t i = 0; i < perm.size(); ++i) inv[perm[i]] = static_cast<Index>(i);
    return inv;
  }

  // The named parameters of the constructors but `geom_traits`.
  template <class NP>
  void read_parameters(const NP& np) {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    namespace np_tags = PR_star_octree::internal_np;
    bucket_size_ = choose_parameter(get_parameter(np, np_tags::bucket_size), default_bucket_size);
    bucket_relations_ = choose_parameter(get_parameter(np, np_tags::bucket_size_relations),
                                         PR_star_octree::default_bucket_size_relations);
    max_depth_ = choose_parameter(get_parameter(np, np_tags::maximum_depth), default_max_depth);
    keep_vertex_permutation_ = choose_parameter(get_parameter(np, np_tags::vertex_permutation), true);
    keep_tetrahedron_permutation_ =
        choose_parameter(get_parameter(np, np_tags::tetrahedron_permutation), true);
    compact_ = choose_parameter(get_parameter(np, np_tags::compact_tetrahedra), false);
    slab_tetrahedra_ = choose_parameter(get_parameter(np, np_tags::slab_tetrahedra), std::size_t(0));
    precision_ = choose_parameter(get_parameter(np, np_tags::coordinate_precision),
                                  PR_star_octree::Coordinate_precision::as_input);
  }
  void check_bucket_size() const {
    if (bucket_size_ == 0)
      throw std::invalid_argument("PR_star_octree_3: the bucket size k_v must be at least 1");
  }
  template <class NP>
  void build_with(const NP&) {
    using Tag = typename internal_np::Lookup_named_param_def<PR_star_octree::internal_np::concurrency_tag_t,
                                                             NP, CGAL::Parallel_if_available_tag>::type;
    build_in_place<Tag>();
  }
  void check_sizes(std::size_t nv, std::size_t nt) const;
  template <class InputMesh>
  void copy_input(const InputMesh& input);
  void take_mesh(PR_star_octree::Indexed_tetrahedral_mesh<Point_3, Index>&& mesh);
  void set_labels_uniform_if_possible();
  void choose_storage(std::size_t nv, std::size_t nt);
  template <class ConcurrencyTag>
  void build_in_place();
  template <class ConcurrencyTag>
  std::vector<Index> build_vertices();
  template <class ConcurrencyTag, class TetrahedronSource>
  void build_streaming(const TetrahedronSource& source);
  template <class ConcurrencyTag>
  void to_float();
  template <class ConcurrencyTag>
  void split_vertices(std::vector<Index>& order);
  template <class ConcurrencyTag>
  void sort_and_orient_tetrahedra(const std::vector<Index>& from_original);
  template <class ConcurrencyTag>
  void build_leaf_lists();

  Geom_traits gt_;
  std::size_t bucket_size_;
  std::size_t max_depth_;
  bool keep_vertex_permutation_ = true;
  bool keep_tetrahedron_permutation_ = true;
  bool compact_ = false;
  std::size_t slab_tetrahedra_ = 0; // the streaming construction's slabs (0: the default)
  PR_star_octree::Coordinate_precision precision_ = PR_star_octree::Coordinate_precision::as_input;
  bool input_float32_ = false;     // the input said its coordinates are 32-bit floats
  bool float_coordinates_ = false; // `float_points_` holds V, `points_` is empty
  bool automatic_ = false;
  unsigned bucket_relations_ = PR_star_octree::default_bucket_size_relations;
  PR_star_octree::Bucket_size_choice choice_;
  std::size_t depth_ = 0;
  std::size_t depth_limited_leaves_ = 0;
  std::size_t coincident_leaves_ = 0;
  std::size_t degenerate_tetrahedra_ = 0;
  std::size_t reoriented_count_ = 0;
  bool has_scalar_ = false;
  std::array<double, 3> root_lo_{{0, 0, 0}}, root_hi_{{1, 1, 1}};

  std::vector<Point_3> points_;                    // V, unless float_coordinates_
  std::vector<std::array<float, 3>> float_points_; // V when float_coordinates_
  std::vector<double> scalars_;
  std::vector<int> labels_; // empty when every tetrahedron has `uniform_label_`
  int uniform_label_ = 0;
  bool has_labels_ = false;
  std::vector<Tetrahedron> tetrahedra_; // empty when compact_
  PR_star_octree::internal::Compact_tetrahedra<Index> compact_tetrahedra_;
  std::vector<Node> nodes_;
  std::vector<Node_index> leaves_;
  std::vector<std::uint16_t> leaf_offsets_;                                   // the shared lists, encoded
  std::vector<PR_star_octree::internal::Leaf_list_group<Index>> leaf_groups_; // and their groups
  std::vector<Index> vertex_to_original_;
  std::vector<Index> tetrahedron_to_original_;
  std::vector<std::uint64_t> reoriented_;
};

} // namespace CGAL

#include <CGAL/PR_star_octree/internal/PR_star_octree_3_impl.h>

#endif // CGAL_PR_STAR_OCTREE_H
