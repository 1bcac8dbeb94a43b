// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar info: what a mesh file holds (counts, cells, bounding box, arrays, labels), the shape of
// its tetrahedra and their orientation; no octree is built.

#include "commands.h"

#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/mesh_quality.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

namespace prstar {

namespace {

namespace PIO = CGAL::PR_star_octree::IO;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;

// The shape and orientation of a range of tetrahedra (added in any order: the same result).
struct Shape {
  std::size_t positive = 0, negative = 0, flat = 0; // the exact orientation as listed
  double min_dihedral = 180, max_dihedral = 0, min_radius_ratio = 1;
  std::size_t under_5 = 0, under_10 = 0;
  std::array<std::size_t, 10> radius_ratio_histogram{}; // [0, 0.1), ..., [0.9, 1]
  void add(const Shape& o) {
    positive += o.positive;
    negative += o.negative;
    flat += o.flat;
    min_dihedral = std::min(min_dihedral, o.min_dihedral);
    max_dihedral = std::max(max_dihedral, o.max_dihedral);
    min_radius_ratio = std::min(min_radius_ratio, o.min_radius_ratio);
    under_5 += o.under_5;
    under_10 += o.under_10;
    for (std::size_t i = 0; i < 10; ++i) radius_ratio_histogram[i] += o.radius_ratio_histogram[i];
  }
};

Shape measure(const Mesh& mesh, std::size_t begin, std::size_t end) {
  Shape s;
  for (std::size_t t = begin; t < end; ++t) {
    const auto& c = mesh.tetrahedra[t];
    const auto &p = mesh.points[c[0]], &q = mesh.points[c[1]], &r = mesh.points[c[2]], &u = mesh.points[c[3]];
    const CGAL::Orientation o = CGAL::orientation(p, q, r, u);
    s.positive += o == CGAL::POSITIVE;
    s.negative += o == CGAL::NEGATIVE;
    s.flat += o == CGAL::COPLANAR;
    const double lo = CGAL::PR_star_octree::min_dihedral_angle(p, q, r, u);
    const double rr = CGAL::PR_star_octree::radius_ratio(p, q, r, u);
    s.min_dihedral = std::min(s.min_dihedral, lo);
    s.max_dihedral = std::max(s.max_dihedral, CGAL::PR_star_octree::max_dihedral_angle(p, q, r, u));
    s.min_radius_ratio = std::min(s.min_radius_ratio, rr);
    s.under_5 += lo < 5;
    s.under_10 += lo < 10;
    ++s.radius_ratio_histogram[std::min<std::size_t>(9, static_cast<std::size_t>(std::max(0., rr) * 10))];
  }
  return s;
}

// Over every tetrahedron, in blocks (in parallel with TBB), with progress.
Shape measure(const Mesh& mesh, Progress_bar& progress) {
  const std::size_t n = mesh.tetrahedra.size(), block = 1 << 16, blocks = (n + block - 1) / block;
  std::vector<Shape> parts(blocks);
  std::atomic<std::size_t> done{0};
  const auto report = progress.callback();
  auto run = [&](std::size_t b) {
    parts[b] = measure(mesh, b * block, std::min(n, (b + 1) * block));
    report(++done, blocks);
  };
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t b = r.begin(); b < r.end(); ++b) run(b);
                    });
#else
  for (std::size_t b = 0; b < blocks; ++b) run(b);
#endif
  Shape s;
  for (const Shape& p : parts) s.add(p);
  return s;
}

// A data array: whether its values are all integers, their range, the non-finite ones.
struct Array_info {
  std::string name;
  bool integers = true;
  double min = std::numeric_limits<double>::infinity(), max = -std::numeric_limits<double>::infinity();
  std::size_t non_finite = 0;
};

Array_info describe(const CGAL::PR_star_octree::Data_array& a) {
  Array_info r;
  r.name = a.name;
  for (double x : a.values) {
    if (!std::isfinite(x)) {
      ++r.non_finite;
      continue;
    }
    r.integers = r.integers && x == std::floor(x);
    r.min = std::min(r.min, x);
    r.max = std::max(r.max, x);
  }
  return r;
}

void json_arrays(Json& j, const std::string& key, const std::vector<Array_info>& arrays) {
  j.key(key).begin_array();
  for (const Array_info& a : arrays) {
    j.begin_object()
        .field("name", a.name)
        .field("type", a.integers ? "integer" : "real")
        .field("components", 1);
    if (a.min <= a.max) j.field("min", a.min).field("max", a.max);
    j.field("non_finite", a.non_finite).end_object();
  }
  j.end_array();
}

void table_arrays(Table& t, const std::string& kind, const std::vector<Array_info>& arrays) {
  for (const Array_info& a : arrays)
    t.add({kind, a.name, a.integers ? "integer" : "real",
           a.min <= a.max ? short_number(a.min) + " .. " + short_number(a.max) : "-",
           a.non_finite ? std::to_string(a.non_finite) + " not finite" : ""});
}

int run_info(const Options& o) {
  const std::string& input = o.input();
  Progress_bar progress(o.show_progress());
  struct stat st;
  const double bytes = ::stat(input.c_str(), &st) == 0 ? double(st.st_size) : 0;
  progress.phase("reading " + input + " (" + human_bytes(bytes) + ")");
  const auto start = std::chrono::steady_clock::now();
  Mesh mesh;
  PIO::read_tetrahedral_mesh(input, mesh);
  const auto* format = PIO::find_mesh_format<Mesh>(input);

  progress.phase("measuring the tetrahedra");
  const Shape shape = measure(mesh, progress);
  progress.finish();

  // bounding box, unreferenced vertices, labels
  std::array<double, 3> lo{{0, 0, 0}}, hi{{0, 0, 0}};
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    for (int k = 0; k < 3; ++k) {
      lo[k] = v == 0 ? mesh.points[v][k] : std::min(lo[k], mesh.points[v][k]);
      hi[k] = v == 0 ? mesh.points[v][k] : std::max(hi[k], mesh.points[v][k]);
    }
  std::vector<char> used(mesh.points.size(), 0);
  for (const auto& c : mesh.tetrahedra)
    for (auto v : c) used[v] = 1;
  const std::size_t unreferenced = static_cast<std::size_t>(std::count(used.begin(), used.end(), 0));
  std::map<int, std::size_t> labels;
  for (int l : mesh.tetrahedron_labels) ++labels[l];
  std::vector<Array_info> point_arrays, cell_arrays;
  for (const auto& a : mesh.point_data) point_arrays.push_back(describe(a));
  for (const auto& a : mesh.cell_data) cell_arrays.push_back(describe(a));
  const double diagonal = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                    (hi[2] - lo[2]) * (hi[2] - lo[2]));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const bool any = !mesh.tetrahedra.empty();

  if (o.json()) {
    Json j;
    j.begin_object()
        .field("file", input)
        .field("format", format->name)
        .field("bytes", static_cast<std::size_t>(bytes))
        .field("vertices", mesh.points.size())
        .field("tetrahedra", mesh.tetrahedra.size())
        .field("unreferenced_vertices", unreferenced);
    j.key("other_cells").begin_object();
    for (const auto& c : mesh.skipped_cells) j.field(c.first, c.second);
    j.end_object();
    j.key("bounding_box").begin_object().key("min").begin_array();
    for (double x : lo) j.value(x);
    j.end_array().key("max").begin_array();
    for (double x : hi) j.value(x);
    j.end_array().field("diagonal", diagonal).end_object();
    json_arrays(j, "point_data", point_arrays);
    json_arrays(j, "cell_data", cell_arrays);
    j.key("labels").begin_array();
    for (const auto& l : labels) {
      j.begin_object().field("label", l.first).field("tetrahedra", l.second);
      const auto name = mesh.label_names.find(l.first);
      if (name != mesh.label_names.end()) j.field("name", name->second);
      j.end_object();
    }
    j.end_array();
    j.key("orientation")
        .begin_object()
        .field("positive", shape.positive)
        .field("negative", shape.negative)
        .field("flat", shape.flat)
        .end_object();
    j.key("quality").begin_object();
    if (any)
      j.field("min_dihedral", shape.min_dihedral)
          .field("max_dihedral", shape.max_dihedral)
          .field("min_radius_ratio", shape.min_radius_ratio);
    j.field("under_5_degrees", shape.under_5).field("under_10_degrees", shape.under_10);
    j.key("radius_ratio_histogram").begin_array();
    for (std::size_t c : shape.radius_ratio_histogram) j.value(c);
    j.end_array().end_object().field("seconds", seconds).end_object();
    std::cout << j.str() << '\n';
    return exit_success;
  }

  std::cout << input << ": " << format->name << ", " << human_bytes(bytes) << '\n';
  Table t({"", "value"});
  t.align_left(1);
  t.add({"vertices", std::to_string(mesh.points.size()) +
                         (unreferenced ? " (" + std::to_string(unreferenced) + " in no tetrahedron)" : "")});
  t.add({"tetrahedra", std::to_string(mesh.tetrahedra.size())});
  for (const auto& c : mesh.skipped_cells) t.add({c.first + " (not kept)", std::to_string(c.second)});
  t.add({"bounding box min", short_number(lo[0]) + " " + short_number(lo[1]) + " " + short_number(lo[2])});
  t.add({"bounding box max", short_number(hi[0]) + " " + short_number(hi[1]) + " " + short_number(hi[2])});
  t.add({"diagonal", short_number(diagonal)});
  t.add({"orientation as listed", std::to_string(shape.positive) + " positive, " +
                                      std::to_string(shape.negative) + " negative, " +
                                      std::to_string(shape.flat) + " flat"});
  if (any) {
    t.add(
        {"dihedral angles (degrees)", fixed(shape.min_dihedral, 2) + " .. " + fixed(shape.max_dihedral, 2)});
    t.add({"  smallest under 5 / under 10",
           std::to_string(shape.under_5) + " / " + std::to_string(shape.under_10)});
    t.add({"smallest radius ratio", fixed(shape.min_radius_ratio, 4)});
  }
  std::cout << t.str();
  if (any) {
    std::cout << "\nradius ratio (3 r / R; 1 for the regular tetrahedron):\n";
    const std::size_t most =
        *std::max_element(shape.radius_ratio_histogram.begin(), shape.radius_ratio_histogram.end());
    for (std::size_t i = 0; i < 10; ++i) {
      const std::size_t c = shape.radius_ratio_histogram[i];
      std::cout << "  " << fixed(i / 10., 1) << (i == 9 ? "-1.0 " : "-" + fixed((i + 1) / 10., 1) + " ")
                << std::string(10 - std::min<std::size_t>(10, std::to_string(c).size()), ' ') << c << "  "
                << std::string(most ? (40 * c + most - 1) / most : 0, '#') << '\n';
    }
  }
  if (!point_arrays.empty() || !cell_arrays.empty()) {
    Table a({"data", "name", "type", "range", ""});
    a.align_left(1).align_left(2).align_left(3).align_left(4);
    table_arrays(a, "point", point_arrays);
    table_arrays(a, "cell", cell_arrays);
    std::cout << '\n' << a.str();
  }
  if (!labels.empty()) {
    Table l({"label", "tetrahedra", "name"});
    l.align_left(2);
    for (const auto& x : labels) {
      const auto name = mesh.label_names.find(x.first);
      l.add({std::to_string(x.first), std::to_string(x.second),
             name == mesh.label_names.end() ? "" : name->second});
    }
    std::cout << '\n' << l.str();
  }
  return exit_success;
}

} // namespace

Command info_command() {
  return Command("info", "what a mesh file holds: counts, arrays, labels, quality, orientation")
      .input()
      .description(
          R"(Reads MESH and prints its counts (the cells other than tetrahedra as well), bounding box, point
and cell data arrays (type, range), labels with their names and counts, the orientation of the
tetrahedra as listed (exact predicate), and their shape: dihedral angles, radius ratios and
their histogram.  No octree is built.)")
      .json_keys("keys: file, format, bytes, vertices, tetrahedra, unreferenced_vertices, other_cells,\n"
                 "bounding_box {min, max, diagonal}, point_data and cell_data [{name, type,\n"
                 "components, min, max, non_finite}], labels [{label, tetrahedra, name}],\n"
                 "orientation {positive, negative, flat}, quality {min_dihedral, max_dihedral,\n"
                 "min_radius_ratio, under_5_degrees, under_10_degrees, radius_ratio_histogram}, seconds")
      .run(run_info);
}

} // namespace prstar
