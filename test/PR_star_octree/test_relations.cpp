// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The local topological relations of the PR-star octree (Leaf_topology, for_each_leaf, random
// access, global counts) against a brute-force global computation on the user's arrays (original
// numbering, maps and sorting only), against the extended IA baseline, and against CGAL's
// Triangulation_3 adjacency, on generated (Mesh_3, TetGen) and real meshes, for several k_v.
//
// usage: test_relations GENERATED_DATA_DIR [SHARED_DATA_DIR]

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/Leaf_topology.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/distortion.h>
#include <CGAL/property_map.h>

#include <cmath>

#include "baselines/Cgal_triangulation_baseline.h"
#include "baselines/Extended_IA.h"
#include "baselines/curvature_baselines.h"
#include "test_harness.h"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace {

using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;
using Octree = CGAL::PR_star_octree_3<>;
using Local = CGAL::PR_star_octree::Leaf_topology<Octree>;
using Index = std::uint32_t;
using Face = std::array<Index, 3>;
using EdgeKey = std::pair<Index, Index>;
using CGAL::PR_star_octree::Vertex_curvature;

// The brute-force truth, on the user's numbering.
struct Truth {
  std::vector<std::vector<Index>> vt; // sorted
  std::vector<std::set<Index>> vv;
  std::map<Face, std::vector<Index>> faces;
  std::map<EdgeKey, std::vector<Index>> edges; // sorted star
  std::size_t referenced = 0;

  explicit Truth(const Mesh& m) : vt(m.points.size()), vv(m.points.size()) {
    for (Index t = 0; t < m.tetrahedra.size(); ++t) {
      const auto& c = m.tetrahedra[t];
      for (int i = 0; i < 4; ++i) {
        vt[c[i]].push_back(t);
        for (int j = 0; j < 4; ++j)
          if (i != j) vv[c[i]].insert(c[j]);
        for (int j = i + 1; j < 4; ++j) edges[{std::min(c[i], c[j]), std::max(c[i], c[j])}].push_back(t);
        Face f{{c[(i + 1) & 3], c[(i + 2) & 3], c[(i + 3) & 3]}};
        std::sort(f.begin(), f.end());
        faces[f].push_back(t);
      }
    }
    for (const auto& s : vt) referenced += !s.empty();
  }
  // A vertex is pinched (non-manifold) when the tetrahedra of its star are not all connected
  // through faces incident in it.
  bool is_pinched(const Mesh& m, Index v) const {
    const auto& st = vt[v];
    if (st.empty()) return false;
    std::vector<int> seen(st.size(), 0);
    std::vector<std::size_t> todo{0};
    seen[0] = 1;
    while (!todo.empty()) {
      const std::size_t i = todo.back();
      todo.pop_back();
      for (std::size_t j = 0; j < st.size(); ++j)
        if (!seen[j] && shares_face_with(m.tetrahedra[st[i]], m.tetrahedra[st[j]], v, v)) {
          seen[j] = 1;
          todo.push_back(j);
        }
    }
    return std::count(seen.begin(), seen.end(), 0) > 0;
  }
  // A vertex is manifold when its link (the faces opposite it) is a triangulated sphere or disc:
  // connected, every link edge in at most two link triangles, and Euler characteristic 2 without
  // boundary or 1 with a single boundary loop.
  bool is_manifold_vertex(const Mesh& m, Index v) const {
    const auto& st = vt[v];
    if (st.empty()) return true;
    std::map<EdgeKey, int> link_edges;
    std::set<Index> link_vertices;
    for (Index t : st)
      for (Index a : m.tetrahedra[t])
        for (Index b : m.tetrahedra[t])
          if (a < b && a != v && b != v) {
            ++link_edges[{a, b}];
            link_vertices.insert(a);
            link_vertices.insert(b);
          }
    std::map<Index, int> boundary_degree;
    std::size_t boundary_edges = 0;
    for (const auto& e : link_edges) {
      if (e.second > 2) return false;
      if (e.second == 1) {
        ++boundary_edges;
        ++boundary_degree[e.first.first];
        ++boundary_degree[e.first.second];
      }
    }
    for (const auto& d : boundary_degree)
      if (d.second != 2) return false; // the boundary of the link must be simple loops
    const long long chi =
        (long long)link_vertices.size() - (long long)link_edges.size() + (long long)st.size();
    if (is_pinched(m, v)) return false;
    if (boundary_edges == 0) return chi == 2;
    // One boundary loop: its edges form a single cycle.
    std::map<Index, std::vector<Index>> adj;
    for (const auto& e : link_edges)
      if (e.second == 1) {
        adj[e.first.first].push_back(e.first.second);
        adj[e.first.second].push_back(e.first.first);
      }
    std::set<Index> seen{adj.begin()->first};
    std::vector<Index> todo{adj.begin()->first};
    while (!todo.empty()) {
      const Index x = todo.back();
      todo.pop_back();
      for (Index y : adj[x])
        if (seen.insert(y).second) todo.push_back(y);
    }
    return seen.size() == adj.size() && chi == 1;
  }
  // An edge is manifold when its star is a single fan or cycle: tetrahedra linked through faces
  // containing the edge form a connected path or cycle, each face in at most two tetrahedra.
  bool is_manifold_edge(const Mesh& m, Index a, Index b) const {
    const auto& st = edges.at({std::min(a, b), std::max(a, b)});
    std::vector<int> degree(st.size(), 0), seen(st.size(), 0);
    for (std::size_t i = 0; i < st.size(); ++i)
      for (std::size_t j = 0; j < st.size(); ++j)
        if (i != j && shares_face_with(m.tetrahedra[st[i]], m.tetrahedra[st[j]], a, b)) ++degree[i];
    if (std::any_of(degree.begin(), degree.end(), [](int d) { return d > 2; })) return false;
    std::vector<std::size_t> todo{0};
    seen[0] = 1;
    while (!todo.empty()) {
      const std::size_t i = todo.back();
      todo.pop_back();
      for (std::size_t j = 0; j < st.size(); ++j)
        if (!seen[j] && shares_face_with(m.tetrahedra[st[i]], m.tetrahedra[st[j]], a, b)) {
          seen[j] = 1;
          todo.push_back(j);
        }
    }
    return std::count(seen.begin(), seen.end(), 0) == 0;
  }
  // Whether x and y share a face (three vertices) containing a and b.
  static bool shares_face_with(const Mesh::Tetrahedron& x, const Mesh::Tetrahedron& y, Index a, Index b) {
    int shared = 0;
    bool has_a = false, has_b = false;
    for (Index p : x)
      for (Index q : y)
        if (p == q) {
          ++shared;
          has_a = has_a || p == a;
          has_b = has_b || p == b;
        }
    return shared == 3 && has_a && has_b;
  }
  std::size_t boundary_faces() const {
    std::size_t n = 0;
    for (const auto& f : faces) n += f.second.size() == 1;
    return n;
  }
  bool is_boundary_edge(Index a, Index b) const {
    // An edge is on the boundary when a boundary face contains it.
    const auto& star = edges.at({std::min(a, b), std::max(a, b)});
    return std::any_of(star.begin(), star.end(), [&](Index t) { return has_boundary_face_with(t, a, b); });
  }
  const std::vector<Index>* tets_of_face(Face f) const {
    std::sort(f.begin(), f.end());
    auto it = faces.find(f);
    return it == faces.end() ? nullptr : &it->second;
  }
  const Mesh* mesh = nullptr;
  bool has_boundary_face_with(Index t, Index a, Index b) const {
    const auto& c = mesh->tetrahedra[t];
    for (int k = 0; k < 4; ++k) {
      Face f{{c[(k + 1) & 3], c[(k + 2) & 3], c[(k + 3) & 3]}};
      if (std::find(f.begin(), f.end(), a) == f.end() || std::find(f.begin(), f.end(), b) == f.end())
        continue;
      if (tets_of_face(f)->size() == 1) return true;
    }
    return false;
  }
};

std::size_t shared_vertices(const Mesh::Tetrahedron& x, const Mesh::Tetrahedron& y) {
  std::size_t n = 0;
  for (Index a : x)
    for (Index b : y) n += a == b;
  return n;
}

// Checks that `star` (original tet indices) is a cyclic (closed) or linear (open) sequence of
// tetrahedra around edge (a, b), consecutive ones sharing a face that contains the edge.
bool is_ordered_star(const Mesh& m, const std::vector<Index>& star, bool closed) {
  for (std::size_t i = 0; i + 1 < star.size(); ++i)
    if (shared_vertices(m.tetrahedra[star[i]], m.tetrahedra[star[i + 1]]) != 3) return false;
  if (closed && star.size() > 2 &&
      shared_vertices(m.tetrahedra[star.front()], m.tetrahedra[star.back()]) != 3)
    return false;
  return true;
}

// Same cyclic sequence up to rotation and reversal (closed stars), or the same sequence up to
// reversal (open fans).
bool same_star(std::vector<Index> a, const std::vector<Index>& b, bool closed) {
  if (a.size() != b.size()) return false;
  if (a.empty()) return true;
  for (int dir = 0; dir < 2; ++dir) {
    for (std::size_t r = 0; r < (closed ? a.size() : 1); ++r) {
      bool eq = true;
      for (std::size_t i = 0; i < a.size() && eq; ++i) eq = a[(r + i) % a.size()] == b[i];
      if (eq) return true;
    }
    std::reverse(a.begin(), a.end());
  }
  return false;
}

// The random-access queries against brute force over all tetrahedra, for every vertex and every
// tetrahedron of `tree`: vertex_star(tree, v) must be exactly the tetrahedra whose vertex list holds
// v, in increasing order (one scan of the tree's whole tetrahedron array, octree numbering), and,
// mapped back, the user's star of the vertex; tetrahedron_neighbors(tree, t)[k] the other
// tetrahedron of the face opposite vertex k, no_neighbor on the boundary, one of the others at a
// face of three or more tetrahedra.
void check_random_access(const Octree& tree, const Truth& truth) {
  const std::size_t nv = tree.number_of_vertices(), nt = tree.number_of_tetrahedra();
  std::vector<std::vector<Index>> brute(nv);
  for (Index t = 0; t < nt; ++t)
    for (Index v : tree.tetrahedron(t)) brute[v].push_back(t); // increasing in t
  std::size_t star_mismatches = 0, compared = 0;
  for (Index v = 0; v < nv; ++v) {
    std::vector<Index> r;
    CGAL::PR_star_octree::vertex_star(tree, v, std::back_inserter(r));
    CHECK_EQUAL(r, brute[v]);
    star_mismatches += r != brute[v];
    std::vector<Index> user;
    for (Index t : r) user.push_back(tree.original_tetrahedron(t));
    std::sort(user.begin(), user.end());
    CHECK_EQUAL(user, truth.vt[tree.original_vertex(v)]);
    compared += r.size();
    if (star_mismatches > 5) break; // enough printed
  }
  CHECK_EQUAL(compared, 4 * nt);
  for (Index t = 0; t < nt; ++t) {
    const auto ra = CGAL::PR_star_octree::tetrahedron_neighbors(tree, t);
    const auto& c = tree.tetrahedron(t);
    for (int k = 0; k < 4; ++k) {
      const Face f{{tree.original_vertex(c[(k + 1) & 3]), tree.original_vertex(c[(k + 2) & 3]),
                    tree.original_vertex(c[(k + 3) & 3])}};
      const auto* ft = truth.tets_of_face(f);
      CHECK(ft != nullptr);
      if (!ft) continue;
      std::vector<Index> others;
      for (Index u : *ft)
        if (u != tree.original_tetrahedron(t)) others.push_back(u);
      if (others.empty())
        CHECK_EQUAL(ra[k], Local::no_neighbor);
      else if (others.size() == 1)
        CHECK_EQUAL(ra[k] == Local::no_neighbor ? ra[k] : tree.original_tetrahedron(ra[k]), others[0]);
      else
        CHECK(ra[k] != Local::no_neighbor &&
              std::count(others.begin(), others.end(), tree.original_tetrahedron(ra[k])) == 1);
    }
  }
}

void check_mesh(const Mesh& mesh, const std::string& name, const std::vector<std::size_t>& kvs,
                bool with_cgal) {
  Truth truth(mesh);
  truth.mesh = &mesh;
  const prstar_test::Failure_context context(name);

  // Extended IA against the brute force.
  prstar_baselines::Extended_IA<Index> ia(mesh.points.size(), mesh.tetrahedra);
  std::vector<Index> star, stack;
  std::vector<char> pinched(mesh.points.size());
  std::size_t pinched_count = 0;
  for (Index v = 0; v < mesh.points.size(); ++v) pinched_count += pinched[v] = truth.is_pinched(mesh, v);
  for (Index v = 0; v < mesh.points.size(); ++v) {
    ia.vertex_tetrahedra(v, star, stack);
    std::sort(star.begin(), star.end());
    if (!pinched[v]) CHECK_EQUAL(star, truth.vt[v]);
    // At a pinched vertex the walk of the IA reaches one component of the star only.
    else
      CHECK(!star.empty() && std::includes(truth.vt[v].begin(), truth.vt[v].end(), star.begin(), star.end()));
  }
  if (pinched_count) std::cout << "  " << name << ": " << pinched_count << " pinched vertices\n";
  std::size_t nonmanifold_count = 0;
  for (Index v = 0; v < mesh.points.size(); ++v) nonmanifold_count += !truth.is_manifold_vertex(mesh, v);
  if (nonmanifold_count) std::cout << "  " << name << ": " << nonmanifold_count << " non-manifold vertices\n";

  // CGAL's triangulation adjacency against the brute force.
  std::map<EdgeKey, std::vector<Index>> cgal_stars; // in CGAL's cyclic order
  std::unique_ptr<prstar_baselines::Cgal_triangulation_baseline> cgal_ptr;
  if (with_cgal) {
    try {
      cgal_ptr =
          std::make_unique<prstar_baselines::Cgal_triangulation_baseline>(mesh.points, mesh.tetrahedra);
    } catch (const std::runtime_error& e) {
      // CGAL's triangulation cannot represent a non-manifold vertex; anything else is a failure.
      std::cout << "  " << name << ": no CGAL comparison: " << e.what() << "\n";
      CHECK(nonmanifold_count > 0);
      with_cgal = false;
    }
  }
  if (with_cgal) {
    const auto& cgal = *cgal_ptr;
    CHECK_EQUAL(cgal.number_of_finite_cells(), mesh.tetrahedra.size());
    for (Index v = 0; v < mesh.points.size(); ++v) {
      std::vector<Index> s;
      cgal.vertex_tetrahedra(v, std::back_inserter(s));
      std::sort(s.begin(), s.end());
      CHECK_EQUAL(s, truth.vt[v]);
    }
    for (Index t = 0; t < mesh.tetrahedra.size(); ++t) {
      const auto n = cgal.tetrahedron_neighbors(t);
      const auto& c = mesh.tetrahedra[t];
      for (int k = 0; k < 4; ++k) {
        const auto* f = truth.tets_of_face({{c[(k + 1) & 3], c[(k + 2) & 3], c[(k + 3) & 3]}});
        const Index expected = f->size() == 1 ? Index(-1) : ((*f)[0] == t ? (*f)[1] : (*f)[0]);
        CHECK_EQUAL(n[k], expected);
      }
    }
    cgal.for_each_edge_star([&](Index a, Index b, const std::vector<Index>& s, bool on_boundary) {
      const EdgeKey key{std::min(a, b), std::max(a, b)};
      auto it = truth.edges.find(key);
      CHECK(it != truth.edges.end());
      if (it == truth.edges.end()) return;
      std::vector<Index> sorted = s;
      std::sort(sorted.begin(), sorted.end());
      CHECK_EQUAL(sorted, it->second);
      CHECK_EQUAL(on_boundary, truth.is_boundary_edge(a, b));
      CHECK(is_ordered_star(mesh, s, !on_boundary));
      cgal_stars[key] = s;
    });
    CHECK_EQUAL(cgal_stars.size(), truth.edges.size());
  }

  // Boundary (paper Section 7) and distortion (Section 8): against brute force, IA and CGAL.
  {
    using CGAL::PR_star_octree::Vertex_type;
    std::vector<char> on_boundary_face(mesh.points.size(), 0);
    for (const auto& f : truth.faces)
      if (f.second.size() == 1)
        for (Index v : f.first) on_boundary_face[v] = 1;
    const std::vector<char> ia_b = prstar_baselines::ia_boundary(ia);
    // A non-linear field, or the mesh's own scalar field.
    std::vector<double> values(mesh.points.size());
    for (std::size_t v = 0; v < values.size(); ++v) {
      const auto& p = mesh.points[v];
      values[v] =
          mesh.scalar_field() ? mesh.scalar_field()->values[v] : p.x() * p.x() + std::sin(3 * p.y()) + p.z();
    }
    auto field = [&](Index v) { return values[v]; };
    const auto ia_c = prstar_baselines::ia_curvature(mesh.points, mesh.tetrahedra, ia, field);
    std::vector<Vertex_curvature> cgal_c;
    if (with_cgal) cgal_c = prstar_baselines::cgal_curvature(mesh.points, mesh.tetrahedra, *cgal_ptr, field);
    namespace params = CGAL::PR_star_octree::parameters;
    // Brute-force counts of the tetrahedra touching the boundary.
    std::set<Index> boundary_face_tets;
    for (const auto& f : truth.faces)
      if (f.second.size() == 1) boundary_face_tets.insert(f.second[0]);
    // (the compact tetrahedron array too: the kernels decode it, the results must not change)
    const std::pair<std::size_t, bool> configurations[] = {
        {3, false}, {64, false}, {Octree::infinite_bucket_size, false}, {3, true}, {64, true}};
    for (const auto& [kv, compact] : configurations) {
      const prstar_test::Failure_context kv_context(name + (compact ? " compact" : "") + " k_v " +
                                                    std::to_string(kv));
      Octree tree(CGAL::PR_star_octree::make_input(mesh),
                  CGAL::PR_star_octree::parameters::bucket_size(kv).compact_tetrahedra(compact));
      CHECK_EQUAL(tree.is_compact(), compact);
      const std::size_t n = mesh.points.size();
      // Everything below is in the user's numbering (property maps keyed by the input order).
      std::vector<Vertex_type> types(n, Vertex_type::NONMANIFOLD);
      std::vector<std::array<std::size_t, 3>> boundary_triangles;
      const auto b = CGAL::PR_star_octree::compute_boundary(
          tree, CGAL::make_property_map(types),
          params::boundary_triangles_output(std::back_inserter(boundary_triangles)));
      CHECK_EQUAL(b.boundary_triangles, truth.boundary_faces());
      CHECK_EQUAL(boundary_triangles.size(), truth.boundary_faces());
      CHECK_EQUAL(b.boundary_face_tetrahedra, boundary_face_tets.size());
      // Each boundary triangle once, a face of one tetrahedron only, oriented outward: the fourth
      // vertex of its tetrahedron lies on its negative side.
      std::set<Face> seen_triangles;
      for (const auto& tr : boundary_triangles) {
        Face f{{Index(tr[0]), Index(tr[1]), Index(tr[2])}};
        const auto* ft = truth.tets_of_face(f);
        CHECK(ft != nullptr && ft->size() == 1);
        if (!ft || ft->size() != 1) continue;
        std::sort(f.begin(), f.end());
        CHECK(seen_triangles.insert(f).second);
        const auto& c = mesh.tetrahedra[(*ft)[0]];
        Index apex = c[0];
        for (Index x : c)
          if (x != tr[0] && x != tr[1] && x != tr[2]) apex = x;
        CHECK(CGAL::orientation(mesh.points[tr[0]], mesh.points[tr[1]], mesh.points[tr[2]],
                                mesh.points[apex]) == CGAL::NEGATIVE);
      }
      // The paper's count alone agrees wherever the link proof says the vertex is manifold.
      std::vector<Vertex_type> fast(n, Vertex_type::UNREFERENCED);
      const auto fb = CGAL::PR_star_octree::compute_boundary(
          tree, CGAL::make_property_map(fast), params::check_links(false).with_boundary_triangles(false));
      CHECK_EQUAL(fb.boundary_triangles, std::size_t(0));
      for (Index o = 0; o < n; ++o)
        if (types[o] != Vertex_type::NONMANIFOLD) CHECK_EQUAL(fast[o], types[o]);
      std::vector<Vertex_curvature> curv(n), linear(n);
      CGAL::PR_star_octree::compute_curvature(tree, CGAL::make_property_map(values),
                                              CGAL::make_property_map(curv));
      CGAL::PR_star_octree::compute_curvature(tree, CGAL::PR_star_octree::coordinate_field_map(tree, 1),
                                              CGAL::make_property_map(linear));
      CGAL::PR_star_octree::Vertex_type_counts expected_counts;
      std::size_t touching = 0;
      for (Index o = 0; o < n; ++o) {
        const Vertex_type expected = truth.vt[o].empty()                  ? Vertex_type::UNREFERENCED
                                     : !truth.is_manifold_vertex(mesh, o) ? Vertex_type::NONMANIFOLD
                                     : on_boundary_face[o]                ? Vertex_type::BOUNDARY
                                                                          : Vertex_type::INTERIOR;
        expected_counts.add(expected);
        CHECK_EQUAL(types[o], expected);
        CHECK_EQUAL(curv[o].type, expected);
        if (expected == Vertex_type::INTERIOR || expected == Vertex_type::BOUNDARY) {
          CHECK_EQUAL(bool(ia_b[o]), expected == Vertex_type::BOUNDARY);
          if (with_cgal) CHECK_EQUAL(cgal_ptr->is_boundary_vertex(o), expected == Vertex_type::BOUNDARY);
          // Distortion equal across PR-star, IA and CGAL.
          CHECK_NEAR(curv[o].distortion, ia_c[o].distortion, 1e-9);
          CHECK_NEAR(curv[o].domain_curvature, ia_c[o].domain_curvature, 1e-9);
          if (with_cgal) CHECK_NEAR(curv[o].distortion, cgal_c[o].distortion, 1e-9);
          // A linear field does not bend the lifted mesh: zero distortion at interior vertices.
          if (expected == Vertex_type::INTERIOR) CHECK_NEAR(linear[o].distortion, 0.0, 1e-9);
        } else if (expected == Vertex_type::NONMANIFOLD)
          CHECK(std::isnan(curv[o].distortion));
      }
      for (const auto& c : mesh.tetrahedra)
        touching += std::any_of(c.begin(), c.end(), [&](Index x) {
          return types[x] == Vertex_type::BOUNDARY || types[x] == Vertex_type::NONMANIFOLD;
        });
      CHECK_EQUAL(b.boundary_tetrahedra, touching);
      CHECK_EQUAL(b.interior_vertices, expected_counts.interior_vertices);
      CHECK_EQUAL(b.boundary_vertices, expected_counts.boundary_vertices);
      CHECK_EQUAL(b.nonmanifold_vertices, expected_counts.nonmanifold_vertices);
      CHECK_EQUAL(b.unreferenced_vertices, expected_counts.unreferenced_vertices);
      // Random access and box queries give the same values as the streaming computation (NaN
      // where it has NaN), and the IA baseline's where the vertex is manifold.
      auto same = [](double a, double b) { return std::isnan(a) ? std::isnan(b) : a == b; };
      auto check_one = [&](Index v, const Vertex_curvature& one) {
        const Index o = tree.original_vertex(v);
        CHECK_EQUAL(one.type, curv[o].type);
        CHECK(same(one.distortion, curv[o].distortion));
        CHECK(same(one.domain_curvature, curv[o].domain_curvature));
        if (one.type == Vertex_type::INTERIOR || one.type == Vertex_type::BOUNDARY) {
          CHECK_NEAR(one.distortion, ia_c[o].distortion, 1e-9);
          CHECK_NEAR(one.domain_curvature, ia_c[o].domain_curvature, 1e-9);
        }
      };
      std::size_t random_access = 0;
      for (Index v = 0; v < mesh.points.size(); v += 97, ++random_access)
        check_one(v, CGAL::PR_star_octree::curvature_at(tree, v, CGAL::make_property_map(values)));
      CHECK(random_access > 0);
      std::vector<std::pair<Index, Vertex_curvature>> in_box;
      const auto bb = tree.bbox();
      const CGAL::Bbox_3 box(bb.xmin(), bb.ymin(), bb.zmin(), (bb.xmin() + bb.xmax()) / 2, bb.ymax(),
                             bb.zmax());
      CGAL::PR_star_octree::curvature_in_box(tree, box, CGAL::make_property_map(values), in_box);
      std::size_t expected_in_box = 0;
      for (Index v = 0; v < mesh.points.size(); ++v) expected_in_box += tree.point(v).x() <= box.xmax();
      CHECK_EQUAL(in_box.size(), expected_in_box);
      CHECK(expected_in_box > 0);
      for (const auto& e : in_box) {
        CHECK(tree.point(e.first).x() <= box.xmax());
        check_one(e.first, e.second);
      }
    }
  }

  for (const bool compact : {false, true})
    for (std::size_t kv : kvs) {
      // (compact: the finite k_v; with one leaf, random access decodes all of T for each vertex)
      if (compact && kv == Octree::infinite_bucket_size) continue;
      const prstar_test::Failure_context kv_context(name + (compact ? " compact" : "") + " k_v " +
                                                    std::to_string(kv));
      Octree tree(CGAL::PR_star_octree::make_input(mesh),
                  CGAL::PR_star_octree::parameters::bucket_size(kv).compact_tetrahedra(compact));
      check_random_access(tree, truth);
      auto orig_v = [&](Index v) { return tree.original_vertex(v); };
      auto orig_t = [&](Index t) { return tree.original_tetrahedron(t); };
      std::size_t edges_owned = 0, triangles_owned = 0, boundary_owned = 0;
      std::set<EdgeKey> edges_seen;
      std::set<Face> triangles_seen;

      CGAL::PR_star_octree::for_each_leaf(tree, CGAL::PR_star_octree::ALL_RELATIONS, [&](const Local& local) {
        const auto tets = local.tetrahedra();
        for (Index v = local.vertex_begin(); v < local.vertex_end(); ++v) {
          // VT (Algorithm 1) and the random-access star.
          std::vector<Index> s;
          for (Index t : local.vertex_tetrahedra(v)) s.push_back(orig_t(t));
          std::sort(s.begin(), s.end());
          CHECK_EQUAL(s, truth.vt[orig_v(v)]);
          CHECK(std::is_sorted(local.vertex_tetrahedra(v).begin(), local.vertex_tetrahedra(v).end()));
          // VV.
          std::set<Index> w;
          for (Index u : local.vertex_vertices(v)) w.insert(orig_v(u));
          CHECK_EQUAL(w, truth.vv[orig_v(v)]);
          // Vertex link: the faces opposite v, positively oriented with v first.
          std::vector<std::array<Index, 3>> link;
          local.vertex_link(v, std::back_inserter(link));
          CHECK_EQUAL(link.size(), s.size());
          for (const auto& f : link) {
            CHECK(CGAL::orientation(tree.point(v), tree.point(f[0]), tree.point(f[1]), tree.point(f[2])) !=
                  CGAL::NEGATIVE);
            CHECK(truth.tets_of_face({{orig_v(f[0]), orig_v(f[1]), orig_v(f[2])}}) != nullptr);
          }
          // VE: the edges of v.
          std::size_t degree = 0;
          for (Index e : local.vertex_edges(v)) {
            CHECK(local.edge(e).v0 == v || local.edge(e).v1 == v);
            ++degree;
          }
          CHECK_EQUAL(degree, truth.vv[orig_v(v)].size());
        }
        // TT (Algorithm 2): exact for faces with a vertex in the leaf; random access for all.
        for (std::size_t i = 0; i < tets.size(); ++i) {
          const Index t = tets[i];
          const auto& c = tree.tetrahedron(t);
          for (int k = 0; k < 4; ++k) {
            const Face f{{orig_v(c[(k + 1) & 3]), orig_v(c[(k + 2) & 3]), orig_v(c[(k + 3) & 3])}};
            const auto* ft = truth.tets_of_face(f);
            CHECK(ft != nullptr);
            if (!ft) continue;
            const Index expected =
                ft->size() == 1 ? Local::no_neighbor : ((*ft)[0] == orig_t(t) ? (*ft)[1] : (*ft)[0]);
            const Index got = local.tetrahedron_adjacency(i)[k];
            const bool face_in_leaf = local.is_local_vertex(c[(k + 1) & 3]) ||
                                      local.is_local_vertex(c[(k + 2) & 3]) ||
                                      local.is_local_vertex(c[(k + 3) & 3]);
            if (face_in_leaf)
              CHECK_EQUAL((got == Local::no_neighbor ? got : orig_t(got)), expected);
            else
              CHECK_EQUAL(got, Local::unknown_neighbor);
          }
        }
        // Edges: stars as sets and as cyclic sequences, links, boundary flags, each owned once.
        for (std::size_t e = 0; e < local.number_of_edges(); ++e) {
          const auto& ed = local.edge(e);
          CHECK(ed.v0 < ed.v1);
          CHECK(local.is_local_vertex(ed.v0) || local.is_local_vertex(ed.v1));
          const EdgeKey key{std::min(orig_v(ed.v0), orig_v(ed.v1)), std::max(orig_v(ed.v0), orig_v(ed.v1))};
          auto it = truth.edges.find(key);
          CHECK(it != truth.edges.end());
          if (it == truth.edges.end()) continue;
          std::vector<Index> s;
          for (Index t : local.edge_tetrahedra(e)) s.push_back(orig_t(t));
          std::vector<Index> sorted = s;
          std::sort(sorted.begin(), sorted.end());
          CHECK_EQUAL(sorted, it->second);
          const bool boundary = truth.is_boundary_edge(key.first, key.second);
          const bool manifold = truth.is_manifold_edge(mesh, key.first, key.second);
          CHECK_EQUAL(local.is_nonmanifold_edge(e), !manifold);
          if (!manifold) {
            if (local.owns_edge(e)) {
              ++edges_owned;
              CHECK(edges_seen.insert(key).second);
            }
            continue;
          }
          CHECK_EQUAL(local.is_boundary_edge(e), boundary);
          CHECK(is_ordered_star(mesh, s, !boundary));
          // The same cyclic order as CGAL's circulator around the edge (up to rotation and reversal).
          if (with_cgal) CHECK(same_star(s, cgal_stars[key], !boundary));
          // The link: one vertex per tetrahedron (closed) or one more (open); tetrahedron i holds
          // link vertices i and i+1 (cyclically).
          const auto lk = local.edge_link(e);
          CHECK_EQUAL(lk.size(), s.size() + (boundary ? 1 : 0));
          for (std::size_t i = 0; i < s.size() && lk.size() == s.size() + (boundary ? 1 : 0); ++i) {
            const auto& c = tree.tetrahedron(local.edge_tetrahedra(e).begin()[i]);
            const Index x = lk.begin()[i], y = lk.begin()[(i + 1) % lk.size()];
            CHECK(std::count(c.begin(), c.end(), x) == 1 && std::count(c.begin(), c.end(), y) == 1);
            // Right-hand rule around v0 -> v1: (v0, v1, x, y) positively oriented.
            CHECK(CGAL::orientation(tree.point(ed.v0), tree.point(ed.v1), tree.point(x), tree.point(y)) !=
                  CGAL::NEGATIVE);
          }
          if (local.owns_edge(e)) {
            ++edges_owned;
            CHECK(edges_seen.insert(key).second);
          }
        }
        // Triangles.
        for (std::size_t f = 0; f < local.number_of_triangles(); ++f) {
          const auto& tr = local.triangle(f);
          Face key{{orig_v(tr[0]), orig_v(tr[1]), orig_v(tr[2])}};
          std::sort(key.begin(), key.end());
          const auto* ft = truth.tets_of_face(key);
          CHECK(ft != nullptr);
          if (!ft) continue;
          std::vector<Index> s;
          for (Index t : local.triangle_tetrahedra(f)) s.push_back(orig_t(t));
          std::sort(s.begin(), s.end());
          std::vector<Index> expected = *ft;
          std::sort(expected.begin(), expected.end());
          CHECK_EQUAL(s, expected);
          if (local.owns_triangle(f)) {
            ++triangles_owned;
            boundary_owned += s.size() == 1;
            CHECK(triangles_seen.insert(key).second);
          }
        }
      });
      CHECK_EQUAL(edges_owned, truth.edges.size());
      CHECK_EQUAL(triangles_owned, truth.faces.size());
      CHECK_EQUAL(boundary_owned, truth.boundary_faces());
      const auto counts = CGAL::PR_star_octree::count_simplices(tree);
      CHECK_EQUAL(counts.edges, truth.edges.size());
      CHECK_EQUAL(counts.triangles, truth.faces.size());
      CHECK_EQUAL(counts.boundary_triangles, truth.boundary_faces());
      std::size_t nonmanifold_faces = 0;
      for (const auto& f : truth.faces) nonmanifold_faces += f.second.size() > 2;
      CHECK_EQUAL(counts.nonmanifold_triangles, nonmanifold_faces);
      CHECK_EQUAL(counts.vertices, truth.referenced);
      CHECK(counts.euler_characteristic() == (long long)truth.referenced - (long long)truth.edges.size() +
                                                 (long long)truth.faces.size() -
                                                 (long long)mesh.tetrahedra.size());
      if (kv == kvs.front())
        std::cout << "  " << name << ": V=" << counts.vertices << " E=" << counts.edges
                  << " F=" << counts.triangles << " (boundary " << counts.boundary_triangles
                  << ") T=" << counts.tetrahedra << " Euler=" << counts.euler_characteristic() << "\n";
    }
}

} // namespace

// test_curvature_closed_forms.cpp
void test_curvature_closed_forms();
// test_scalar_topology.cpp
void test_scalar_topology(const prstar_test::Data_folders& data);

int main(int argc, char** argv) {
  const prstar_test::Data_folders data(argc, argv);
  test_curvature_closed_forms();
  test_scalar_topology(data);
  const std::vector<std::size_t> kvs = {1, 4, 20, 100, Octree::infinite_bucket_size};

  // Hand-checked: the cube in six tetrahedra, 19 edges, 18 triangles (12 on the boundary), Euler 1.
  {
    Mesh cube;
    cube.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
    cube.tetrahedra = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};
    for (std::size_t kv : kvs) {
      Octree tree(CGAL::PR_star_octree::make_input(cube), CGAL::PR_star_octree::parameters::bucket_size(kv));
      const auto c = CGAL::PR_star_octree::count_simplices(tree);
      CHECK_EQUAL(c.vertices, std::size_t(8));
      CHECK_EQUAL(c.edges, std::size_t(19));
      CHECK_EQUAL(c.triangles, std::size_t(18));
      CHECK_EQUAL(c.boundary_triangles, std::size_t(12));
      CHECK_EQUAL(c.tetrahedra, std::size_t(6));
      CHECK_EQUAL(c.euler_characteristic(), 1LL);
      // The diagonal (0,7) is the only interior edge: its star is the closed cycle of all 6.
      std::size_t diagonals = 0, owned = 0;
      CGAL::PR_star_octree::for_each_leaf(tree, CGAL::PR_star_octree::EDGES, [&](const Local& local) {
        for (std::size_t e = 0; e < local.number_of_edges(); ++e) {
          const Index a = tree.original_vertex(local.edge(e).v0), b = tree.original_vertex(local.edge(e).v1);
          const bool diagonal = std::min(a, b) == 0 && std::max(a, b) == 7;
          owned += local.owns_edge(e);
          CHECK_EQUAL(local.is_boundary_edge(e), !diagonal);
          if (!diagonal) continue;
          ++diagonals;
          CHECK_EQUAL(local.edge_tetrahedra(e).size(), std::size_t(6));
          CHECK_EQUAL(local.edge_link(e).size(), std::size_t(6));
        }
      });
      CHECK(diagonals >= 1); // seen from the leaf of 0 and from the leaf of 7
      CHECK_EQUAL(owned, std::size_t(19));
    }
    check_mesh(cube, "cube (6 tetrahedra)", kvs, true);
  }

  // A triangle in three tetrahedra (a book of three pages) beside a lone tetrahedron: 10 + 4
  // triangles, the shared one non-manifold, the 9 other faces of the pages and the 4 of the lone
  // tetrahedron on the boundary; also checked against the brute force.
  {
    Mesh book;
    book.points = {{0, 0, 0},     {1, 0, 0}, {0, 1, 0}, {0.3, 0.3, 1}, {0.3, 0.3, -1},
                   {-1, -1, 0.2}, {5, 5, 5}, {6, 5, 5}, {5, 6, 5},     {5, 5, 6}};
    book.tetrahedra = {{0, 1, 2, 3}, {0, 1, 2, 4}, {0, 1, 2, 5}, {6, 7, 8, 9}};
    const Truth truth(book); // (check_mesh's extended IA refuses a non-manifold triangle)
    std::size_t nonmanifold = 0;
    for (const auto& f : truth.faces) nonmanifold += f.second.size() > 2;
    CHECK_EQUAL(nonmanifold, std::size_t(1));
    for (std::size_t kv : {std::size_t(1), std::size_t(2), std::size_t(4), Octree::infinite_bucket_size}) {
      Octree tree(CGAL::PR_star_octree::make_input(book), CGAL::PR_star_octree::parameters::bucket_size(kv));
      const auto c = CGAL::PR_star_octree::count_simplices(tree);
      CHECK_EQUAL(c.nonmanifold_triangles, std::size_t(1));
      CHECK_EQUAL(c.triangles, std::size_t(10 + 4));
      CHECK_EQUAL(c.triangles, truth.faces.size());
      CHECK_EQUAL(c.boundary_triangles, std::size_t(9 + 4));
      CHECK_EQUAL(c.boundary_triangles, truth.boundary_faces());
      CHECK_EQUAL(c.edges, truth.edges.size());
      CHECK_EQUAL(c.vertices, std::size_t(10));
    }
  }

  // Links of more than 64 vertices (the link kernel tests small links on 64-bit masks and larger
  // ones by hashing), checked against the brute force: a double cone, 2n tetrahedra around a
  // centre vertex whose link is a sphere of n + 2 vertices, the apices' links discs of n + 1
  // vertices; with a second double cone on the same centre (turned by 90 degrees, twice as large),
  // the centre is pinched (two spheres).  n = 62, 63 put the centre's link on either side of 64.
  for (int n : {20, 62, 63, 100}) {
    for (int cones : {1, 2}) {
      Mesh m;
      m.points.push_back({0, 0, 0}); // the centre
      for (int c = 0; c < cones; ++c) {
        // cone c in the coordinates (axis, u, w): (z, x, y) for the first, (x, y, z) for the second
        auto point = [&](double axis, double u, double w) {
          const double s = c + 1.;
          return c == 0 ? Mesh::Point_3(s * u, s * w, s * axis) : Mesh::Point_3(s * axis, s * u, s * w);
        };
        const Index top = static_cast<Index>(m.points.size());
        m.points.push_back(point(1, 0, 0));
        m.points.push_back(point(-1, 0, 0));
        const Index ring = static_cast<Index>(m.points.size());
        for (int i = 0; i < n; ++i) {
          const double a = 2 * 3.14159265358979323846 * i / n;
          m.points.push_back(point(0, std::cos(a), std::sin(a)));
        }
        for (int i = 0; i < n; ++i) {
          const Index r0 = ring + i, r1 = ring + (i + 1) % n;
          m.tetrahedra.push_back({0, top, r0, r1});
          m.tetrahedra.push_back({0, top + 1, r1, r0});
        }
      }
      check_mesh(m, "double cone" + std::string(cones == 2 ? "s" : "") + " of " + std::to_string(n), kvs,
                 cones == 1);
    }
  }

  // Under the sanitizers (scripts/test_sanitizers.sh sets PRSTAR_SANITIZER_LIGHT) the meshes read
  // from files are checked at two k_v (many small leaves, and leaves of about a hundred vertices)
  // instead of five: they are most of this test, 325 s under ASan with all five.
  const bool light = std::getenv("PRSTAR_SANITIZER_LIGHT") != nullptr;
  const std::vector<std::size_t> file_kvs = light ? std::vector<std::size_t>{4, 100} : kvs;
  if (light) std::cout << "PRSTAR_SANITIZER_LIGHT: the meshes of files at k_v 4 and 100 only" << std::endl;
  for (const char* name :
       {"sphere.mesh", "torus.mesh", "cube.mesh", "sphere_tetgen.mesh", "cube_tetgen.vtu"}) {
    const auto file = data.generated_file(name);
    if (!file) continue;
    Mesh mesh;
    CGAL::PR_star_octree::IO::read_tetrahedral_mesh(*file, mesh);
    check_mesh(mesh, name, file_kvs, true);
  }
  if (data.report_shared()) {
    for (const char* name : {"spx_zsweep.off", "armadillo_sofa.vtu", "bunny_sofa.vtu", "skull_14k.off",
                             "t13_data.1.node", "part1.1.node"}) {
      const auto file = data.shared_file(name);
      if (!file) continue;
      Mesh mesh;
      CGAL::PR_star_octree::IO::read_tetrahedral_mesh(*file, mesh);
      check_mesh(mesh, name, file_kvs, true);
    }
  }
  return prstar_test::summary("test_relations");
}
