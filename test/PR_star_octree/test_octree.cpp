// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Tests of the PR-star octree: invariants checked against brute-force computations that do not use
// the octree's own lookups (point-in-box over all leaves, leaf sets per tetrahedron), permutations,
// orientation, duplicates, the cost model on a hand-checked mesh, other traits and index types.
//
// usage: test_octree GENERATED_DATA_DIR [SHARED_DATA_DIR]

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/Tetrahedron_source.h>
#include <CGAL/Simple_cartesian.h>

#include "test_harness.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;

// Half-open containment of a point in a box, closed on the root's upper faces.
template <class P>
bool in_box(const P& p, const CGAL::Bbox_3& b, const CGAL::Bbox_3& root) {
  const double c[3] = {p.x(), p.y(), p.z()};
  for (int a = 0; a < 3; ++a) {
    if (c[a] < b.min(a)) return false;
    if (c[a] > b.max(a)) return false;
    if (c[a] == b.max(a) && b.max(a) != root.max(a)) return false;
  }
  return true;
}

// Every invariant of the structure, against brute force.  Returns the sorted leaf vertex sets
// (in original numbering, with the leaf boxes) to compare trees built from shuffled inputs.
template <class Tree, class Input>
std::map<std::vector<double>, std::set<std::size_t>> check_invariants(const Tree& tree, const Input& input,
                                                                      const std::string& what) {
  using Index = typename Tree::Index;
  const std::size_t nv = input.number_of_vertices(), nt = input.number_of_tetrahedra();
  const prstar_test::Failure_context context(what);
  CHECK_EQUAL(tree.number_of_vertices(), nv);
  CHECK_EQUAL(tree.number_of_tetrahedra(), nt);

  // Permutations are bijections; coordinates and scalars preserved.
  std::vector<int> seen(nv, 0);
  for (std::size_t v = 0; v < nv; ++v) {
    const Index o = tree.original_vertex(static_cast<Index>(v));
    CHECK(o < nv);
    if (o < nv) {
      ++seen[o];
      const auto& p = input.point(o);
      CHECK(tree.point(static_cast<Index>(v)).x() == p.x() &&
            tree.point(static_cast<Index>(v)).y() == p.y() && tree.point(static_cast<Index>(v)).z() == p.z());
      if (input.has_scalar_field()) CHECK_EQUAL(tree.scalar(static_cast<Index>(v)), input.scalar(o));
    }
  }
  CHECK(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }));
  std::vector<int> tseen(nt, 0);
  for (std::size_t t = 0; t < nt; ++t) {
    const Index o = tree.original_tetrahedron(static_cast<Index>(t));
    CHECK(o < nt);
    if (o >= nt) continue;
    ++tseen[o];
    // Same vertices as the user's, in the user's order once mapped back.
    const auto back = tree.original_tetrahedron_vertices(static_cast<Index>(t));
    const auto orig = input.tetrahedron(o);
    for (int k = 0; k < 4; ++k) CHECK(std::size_t(back[k]) == std::size_t(orig[k]));
    // Positively oriented (or flat), decided exactly.
    const auto& c = tree.tetrahedron(static_cast<Index>(t));
    const auto o3 =
        CGAL::orientation(Point(tree.point(c[0]).x(), tree.point(c[0]).y(), tree.point(c[0]).z()),
                          Point(tree.point(c[1]).x(), tree.point(c[1]).y(), tree.point(c[1]).z()),
                          Point(tree.point(c[2]).x(), tree.point(c[2]).y(), tree.point(c[2]).z()),
                          Point(tree.point(c[3]).x(), tree.point(c[3]).y(), tree.point(c[3]).z()));
    CHECK(o3 != CGAL::NEGATIVE);
  }
  CHECK(std::all_of(tseen.begin(), tseen.end(), [](int c) { return c == 1; }));

  // Leaf ranges partition [0, |V|) in depth-first order; internal ranges are unions of children.
  std::size_t next = 0;
  for (auto n : tree.leaves()) {
    CHECK(tree.node(n).is_leaf());
    CHECK_EQUAL(tree.node(n).vertex_begin, next);
    next = tree.node(n).vertex_end;
  }
  CHECK_EQUAL(next, nv);
  std::size_t leaf_count = 0;
  for (std::size_t n = 0; n < tree.number_of_nodes(); ++n) {
    const auto& nd = tree.node(static_cast<Index>(n));
    if (nd.is_leaf()) {
      ++leaf_count;
      // k_v respected except at the depth bound or for coincident points.
      if (nd.number_of_vertices() > tree.bucket_size()) {
        bool all_same = true;
        for (Index v = nd.vertex_begin + 1; v < nd.vertex_end; ++v)
          all_same = all_same && tree.point(v) == tree.point(nd.vertex_begin);
        CHECK(all_same || tree.depth(static_cast<Index>(n)) == tree.max_depth());
      }
    } else {
      CHECK_EQUAL(nd.number_of_tetrahedra(), 0);
      CHECK_EQUAL(tree.node(nd.first_child).vertex_begin, nd.vertex_begin);
      CHECK_EQUAL(tree.node(nd.first_child + 7).vertex_end, nd.vertex_end);
      for (int c = 0; c < 7; ++c)
        CHECK_EQUAL(tree.node(nd.first_child + c).vertex_end, tree.node(nd.first_child + c + 1).vertex_begin);
      for (int c = 0; c < 8; ++c) CHECK(tree.node(nd.first_child + c).parent == n);
      // Internal nodes hold more than k_v vertices (otherwise they would not have been split).
      CHECK(nd.number_of_vertices() > tree.bucket_size());
    }
  }
  CHECK_EQUAL(leaf_count, tree.number_of_leaves());

  // Every vertex lies in the box of its leaf and in no other leaf box (brute force over all leaves).
  const CGAL::Bbox_3 root = tree.bbox();
  std::vector<Index> leaf_of(nv);
  std::vector<CGAL::Bbox_3> boxes;
  for (auto n : tree.leaves()) boxes.push_back(tree.node_bbox(n));
  for (std::size_t l = 0; l < tree.number_of_leaves(); ++l) {
    const auto& nd = tree.node(tree.leaves()[l]);
    for (Index v = nd.vertex_begin; v < nd.vertex_end; ++v) {
      leaf_of[v] = tree.leaves()[l];
      CHECK(in_box(tree.point(v), boxes[l], root));
      CHECK_EQUAL(tree.leaf_of_vertex(v), tree.leaves()[l]);
      CHECK_EQUAL(tree.locate(tree.point(v)), tree.leaves()[l]);
    }
  }
  // In no other leaf box: every vertex when |V| |leaves| is small, a regular sample of them
  // otherwise (at most about 4e7 box tests).
  const std::size_t work = nv * tree.number_of_leaves();
  const std::size_t stride = work <= 40000000 ? 1 : work / 40000000 + 1;
  std::size_t sampled = 0;
  for (std::size_t v = 0; v < nv; v += stride, ++sampled) {
    int inside = 0;
    for (std::size_t l = 0; l < boxes.size(); ++l)
      inside += in_box(tree.point(static_cast<Index>(v)), boxes[l], root);
    CHECK_EQUAL(inside, 1);
  }
  CHECK(nv == 0 || sampled > 0);

  // Each tetrahedron is listed in exactly the leaves of its vertices.
  std::vector<std::set<Index>> listed(nt);
  std::size_t entries = 0;
  for (auto n : tree.leaves()) {
    Index prev = 0;
    bool first = true;
    for (Index t : tree.leaf_tetrahedra(n)) {
      CHECK(t < nt);
      if (t >= nt) continue;
      CHECK(first || t > prev); // increasing, no repeats
      prev = t;
      first = false;
      listed[t].insert(n);
      ++entries;
    }
  }
  for (std::size_t t = 0; t < nt; ++t) {
    std::set<Index> expected;
    for (Index v : tree.tetrahedron(static_cast<Index>(t))) expected.insert(leaf_of[v]);
    CHECK_EQUAL(listed[t], expected);
  }
  const auto s = tree.statistics();
  CHECK_EQUAL(s.leaf_tetrahedra_entries, entries);
  CHECK(nt == 0 || (s.chi >= 1.0 && s.chi <= 4.0));
  CHECK(s.nodes == tree.number_of_nodes() && s.leaves == tree.number_of_leaves());
  CHECK_EQUAL((s.nodes - 1) % 8, 0);

  std::map<std::vector<double>, std::set<std::size_t>> shape;
  for (std::size_t l = 0; l < boxes.size(); ++l) {
    std::vector<double> key{boxes[l].xmin(), boxes[l].ymin(), boxes[l].zmin(),
                            boxes[l].xmax(), boxes[l].ymax(), boxes[l].zmax()};
    std::set<std::size_t> vs;
    const auto& nd = tree.node(tree.leaves()[l]);
    for (Index v = nd.vertex_begin; v < nd.vertex_end; ++v) vs.insert(tree.original_vertex(v));
    shape[key] = vs;
  }
  return shape;
}

// The same mesh, vertices and tetrahedra shuffled: the same tree (boxes and leaf vertex sets).
void check_shuffle_invariance(const Mesh& mesh, std::size_t kv, const std::string& what) {
  auto in = CGAL::PR_star_octree::make_input(mesh);
  CGAL::PR_star_octree_3<> a(in, CGAL::PR_star_octree::parameters::bucket_size(kv));
  const auto shape_a = check_invariants(a, in, what);

  std::mt19937 rng(12345);
  std::vector<std::uint32_t> perm(mesh.points.size());
  std::iota(perm.begin(), perm.end(), 0u);
  std::shuffle(perm.begin(), perm.end(), rng); // perm[new] = old
  std::vector<std::uint32_t> inv(perm.size());
  for (std::size_t i = 0; i < perm.size(); ++i) inv[perm[i]] = static_cast<std::uint32_t>(i);
  Mesh shuffled;
  for (std::uint32_t o : perm) shuffled.points.push_back(mesh.points[o]);
  shuffled.tetrahedra = mesh.tetrahedra;
  std::shuffle(shuffled.tetrahedra.begin(), shuffled.tetrahedra.end(), rng);
  for (auto& c : shuffled.tetrahedra)
    for (auto& v : c) v = inv[v];
  auto in_b = CGAL::PR_star_octree::make_input(shuffled);
  CGAL::PR_star_octree_3<> b(in_b, CGAL::PR_star_octree::parameters::bucket_size(kv));
  auto shape_b = check_invariants(b, in_b, what + " (shuffled)");
  // Map b's original indices (shuffled) back to the mesh's numbering.
  for (auto& kvp : shape_b) {
    std::set<std::size_t> mapped;
    for (std::size_t v : kvp.second) mapped.insert(perm[v]);
    kvp.second = mapped;
  }
  CHECK_EQUAL(shape_a, shape_b);
  CHECK_EQUAL(a.number_of_nodes(), b.number_of_nodes());
  CHECK_EQUAL(a.statistics().chi, b.statistics().chi);
}

// The lean construction (the mesh moved in, reordered there), without the tetrahedron
// permutation, sequential and parallel: checked against brute force like the copying one, and the
// same structure as the copying one, array for array.
void check_lean_construction(const Mesh& mesh, std::size_t kv, const std::string& what) {
  namespace params = CGAL::PR_star_octree::parameters;
  using Tree = CGAL::PR_star_octree_3<>;
  const prstar_test::Failure_context context(what + " (lean)");
  Mesh labelled = mesh; // labels of three values, so that they are stored per tetrahedron
  labelled.tetrahedron_labels.resize(mesh.tetrahedra.size());
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) labelled.tetrahedron_labels[t] = int(t % 3) - 1;
  labelled.point_data.push_back({"second", std::vector<double>(mesh.points.size(), 2.5)});
  const auto in = CGAL::PR_star_octree::make_input(labelled);
  const Tree a(in, params::bucket_size(kv));

  Mesh moved = labelled;
  const Tree b(std::move(moved), params::bucket_size(kv));
  CHECK(moved.points.empty() && moved.tetrahedra.empty() && moved.tetrahedron_labels.empty());
  CHECK_EQUAL(moved.point_data.size(), labelled.point_data.size() - 1); // the scalar field moved out
  CHECK(b.has_tetrahedron_permutation());
  check_invariants(b, in, what + " (moved in)");
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t)
    CHECK_EQUAL(b.tetrahedron_label(Tree::Index(t)),
                labelled.tetrahedron_labels[b.original_tetrahedron(Tree::Index(t))]);

  for (int parallel = 0; parallel < 2; ++parallel) {
    Mesh m = labelled;
    // the second run also drops the vertex permutation: the octree's numbering stands for the user's
    const auto np = params::bucket_size(kv).tetrahedron_permutation(false).vertex_permutation(parallel == 0);
    const Tree c = parallel ? Tree(std::move(m), np.concurrency_tag(CGAL::Parallel_if_available_tag()))
                            : Tree(std::move(m), np.concurrency_tag(CGAL::Sequential_tag()));
    CHECK(!c.has_tetrahedron_permutation());
    CHECK(c.tetrahedron_permutation().empty());
    CHECK(std::equal(c.points().begin(), c.points().end(), a.points().begin(), a.points().end()));
    CHECK(c.scalars() == a.scalars());
    CHECK(std::equal(c.tetrahedra().begin(), c.tetrahedra().end(), a.tetrahedra().begin(),
                     a.tetrahedra().end()));
    CHECK_EQUAL(c.has_vertex_permutation(), parallel == 0);
    if (parallel == 0)
      CHECK(c.vertex_permutation() == a.vertex_permutation());
    else
      CHECK(c.vertex_permutation().empty() && c.original_vertex(Tree::Index(3)) == Tree::Index(3) &&
            c.vertex_from_original()[5] == Tree::Index(5));
    CHECK_EQUAL(c.number_of_shared_entries(), a.number_of_shared_entries());
    CHECK(c.leaves() == a.leaves());
    CHECK_EQUAL(c.number_of_nodes(), a.number_of_nodes());
    bool same_nodes = true, same_labels = true, same_user_tetrahedra = true;
    for (std::size_t n = 0; n < a.number_of_nodes(); ++n) {
      const auto &x = a.node(Tree::Node_index(n)), &y = c.node(Tree::Node_index(n));
      same_nodes = same_nodes && x.vertex_begin == y.vertex_begin && x.vertex_end == y.vertex_end &&
                   x.owned_begin == y.owned_begin && x.owned_end == y.owned_end &&
                   x.shared_begin == y.shared_begin && x.shared_end == y.shared_end &&
                   x.group_begin == y.group_begin && x.group_end == y.group_end &&
                   x.first_child == y.first_child && x.parent == y.parent;
    }
    for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
      same_labels = same_labels && c.tetrahedron_label(Tree::Index(t)) == a.tetrahedron_label(Tree::Index(t));
      auto user = c.original_tetrahedron_vertices(Tree::Index(t)); // octree numbering without permutation
      if (!c.has_vertex_permutation())
        for (auto& v : user) v = a.original_vertex(v);
      same_user_tetrahedra = same_user_tetrahedra &&
                             user == a.original_tetrahedron_vertices(Tree::Index(t)) &&
                             c.is_reoriented(Tree::Index(t)) == a.is_reoriented(Tree::Index(t));
    }
    CHECK(same_nodes);
    CHECK(same_labels);
    CHECK(same_user_tetrahedra);
    const auto sa = a.statistics(), sc = c.statistics();
    CHECK_EQUAL(sc.reoriented_tetrahedra, sa.reoriented_tetrahedra);
    CHECK_EQUAL(sc.degenerate_tetrahedra, sa.degenerate_tetrahedra);
    CHECK_EQUAL(sc.subdomains, sa.subdomains);
    CHECK_EQUAL(sa.bytes.permutations - sc.bytes.permutations,
                (mesh.tetrahedra.size() + (parallel ? mesh.points.size() : 0)) * sizeof(Tree::Index));
  }
}

// The in-place radix sort against std::sort: the same keys in order, the same elements; and the
// same order with one thread and with several (from 2^16 elements the top digit is placed in
// parts, in parallel: 65536 and 300000 take that path, with few distinct keys too, where most
// elements have no room in their own part and are left to the later rounds).
void test_radix_sort_in_place() {
  std::mt19937 rng(11);
  for (std::size_t n : {std::size_t(0), std::size_t(5), std::size_t(63), std::size_t(64), std::size_t(5000),
                        std::size_t(65536), std::size_t(300000)}) {
    for (std::uint64_t bound : {std::uint64_t(1), std::uint64_t(7), std::uint64_t(1000),
                                std::uint64_t(1) << 21, std::uint64_t(1) << 33}) {
      std::uniform_int_distribution<std::uint64_t> u(0, bound - 1);
      std::vector<std::pair<std::uint64_t, std::size_t>> a(n); // (key, identity)
      for (std::size_t i = 0; i < n; ++i) a[i] = {u(rng), i};
      auto expected = a;
      std::sort(expected.begin(), expected.end());
      int width = 0;
      while (width < 64 && ((bound - 1) >> width) != 0) ++width;
      const int shift = std::max(width - 10, 0);
      auto b = a;
      const auto run = [&](auto tag, std::vector<std::pair<std::uint64_t, std::size_t>>& v) {
        CGAL::PR_star_octree::internal::radix_sort_in_place<decltype(tag)>(
            0, v.size(), shift, [&](std::size_t i) { return v[i].first; },
            [&](std::size_t i, std::size_t j) { std::swap(v[i], v[j]); });
      };
      run(CGAL::Sequential_tag(), a);
      run(CGAL::Parallel_if_available_tag(), b);
      CHECK(a == b);
      bool sorted = true;
      for (std::size_t i = 1; i < n; ++i) sorted = sorted && a[i - 1].first <= a[i].first;
      CHECK(sorted);
      std::sort(a.begin(), a.end());
      CHECK(a == expected);
    }
  }
}

// The parted placement of the radix sort's top digit, alone: every range ends up with its own
// elements, none lost or repeated (checked against a counting of the input), for 1 to 7 parts,
// uniform and skewed digits (nine tenths of one value: the parts of the others fill at once), and
// the same result sequentially and in parallel for a given number of parts.
void test_parallel_bucket_permutation() {
  std::mt19937 rng(5);
  const std::size_t radix = 64, n = 200000;
  for (int skewed = 0; skewed < 2; ++skewed) {
    std::vector<std::pair<std::size_t, std::size_t>> input(n); // (digit, identity)
    for (std::size_t i = 0; i < n; ++i)
      input[i] = {skewed && rng() % 10 != 0 ? std::size_t(3) : std::size_t(rng() % radix), i};
    std::vector<std::size_t> first(radix + 1, 0);
    for (const auto& x : input) ++first[x.first + 1];
    for (std::size_t d = 0; d < radix; ++d) first[d + 1] += first[d];
    for (std::size_t parts : {1, 2, 3, 4, 7}) {
      const auto run = [&](auto tag) {
        auto v = input;
        std::vector<std::size_t> head(first.begin(), first.end() - 1), end(first.begin() + 1, first.end());
        CGAL::PR_star_octree::internal::parallel_bucket_permutation<decltype(tag)>(
            head, end, [&](std::size_t i) { return v[i].first; },
            [&](std::size_t i, std::size_t j) { std::swap(v[i], v[j]); }, parts);
        CHECK(head == end);
        return v;
      };
      const auto a = run(CGAL::Sequential_tag());
      bool placed = true;
      for (std::size_t d = 0; d < radix; ++d)
        for (std::size_t i = first[d]; i < first[d + 1]; ++i) placed = placed && a[i].first == d;
      CHECK(placed);
      std::vector<char> seen(n, 0);
      for (const auto& x : a) seen[x.second] = 1;
      CHECK(std::count(seen.begin(), seen.end(), 1) == std::ptrdiff_t(n));
      CHECK(run(CGAL::Parallel_if_available_tag()) == a);
    }
  }
}

// A Kuhn lattice of n^3 cubes (6 n^3 tetrahedra), vertices listed in a shuffled order.
Mesh shuffled_lattice(std::size_t n, unsigned seed) {
  const std::size_t side = n + 1, nv = side * side * side;
  std::vector<std::uint32_t> label(nv); // the vertex at lattice position i gets number label[i]
  std::iota(label.begin(), label.end(), 0u);
  std::mt19937 rng(seed);
  std::shuffle(label.begin(), label.end(), rng);
  Mesh m;
  m.points.resize(nv);
  for (std::size_t z = 0; z < side; ++z)
    for (std::size_t y = 0; y < side; ++y)
      for (std::size_t x = 0; x < side; ++x)
        m.points[label[x + side * (y + side * z)]] = Point(double(x), double(y), double(z));
  const int paths[6][2] = {{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}};
  for (std::size_t z = 0; z < n; ++z)
    for (std::size_t y = 0; y < n; ++y)
      for (std::size_t x = 0; x < n; ++x) {
        std::uint32_t c[8];
        for (int b = 0; b < 8; ++b)
          c[b] = label[(x + (b & 1)) + side * ((y + ((b >> 1) & 1)) + side * (z + ((b >> 2) & 1)))];
        for (const auto& p : paths) m.tetrahedra.push_back({c[0], c[p[0]], c[p[1]], c[7]});
      }
  return m;
}

// The compact leaf lists on a mesh big enough for several groups per leaf (indices 2^16 apart):
// every invariant against brute force, and the random-access iterator (operator[], +=, --, the
// shared part) against a plain decoded copy.
void test_compact_leaf_lists() {
  using Tree = CGAL::PR_star_octree_3<>;
  const Mesh mesh = shuffled_lattice(30, 5); // 162,000 tetrahedra
  const auto in = CGAL::PR_star_octree::make_input(mesh);
  for (std::size_t kv : {std::size_t(8), std::size_t(60)}) {
    const Tree tree(in, CGAL::PR_star_octree::parameters::bucket_size(kv));
    check_invariants(tree, in, "lattice 30, k_v=" + std::to_string(kv));
    std::size_t multi_group_leaves = 0;
    bool same = true;
    for (auto n : tree.leaves()) {
      const auto tets = tree.leaf_tetrahedra(n);
      const std::vector<Tree::Index> plain(tets.begin(), tets.end());
      multi_group_leaves += tree.node(n).group_end - tree.node(n).group_begin > 1;
      same = same && plain.size() == tets.size();
      for (std::size_t i = 0; i < plain.size() && same; i += 7) same = tets[i] == plain[i];
      auto it = tets.end();
      for (std::size_t i = plain.size(); i-- > 0 && same;) same = *--it == plain[i];
      for (std::size_t i = 0; i + 3 < plain.size() && same; i += 5) {
        auto j = tets.begin() + std::ptrdiff_t(i);
        j += 3;
        same =
            *j == plain[i + 3] && j - tets.begin() == std::ptrdiff_t(i + 3) && (j -= 2, *j == plain[i + 1]);
      }
      const auto shared = tets.shared();
      same = same && std::size_t(shared.size()) == tree.node(n).shared_end - tree.node(n).shared_begin &&
             std::equal(shared.begin(), shared.end(), plain.begin());
    }
    CHECK(same);
    CHECK(multi_group_leaves > 0); // the multi-group path was exercised
  }
}

// The compact tetrahedron array against the plain one it encodes: every tetrahedron by random
// access, in one pass, through a cursor moving back and forth, and the edge cases of the encoding
// (a vertex owning 255 or more tetrahedra, differences of 1 to 4 bytes, 64-bit indices, vertices
// owning none, an empty array, unsorted input).
template <class Index>
void check_compact_codec(const std::vector<std::array<Index, 4>>& T, std::size_t nv,
                         const std::string& what) {
  const prstar_test::Failure_context context(what);
  using Codec = CGAL::PR_star_octree::internal::Compact_tetrahedra<Index>;
  Codec c;
  c.assign(T.data(), T.size(), nv);
  CHECK_EQUAL(c.size(), T.size());
  std::vector<std::array<Index, 4>> out;
  c.decode(0, T.size(), std::back_inserter(out));
  CHECK(out == T);
  bool same = true;
  for (std::size_t t = 0; t < T.size(); ++t) same = same && c[t] == T[t];
  CHECK(same);
  std::mt19937 rng(7);
  typename Codec::Cursor cur(c, 0);
  for (int i = 0; i < 2000 && !T.empty(); ++i) {
    const std::size_t t =
        i % 3 == 0 ? rng() % T.size() : (std::min)(T.size() - 1, cur.position() + rng() % 70);
    cur.seek(t);
    same = same && cur.position() == t && *cur == T[t];
  }
  CHECK(same);
  std::vector<std::size_t> owned(nv, 0);
  for (const auto& x : T) ++owned[*std::min_element(x.begin(), x.end())];
  for (std::size_t v = 0; v < nv; ++v) same = same && c.count(Index(v)) == owned[v];
  CHECK(same);
  // the same records encoded by streaming, in chunks of random sizes
  Codec s;
  std::size_t bytes = 0;
  for (const auto& x : T) bytes += c.record_length(x);
  s.start(owned.data(), nv, T.size(), bytes);
  for (std::size_t t = 0; t < T.size();) {
    const std::size_t n = (std::min)(T.size() - t, std::size_t(1 + rng() % 100));
    s.append(T.data() + t, n);
    t += n;
  }
  s.finish();
  // ranges decoded in one pass, from anywhere to anywhere (within a run of one vertex, across runs
  // and blocks, at the ends), from both encodings; seeks that jump into every run of a block
  std::vector<std::array<Index, 4>> buffer(T.size() + 1);
  for (int i = 0; i < 300 && !T.empty(); ++i) {
    std::size_t a = rng() % (T.size() + 1), b = i % 4 == 0 ? T.size() : rng() % (T.size() + 1);
    if (i % 5 == 1) b = (std::min)(T.size(), a + rng() % 20);
    if (a > b) std::swap(a, b);
    const Codec& from = i % 2 == 0 ? c : s;
    const auto* end = from.decode_range(a, b, buffer.data());
    same = same && end == buffer.data() + (b - a) && std::equal(T.begin() + a, T.begin() + b, buffer.data());
    std::size_t j = a / 64 * 64 + rng() % 64;
    if (j >= T.size()) j = T.size() - 1;
    typename Codec::Cursor jump(from, j);
    same = same && jump.position() < T.size() && *jump == T[jump.position()];
  }
  CHECK(same);
}

void test_compact_tetrahedra() {
  std::mt19937 rng(3);
  // differences of every byte length, a vertex owning 600 tetrahedra, vertices owning none
  std::vector<std::array<std::uint32_t, 4>> T;
  const std::uint32_t nv = 40000000;
  for (std::uint32_t v = 0; v < 3000; v += 1 + rng() % 3) {
    const int n = v == 1500 ? 600 : int(rng() % 9);
    for (int i = 0; i < n; ++i) {
      auto r = [&](std::uint32_t n) { return std::uint32_t(rng() % n); };
      const std::uint32_t far[4] = {1 + r(200), 300 + r(60000), 70000 + r(1000000), 20000000 + r(19000000)};
      std::array<std::uint32_t, 4> c{{v, v + far[rng() % 4], v + far[rng() % 4] + 1, v + far[rng() % 4] + 2}};
      if (c[1] == c[2] || c[1] == c[3] || c[2] == c[3]) continue;
      std::shuffle(c.begin(), c.end(), rng);
      T.push_back(c);
    }
  }
  check_compact_codec(T, nv, "compact codec, 32-bit");
  std::vector<std::array<std::uint64_t, 4>> T64;
  for (const auto& c : T) T64.push_back({{c[0], c[1], c[2], c[3]}});
  check_compact_codec(T64, nv, "compact codec, 64-bit"); // (lengths 1, 2, 4, 8: 8 needs |V| > 2^32)
  check_compact_codec(std::vector<std::array<std::uint32_t, 4>>(), 10, "compact codec, empty");
  // unsorted by smallest vertex, a repeated vertex, a vertex out of range
  CGAL::PR_star_octree::internal::Compact_tetrahedra<std::uint32_t> c;
  const std::vector<std::array<std::uint32_t, 4>> unsorted{{{5, 6, 7, 8}}, {{1, 2, 3, 4}}},
      repeated{{{1, 2, 2, 4}}}, outside{{{1, 2, 3, 40}}};
  CHECK_THROWS(std::invalid_argument, "not sorted", c.assign(unsorted.data(), 2, 10));
  CHECK_THROWS(std::invalid_argument, "repeated", c.assign(repeated.data(), 1, 10));
  CHECK_THROWS(std::invalid_argument, "out-of-range", c.assign(outside.data(), 1, 10));

  // In the octree: the same tetrahedra, the same leaves, a quarter of the bytes or less.
  using Tree = CGAL::PR_star_octree_3<>;
  const Mesh mesh = shuffled_lattice(20, 9);
  const auto in = CGAL::PR_star_octree::make_input(mesh);
  for (std::size_t kv : {std::size_t(1), std::size_t(50)}) {
    const Tree plain(in, CGAL::PR_star_octree::parameters::bucket_size(kv));
    const Tree compact(in, CGAL::PR_star_octree::parameters::bucket_size(kv).compact_tetrahedra(true));
    CHECK(compact.is_compact() && !plain.is_compact());
    CHECK(compact.tetrahedra().data() == nullptr);
    check_invariants(compact, in, "compact lattice 20, k_v=" + std::to_string(kv));
    CHECK(std::equal(compact.tetrahedra().begin(), compact.tetrahedra().end(), plain.tetrahedra().begin(),
                     plain.tetrahedra().end()));
    bool same = true;
    for (std::size_t t = 0; t < plain.number_of_tetrahedra(); t += 13)
      same = same && compact.tetrahedron(Tree::Index(t)) == plain.tetrahedron(Tree::Index(t)) &&
             compact.original_tetrahedron_vertices(Tree::Index(t)) ==
                 plain.original_tetrahedron_vertices(Tree::Index(t));
    CHECK(same);
    const auto a = plain.statistics(), b = compact.statistics();
    CHECK_EQUAL(a.leaf_tetrahedra_entries, b.leaf_tetrahedra_entries);
    CHECK_EQUAL(a.unreferenced_vertices, b.unreferenced_vertices);
    std::cout << "  compact lattice 20, k_v=" << kv << ": "
              << double(b.bytes.tetrahedra) / double(b.tetrahedra) << " bytes per tetrahedron instead of "
              << double(a.bytes.tetrahedra) / double(a.tetrahedra) << "\n";
    CHECK(3 * b.bytes.tetrahedra <= a.bytes.tetrahedra);
    CHECK(b.bytes.tetrahedra > 0);
  }
}

// The automatic bucket threshold: the cost model's rule against values worked out by hand, its
// bounds, and the octree's default, which must give the same octree as that k_v given explicitly.
void test_automatic_bucket_size() {
  namespace P = CGAL::PR_star_octree;
  const std::size_t MiB = std::size_t(1) << 20;
  // |T|/|V| = 5.5; links and triangles: 109 + 240 = 349 bytes per listed tetrahedron, a full leaf
  // 1.5 * 5.5 * 349 = 2879.25 bytes per vertex of k_v; 8 MiB / 2879.25 = 2913.5: k_v = 2048.
  P::Bucket_size_choice c = P::choose_bucket_size(2000000, 11000000, P::VERTEX_LINKS | P::TRIANGLES, MiB);
  CHECK_EQUAL(c.bucket_size, std::size_t(2048));
  CHECK_NEAR(c.leaf_bytes_per_tetrahedron, 349., 1e-9);
  CHECK_NEAR(c.tetrahedra_per_vertex, 5.5, 1e-12);
  CHECK_NEAR(c.estimated_leaf_bytes, 2048 * 1.5 * 5.5 * 349, 1e-6);
  CHECK(!c.limited_by_mesh_size);
  CHECK_EQUAL(c.cache_bytes, MiB);
  // VT alone (47 bytes): 8 MiB / 387.75 = 21,634, capped at 4096
  CHECK_EQUAL(P::choose_bucket_size(2000000, 11000000, P::VERTEX_TETRAHEDRA, MiB).bucket_size,
              std::size_t(4096));
  // everything (993 bytes): 8 MiB / 8192.25 = 1023.97: 512
  CHECK_EQUAL(P::choose_bucket_size(2000000, 11000000, P::ALL_RELATIONS, MiB).bucket_size, std::size_t(512));
  // a larger cache, larger leaves; a tiny one, the floor of 64
  CHECK_EQUAL(P::choose_bucket_size(2000000, 11000000, P::VERTEX_LINKS | P::TRIANGLES, 2 * MiB).bucket_size,
              std::size_t(4096));
  CHECK_EQUAL(P::choose_bucket_size(2000000, 11000000, P::VERTEX_LINKS | P::TRIANGLES, 1024).bucket_size,
              std::size_t(64));
  // no relation named: the default (links and triangles); UNCHECKED_LINKS is no relation
  CHECK_EQUAL(P::choose_bucket_size(2000000, 11000000, 0, MiB).bucket_size, std::size_t(2048));
  CHECK_EQUAL(
      P::choose_bucket_size(2000000, 11000000, P::VERTEX_LINKS | P::TRIANGLES | P::UNCHECKED_LINKS, MiB)
          .bucket_size,
      std::size_t(2048));
  // a small mesh keeps 16 leaves' worth of vertices: |V| / 16 = 250 -> 128
  c = P::choose_bucket_size(4000, 22000, P::VERTEX_LINKS | P::TRIANGLES, MiB);
  CHECK_EQUAL(c.bucket_size, std::size_t(128));
  CHECK(c.limited_by_mesh_size);
  CHECK_EQUAL(P::choose_bucket_size(0, 0).bucket_size, std::size_t(64)); // an empty mesh: the floor
  CHECK(P::cache_bytes_per_core() > 0);

  // The octree's default is automatic, with the relations it is told of, and builds the same
  // octree as the chosen k_v given explicitly.
  using Tree = CGAL::PR_star_octree_3<>;
  const Mesh mesh = shuffled_lattice(20, 4);
  const auto in = CGAL::PR_star_octree::make_input(mesh);
  const Tree automatic(in);
  const P::Bucket_size_choice expected = P::choose_bucket_size(mesh.points.size(), mesh.tetrahedra.size());
  CHECK(automatic.has_automatic_bucket_size());
  CHECK_EQUAL(automatic.bucket_size(), expected.bucket_size);
  CHECK_EQUAL(automatic.bucket_size_choice().estimated_leaf_bytes, expected.estimated_leaf_bytes);
  const Tree given(in, P::parameters::bucket_size(expected.bucket_size));
  CHECK(!given.has_automatic_bucket_size());
  CHECK_EQUAL(automatic.number_of_leaves(), given.number_of_leaves());
  CHECK(std::equal(automatic.tetrahedra().begin(), automatic.tetrahedra().end(), given.tetrahedra().begin(),
                   given.tetrahedra().end()));
  const auto s = automatic.statistics();
  CHECK(s.automatic_bucket_size && !given.statistics().automatic_bucket_size);
  CHECK_EQUAL(s.bucket_size, expected.bucket_size);
  const Tree vt(
      in,
      P::parameters::bucket_size(Tree::automatic_bucket_size).bucket_size_relations(P::VERTEX_TETRAHEDRA));
  CHECK_EQUAL(
      vt.bucket_size(),
      P::choose_bucket_size(mesh.points.size(), mesh.tetrahedra.size(), P::VERTEX_TETRAHEDRA).bucket_size);
  CHECK_EQUAL(vt.bucket_size_choice().relations, unsigned(P::VERTEX_TETRAHEDRA));
}

// A hand-checked mesh: the unit cube split into 6 tetrahedra around the diagonal (0,0,0)-(1,1,1),
// plus one tetrahedron listed with negative orientation and one unreferenced vertex.
void test_hand_checked() {
  std::vector<Point> pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1},
                            {1, 0, 1}, {0, 1, 1}, {1, 1, 1}, {2, 0, 0}, {5, 5, 5}};
  // Kuhn triangulation of the cube: the 6 paths from 0 to 7.
  std::vector<std::array<int, 4>> tets = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7},
                                          {0, 4, 5, 7}, {0, 4, 6, 7}, {1, 8, 3, 5}};
  auto in = CGAL::PR_star_octree::make_input(pts, tets);

  // k_v = infinity: one leaf holding everything.
  CGAL::PR_star_octree_3<> single(
      in, CGAL::PR_star_octree::parameters::bucket_size(CGAL::PR_star_octree_3<>::infinite_bucket_size));
  CHECK(single.number_of_nodes() == 1 && single.number_of_leaves() == 1);
  CHECK_EQUAL(single.leaf_tetrahedra(0).size(), tets.size());
  auto s = single.statistics();
  CHECK_EQUAL(s.chi, 1.0);
  CHECK_EQUAL(s.unreferenced_vertices, 1);
  CHECK_EQUAL(s.duplicate_vertices, 0);
  // Hand-computed cost model: |V| = 10, |T| = 7, |N| = 1, chi = 1.
  CHECK(std::abs(s.prstar_overhead_per_vertex - (7.0 + 7.0) / 10) < 1e-12);
  CHECK(std::abs(s.prstar_total_per_vertex - (5.0 * 7 + 30 + 7) / 10) < 1e-12);
  CHECK(std::abs(s.ia_overhead_per_vertex - (28.0 + 10) / 10) < 1e-12);
  CHECK(std::abs(s.ia_total_per_vertex - (56.0 + 40) / 10) < 1e-12);
  check_invariants(single, in, "hand-checked, k_v = inf");

  // Orientation: exactly the tets whose listed order is negative are reoriented.
  std::size_t negative = 0;
  for (auto& c : tets)
    negative += CGAL::orientation(pts[c[0]], pts[c[1]], pts[c[2]], pts[c[3]]) == CGAL::NEGATIVE;
  CHECK_EQUAL(s.reoriented_tetrahedra, negative);
  CHECK(negative > 0 && negative < tets.size());

  // Bounding cube [0,5]^3, mid 2.5: k_v = 9 splits the root once; (5,5,5) goes alone to octant 7
  // (upper faces of the root are closed), the 9 others to octant 0.
  CGAL::PR_star_octree_3<> one(in, CGAL::PR_star_octree::parameters::bucket_size(9));
  CHECK_EQUAL(one.number_of_nodes(), 9);
  CHECK_EQUAL(one.number_of_leaves(), 8);
  CHECK_EQUAL(one.depth(), 1);
  CHECK_EQUAL(one.node(1).number_of_vertices(), 9);
  CHECK_EQUAL(one.node(8).number_of_vertices(), 1);
  CHECK_EQUAL(one.original_vertex(9), 9);
  CHECK_EQUAL(one.statistics().empty_leaves, 6);
  CHECK_EQUAL(one.statistics().chi, 1.0);
  check_invariants(one, in, "hand-checked, k_v = 9");
  // The same through the named-parameter constructor.
  CGAL::PR_star_octree_3<> one_np(in, CGAL::PR_star_octree::parameters::bucket_size(std::size_t(9)));
  CHECK_EQUAL(one_np.bucket_size(), std::size_t(9));
  CHECK_EQUAL(one_np.number_of_nodes(), one.number_of_nodes());
  CHECK_EQUAL(one_np.node(8).number_of_vertices(), std::size_t(1));

  // k_v = 1: every vertex in its own leaf; chi = (6 * 4 + 4) / 7.
  CGAL::PR_star_octree_3<> tiny(in, CGAL::PR_star_octree::parameters::bucket_size(1));
  check_invariants(tiny, in, "hand-checked, k_v = 1");
  CHECK_EQUAL(tiny.statistics().max_leaf_vertices, 1);
  CHECK_EQUAL(tiny.statistics().chi, 4.0);
  // Vertex (2,0,0) and (1,0,0): split at 2.5, 1.25, 0.625 ... they separate at depth 2 (mid 1.25).
  CHECK(tiny.leaf_of_vertex(0) != tiny.leaf_of_vertex(1));
}

void test_duplicates_and_depth() {
  // 100 copies of one point plus a few others: must not split forever, must be reported.
  std::vector<Point> pts(100, Point(0.3, 0.3, 0.3));
  pts.push_back(Point(0, 0, 0));
  pts.push_back(Point(1, 1, 1));
  pts.push_back(Point(0.3, 0.3, std::nextafter(0.3, 1.0))); // distinct, closer than depth 32 can separate
  std::vector<std::array<int, 4>> tets = {{100, 101, 0, 102}};
  auto in = CGAL::PR_star_octree::make_input(pts, tets);
  CGAL::PR_star_octree_3<> tree(in, CGAL::PR_star_octree::parameters::bucket_size(4));
  const auto s = tree.statistics();
  CHECK_EQUAL(s.duplicate_vertices, 99);
  CHECK(s.depth_limited_leaves + s.coincident_leaves >= 1);
  CHECK(s.max_leaf_vertices >= 100);
  CHECK(s.depth <= tree.max_depth());
  CHECK_EQUAL(s.degenerate_tetrahedra, 1);
  check_invariants(tree, in, "duplicates");

  // A small depth bound: leaves over k_v are allowed at the bound, and reported.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point> cloud;
  for (int i = 0; i < 2000; ++i) cloud.emplace_back(u(rng), u(rng), u(rng));
  std::vector<std::array<int, 4>> none;
  auto cin = CGAL::PR_star_octree::make_input(cloud, none);
  CGAL::PR_star_octree_3<> shallow(cin, CGAL::PR_star_octree::parameters::bucket_size(2).maximum_depth(2));
  CHECK_EQUAL(shallow.depth(), 2);
  CHECK(shallow.statistics().depth_limited_leaves > 0);
  CHECK_EQUAL(shallow.number_of_nodes(), 1 + 8 + 64);
  namespace params = CGAL::PR_star_octree::parameters;
  CGAL::PR_star_octree_3<> shallow_np(cin, params::bucket_size(std::size_t(2)).maximum_depth(std::size_t(2)));
  CHECK_EQUAL(shallow_np.max_depth(), std::size_t(2));
  CHECK_EQUAL(shallow_np.number_of_nodes(), std::size_t(1 + 8 + 64));
  CHECK_EQUAL(shallow_np.statistics().depth_limited_leaves, shallow.statistics().depth_limited_leaves);
  check_invariants(shallow, cin, "depth bound 2");

  // Empty mesh and a single point.
  std::vector<Point> empty;
  auto ein = CGAL::PR_star_octree::make_input(empty, none);
  CGAL::PR_star_octree_3<> e(ein, CGAL::PR_star_octree::parameters::bucket_size(10));
  CHECK(e.number_of_leaves() == 1 && e.number_of_vertices() == 0);
}

void test_errors() {
  std::vector<Point> pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  using Tree = CGAL::PR_star_octree_3<>;
  std::vector<std::array<int, 4>> out_of_range = {{0, 1, 2, 4}};
  CHECK_THROWS(std::invalid_argument, "tetrahedron 0 has vertex index 4 out of range",
               (void)Tree(CGAL::PR_star_octree::make_input(pts, out_of_range)));
  std::vector<std::array<int, 4>> negative = {{0, 1, -2, 3}};
  CHECK_THROWS(std::invalid_argument, "has vertex index -2 out of range",
               (void)Tree(CGAL::PR_star_octree::make_input(pts, negative)));
  std::vector<std::array<int, 4>> twice = {{0, 1, 2, 3}, {0, 1, 1, 3}};
  CHECK_THROWS(std::invalid_argument, "tetrahedron 1 lists vertex 1 twice",
               (void)Tree(CGAL::PR_star_octree::make_input(pts, twice)));
  std::vector<std::array<int, 4>> ok = {{0, 1, 2, 3}};
  CHECK_THROWS(std::invalid_argument, "at least 1",
               (void)Tree(CGAL::PR_star_octree::make_input(pts, ok),
                          CGAL::PR_star_octree::parameters::bucket_size(0)));
  std::vector<Point> bad = pts;
  bad[2] = Point(0, std::nan(""), 0);
  CHECK_THROWS(std::invalid_argument, "vertex 2 has a non-finite coordinate",
               (void)Tree(CGAL::PR_star_octree::make_input(bad, ok)));

  // The same refusals when the mesh is moved in, and arrays of the wrong size.
  const auto moved = [&](std::vector<std::array<std::uint32_t, 4>> tets, std::size_t scalars,
                         std::size_t labels) {
    Mesh m;
    m.points = pts;
    m.tetrahedra = std::move(tets);
    if (scalars) m.point_data.push_back({"f", std::vector<double>(scalars, 1.)});
    m.tetrahedron_labels.assign(labels, 1);
    return Tree(std::move(m));
  };
  CHECK_THROWS(std::invalid_argument, "tetrahedron 0 has vertex index 4 out of range",
               (void)moved({{0, 1, 2, 4}}, 0, 0));
  CHECK_THROWS(std::invalid_argument, "tetrahedron 1 lists vertex 1 twice",
               (void)moved({{0, 1, 2, 3}, {0, 1, 1, 3}}, 0, 0));
  CHECK_THROWS(std::invalid_argument, "the scalar field has 3 values for 4 vertices",
               (void)moved({{0, 1, 2, 3}}, 3, 0));
  CHECK_THROWS(std::invalid_argument, "2 labels for 1 tetrahedra", (void)moved({{0, 1, 2, 3}}, 4, 2));
  CHECK_EQUAL(moved({{0, 1, 3, 2}}, 4, 1).statistics().reoriented_tetrahedra, std::size_t(1));
}

// Another traits class (a plain Cartesian kernel) and 64-bit indices, with a scalar field.
void test_other_traits() {
  using SK = CGAL::Simple_cartesian<double>;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<SK::Point_3> pts;
  std::vector<double> f;
  for (int i = 0; i < 500; ++i) {
    pts.emplace_back(u(rng), u(rng), u(rng));
    f.push_back(pts.back().x() * 2 + 1);
  }
  std::vector<std::vector<std::size_t>> tets;
  for (std::size_t i = 0; i + 3 < pts.size(); i += 3) tets.push_back({i, i + 1, i + 2, i + 3});
  auto in = CGAL::PR_star_octree::make_input(pts, tets, f);
  CGAL::PR_star_octree_3<SK, std::uint64_t> tree(in, CGAL::PR_star_octree::parameters::bucket_size(8));
  CHECK(tree.has_scalar_field());
  check_invariants(tree, in, "Simple_cartesian, 64-bit indices");
}

// Coordinates stored as 32-bit floats (issue 24): kept as floats when the input says its coordinates
// are floats, rounded to the nearest float when asked, the octree and the orientations being those
// of the stored values; the same octree as with doubles when the values are floats anyway.
struct Float_point {
  float x_, y_, z_;
  float x() const { return x_; }
  float y() const { return y_; }
  float z() const { return z_; }
};

void test_float_coordinates() {
  using Tree = CGAL::PR_star_octree_3<>;
  namespace params = CGAL::PR_star_octree::parameters;
  using CGAL::PR_star_octree::Coordinate_precision;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  Mesh mesh = shuffled_lattice(12, 2); // 10,368 tetrahedra
  for (Point& p : mesh.points)         // jittered: coordinates that are no floats
    p = Point(p.x() + jitter(rng), p.y() + jitter(rng), p.z() + jitter(rng));
  mesh.point_data.push_back({"f", std::vector<double>(mesh.points.size())});
  for (std::size_t v = 0; v < mesh.points.size(); ++v) mesh.point_data[0].values[v] = mesh.points[v].x();
  // Rounded here, each coordinate by a cast through a volatile float: GCC 12 at -O2 drops the round
  // trip double(float(x)) of two coordinates vectorized together.
  const auto round = [](double x) {
    volatile float f = static_cast<float>(x);
    return double(f);
  };
  Mesh rounded = mesh;
  for (Point& p : rounded.points) p = Point(round(p.x()), round(p.y()), round(p.z()));
  CHECK(!(rounded.points == mesh.points));

  for (std::size_t kv : {std::size_t(1), std::size_t(40)}) {
    const std::string what = "float coordinates, k_v=" + std::to_string(kv);
    // Doubles by default; rounded when asked: the octree of the rounded mesh, 12 bytes per vertex.
    const Tree d(CGAL::PR_star_octree::make_input(mesh), params::bucket_size(kv));
    CHECK(!d.has_float_coordinates());
    const Tree f(CGAL::PR_star_octree::make_input(mesh),
                 params::bucket_size(kv).coordinate_precision(Coordinate_precision::float32));
    CHECK(f.has_float_coordinates());
    check_invariants(f, CGAL::PR_star_octree::make_input(rounded), what + " (rounded)");
    const Tree r(CGAL::PR_star_octree::make_input(rounded), params::bucket_size(kv));
    CHECK(std::equal(f.tetrahedra().begin(), f.tetrahedra().end(), r.tetrahedra().begin(),
                     r.tetrahedra().end()));
    CHECK(f.vertex_permutation() == r.vertex_permutation());
    CHECK_EQUAL(f.number_of_leaves(), r.number_of_leaves());
    const auto fs = f.statistics(), rs = r.statistics();
    CHECK(fs.float32_coordinates && !rs.float32_coordinates);
    CHECK_EQUAL(fs.bytes.points, 12 * mesh.points.size());
    CHECK_EQUAL(rs.bytes.points, sizeof(Point) * mesh.points.size());
    CHECK_EQUAL(fs.leaf_tetrahedra_entries, rs.leaf_tetrahedra_entries);

    // An input of floats stays floats (the flag of a reader, or float points), unless asked.
    Mesh flagged = rounded;
    flagged.float32_points = true;
    const Tree a(CGAL::PR_star_octree::make_input(flagged), params::bucket_size(kv));
    CHECK(a.has_float_coordinates());
    check_invariants(a, CGAL::PR_star_octree::make_input(rounded), what + " (float input)");
    const Tree b(CGAL::PR_star_octree::make_input(flagged),
                 params::bucket_size(kv).coordinate_precision(Coordinate_precision::point_3));
    CHECK(!b.has_float_coordinates());
    Mesh moved = flagged;
    const Tree c(std::move(moved), params::bucket_size(kv).compact_tetrahedra(true));
    CHECK(c.has_float_coordinates() && c.is_compact());
    check_invariants(c, CGAL::PR_star_octree::make_input(rounded), what + " (float input, moved, compact)");
    std::vector<Float_point> fp;
    for (const Point& p : rounded.points) fp.push_back({float(p.x()), float(p.y()), float(p.z())});
    const Tree e(CGAL::PR_star_octree::make_input(fp, rounded.tetrahedra), params::bucket_size(kv));
    CHECK(e.has_float_coordinates());
    CHECK(std::equal(e.points().begin(), e.points().end(), r.points().begin(), r.points().end()));
    CHECK(e.points().size() == r.number_of_vertices() && e.points()[5] == r.point(5));
  }

  // Rounding decides the orientation: a sliver of height 1e-50 is flat in floats (counted as
  // degenerate, kept as given) and negative in doubles (reoriented).
  std::vector<Point> pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, -1e-50}};
  const std::vector<std::array<int, 4>> one = {{0, 1, 2, 3}};
  const Tree dd(CGAL::PR_star_octree::make_input(pts, one));
  CHECK_EQUAL(dd.statistics().reoriented_tetrahedra, std::size_t(1));
  CHECK_EQUAL(dd.statistics().degenerate_tetrahedra, std::size_t(0));
  const Tree ff(CGAL::PR_star_octree::make_input(pts, one),
                params::coordinate_precision(Coordinate_precision::float32));
  CHECK_EQUAL(ff.statistics().reoriented_tetrahedra, std::size_t(0));
  CHECK_EQUAL(ff.statistics().degenerate_tetrahedra, std::size_t(1));
  CHECK(!ff.is_reoriented(0) && dd.is_reoriented(0));
  bool z_zero = false;
  for (std::size_t v = 0; v < 4; ++v)
    z_zero = z_zero || (ff.point(Tree::Index(v)).x() == 0.25 && ff.point(Tree::Index(v)).z() == 0.);
  CHECK(z_zero);
  // A coordinate beyond the floats' range is refused, not made infinite.
  pts[1] = Point(1e300, 0, 0);
  CHECK_THROWS(std::invalid_argument, "vertex 1 has a coordinate beyond the range of a 32-bit float",
               (void)Tree(CGAL::PR_star_octree::make_input(pts, one),
                          params::coordinate_precision(Coordinate_precision::float32)));
  CHECK_EQUAL(Tree(CGAL::PR_star_octree::make_input(pts, one)).number_of_vertices(), std::size_t(4));
}

// The streaming construction (issue 24): the tetrahedra from a source read several times, a slab of
// smallest vertices at a time; the same octree as the in-place construction with the compact T, on
// a shuffled lattice with labels, a scalar field and reoriented tetrahedra, at several slab sizes
// and chunk sizes; the errors.
template <class Source>
struct Uncounted { // a tetrahedron source without number_of_tetrahedra()
  const Source& source;
  template <class F>
  void for_each_chunk(F f) const {
    source.for_each_chunk(f);
  }
};

template <class Source>
struct Miscounted { // a tetrahedron source whose count is not what it gives
  const Source& source;
  std::size_t count;
  std::size_t number_of_tetrahedra() const { return count; }
  template <class F>
  void for_each_chunk(F f) const {
    source.for_each_chunk(f);
  }
};

void test_streaming_construction() {
  using Tree = CGAL::PR_star_octree_3<>;
  namespace params = CGAL::PR_star_octree::parameters;
  using Tets = std::vector<std::array<std::uint32_t, 4>>;
  using Source = CGAL::PR_star_octree::Tetrahedron_range_source<Tets>;
  Mesh mesh = shuffled_lattice(14, 8); // 16,464 tetrahedra
  std::mt19937 rng(2);
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); t += 3)
    std::swap(mesh.tetrahedra[t][0], mesh.tetrahedra[t][1]);
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) mesh.tetrahedron_labels.push_back(int(rng() % 3));
  mesh.point_data.push_back({"f", std::vector<double>(mesh.points.size())});
  for (std::size_t v = 0; v < mesh.points.size(); ++v) mesh.point_data[0].values[v] = mesh.points[v].y() * 3;
  // a tetrahedron's vertices with its label, sorted: the same whatever its index
  const auto keyed = [](const Tree& tree, std::size_t t) {
    std::array<std::uint32_t, 5> k{};
    const auto c = tree.tetrahedron(Tree::Index(t));
    for (int i = 0; i < 4; ++i) k[i] = tree.original_vertex(c[i]);
    std::sort(k.begin(), k.begin() + 4);
    k[4] = std::uint32_t(tree.tetrahedron_label(Tree::Index(t)));
    return k;
  };
  for (std::size_t kv : {std::size_t(1), std::size_t(30)})
    for (std::size_t slab : {std::size_t(1), std::size_t(777), std::size_t(0)}) {
      const std::string what = "streaming, k_v=" + std::to_string(kv) + ", slab " + std::to_string(slab);
      const prstar_test::Failure_context context(what);
      const Tree a(CGAL::PR_star_octree::make_input(mesh), params::bucket_size(kv).compact_tetrahedra(true));
      Mesh vertices = mesh;
      const Tets tets = std::move(vertices.tetrahedra);
      const std::vector<int> labels = std::move(vertices.tetrahedron_labels);
      vertices.tetrahedra.clear();
      vertices.tetrahedron_labels.clear();
      const Source source(tets, &labels, slab == 777 ? 1000 : 64);
      // a source that does not count its tetrahedra (read once more, to count them) for slab 777
      const Tree b = slab == 777
                         ? Tree(std::move(vertices), Uncounted<Source>{source},
                                params::bucket_size(kv).slab_tetrahedra(slab))
                         : Tree(std::move(vertices), source, params::bucket_size(kv).slab_tetrahedra(slab));
      CHECK(b.is_compact() && !b.has_tetrahedron_permutation());
      CHECK(b.vertex_permutation() == a.vertex_permutation());
      CHECK(std::equal(b.points().begin(), b.points().end(), a.points().begin(), a.points().end()));
      CHECK(b.scalars() == a.scalars());
      CHECK_EQUAL(b.number_of_tetrahedra(), a.number_of_tetrahedra());
      // the same tetrahedra (vertices in the same order, as oriented), each smallest vertex's in
      // the source's order; and the same labels
      std::vector<std::array<std::uint32_t, 4>> ta(a.tetrahedra().begin(), a.tetrahedra().end()),
          tb(b.tetrahedra().begin(), b.tetrahedra().end());
      bool sorted_by_smallest = true;
      for (std::size_t t = 1; t < tb.size(); ++t)
        sorted_by_smallest = sorted_by_smallest && *std::min_element(tb[t - 1].begin(), tb[t - 1].end()) <=
                                                       *std::min_element(tb[t].begin(), tb[t].end());
      CHECK(sorted_by_smallest);
      std::sort(ta.begin(), ta.end());
      std::sort(tb.begin(), tb.end());
      CHECK(ta == tb);
      const auto sa = a.statistics(), sb = b.statistics();
      CHECK_EQUAL(sb.reoriented_tetrahedra, sa.reoriented_tetrahedra);
      CHECK(sb.reoriented_tetrahedra > 0);
      CHECK_EQUAL(sb.leaf_tetrahedra_entries, sa.leaf_tetrahedra_entries);
      CHECK(sb.subdomains == sa.subdomains);
      // each leaf lists the same tetrahedra (by their vertices and label); the reorientation bits
      // give back the user's vertex order
      CHECK_EQUAL(b.number_of_leaves(), a.number_of_leaves());
      bool same_leaves = true, same_user_order = true;
      std::map<std::array<std::uint32_t, 4>, std::array<std::uint32_t, 4>> user; // sorted -> as listed
      for (const auto& c : tets) {
        std::array<std::uint32_t, 4> k = c;
        std::sort(k.begin(), k.end());
        user[k] = c;
      }
      for (std::size_t l = 0; l < a.number_of_leaves(); ++l) {
        std::vector<std::array<std::uint32_t, 5>> la, lb;
        for (auto t : a.leaf_tetrahedra(a.leaves()[l])) la.push_back(keyed(a, t));
        for (auto t : b.leaf_tetrahedra(b.leaves()[l])) lb.push_back(keyed(b, t));
        std::sort(la.begin(), la.end());
        std::sort(lb.begin(), lb.end());
        same_leaves = same_leaves && la == lb;
      }
      for (std::size_t t = 0; t < b.number_of_tetrahedra(); ++t) {
        const std::array<std::uint32_t, 4> orig = b.original_tetrahedron_vertices(Tree::Index(t)); // user's
        std::array<std::uint32_t, 4> k = orig;
        std::sort(k.begin(), k.end());
        same_user_order = same_user_order && user[k] == orig;
      }
      CHECK(same_leaves);
      CHECK(same_user_order);
    }

  // Errors: named with the tetrahedron, before anything is built; tetrahedra in the mesh refused.
  std::vector<Point> pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  for (bool counted : {true, false}) {
    const auto build = [&](Tets t, std::size_t chunk) {
      Mesh m;
      m.points = pts;
      const Source src(t, nullptr, chunk);
      return counted ? Tree(std::move(m), src, params::default_values())
                     : Tree(std::move(m), Uncounted<Source>{src}, params::default_values());
    };
    CHECK_THROWS(std::invalid_argument, "tetrahedron 2 has vertex index 5 out of range",
                 (void)build({{0, 1, 2, 3}, {1, 2, 3, 4}, {0, 1, 2, 5}}, 2));
    CHECK_THROWS(std::invalid_argument, "tetrahedron 1 lists vertex 3 twice",
                 (void)build({{0, 1, 2, 3}, {1, 3, 3, 4}}, 1));
    CHECK_EQUAL(build({{0, 1, 2, 3}, {1, 2, 4, 3}}, 1).number_of_tetrahedra(), std::size_t(2));
    CHECK_EQUAL(build({}, 1).number_of_tetrahedra(), std::size_t(0));
  }
  { // a source whose count is not what it gives
    Mesh m;
    m.points = pts;
    const Tets two = {{0, 1, 2, 3}, {1, 2, 4, 3}};
    const Source src(two);
    CHECK_THROWS(std::invalid_argument, "gave 2 tetrahedra, not the 3 it counted",
                 (void)Tree(std::move(m), Miscounted<Source>{src, 3}, params::default_values()));
  }
  Mesh with_tets;
  with_tets.points = pts;
  with_tets.tetrahedra = {{{0, 1, 2, 3}}};
  const Tets none;
  CHECK_THROWS(std::invalid_argument, "takes the tetrahedra and their labels from the source",
               (void)Tree(std::move(with_tets), Source(none), params::default_values()));
}

// chi and |N| fall as k_v grows (paper Table 1), on a generated mesh.
void test_table1_behaviour(const Mesh& mesh, const std::string& what) {
  auto in = CGAL::PR_star_octree::make_input(mesh);
  double prev_chi = 5;
  std::size_t prev_nodes = std::size_t(-1);
  for (std::size_t kv : {std::size_t(10), std::size_t(20), std::size_t(50), std::size_t(100),
                         std::size_t(200), CGAL::PR_star_octree_3<>::infinite_bucket_size}) {
    CGAL::PR_star_octree_3<> tree(in, CGAL::PR_star_octree::parameters::bucket_size(kv));
    const auto s = tree.statistics();
    std::cout << "  " << what << " k_v=" << (kv > 1000000 ? std::string("inf") : std::to_string(kv))
              << " |N|=" << s.nodes << " |N_leaf|=" << s.leaves << " chi=" << s.chi << "\n";
    CHECK(s.chi <= prev_chi + 0.05); // allow tiny non-monotonic wiggles between close k_v
    CHECK(s.nodes <= prev_nodes);
    prev_chi = s.chi;
    prev_nodes = s.nodes;
  }
  CHECK_EQUAL(prev_chi, 1.0);
}

} // namespace

int main(int argc, char** argv) {
  const prstar_test::Data_folders data(argc, argv);

  test_hand_checked();
  test_duplicates_and_depth();
  test_errors();
  test_other_traits();
  test_radix_sort_in_place();
  test_parallel_bucket_permutation();
  test_compact_leaf_lists();
  test_compact_tetrahedra();
  test_automatic_bucket_size();
  test_float_coordinates();
  test_streaming_construction();

  // Generated meshes (CGAL Mesh_3 and TetGen, made by the test fixture).
  for (const char* name :
       {"sphere.mesh", "torus.mesh", "cube.mesh", "sphere_tetgen.mesh", "cube_tetgen.vtu"}) {
    const auto file = data.generated_file(name);
    if (!file) continue;
    Mesh mesh;
    CGAL::PR_star_octree::IO::read_tetrahedral_mesh(*file, mesh);
    CHECK(mesh.tetrahedra.size() > 1000);
    for (std::size_t kv : {std::size_t(1), std::size_t(7), std::size_t(50), std::size_t(400)})
      check_shuffle_invariance(mesh, kv, std::string(name) + " k_v=" + std::to_string(kv));
    for (std::size_t kv : {std::size_t(1), std::size_t(50)})
      check_lean_construction(mesh, kv, std::string(name) + " k_v=" + std::to_string(kv));
    test_table1_behaviour(mesh, name);
  }

  // Real meshes made by others, when present.
  if (data.report_shared()) {
    for (const char* name : {"spx_zsweep.off", "armadillo_sofa.vtu", "bunny_sofa.vtu", "skull_14k.off",
                             "t13_data.1.node", "part1.1.node"}) {
      const auto file = data.shared_file(name);
      if (!file) continue;
      Mesh mesh;
      CGAL::PR_star_octree::IO::read_tetrahedral_mesh(*file, mesh);
      for (std::size_t kv : {std::size_t(3), std::size_t(20), std::size_t(200)})
        check_shuffle_invariance(mesh, kv, std::string(name) + " k_v=" + std::to_string(kv));
      if (std::string(name) == "spx_zsweep.off") {
        CGAL::PR_star_octree_3<> t(CGAL::PR_star_octree::make_input(mesh),
                                   CGAL::PR_star_octree::parameters::bucket_size(20));
        // The data README: 12,924 of the 12,936 tets are listed with negative orientation.
        CHECK_EQUAL(t.statistics().reoriented_tetrahedra, std::size_t(12924));
        CHECK(t.has_scalar_field());
      }
    }
  }
  return prstar_test::summary("test_octree");
}
