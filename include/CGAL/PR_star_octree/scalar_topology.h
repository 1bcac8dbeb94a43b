// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_SCALAR_TOPOLOGY_H
#define CGAL_PR_STAR_OCTREE_SCALAR_TOPOLOGY_H

/// \file scalar_topology.h
/// The topology of a scalar field sampled at the vertices: critical points of the
/// piecewise-linear field, the discrete (Forman) gradient of the lower stars, the Morse complexes
/// and the persistence pairs of the extrema, each computed leaf by leaf.

#include <CGAL/PR_star_octree/Leaf_executor.h>
#include <CGAL/PR_star_octree/distortion.h>
#include <CGAL/PR_star_octree/internal/lower_star.h>
#include <CGAL/PR_star_octree/parameters.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {

/// \ingroup PkgPRStarOctreeRef
/// The kind of a vertex of a piecewise-linear scalar field, from the numbers of connected
/// components of its lower and upper links (`classify_critical_point()`).  The numeric values are
/// those of TTK's `CriticalType` (0 minimum ... 5 regular), so that arrays written by the package
/// read as TTK's in ParaView.
enum class Critical_type : std::uint8_t {
  MINIMUM = 0,    ///< empty lower link
  SADDLE_1 = 1,   ///< two lower components, one upper (a join saddle)
  SADDLE_2 = 2,   ///< one lower component, two upper (a split saddle)
  MAXIMUM = 3,    ///< empty upper link
  DEGENERATE = 4, ///< any other count: monkey saddles and vertices that are both join and split
  REGULAR = 5     ///< one lower and one upper component (and unreferenced vertices)
};

/// \ingroup PkgPRStarOctreeRef
/// The name of a critical type: "minimum", "1-saddle", "2-saddle", "maximum", "degenerate", "regular".
inline const char* critical_type_name(Critical_type t) {
  switch (t) {
  case Critical_type::MINIMUM:
    return "minimum";
  case Critical_type::SADDLE_1:
    return "1-saddle";
  case Critical_type::SADDLE_2:
    return "2-saddle";
  case Critical_type::MAXIMUM:
    return "maximum";
  case Critical_type::DEGENERATE:
    return "degenerate";
  default:
    return "regular";
  }
}

/// \ingroup PkgPRStarOctreeRef
/// The critical type of a vertex whose lower link has `lower` connected components and whose
/// upper link has `upper`.  The link is taken as it is: the sphere around an interior vertex, the
/// disc around a boundary vertex (the convention of TTK's `ScalarFieldCriticalPoints`), so that a
/// boundary vertex is an extremum when the field decreases (increases) along all its edges, and a
/// saddle when its lower or upper half-disc splits.
inline Critical_type classify_critical_point(unsigned lower, unsigned upper) {
  if (lower == 0 && upper == 0) return Critical_type::REGULAR; // unreferenced
  if (lower == 0) return Critical_type::MINIMUM;
  if (upper == 0) return Critical_type::MAXIMUM;
  if (lower == 1 && upper == 1) return Critical_type::REGULAR;
  if (lower == 2 && upper == 1) return Critical_type::SADDLE_1;
  if (lower == 1 && upper == 2) return Critical_type::SADDLE_2;
  return Critical_type::DEGENERATE;
}

/// \ingroup PkgPRStarOctreeRef
/// A vertex that is not regular.
struct Critical_point {
  std::size_t vertex = 0; ///< the user's vertex index
  Critical_type type = Critical_type::REGULAR;
  unsigned lower_components = 0; ///< connected components of the lower link
  unsigned upper_components = 0; ///< connected components of the upper link
  double value = 0;              ///< the field at the vertex
  /// whether its link is not a closed surface (a vertex on the boundary of the mesh, or non-manifold)
  bool on_boundary = false;
  /// the multiplicity of a saddle: `lower - 1` merges of the sublevel sets plus `upper - 1` splits of
  /// the superlevel sets (1 for a simple saddle, 0 for an extremum)
  unsigned multiplicity() const {
    return (lower_components > 1 ? lower_components - 1 : 0) +
           (upper_components > 1 ? upper_components - 1 : 0);
  }
};

/// \ingroup PkgPRStarOctreeRef
/// The numbers of vertices of each critical type.
struct Critical_point_counts {
  std::size_t minima = 0, saddles_1 = 0, saddles_2 = 0, maxima = 0, degenerate = 0, regular = 0;
  std::size_t unreferenced = 0; ///< vertices in no tetrahedron (counted apart from `regular`)
  /// the sum of the multiplicities of the join saddles (`lower - 1`) and of the split saddles (`upper - 1`)
  std::size_t join_multiplicity = 0, split_multiplicity = 0;
  void add(unsigned lower, unsigned upper) {
    if (lower == 0 && upper == 0) {
      ++unreferenced;
      return;
    }
    switch (classify_critical_point(lower, upper)) {
    case Critical_type::MINIMUM:
      ++minima;
      break;
    case Critical_type::SADDLE_1:
      ++saddles_1;
      break;
    case Critical_type::SADDLE_2:
      ++saddles_2;
      break;
    case Critical_type::MAXIMUM:
      ++maxima;
      break;
    case Critical_type::DEGENERATE:
      ++degenerate;
      break;
    default:
      ++regular;
    }
    if (lower > 1) join_multiplicity += lower - 1;
    if (upper > 1) split_multiplicity += upper - 1;
  }
};

/// \ingroup PkgPRStarOctreeRef
/// A critical simplex of a discrete gradient.
struct Critical_simplex {
  int dimension = 0; ///< 0 vertex, 1 edge, 2 triangle, 3 tetrahedron
  /// the user's indices of its vertices, the highest in the field order first (the vertex whose
  /// lower star holds it), then by decreasing order; the unused ones `no_vertex`
  std::array<std::size_t, 4> vertices{{no_vertex, no_vertex, no_vertex, no_vertex}};
  double value = 0; ///< the field at its highest vertex
  static constexpr std::size_t no_vertex = (std::numeric_limits<std::size_t>::max)();
};

/// \ingroup PkgPRStarOctreeRef
/// A persistence pair of the extrema: a minimum with the 1-saddle where its component of the
/// sublevel sets merges into an older one, or a maximum with the 2-saddle where its component of
/// the superlevel sets merges into a higher one (the elder rule).  Essential pairs (the lowest
/// minimum and the highest maximum of each connected component) have no saddle.
struct Persistence_pair {
  enum Type { MINIMUM_SADDLE = 0, SADDLE_MAXIMUM = 1 };
  Type type = MINIMUM_SADDLE;
  std::size_t extremum = 0; ///< the user's index of the minimum or maximum
  std::size_t saddle =
      Critical_simplex::no_vertex; ///< the user's index of the saddle; `no_vertex` if essential
  double extremum_value = 0, saddle_value = 0;
  bool is_essential() const { return saddle == Critical_simplex::no_vertex; }
  /// `|saddle - extremum|`, infinite for an essential pair
  double persistence() const {
    return is_essential()
               ? std::numeric_limits<double>::infinity()
               : (type == MINIMUM_SADDLE ? saddle_value - extremum_value : extremum_value - saddle_value);
  }
  /// the diagram's coordinates: (minimum, saddle) or (saddle, maximum); infinite for an essential pair
  double birth() const {
    return type == MINIMUM_SADDLE
               ? extremum_value
               : (is_essential() ? -std::numeric_limits<double>::infinity() : saddle_value);
  }
  double death() const {
    return type == MINIMUM_SADDLE ? (is_essential() ? std::numeric_limits<double>::infinity() : saddle_value)
                                  : extremum_value;
  }
};

/// \ingroup PkgPRStarOctreeRef
/// A discrete (Forman) gradient of a scalar field on the mesh of an octree, built by
/// `compute_forman_gradient()`: for each simplex, the simplex it is paired with (one dimension up
/// or down), or nothing for a critical simplex.
///
/// It is stored as one byte per corner of each tetrahedron, 4 bytes per tetrahedron: the byte of
/// corner `i` of tetrahedron `t` (`corner_code(t, i)`, positions as in `octree.tetrahedron(t)`)
/// holds the pairs between simplices of `t` whose highest vertex is that corner: bits 0-1 the edge
/// of `t` the vertex is paired with (0 none, 1-3 the other corner, the positions other than `i` in
/// increasing order), then 2 bits for each of the three triangles of `t` through the corner (the
/// triangles opposite the other positions in increasing order): 0 not paired within `t` from that
/// corner, 1 or 2 paired with its edge to the first or second of its other two corners, 3 paired with
/// `t`.  Each byte is written by the one leaf holding its corner's vertex: no two leaves share it.
template <class Octree>
class Forman_gradient {
public:
  using Index = typename Octree::Index;

  Forman_gradient() = default;

  /// the byte of corner `i` of tetrahedron `t` (see the class description)
  std::uint8_t corner_code(Index t, int i) const { return codes_[4 * static_cast<std::size_t>(t) + i]; }
  /// the critical simplices, by dimension, each dimension in increasing order of the field (the
  /// lexicographic order of their vertices' decreasing values)
  const std::vector<Critical_simplex>& critical_simplices() const { return critical_; }
  /// the number of critical simplices of dimension `d`
  std::size_t number_of_critical_simplices(int d) const { return counts_[static_cast<std::size_t>(d)]; }
  /// `c0 - c1 + c2 - c3`, the Euler characteristic of the mesh for a gradient
  long long alternating_sum() const {
    return static_cast<long long>(counts_[0]) - static_cast<long long>(counts_[1]) +
           static_cast<long long>(counts_[2]) - static_cast<long long>(counts_[3]);
  }
  /// `V - E + F - T` of the mesh, counted in the same pass as the gradient but apart from it (each
  /// simplex at its smallest vertex in the octree's numbering, not in the field order)
  long long euler_characteristic() const { return euler_; }
  /// the bytes of the pairs (4 per tetrahedron), not counting the list of critical simplices
  std::size_t memory_bytes() const { return codes_.capacity(); }
  /// `memory_bytes()` per tetrahedron: 4
  double bytes_per_tetrahedron() const {
    return codes_.empty() ? 0.0 : static_cast<double>(codes_.size()) / static_cast<double>(codes_.size() / 4);
  }

  /// \cond SKIP_IN_MANUAL
  std::vector<std::uint8_t> codes_;
  std::vector<Critical_simplex> critical_;
  std::array<std::size_t, 4> counts_{{0, 0, 0, 0}};
  long long euler_ = 0;
  /// \endcond
};

/// \ingroup PkgPRStarOctreeRef
/// A polyline of the Morse-Smale 1-skeleton: a gradient path from a saddle to an extremum.
struct Morse_arc {
  /// 1: from a critical edge (1-saddle) down to a minimum, through vertices; 2: from a critical
  /// triangle (2-saddle) up to a maximum, through the barycentres of tetrahedra
  int saddle_dimension = 1;
  std::size_t saddle = 0; ///< the position of the saddle in `Forman_gradient::critical_simplices()`
  /// the user's index of the extremum's vertex (for a maximum: the highest vertex of its critical
  /// tetrahedron), `no_vertex` when the path leaves the domain through its boundary
  std::size_t extremum = Critical_simplex::no_vertex;
  std::vector<std::array<double, 3>> points; ///< from the saddle's barycentre to the extremum
};

/// \ingroup PkgPRStarOctreeRef
/// The Morse complexes of a scalar field, from `compute_morse_complexes()`.
template <class Octree>
struct Morse_complexes {
  using Index = typename Octree::Index;
  static constexpr std::size_t no_cell = Critical_simplex::no_vertex;

  Forman_gradient<Octree> gradient;      ///< the discrete gradient they follow
  Critical_point_counts critical_points; ///< the piecewise-linear critical points
  /// per vertex (the user's numbering): its critical type
  std::vector<Critical_type> critical_type;
  /// per vertex (the user's numbering): the user's index of the minimum whose ascending 3-cell holds
  /// it (after the cancellations below the threshold), `no_cell` for an unreferenced vertex
  std::vector<std::size_t> ascending_cell;
  /// per tetrahedron (the user's numbering, or the octree's without a tetrahedron permutation): the
  /// user's index of the maximum whose descending 3-cell holds it (the highest vertex of its
  /// critical tetrahedron, after the cancellations), `no_cell` when its gradient path leaves the
  /// domain through the boundary (the cell of a maximum on the boundary) or through a non-manifold
  /// triangle
  std::vector<std::size_t> descending_cell;
  /// the persistence pairs, minimum-saddle pairs first, each kind by increasing extremum order
  std::vector<Persistence_pair> persistence_pairs;
  double field_min = 0, field_max = 0;
  double persistence_threshold = 0;   ///< the absolute threshold applied
  std::size_t ascending_cells = 0;    ///< the number of ascending 3-cells (after the cancellations)
  std::size_t descending_cells = 0;   ///< the number of descending 3-cells (after the cancellations)
  std::size_t outflow_tetrahedra = 0; ///< the tetrahedra whose gradient path leaves the domain
};

namespace internal {

enum Topology_work : unsigned { TOPOLOGY_LINKS = 1u, TOPOLOGY_GRADIENT = 2u };

// The field in the octree's numbering, in a total order.
template <class Octree, class FieldMap>
Field_order<Octree> make_field_order(const Octree& tree, const FieldMap& field) {
  return Field_order<Octree>(tree, [&](typename Octree::Index v) { return field_value(tree, field, v); });
}

template <class Index>
struct Saddle_event {
  Index vertex;
  std::vector<Index> representatives;
};

template <class Index>
struct Critical_record {
  int dimension;
  std::array<Index, 4> vertices; // octree numbering, highest first
  std::array<Index, 2> cofacets; // triangles: their tetrahedra
};

template <class Index>
struct Topology_leaf_output {
  std::vector<Critical_record<Index>> critical;
  std::vector<Saddle_event<Index>> joins, splits;
  long long euler = 0;
};

// What one pass over the leaves gives, in the octree's numbering.
template <class Octree>
struct Topology_pass {
  using Index = typename Octree::Index;
  static constexpr Index none = Index(-1);
  std::vector<std::uint8_t> lower, upper; // link components (saturated at 255)
  std::vector<std::uint8_t> open_link;    // 1: the link is not a closed surface
  std::vector<Index> descent, ascent;     // steepest neighbours (the vertex itself at an extremum)
  std::vector<std::uint8_t> codes;        // the gradient
  std::vector<Index> tet_parent;          // the tetrahedron across its paired triangle
  std::vector<Critical_record<Index>> critical;
  std::vector<Saddle_event<Index>> joins, splits;
  long long euler = 0;
};

template <class ConcurrencyTag, class Octree, class NP>
Topology_pass<Octree> run_topology_pass(const Octree& tree, const Field_order<Octree>& order, unsigned work,
                                        bool parents, bool events, const NP& np) {
  using Index = typename Octree::Index;
  using Pass = Topology_pass<Octree>;
  using Out = Topology_leaf_output<Index>;
  Pass pass;
  const std::size_t nv = tree.number_of_vertices(), nt = tree.number_of_tetrahedra();
  const bool links = (work & TOPOLOGY_LINKS) != 0, gradient = (work & TOPOLOGY_GRADIENT) != 0;
  if (links) {
    pass.lower.assign(nv, 0);
    pass.open_link.assign(nv, 0);
    pass.upper.assign(nv, 0);
    if (events) {
      pass.descent.assign(nv, Pass::none);
      pass.ascent.assign(nv, Pass::none);
    }
  }
  if (gradient) {
    pass.codes.assign(4 * nt, 0);
    if (parents) pass.tet_parent.assign(nt, Pass::none);
  }
  std::uint8_t* codes = pass.codes.data();
  Leaf_executor<ConcurrencyTag>().map_reduce(
      tree, VERTEX_TETRAHEDRA, Lower_star_processor<Octree>(),
      [&](Lower_star_processor<Octree>& proc, const Leaf_topology<Octree>& local) {
        Out out;
        for (Index v = local.vertex_begin(); v < local.vertex_end(); ++v) {
          const auto star = local.vertex_tetrahedra(v);
          if (links && star.size() != 0) {
            const auto& l = proc.analyse_links(order, v, star);
            pass.lower[v] = static_cast<std::uint8_t>((std::min)(l.lower_components, 255u));
            pass.upper[v] = static_cast<std::uint8_t>((std::min)(l.upper_components, 255u));
            if (classify_critical_point(l.lower_components, l.upper_components) != Critical_type::REGULAR)
              pass.open_link[v] = !proc.link_is_closed();
            if (events) {
              pass.descent[v] = l.lower_components == 0 ? v : l.lowest_lower;
              pass.ascent[v] = l.upper_components == 0 ? v : l.highest_upper;
              if (l.lower_components >= 2) out.joins.push_back({v, l.lower_representatives});
              if (l.upper_components >= 2) out.splits.push_back({v, l.upper_representatives});
            }
          }
          if (gradient) out.euler += proc.euler_at_smallest(tree, v, star);
          if (gradient)
            proc.process_lower_star(
                order, v, star, codes,
                [&](int d, const std::array<Index, 4>& vs, const std::array<Index, 2>& cof) {
                  out.critical.push_back({d, vs, cof});
                },
                [&](Index t, Index p) {
                  if (parents) pass.tet_parent[t] = p;
                });
        }
        return out;
      },
      [&](Out&& out) {
        pass.critical.insert(pass.critical.end(), out.critical.begin(), out.critical.end());
        for (auto& e : out.joins) pass.joins.push_back(std::move(e));
        for (auto& e : out.splits) pass.splits.push_back(std::move(e));
        pass.euler += out.euler;
      },
      Progress_reporter<NP>(np));
  return pass;
}

// Every parent chain replaced by its end: a root (`p[r] == r`) or `none`.
template <class Index>
void resolve_roots(std::vector<Index>& p) {
  const Index none = Index(-1);
  const std::size_t n = p.size();
  for (std::size_t x = 0; x < n; ++x) {
    Index r = static_cast<Index>(x);
    std::size_t steps = 0;
    while (p[r] != none && p[r] != r) {
      r = p[r];
      if (++steps > n) throw std::logic_error("the gradient paths form a cycle");
    }
    const Index root = p[r] == none ? none : r;
    Index y = static_cast<Index>(x);
    while (y != r) {
      const Index next = p[y];
      p[y] = root;
      y = next;
    }
  }
}

// Sorts the critical records into the gradient's list (user numbering), by dimension then G.
template <class Octree>
void finish_gradient(const Octree& tree, const Field_order<Octree>& order,
                     std::vector<Critical_record<typename Octree::Index>>& records,
                     Forman_gradient<Octree>& g) {
  using Index = typename Octree::Index;
  const Index none = Index(-1);
  std::sort(records.begin(), records.end(), [&](const auto& a, const auto& b) {
    if (a.dimension != b.dimension) return a.dimension < b.dimension;
    for (int i = 0; i <= a.dimension; ++i)
      if (a.vertices[i] != b.vertices[i]) return order.less(a.vertices[i], b.vertices[i]);
    return false;
  });
  g.critical_.clear();
  g.counts_ = {{0, 0, 0, 0}};
  for (const auto& r : records) {
    Critical_simplex c;
    c.dimension = r.dimension;
    for (int i = 0; i <= r.dimension; ++i)
      c.vertices[i] = r.vertices[i] == none ? Critical_simplex::no_vertex
                                            : static_cast<std::size_t>(tree.original_vertex(r.vertices[i]));
    c.value = order.value(r.vertices[0]);
    g.critical_.push_back(c);
    ++g.counts_[static_cast<std::size_t>(r.dimension)];
  }
}

// The elder rule over the saddle events: `root` maps a vertex to its extremum; events sorted by
// `before` (increasing for minima, decreasing for maxima).  Fills `pairs` and `merged_into`.
template <class Octree, class Before>
void elder_rule(const Field_order<Octree>& order, std::vector<Saddle_event<typename Octree::Index>>& events,
                const std::vector<typename Octree::Index>& root,
                const std::vector<typename Octree::Index>& extrema, Persistence_pair::Type type,
                const Before& before, std::vector<Persistence_pair>& pairs,
                std::vector<typename Octree::Index>& merged_into, std::vector<double>& persistence) {
  using Index = typename Octree::Index;
  const Octree& tree = order.octree();
  // union-find over the extrema, by their position in `extrema` (sorted by index)
  const std::vector<Index>& sorted = extrema;
  auto id = [&](Index v) {
    return static_cast<std::size_t>(std::lower_bound(sorted.begin(), sorted.end(), v) - sorted.begin());
  };
  std::vector<std::size_t> uf(sorted.size());
  std::vector<Index> oldest(sorted);
  for (std::size_t i = 0; i < uf.size(); ++i) uf[i] = i;
  auto find = [&](std::size_t i) {
    while (uf[i] != i) i = uf[i] = uf[uf[i]];
    return i;
  };
  std::sort(events.begin(), events.end(),
            [&](const auto& a, const auto& b) { return before(a.vertex, b.vertex); });
  std::vector<std::size_t> sets;
  for (const auto& e : events) {
    sets.clear();
    for (Index r : e.representatives) sets.push_back(find(id(root[r])));
    std::sort(sets.begin(), sets.end());
    sets.erase(std::unique(sets.begin(), sets.end()), sets.end());
    if (sets.size() < 2) continue;
    std::size_t elder = sets[0];
    for (std::size_t s : sets)
      if (before(oldest[s], oldest[elder])) elder = s;
    // the younger ones die here, in the order of their extrema (the same pairs in any order)
    std::sort(sets.begin(), sets.end(),
              [&](std::size_t a, std::size_t b) { return before(oldest[a], oldest[b]); });
    for (std::size_t s : sets) {
      if (s == elder) continue;
      Persistence_pair p;
      p.type = type;
      p.extremum = static_cast<std::size_t>(tree.original_vertex(oldest[s]));
      p.extremum_value = order.value(oldest[s]);
      p.saddle = static_cast<std::size_t>(tree.original_vertex(e.vertex));
      p.saddle_value = order.value(e.vertex);
      pairs.push_back(p);
      merged_into[id(oldest[s])] = oldest[elder];
      persistence[id(oldest[s])] = p.persistence();
      uf[s] = elder;
    }
  }
  // the survivors: essential
  for (std::size_t i = 0; i < uf.size(); ++i)
    if (find(i) == i) {
      Persistence_pair p;
      p.type = type;
      p.extremum = static_cast<std::size_t>(tree.original_vertex(oldest[i]));
      p.extremum_value = order.value(oldest[i]);
      pairs.push_back(p);
    }
}

} // namespace internal

/// \ingroup PkgPRStarOctreeRef
/// Classifies every vertex of the mesh by the connected components of its lower and upper links
/// (the field compared as the pair (value, user's vertex index), so that flat regions are well
/// defined), leaf by leaf.
///
/// \tparam FieldMap as in `compute_curvature()`: a `ReadablePropertyMap` keyed by the user's vertex
///         index, value convertible to `double`
/// \tparam TypeMap a `WritablePropertyMap` keyed by the user's vertex index with value
///         `Critical_type`, or `nullptr` (no map)
/// \param tree the octree of the mesh
/// \param field the scalar field (finite at every vertex)
/// \param type_map receives the type of each vertex
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{critical_points_output}
///     \cgalParamDescription{receives a `Critical_point` for each vertex that is not regular, by
///     increasing user's index}
///     \cgalParamType{an output iterator}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress}
///     \cgalParamDescription{called as `F(done, total)` after each leaf}
///     \cgalParamType{a callable `F(std::size_t, std::size_t)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the numbers of vertices of each type
/// \throws std::invalid_argument if the field is not finite at some vertex
/// \tparam ConcurrencyTag `CGAL::Parallel_tag`, `CGAL::Sequential_tag` or the default
///         `CGAL::Parallel_if_available_tag`: the same result either way
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class GT, class I, class FieldMap,
          class TypeMap, class NP = parameters::Default_named_parameters>
Critical_point_counts compute_critical_points(const PR_star_octree_3<GT, I>& tree, const FieldMap& field,
                                              TypeMap type_map, const NP& np = parameters::default_values()) {
  const auto order = internal::make_field_order(tree, field);
  const auto pass =
      internal::run_topology_pass<ConcurrencyTag>(tree, order, internal::TOPOLOGY_LINKS, false, false, np);
  Critical_point_counts counts;
  const std::size_t nv = tree.number_of_vertices();
  std::vector<Critical_point> points;
  for (std::size_t v = 0; v < nv; ++v) {
    const unsigned lo = pass.lower[v], up = pass.upper[v];
    counts.add(lo, up);
    const Critical_type type = classify_critical_point(lo, up);
    const std::size_t user = static_cast<std::size_t>(tree.original_vertex(static_cast<I>(v)));
    if constexpr (!std::is_same<TypeMap, std::nullptr_t>::value) put(type_map, user, type);
    if (type != Critical_type::REGULAR)
      points.push_back({user, type, lo, up, order.value(static_cast<I>(v)), pass.open_link[v] != 0});
  }
  auto out = parameters::get_parameter(np, internal_np::critical_points_output);
  if constexpr (!std::is_same<decltype(out), CGAL::internal_np::Param_not_found>::value) {
    std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.vertex < b.vertex; });
    for (const auto& p : points) *out++ = p;
  }
  return counts;
}

/// \ingroup PkgPRStarOctreeRef
/// The discrete gradient of the field by the lower stars of the vertices (Robins, Wood and
/// Sheppard 2011, ProcessLowerStars), each vertex's lower star processed in the leaf holding it;
/// the field compared as the pair (value, user's vertex index).  Its critical simplices are in
/// one-to-one correspondence with the changes of the homology of the lower-star filtration, and
/// `c0 - c1 + c2 - c3` is the Euler characteristic of the mesh.
///
/// \param tree the octree of the mesh
/// \param field the scalar field, as in `compute_critical_points()`
/// \param np an optional sequence of named parameters: `progress` as in `compute_critical_points()`
/// \throws std::invalid_argument if the field is not finite at some vertex
/// \tparam ConcurrencyTag as in `compute_critical_points()` (the same gradient either way)
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class GT, class I, class FieldMap,
          class NP = parameters::Default_named_parameters>
Forman_gradient<PR_star_octree_3<GT, I>>
compute_forman_gradient(const PR_star_octree_3<GT, I>& tree, const FieldMap& field,
                        const NP& np = parameters::default_values()) {
  using Octree = PR_star_octree_3<GT, I>;
  const auto order = internal::make_field_order(tree, field);
  auto pass =
      internal::run_topology_pass<ConcurrencyTag>(tree, order, internal::TOPOLOGY_GRADIENT, false, false, np);
  Forman_gradient<Octree> g;
  g.codes_ = std::move(pass.codes);
  g.euler_ = pass.euler;
  internal::finish_gradient(tree, order, pass.critical, g);
  return g;
}

/// \ingroup PkgPRStarOctreeRef
/// The pairs of a discrete gradient, each once, in the user's vertex indices: `(lower, upper)`
/// with `lower` a face of `upper` one dimension down, each simplex as its vertices sorted by
/// increasing user's index (unused entries `Critical_simplex::no_vertex`).  Ordered by the leaf
/// and then the highest vertex of the pair.  For checks and small meshes (one pass over the leaves).
template <class GT, class I, class OutputIterator>
OutputIterator forman_gradient_pairs(const PR_star_octree_3<GT, I>& tree,
                                     const Forman_gradient<PR_star_octree_3<GT, I>>& g, OutputIterator out) {
  using Octree = PR_star_octree_3<GT, I>;
  using Simplex = std::array<std::size_t, 4>;
  const std::size_t none = Critical_simplex::no_vertex;
  auto make = [&](std::initializer_list<I> vs) {
    Simplex s{{none, none, none, none}};
    std::size_t k = 0;
    for (I v : vs) s[k++] = static_cast<std::size_t>(tree.original_vertex(v));
    std::sort(s.begin(), s.end()); // the unused entries (no_vertex) last
    return s;
  };
  std::vector<std::pair<Simplex, Simplex>> local;
  for_each_leaf<CGAL::Sequential_tag>(tree, VERTEX_TETRAHEDRA, [&](const Leaf_topology<Octree>& leaf) {
    for (I v = leaf.vertex_begin(); v < leaf.vertex_end(); ++v) {
      local.clear();
      for (auto t : leaf.vertex_tetrahedra(v)) {
        const auto& tv = tree.tetrahedron(t);
        int i = 0;
        while (tv[i] != v) ++i;
        const std::uint8_t c = g.corner_code(t, i);
        int slot = 0;
        for (int j = 0; j < 4; ++j)
          if (j != i && ++slot == (c & 3)) local.emplace_back(make({v}), make({v, tv[j]}));
        int s = 0;
        for (int m = 0; m < 4; ++m) {
          if (m == i) continue;
          const unsigned code = (c >> (2 + 2 * s)) & 3u;
          ++s;
          if (code == 0) continue;
          int a = -1, b = -1;
          for (int j = 0; j < 4; ++j)
            if (j != i && j != m) (a < 0 ? a : b) = j;
          const Simplex tri = make({v, tv[a], tv[b]});
          if (code == 3)
            local.emplace_back(tri, make({tv[0], tv[1], tv[2], tv[3]}));
          else
            local.emplace_back(make({v, code == 1 ? tv[a] : tv[b]}), tri);
        }
      }
      std::sort(local.begin(), local.end());
      local.erase(std::unique(local.begin(), local.end()), local.end());
      for (const auto& p : local) *out++ = p;
    }
  });
  return out;
}

/// \ingroup PkgPRStarOctreeRef
/// The Morse complexes of the field: its critical points, its discrete gradient, the ascending
/// 3-cells of the minima (per vertex) and the descending 3-cells of the maxima (per tetrahedron),
/// found by following the gradient paths, and the persistence pairs of the extrema; the pairs of
/// persistence below `persistence_threshold` are cancelled (a cancelled extremum's cell joins the
/// cell of the extremum it merged into).
///
/// One pass over the leaves gives, per vertex, its links' components and its steepest lower
/// neighbour (the vertex-edge pair of the gradient), and per tetrahedron the gradient's pairs and
/// the tetrahedron across its paired triangle: no adjacency is kept beyond the leaf.  The gradient
/// paths are then followed on those arrays (4 bytes per vertex and per tetrahedron), and the
/// persistence pairs come from the saddle vertices alone (union-find over the extrema, in the field
/// order): they are those of the 0-dimensional homology of the sublevel sets (minimum-saddle) and
/// of the superlevel sets (saddle-maximum) of the piecewise-linear field.
///
/// \param tree the octree of the mesh
/// \param field the scalar field, as in `compute_critical_points()`
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{persistence_threshold}
///     \cgalParamDescription{the pairs of persistence strictly below it are cancelled in the cells}
///     \cgalParamType{`double` (in the field's units)}
///     \cgalParamDefault{0 (no cancellation)}
///   \cgalParamNEnd
///   \cgalParamNBegin{arcs_output}
///     \cgalParamDescription{receives the `Morse_arc`s of the Morse-Smale 1-skeleton: two per
///     critical edge and per critical triangle (one for a triangle on the boundary)}
///     \cgalParamType{an output iterator}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress}
///     \cgalParamDescription{called as `F(done, total)` after each leaf}
///     \cgalParamType{a callable `F(std::size_t, std::size_t)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws std::invalid_argument if the field is not finite at some vertex
/// \tparam ConcurrencyTag as in `compute_critical_points()` (the same result either way)
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class GT, class I, class FieldMap,
          class NP = parameters::Default_named_parameters>
Morse_complexes<PR_star_octree_3<GT, I>>
compute_morse_complexes(const PR_star_octree_3<GT, I>& tree, const FieldMap& field,
                        const NP& np = parameters::default_values()) {
  using Octree = PR_star_octree_3<GT, I>;
  using Index = I;
  const Index none = Index(-1);
  const std::size_t no_cell = Morse_complexes<Octree>::no_cell;
  const auto order = internal::make_field_order(tree, field);
  auto pass = internal::run_topology_pass<ConcurrencyTag>(
      tree, order, internal::TOPOLOGY_LINKS | internal::TOPOLOGY_GRADIENT, true, true, np);
  const std::size_t nv = tree.number_of_vertices(), nt = tree.number_of_tetrahedra();
  Morse_complexes<Octree> m;
  m.gradient.codes_ = std::move(pass.codes);
  m.gradient.euler_ = pass.euler;
  internal::finish_gradient(tree, order, pass.critical, m.gradient);
  m.persistence_threshold =
      parameters::choose_parameter(parameters::get_parameter(np, internal_np::persistence_threshold), 0.0);
  bool first = true;
  for (std::size_t v = 0; v < nv; ++v) {
    if (pass.lower[v] == 0 && pass.upper[v] == 0) continue;
    const double x = order.value(static_cast<Index>(v));
    m.field_min = first ? x : (std::min)(m.field_min, x);
    m.field_max = first ? x : (std::max)(m.field_max, x);
    first = false;
  }
  // the extrema and the arcs' paths, before the chains are resolved
  std::vector<Index> minima, maxima;
  for (std::size_t v = 0; v < nv; ++v) {
    if (pass.descent[v] == static_cast<Index>(v)) minima.push_back(static_cast<Index>(v));
    if (pass.ascent[v] == static_cast<Index>(v)) maxima.push_back(static_cast<Index>(v));
  }
  auto arcs = parameters::get_parameter(np, internal_np::arcs_output);
  if constexpr (!std::is_same<decltype(arcs), CGAL::internal_np::Param_not_found>::value) {
    auto point = [&](Index v) { return tree.coordinates(tree.point(v)); };
    auto barycentre = [&](std::initializer_list<Index> vs) {
      std::array<double, 3> b{{0, 0, 0}};
      for (Index v : vs) {
        const auto p = point(v);
        for (int k = 0; k < 3; ++k) b[k] += p[k];
      }
      for (int k = 0; k < 3; ++k) b[k] /= static_cast<double>(vs.size());
      return b;
    };
    auto tet_centre = [&](Index t) {
      const auto& c = tree.tetrahedron(t);
      return barycentre({c[0], c[1], c[2], c[3]});
    };
    for (std::size_t s = 0; s < pass.critical.size(); ++s) {
      const auto& r = pass.critical[s];
      if (r.dimension == 1) {
        for (Index start : {r.vertices[0], r.vertices[1]}) {
          Morse_arc a;
          a.saddle_dimension = 1;
          a.saddle = s;
          a.points.push_back(barycentre({r.vertices[0], r.vertices[1]}));
          Index v = start;
          a.points.push_back(point(v));
          for (std::size_t steps = 0; pass.descent[v] != v && steps <= nv; ++steps) {
            v = pass.descent[v];
            a.points.push_back(point(v));
          }
          a.extremum = static_cast<std::size_t>(tree.original_vertex(v));
          *arcs++ = std::move(a);
        }
      } else if (r.dimension == 2) {
        for (Index start : r.cofacets) {
          if (start == none) continue;
          Morse_arc a;
          a.saddle_dimension = 2;
          a.saddle = s;
          a.points.push_back(barycentre({r.vertices[0], r.vertices[1], r.vertices[2]}));
          Index t = start;
          a.points.push_back(tet_centre(t));
          for (std::size_t steps = 0; steps <= nt; ++steps) {
            const Index p = pass.tet_parent[t];
            if (p == none) {
              t = none;
              break;
            }
            if (p == t) break;
            t = p;
            a.points.push_back(tet_centre(t));
          }
          a.extremum = no_cell;
          if (t != none) { // the highest vertex of the critical tetrahedron
            const auto& c = tree.tetrahedron(t);
            Index h = c[0];
            for (Index u : c)
              if (order.less(h, u)) h = u;
            a.extremum = static_cast<std::size_t>(tree.original_vertex(h));
          }
          *arcs++ = std::move(a);
        }
      }
    }
  }
  // the Morse cells: the chains resolved to their ends
  internal::resolve_roots(pass.descent);
  internal::resolve_roots(pass.ascent);
  internal::resolve_roots(pass.tet_parent);
  // the persistence pairs and the cancellations
  const double infinity = std::numeric_limits<double>::infinity();
  std::vector<Index> min_into(minima.size(), none), max_into(maxima.size(), none);
  std::vector<double> min_persistence(minima.size(), infinity), max_persistence(maxima.size(), infinity);
  internal::elder_rule(
      order, pass.joins, pass.descent, minima, Persistence_pair::MINIMUM_SADDLE,
      [&](Index a, Index b) { return order.less(a, b); }, m.persistence_pairs, min_into, min_persistence);
  std::vector<Persistence_pair> max_pairs;
  internal::elder_rule(
      order, pass.splits, pass.ascent, maxima, Persistence_pair::SADDLE_MAXIMUM,
      [&](Index a, Index b) { return order.less(b, a); }, max_pairs, max_into, max_persistence);
  auto by_extremum = [](const Persistence_pair& a, const Persistence_pair& b) {
    return a.extremum_value < b.extremum_value ||
           (a.extremum_value == b.extremum_value && a.extremum < b.extremum);
  };
  std::sort(m.persistence_pairs.begin(), m.persistence_pairs.end(), by_extremum);
  std::sort(max_pairs.begin(), max_pairs.end(), by_extremum);
  m.persistence_pairs.insert(m.persistence_pairs.end(), max_pairs.begin(), max_pairs.end());
  // the extremum each one ends in after the cancellations: the older ones first, so that the one
  // it merged into is final already
  auto id_in = [](const std::vector<Index>& sorted, Index v) {
    return static_cast<std::size_t>(std::lower_bound(sorted.begin(), sorted.end(), v) - sorted.begin());
  };
  auto finals = [&](const std::vector<Index>& extrema, const std::vector<Index>& into,
                    const std::vector<double>& persistence, bool minimum) {
    std::vector<std::size_t> by_age(extrema.size());
    for (std::size_t i = 0; i < by_age.size(); ++i) by_age[i] = i;
    std::sort(by_age.begin(), by_age.end(), [&](std::size_t a, std::size_t b) {
      return minimum ? order.less(extrema[a], extrema[b]) : order.less(extrema[b], extrema[a]);
    });
    std::vector<Index> result(extrema.size(), none);
    for (std::size_t i : by_age)
      result[i] = (into[i] != none && persistence[i] < m.persistence_threshold)
                      ? result[id_in(extrema, into[i])]
                      : extrema[i];
    return result;
  };
  const std::vector<Index> min_final = finals(minima, min_into, min_persistence, true);
  const std::vector<Index> max_final = finals(maxima, max_into, max_persistence, false);
  for (std::size_t i = 0; i < minima.size(); ++i) m.ascending_cells += (min_final[i] == minima[i]);
  // per vertex
  m.critical_type.assign(nv, Critical_type::REGULAR);
  m.ascending_cell.assign(nv, no_cell);
  for (std::size_t v = 0; v < nv; ++v) {
    const std::size_t user = static_cast<std::size_t>(tree.original_vertex(static_cast<Index>(v)));
    m.critical_points.add(pass.lower[v], pass.upper[v]);
    m.critical_type[user] = classify_critical_point(pass.lower[v], pass.upper[v]);
    const Index root = pass.descent[v];
    if (root == none) continue; // unreferenced
    m.ascending_cell[user] = static_cast<std::size_t>(tree.original_vertex(min_final[id_in(minima, root)]));
  }
  // per tetrahedron: the highest vertex of the critical tetrahedron its path ends in
  auto label_of_root = [&](Index r) {
    const auto& c = tree.tetrahedron(r);
    Index h = c[0];
    for (Index u : c)
      if (order.less(h, u)) h = u;
    const auto it = std::lower_bound(maxima.begin(), maxima.end(), h);
    if (it != maxima.end() && *it == h) h = max_final[static_cast<std::size_t>(it - maxima.begin())];
    return static_cast<std::size_t>(tree.original_vertex(h));
  };
  std::vector<std::size_t> labels; // of the critical tetrahedra
  m.descending_cell.assign(nt, no_cell);
  const bool permuted = tree.has_tetrahedron_permutation();
  for (std::size_t t = 0; t < nt; ++t) {
    const Index r = pass.tet_parent[t];
    const std::size_t slot =
        permuted ? static_cast<std::size_t>(tree.original_tetrahedron(static_cast<Index>(t))) : t;
    if (r == none) {
      ++m.outflow_tetrahedra;
      continue;
    }
    m.descending_cell[slot] = label_of_root(r);
    if (r == static_cast<Index>(t)) labels.push_back(m.descending_cell[slot]);
  }
  std::sort(labels.begin(), labels.end());
  m.descending_cells = static_cast<std::size_t>(std::unique(labels.begin(), labels.end()) - labels.begin());
  return m;
}

} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_SCALAR_TOPOLOGY_H
