// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar validate: orientation, flat and non-manifold elements, Euler characteristic, boundary
// components.  Exit status 0 valid, 3 invalid (1 and 2 stay errors).

#include "commands.h"

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/parameters.h>
#include <CGAL/PR_star_octree/validity.h>

#include <chrono>
#include <iostream>

namespace prstar {

// The summary of the validate command (one process or distributed), and its exit status.
int report_validity(const Options& o, const CGAL::PR_star_octree::Validity_result& r, double seconds) {
  const std::string& input = o.input();
  if (o.json()) {
    Json j;
    j.begin_object()
        .field("valid", r.valid)
        .field("tetrahedra", r.tetrahedra)
        .field("inverted", r.inverted)
        .field("degenerate", r.degenerate)
        .field("nonmanifold_triangles", r.nonmanifold_triangles)
        .field("nonmanifold_vertices", r.nonmanifold_vertices)
        .field("euler_characteristic", r.euler_characteristic)
        .field("boundary_triangles", r.boundary_triangles)
        .field("boundary_components", r.boundary_components)
        .field("seconds", seconds)
        .end_object();
    std::cout << j.str() << '\n';
  } else {
    Table t({"check", "count"});
    t.add({"tetrahedra", std::to_string(r.tetrahedra)});
    t.add({"  positive as listed", std::to_string(r.positive)});
    t.add({"  negative as listed", std::to_string(r.negative)});
    t.add({"  inverted (minority sign)", std::to_string(r.inverted)});
    t.add({"  flat (degenerate)", std::to_string(r.degenerate)});
    t.add({"triangles in 3+ tetrahedra", std::to_string(r.nonmanifold_triangles)});
    t.add({"non-manifold vertices", std::to_string(r.nonmanifold_vertices)});
    t.add({"Euler characteristic", std::to_string(r.euler_characteristic)});
    t.add({"boundary triangles", std::to_string(r.boundary_triangles)});
    t.add({"boundary components", std::to_string(r.boundary_components)});
    std::cout << input << ": " << (r.valid ? "valid" : "INVALID") << " (" << fixed(seconds, 3) << " s)\n"
              << t.str();
  }
  return r.valid ? exit_success : exit_invalid_mesh;
}

namespace {

using Octree = CGAL::PR_star_octree_3<>;
namespace params = CGAL::PR_star_octree::parameters;

int run_validate(const Options& o) {
  const std::string& input = o.input();
  const std::size_t kv = o.kv();
  Progress_bar progress(o.show_progress());
  const Mesh mesh = read_mesh(input, progress);
  const auto start = std::chrono::steady_clock::now();
  progress.phase("building the PR-star octree (k_v = " + bucket_size_string(kv) + ")");
  const Octree tree(CGAL::PR_star_octree::make_input(mesh.points, mesh.tetrahedra),
                    params::bucket_size(kv).maximum_depth(o.max_depth()));
  progress.phase("checking the mesh");
  const auto r = CGAL::PR_star_octree::check_validity(tree, params::progress(progress.callback()));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.finish();
  return report_validity(o, r, seconds);
}

} // namespace

Command validate_command() {
  return Command("validate",
                 "orientation, flat and non-manifold elements, Euler characteristic, boundary components")
      .input()
      .description(
          R"(Checks MESH leaf by leaf: the orientation of every tetrahedron with an exact predicate (all must
have the same sign as listed; "inverted" counts the minority sign), flat tetrahedra, triangles in
three or more tetrahedra, non-manifold vertices, the Euler characteristic and the number of
boundary components (boundary triangles connected through edges).

exit status: 0 the mesh is valid, 3 the mesh was checked and is not valid, 1 an error (missing,
unreadable or malformed file), 2 a usage error.)")
      .kv()
      .max_depth()
      .json_keys(
          "keys: valid, tetrahedra, inverted, degenerate, nonmanifold_triangles,\n"
          "nonmanifold_vertices, euler_characteristic, boundary_triangles, boundary_components, seconds")
      .run(run_validate);
}

} // namespace prstar
