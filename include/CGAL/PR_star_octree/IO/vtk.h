// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_VTK_H
#define CGAL_PR_STAR_OCTREE_IO_VTK_H

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>
#include <CGAL/PR_star_octree/IO/internal/vtk_cells.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <cstddef>
#include <istream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {

inline bool is_legacy_vtk_type(std::string_view t) {
  static const char* types[] = {
      "bit",           "unsigned_char", "char",          "unsigned_short", "short",         "unsigned_int",
      "int",           "unsigned_long", "long",          "float",          "double",        "vtktypeint64",
      "vtktypeuint64", "vtkidtype",     "signed_char",   "vtktypeint8",    "vtktypeuint8",  "vtktypeint16",
      "vtktypeuint16", "vtktypeint32",  "vtktypeuint32", "vtktypefloat32", "vtktypefloat64"};
  for (const char* s : types)
    if (iequals(t, s)) return true;
  return false;
}

/// Legacy VTK encodes spaces and other special characters of names as `%XX`.
inline std::string vtk_decode_name(std::string_view s) {
  std::string r;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto hex = [](char c) {
      return (c >= '0' && c <= '9')   ? c - '0'
             : (c >= 'a' && c <= 'f') ? c - 'a' + 10
             : (c >= 'A' && c <= 'F') ? c - 'A' + 10
                                      : -1;
    };
    if (s[i] == '%' && i + 2 < s.size() && hex(s[i + 1]) >= 0 && hex(s[i + 2]) >= 0) {
      r += char(hex(s[i + 1]) * 16 + hex(s[i + 2]));
      i += 2;
    } else {
      r += s[i];
    }
  }
  return r;
}

class Legacy_vtk_parser {
public:
  Legacy_vtk_parser(std::string_view text, const std::string& name) : r(text, name, 0) {}

  Text_reader r;

  void expect_type(const char* what) {
    const std::string_view t = r.expect_token(what);
    if (!is_legacy_vtk_type(t)) r.fail("unknown VTK data type " + quote(t) + " for " + what);
  }

  /// Reads `count` values; into `out` when not null (finite values required), else only checked
  /// to be numbers (not-a-number and infinite values allowed).
  void values(std::size_t count, std::vector<double>* out, const char* what) {
    if (out) capped_reserve(*out, count, r.remaining_bytes(), 2);
    for (std::size_t i = 0; i < count; ++i) {
      const std::string_view tok = r.expect_token(what);
      double v;
      const char* why = parse_double(tok, v);
      if (why != nullptr && (out != nullptr || std::string_view(why).substr(0, 13) != "is not finite"))
        r.fail(std::string(what) + " value " + std::to_string(i) + ": " + quote(tok) + " " + why);
      if (out) out->push_back(v);
    }
  }

  void integers(std::size_t count, std::vector<long long>& out, const char* what) {
    capped_reserve(out, count, r.remaining_bytes(), 2);
    for (std::size_t i = 0; i < count; ++i) out.push_back(r.expect_integer(what));
  }

  /// `METADATA` blocks run to the first blank line.
  void skip_metadata() {
    std::string_view line;
    r.next_raw_line(line); // the rest of the METADATA line
    while (r.next_raw_line(line))
      if (trim(line).empty()) return;
  }

  /// count = `count * components` check without overflow
  std::size_t product(std::size_t a, std::size_t b) {
    if (b != 0 && a > std::numeric_limits<std::size_t>::max() / 64 / b) r.fail("array size overflow");
    return a * b;
  }
};

template <class Mesh>
void read_vtk_text(std::string_view text, const std::string& name, Mesh& result) {
  using Point_3 = typename Mesh::Point_3;
  using Index = typename Mesh::Index;
  Legacy_vtk_parser p(text, name);
  Text_reader& r = p.r;
  Mesh mesh;

  std::string_view line;
  if (!r.next_raw_line(line) || !istarts_with(trim(line), "# vtk DataFile Version"))
    r.fail("not a legacy VTK file: the first line must be '# vtk DataFile Version x.y'");
  if (!r.next_raw_line(line)) r.fail("unexpected end of file, expected the title line");
  if (!r.next_raw_line(line)) r.fail("unexpected end of file, expected ASCII or BINARY");
  if (iequals(trim(line), "BINARY")) r.fail("binary legacy VTK files are not supported (only ASCII)");
  if (!iequals(trim(line), "ASCII")) r.fail("expected ASCII or BINARY, found " + quote(trim(line)));

  bool has_dataset = false, has_points = false, has_cells = false, has_types = false;
  std::vector<long long> starts, connectivity, types;
  std::vector<double> coordinates, labels;
  bool has_labels = false;
  std::size_t nv = 0, nc = 0;
  enum { NONE, POINT, CELL } attribute_mode = NONE;
  bool seen_point_data = false, seen_cell_data = false;

  // an attribute array of the current POINT_DATA / CELL_DATA block with 1 component
  const auto take_array = [&](const std::string& array_name, std::size_t components, const char* what) {
    const std::size_t n = attribute_mode == POINT ? nv : nc;
    const std::size_t count = p.product(n, components);
    if (attribute_mode == POINT && components == 1) {
      for (const auto& a : mesh.point_data)
        if (a.name == array_name) r.fail("duplicate point data array " + quote(array_name));
      mesh.point_data.push_back(Point_data_array{array_name, {}});
      p.values(count, &mesh.point_data.back().values, what);
    } else if (attribute_mode == CELL && components == 1 && is_vtk_label_array_name(array_name) &&
               !has_labels) {
      has_labels = true;
      p.values(count, &labels, what);
    } else {
      p.values(count, nullptr, what);
    }
  };

  std::string_view token;
  while (r.next_token(token)) {
    const std::string key = to_lower(token);
    if (!has_dataset) {
      if (key != "dataset") r.fail("expected DATASET, found " + quote(token));
      const std::string_view type = r.expect_token("dataset type");
      if (!iequals(type, "UNSTRUCTURED_GRID"))
        r.fail("DATASET " + std::string(type) + " is not supported (only UNSTRUCTURED_GRID)");
      has_dataset = true;
    } else if (key == "metadata") {
      p.skip_metadata();
    } else if (key == "points") {
      if (has_points) r.fail("duplicate POINTS section");
      has_points = true;
      nv = r.expect_count("number of points");
      if (nv > max_vertices<Index>())
        r.fail(std::to_string(nv) + " points do not fit in the index type of the mesh");
      p.expect_type("POINTS");
      p.values(p.product(nv, 3), &coordinates, "POINTS");
    } else if (key == "cells") {
      if (has_cells) r.fail("duplicate CELLS section");
      has_cells = true;
      const std::size_t a = r.expect_count("CELLS first number");
      const std::size_t b = r.expect_count("CELLS second number");
      if (iequals(r.peek_token(), "OFFSETS")) { // VTK >= 5.1: CELLS <#offsets> <#connectivity>
        r.expect_token("OFFSETS");
        p.expect_type("OFFSETS");
        if (a == 0) r.fail("CELLS: the number of offsets must be at least 1");
        p.integers(a, starts, "offset");
        if (!iequals(r.expect_token("CONNECTIVITY"), "CONNECTIVITY"))
          r.fail("expected CONNECTIVITY after the offsets");
        p.expect_type("CONNECTIVITY");
        p.integers(b, connectivity, "connectivity index");
        nc = a - 1;
      } else { // CELLS <#cells> <size>, then records "k i_1 ... i_k"
        nc = a;
        capped_reserve(starts, nc + 1, r.remaining_bytes(), 4);
        capped_reserve(connectivity, b, r.remaining_bytes(), 2);
        starts.push_back(0);
        std::size_t used = 0;
        for (std::size_t i = 0; i < nc; ++i) {
          r.set_context("cell", i);
          const long long k = r.expect_integer("number of cell vertices");
          if (k < 0 || k > 1000000) r.fail("invalid number of cell vertices " + std::to_string(k));
          used += 1 + static_cast<std::size_t>(k);
          if (used > b)
            r.fail("the cells use more than the " + std::to_string(b) + " values declared by CELLS " +
                   std::to_string(nc) + " " + std::to_string(b));
          for (long long j = 0; j < k; ++j) connectivity.push_back(r.expect_integer("vertex index"));
          starts.push_back(static_cast<long long>(connectivity.size()));
        }
        r.clear_context();
        if (used != b)
          r.fail("the cells use " + std::to_string(used) + " values, CELLS declares " + std::to_string(b));
      }
    } else if (key == "cell_types") {
      if (has_types) r.fail("duplicate CELL_TYPES section");
      has_types = true;
      const std::size_t n = r.expect_count("number of cell types");
      if (has_cells && n != nc)
        r.fail("CELL_TYPES " + std::to_string(n) + " for " + std::to_string(nc) + " cells");
      p.integers(n, types, "cell type");
    } else if (key == "point_data") {
      if (seen_point_data) r.fail("duplicate POINT_DATA section");
      if (!has_points) r.fail("POINT_DATA before POINTS");
      seen_point_data = true;
      const std::size_t n = r.expect_count("POINT_DATA size");
      if (n != nv) r.fail("POINT_DATA " + std::to_string(n) + " for " + std::to_string(nv) + " points");
      attribute_mode = POINT;
    } else if (key == "cell_data") {
      if (seen_cell_data) r.fail("duplicate CELL_DATA section");
      if (!has_cells) r.fail("CELL_DATA before CELLS");
      seen_cell_data = true;
      const std::size_t n = r.expect_count("CELL_DATA size");
      if (n != nc) r.fail("CELL_DATA " + std::to_string(n) + " for " + std::to_string(nc) + " cells");
      attribute_mode = CELL;
    } else if (key == "field") { // FIELD name #arrays, then arrays "name #components #tuples type values"
      r.expect_token("field name");
      const std::size_t narrays = r.expect_count("number of field arrays");
      for (std::size_t i = 0; i < narrays; ++i) {
        std::string_view array_name = r.expect_token("field array name");
        while (iequals(array_name, "METADATA")) {
          p.skip_metadata();
          array_name = r.expect_token("field array name");
        }
        const std::size_t components = r.expect_count("number of components");
        const std::size_t tuples = r.expect_count("number of tuples");
        p.expect_type("field array");
        const std::size_t n = attribute_mode == POINT ? nv : attribute_mode == CELL ? nc : 0;
        if (attribute_mode != NONE && tuples == n)
          take_array(vtk_decode_name(array_name), components, "field array");
        else
          p.values(p.product(components, tuples), nullptr, "field array");
      }
    } else if (attribute_mode == NONE) {
      r.fail("unknown or misplaced keyword " + quote(token));
    } else if (key == "scalars") {
      const std::string array_name = vtk_decode_name(r.expect_token("SCALARS name"));
      p.expect_type("SCALARS");
      std::string_view rest;
      r.next_raw_line(rest);
      std::vector<std::string_view> f;
      Text_reader::split(rest, f);
      long long components = 1;
      if (f.size() > 1) r.fail("SCALARS: expected at most the number of components after the type");
      if (f.size() == 1) {
        if (parse_integer(f[0], components) != nullptr || components < 1 || components > 4)
          r.fail("SCALARS: invalid number of components " + quote(f[0]) + " (1 to 4)");
      }
      if (iequals(r.peek_token(), "LOOKUP_TABLE")) {
        r.expect_token("LOOKUP_TABLE");
        r.expect_token("lookup table name");
      }
      take_array(array_name, static_cast<std::size_t>(components), "SCALARS");
    } else if (key == "lookup_table") {
      r.expect_token("lookup table name");
      const std::size_t n = r.expect_count("lookup table size");
      p.values(p.product(n, 4), nullptr, "LOOKUP_TABLE");
    } else if (key == "vectors" || key == "normals" || key == "tensors" || key == "tensors6") {
      r.expect_token("array name");
      p.expect_type(key.c_str());
      const std::size_t components = key == "tensors" ? 9 : key == "tensors6" ? 6 : 3;
      p.values(p.product(attribute_mode == POINT ? nv : nc, components), nullptr, "array");
    } else if (key == "texture_coordinates") {
      r.expect_token("array name");
      const std::size_t dim = r.expect_count("texture dimension");
      if (dim < 1 || dim > 3) r.fail("invalid texture dimension " + std::to_string(dim));
      p.expect_type("TEXTURE_COORDINATES");
      p.values(p.product(attribute_mode == POINT ? nv : nc, dim), nullptr, "TEXTURE_COORDINATES");
    } else if (key == "color_scalars") {
      r.expect_token("array name");
      const std::size_t n = r.expect_count("number of color components");
      p.values(p.product(attribute_mode == POINT ? nv : nc, n), nullptr, "COLOR_SCALARS");
    } else if (key == "global_ids" || key == "pedigree_ids") {
      r.expect_token("array name");
      p.expect_type(key.c_str());
      p.values(attribute_mode == POINT ? nv : nc, nullptr, "ids");
    } else {
      r.fail("unknown or misplaced keyword " + quote(token));
    }
  }
  if (!has_dataset) r.fail("no DATASET line");
  if (!has_points) r.fail("no POINTS section");
  if (!has_cells) r.fail("no CELLS section");
  if (!has_types) r.fail("no CELL_TYPES section");

  capped_reserve(mesh.points, nv, coordinates.size() * 8, 24);
  for (std::size_t i = 0; i < nv; ++i)
    mesh.points.push_back(Point_3(coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]));
  mesh.tetrahedra.reserve(nc);
  vtk_cells_to_tetrahedra(starts, connectivity, types, nv, 0, mesh.tetrahedra,
                          [&](const std::string& m) { throw Read_error(name, 0, m); });
  if (has_labels)
    vtk_labels_to_int(labels, mesh.tetrahedron_labels,
                      [&](const std::string& m) { throw Read_error(name, 0, m); });
  result = std::move(mesh);
}

} // namespace internal

/// \ingroup PkgPRStarOctreeIO
/// Reads a legacy VTK text from a stream; `name` is used in error messages.  See
/// `read_vtk(const std::string&, Mesh&)`.
template <class Mesh>
void read_vtk(std::istream& in, Mesh& mesh, const std::string& name = "<stream>") {
  const std::string text = internal::load_stream(in, name);
  internal::read_vtk_text(text, name, mesh);
}

/// \ingroup PkgPRStarOctreeIO
/// Reads a tetrahedral mesh from a legacy VTK file (`.vtk`), ASCII only.
///
/// Expected: the header `# vtk DataFile Version x.y`, a title line, `ASCII`,
/// `DATASET UNSTRUCTURED_GRID`, `POINTS n type`, the cells either as `CELLS n size` followed by
/// records `4 a b c d` (up to version 5.0) or as `CELLS nOffsets nConnectivity` followed by
/// `OFFSETS type` and `CONNECTIVITY type` arrays (version 5.1), and `CELL_TYPES n`.  Every cell
/// must be a tetrahedron (type 10): any other cell is an error naming the cell and its type.
///
/// `POINT_DATA`: every one-component `SCALARS` array (`LOOKUP_TABLE` line optional) and every
/// one-component array of a `FIELD` becomes a point-data array, in file order (`%XX` escapes of
/// names decoded); arrays with several components, `VECTORS`, `NORMALS`, `TENSORS`,
/// `TEXTURE_COORDINATES`, `COLOR_SCALARS`, lookup tables, ids and `METADATA` blocks are skipped
/// (their values are still checked to be numbers).  `CELL_DATA`: a one-component array named
/// `label` or `medit:ref` gives `tetrahedron_labels` (rounded), the rest is skipped likewise.
/// Keywords are case-insensitive; comments are not part of the format.
///
/// \throws Read_error on any problem (binary file, other dataset, non-tetrahedral cell, count
/// mismatch, truncated data, index out of range, non-finite coordinate or point-data value...).
/// `mesh` is then left unchanged; it is replaced on success.
template <class Mesh>
void read_vtk(const std::string& filename, Mesh& mesh) {
  const std::string text = internal::load_file(filename);
  internal::read_vtk_text(text, filename, mesh);
}

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_VTK_H
