// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTK_LEGACY_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTK_LEGACY_H

// The legacy VTK (.vtk) reader and writer: ASCII and binary (big-endian), versions 4.x and 5.x.

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/internal/file_bytes.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>
#include <CGAL/PR_star_octree/IO/internal/vtk_cells.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>
#include <CGAL/Named_function_parameters.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <fstream>
#include <istream>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>
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

/// Size and kind of a legacy VTK data type in a binary file (big-endian); false for `bit`.
inline bool legacy_vtk_binary_type(std::string_view t, std::size_t& size,
                                   int& kind /* 0 signed, 1 unsigned, 2 float */) {
  static const struct {
    const char* name;
    std::size_t size;
    int kind;
  } table[] = {
      {"unsigned_char", 1, 1}, {"char", 1, 0},          {"signed_char", 1, 0},    {"vtktypeint8", 1, 0},
      {"vtktypeuint8", 1, 1},  {"short", 2, 0},         {"unsigned_short", 2, 1}, {"vtktypeint16", 2, 0},
      {"vtktypeuint16", 2, 1}, {"int", 4, 0},           {"unsigned_int", 4, 1},   {"vtktypeint32", 4, 0},
      {"vtktypeuint32", 4, 1}, {"vtkidtype", 4, 0},     {"long", 8, 0},           {"unsigned_long", 8, 1},
      {"vtktypeint64", 8, 0},  {"vtktypeuint64", 8, 1}, {"float", 4, 2},          {"vtktypefloat32", 4, 2},
      {"double", 8, 2},        {"vtktypefloat64", 8, 2}};
  for (const auto& x : table)
    if (iequals(t, x.name)) {
      size = x.size;
      kind = x.kind;
      return true;
    }
  return false;
}

class Legacy_vtk_parser {
public:
  Legacy_vtk_parser(std::string_view text, const std::string& name) : r(text, name, 0), text_(text) {}

  Text_reader r;
  bool binary = false;

  std::string_view expect_type(const char* what) {
    const std::string_view t = r.expect_token(what);
    if (!is_legacy_vtk_type(t)) r.fail("unknown VTK data type " + quote(t) + " for " + what);
    return t;
  }

  /// Reads `count` values of type `type`; into `out` when not null (finite values required), else
  /// only checked to be numbers in ascii (not-a-number and infinite values allowed) and skipped in
  /// binary.
  void values(std::size_t count, std::vector<double>* out, const char* what, std::string_view type) {
    if (binary) {
      binary_values(count, type, out, nullptr, what);
      return;
    }
    if (out) {
      capped_reserve(*out, count, r.remaining_bytes(), 2);
      advise_huge_pages(out->data(), out->capacity() * sizeof(double));
    }
    for (std::size_t i = 0; i < count; ++i) {
      double v;
      if (r.fast_double(v)) {
        if (out) out->push_back(v);
        continue;
      }
      const std::string_view tok = r.expect_token(what);
      const char* why = parse_double(tok, v);
      if (why != nullptr && (out != nullptr || std::string_view(why).substr(0, 13) != "is not finite"))
        r.fail(std::string(what) + " value " + std::to_string(i) + ": " + quote(tok) + " " + why);
      if (out) out->push_back(v);
    }
  }

  void integers(std::size_t count, std::vector<long long>& out, const char* what, std::string_view type) {
    if (binary) {
      binary_values(count, type, nullptr, &out, what);
      return;
    }
    capped_reserve(out, count, r.remaining_bytes(), 2);
    advise_huge_pages(out.data(), out.capacity() * sizeof(long long));
    for (std::size_t i = 0; i < count; ++i) out.push_back(r.expect_integer(what));
  }

  /// In a binary file: the data start on the line after the current one.
  void skip_to_next_line() {
    std::string_view rest;
    r.next_raw_line(rest);
  }

  /// Reads `count` big-endian binary values starting at the next line.
  void binary_values(std::size_t count, std::string_view type, std::vector<double>* dout,
                     std::vector<long long>* iout, const char* what) {
    std::size_t size = 0;
    int kind = 0;
    if (!legacy_vtk_binary_type(type, size, kind))
      r.fail(std::string(what) + ": data type " + quote(type) + " is not supported in binary files");
    if (iout != nullptr && kind == 2)
      r.fail(std::string(what) + " must have an integer type, not " + quote(type));
    skip_to_next_line();
    Text_reader::Mark m = r.mark();
    const std::size_t begin = m.pos;
    const std::size_t left = text_.size() - std::min(begin, text_.size());
    if (count > left / size)
      r.fail("unexpected end of file in the binary " + std::string(what) + " data at byte " +
             std::to_string(begin) + ": " + std::to_string(count) + " values of " + std::to_string(size) +
             " bytes announced, " + std::to_string(left) + " bytes left");
    Byte_cursor c(text_, r.name(), host_is_little_endian()); // big-endian data
    c.seek(begin);
    // one loop per stored type, chosen once; the values were bounded above, so that they are read
    // in place (`load_value`) into the resized output
    const bool swap = c.swap();
    const char* const data = c.here();
    const auto convert = [&](auto stored) {
      using T = decltype(stored);
      const auto bad = [&](std::size_t i, const char* why) {
        r.fail(std::string(what) + " value " + std::to_string(i) + " (byte " +
               std::to_string(begin + i * size) + ") " + why);
      };
      if (dout != nullptr) {
        const std::size_t at = dout->size();
        dout->resize(at + count);
        double* out = dout->data() + at;
        for (std::size_t i = 0; i < count; ++i) {
          const T v = load_value<T>(data + i * sizeof(T), swap);
          if constexpr (std::is_floating_point<T>::value) {
            if (!std::isfinite(v)) bad(i, "is not finite");
          } else if constexpr (std::is_same<T, std::uint64_t>::value) {
            if (v > static_cast<std::uint64_t>(std::numeric_limits<long long>::max())) bad(i, "is too large");
          }
          out[i] = static_cast<double>(v);
        }
      } else if constexpr (!std::is_floating_point<T>::value) {
        const std::size_t at = iout->size();
        iout->resize(at + count);
        long long* out = iout->data() + at;
        for (std::size_t i = 0; i < count; ++i) {
          const T v = load_value<T>(data + i * sizeof(T), swap);
          if constexpr (std::is_same<T, std::uint64_t>::value)
            if (v > static_cast<std::uint64_t>(std::numeric_limits<long long>::max())) bad(i, "is too large");
          out[i] = static_cast<long long>(v);
        }
      }
      c.skip(count * sizeof(T), what);
    };
    if (dout != nullptr || iout != nullptr) {
      if (kind == 2) {
        if (size == 4)
          convert(float());
        else
          convert(double());
      } else if (kind == 1) {
        if (size == 1)
          convert(std::uint8_t());
        else if (size == 2)
          convert(std::uint16_t());
        else if (size == 4)
          convert(std::uint32_t());
        else
          convert(std::uint64_t());
      } else {
        if (size == 1)
          convert(std::int8_t());
        else if (size == 2)
          convert(std::int16_t());
        else if (size == 4)
          convert(std::int32_t());
        else
          convert(std::int64_t());
      }
    }
    m.pos = begin + count * size;
    r.restore(m);
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

  /// whether the text at the current position (after blanks) starts with `word`
  bool next_is(std::string_view word) {
    Text_reader::Mark m = r.mark();
    std::size_t p = m.pos;
    while (p < text_.size() && is_space(text_[p])) ++p;
    return text_.size() - p >= word.size() && iequals(text_.substr(p, word.size()), word);
  }

private:
  std::string_view text_;
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
  const std::size_t format_line = r.line();
  if (iequals(trim(line), "BINARY"))
    p.binary = true;
  else if (!iequals(trim(line), "ASCII"))
    r.fail("expected ASCII or BINARY, found " + quote(trim(line)));

  bool has_dataset = false, has_points = false, has_cells = false, has_types = false;
  std::vector<long long> starts, connectivity, types;
  // ASCII CELLS records: while every cell has 4 vertices the starts are implicit (4 i, `starts`
  // stays empty), and while every vertex index fits they are kept on 4 bytes in `compact` (the
  // arrays of a large tetrahedral mesh); both fall back to `starts` and `connectivity` otherwise
  bool implicit_starts = false, compact_cells = false;
  std::vector<std::uint32_t> compact;
  std::vector<double> coordinates;
  std::vector<Data_array> cell_arrays; // one-component cell data, labels among them
  std::size_t nv = 0, nc = 0;
  bool float32_points = false; // POINTS n float (or vtktypefloat32)
  enum { NONE, POINT, CELL } attribute_mode = NONE;
  bool seen_point_data = false, seen_cell_data = false;

  // an attribute array of the current POINT_DATA / CELL_DATA block
  const auto take_array = [&](const std::string& array_name, std::size_t components, const char* what,
                              std::string_view type) {
    const std::size_t n = attribute_mode == POINT ? nv : nc;
    const std::size_t count = p.product(n, components);
    if (attribute_mode == POINT && components == 1) {
      for (const auto& a : mesh.point_data)
        if (a.name == array_name) r.fail("duplicate point data array " + quote(array_name));
      mesh.point_data.push_back(Data_array{array_name, {}});
      p.values(count, &mesh.point_data.back().values, what, type);
    } else if (attribute_mode == CELL && components == 1) {
      for (const auto& a : cell_arrays)
        if (a.name == array_name) r.fail("duplicate cell data array " + quote(array_name));
      cell_arrays.push_back(Data_array{array_name, {}});
      p.values(count, &cell_arrays.back().values, what, type);
    } else {
      p.values(count, nullptr, what, type);
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
      const std::string_view type = p.expect_type("POINTS");
      p.values(p.product(nv, 3), &coordinates, "POINTS", type);
      float32_points = iequals(type, "float") || iequals(type, "vtktypefloat32");
    } else if (key == "cells") {
      if (has_cells) r.fail("duplicate CELLS section");
      has_cells = true;
      const std::size_t a = r.expect_count("CELLS first number");
      const std::size_t b = r.expect_count("CELLS second number");
      if (p.next_is("OFFSETS")) { // VTK >= 5.1: CELLS <#offsets> <#connectivity>
        r.expect_token("OFFSETS");
        const std::string_view ot = p.expect_type("OFFSETS");
        if (a == 0) r.fail("CELLS: the number of offsets must be at least 1");
        p.integers(a, starts, "offset", ot);
        if (!iequals(r.expect_token("CONNECTIVITY"), "CONNECTIVITY"))
          r.fail("expected CONNECTIVITY after the offsets");
        const std::string_view ct = p.expect_type("CONNECTIVITY");
        p.integers(b, connectivity, "connectivity index", ct);
        nc = a - 1;
      } else if (p.binary) { // CELLS <#cells> <size>, then int32 records "k i_1 ... i_k"
        nc = a;
        std::vector<long long> records;
        p.integers(b, records, "CELLS", "int");
        capped_reserve(starts, nc + 1, records.size() + 1, 1);
        connectivity.reserve(records.size());
        starts.push_back(0);
        std::size_t at = 0;
        for (std::size_t i = 0; i < nc; ++i) {
          if (at >= records.size())
            r.fail("the cells use more than the " + std::to_string(b) + " values declared by CELLS " +
                   std::to_string(nc) + " " + std::to_string(b) + " (cell " + std::to_string(i) + ")");
          const long long k = records[at++];
          if (k < 0 || static_cast<unsigned long long>(k) > records.size() - at)
            r.fail("cell " + std::to_string(i) + ": invalid number of cell vertices " + std::to_string(k) +
                   " (the CELLS data hold " + std::to_string(records.size() - at) + " more values)");
          connectivity.insert(connectivity.end(), records.begin() + static_cast<std::ptrdiff_t>(at),
                              records.begin() +
                                  static_cast<std::ptrdiff_t>(at + static_cast<std::size_t>(k)));
          at += static_cast<std::size_t>(k);
          starts.push_back(static_cast<long long>(connectivity.size()));
        }
        if (at != records.size())
          r.fail("the cells use " + std::to_string(at) + " values, CELLS declares " + std::to_string(b));
      } else { // CELLS <#cells> <size>, then records "k i_1 ... i_k"
        nc = a;
        implicit_starts = compact_cells = true;
        capped_reserve(compact, b, r.remaining_bytes(), 2);
        advise_huge_pages(compact.data(), compact.capacity() * sizeof(std::uint32_t));
        std::size_t used = 0;
        for (std::size_t i = 0; i < nc; ++i) {
          r.set_context("cell", i);
          const long long k = r.expect_integer("number of cell vertices");
          if (k < 0 || k > 1000000) r.fail("invalid number of cell vertices " + std::to_string(k));
          used += 1 + static_cast<std::size_t>(k);
          if (used > b)
            r.fail("the cells use more than the " + std::to_string(b) + " values declared by CELLS " +
                   std::to_string(nc) + " " + std::to_string(b));
          if (implicit_starts && k != 4) { // explicit starts from now on
            implicit_starts = false;
            capped_reserve(starts, nc + 1, r.remaining_bytes(), 4);
            for (std::size_t c = 0; c <= i; ++c) starts.push_back(4 * static_cast<long long>(c));
          }
          for (long long j = 0; j < k; ++j) {
            const long long v = r.expect_integer("vertex index");
            if (compact_cells && v >= 0 && v <= 0xffffffffLL) {
              compact.push_back(static_cast<std::uint32_t>(v));
              continue;
            }
            if (compact_cells) { // 8-byte indices from now on
              compact_cells = false;
              capped_reserve(connectivity, b, r.remaining_bytes() + 2 * compact.size(), 2);
              connectivity.assign(compact.begin(), compact.end());
              std::vector<std::uint32_t>().swap(compact);
            }
            connectivity.push_back(v);
          }
          if (!implicit_starts)
            starts.push_back(static_cast<long long>(compact_cells ? compact.size() : connectivity.size()));
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
      p.integers(n, types, "cell type", "int");
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
        const std::string_view type = p.expect_type("field array");
        const std::size_t n = attribute_mode == POINT ? nv : attribute_mode == CELL ? nc : 0;
        if (attribute_mode != NONE && tuples == n)
          take_array(vtk_decode_name(array_name), components, "field array", type);
        else
          p.values(p.product(components, tuples), nullptr, "field array", type);
      }
    } else if (attribute_mode == NONE) {
      r.fail("unknown or misplaced keyword " + quote(token));
    } else if (key == "scalars") {
      const std::string array_name = vtk_decode_name(r.expect_token("SCALARS name"));
      const std::string_view type = p.expect_type("SCALARS");
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
      if (p.next_is("LOOKUP_TABLE")) {
        r.expect_token("LOOKUP_TABLE");
        r.expect_token("lookup table name");
      } else if (p.binary) {
        // the data start right after the SCALARS line: come back to its end
        Text_reader::Mark m = r.mark();
        --m.pos;
        r.restore(m);
      }
      take_array(array_name, static_cast<std::size_t>(components), "SCALARS", type);
    } else if (key == "lookup_table") {
      r.expect_token("lookup table name");
      const std::size_t n = r.expect_count("lookup table size");
      if (p.binary)
        p.values(p.product(n, 4), nullptr, "LOOKUP_TABLE", "unsigned_char");
      else
        p.values(p.product(n, 4), nullptr, "LOOKUP_TABLE", "float");
    } else if (key == "vectors" || key == "normals" || key == "tensors" || key == "tensors6") {
      r.expect_token("array name");
      const std::string_view type = p.expect_type(key.c_str());
      const std::size_t components = key == "tensors" ? 9 : key == "tensors6" ? 6 : 3;
      p.values(p.product(attribute_mode == POINT ? nv : nc, components), nullptr, "array", type);
    } else if (key == "texture_coordinates") {
      r.expect_token("array name");
      const std::size_t dim = r.expect_count("texture dimension");
      if (dim < 1 || dim > 3) r.fail("invalid texture dimension " + std::to_string(dim));
      const std::string_view type = p.expect_type("TEXTURE_COORDINATES");
      p.values(p.product(attribute_mode == POINT ? nv : nc, dim), nullptr, "TEXTURE_COORDINATES", type);
    } else if (key == "color_scalars") {
      r.expect_token("array name");
      const std::size_t n = r.expect_count("number of color components");
      p.values(p.product(attribute_mode == POINT ? nv : nc, n), nullptr, "COLOR_SCALARS",
               p.binary ? "unsigned_char" : "float");
    } else if (key == "global_ids" || key == "pedigree_ids") {
      r.expect_token("array name");
      const std::string_view type = p.expect_type(key.c_str());
      p.values(attribute_mode == POINT ? nv : nc, nullptr, "ids", type);
    } else {
      r.fail("unknown or misplaced keyword " + quote(token));
    }
  }
  if (!has_dataset)
    r.fail_at(format_line, std::string("the ") + (p.binary ? "binary" : "ASCII") +
                               " file ends after its header: no DATASET line");
  if (!has_points) r.fail("no POINTS section");
  if (!has_cells) r.fail("no CELLS section");
  if (!has_types) r.fail("no CELL_TYPES section");

  capped_reserve(mesh.points, nv, coordinates.size() * 8, 24);
  for (std::size_t i = 0; i < nv; ++i)
    mesh.points.push_back(Point_3(coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]));
  // ASCII numbers of type float: the floats nearest to them (as VTK reads them), unless one is
  // beyond the float range (then read as doubles)
  if (float32_points && !p.binary) float32_points = round_points_to_float(mesh.points, 0);
  set_float32_points(mesh, float32_points);
  mesh.tetrahedra.reserve(nc);
  std::vector<char> kept;
  const auto cell_fail = [&](const std::string& m) { throw Read_error(name, 0, m); };
  if (implicit_starts || compact_cells) {
    // the checks of vtk_cells_to_tetrahedra(): the starts begin at 0 and end at the size of the
    // connectivity by construction
    if (types.size() != nc)
      cell_fail(std::to_string(types.size()) + " cell types for " + std::to_string(nc) + " cells");
    if (nc > 0) {
      Vtk_tetrahedra_builder<typename Mesh::Tetrahedron, long long> builder(
          implicit_starts ? nullptr : starts.data() + 1, types.data(), nc, nv, 0, mesh.tetrahedra, kept,
          mesh.skipped_cells, cell_fail);
      if (compact_cells) { // 4-byte indices handed over in chunks of 8-byte ones
        long long chunk[4096];
        for (std::size_t at = 0; at < compact.size(); at += 4096) {
          const std::size_t n = std::min<std::size_t>(4096, compact.size() - at);
          for (std::size_t j = 0; j < n; ++j) chunk[j] = compact[at + j];
          builder(chunk, n);
        }
      } else {
        builder(connectivity.data(), connectivity.size());
      }
      builder.finish();
    }
  } else {
    vtk_cells_to_tetrahedra(starts, connectivity, types, nv, 0, mesh.tetrahedra, kept, mesh.skipped_cells,
                            cell_fail);
  }
  bool has_labels = false;
  for (Data_array& a : cell_arrays) {
    vtk_keep_cells(a.values, kept);
    if (!has_labels && is_vtk_label_array_name(a.name) && vtk_integer_valued(a.values)) {
      vtk_labels_to_int(a.values, mesh.tetrahedron_labels,
                        [&](const std::string& m) { throw Read_error(name, 0, m); });
      has_labels = true;
    } else {
      mesh.cell_data.push_back(std::move(a));
    }
  }
  result = std::move(mesh);
}

/// Legacy VTK names cannot hold blanks: `%XX` escapes (what VTK's reader decodes).
inline std::string vtk_encode_name(const std::string& s) {
  static const char* hex = "0123456789ABCDEF";
  std::string r;
  for (unsigned char c : s) {
    if (c <= ' ' || c == '%' || c >= 127) {
      r += '%';
      r += hex[c >> 4];
      r += hex[c & 15];
    } else {
      r += char(c);
    }
  }
  return r;
}

/// Writes legacy VTK 4.2 (readable by VTK 5 to 9, ParaView and meshio: `CELLS` records of 32-bit
/// integers) or 5.1 (VTK 9: `OFFSETS` and `CONNECTIVITY` arrays of 64-bit integers), ascii or binary
/// (big-endian).
template <class Mesh>
void write_vtk_stream(std::ostream& out, const Mesh& mesh, const std::vector<Data_array>& extra_point_data,
                      bool binary, bool version_51, const std::string& name) {
  const std::vector<const Data_array*> data = check_named_arrays_for_writing(mesh, extra_point_data, name);
  const bool float32 = write_float32_points(mesh, name);
  const std::size_t nv = mesh.points.size(), nt = mesh.tetrahedra.size();
  if (binary && !version_51 && (nt > std::size_t(0x7fffffff) / 5 || nv > std::size_t(0x7fffffff)))
    throw Write_error(name,
                      "too many tetrahedra or vertices for the 32-bit cells of a binary legacy VTK file");
  std::string buf;
  const auto put_be = [&](const void* v, std::size_t size) {
    unsigned char b[8];
    std::memcpy(b, v, size);
    if (host_is_little_endian())
      for (std::size_t k = 0; k < size / 2; ++k) std::swap(b[k], b[size - 1 - k]);
    buf.append(reinterpret_cast<const char*>(b), size);
  };
  const auto put_double = [&](double v, char sep) {
    if (binary) {
      put_be(&v, 8);
    } else {
      append_double(buf, v);
      buf += sep;
    }
  };
  const auto put_float = [&](double d, char sep) {
    if (binary) {
      const float v = static_cast<float>(d);
      put_be(&v, 4);
    } else {
      append_float(buf, d);
      buf += sep;
    }
  };
  const auto put_int = [&](std::int32_t v, char sep) {
    if (binary) {
      put_be(&v, 4);
    } else {
      append_integer(buf, v);
      buf += sep;
    }
  };
  const auto put_int64 = [&](std::int64_t v, char sep) {
    if (binary) {
      put_be(&v, 8);
    } else {
      append_integer(buf, v);
      buf += sep;
    }
  };
  buf += version_51 ? "# vtk DataFile Version 5.1\n" : "# vtk DataFile Version 4.2\n";
  buf += "PR-star octree tetrahedral mesh\n";
  buf += binary ? "BINARY\n" : "ASCII\n";
  buf += "DATASET UNSTRUCTURED_GRID\nPOINTS ";
  append_integer(buf, nv);
  buf += float32 ? " float\n" : " double\n";
  const auto put_coordinate = [&](double v, char sep) { float32 ? put_float(v, sep) : put_double(v, sep); };
  for (const auto& pt : mesh.points) {
    put_coordinate(CGAL::to_double(pt.x()), ' ');
    put_coordinate(CGAL::to_double(pt.y()), ' ');
    put_coordinate(CGAL::to_double(pt.z()), '\n');
    flush_buffer(out, buf, name);
  }
  if (binary) buf += '\n';
  if (version_51) {
    buf += "CELLS ";
    append_integer(buf, nt + 1);
    buf += ' ';
    append_integer(buf, 4 * nt);
    buf += "\nOFFSETS vtktypeint64\n";
    for (std::size_t i = 0; i <= nt; ++i) {
      put_int64(static_cast<std::int64_t>(4 * i), i % 8 == 7 || i == nt ? '\n' : ' ');
      flush_buffer(out, buf, name);
    }
    if (binary) buf += '\n';
    buf += "CONNECTIVITY vtktypeint64\n";
    for (const auto& t : mesh.tetrahedra) {
      for (int k = 0; k < 4; ++k) put_int64(static_cast<std::int64_t>(t[k]), k == 3 ? '\n' : ' ');
      flush_buffer(out, buf, name);
    }
  } else {
    buf += "CELLS ";
    append_integer(buf, nt);
    buf += ' ';
    append_integer(buf, 5 * nt);
    buf += '\n';
    for (const auto& t : mesh.tetrahedra) {
      put_int(4, ' ');
      for (int k = 0; k < 4; ++k) put_int(static_cast<std::int32_t>(t[k]), k == 3 ? '\n' : ' ');
      flush_buffer(out, buf, name);
    }
  }
  if (binary) buf += '\n';
  buf += "CELL_TYPES ";
  append_integer(buf, nt);
  buf += '\n';
  for (std::size_t i = 0; i < nt; ++i) {
    put_int(10, '\n');
    flush_buffer(out, buf, name);
  }
  if (binary) buf += '\n';
  // the first array of a section as SCALARS (the active one), the others in one FIELD: VTK's
  // reader reads only the first SCALARS of a section by default, but every FIELD array
  const auto array = [&](bool first, std::size_t count, const std::string& array_name, const char* type,
                         std::size_t n, const auto& get) {
    if (first) {
      buf += "SCALARS ";
      buf += vtk_encode_name(array_name);
      buf += ' ';
      buf += type;
      buf += " 1\nLOOKUP_TABLE default\n";
    } else {
      if (count > 0) {
        buf += "FIELD FieldData ";
        append_integer(buf, count);
        buf += '\n';
      }
      buf += vtk_encode_name(array_name);
      buf += " 1 ";
      append_integer(buf, n);
      buf += ' ';
      buf += type;
      buf += '\n';
    }
    for (std::size_t i = 0; i < n; ++i) {
      get(i);
      flush_buffer(out, buf, name);
    }
    if (binary) buf += '\n';
  };
  if (!data.empty()) {
    buf += "POINT_DATA ";
    append_integer(buf, nv);
    buf += '\n';
    for (std::size_t k = 0; k < data.size(); ++k)
      array(k == 0, k == 1 ? data.size() - 1 : 0, data[k]->name, "double", nv,
            [&](std::size_t i) { put_double(data[k]->values[i], '\n'); });
  }
  if (!mesh.tetrahedron_labels.empty() || !mesh.cell_data.empty()) {
    buf += "CELL_DATA ";
    append_integer(buf, nt);
    buf += '\n';
    const bool labels = !mesh.tetrahedron_labels.empty();
    if (labels)
      array(true, 0, "label", "int", nt, [&](std::size_t i) { put_int(mesh.tetrahedron_labels[i], '\n'); });
    const std::size_t nf = mesh.cell_data.size() - (labels ? 0 : 1);
    for (std::size_t k = 0; k < mesh.cell_data.size(); ++k) {
      const bool first = !labels && k == 0;
      const bool first_field = labels ? k == 0 : k == 1;
      array(first, first_field ? nf : 0, mesh.cell_data[k].name, "double", nt,
            [&](std::size_t i) { put_double(mesh.cell_data[k].values[i], '\n'); });
    }
  }
  flush_buffer(out, buf, name, true);
}

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTK_LEGACY_H
