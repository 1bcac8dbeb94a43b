// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_TETGEN_H
#define CGAL_PR_STAR_OCTREE_IO_TETGEN_H

#include <CGAL/PR_star_octree/IO/Memory_limit.h>
#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/Write_options.h>
#include <CGAL/PR_star_octree/IO/internal/file_bytes.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <system_error>
#include <fstream>
#include <istream>
#include <ostream>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {

/// The `.node` and `.ele` names of a TetGen mesh given either of them; throws `Read_error` when
/// the name ends with neither (case-insensitive; the other name gets the same case).
inline std::pair<std::string, std::string> tetgen_file_names(const std::string& filename) {
  const std::size_t dot = filename.find_last_of('.');
  const std::string ext = dot == std::string::npos ? std::string() : filename.substr(dot + 1);
  const bool upper = !ext.empty() && ext[0] >= 'A' && ext[0] <= 'Z';
  const std::string base = dot == std::string::npos ? filename : filename.substr(0, dot + 1);
  if (iequals(ext, "node")) return {filename, base + (upper ? "ELE" : "ele")};
  if (iequals(ext, "ele")) return {base + (upper ? "NODE" : "node"), filename};
  throw Read_error(filename, 0, "a TetGen mesh is read from a '.node' or '.ele' file name");
}

template <class Mesh>
void read_tetgen_text(std::string_view node_text, const std::string& node_name, std::string_view ele_text,
                      const std::string& ele_name, Mesh& result) {
  using Point_3 = typename Mesh::Point_3;
  using Index = typename Mesh::Index;
  Mesh mesh;
  std::vector<std::string_view> f;
  long long first_number = 0;

  // ---- .node
  {
    Text_reader r(node_text, node_name);
    if (!r.next_line(f))
      r.fail("empty file: expected '<#points> <dimension> <#attributes> <#boundary markers>'");
    if (f.size() > 4)
      r.fail("the first line must hold at most 4 numbers: <#points> <dimension> <#attributes> <#markers>");
    long long header[4] = {0, 3, 0, 0};
    static const char* names[4] = {"number of points", "dimension", "number of attributes",
                                   "boundary marker flag"};
    for (std::size_t i = 0; i < f.size(); ++i)
      if (const char* why = parse_integer(f[i], header[i]))
        r.fail(std::string(names[i]) + " " + quote(f[i]) + " " + why);
    if (header[0] <= 0)
      r.fail("number of points " + std::to_string(header[0]) +
             " (TetGen files with points in a .poly file are not supported)");
    if (header[1] != 3) r.fail("dimension " + std::to_string(header[1]) + " is not supported (must be 3)");
    if (header[2] < 0 || header[2] > 1000)
      r.fail("invalid number of attributes " + std::to_string(header[2]));
    if (header[3] != 0 && header[3] != 1)
      r.fail("boundary marker flag must be 0 or 1, not " + std::to_string(header[3]));
    const std::size_t n = static_cast<std::size_t>(header[0]);
    const std::size_t nattr = static_cast<std::size_t>(header[2]);
    const std::size_t fields = 4 + nattr + static_cast<std::size_t>(header[3]);
    if (static_cast<unsigned long long>(header[0]) > max_vertices<Index>())
      r.fail(std::to_string(n) + " points do not fit in the index type of the mesh");
    check_memory_if_present(r.name(), r.line(), n, mesh.tetrahedra.size(), sizeof(Point_3) + 8 * nattr,
                            sizeof(typename Mesh::Tetrahedron) + sizeof(int), n, 2 * fields,
                            r.remaining_bytes());
    capped_reserve(mesh.points, n, r.remaining_bytes(), 2 * fields);
    advise_huge_pages(mesh.points.data(), mesh.points.capacity() * sizeof(Point_3));
    mesh.point_data.resize(nattr);
    for (std::size_t a = 0; a < nattr; ++a) {
      mesh.point_data[a].name = "attribute_" + std::to_string(a);
      capped_reserve(mesh.point_data[a].values, n, r.remaining_bytes(), 2 * fields);
    }
    std::vector<double> attributes(nattr);
    for (std::size_t i = 0; i < n; ++i) {
      if (i > 0) { // fast path: the expected index, plain numbers, the declared number of fields
        Text_reader::Line_cursor c(r);
        long long id = 0, marker = 0;
        double x, y, z;
        bool ok = c.integer(id) && id == first_number + static_cast<long long>(i) && c.real(x) && c.real(y) &&
                  c.real(z);
        for (std::size_t a = 0; ok && a < nattr; ++a) ok = c.real(attributes[a]);
        if (ok && (header[3] == 0 || c.integer(marker)) && c.end_of_line()) {
          mesh.points.push_back(Point_3(x, y, z));
          for (std::size_t a = 0; a < nattr; ++a) mesh.point_data[a].values.push_back(attributes[a]);
          continue;
        }
      }
      if (!r.next_line(f))
        r.fail("unexpected end of file: " + std::to_string(i) + " points read, " + std::to_string(n) +
               " declared");
      r.set_context("point", i + 1);
      if (f.size() != fields)
        r.fail("expected " + std::to_string(fields) + " fields (index x y z" + (nattr ? " attributes" : "") +
               (header[3] ? " marker" : "") + "), found " + std::to_string(f.size()));
      long long id;
      if (const char* why = parse_integer(f[0], id)) r.fail("point index " + quote(f[0]) + " " + why);
      if (i == 0) {
        if (id != 0 && id != 1) r.fail("the first point index must be 0 or 1, not " + std::to_string(id));
        first_number = id;
      } else if (id != first_number + static_cast<long long>(i)) {
        r.fail("point index " + std::to_string(id) + " where " +
               std::to_string(first_number + static_cast<long long>(i)) +
               " was expected (indices must be consecutive)");
      }
      double c[3];
      for (int k = 0; k < 3; ++k)
        if (const char* why = parse_double(f[1 + k], c[k]))
          r.fail("coordinate " + quote(f[1 + k]) + " " + why);
      mesh.points.push_back(Point_3(c[0], c[1], c[2]));
      for (std::size_t a = 0; a < nattr; ++a) {
        double v;
        if (const char* why = parse_double(f[4 + a], v)) r.fail("attribute " + quote(f[4 + a]) + " " + why);
        mesh.point_data[a].values.push_back(v);
      }
      if (header[3]) {
        long long marker;
        if (const char* why = parse_integer(f[4 + nattr], marker))
          r.fail("boundary marker " + quote(f[4 + nattr]) + " " + why);
      }
      r.clear_context();
    }
    if (r.next_line(f)) r.fail("unexpected data after the " + std::to_string(n) + " declared points");
  }

  // ---- .ele
  {
    Text_reader r(ele_text, ele_name);
    if (!r.next_line(f)) r.fail("empty file: expected '<#tetrahedra> <nodes per tetrahedron> <#attributes>'");
    if (f.size() > 3)
      r.fail(
          "the first line must hold at most 3 numbers: <#tetrahedra> <nodes per tetrahedron> <#attributes>");
    long long header[3] = {0, 4, 0};
    static const char* names[3] = {"number of tetrahedra", "number of nodes per tetrahedron",
                                   "number of attributes"};
    for (std::size_t i = 0; i < f.size(); ++i)
      if (const char* why = parse_integer(f[i], header[i]))
        r.fail(std::string(names[i]) + " " + quote(f[i]) + " " + why);
    if (header[0] < 0) r.fail("negative number of tetrahedra " + std::to_string(header[0]));
    if (header[1] != 4 && header[1] != 10)
      r.fail("number of nodes per tetrahedron must be 4 or 10, not " + std::to_string(header[1]));
    if (header[2] < 0 || header[2] > 1000)
      r.fail("invalid number of attributes " + std::to_string(header[2]));
    if (static_cast<unsigned long long>(header[0]) > std::numeric_limits<std::size_t>::max() / 64)
      r.fail("number of tetrahedra " + std::to_string(header[0]) + " is too large");
    const std::size_t n = static_cast<std::size_t>(header[0]);
    const std::size_t npt = static_cast<std::size_t>(header[1]);
    const std::size_t fields = 1 + npt + static_cast<std::size_t>(header[2]);
    const bool labels = header[2] > 0;
    check_memory_if_present(r.name(), r.line(), mesh.points.size(), n, sizeof(Point_3),
                            sizeof(typename Mesh::Tetrahedron) + sizeof(int), n, 2 * fields,
                            r.remaining_bytes());
    capped_reserve(mesh.tetrahedra, n, r.remaining_bytes(), 2 * fields);
    advise_huge_pages(mesh.tetrahedra.data(),
                      mesh.tetrahedra.capacity() * sizeof(typename Mesh::Tetrahedron));
    if (labels) capped_reserve(mesh.tetrahedron_labels, n, r.remaining_bytes(), 2 * fields);
    const long long nv = static_cast<long long>(mesh.points.size());
    long long first_id = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (i > 0) { // fast path: the expected index, distinct vertex indices in range, plain numbers
        Text_reader::Line_cursor c(r);
        long long id = 0;
        bool ok = c.integer(id) && id == first_id + static_cast<long long>(i);
        typename Mesh::Tetrahedron t;
        for (std::size_t k = 0; ok && k < npt; ++k) {
          long long v = 0;
          ok = c.integer(v) && v - first_number >= 0 && v - first_number < nv;
          if (ok && k < 4) t[k] = static_cast<Index>(v - first_number);
        }
        Index twice;
        ok = ok && !has_repeated_vertex(t, twice);
        double region = 0;
        if (ok && labels) {
          ok = c.real(region) && std::round(region) >= double(std::numeric_limits<int>::min()) &&
               std::round(region) <= double(std::numeric_limits<int>::max());
          double a;
          for (std::size_t k = 1; ok && k < static_cast<std::size_t>(header[2]); ++k) ok = c.real(a);
        }
        if (ok && c.end_of_line()) {
          mesh.tetrahedra.push_back(t);
          if (labels) mesh.tetrahedron_labels.push_back(static_cast<int>(std::round(region)));
          continue;
        }
      }
      if (!r.next_line(f))
        r.fail("unexpected end of file: " + std::to_string(i) + " tetrahedra read, " + std::to_string(n) +
               " declared");
      r.set_context("tetrahedron", i + 1);
      if (f.size() != fields)
        r.fail("expected " + std::to_string(fields) + " fields (index, " + std::to_string(npt) + " corners" +
               (labels ? ", attributes" : "") + "), found " + std::to_string(f.size()));
      long long id;
      if (const char* why = parse_integer(f[0], id)) r.fail("tetrahedron index " + quote(f[0]) + " " + why);
      if (i == 0) {
        if (id != 0 && id != 1)
          r.fail("the first tetrahedron index must be 0 or 1, not " + std::to_string(id));
        first_id = id;
      } else if (id != first_id + static_cast<long long>(i)) {
        r.fail("tetrahedron index " + std::to_string(id) + " where " +
               std::to_string(first_id + static_cast<long long>(i)) +
               " was expected (indices must be consecutive)");
      }
      typename Mesh::Tetrahedron t;
      for (std::size_t k = 0; k < npt; ++k) {
        long long v;
        if (const char* why = parse_integer(f[1 + k], v))
          r.fail("vertex index " + quote(f[1 + k]) + " " + why);
        const long long v0 = v - first_number;
        if (v0 < 0 || v0 >= nv)
          r.fail("vertex index " + std::to_string(v) + " out of range (" + std::to_string(first_number) +
                 ".." + std::to_string(nv - 1 + first_number) + ", as the .node file)");
        if (k < 4) t[k] = static_cast<Index>(v0);
      }
      long long twice;
      if (has_repeated_vertex(t, twice))
        r.fail("vertex index " + std::to_string(twice + first_number) + " listed twice");
      mesh.tetrahedra.push_back(t);
      if (labels) {
        double a;
        if (const char* why = parse_double(f[1 + npt], a))
          r.fail("region attribute " + quote(f[1 + npt]) + " " + why);
        const double rounded = std::round(a);
        if (rounded < double(std::numeric_limits<int>::min()) ||
            rounded > double(std::numeric_limits<int>::max()))
          r.fail("region attribute " + quote(f[1 + npt]) + " is out of the int range");
        mesh.tetrahedron_labels.push_back(static_cast<int>(rounded));
        for (std::size_t k = 1; k < static_cast<std::size_t>(header[2]); ++k)
          if (const char* why = parse_double(f[1 + npt + k], a))
            r.fail("attribute " + quote(f[1 + npt + k]) + " " + why);
      }
      r.clear_context();
    }
    if (r.next_line(f)) r.fail("unexpected data after the " + std::to_string(n) + " declared tetrahedra");
  }
  result = std::move(mesh);
}

} // namespace internal

/// \ingroup PkgPRStarOctreeIO
/// Reads a TetGen mesh from two streams holding the `.node` and the `.ele` texts; the names are
/// used in error messages.  See `read_tetgen(const std::string&, Mesh&)`.
template <class Mesh>
void read_tetgen(std::istream& node, std::istream& ele, Mesh& mesh,
                 const std::string& node_name = "<node stream>",
                 const std::string& ele_name = "<ele stream>") {
  const std::string node_text = internal::load_stream(node, node_name);
  const std::string ele_text = internal::load_stream(ele, ele_name);
  internal::read_tetgen_text(node_text, node_name, ele_text, ele_name, mesh);
}

/// \ingroup PkgPRStarOctreeIO
/// Reads a TetGen mesh, given the name of either its `.node` or its `.ele` file: both are read
/// and both are required.
///
/// `.node`: a first line `<#points> <dimension: 3> <#attributes> <boundary marker flag: 0|1>`
/// (trailing numbers optional), then one line per point `index x y z [attributes] [marker]`.
/// The first index (0 or 1) fixes the numbering of both files, like TetGen's `firstnumber`;
/// indices must then be consecutive.  Point attribute `k` becomes the point-data array
/// `attribute_k` (the first one is thus the scalar field).
///
/// `.ele`: a first line `<#tetrahedra> <nodes per tetrahedron: 4|10> <#attributes>`, then one
/// line per tetrahedron `index a b c d [6 more nodes] [attributes]`; of a 10-node tetrahedron,
/// the 4 corners are kept.  The first attribute (TetGen's region attribute), rounded to an
/// integer, goes to `tetrahedron_labels`.
///
/// `#` starts a comment, blank lines are ignored.  Every line must have exactly the number of
/// fields announced by the header, and non-comment lines after the declared entries are an error
/// (a sign of a corrupted or mismatched file).
///
/// \throws Read_error on any problem, including a missing `.ele` file; `mesh` is then left
/// unchanged.  It is replaced on success.
template <class Mesh>
void read_tetgen(const std::string& node_or_ele_filename, Mesh& mesh) {
  const std::pair<std::string, std::string> names = internal::tetgen_file_names(node_or_ele_filename);
  const auto load = [](const std::string& name) {
    std::error_code ec;
    if (!std::filesystem::exists(std::filesystem::path(name), ec))
      throw Read_error(name, 0, "no such file (a TetGen mesh needs both its .node and its .ele file)");
    return std::make_unique<internal::File_bytes>(name); // not zero-filled, huge pages when large
  };
  const auto node_text = load(names.first);
  const auto ele_text = load(names.second);
  internal::read_tetgen_text(node_text->view(), names.first, ele_text->view(), names.second, mesh);
}

namespace internal {

/// What the TetGen writer accepts: text, no version.
inline constexpr Write_support tetgen_write_support{
    true, false, false, false, false, {nullptr, nullptr, nullptr, nullptr}, nullptr};

template <class Mesh>
void write_tetgen_streams(std::ostream& node, std::ostream& ele, const Mesh& mesh, const Write_options& given,
                          const std::string& node_name, const std::string& ele_name) {
  resolve_write_options(given, tetgen_write_support, "TetGen", node_name);
  check_mesh_for_writing(mesh, node_name);
  std::string buf;
  const std::size_t na = mesh.point_data.size();
  append_integer(buf, mesh.points.size());
  buf += " 3 ";
  append_integer(buf, na);
  buf += " 0\n";
  for (std::size_t i = 0; i < mesh.points.size(); ++i) {
    const auto& p = mesh.points[i];
    append_integer(buf, i + 1);
    for (const double c : {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}) {
      buf += ' ';
      append_double(buf, c);
    }
    for (const auto& a : mesh.point_data) {
      buf += ' ';
      append_double(buf, a.values[i]);
    }
    buf += '\n';
    flush_buffer(node, buf, node_name);
  }
  flush_buffer(node, buf, node_name, true);
  const bool labels = !mesh.tetrahedron_labels.empty();
  append_integer(buf, mesh.tetrahedra.size());
  buf += labels ? " 4 1\n" : " 4 0\n";
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    append_integer(buf, t + 1);
    for (const auto v : mesh.tetrahedra[t]) {
      buf += ' ';
      append_integer(buf, static_cast<unsigned long long>(v) + 1);
    }
    if (labels) {
      buf += ' ';
      append_integer(buf, mesh.tetrahedron_labels[t]);
    }
    buf += '\n';
    flush_buffer(ele, buf, ele_name);
  }
  flush_buffer(ele, buf, ele_name, true);
}

template <class Mesh>
void write_tetgen_file(const std::string& node_or_ele_filename, const Mesh& mesh,
                       const Write_options& given) {
  std::pair<std::string, std::string> names;
  try {
    names = tetgen_file_names(node_or_ele_filename);
  } catch (const Read_error&) {
    throw Write_error(node_or_ele_filename, "a TetGen mesh is written to a '.node' or '.ele' file name");
  }
  resolve_write_options(given, tetgen_write_support, "TetGen", node_or_ele_filename);
  check_mesh_for_writing(mesh, node_or_ele_filename);
  std::ofstream node, ele;
  open_for_writing(node, names.first);
  open_for_writing(ele, names.second);
  write_tetgen_streams(node, ele, mesh, given, names.first, names.second);
  close_written(node, names.first);
  close_written(ele, names.second);
}

/// The reader of the format table (one stream): the `.node` text, a NUL byte, the `.ele` text (an
/// input without NUL is a `.node` text with an empty `.ele` text).
template <class Mesh>
void read_tetgen_joined(std::istream& in, Mesh& mesh, const std::string& name) {
  const std::string all = load_stream(in, name);
  const std::size_t nul = all.find('\0');
  const std::string_view text(all);
  read_tetgen_text(text.substr(0, nul), name + " (node)",
                   nul == std::string::npos ? std::string_view() : text.substr(nul + 1), name + " (ele)",
                   mesh);
}

} // namespace internal

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` as TetGen `.node` and `.ele` texts to two streams; see
/// `write_tetgen(const std::string&, const Mesh&, const NamedParameters&)`, whose options it takes.
template <class Mesh, class NamedParameters = parameters::Default_named_parameters>
void write_tetgen(std::ostream& node, std::ostream& ele, const Mesh& mesh,
                  const NamedParameters& np = parameters::default_values(),
                  const std::string& node_name = "<node stream>",
                  const std::string& ele_name = "<ele stream>") {
  internal::write_tetgen_streams(node, ele, mesh, internal::write_options(np), node_name, ele_name);
}

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` as a TetGen mesh, given the name of either its `.node` or its `.ele` file (both
/// are written, the other name gets the same base): 1-based indices as TetGen writes them by
/// default; the `.node` file holds the point-data arrays as point attributes (in order, so
/// `read_tetgen()` gives them back as `attribute_k`) and no boundary marker; the `.ele` file has
/// 4 nodes per tetrahedron and, when the mesh has labels, one attribute: the label (TetGen's region
/// attribute, read back by `read_tetgen()` as the label).  Names of labels and cell data are not
/// written.
/// \param node_or_ele_filename the name of the `.node` or of the `.ele` file
/// \param mesh the mesh
/// \param np the write options (`Write_options.h`); TetGen files are text only and have no version
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{use_binary_mode}
///     \cgalParamDescription{must be `false`}
///     \cgalParamType{Boolean}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Write_error when the name does not end with `.node` or `.ele`, a file cannot be
/// written, the mesh is inconsistent or an option is not possible.
template <class Mesh, class NamedParameters = parameters::Default_named_parameters>
void write_tetgen(const std::string& node_or_ele_filename, const Mesh& mesh,
                  const NamedParameters& np = parameters::default_values()) {
  internal::write_tetgen_file(node_or_ele_filename, mesh, internal::write_options(np));
}

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_TETGEN_H
