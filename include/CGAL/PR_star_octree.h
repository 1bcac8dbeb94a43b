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
#include <CGAL/PR_star_octree/internal/concept_checks.h>

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
/// The PR-star octree of a tetrahedral mesh (De Floriani, Fellegara, Magillo; paper Section 4).
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
  /// sorted by smallest vertex; they are not listed.  The others (smallest vertex in an earlier
  /// leaf) are listed in `shared_tetrahedra_array()[shared_begin, shared_end)`.  So the lists hold
  /// `(chi - 1) |T|` indices instead of `chi |T|`.
  struct Node {
    Index vertex_begin; ///< first vertex of the node (depth-first numbering)
    Index vertex_end;   ///< one past the last vertex of the node
    Index owned_begin;  ///< first tetrahedron owned by the leaf (empty range for internal nodes)
    Index owned_end;    ///< one past the last tetrahedron owned by the leaf
    Index shared_begin; ///< into `shared_tetrahedra_array()`: the leaf's other tetrahedra
    Index shared_end;
    Node_index first_child; ///< the eight children are contiguous; `no_node` for a leaf
    Node_index parent;      ///< `no_node` for the root
    bool is_leaf() const { return first_child == no_node; }
    std::size_t number_of_vertices() const { return vertex_end - vertex_begin; }
    /// the number of tetrahedra incident in the leaf's vertices (0 for internal nodes)
    std::size_t number_of_tetrahedra() const {
      return (owned_end - owned_begin) + (shared_end - shared_begin);
    }
  };

  /// A contiguous read-only range.
  template <class T>
  struct Range {
    const T* first;
    const T* last;
    const T* begin() const { return first; }
    const T* end() const { return last; }
    std::size_t size() const { return static_cast<std::size_t>(last - first); }
    bool empty() const { return first == last; }
    const T& operator[](std::size_t i) const { return first[i]; }
  };

  /// The tetrahedra of a leaf in increasing index order: the listed shared ones, then the owned
  /// range.  A random-access range of `Index` values.
  class Leaf_tetrahedra {
  public:
    class iterator {
    public:
      using iterator_category = std::random_access_iterator_tag;
      using value_type = Index;
      using difference_type = std::ptrdiff_t;
      using pointer = const Index*;
      using reference = Index;
      iterator() = default;
      iterator(const Leaf_tetrahedra* r, std::size_t i) : r_(r), i_(i) {}
      Index operator*() const { return (*r_)[i_]; }
      Index operator[](difference_type d) const { return (*r_)[i_ + d]; }
      iterator& operator++() {
        ++i_;
        return *this;
      }
      iterator operator++(int) {
        iterator c = *this;
        ++i_;
        return c;
      }
      iterator& operator--() {
        --i_;
        return *this;
      }
      iterator& operator+=(difference_type d) {
        i_ += d;
        return *this;
      }
      iterator& operator-=(difference_type d) {
        i_ -= d;
        return *this;
      }
      friend iterator operator+(iterator a, difference_type d) { return a += d; }
      friend iterator operator-(iterator a, difference_type d) { return a -= d; }
      friend difference_type operator-(const iterator& a, const iterator& b) {
        return static_cast<difference_type>(a.i_) - static_cast<difference_type>(b.i_);
      }
      friend bool operator==(const iterator& a, const iterator& b) { return a.i_ == b.i_; }
      friend bool operator!=(const iterator& a, const iterator& b) { return a.i_ != b.i_; }
      friend bool operator<(const iterator& a, const iterator& b) { return a.i_ < b.i_; }

    private:
      const Leaf_tetrahedra* r_ = nullptr;
      std::size_t i_ = 0;
    };

    Leaf_tetrahedra(const Index* shared, std::size_t n_shared, Index owned_begin, Index owned_end)
        : shared_(shared), n_shared_(n_shared), owned_begin_(owned_begin),
          size_(n_shared + (owned_end - owned_begin)) {}
    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    Index operator[](std::size_t i) const {
      return i < n_shared_ ? shared_[i] : static_cast<Index>(owned_begin_ + (i - n_shared_));
    }
    iterator begin() const { return iterator(this, 0); }
    iterator end() const { return iterator(this, size_); }
    /// the listed (shared) part
    Range<Index> shared() const { return {shared_, shared_ + n_shared_}; }
    /// the owned part: the tetrahedra `[first, second)` of `T`
    std::pair<Index, Index> owned() const {
      return {owned_begin_, static_cast<Index>(owned_begin_ + (size_ - n_shared_))};
    }

  private:
    const Index* shared_;
    std::size_t n_shared_;
    Index owned_begin_;
    std::size_t size_;
  };
  /// @}

  static constexpr Node_index no_node = (std::numeric_limits<Index>::max)();
  /// `k_v = infinity`: a single leaf, the global baseline
  static constexpr std::size_t infinite_bucket_size = (std::numeric_limits<std::size_t>::max)();
  static constexpr std::size_t default_bucket_size = 50;
  static constexpr std::size_t default_max_depth = 32;

  /// \name Creation
  /// @{

  /// Builds the PR-star octree of `input`, a model of `PRStarOctreeInputMesh`
  /// (see `CGAL::PR_star_octree::make_input()`).
  ///
  /// \param bucket_size the bucket threshold `k_v` (at least 1), or `infinite_bucket_size`
  /// \param max_depth the depth bound that stops splitting (duplicate or extremely close points)
  ///
  /// \throws std::invalid_argument if a tetrahedron has a vertex index out of range or twice, or if
  ///         the mesh does not fit in `IndexType`, or on a non-finite coordinate, or `bucket_size == 0`.
  template <class InputMesh>
  explicit PR_star_octree_3(const InputMesh& input, std::size_t bucket_size = default_bucket_size,
                            std::size_t max_depth = default_max_depth, const Geom_traits& gt = Geom_traits())
      : gt_(gt), bucket_size_(bucket_size), max_depth_(max_depth) {
    static_assert(PR_star_octree::internal::Check_input_mesh<InputMesh>::value, "");
    if (bucket_size_ == 0)
      throw std::invalid_argument("PR_star_octree_3: the bucket size k_v must be at least 1");
    build(input);
  }
  /// @}

  /// \name The mesh (new numbering)
  /// @{
  std::size_t number_of_vertices() const { return points_.size(); }
  std::size_t number_of_tetrahedra() const { return tetrahedra_.size(); }
  const std::vector<Point_3>& points() const { return points_; }
  const Point_3& point(Index v) const { return points_[v]; }
  const std::vector<Tetrahedron>& tetrahedra() const { return tetrahedra_; }
  const Tetrahedron& tetrahedron(Index t) const { return tetrahedra_[t]; }
  bool has_scalar_field() const { return has_scalar_; }
  /// one value per vertex (new numbering), or empty
  const std::vector<double>& scalars() const { return scalars_; }
  double scalar(Index v) const { return scalars_[v]; }
  const Geom_traits& geom_traits() const { return gt_; }
  /// @}

  /// \name The octree
  /// @{
  std::size_t bucket_size() const { return bucket_size_; }
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
  /// the tetrahedra incident in the vertices of leaf `n` (its star), in increasing index order
  Leaf_tetrahedra leaf_tetrahedra(Node_index n) const {
    const Node& nd = nodes_[n];
    return Leaf_tetrahedra(leaf_tetrahedra_.data() + nd.shared_begin, nd.shared_end - nd.shared_begin,
                           nd.owned_begin, nd.owned_end);
  }
  /// the concatenation of the listed (shared) parts of all leaves: `(chi - 1) |T|` indices
  const std::vector<Index>& shared_tetrahedra_array() const { return leaf_tetrahedra_; }
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
    for (auto it = path.rbegin(); it != path.rend(); ++it)
      for (int a = 0; a < 3; ++a) {
        const double mid = midpoint(lo[a], hi[a]);
        if ((*it >> a) & 1u)
          lo[a] = mid;
        else
          hi[a] = mid;
      }
    return Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
  }
  /// the leaf whose box contains `p` (descends from the root; `p` outside the root box is clamped)
  Node_index locate(const Point_3& p) const {
    const std::array<double, 3> c = coordinates(p);
    std::array<double, 3> lo = root_lo_, hi = root_hi_;
    Node_index n = root();
    while (!nodes_[n].is_leaf()) {
      unsigned code = 0;
      for (int a = 0; a < 3; ++a) {
        const double mid = midpoint(lo[a], hi[a]);
        if (c[a] >= mid) {
          code |= 1u << a;
          lo[a] = mid;
        } else
          hi[a] = mid;
      }
      n = nodes_[n].first_child + code;
    }
    return n;
  }
  /// @}

  /// \name Back to the user's numbering
  /// @{
  /// the original index of vertex `v`
  Index original_vertex(Index v) const { return vertex_to_original_[v]; }
  /// the original index of tetrahedron `t`
  Index original_tetrahedron(Index t) const { return tetrahedron_to_original_[t]; }
  /// new -> original vertex indices (a permutation of `[0, |V|)`)
  const std::vector<Index>& vertex_permutation() const { return vertex_to_original_; }
  /// new -> original tetrahedron indices
  const std::vector<Index>& tetrahedron_permutation() const { return tetrahedron_to_original_; }
  /// whether tetrahedron `t` was negatively oriented as the user listed it
  bool is_reoriented(Index t) const { return (reoriented_[t >> 6] >> (t & 63)) & 1u; }
  /// tetrahedron `t` as the user gave it: original vertex indices, original vertex order
  std::array<Index, 4> original_tetrahedron_vertices(Index t) const {
    Tetrahedron c = tetrahedra_[t];
    if (is_reoriented(t)) std::swap(c[2], c[3]);
    for (Index& v : c) v = vertex_to_original_[v];
    return c;
  }
  /// original -> new vertex indices (computed, `O(|V|)`)
  std::vector<Index> vertex_from_original() const { return inverse(vertex_to_original_); }
  /// original -> new tetrahedron indices (computed, `O(|T|)`)
  std::vector<Index> tetrahedron_from_original() const { return inverse(tetrahedron_to_original_); }
  /// @}

  /// \name Statistics
  /// @{
  /// the storage statistics of paper Table 1 and the bytes used (see `PR_star_octree::Statistics`)
  Statistics statistics() const;
  /// @}

private:
  static double midpoint(double lo, double hi) { return lo + (hi - lo) * 0.5; }

  template <class P>
  static std::array<double, 3> coordinates(const P& p) {
    return {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  }

  template <class P>
  static Point_3 convert_point(const P& p) {
    if constexpr (std::is_convertible<P, Point_3>::value)
      return Point_3(p);
    else
      return Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }

  static std::vector<Index> inverse(const std::vector<Index>& perm) {
    std::vector<Index> inv(perm.size());
    for (std::size_t i = 0; i < perm.size(); ++i) inv[perm[i]] = static_cast<Index>(i);
    return inv;
  }

  template <class InputMesh>
  void build(const InputMesh& input);
  void split_vertices(const std::vector<std::array<double, 3>>& xyz, std::vector<Index>& order);
  template <class InputMesh>
  void build_tetrahedra(const InputMesh& input, const std::vector<Index>& vertex_from_original);
  void build_leaf_lists();

  Geom_traits gt_;
  std::size_t bucket_size_;
  std::size_t max_depth_;
  std::size_t depth_ = 0;
  std::size_t depth_limited_leaves_ = 0;
  std::size_t coincident_leaves_ = 0;
  std::size_t degenerate_tetrahedra_ = 0;
  std::size_t reoriented_count_ = 0;
  bool has_scalar_ = false;
  std::array<double, 3> root_lo_{{0, 0, 0}}, root_hi_{{1, 1, 1}};

  std::vector<Point_3> points_;
  std::vector<double> scalars_;
  std::vector<Tetrahedron> tetrahedra_;
  std::vector<Node> nodes_;
  std::vector<Node_index> leaves_;
  std::vector<Index> leaf_tetrahedra_;
  std::vector<Index> vertex_to_original_;
  std::vector<Index> tetrahedron_to_original_;
  std::vector<std::uint64_t> reoriented_;
};

// ---------------------------------------------------------------------------------------------
// Construction
// ---------------------------------------------------------------------------------------------

template <class GT, class I>
template <class InputMesh>
void PR_star_octree_3<GT, I>::build(const InputMesh& input) {
  const std::size_t nv = input.number_of_vertices();
  const std::size_t nt = input.number_of_tetrahedra();
  const std::size_t index_max = static_cast<std::size_t>(no_node) - 1;
  if (nv > index_max || nt > index_max || 4 * nt > index_max)
    throw std::invalid_argument("PR_star_octree_3: the mesh (" + std::to_string(nv) + " vertices, " +
                                std::to_string(nt) + " tetrahedra) does not fit the " +
                                std::to_string(8 * sizeof(I)) + "-bit index type");

  // 1. Coordinates and bounding cube.
  std::vector<std::array<double, 3>> xyz(nv);
  std::array<double, 3> lo{{0, 0, 0}}, hi{{0, 0, 0}};
  for (std::size_t i = 0; i < nv; ++i) {
    xyz[i] = coordinates(input.point(i));
    for (int a = 0; a < 3; ++a) {
      if (!std::isfinite(xyz[i][a]))
        throw std::invalid_argument("PR_star_octree_3: vertex " + std::to_string(i) +
                                    " has a non-finite coordinate");
      if (i == 0 || xyz[i][a] < lo[a]) lo[a] = xyz[i][a];
      if (i == 0 || xyz[i][a] > hi[a]) hi[a] = xyz[i][a];
    }
  }
  double side = (std::max)({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  if (!(side > 0)) side = 1.; // empty mesh, a single point or all points coincident
  for (int a = 0; a < 3; ++a) {
    root_lo_[a] = lo[a];
    root_hi_[a] = lo[a] + side;
    if (root_hi_[a] < hi[a]) root_hi_[a] = hi[a]; // rounding: the cube must contain every point
  }

  // 2. PR split of the vertices, depth first: `order[new] = original`.
  std::vector<Index> order(nv);
  std::iota(order.begin(), order.end(), Index(0));
  split_vertices(xyz, order);
  xyz.clear();
  xyz.shrink_to_fit();

  // 3. Re-indexed vertex array.
  points_.reserve(nv);
  for (std::size_t i = 0; i < nv; ++i) points_.push_back(convert_point(input.point(order[i])));
  if (input.has_scalar_field()) {
    has_scalar_ = true;
    scalars_.resize(nv);
    for (std::size_t i = 0; i < nv; ++i) scalars_[i] = static_cast<double>(input.scalar(order[i]));
  }
  vertex_to_original_ = order;
  std::vector<Index> from_original = inverse(order);

  // 4. Re-indexed, oriented tetrahedra and the leaf lists.
  build_tetrahedra(input, from_original);
  build_leaf_lists();
}

template <class GT, class I>
void PR_star_octree_3<GT, I>::split_vertices(const std::vector<std::array<double, 3>>& xyz,
                                             std::vector<Index>& order) {
  struct Item {
    Node_index node;
    std::array<double, 3> lo, hi;
    std::size_t depth;
  };
  const std::size_t nv = order.size();
  nodes_.clear();
  leaves_.clear();
  nodes_.push_back(Node{0, static_cast<Index>(nv), 0, 0, 0, 0, no_node, no_node});
  std::vector<Item> stack{Item{0, root_lo_, root_hi_, 0}};
  std::vector<Index> buffer;
  std::vector<unsigned char> code;

  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    const Index b = nodes_[item.node].vertex_begin, e = nodes_[item.node].vertex_end;
    const std::size_t count = e - b;
    bool split = count > bucket_size_;
    if (split && item.depth >= max_depth_) {
      split = false;
      ++depth_limited_leaves_;
    }
    if (split) { // points that all coincide can never be separated: stop and report
      const std::array<double, 3>& p0 = xyz[order[b]];
      bool all_same = true;
      for (Index i = b + 1; i < e && all_same; ++i) all_same = (xyz[order[i]] == p0);
      if (all_same) {
        split = false;
        ++coincident_leaves_;
      }
    }
    if (!split) {
      leaves_.push_back(item.node);
      depth_ = (std::max)(depth_, item.depth);
      continue;
    }

    // Stable counting sort of [b, e) by octant: bit a set when coordinate a >= midpoint.
    std::array<double, 3> mid;
    for (int a = 0; a < 3; ++a) mid[a] = midpoint(item.lo[a], item.hi[a]);
    code.resize(count);
    std::array<std::size_t, 9> start{};
    for (std::size_t i = 0; i < count; ++i) {
      const std::array<double, 3>& p = xyz[order[b + i]];
      const unsigned c =
          unsigned(p[0] >= mid[0]) | (unsigned(p[1] >= mid[1]) << 1) | (unsigned(p[2] >= mid[2]) << 2);
      code[i] = static_cast<unsigned char>(c);
      ++start[c + 1];
    }
    for (int c = 0; c < 8; ++c) start[c + 1] += start[c];
    buffer.resize(count);
    std::array<std::size_t, 8> pos;
    std::copy(start.begin(), start.begin() + 8, pos.begin());
    for (std::size_t i = 0; i < count; ++i) buffer[pos[code[i]]++] = order[b + i];
    std::copy(buffer.begin(), buffer.end(), order.begin() + b);

    const Node_index first = static_cast<Node_index>(nodes_.size());
    if (static_cast<std::size_t>(first) + 8 >= static_cast<std::size_t>(no_node))
      throw std::invalid_argument("PR_star_octree_3: too many octree nodes for the index type");
    nodes_[item.node].first_child = first;
    for (unsigned c = 0; c < 8; ++c)
      nodes_.push_back(Node{static_cast<Index>(b + start[c]), static_cast<Index>(b + start[c + 1]), 0, 0, 0,
                            0, no_node, item.node});
    // Push the children in reverse so that child 0 is visited first: leaves come out depth first.
    for (unsigned c = 8; c-- > 0;) {
      Item child{static_cast<Node_index>(first + c), item.lo, item.hi, item.depth + 1};
      for (int a = 0; a < 3; ++a) {
        if ((c >> a) & 1u)
          child.lo[a] = mid[a];
        else
          child.hi[a] = mid[a];
      }
      stack.push_back(child);
    }
  }
}

template <class GT, class I>
template <class InputMesh>
void PR_star_octree_3<GT, I>::build_tetrahedra(const InputMesh& input,
                                               const std::vector<Index>& from_original) {
  const std::size_t nv = points_.size();
  const std::size_t nt = input.number_of_tetrahedra();

  // Validate and find the smallest vertex of each tetrahedron in the new numbering (the sort key).
  // The input is read twice rather than remapped into a temporary copy of T: the peak memory of
  // the construction stays at one T (ours) plus one index per tetrahedron.
  auto remap = [&](std::size_t t) {
    const auto c = input.tetrahedron(t);
    Tetrahedron r;
    for (int k = 0; k < 4; ++k) {
      const auto v = c[k];
      if (!(v >= 0) || static_cast<std::size_t>(v) >= nv)
        throw std::invalid_argument("PR_star_octree_3: tetrahedron " + std::to_string(t) +
                                    " has vertex index " + std::to_string(v) + " out of range [0, " +
                                    std::to_string(nv) + ")");
      // (the check above also rejects negative indices of a signed index type)
      r[k] = from_original[static_cast<std::size_t>(v)];
    }
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        if (r[i] == r[j])
          throw std::invalid_argument("PR_star_octree_3: tetrahedron " + std::to_string(t) +
                                      " lists vertex " + std::to_string(c[i]) + " twice");
    return r;
  };
  std::vector<Index> key(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const Tetrahedron r = remap(t);
    key[t] = *std::min_element(r.begin(), r.end());
  }

  // Locality: counting sort by smallest vertex (stable, so the result is deterministic).
  std::vector<Index> start(nv + 1, 0);
  for (Index k : key) ++start[k + 1];
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  tetrahedron_to_original_.assign(nt, 0);
  for (std::size_t t = 0; t < nt; ++t) tetrahedron_to_original_[start[key[t]]++] = static_cast<Index>(t);
  std::vector<Index>().swap(key);
  std::vector<Index>().swap(start);

  // Positive orientation with the exact predicate.
  tetrahedra_.resize(nt);
  reoriented_.assign((nt + 63) / 64, 0);
  auto orientation = gt_.orientation_3_object();
  for (std::size_t t = 0; t < nt; ++t) {
    Tetrahedron c = remap(tetrahedron_to_original_[t]);
    const CGAL::Orientation o = orientation(points_[c[0]], points_[c[1]], points_[c[2]], points_[c[3]]);
    if (o == CGAL::NEGATIVE) {
      std::swap(c[2], c[3]);
      reoriented_[t >> 6] |= std::uint64_t(1) << (t & 63);
      ++reoriented_count_;
    } else if (o == CGAL::COPLANAR)
      ++degenerate_tetrahedra_;
    tetrahedra_[t] = c;
  }
}

template <class GT, class I>
void PR_star_octree_3<GT, I>::build_leaf_lists() {
  const std::size_t nv = points_.size();
  const std::size_t nl = leaves_.size();
  std::vector<Index> leaf_of(nv); // position of the leaf in `leaves_`
  for (std::size_t l = 0; l < nl; ++l) {
    const Node& nd = nodes_[leaves_[l]];
    std::fill(leaf_of.begin() + nd.vertex_begin, leaf_of.begin() + nd.vertex_end, static_cast<Index>(l));
  }
  // The distinct leaves of a tetrahedron, in increasing order.
  auto distinct_leaves = [&](const Tetrahedron& c, std::array<Index, 4>& out) {
    std::array<Index, 4> l{{leaf_of[c[0]], leaf_of[c[1]], leaf_of[c[2]], leaf_of[c[3]]}};
    std::sort(l.begin(), l.end());
    int k = 0;
    for (int i = 0; i < 4; ++i)
      if (i == 0 || l[i] != l[i - 1]) out[k++] = l[i];
    return k;
  };
  // The owner of a tetrahedron is the leaf of its smallest vertex, i.e. its first distinct leaf:
  // as T is sorted by smallest vertex, each leaf owns a contiguous range of T.  The other leaves
  // list it explicitly.
  std::vector<std::size_t> owned(nl + 1, 0), shared(nl + 1, 0);
  std::array<Index, 4> ls;
  for (const Tetrahedron& c : tetrahedra_) {
    const int k = distinct_leaves(c, ls);
    ++owned[ls[0] + 1];
    for (int i = 1; i < k; ++i) ++shared[ls[i] + 1];
  }
  for (std::size_t l = 0; l < nl; ++l) {
    owned[l + 1] += owned[l];
    shared[l + 1] += shared[l];
  }
  if (shared[nl] >= static_cast<std::size_t>(no_node))
    throw std::invalid_argument("PR_star_octree_3: the leaf lists do not fit the index type");
  leaf_tetrahedra_.assign(shared[nl], 0);
  for (std::size_t l = 0; l < nl; ++l) {
    Node& nd = nodes_[leaves_[l]];
    nd.owned_begin = static_cast<Index>(owned[l]);
    nd.owned_end = static_cast<Index>(owned[l + 1]);
    nd.shared_begin = static_cast<Index>(shared[l]);
    nd.shared_end = static_cast<Index>(shared[l + 1]);
  }
  for (std::size_t t = 0; t < tetrahedra_.size(); ++t) {
    const int k = distinct_leaves(tetrahedra_[t], ls);
    CGAL_assertion(t >= nodes_[leaves_[ls[0]]].owned_begin && t < nodes_[leaves_[ls[0]]].owned_end);
    for (int i = 1; i < k; ++i) leaf_tetrahedra_[shared[ls[i]]++] = static_cast<Index>(t);
  }
}

// ---------------------------------------------------------------------------------------------
// Statistics
// ---------------------------------------------------------------------------------------------

template <class GT, class I>
typename PR_star_octree_3<GT, I>::Statistics PR_star_octree_3<GT, I>::statistics() const {
  Statistics s;
  s.vertices = points_.size();
  s.tetrahedra = tetrahedra_.size();
  s.bucket_size = bucket_size_;
  s.infinite_bucket_size = (bucket_size_ == infinite_bucket_size);
  s.max_depth = max_depth_;
  s.nodes = nodes_.size();
  s.leaves = leaves_.size();
  s.depth = depth_;
  s.depth_limited_leaves = depth_limited_leaves_;
  s.coincident_leaves = coincident_leaves_;
  s.reoriented_tetrahedra = reoriented_count_;
  s.degenerate_tetrahedra = degenerate_tetrahedra_;
  s.leaf_tetrahedra_entries = leaf_tetrahedra_.size() + tetrahedra_.size();
  for (Node_index n : leaves_) {
    const Node& nd = nodes_[n];
    if (nd.vertex_begin == nd.vertex_end) ++s.empty_leaves;
    s.max_leaf_vertices = (std::max)(s.max_leaf_vertices, nd.number_of_vertices());
    s.max_leaf_tetrahedra = (std::max)(s.max_leaf_tetrahedra, nd.number_of_tetrahedra());
  }

  // Unreferenced and duplicate vertices (coincident points always share a leaf).
  std::vector<bool> referenced(points_.size(), false);
  for (const Tetrahedron& c : tetrahedra_)
    for (Index v : c) referenced[v] = true;
  s.unreferenced_vertices = static_cast<std::size_t>(std::count(referenced.begin(), referenced.end(), false));
  std::vector<std::array<double, 3>> xyz;
  for (Node_index n : leaves_) {
    const Node& nd = nodes_[n];
    xyz.clear();
    for (Index v = nd.vertex_begin; v < nd.vertex_end; ++v) xyz.push_back(coordinates(points_[v]));
    std::sort(xyz.begin(), xyz.end());
    for (std::size_t i = 1; i < xyz.size(); ++i)
      if (xyz[i] == xyz[i - 1]) ++s.duplicate_vertices;
  }

  s.compute_cost_model();

  s.bytes.points = points_.capacity() * sizeof(Point_3);
  s.bytes.scalars = scalars_.capacity() * sizeof(double);
  s.bytes.tetrahedra = tetrahedra_.capacity() * sizeof(Tetrahedron);
  s.bytes.nodes = nodes_.capacity() * sizeof(Node) + leaves_.capacity() * sizeof(Node_index);
  s.bytes.leaf_tetrahedra = leaf_tetrahedra_.capacity() * sizeof(Index);
  s.bytes.permutations =
      (vertex_to_original_.capacity() + tetrahedron_to_original_.capacity()) * sizeof(Index) +
      reoriented_.capacity() * sizeof(std::uint64_t);
  return s;
}

} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_H
