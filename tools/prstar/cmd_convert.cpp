// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// prstar convert: a mesh file to another format, keeping the vertex and tetrahedron order, the
// point data, the cell data, the labels and their names wherever the target format can hold them.
// What the target drops is found by reading the written file back (before it replaces OUT) and
// comparing it with the input, so the report is what the file holds, not what a table claims.

#include "commands.h"

#include <CGAL/PR_star_octree/IO.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace prstar {

namespace {

namespace PIO = CGAL::PR_star_octree::IO;

// The write options of the command line, for the writer's format table record.
PIO::internal::Write_options write_options(const Options& o) {
  PIO::internal::Write_options w;
  if (o.flag("--ascii") || o.flag("--binary")) {
    w.has_binary = true;
    w.binary = o.flag("--binary");
  }
  if (o.has("--compression")) {
    const std::string c = o.get("--compression");
    if (c != "zlib" && c != "none") throw Usage_error("--compression must be zlib or none");
    w.has_compression = true;
    w.compression = c == "zlib" ? PIO::Compression::zlib : PIO::Compression::none;
  }
  if (o.has("--format-version")) {
    w.has_version = true;
    w.version = o.get_double("--format-version", 0);
  }
  return w;
}

// Checks the options against the target format before anything is read.
void check_convert(const Options& o) {
  if (o.flag("--ascii") && o.flag("--binary")) throw Usage_error("give --ascii or --binary, not both");
  const auto* f = PIO::find_mesh_format<Mesh>(o.output());
  if (f == nullptr) return; // refused by the output check already
  try {
    PIO::internal::resolve_write_options(write_options(o), *f->write_options, f->name, o.output());
  } catch (const PIO::Write_error& e) {
    throw Usage_error(e.what());
  }
}

std::string quoted_list(const std::vector<std::string>& names) {
  std::string r;
  for (const std::string& n : names) r += (r.empty() ? "'" : ", '") + n + "'";
  return r;
}

bool same_bits(double a, double b) {
  return a == b ? std::signbit(a) == std::signbit(b) : (std::isnan(a) && std::isnan(b));
}

bool same_values(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!same_bits(a[i], b[i])) return false;
  return true;
}

// What a written file holds of the input: `dropped` (not there, or changed), `notes` (kept in
// another form: an array under another name).
struct Comparison {
  std::vector<std::string> dropped, notes;
};

void compare_arrays(const std::vector<CGAL::PR_star_octree::Data_array>& in,
                    const std::vector<CGAL::PR_star_octree::Data_array>& back, const std::string& kind,
                    Comparison& c) {
  std::vector<std::string> lost, rounded;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const CGAL::PR_star_octree::Data_array* b = nullptr;
    for (const auto& x : back)
      if (x.name == in[i].name) b = &x;
    if (b == nullptr && i < back.size() && same_values(back[i].values, in[i].values)) {
      // an unnamed format (TetGen attributes): the same values, in the same place
      c.notes.push_back(kind + " '" + in[i].name + "' kept unnamed (read back as '" + back[i].name + "')");
      continue;
    }
    if (b == nullptr)
      lost.push_back(in[i].name);
    else if (!same_values(b->values, in[i].values))
      rounded.push_back(in[i].name);
  }
  if (!lost.empty()) c.dropped.push_back(kind + " " + quoted_list(lost));
  if (!rounded.empty()) c.dropped.push_back(kind + " " + quoted_list(rounded) + " (values changed)");
}

// Compares the mesh read back from the written file with the input.
Comparison compare(const Mesh& in, const Mesh& back) {
  Comparison c;
  if (back.points.size() != in.points.size() || back.tetrahedra.size() != in.tetrahedra.size())
    throw std::runtime_error("the file written holds " + std::to_string(back.points.size()) +
                             " vertices and " + std::to_string(back.tetrahedra.size()) + " tetrahedra, not " +
                             std::to_string(in.points.size()) + " and " +
                             std::to_string(in.tetrahedra.size()));
  std::size_t moved = 0;
  for (std::size_t v = 0; v < in.points.size(); ++v)
    for (int k = 0; k < 3; ++k)
      if (!same_bits(in.points[v][k], back.points[v][k])) {
        ++moved;
        break;
      }
  if (moved != 0) c.dropped.push_back("exact coordinates (" + std::to_string(moved) + " vertices rounded)");
  if (back.tetrahedra != in.tetrahedra)
    c.dropped.push_back("the order of the tetrahedra or of their vertices");
  const auto has_labels = [](const Mesh& m) {
    for (int l : m.tetrahedron_labels)
      if (l != m.tetrahedron_labels.front()) return true;
    return !m.tetrahedron_labels.empty() && m.tetrahedron_labels.front() != 0;
  };
  if (has_labels(in)) {
    if (!has_labels(back))
      c.dropped.push_back("the labels");
    else if (back.tetrahedron_labels != in.tetrahedron_labels)
      c.dropped.push_back("the labels (values changed)");
  }
  std::vector<std::string> names;
  for (const auto& n : in.label_names) {
    const auto it = back.label_names.find(n.first);
    if (it == back.label_names.end() || it->second != n.second) names.push_back(n.second);
  }
  if (!names.empty()) c.dropped.push_back("the label names " + quoted_list(names));
  compare_arrays(in.point_data, back.point_data, "point data", c);
  compare_arrays(in.cell_data, back.cell_data, "cell data", c);
  return c;
}

std::string format_name(const std::string& file) {
  const auto* f = PIO::find_mesh_format<Mesh>(file);
  return f == nullptr ? "?" : f->name;
}

int run_convert(const Options& o) {
  const std::string& input = o.input();
  const std::string out = o.output();
  Progress_bar progress(o.show_progress());
  const auto start = std::chrono::steady_clock::now();
  const Mesh mesh = read_mesh(input, progress);
  const auto* target = PIO::find_mesh_format<Mesh>(out);
  const PIO::internal::Write_options options = write_options(o);
  Comparison c;
  write_through_temporary(out, [&](const std::string& tmp) {
    progress.phase("writing " + out);
    target->write_file(tmp, mesh, options);
    progress.phase("reading " + out + " back");
    Mesh back;
    PIO::read_tetrahedral_mesh(tmp, back);
    c = compare(mesh, back);
    if (!mesh.skipped_cells.empty()) { // the package keeps tetrahedra only
      std::string what;
      for (const auto& x : mesh.skipped_cells)
        what += (what.empty() ? "" : ", ") + std::to_string(x.second) + " " + x.first + "(s)";
      c.dropped.push_back("the cells other than tetrahedra (" + what +
                          "; the package keeps tetrahedra only)");
    }
    if (!c.dropped.empty() && o.flag("--strict")) {
      std::string what;
      for (const std::string& d : c.dropped) what += "; " + d;
      throw std::runtime_error(out + ": not kept:" + what.substr(1) + " (--strict: nothing written)");
    }
  });
  progress.finish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const std::string& d : c.dropped)
    std::cerr << "prstar convert: " << out << ": not kept (" << target->name << "): " << d << '\n';
  if (o.json()) {
    Json j;
    j.begin_object()
        .field("input", input)
        .field("input_format", format_name(input))
        .field("output", out)
        .field("output_format", target->name)
        .field("vertices", mesh.points.size())
        .field("tetrahedra", mesh.tetrahedra.size());
    j.key("dropped").begin_array();
    for (const std::string& d : c.dropped) j.value(d);
    j.end_array().key("notes").begin_array();
    for (const std::string& d : c.notes) j.value(d);
    j.end_array().field("seconds", seconds).end_object();
    std::cout << j.str() << '\n';
  } else if (o.show_summary()) {
    std::cout << input << " (" << format_name(input) << ") -> " << out << " (" << target->name
              << "): " << mesh.points.size() << " vertices, " << mesh.tetrahedra.size() << " tetrahedra, "
              << (c.dropped.empty() ? "everything kept"
                                    : std::to_string(c.dropped.size()) + " thing(s) dropped")
              << " (" << fixed(seconds, 2) << " s)\n";
    for (const std::string& n : c.notes) std::cout << "  " << n << '\n';
  }
  return exit_success;
}

} // namespace

Command convert_command() {
  return Command("convert", "convert a mesh file to another format, keeping order and data")
      .input("IN")
      .output_positional()
      .synopsis("OUT [--ascii | --binary] [--compression zlib|none] [--format-version V] [--strict]")
      .description(
          R"(Reads IN and writes OUT in the format of its extension, with the same vertices and tetrahedra in
the same order, the point data, the cell data, the labels and their names wherever the format can
hold them.  The file written is read back and compared with IN before it replaces OUT: what the
format could not hold (named arrays, labels, names, exact coordinates) is named on stderr, and
with --strict it is an error and nothing is written.)")
      .flag("--ascii", "write a text file (the formats that have both)")
      .flag("--binary", "write a binary file (the formats that have both)")
      .option("--compression", "zlib|none", "compression of the binary data (.vtu)")
      .option("--format-version", "V", "the version of the format written, e.g. 2.2 or 4.1 for .msh")
      .flag("--strict", "an error (exit status 1, nothing written) when OUT would drop anything")
      .output("OUT", "", "the file to write", true)
      .quiet_silences_summary()
      .json_keys("keys: input, input_format, output, output_format, vertices, tetrahedra, dropped\n"
                 "(what the format could not hold), notes, seconds")
      .check(check_convert)
      .run(run_convert);
}

} // namespace prstar
