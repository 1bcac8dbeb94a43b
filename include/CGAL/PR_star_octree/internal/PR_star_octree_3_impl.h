// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_PR_STAR_OCTREE_3_IMPL_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_PR_STAR_OCTREE_3_IMPL_H

// The construction and the statistics of `CGAL::PR_star_octree_3` (included by PR_star_octree.h).

#include <CGAL/PR_star_octree.h>

namespace CGAL {

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
    xyz[i] = coordinates(convert_point(input.point(i)));
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

  // The labels, in the new numbering.
  if constexpr (PR_star_octree::internal::has_tetrahedron_labels<InputMesh>::value) {
    if (input.has_tetrahedron_labels()) {
      has_labels_ = true;
      bool uniform = true;
      const int first = nt ? static_cast<int>(input.tetrahedron_label(0)) : 0;
      for (std::size_t t = 1; t < nt && uniform; ++t)
        uniform = static_cast<int>(input.tetrahedron_label(t)) == first;
      if (uniform) // one subdomain: one value, not |T|
        uniform_label_ = first;
      else {
        labels_.resize(nt);
        for (std::size_t t = 0; t < nt; ++t)
          labels_[t] = input.tetrahedron_label(tetrahedron_to_original_[t]);
      }
    }
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
  s.bytes.labels = labels_.capacity() * sizeof(int);
  for (int l : labels_) ++s.subdomains[l];
  if (has_labels_ && labels_.empty() && !tetrahedra_.empty())
    s.subdomains[uniform_label_] = tetrahedra_.size();
  s.bytes.tetrahedra = tetrahedra_.capacity() * sizeof(Tetrahedron);
  s.bytes.nodes = nodes_.capacity() * sizeof(Node) + leaves_.capacity() * sizeof(Node_index);
  s.bytes.leaf_tetrahedra = leaf_tetrahedra_.capacity() * sizeof(Index);
  s.bytes.permutations =
      (vertex_to_original_.capacity() + tetrahedron_to_original_.capacity()) * sizeof(Index) +
      reoriented_.capacity() * sizeof(std::uint64_t);
  return s;
}

} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_PR_STAR_OCTREE_3_IMPL_H
