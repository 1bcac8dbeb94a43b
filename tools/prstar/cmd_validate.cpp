// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar validate: orientation, flat and non-manifold elements, unreferenced vertices, Euler
// characteristic, boundary components, and where the problems are (the first ones in the table,
// all of them in the JSON, as flags in the arrays of `-o`).  Exit status 0 valid, 3 invalid (1 and
// 2 stay errors).

#include "commands.h"

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/IO/vtu_source.h>
#include <CGAL/PR_star_octree/parameters.h>
#include <CGAL/PR_star_octree/validity.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <iostream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace prstar {

namespace {

using Problem = CGAL::PR_star_octree::Validity_problem;
using Kind = CGAL::PR_star_octree::Validity_problem_kind;

// How many problems of each kind the table lists.
constexpr std::size_t table_problems_per_kind = 10;

// The kind as a JSON value, and in the table's words (plural, for "... and N more").
const char* kind_key(Kind k) {
  switch (k) {
  case Kind::INVERTED_TETRAHEDRON:
    return "inverted_tetrahedron";
  case Kind::FLAT_TETRAHEDRON:
    return "flat_tetrahedron";
  case Kind::NONMANIFOLD_TRIANGLE:
    return "nonmanifold_triangle";
  case Kind::NONMANIFOLD_VERTEX:
    return "nonmanifold_vertex";
  default:
    return "unreferenced_vertex";
  }
}
const char* kind_plural(Kind k) {
  switch (k) {
  case Kind::INVERTED_TETRAHEDRON:
    return "inverted tetrahedra";
  case Kind::FLAT_TETRAHEDRON:
    return "flat tetrahedra";
  case Kind::NONMANIFOLD_TRIANGLE:
    return "triangles in 3+ tetrahedra";
  case Kind::NONMANIFOLD_VERTEX:
    return "non-manifold vertices";
  default:
    return "unreferenced vertices";
  }
}

std::string join(const std::size_t* first, const std::size_t* last, const char* separator) {
  std::string s;
  for (const std::size_t* p = first; p != last; ++p) s += (p == first ? "" : separator) + std::to_string(*p);
  return s;
}

// What is wrong, in words (the table's text after the element, the JSON's "reason").
std::string reason(const Problem& p, const CGAL::PR_star_octree::Validity_result& r) {
  switch (p.kind) {
  case Kind::INVERTED_TETRAHEDRON:
    return r.negative <= r.positive ? "inverted (negative as listed, the minority sign)"
                                    : "inverted (positive as listed, the minority sign)";
  case Kind::FLAT_TETRAHEDRON:
    return "flat (its four vertices are coplanar)";
  case Kind::NONMANIFOLD_TRIANGLE:
    return "in " + std::to_string(p.tetrahedra.size()) + " tetrahedra (" +
           join(p.tetrahedra.data(), p.tetrahedra.data() + p.tetrahedra.size(), ", ") + ")";
  case Kind::NONMANIFOLD_VERTEX:
    return "non-manifold (its link is neither a sphere nor a disc)";
  default:
    return "unreferenced (in no tetrahedron; a warning, the mesh stays valid)";
  }
}

// The element, in words: "tetrahedron 17 (vertices 3 8 9 12)", "triangle 4 5 9", "vertex 33".
std::string element(const Problem& p) {
  switch (p.kind) {
  case Kind::INVERTED_TETRAHEDRON:
  case Kind::FLAT_TETRAHEDRON:
    return "tetrahedron " + std::to_string(p.tetrahedron) + " (vertices " +
           join(p.vertices.data(), p.vertices.data() + 4, " ") + ")";
  case Kind::NONMANIFOLD_TRIANGLE:
    return "triangle " + join(p.vertices.data(), p.vertices.data() + 3, " ");
  default:
    return "vertex " + std::to_string(p.vertices[0]);
  }
}

void json_problem(Json& j, const Problem& p, const CGAL::PR_star_octree::Validity_result& r) {
  j.begin_object().field("kind", kind_key(p.kind));
  if (p.tetrahedron != Problem::no_id) j.field("tetrahedron", p.tetrahedron);
  if (p.number_of_vertices() == 1) j.field("vertex", p.vertices[0]);
  j.key("vertices").begin_array();
  for (std::size_t k = 0; k < p.number_of_vertices(); ++k) j.value(p.vertices[k]);
  j.end_array();
  if (!p.tetrahedra.empty()) {
    j.key("tetrahedra").begin_array();
    for (std::size_t t : p.tetrahedra) j.value(t);
    j.end_array();
  }
  j.field("reason", reason(p, r)).end_object();
}

// The first problems of each kind, and how many more.
std::string problem_lines(const std::vector<Problem>& problems,
                          const CGAL::PR_star_octree::Validity_result& r) {
  std::string s;
  for (auto first = problems.begin(); first != problems.end();) {
    const Kind kind = first->kind;
    const auto last =
        std::find_if(first, problems.end(), [kind](const Problem& p) { return p.kind != kind; });
    const std::size_t n = static_cast<std::size_t>(last - first);
    for (auto p = first; p != last && p - first < std::ptrdiff_t(table_problems_per_kind); ++p)
      s += "  " + element(*p) + ": " + reason(*p, r) + "\n";
    if (n > table_problems_per_kind)
      s += "  ... and " + std::to_string(n - table_problems_per_kind) + " more " + kind_plural(kind) + "\n";
    first = last;
  }
  return s;
}

} // namespace

// The summary of the validate command (one process or distributed), and its exit status.
int report_validity(const Options& o, const CGAL::PR_star_octree::Validity_result& r, double seconds,
                    const std::vector<Problem>* problems, bool compact, bool streamed) {
  const std::string& input = o.input();
  const std::string out = o.output();
  if (o.json()) {
    Json j;
    j.begin_object()
        .field("valid", r.valid)
        .field("tetrahedra", r.tetrahedra)
        .field("inverted", r.inverted)
        .field("degenerate", r.degenerate)
        .field("nonmanifold_triangles", r.nonmanifold_triangles)
        .field("nonmanifold_vertices", r.nonmanifold_vertices)
        .field("unreferenced_vertices", r.unreferenced_vertices)
        .field("euler_characteristic", r.euler_characteristic)
        .field("boundary_triangles", r.boundary_triangles)
        .field("boundary_components", r.boundary_components)
        .field("seconds", seconds);
    if (!out.empty()) j.field("output", out);
    if (problems != nullptr) {
      j.key("problems").begin_array();
      for (const Problem& p : *problems) json_problem(j, p, r);
      j.end_array();
    }
    j.end_object();
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
    t.add({"unreferenced vertices (warning)", std::to_string(r.unreferenced_vertices)});
    t.add({"Euler characteristic", std::to_string(r.euler_characteristic)});
    t.add({"boundary triangles", std::to_string(r.boundary_triangles)});
    t.add({"boundary components", std::to_string(r.boundary_components)});
    std::cout << input << ": " << (r.valid ? "valid" : "INVALID") << " ("
              << (streamed  ? "compact tetrahedra, read in passes, "
                  : compact ? "compact tetrahedra, "
                            : "")
              << fixed(seconds, 3) << " s)\n"
              << t.str();
    if (problems != nullptr && !problems->empty())
      std::cout << "problems (user numbering from 0, at most " << table_problems_per_kind
                << " of each kind; all of them with --json):\n"
                << problem_lines(*problems, r);
    else if (problems == nullptr && (!r.valid || r.unreferenced_vertices > 0))
      std::cout << "problems: listed by one process only (run without mpirun)\n";
    if (!out.empty()) std::cout << "wrote " << out << " (arrays `problem`)\n";
  }
  return r.valid ? exit_success : exit_invalid_mesh;
}

namespace {

using Octree = CGAL::PR_star_octree_3<>;
namespace params = CGAL::PR_star_octree::parameters;
namespace PIO = CGAL::PR_star_octree::IO;

// The output extensions that keep point and cell data (from the library's format table).
std::string cell_data_outputs() {
  std::string r;
  for (const auto& f : CGAL::PR_star_octree::IO::mesh_formats<>)
    if (f.point_data_kept == CGAL::PR_star_octree::IO::Point_data_kept::all_arrays &&
        std::string(f.cell_data) == "yes")
      for (const char* e : f.extensions)
        if (e != nullptr) r += (r.empty() ? "." : ",.") + std::string(e);
  return r;
}

// `mesh` with the arrays `problem` (replacing any of that name): bit flags per tetrahedron (1
// inverted, 2 flat, 4 in a non-manifold triangle) and per vertex (1 non-manifold, 2 unreferenced,
// 4 on a non-manifold triangle).
void add_problem_arrays(Mesh& mesh, const std::vector<Problem>& problems) {
  auto named_problem = [](const CGAL::PR_star_octree::Data_array& a) { return a.name == "problem"; };
  mesh.point_data.erase(std::remove_if(mesh.point_data.begin(), mesh.point_data.end(), named_problem),
                        mesh.point_data.end());
  mesh.cell_data.erase(std::remove_if(mesh.cell_data.begin(), mesh.cell_data.end(), named_problem),
                       mesh.cell_data.end());
  std::vector<unsigned char> cells(mesh.tetrahedra.size(), 0), points(mesh.points.size(), 0);
  for (const Problem& p : problems) switch (p.kind) {
    case Kind::INVERTED_TETRAHEDRON:
      cells[p.tetrahedron] |= 1;
      break;
    case Kind::FLAT_TETRAHEDRON:
      cells[p.tetrahedron] |= 2;
      break;
    case Kind::NONMANIFOLD_TRIANGLE:
      for (std::size_t t : p.tetrahedra) cells[t] |= 4;
      for (int k = 0; k < 3; ++k) points[p.vertices[k]] |= 4;
      break;
    case Kind::NONMANIFOLD_VERTEX:
      points[p.vertices[0]] |= 1;
      break;
    case Kind::UNREFERENCED_VERTEX:
      points[p.vertices[0]] |= 2;
      break;
    }
  mesh.cell_data.push_back({"problem", std::vector<double>(cells.begin(), cells.end())});
  mesh.point_data.push_back({"problem", std::vector<double>(points.begin(), points.end())});
}

// The streaming construction keeps no tetrahedron permutation, so `check_validity()` names the
// tetrahedra of `problems` by the octree's index.  One more pass over the file gives them the
// input's: each is found by its four vertices as listed (the input's numbering, which the vertex
// permutation gives back); tetrahedra listed alike are matched in order, as the octree keeps the
// source's order among the tetrahedra of a smallest vertex.  Memory: the problems' tetrahedra and a
// bit per vertex.  \throws std::runtime_error if a tetrahedron is not found (the file changed)
void number_tetrahedra_as_listed(const Octree& tree, const PIO::Vtu_tetrahedron_source& source,
                                 const std::string& file, std::vector<Problem>& problems) {
  std::vector<std::size_t> ids; // the octree's indices named by the problems
  for (const Problem& p : problems) {
    if (p.tetrahedron != Problem::no_id) ids.push_back(p.tetrahedron);
    ids.insert(ids.end(), p.tetrahedra.begin(), p.tetrahedra.end());
  }
  if (ids.empty()) return;
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  struct Entry {
    std::array<std::uint64_t, 4> vertices; // as listed, the input's numbering
    std::size_t octree, input;
  };
  std::vector<Entry> entries;
  entries.reserve(ids.size());
  std::vector<bool> first_vertex(tree.number_of_vertices(), false); // a filter before the search
  for (std::size_t t : ids) {
    const auto c = tree.original_tetrahedron_vertices(static_cast<Octree::Index>(t));
    entries.push_back(Entry{{{c[0], c[1], c[2], c[3]}}, t, Problem::no_id});
    first_vertex[c[0]] = true;
  }
  const auto by_vertices = [](const Entry& a, const Entry& b) {
    return std::tie(a.vertices, a.octree) < std::tie(b.vertices, b.octree);
  };
  std::sort(entries.begin(), entries.end(), by_vertices);
  std::vector<std::size_t> matched(entries.size(), 0); // at the first entry of each list of vertices
  std::size_t input = 0, found = 0;
  source.for_each_chunk([&](const std::uint64_t* c, const int*, std::size_t n) {
    for (std::size_t t = 0; t < n; ++t, ++input, c += 4) {
      if (c[0] >= first_vertex.size() || !first_vertex[c[0]]) continue;
      const Entry key{{{c[0], c[1], c[2], c[3]}}, 0, 0};
      const auto first = std::lower_bound(entries.begin(), entries.end(), key, by_vertices);
      if (first == entries.end() || first->vertices != key.vertices) continue;
      const std::size_t i = static_cast<std::size_t>(first - entries.begin());
      const std::size_t k = i + matched[i];
      if (k < entries.size() && entries[k].vertices == key.vertices) {
        entries[k].input = input;
        ++matched[i];
        ++found;
      }
    }
  });
  if (found != entries.size())
    throw std::runtime_error(file + ": " + std::to_string(entries.size() - found) +
                             " tetrahedra with problems were not found again in the file (did it change?)");
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return a.octree < b.octree; });
  const auto as_listed = [&](std::size_t t) {
    return std::lower_bound(entries.begin(), entries.end(), t,
                            [](const Entry& e, std::size_t x) { return e.octree < x; })
        ->input;
  };
  for (Problem& p : problems) {
    if (p.tetrahedron != Problem::no_id) p.tetrahedron = as_listed(p.tetrahedron);
    for (std::size_t& t : p.tetrahedra) t = as_listed(t);
    std::sort(p.tetrahedra.begin(), p.tetrahedra.end());
  }
  std::sort(problems.begin(), problems.end()); // kind, then element: as in place
}

int run_validate(const Options& o) {
  const std::string& input = o.input();
  const std::size_t kv = o.kv();
  const std::string out = o.output();
  Progress_bar progress(o.show_progress());
  // Without -o, a .vtu readable by ranges with --compact or by default from 2^25 cells: the
  // streaming construction (never the plain tetrahedron array whole), then one more pass over the
  // file if problems name tetrahedra.
  std::optional<PIO::Vtu_tetrahedron_source> streaming;
  if (out.empty()) streaming = streaming_source(o, input);
  if (streaming) progress.phase("reading the vertices of " + input);
  Mesh mesh = streaming ? streaming->read_vertices() : read_mesh(input, progress);
  const auto start = std::chrono::steady_clock::now();
  progress.phase("building the PR-star octree (k_v = " + bucket_size_string(kv) + ")");
  // Without -o the octree takes the mesh over (no second copy of V and T); with it, the mesh is kept
  // as read, to be written with the arrays `problem`.
  const auto np = params::bucket_size(kv)
                      .maximum_depth(o.max_depth())
                      .compact_tetrahedra(o.compact())
                      .coordinate_precision(o.coordinate_precision())
                      .vertex_permutation(true);
  const Octree tree = streaming ? Octree(std::move(mesh), *streaming, np)
                      : out.empty()
                          ? Octree(std::move(mesh), np)
                          : Octree(CGAL::PR_star_octree::make_input(mesh.points, mesh.tetrahedra), np);
  o.set_used_kv(tree);
  progress.phase("checking the mesh");
  std::vector<Problem> problems;
  const auto r = CGAL::PR_star_octree::check_validity(
      tree, params::problems_output(std::back_inserter(problems)).progress(progress.callback()));
  if (streaming) {
    progress.phase("numbering the tetrahedra with problems as in " + input);
    number_tetrahedra_as_listed(tree, *streaming, input, problems);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.finish();
  if (!out.empty()) {
    progress.phase("writing " + out);
    add_problem_arrays(mesh, problems);
    write_mesh_file(out, mesh);
    progress.finish();
  }
  return report_validity(o, r, seconds, &problems, tree.is_compact(), streaming.has_value());
}

} // namespace

Command validate_command() {
  return Command("validate",
                 "orientation, flat and non-manifold elements, Euler characteristic, boundary components")
      .input()
      .description(
          R"help(Checks MESH leaf by leaf: the orientation of every tetrahedron with an exact predicate (all
must have the same sign as listed; "inverted" counts the minority sign, the negative one on a
tie), flat tetrahedra, triangles in three or more tetrahedra, non-manifold vertices, the Euler
characteristic and the number of boundary components (boundary triangles connected through
edges).  Vertices in no tetrahedron are counted and listed as a warning: they do not make the
mesh invalid.

The table lists the first 10 problems of each kind, in the input's numbering (from 0):
  tetrahedron 17 (vertices 3 8 9 12): inverted (negative as listed, the minority sign)
  triangle 4 5 9: in 3 tetrahedra (10, 11, 52)
  vertex 33: unreferenced (in no tetrahedron; a warning, the mesh stays valid)
--json lists all of them, and -o writes the mesh with their places as flags.  Under mpirun
only the counts are reported (no list, no -o): the lists are one-process only.

Without OUT, a .vtu whose arrays are appended raw (as prstar generate writes them) and that has
2^25 cells or more (any size with --compact; never with --no-compact) is read in passes, as
boundary reads it: the plain tetrahedron array is never held whole, and the tetrahedra with
problems are found again in the file for their numbers (one more pass when there are any).

exit status: 0 the mesh is valid, 3 the mesh was checked and is not valid, 1 an error (missing,
unreadable or malformed file), 2 a usage error.)help")
      .kv()
      .max_depth()
      .output("OUT", cell_data_outputs(),
              "write the input mesh (same vertex and tetrahedron order) with the cell\n"
              "array `problem` (bit flags: 1 inverted, 2 flat, 4 in a triangle of 3+\n"
              "tetrahedra) and the point array `problem` (1 non-manifold, 2 unreferenced,\n"
              "4 on a triangle of 3+ tetrahedra), for ParaView: .vtu or .vtk")
      .json_keys("keys: valid, tetrahedra, inverted, degenerate, nonmanifold_triangles,\n"
                 "nonmanifold_vertices, unreferenced_vertices (a warning), euler_characteristic,\n"
                 "boundary_triangles, boundary_components, seconds, output, and problems (one\n"
                 "process only): every problem, sorted by kind then element, in the input's\n"
                 "numbering, as {kind (inverted_tetrahedron, flat_tetrahedron,\n"
                 "nonmanifold_triangle, nonmanifold_vertex, unreferenced_vertex), tetrahedron,\n"
                 "vertex, vertices, tetrahedra (of a triangle), reason}")
      .run(run_validate);
}

} // namespace prstar
