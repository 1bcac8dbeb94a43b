// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Scalar-field topology (scalar_topology.h) against answers written here: closed forms on
// generated lattices (a bowl, Gaussian bumps, a linear field), the Euler characteristic, and
// brute-force references computed in this file from the tetrahedra alone: the critical type of
// every vertex from its link, the persistence pairs by a union-find over the whole vertex graph in
// the field order, and the gradient's validity and acyclicity by a traversal of the Hasse diagram.
// Every result must be the same for k_v = 1 ... infinite and for one or several threads.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/scalar_topology.h>
#include <CGAL/property_map.h>

#include "test_harness.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace prstar_test_meshes {
CGAL::PR_star_octree::Indexed_tetrahedral_mesh<> cube_grid(int n); // test_curvature_closed_forms.cpp
}

namespace {

using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;
using Octree = CGAL::PR_star_octree_3<>;
using CGAL::PR_star_octree::Critical_type;
using CGAL::PR_star_octree::Persistence_pair;
namespace PSO = CGAL::PR_star_octree;
namespace params = CGAL::PR_star_octree::parameters;
using Simplex = std::array<std::size_t, 4>;
const std::size_t none = PSO::Critical_simplex::no_vertex;

// The field order of the test: (value, index).
struct Order {
  const std::vector<double>* f;
  bool operator()(std::size_t a, std::size_t b) const {
    return (*f)[a] < (*f)[b] || ((*f)[a] == (*f)[b] && a < b);
  }
};

// ---------------------------------------------------------------------------------------------
// Brute-force references, from the list of tetrahedra alone.

// The stars of the vertices (tetrahedron indices), by scanning T.
std::vector<std::vector<std::size_t>> stars(const Mesh& m) {
  std::vector<std::vector<std::size_t>> s(m.points.size());
  for (std::size_t t = 0; t < m.tetrahedra.size(); ++t)
    for (auto v : m.tetrahedra[t]) s[v].push_back(t);
  return s;
}

// Lower and upper link components of every vertex: a depth-first search over the link edges.
std::vector<std::pair<unsigned, unsigned>> link_components(const Mesh& m, const std::vector<double>& f) {
  const Order less{&f};
  const auto st = stars(m);
  std::vector<std::pair<unsigned, unsigned>> result(m.points.size(), {0u, 0u});
  for (std::size_t v = 0; v < m.points.size(); ++v) {
    std::map<std::size_t, std::set<std::size_t>> graph; // link vertex -> link neighbours of the same side
    for (auto t : st[v]) {
      std::vector<std::size_t> o;
      for (auto u : m.tetrahedra[t])
        if (u != v) o.push_back(u);
      for (auto u : o) graph[u];
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          if (a != b && less(o[a], v) == less(o[b], v)) graph[o[a]].insert(o[b]);
    }
    std::set<std::size_t> seen;
    for (const auto& g : graph) {
      if (seen.count(g.first)) continue;
      (less(g.first, v) ? result[v].first : result[v].second)++;
      std::vector<std::size_t> stack{g.first};
      seen.insert(g.first);
      while (!stack.empty()) {
        const std::size_t u = stack.back();
        stack.pop_back();
        for (auto w : graph[u])
          if (seen.insert(w).second) stack.push_back(w);
      }
    }
  }
  return result;
}

// The persistence pairs of the extrema by a union-find over the vertex graph in the field order
// (and in the reverse order for the maxima), the elder rule at each vertex.
std::vector<std::tuple<int, std::size_t, std::size_t>>
persistence_by_union_find(const Mesh& m, const std::vector<double>& f) {
  const Order less{&f};
  std::vector<std::set<std::size_t>> adj(m.points.size());
  for (const auto& t : m.tetrahedra)
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        if (a != b) adj[t[a]].insert(t[b]);
  std::vector<std::tuple<int, std::size_t, std::size_t>> pairs;
  for (int type = 0; type < 2; ++type) {
    std::vector<std::size_t> order(m.points.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return type == 0 ? less(a, b) : less(b, a); });
    auto before = [&](std::size_t a, std::size_t b) { return type == 0 ? less(a, b) : less(b, a); };
    std::vector<std::size_t> parent(m.points.size()), oldest(m.points.size());
    std::vector<char> done(m.points.size(), 0);
    std::function<std::size_t(std::size_t)> find = [&](std::size_t x) {
      return parent[x] == x ? x : parent[x] = find(parent[x]);
    };
    for (std::size_t v : order) {
      if (adj[v].empty()) continue;
      parent[v] = v;
      oldest[v] = v;
      done[v] = 1;
      std::set<std::size_t> roots;
      for (auto u : adj[v])
        if (done[u]) roots.insert(find(u));
      if (roots.empty()) continue;
      std::size_t elder = *roots.begin();
      for (auto r : roots)
        if (before(oldest[r], oldest[elder])) elder = r;
      for (auto r : roots)
        if (r != elder) pairs.emplace_back(type, oldest[r], v);
      for (auto r : roots) parent[r] = elder;
      parent[v] = elder;
    }
    for (std::size_t v = 0; v < m.points.size(); ++v)
      if (done[v] && find(v) == v) pairs.emplace_back(type, oldest[v], none);
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

// Every simplex of the mesh (sorted vertices, unused entries `none`), by dimension.
std::array<std::set<Simplex>, 4> all_simplices(const Mesh& m) {
  std::array<std::set<Simplex>, 4> s;
  for (const auto& t : m.tetrahedra) {
    std::array<std::size_t, 4> c{{t[0], t[1], t[2], t[3]}};
    std::sort(c.begin(), c.end());
    for (unsigned mask = 1; mask < 16; ++mask) {
      Simplex x{{none, none, none, none}};
      int k = 0;
      for (int i = 0; i < 4; ++i)
        if (mask & (1u << i)) x[k++] = c[i];
      s[k - 1].insert(x);
    }
  }
  return s;
}

int dimension(const Simplex& s) {
  int k = 0;
  while (k < 4 && s[k] != none) ++k;
  return k - 1;
}

// The gradient's pairs against the mesh: each pair a face of codimension one with the same highest
// vertex, each simplex in at most one pair, the unpaired ones exactly the critical simplices, and
// no closed V-path (a topological order of the modified Hasse diagram exists).
void check_gradient(const Mesh& m, const std::vector<double>& f,
                    const std::vector<std::pair<Simplex, Simplex>>& pairs,
                    const std::vector<PSO::Critical_simplex>& critical, const std::string& what) {
  const Order less{&f};
  const auto simplices = all_simplices(m);
  std::map<Simplex, Simplex> partner;
  bool valid = true;
  for (const auto& p : pairs) {
    const Simplex &a = p.first, &b = p.second;
    const int da = dimension(a), db = dimension(b);
    bool face = db == da + 1 && simplices[da].count(a) && simplices[db].count(b);
    for (int i = 0; face && i <= da; ++i)
      face = std::find(b.begin(), b.begin() + db + 1, a[i]) != b.begin() + db + 1;
    auto highest = [&](const Simplex& s) {
      std::size_t h = s[0];
      for (int i = 1; i <= dimension(s); ++i)
        if (less(h, s[i])) h = s[i];
      return h;
    };
    if (!face || highest(a) != highest(b) || !partner.emplace(a, b).second || !partner.emplace(b, a).second) {
      valid = false;
      break;
    }
  }
  CHECK_MSG(valid, what << ": the pairs are faces one dimension apart in one lower star, each simplex once");
  std::set<Simplex> unpaired, listed;
  for (int d = 0; d < 4; ++d)
    for (const auto& s : simplices[d])
      if (!partner.count(s)) unpaired.insert(s);
  for (const auto& c : critical) {
    Simplex s = c.vertices;
    std::sort(s.begin(), s.end()); // the unused entries (no_vertex) last
    listed.insert(s);
  }
  CHECK_MSG(unpaired == listed, what << ": " << unpaired.size() << " unpaired simplices, " << listed.size()
                                     << " listed as critical");
  // Kahn's algorithm on the modified Hasse diagram: tau -> sigma for each facet sigma of tau, reversed
  // (sigma -> tau) when they are paired.
  std::map<Simplex, std::vector<Simplex>> out;
  std::map<Simplex, int> indegree;
  for (int d = 0; d < 4; ++d)
    for (const auto& s : simplices[d]) indegree[s];
  for (int d = 1; d < 4; ++d)
    for (const auto& t : simplices[d])
      for (int drop = 0; drop <= d; ++drop) {
        Simplex s{{none, none, none, none}};
        int k = 0;
        for (int i = 0; i <= d; ++i)
          if (i != drop) s[k++] = t[i];
        const auto it = partner.find(s);
        if (it != partner.end() && it->second == t) {
          out[s].push_back(t);
          ++indegree[t];
        } else {
          out[t].push_back(s);
          ++indegree[s];
        }
      }
  std::vector<Simplex> ready;
  for (const auto& x : indegree)
    if (x.second == 0) ready.push_back(x.first);
  std::size_t visited = 0;
  while (!ready.empty()) {
    const Simplex s = ready.back();
    ready.pop_back();
    ++visited;
    for (const auto& t : out[s])
      if (--indegree[t] == 0) ready.push_back(t);
  }
  CHECK_MSG(visited == indegree.size(), what << ": the gradient has a closed V-path ("
                                             << indegree.size() - visited << " simplices on cycles)");
}

long long euler(const Mesh& m) {
  const auto s = all_simplices(m);
  return static_cast<long long>(s[0].size()) - static_cast<long long>(s[1].size()) +
         static_cast<long long>(s[2].size()) - static_cast<long long>(s[3].size());
}

// ---------------------------------------------------------------------------------------------
// Everything the package computes, in a form that compares across k_v and threads.

struct Result {
  std::vector<Critical_type> types;
  PSO::Critical_point_counts counts;
  std::vector<PSO::Critical_point> points;
  std::vector<PSO::Critical_simplex> critical;
  std::vector<std::pair<Simplex, Simplex>> pairs;
  std::vector<std::tuple<int, std::size_t, std::size_t>> persistence;
  std::vector<std::size_t> ascending, descending;
  std::size_t arcs = 0;
  std::vector<std::size_t> arc_ends;
  long long euler = 0;

  bool operator==(const Result& o) const {
    auto same_points = [&] {
      if (points.size() != o.points.size()) return false;
      for (std::size_t i = 0; i < points.size(); ++i)
        if (points[i].vertex != o.points[i].vertex || points[i].type != o.points[i].type ||
            points[i].lower_components != o.points[i].lower_components ||
            points[i].upper_components != o.points[i].upper_components)
          return false;
      return true;
    };
    auto same_critical = [&] {
      if (critical.size() != o.critical.size()) return false;
      for (std::size_t i = 0; i < critical.size(); ++i)
        if (critical[i].vertices != o.critical[i].vertices) return false;
      return true;
    };
    return types == o.types && same_points() && same_critical() && pairs == o.pairs &&
           persistence == o.persistence && euler == o.euler && ascending == o.ascending &&
           descending == o.descending && arcs == o.arcs && arc_ends == o.arc_ends;
  }
};

template <class Tag>
Result compute(const Mesh& mesh, const std::vector<double>& f, std::size_t kv, double threshold) {
  Result r;
  const Octree tree(PSO::make_input(mesh), params::bucket_size(kv));
  const auto field = CGAL::make_property_map(f);
  r.types.assign(mesh.points.size(), Critical_type::REGULAR);
  r.counts = PSO::compute_critical_points<Tag>(tree, field, CGAL::make_property_map(r.types),
                                               params::critical_points_output(std::back_inserter(r.points)));
  const auto g = PSO::compute_forman_gradient<Tag>(tree, field);
  r.critical = g.critical_simplices();
  r.euler = g.euler_characteristic();
  PSO::forman_gradient_pairs(tree, g, std::back_inserter(r.pairs));
  std::sort(r.pairs.begin(), r.pairs.end());
  std::vector<PSO::Morse_arc> arcs;
  const auto mc = PSO::compute_morse_complexes<Tag>(
      tree, field, params::persistence_threshold(threshold).arcs_output(std::back_inserter(arcs)));
  for (const auto& p : mc.persistence_pairs) r.persistence.emplace_back(int(p.type), p.extremum, p.saddle);
  std::sort(r.persistence.begin(), r.persistence.end());
  r.ascending = mc.ascending_cell;
  r.descending = mc.descending_cell;
  r.arcs = arcs.size();
  for (const auto& a : arcs) r.arc_ends.push_back(a.extremum);
  // the Morse complexes' gradient is the gradient
  CHECK(mc.gradient.critical_simplices().size() == g.critical_simplices().size());
  CHECK(mc.critical_type == r.types);
  return r;
}

std::vector<double> sample(const Mesh& m, double (*f)(double, double, double)) {
  std::vector<double> v;
  for (const auto& p : m.points) v.push_back(f(p.x(), p.y(), p.z()));
  return v;
}

// The checks every mesh and field goes through: the package against the brute-force references,
// and the same result for k_v in {1, 8, 50, infinite} and sequential or parallel leaves.
Result check_against_references(const Mesh& m, const std::vector<double>& f, const std::string& what,
                                double threshold = 0) {
  const Result r = compute<CGAL::Sequential_tag>(m, f, 50, threshold);
  // critical types from the links
  const auto comps = link_components(m, f);
  std::size_t wrong = 0;
  for (std::size_t v = 0; v < comps.size(); ++v)
    wrong += r.types[v] != PSO::classify_critical_point(comps[v].first, comps[v].second);
  CHECK_MSG(wrong == 0, what << ": " << wrong << " vertices of another critical type than their links say");
  for (const auto& p : r.points)
    CHECK(p.lower_components == comps[p.vertex].first && p.upper_components == comps[p.vertex].second);
  // the gradient
  const long long chi = euler(m);
  std::array<long long, 4> c{{0, 0, 0, 0}};
  for (const auto& s : r.critical) ++c[static_cast<std::size_t>(s.dimension)];
  CHECK_MSG(c[0] - c[1] + c[2] - c[3] == chi, what << ": critical simplices " << c[0] << ", " << c[1] << ", "
                                                   << c[2] << ", " << c[3] << "; Euler characteristic "
                                                   << chi);
  CHECK_MSG(r.euler == chi,
            what << ": the gradient counts the Euler characteristic " << r.euler << ", not " << chi);
  check_gradient(m, f, r.pairs, r.critical, what);
  // persistence
  const auto reference = persistence_by_union_find(m, f);
  CHECK_MSG(r.persistence == reference, what << ": " << r.persistence.size() << " persistence pairs, "
                                             << reference.size() << " by the union-find of the test");
  // the critical vertices of the gradient are the minima
  std::size_t minima = 0;
  for (auto t : r.types) minima += t == Critical_type::MINIMUM;
  CHECK_EQUAL(static_cast<std::size_t>(c[0]), minima);
  // the same for any k_v and thread count
  for (std::size_t kv : {std::size_t(1), std::size_t(8), Octree::infinite_bucket_size}) {
    CHECK_MSG(compute<CGAL::Sequential_tag>(m, f, kv, threshold) == r,
              what << ": another result at k_v " << kv);
  }
#ifdef CGAL_LINKED_WITH_TBB
  CHECK_MSG(compute<CGAL::Parallel_tag>(m, f, 1, threshold) == r,
            what << ": another result in parallel (k_v 1)");
  CHECK_MSG(compute<CGAL::Parallel_tag>(m, f, 50, threshold) == r, what << ": another result in parallel");
#endif
  return r;
}

std::size_t grid_id(int n, int x, int y, int z) {
  return static_cast<std::size_t>(x + (n + 1) * (y + (n + 1) * z));
}
bool interior(int n, const Mesh::Point_3& p) {
  auto in = [n](double c) { return c > 0 && c < n; };
  return in(p.x()) && in(p.y()) && in(p.z());
}

// A quadratic bowl: one minimum, at the grid vertex nearest its centre, no other interior critical
// point; the minima's cells: one, everywhere.
void test_bowl() {
  const int n = 8;
  const Mesh m = prstar_test_meshes::cube_grid(n);
  const std::vector<double> f = sample(m, [](double x, double y, double z) {
    return (x - 3.3) * (x - 3.3) + (y - 4.6) * (y - 4.6) + 1.5 * (z - 3.8) * (z - 3.8);
  });
  const Result r = check_against_references(m, f, "bowl");
  std::size_t minima = 0, interior_critical = 0;
  for (std::size_t v = 0; v < m.points.size(); ++v) {
    minima += r.types[v] == Critical_type::MINIMUM;
    if (interior(n, m.points[v]) && r.types[v] != Critical_type::REGULAR) ++interior_critical;
  }
  CHECK_EQUAL(minima, std::size_t(1));
  CHECK_EQUAL(interior_critical, std::size_t(1));
  CHECK(r.types[grid_id(n, 3, 5, 4)] == Critical_type::MINIMUM);
  for (auto a : r.ascending) CHECK_EQUAL(a, grid_id(n, 3, 5, 4));
  // one essential minimum-saddle pair and nothing else of that kind
  std::size_t min_pairs = 0;
  for (const auto& p : r.persistence) min_pairs += std::get<0>(p) == 0;
  CHECK_EQUAL(min_pairs, std::size_t(1));
}

// Three separated Gaussian bumps on a small background: one interior maximum at each (the grid
// vertex nearest its centre), the 2-saddles between them; with a threshold of 5% of the range the
// persistence pairs above it are the two bumps' (saddle, maximum) pairs and the essential one,
// and the tetrahedra fall into three descending cells around the three maxima.
void test_bumps() {
  const int n = 12;
  const Mesh m = prstar_test_meshes::cube_grid(n);
  struct Bump {
    double x, y, z, height;
  };
  static const Bump bumps[3] = {{3.1, 3.2, 6.1, 2.0}, {8.9, 3.3, 5.8, 1.5}, {6.2, 8.8, 6.3, 1.0}};
  auto bump_field = [](double x, double y, double z) {
    double s = 0.02 * z; // a gentle slope: no flat background
    for (const auto& b : bumps) {
      const double d2 = (x - b.x) * (x - b.x) + (y - b.y) * (y - b.y) + (z - b.z) * (z - b.z);
      s += b.height * std::exp(-d2 / 4.0);
    }
    return s;
  };
  std::vector<double> f;
  for (const auto& p : m.points) f.push_back(bump_field(p.x(), p.y(), p.z()));
  double lo = f[0], hi = f[0];
  for (double x : f) lo = std::min(lo, x), hi = std::max(hi, x);
  const double threshold = 0.05 * (hi - lo);
  const Result r = check_against_references(m, f, "bumps", threshold);
  std::size_t interior_maxima = 0;
  for (std::size_t v = 0; v < m.points.size(); ++v)
    if (interior(n, m.points[v]) && r.types[v] == Critical_type::MAXIMUM) ++interior_maxima;
  CHECK_EQUAL(interior_maxima, std::size_t(3));
  const std::size_t peak[3] = {grid_id(n, 3, 3, 6), grid_id(n, 9, 3, 6), grid_id(n, 6, 9, 6)};
  for (auto p : peak) CHECK(r.types[p] == Critical_type::MAXIMUM);
  // persistence above 5%: two saddle-maximum pairs (the lower bumps) and the essential maximum
  const Octree tree(PSO::make_input(m));
  const auto mc = PSO::compute_morse_complexes(tree, CGAL::make_property_map(f),
                                               params::persistence_threshold(threshold));
  std::vector<std::size_t> strong, essential;
  for (const auto& p : mc.persistence_pairs) {
    if (p.type != Persistence_pair::SADDLE_MAXIMUM) continue;
    if (p.is_essential())
      essential.push_back(p.extremum);
    else if (p.persistence() >= threshold)
      strong.push_back(p.extremum);
  }
  std::sort(strong.begin(), strong.end());
  CHECK_EQUAL(essential, std::vector<std::size_t>{peak[0]});
  CHECK_EQUAL(strong, (std::vector<std::size_t>{peak[1], peak[2]})); // by index
  // the descending cells after the cancellations: the three peaks (and the outflow through the
  // boundary, -1)
  std::set<std::size_t> cells(mc.descending_cell.begin(), mc.descending_cell.end());
  cells.erase(PSO::Morse_complexes<Octree>::no_cell);
  CHECK_EQUAL(cells, (std::set<std::size_t>{peak[0], peak[1], peak[2]}));
  CHECK_EQUAL(mc.descending_cells, std::size_t(3));
  // each peak's cell holds the tetrahedra around it
  for (auto p : peak)
    for (std::size_t t = 0; t < m.tetrahedra.size(); ++t) {
      const auto& c = m.tetrahedra[t];
      if (std::find(c.begin(), c.end(), p) == c.end()) continue;
      CHECK_EQUAL(mc.descending_cell[t], p);
    }
}

// A field of x alone (ties broken by the index): no interior critical point; the lower-star
// filtration of a convex domain by a linear function is contractible at every step, so the
// gradient has one critical simplex, the lowest vertex.
void test_linear() {
  const int n = 6;
  const Mesh m = prstar_test_meshes::cube_grid(n);
  const std::vector<double> f = sample(m, [](double x, double, double) { return x; });
  const Result r = check_against_references(m, f, "f = x");
  for (std::size_t v = 0; v < m.points.size(); ++v)
    if (interior(n, m.points[v])) CHECK(r.types[v] == Critical_type::REGULAR);
  CHECK_EQUAL(r.critical.size(), std::size_t(1));
  CHECK_EQUAL(r.critical.front().vertices[0], std::size_t(0));
}

// Every generated and shared test mesh with a bumpy field: the references, the Euler relation.
void test_files(const prstar_test::Data_folders& data) {
  std::vector<std::string> files;
  for (const char* name : {"cube.mesh", "sphere.mesh", "torus.mesh", "cube_tetgen.vtu"})
    if (auto p = data.generated_file(name)) files.push_back(*p);
  if (data.report_shared())
    for (const char* name : {"t13_data.1.node"})
      if (auto p = data.shared_file(name)) files.push_back(*p);
  for (const auto& path : files) {
    Mesh m;
    try {
      CGAL::PR_star_octree::IO::read_tetrahedral_mesh(path, m);
    } catch (const std::exception& e) {
      FAIL(path << ": " << e.what());
      continue;
    }
    if (m.tetrahedra.size() > 30000) continue; // the references are quadratic-ish
    const std::vector<double> f = sample(m, [](double x, double y, double z) {
      return std::sin(3 * x) * std::cos(2 * y) + 0.5 * std::sin(4 * z + x);
    });
    check_against_references(m, f, path, 0.02);
  }
}

// A vertex of high valence (the centre of a double cone over a ring of 300 points: 600
// tetrahedra and 302 neighbours), with a field that oscillates around the ring: its links have many
// components (a degenerate saddle of high multiplicity).
void test_high_valence() {
  const int n = 300;
  Mesh m;
  m.points.emplace_back(0, 0, 0);  // 0: the centre
  m.points.emplace_back(0, 0, 1);  // 1: the top
  m.points.emplace_back(0, 0, -1); // 2: the bottom
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i) m.points.emplace_back(std::cos(2 * pi * i / n), std::sin(2 * pi * i / n), 0);
  for (int i = 0; i < n; ++i) {
    const std::uint32_t a = 3 + static_cast<std::uint32_t>(i),
                        b = 3 + static_cast<std::uint32_t>((i + 1) % n);
    m.tetrahedra.push_back({0, a, b, 1});
    m.tetrahedra.push_back({0, b, a, 2});
  }
  std::vector<double> f(m.points.size());
  f[0] = 0;
  f[1] = 0.5;
  f[2] = -0.5;
  for (int i = 0; i < n; ++i)
    f[3 + static_cast<std::size_t>(i)] = std::sin(14 * pi * i / n) + 0.001 * (i % 7);
  const Result r = check_against_references(m, f, "double cone of 300");
  CHECK(r.types[0] == Critical_type::DEGENERATE || r.types[0] == Critical_type::REGULAR);
}

// Errors: a NaN field value is refused with the vertex named.
void test_errors() {
  const Mesh m = prstar_test_meshes::cube_grid(1);
  std::vector<double> f(m.points.size(), 1.0);
  f[5] = std::nan("");
  const Octree tree(PSO::make_input(m));
  try {
    PSO::compute_critical_points(tree, CGAL::make_property_map(f), nullptr);
    FAIL("a NaN field value was accepted");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()).find("vertex 5") != std::string::npos);
  }
}

} // namespace

void test_scalar_topology(const prstar_test::Data_folders& data) {
  const auto start = std::chrono::steady_clock::now();
  test_bowl();
  test_bumps();
  test_linear();
  test_high_valence();
  test_errors();
  test_files(data);
  std::cout << "scalar topology: "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s\n";
}
