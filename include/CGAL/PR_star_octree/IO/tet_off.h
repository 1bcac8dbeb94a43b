// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_TET_OFF_H
#define CGAL_PR_STAR_OCTREE_IO_TET_OFF_H

#include <CGAL/PR_star_octree/IO/Memory_limit.h>
#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/Write_options.h>
#include <CGAL/PR_star_octree/IO/internal/file_bytes.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <cstddef>
#include <fstream>
#include <istream>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {

template <class Mesh>
void read_tet_off_text(std::string_view text, const std::string& name, Mesh& result) {
  using Point_3 = typename Mesh::Point_3;
  using Index = typename Mesh::Index;
  Text_reader r(text, name);
  Mesh mesh;
  std::vector<std::string_view> f;

  // ---- header and counts
  if (!r.next_line(f)) r.fail("empty file: expected the numbers of vertices and tetrahedra");
  std::size_t first = 0;
  {
    long long dummy;
    if (parse_integer(f[0], dummy) != nullptr) {
      if (!iequals(f[0], "OFF") && !iequals(f[0], "TOFF"))
        r.fail("expected an 'OFF' header or the number of vertices, found " + quote(f[0]));
      first = 1;
    }
  }
  std::vector<long long> counts;
  const auto take_counts = [&](std::size_t from, const char* expected) {
    if (f.size() - from > 2 - counts.size())
      r.fail(std::string("expected ") + expected + ", found " + std::to_string(f.size() - from) + " values");
    for (std::size_t i = from; i < f.size(); ++i) {
      long long c;
      if (const char* why = parse_integer(f[i], c)) r.fail("count " + quote(f[i]) + " " + why);
      if (c < 0) r.fail("negative count " + std::to_string(c));
      counts.push_back(c);
    }
  };
  take_counts(first, "'nV nT' or 'nV'");
  while (counts.size() < 2) {
    if (!r.next_line(f))
      r.fail(counts.empty() ? "unexpected end of file, expected the number of vertices"
                            : "unexpected end of file, expected the number of tetrahedra");
    take_counts(0, counts.empty() ? "'nV nT' or 'nV'" : "a single number (the number of tetrahedra)");
  }
  if (static_cast<unsigned long long>(counts[0]) > max_vertices<Index>())
    r.fail(std::to_string(counts[0]) + " vertices do not fit in the index type of the mesh");
  if (static_cast<unsigned long long>(counts[1]) > std::numeric_limits<std::size_t>::max() / 64)
    r.fail("number of tetrahedra " + std::to_string(counts[1]) + " is too large");
  const std::size_t nv = static_cast<std::size_t>(counts[0]);
  const std::size_t nt = static_cast<std::size_t>(counts[1]);

  // ---- vertices
  check_memory_if_present(r.name(), r.line(), nv, nt, sizeof(Point_3), sizeof(typename Mesh::Tetrahedron),
                          nv + nt, 6, r.remaining_bytes());
  capped_reserve(mesh.points, nv, r.remaining_bytes(), 6);
  advise_huge_pages(mesh.points.data(), mesh.points.capacity() * sizeof(Point_3));
  std::size_t fields = 0;
  std::vector<double> scalar;
  for (std::size_t i = 0; i < nv; ++i) {
    if (i > 0) { // fast path: a line of plain numbers like the first one (otherwise read below)
      Text_reader::Line_cursor c(r);
      double x, y, z, s = 0;
      if (c.real(x) && c.real(y) && c.real(z) && (fields == 3 || c.real(s)) && c.end_of_line()) {
        mesh.points.push_back(Point_3(x, y, z));
        if (fields == 4) scalar.push_back(s);
        continue;
      }
      r.set_context("vertex", i); // as left by the line before
    }
    if (!r.next_line(f))
      r.fail("unexpected end of file: " + std::to_string(i) + " vertices read, " + std::to_string(nv) +
             " declared");
    r.set_context("vertex", i + 1);
    if (i == 0) {
      if (f.size() != 3 && f.size() != 4)
        r.fail("expected 'x y z' or 'x y z scalar', found " + std::to_string(f.size()) + " values");
      fields = f.size();
      if (fields == 4) capped_reserve(scalar, nv, r.remaining_bytes(), 8);
    } else if (f.size() != fields) {
      r.fail("expected " + std::to_string(fields) + " values like the first vertex line (" +
             (fields == 4 ? "x y z scalar" : "x y z") + "), found " + std::to_string(f.size()));
    }
    double c[4];
    for (std::size_t k = 0; k < fields; ++k)
      if (const char* why = parse_double(f[k], c[k]))
        r.fail((k < 3 ? "coordinate " : "scalar ") + quote(f[k]) + " " + why);
    mesh.points.push_back(Point_3(c[0], c[1], c[2]));
    if (fields == 4) scalar.push_back(c[3]);
  }
  r.clear_context();
  if (fields == 4) mesh.point_data.push_back(Data_array{"scalar", std::move(scalar)});

  // ---- tetrahedra
  capped_reserve(mesh.tetrahedra, nt, r.remaining_bytes(), 8);
  advise_huge_pages(mesh.tetrahedra.data(), mesh.tetrahedra.capacity() * sizeof(typename Mesh::Tetrahedron));
  bool count_column = false;
  for (std::size_t i = 0; i < nt; ++i) {
    if (i > 0) { // fast path: a line like the first one, 4 distinct indices in range
      Text_reader::Line_cursor c(r);
      long long v[4];
      if ((!count_column || c.word("4")) && c.integer(v[0]) && c.integer(v[1]) && c.integer(v[2]) &&
          c.integer(v[3]) && v[0] < static_cast<long long>(nv) && v[1] < static_cast<long long>(nv) &&
          v[2] < static_cast<long long>(nv) && v[3] < static_cast<long long>(nv) && v[0] != v[1] &&
          v[0] != v[2] && v[0] != v[3] && v[1] != v[2] && v[1] != v[3] && v[2] != v[3] && c.end_of_line()) {
        mesh.tetrahedra.push_back({Index(v[0]), Index(v[1]), Index(v[2]), Index(v[3])});
        continue;
      }
      r.set_context("tetrahedron", i); // as left by the line before
    }
    if (!r.next_line(f))
      r.fail("unexpected end of file: " + std::to_string(i) + " tetrahedra read, " + std::to_string(nt) +
             " declared");
    r.set_context("tetrahedron", i + 1);
    if (i == 0) {
      if (f.size() == 5 && f[0] == "4")
        count_column = true;
      else if (f.size() != 4)
        r.fail("expected 4 vertex indices (optionally preceded by the count 4), found " +
               std::to_string(f.size()) + " values");
    }
    if (f.size() != (count_column ? 5u : 4u))
      r.fail(std::string("expected ") +
             (count_column ? "'4 a b c d' like the first tetrahedron line" : "4 vertex indices") +
             ", found " + std::to_string(f.size()) + " values");
    if (count_column && f[0] != "4") r.fail("expected the vertex count 4 first, found " + quote(f[0]));
    typename Mesh::Tetrahedron t;
    for (std::size_t k = 0; k < 4; ++k) {
      const std::string_view tok = f[k + (count_column ? 1 : 0)];
      long long v;
      if (const char* why = parse_integer(tok, v)) r.fail("vertex index " + quote(tok) + " " + why);
      if (v < 0 || static_cast<unsigned long long>(v) >= nv)
        r.fail("vertex index " + std::to_string(v) + " out of range (0-based, " + std::to_string(nv) +
               " vertices)");
      t[k] = static_cast<Index>(v);
    }
    long long twice;
    if (has_repeated_vertex(t, twice)) r.fail("vertex index " + std::to_string(twice) + " listed twice");
    mesh.tetrahedra.push_back(t);
  }
  r.clear_context();
  if (r.next_line(f)) r.fail("unexpected data after the " + std::to_string(nt) + " declared tetrahedra");
  result = std::move(mesh);
}

} // namespace internal

/// \ingroup PkgPRStarOctreeIO
/// Reads a tet-OFF text from a stream; `name` is used in error messages.  See
/// `read_tet_off(const std::string&, Mesh&)`.
template <class Mesh>
void read_tet_off(std::istream& in, Mesh& mesh, const std::string& name = "<stream>") {
  const std::string text = internal::load_stream(in, name);
  internal::read_tet_off_text(text, name, mesh);
}

/// \ingroup PkgPRStarOctreeIO
/// Reads a tetrahedral mesh from a tet-OFF file (`.off`, `.ts`, as used by unstructured volume
/// renderers):
/// - an optional header line `OFF` or `TOFF` (the counts may follow on the same line);
/// - the counts: `nV nT` on one line, or `nV` on a line and `nT` on the next;
/// - `nV` vertex lines `x y z` or `x y z scalar`: the first vertex line decides, all must then
///   have the same number of values; the scalars become the point-data array `scalar`;
/// - `nT` tetrahedron lines `a b c d` (0-based), or `4 a b c d` when the first one has that
///   leading count column (then all must).
///
/// `#` starts a comment, blank lines are ignored.  Any non-comment line after the declared
/// tetrahedra is an error (the counts do not match the data: a sign of corruption).
/// Negatively oriented tetrahedra are kept as listed.
///
/// \throws Read_error on any problem; `mesh` is then left unchanged.  It is replaced on success.
template <class Mesh>
void read_tet_off(const std::string& filename, Mesh& mesh) {
  const internal::File_bytes text(filename); // not zero-filled, huge pages when large
  internal::read_tet_off_text(text.view(), filename, mesh);
}

namespace internal {

/// What the tet-OFF writer accepts: text, no version.
inline constexpr Write_support tet_off_write_support{
    true, false, false, false, false, {nullptr, nullptr, nullptr, nullptr}, nullptr};

template <class Mesh>
void write_tet_off_stream(std::ostream& out, const Mesh& mesh, const Write_options& given,
                          const std::string& name) {
  resolve_write_options(given, tet_off_write_support, "tet-OFF", name);
  check_mesh_for_writing(mesh, name);
  const auto* scalar = mesh.point_data.empty() ? nullptr : &mesh.point_data.front().values;
  std::string buf;
  append_integer(buf, mesh.points.size());
  buf += ' ';
  append_integer(buf, mesh.tetrahedra.size());
  buf += '\n';
  for (std::size_t i = 0; i < mesh.points.size(); ++i) {
    const auto& p = mesh.points[i];
    append_double(buf, CGAL::to_double(p.x()));
    buf += ' ';
    append_double(buf, CGAL::to_double(p.y()));
    buf += ' ';
    append_double(buf, CGAL::to_double(p.z()));
    if (scalar) {
      buf += ' ';
      append_double(buf, (*scalar)[i]);
    }
    buf += '\n';
    flush_buffer(out, buf, name);
  }
  for (const auto& t : mesh.tetrahedra) {
    for (int k = 0; k < 4; ++k) {
      append_integer(buf, static_cast<unsigned long long>(t[k]));
      buf += (k == 3 ? '\n' : ' ');
    }
    flush_buffer(out, buf, name);
  }
  flush_buffer(out, buf, name, true);
}

template <class Mesh>
void write_tet_off_file(const std::string& filename, const Mesh& mesh, const Write_options& given) {
  resolve_write_options(given, tet_off_write_support, "tet-OFF", filename);
  check_mesh_for_writing(mesh, filename);
  std::ofstream out;
  open_for_writing(out, filename);
  write_tet_off_stream(out, mesh, given, filename);
  close_written(out, filename);
}

} // namespace internal

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` as tet-OFF to a stream: a line `nV nT`, the vertex lines `x y z [scalar]` (the
/// scalar being the first point-data array of the mesh, when it has one), the tetrahedron lines
/// `a b c d` (0-based).  Numbers are written with the shortest form that reads back exactly.  The
/// labels and the other point-data arrays are not written.
/// \param out the stream
/// \param mesh the mesh
/// \param np the write options (`Write_options.h`); tet-OFF is text only and has no version
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{use_binary_mode}
///     \cgalParamDescription{must be `false`}
///     \cgalParamType{Boolean}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \param name the name of the stream in error messages
/// \throws Write_error when the stream fails, the mesh is inconsistent or an option is not possible.
template <class Mesh, class NamedParameters = parameters::Default_named_parameters>
void write_tet_off(std::ostream& out, const Mesh& mesh,
                   const NamedParameters& np = parameters::default_values(),
                   const std::string& name = "<stream>") {
  internal::write_tet_off_stream(out, mesh, internal::write_options(np), name);
}

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to the tet-OFF file `filename`; see `write_tet_off(std::ostream&, const Mesh&, const
/// NamedParameters&, const std::string&)`, whose options it takes.
/// \throws Write_error when the file cannot be written, or for the reasons given there.
template <class Mesh, class NamedParameters = parameters::Default_named_parameters>
void write_tet_off(const std::string& filename, const Mesh& mesh,
                   const NamedParameters& np = parameters::default_values()) {
  internal::write_tet_off_file(filename, mesh, internal::write_options(np));
}

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_TET_OFF_H
