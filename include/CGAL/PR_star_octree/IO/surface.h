// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_SURFACE_H
#define CGAL_PR_STAR_OCTREE_IO_SURFACE_H

/// \file surface.h
/// Writing triangle surface meshes with their data (`Triangle_surface`, e.g. the boundary of a
/// tetrahedral mesh) as OFF, STL, PLY, OBJ, VTK XML PolyData (`.vtp`) or Medit `.mesh`, chosen by
/// extension (`write_surface()`, `surface_formats`).  Every format is written by this package's own
/// code, with the write options of `Write_options.h`.

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/Write_options.h>
#include <CGAL/PR_star_octree/IO/internal/file_bytes.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>
#include <CGAL/PR_star_octree/IO/internal/vtu_writer.h>
#include <CGAL/PR_star_octree/IO/medit.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <CGAL/Named_function_parameters.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace PR_star_octree {

/// \ingroup PkgPRStarOctreeIO
/// A named integer array: one value per vertex or per triangle of a `Triangle_surface` (the
/// integer counterpart of `Data_array`).
struct Int_array {
  std::string name;        ///< the name of the array
  std::vector<int> values; ///< one value per vertex or per triangle
};

/// \ingroup PkgPRStarOctreeIO
/// A triangle surface with data, as `write_surface()` writes it (e.g. what `prstar boundary
/// --surface` writes: the boundary triangles of a tetrahedral mesh).
///
/// \tparam Point_3_ the point type (default: `Exact_predicates_inexact_constructions_kernel::Point_3`)
template <class Point_3_ = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>
struct Triangle_surface {
  using Point_3 = Point_3_;                      ///< the point type
  using Triangle = std::array<std::uint32_t, 3>; ///< the vertex indices of a triangle

  /// the vertices
  std::vector<Point_3> points;
  /// the vertex indices (0-based) of each triangle, oriented (for a boundary: counterclockwise
  /// seen from outside, the normal `(b - a) x (c - a)` pointing out)
  std::vector<Triangle> triangles;
  /// per-vertex real arrays, each with `points.size()` values
  std::vector<Data_array> point_data;
  /// per-vertex integer arrays (e.g. `boundary_type`), each with `points.size()` values
  std::vector<Int_array> point_int_data;
  /// per-triangle integer arrays (e.g. `label_inside`, `label_outside`, `interface`), each with
  /// `triangles.size()` values; the first one gives the Medit references and the OBJ groups
  std::vector<Int_array> cell_int_data;
  /// the names of the labels (gmsh physical names): label -> name
  std::map<int, std::string> label_names;
};

namespace IO {

/// \ingroup PkgPRStarOctreeIO
/// One record of `surface_formats`: a file format of triangle surfaces that `write_surface()`
/// writes.
struct Surface_format {
  const char* name;      ///< the name of the format, e.g. `"PLY"`
  const char* extension; ///< its extension, lower case, without the dot
  const char* data;      ///< what it keeps of the data of a `Triangle_surface`
  /// what the writer accepts as named parameters and its defaults (see `write_options_text()`)
  const internal::Write_support* write_options;
};

namespace internal {

/// Text only, no version: OFF, OBJ.
inline constexpr Write_support surface_text_write_support{
    true, false, false, false, false, {nullptr, nullptr, nullptr, nullptr}, nullptr};
/// Binary (default) or text, no version: STL, PLY.
inline constexpr Write_support surface_binary_write_support{
    true, true, true, false, false, {nullptr, nullptr, nullptr, nullptr}, nullptr};
/// VTK XML PolyData: the options of the `.vtu` writer (`vtu_write_support`, not included here to
/// leave its reader out): inline base64 binary (default) or ascii, zlib, version 1.0.
inline constexpr Write_support vtp_write_support{
    true, true, true, true, true, {"1.0", nullptr, nullptr, nullptr}, nullptr};

} // namespace internal

/// \ingroup PkgPRStarOctreeIO
/// The formats of `write_surface()`, in the order of `surface_extensions()`.
inline constexpr Surface_format surface_formats[] = {
    {"OFF", "off", "–", &internal::surface_text_write_support},
    {"STL", "stl", "– (normals computed from the triangles, attribute 0)",
     &internal::surface_binary_write_support},
    {"PLY", "ply", "point arrays (`double`, `int`), triangle arrays (`int`), label names as comments",
     &internal::surface_binary_write_support},
    {"Wavefront OBJ", "obj", "label names as comments, a group per value of the first triangle array",
     &internal::surface_text_write_support},
    {"VTK XML PolyData", "vtp",
     "point arrays (`Float64`, `Int32`), triangle arrays (`Int32`), label names as field data",
     &internal::vtp_write_support},
    {"Medit", "mesh", "the first triangle array as the references of the triangles",
     &internal::medit_write_support},
};

/// \ingroup PkgPRStarOctreeIO
/// The extensions `write_surface()` accepts, for messages: `.off, .stl, .ply, .obj, .vtp, .mesh`.
inline std::string surface_extensions() {
  std::string r;
  for (const Surface_format& f : surface_formats) r += (r.empty() ? "." : ", .") + std::string(f.extension);
  return r;
}

/// \ingroup PkgPRStarOctreeIO
/// The record of `surface_formats` of the extension of `filename` (a file name, or an extension
/// with its dot such as `".ply"`; case-insensitive), or `nullptr`.
inline const Surface_format* find_surface_format(const std::string& filename) {
  const std::size_t dot = filename.find_last_of('.');
  const std::size_t slash = filename.find_last_of("/\\");
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return nullptr;
  const std::string e = internal::to_lower(filename.substr(dot + 1));
  for (const Surface_format& f : surface_formats)
    if (e == f.extension) return &f;
  return nullptr;
}

/// \ingroup PkgPRStarOctreeIO
/// Whether `write_surface()` writes files named like `filename` (by its extension, case-insensitive).
inline bool is_surface_extension(const std::string& filename) {
  return find_surface_format(filename) != nullptr;
}

namespace internal {

/// The record of the extension of `filename`; throws `std::invalid_argument` listing the others.
inline const Surface_format& surface_format_of(const std::string& filename) {
  const Surface_format* f = find_surface_format(filename);
  if (f == nullptr)
    throw std::invalid_argument(filename +
                                ": unknown triangle surface format (the extension must be one of " +
                                surface_extensions() + ")");
  return *f;
}

/// Checks what every surface writer needs: finite coordinates, indices in range, arrays of the
/// right sizes with names of their own, label names on one line.
template <class Surface>
void check_surface_for_writing(const Surface& s, const std::string& name) {
  const std::size_t nv = s.points.size(), nt = s.triangles.size();
  if (nv > 0xffffffffu)
    throw Write_error(name, std::to_string(nv) + " points: more than 32-bit indices can reach");
  // the points and their real arrays: the checks of the tetrahedral writers, on a mesh without tetrahedra
  struct Points_only {
    const decltype(Surface::points)& points;
    std::vector<std::array<std::uint32_t, 4>> tetrahedra;
    std::vector<int> tetrahedron_labels;
    const std::vector<Data_array>& point_data;
  };
  check_mesh_for_writing(Points_only{s.points, {}, {}, s.point_data}, name);
  for (std::size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k)
      if (static_cast<unsigned long long>(s.triangles[t][k]) >= nv)
        throw Write_error(name, "triangle " + std::to_string(t) + " has vertex index " +
                                    std::to_string(s.triangles[t][k]) + " out of range (" +
                                    std::to_string(nv) + " vertices)");
  std::vector<const std::string*> point_names, cell_names;
  for (const Data_array& a : s.point_data) point_names.push_back(&a.name);
  const auto check_ints = [&](const Int_array& a, std::size_t n, const char* what, const char* per,
                              std::vector<const std::string*>& names) {
    if (a.values.size() != n)
      throw Write_error(name, std::string(what) + " '" + a.name + "' has " + std::to_string(a.values.size()) +
                                  " values for " + std::to_string(n) + " " + per);
    names.push_back(&a.name);
  };
  for (const Int_array& a : s.point_int_data) check_ints(a, nv, "point data", "vertices", point_names);
  for (const Int_array& a : s.cell_int_data) check_ints(a, nt, "triangle data", "triangles", cell_names);
  for (const auto* names : {&point_names, &cell_names})
    for (std::size_t i = 0; i < names->size(); ++i) {
      const std::string& n = *(*names)[i];
      const char* what = names == &point_names ? "point" : "triangle";
      if (n.empty()) throw Write_error(name, std::string("a ") + what + " data array has an empty name");
      for (std::size_t j = 0; j < i; ++j)
        if (n == *(*names)[j])
          throw Write_error(name, std::string("two ") + what + " data arrays are named '" + n + "'");
    }
  for (const auto& l : s.label_names)
    for (char c : l.second)
      if (c == '\n' || c == '\r' || c == '\0')
        throw Write_error(name, "the name of label " + std::to_string(l.first) + " is not one line of text");
}

/// Appends `v` in little-endian byte order.
template <class T>
void append_little_endian(std::string& out, T v) {
  append_binary(out, host_is_little_endian() ? v : byte_swapped(v));
}

/// The coordinates of a point as doubles.
template <class Point>
std::array<double, 3> xyz(const Point& p) {
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

/// Appends `prefix`, the three numbers and `suffix` separated by spaces (shortest exact form).
inline void append_triple(std::string& buf, const char* prefix, const std::array<double, 3>& v,
                          const char* suffix) {
  buf += prefix;
  for (int k = 0; k < 3; ++k) {
    if (k > 0) buf += ' ';
    append_double(buf, v[k]);
  }
  buf += suffix;
}

/// Appends `prefix`, the three vertex indices of a triangle plus `base`, and `suffix`.
template <class Triangle>
void append_indices(std::string& buf, const char* prefix, const Triangle& t, unsigned long long base,
                    const char* suffix) {
  buf += prefix;
  for (int k = 0; k < 3; ++k) {
    if (k > 0) buf += ' ';
    append_integer(buf, static_cast<unsigned long long>(t[k]) + base);
  }
  buf += suffix;
}

/// ASCII OFF: the points and the triangles.
template <class Surface>
void write_off_surface(std::ostream& out, const Surface& s, const std::string& name) {
  std::string buf = "OFF\n";
  append_integer(buf, s.points.size());
  buf += ' ';
  append_integer(buf, s.triangles.size());
  buf += " 0\n";
  for (const auto& p : s.points) {
    append_triple(buf, "", xyz(p), "\n");
    flush_buffer(out, buf, name);
  }
  for (const auto& t : s.triangles) {
    append_indices(buf, "3 ", t, 0, "\n");
    flush_buffer(out, buf, name);
  }
  flush_buffer(out, buf, name, true);
}

/// The unit normal `(b - a) x (c - a)` of a triangle (0 for a degenerate one).
template <class Surface, class Triangle>
std::array<double, 3> triangle_normal(const Surface& s, const Triangle& t) {
  const std::array<double, 3> a = xyz(s.points[t[0]]), b = xyz(s.points[t[1]]), c = xyz(s.points[t[2]]);
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  std::array<double, 3> n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (length > 0 && std::isfinite(length))
    for (double& x : n) x /= length;
  else
    n = {0, 0, 0};
  return n;
}

/// STL: binary (an 80-byte header, the count, then per triangle its normal and vertices as
/// little-endian `float` and the attribute 0) or ASCII (`solid` ... `endsolid`, exact doubles).
template <class Surface>
void write_stl_surface(std::ostream& out, const Surface& s, bool binary, const std::string& name) {
  std::string buf;
  if (binary) {
    if (s.triangles.size() > 0xffffffffu)
      throw Write_error(name, "more triangles than a binary STL file can count");
    std::string header = "binary STL written by the PR-star octree package (CGAL)";
    header.resize(80, ' ');
    buf += header;
    append_little_endian(buf, static_cast<std::uint32_t>(s.triangles.size()));
    for (const auto& t : s.triangles) {
      for (double x : triangle_normal(s, t)) append_little_endian(buf, static_cast<float>(x));
      for (int k = 0; k < 3; ++k)
        for (double x : xyz(s.points[t[k]])) append_little_endian(buf, static_cast<float>(x));
      append_little_endian(buf, std::uint16_t(0));
      flush_buffer(out, buf, name);
    }
  } else {
    buf += "solid prstar_surface\n";
    for (const auto& t : s.triangles) {
      append_triple(buf, "  facet normal ", triangle_normal(s, t), "\n    outer loop\n");
      for (int k = 0; k < 3; ++k) append_triple(buf, "      vertex ", xyz(s.points[t[k]]), "\n");
      buf += "    endloop\n  endfacet\n";
      flush_buffer(out, buf, name);
    }
    buf += "endsolid prstar_surface\n";
  }
  flush_buffer(out, buf, name, true);
}

/// The checks of the PLY writer: property names without spaces, not those of the geometry, and
/// indices that fit its `int`.
template <class Surface>
void check_ply_surface(const Surface& s, const std::string& name) {
  const auto check_name = [&](const std::string& n, bool point) {
    for (char c : n)
      if (c <= ' ' || c == 0x7f)
        throw Write_error(name, "'" + n + "': PLY property names cannot contain spaces");
    if ((point && (n == "x" || n == "y" || n == "z")) || (!point && n == "vertex_indices"))
      throw Write_error(name, "'" + n + "' is a PLY property this writer uses for the geometry");
  };
  for (const auto& a : s.point_data) check_name(a.name, true);
  for (const auto& a : s.point_int_data) check_name(a.name, true);
  for (const auto& a : s.cell_int_data) check_name(a.name, false);
  if (s.points.size() > 0x7fffffffu) throw Write_error(name, "more points than PLY int indices can reach");
}

/// PLY, binary little-endian or ASCII: vertices `x y z` (`double`) and the point arrays, faces
/// `vertex_indices` (`list uchar int`) and the triangle arrays; label names as comments.
template <class Surface>
void write_ply_surface(std::ostream& out, const Surface& s, bool binary, const std::string& name) {
  std::string buf = binary ? "ply\nformat binary_little_endian 1.0\n" : "ply\nformat ascii 1.0\n";
  buf += "comment written by the PR-star octree package (CGAL)\n";
  for (const auto& l : s.label_names) {
    buf += "comment label ";
    append_integer(buf, l.first);
    buf += ' ' + l.second + '\n';
  }
  buf += "element vertex ";
  append_integer(buf, s.points.size());
  buf += "\nproperty double x\nproperty double y\nproperty double z\n";
  for (const auto& a : s.point_data) buf += "property double " + a.name + '\n';
  for (const auto& a : s.point_int_data) buf += "property int " + a.name + '\n';
  buf += "element face ";
  append_integer(buf, s.triangles.size());
  buf += "\nproperty list uchar int vertex_indices\n";
  for (const auto& a : s.cell_int_data) buf += "property int " + a.name + '\n';
  buf += "end_header\n";
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const std::array<double, 3> p = xyz(s.points[i]);
    if (binary) {
      for (double x : p) append_little_endian(buf, x);
      for (const auto& a : s.point_data) append_little_endian(buf, a.values[i]);
      for (const auto& a : s.point_int_data) append_little_endian(buf, std::int32_t(a.values[i]));
    } else {
      append_triple(buf, "", p, "");
      for (const auto& a : s.point_data) {
        buf += ' ';
        append_double(buf, a.values[i]);
      }
      for (const auto& a : s.point_int_data) {
        buf += ' ';
        append_integer(buf, a.values[i]);
      }
      buf += '\n';
    }
    flush_buffer(out, buf, name);
  }
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    if (binary) {
      buf += char(3);
      for (int k = 0; k < 3; ++k) append_little_endian(buf, std::int32_t(s.triangles[i][k]));
      for (const auto& a : s.cell_int_data) append_little_endian(buf, std::int32_t(a.values[i]));
    } else {
      append_indices(buf, "3 ", s.triangles[i], 0, "");
      for (const auto& a : s.cell_int_data) {
        buf += ' ';
        append_integer(buf, a.values[i]);
      }
      buf += '\n';
    }
    flush_buffer(out, buf, name);
  }
  flush_buffer(out, buf, name, true);
}

/// Wavefront OBJ: `v` and `f` lines (1-based); label names as comments; with a triangle array, a
/// `g NAME_VALUE` line (spaces of the name as `_`) each time its value changes along the triangles.
template <class Surface>
void write_obj_surface(std::ostream& out, const Surface& s, const std::string& name) {
  std::string buf = "# Wavefront OBJ written by the PR-star octree package (CGAL)\n";
  for (const auto& l : s.label_names) {
    buf += "# label ";
    append_integer(buf, l.first);
    buf += ' ' + l.second + '\n';
  }
  for (const auto& p : s.points) {
    append_triple(buf, "v ", xyz(p), "\n");
    flush_buffer(out, buf, name);
  }
  const Int_array* groups = s.cell_int_data.empty() ? nullptr : &s.cell_int_data.front();
  std::string group_prefix;
  if (groups != nullptr) {
    group_prefix = "g " + groups->name + '_';
    for (std::size_t i = 2; i < group_prefix.size(); ++i)
      if (group_prefix[i] <= ' ') group_prefix[i] = '_';
  }
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    if (groups != nullptr && (i == 0 || groups->values[i] != groups->values[i - 1])) {
      buf += group_prefix;
      append_integer(buf, groups->values[i]);
      buf += '\n';
    }
    append_indices(buf, "f ", s.triangles[i], 1, "\n");
    flush_buffer(out, buf, name);
  }
  flush_buffer(out, buf, name, true);
}

/// VTK XML PolyData through the `.vtu` writer's arrays (`Vtu_array_writer`): the label names as
/// the field data `label_ids` (`Int32`) and `label_names` (`String`), always in ascii.
template <class Surface>
void write_vtp_surface(std::ostream& out, const Surface& s, const Write_options& o, const std::string& name) {
  const std::size_t nv = s.points.size(), nt = s.triangles.size();
  std::string buf;
  Vtu_array_writer w(out, buf, name, o.binary, o.compression == Compression::zlib);
  buf += "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\"";
  buf += w.compressor_attribute();
  buf += ">\n  <PolyData>\n";
  if (!s.label_names.empty()) {
    const std::string tuples = std::to_string(s.label_names.size());
    buf += "    <FieldData>\n      <DataArray type=\"Int32\" Name=\"label_ids\" NumberOfTuples=\"" + tuples +
           "\" format=\"ascii\">\n       ";
    for (const auto& l : s.label_names) {
      buf += ' ';
      append_integer(buf, l.first);
    }
    buf += "\n      </DataArray>\n      <Array type=\"String\" Name=\"label_names\" NumberOfTuples=\"" +
           tuples + "\" format=\"ascii\">\n       "; // each string as its byte values, ended by a 0
    for (const auto& l : s.label_names) {
      for (char c : l.second) {
        buf += ' ';
        append_integer(buf, static_cast<unsigned char>(c));
      }
      buf += " 0";
    }
    buf += "\n      </Array>\n    </FieldData>\n";
  }
  buf += "    <Piece NumberOfPoints=\"";
  append_integer(buf, nv);
  buf += "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"";
  append_integer(buf, nt);
  buf += "\">\n";
  if (!s.point_data.empty() || !s.point_int_data.empty()) {
    buf += "      <PointData>\n";
    for (const Data_array& a : s.point_data)
      w.write<double>("Float64", a.name, 1, nv, [&](std::size_t i) { return a.values[i]; });
    for (const Int_array& a : s.point_int_data)
      w.write<std::int32_t>("Int32", a.name, 1, nv, [&](std::size_t i) { return std::int32_t(a.values[i]); });
    buf += "      </PointData>\n";
  }
  if (!s.cell_int_data.empty()) {
    buf += "      <CellData>\n";
    for (const Int_array& a : s.cell_int_data)
      w.write<std::int32_t>("Int32", a.name, 1, nt, [&](std::size_t i) { return std::int32_t(a.values[i]); });
    buf += "      </CellData>\n";
  }
  buf += "      <Points>\n";
  w.write<double>("Float64", "Points", 3, 3 * nv, [&](std::size_t i) { return xyz(s.points[i / 3])[i % 3]; });
  buf += "      </Points>\n      <Polys>\n";
  w.write<std::int64_t>("Int64", "connectivity", 1, 3 * nt,
                        [&](std::size_t i) { return std::int64_t(s.triangles[i / 3][i % 3]); });
  w.write<std::int64_t>("Int64", "offsets", 1, nt, [&](std::size_t i) { return std::int64_t(3 * (i + 1)); });
  buf += "      </Polys>\n    </Piece>\n  </PolyData>\n";
  buf += "</VTKFile>\n";
  flush_buffer(out, buf, name, true);
}

/// Medit ASCII, version 2: `Vertices` (reference 0) and `Triangles` (1-based, the first triangle
/// array as references, or 0).
template <class Surface>
void write_medit_surface(std::ostream& out, const Surface& s, const std::string& name) {
  std::string buf = "MeshVersionFormatted 2\nDimension 3\n\nVertices\n";
  append_integer(buf, s.points.size());
  buf += '\n';
  for (const auto& p : s.points) {
    append_triple(buf, "", xyz(p), " 0\n");
    flush_buffer(out, buf, name);
  }
  buf += "\nTriangles\n";
  append_integer(buf, s.triangles.size());
  buf += '\n';
  const Int_array* refs = s.cell_int_data.empty() ? nullptr : &s.cell_int_data.front();
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    append_indices(buf, "", s.triangles[i], 1, " ");
    append_integer(buf, refs != nullptr ? refs->values[i] : 0);
    buf += '\n';
    flush_buffer(out, buf, name);
  }
  buf += "\nEnd\n";
  flush_buffer(out, buf, name, true);
}

/// The options of `format` (see `resolve_write_options()`) after the checks of the surface for
/// it: everything that can be refused before a file is opened.
template <class Surface>
Write_options check_surface_for_writing(const Surface& s, const Surface_format& format,
                                        const Write_options& given, const std::string& name) {
  const Write_options o = resolve_write_options(given, *format.write_options, format.name, name);
  check_surface_for_writing(s, name);
  if (std::string(format.extension) == "ply") check_ply_surface(s, name);
  return o;
}

/// Writes `s` in `format` with the options `given` (checked here); `name` names the output in
/// messages.
template <class Surface>
void write_surface_stream(std::ostream& out, const Surface& s, const Surface_format& format,
                          const Write_options& given, const std::string& name) {
  const Write_options o = check_surface_for_writing(s, format, given, name);
  const std::string e = format.extension;
  if (e == "off")
    write_off_surface(out, s, name);
  else if (e == "stl")
    write_stl_surface(out, s, o.binary, name);
  else if (e == "ply")
    write_ply_surface(out, s, o.binary, name);
  else if (e == "obj")
    write_obj_surface(out, s, name);
  else if (e == "vtp")
    write_vtp_surface(out, s, o, name);
  else
    write_medit_surface(out, s, name);
}

/// `e` with the operating system's reason for `error` (an `errno` value) appended, if any.
inline Write_error with_os_reason(const Write_error& e, int error) {
  if (error == 0) return e;
  return Write_error(e.file(), e.message() + ": " + std::strerror(error));
}

} // namespace internal

/// \ingroup PkgPRStarOctreeIO
/// Writes the triangle surface `s` to a stream in the format of `extension` (one of
/// `surface_extensions()`, with or without its dot, or a file name); see `write_surface(const
/// std::string&, const Surface&, const NamedParameters&)`.
/// \throws std::invalid_argument when the extension is not one of `surface_extensions()`.
/// \throws Write_error when the stream fails, the surface is inconsistent or an option is not possible.
template <class Surface, class NamedParameters = parameters::Default_named_parameters>
void write_surface(std::ostream& out, const Surface& s, const std::string& extension,
                   const NamedParameters& np = parameters::default_values(),
                   const std::string& name = "<stream>") {
  const std::string e = extension.find('.') == std::string::npos ? "." + extension : extension;
  internal::write_surface_stream(out, s, internal::surface_format_of(e), internal::write_options(np), name);
}

/// \ingroup PkgPRStarOctreeIO
/// Writes the triangle surface `s` (a `Triangle_surface`, or any type with its members) to the
/// file `filename`, in the format of its extension (case-insensitive):
///
/// | extension | format | data written |
/// |---|---|---|
/// | `.off` | ASCII OFF | points and triangles only |
/// | `.stl` | STL, binary (default) or ASCII | triangles with their unit normal `(b - a) x (c - a)`; binary:
/// `float` coordinates, attribute 0 | | `.ply` | PLY, `binary_little_endian` (default) or `ascii` | `double`
/// `x y z`, the point arrays as `double` and `int` vertex properties, `list uchar int vertex_indices` and the
/// triangle arrays as `int` face properties, label names as `comment label N name` | | `.obj` | Wavefront OBJ
/// | `v`, `f` (1-based); label names as `# label N name`; `g NAME_VALUE` each time the value of the first
/// triangle array changes | | `.vtp` | VTK XML PolyData, inline base64 binary (default, zlib-compressed when
/// the build has zlib) or ascii | the arrays by name (`Float64`, `Int32`), `Float64` points, `Int64`
/// polygons; label names as the field data `label_ids` and `label_names` (ascii) | | `.mesh` | Medit ASCII,
/// version 2 | `Vertices` (reference 0), `Triangles` (1-based) with the first triangle array as references
/// (or 0) |
///
/// Text numbers are written with the shortest decimal form that reads back exactly, binary ones
/// bit for bit (STL: rounded to `float`, the format's type).  The triangles are written in their
/// order with their orientation.
///
/// \tparam NamedParameters a sequence of named parameters
/// \param filename the file; its extension chooses the format
/// \param s the surface
/// \param np the write options (`Write_options.h`)
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{use_binary_mode}
///     \cgalParamDescription{binary (`true`) or text (`false`): `.stl`, `.ply`, `.vtp` only (the
///       others are text only and refuse `true`)}
///     \cgalParamType{Boolean}
///     \cgalParamDefault{`true` for `.stl`, `.ply`, `.vtp`}
///   \cgalParamNEnd
///   \cgalParamNBegin{compression}
///     \cgalParamDescription{`.vtp` in binary only: `Compression::zlib` or `Compression::none`}
///     \cgalParamType{`CGAL::PR_star_octree::IO::Compression`}
///     \cgalParamDefault{`Compression::zlib` for a binary `.vtp` when the build has zlib, else
///     `Compression::none`}
///   \cgalParamNEnd
///   \cgalParamNBegin{format_version}
///     \cgalParamDescription{`.vtp`: 1.0; `.mesh`: 2; the others have none to choose}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1.0 for `.vtp`, 2 for `.mesh`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws std::invalid_argument when the extension is not one of `surface_extensions()`.
/// \throws Write_error (a `std::runtime_error`; `what()` reads `FILE: message`) when the file
/// cannot be opened or written (with the system's reason, e.g. `No space left on device`), an
/// array does not have one (finite) value per vertex or triangle, two arrays of points or of
/// triangles have the same name, an index is out of range, a coordinate is not finite, a label
/// name is not one line, a PLY property name contains spaces, or an option is not possible.
template <class Surface, class NamedParameters = parameters::Default_named_parameters>
void write_surface(const std::string& filename, const Surface& s,
                   const NamedParameters& np = parameters::default_values()) {
  const Surface_format& format = internal::surface_format_of(filename);
  const internal::Write_options given = internal::write_options(np);
  internal::check_surface_for_writing(s, format, given, filename);
  std::ofstream out;
  errno = 0;
  try {
    internal::open_for_writing(out, filename);
  } catch (const Write_error& e) {
    throw internal::with_os_reason(e, errno);
  }
  errno = 0;
  try {
    internal::write_surface_stream(out, s, format, given, filename);
    internal::close_written(out, filename);
  } catch (const Write_error& e) {
    throw internal::with_os_reason(e, errno);
  }
}

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_SURFACE_H
