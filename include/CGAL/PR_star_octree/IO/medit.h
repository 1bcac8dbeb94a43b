// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_MEDIT_H
#define CGAL_PR_STAR_OCTREE_IO_MEDIT_H

#include <CGAL/PR_star_octree/IO/Memory_limit.h>
#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/Write_options.h>
#include <CGAL/PR_star_octree/IO/internal/file_bytes.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <array>
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

/// Number of values per entry of the Medit sections this reader knows (and skips, except
/// `Vertices` and `Tetrahedra`), for a 3D mesh; 0 when the keyword is unknown.
inline std::size_t medit_entry_size(const std::string& lower_keyword) {
  static const std::pair<const char*, std::size_t> table[] = {
      {"vertices", 4},
      {"edges", 3},
      {"triangles", 4},
      {"quadrilaterals", 5},
      {"tetrahedra", 5},
      {"pentahedra", 7},
      {"prisms", 7},
      {"hexahedra", 9},
      {"pyramids", 6},
      {"edgesp2", 4},
      {"trianglesp2", 7},
      {"quadrilateralsq2", 10},
      {"tetrahedrap2", 11},
      {"hexahedraq2", 28},
      {"corners", 1},
      {"ridges", 1},
      {"requiredvertices", 1},
      {"requirededges", 1},
      {"requiredtriangles", 1},
      {"requiredquadrilaterals", 1},
      {"requiredtetrahedra", 1},
      {"normals", 3},
      {"tangents", 3},
      {"normalatvertices", 2},
      {"tangentatvertices", 2},
      {"normalattrianglevertices", 3},
      {"normalatquadrilateralvertices", 3},
      {"tangentatedgevertices", 3},
  };
  for (const auto& e : table)
    if (lower_keyword == e.first) return e.second;
  return 0;
}

template <class Mesh>
void read_medit_text(std::string_view text, const std::string& name, Mesh& result) {
  using Point_3 = typename Mesh::Point_3;
  using Index = typename Mesh::Index;
  Text_reader r(text, name);
  Mesh mesh;
  bool has_version = false, has_dimension = false, has_vertices = false, has_tetrahedra = false;
  std::vector<std::array<long long, 4>> pending; // tetrahedra read before the vertices (1-based)

  const auto check_tet = [&](const std::array<long long, 4>& t, std::size_t number, bool with_line) {
    for (long long v : t)
      if (v < 1 || static_cast<unsigned long long>(v) > mesh.points.size()) {
        const std::string msg = "tetrahedron " + std::to_string(number + 1) + ": vertex index " +
                                std::to_string(v) + " out of range (1-based, " +
                                std::to_string(mesh.points.size()) + " vertices)";
        if (with_line) r.fail(msg);
        throw Read_error(name, 0, msg);
      }
  };

  std::string_view token;
  while (r.next_token(token)) {
    const std::string keyword = to_lower(token);
    if (!has_version) {
      if (keyword != "meshversionformatted")
        r.fail("not a Medit mesh: expected 'MeshVersionFormatted', found " + quote(token));
      const long long version = r.expect_integer("MeshVersionFormatted value");
      if (version < 1 || version > 4) r.fail("unsupported MeshVersionFormatted " + std::to_string(version));
      has_version = true;
      continue;
    }
    if (keyword == "end") break; // anything after End is ignored
    if (keyword == "meshversionformatted") r.fail("duplicate 'MeshVersionFormatted'");
    if (keyword == "dimension") {
      if (has_dimension) r.fail("duplicate 'Dimension'");
      const long long dim = r.expect_integer("dimension");
      if (dim != 3)
        r.fail("Dimension " + std::to_string(dim) + " is not supported (tetrahedral meshes need 3)");
      has_dimension = true;
      continue;
    }
    const std::size_t entry = medit_entry_size(keyword);
    if (entry == 0) r.fail("unknown Medit keyword " + quote(token));
    if (!has_dimension) r.fail("section '" + std::string(token) + "' before 'Dimension'");
    const std::string section(token);
    const std::size_t count = r.expect_count("entry count");

    if (keyword == "vertices") {
      if (has_vertices) r.fail("duplicate 'Vertices' section");
      has_vertices = true;
      if (count > max_vertices<Index>())
        r.fail(std::to_string(count) + " vertices do not fit in the index type of the mesh");
      check_memory_if_present(r.name(), r.line(), count, mesh.tetrahedra.size(), sizeof(Point_3),
                              sizeof(typename Mesh::Tetrahedron) + sizeof(int), count, 8,
                              r.remaining_bytes());
      capped_reserve(mesh.points, count, r.remaining_bytes(), 8);
      advise_huge_pages(mesh.points.data(), mesh.points.capacity() * sizeof(Point_3));
      for (std::size_t i = 0; i < count; ++i) {
        r.set_context("vertex", i + 1);
        const double x = r.expect_double("coordinate");
        const double y = r.expect_double("coordinate");
        const double z = r.expect_double("coordinate");
        r.expect_integer("reference");
        mesh.points.push_back(Point_3(x, y, z));
      }
      r.clear_context();
      for (std::size_t t = 0; t < pending.size(); ++t) check_tet(pending[t], t, false);
    } else if (keyword == "tetrahedra") {
      if (has_tetrahedra) r.fail("duplicate 'Tetrahedra' section");
      has_tetrahedra = true;
      check_memory_if_present(r.name(), r.line(), mesh.points.size(), count, sizeof(Point_3),
                              sizeof(typename Mesh::Tetrahedron) + sizeof(int), count, 10,
                              r.remaining_bytes());
      capped_reserve(mesh.tetrahedra, count, r.remaining_bytes(), 10);
      capped_reserve(mesh.tetrahedron_labels, count, r.remaining_bytes(), 10);
      advise_huge_pages(mesh.tetrahedra.data(),
                        mesh.tetrahedra.capacity() * sizeof(typename Mesh::Tetrahedron));
      for (std::size_t i = 0; i < count; ++i) {
        r.set_context("tetrahedron", i + 1);
        std::array<long long, 4> t;
        for (long long& v : t) v = r.expect_integer("vertex index");
        long long twice;
        if (has_repeated_vertex(t, twice)) r.fail("vertex index " + std::to_string(twice) + " listed twice");
        const long long ref = r.expect_integer("reference");
        if (ref < std::numeric_limits<int>::min() || ref > std::numeric_limits<int>::max())
          r.fail("reference " + std::to_string(ref) + " out of the int range");
        r.clear_context();
        if (has_vertices) check_tet(t, i, true);
        if (has_vertices) {
          mesh.tetrahedra.push_back({Index(t[0] - 1), Index(t[1] - 1), Index(t[2] - 1), Index(t[3] - 1)});
        } else {
          pending.push_back(t);
          mesh.tetrahedra.push_back({0, 0, 0, 0});
        }
        mesh.tetrahedron_labels.push_back(static_cast<int>(ref));
      }
    } else {
      for (std::size_t i = 0; i < count * entry; ++i) {
        double d;
        if (r.fast_double(d)) continue;
        const std::string_view value = r.expect_token("a value of a skipped section");
        if (parse_double(value, d) != nullptr)
          r.fail("section " + section + " (" + std::to_string(count) + " entries of " +
                 std::to_string(entry) + " values): expected a number, found " + quote(value));
      }
    }
  }
  if (!has_version) r.fail("empty file: expected 'MeshVersionFormatted'");
  if (!has_vertices) r.fail("no 'Vertices' section");
  if (!has_tetrahedra) r.fail("no 'Tetrahedra' section");
  for (std::size_t t = 0; t < pending.size(); ++t)
    for (int k = 0; k < 4; ++k) mesh.tetrahedra[t][k] = Index(pending[t][k] - 1);
  result = std::move(mesh);
}

} // namespace internal

/// \ingroup PkgPRStarOctreeIO
/// Reads a tetrahedral mesh from a Medit ASCII `.mesh` text held by a stream; `name` is used in
/// error messages.  See `read_medit(const std::string&, Mesh&)`.
template <class Mesh>
void read_medit(std::istream& in, Mesh& mesh, const std::string& name = "<stream>") {
  const std::string text = internal::load_stream(in, name);
  internal::read_medit_text(text, name, mesh);
}

/// \ingroup PkgPRStarOctreeIO
/// Reads a tetrahedral mesh from a Medit ASCII `.mesh` file.
///
/// The file starts with `MeshVersionFormatted 1|2` (3 and 4 accepted) and `Dimension 3`; then
/// come sections, each a keyword, a count and the entries.  `Vertices` (`x y z ref`, the reference
/// is ignored) and `Tetrahedra` (`a b c d ref`, 1-based) are required and read, the reference of
/// each tetrahedron going to `tetrahedron_labels`; the other common sections (`Edges`,
/// `Triangles`, `Quadrilaterals`, `Prisms`, `Hexahedra`, `Pyramids`, P2/Q2 elements, `Corners`,
/// `Ridges`, `Required*`, `Normals`, `Tangents`, `NormalAt*`, `TangentAt*`) are skipped according
/// to their counts.  Keywords are case-insensitive, `#` starts a comment, everything after `End`
/// is ignored and a missing `End` is accepted.  The order of the vertices of the tetrahedra is
/// kept.
///
/// \throws Read_error on any problem (unknown keyword, `Dimension` other than 3, truncated
/// section, index out of range, non-finite coordinate, duplicate or missing section...).  `mesh`
/// is then left unchanged; it is replaced on success.
template <class Mesh>
void read_medit(const std::string& filename, Mesh& mesh) {
  const internal::File_bytes text(filename); // not zero-filled, huge pages when large
  internal::read_medit_text(text.view(), filename, mesh);
}

namespace internal {

/// What the Medit ASCII writer accepts: text, version 2 (double precision).
inline constexpr Write_support medit_write_support{
    true, false, false, false, false, {"2", nullptr, nullptr, nullptr}, nullptr};

template <class Mesh>
void write_medit_stream(std::ostream& out, const Mesh& mesh, const Write_options& given,
                        const std::string& name) {
  resolve_write_options(given, medit_write_support, "Medit .mesh", name);
  check_mesh_for_writing(mesh, name);
  std::string buf;
  buf += "MeshVersionFormatted 2\nDimension 3\n\nVertices\n";
  append_integer(buf, mesh.points.size());
  buf += '\n';
  for (const auto& p : mesh.points) {
    append_double(buf, CGAL::to_double(p.x()));
    buf += ' ';
    append_double(buf, CGAL::to_double(p.y()));
    buf += ' ';
    append_double(buf, CGAL::to_double(p.z()));
    buf += " 0\n";
    flush_buffer(out, buf, name);
  }
  buf += "\nTetrahedra\n";
  append_integer(buf, mesh.tetrahedra.size());
  buf += '\n';
  const bool labels = !mesh.tetrahedron_labels.empty();
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    for (const auto v : mesh.tetrahedra[t]) {
      append_integer(buf, static_cast<unsigned long long>(v) + 1);
      buf += ' ';
    }
    append_integer(buf, labels ? mesh.tetrahedron_labels[t] : 1);
    buf += '\n';
    flush_buffer(out, buf, name);
  }
  buf += "\nEnd\n";
  flush_buffer(out, buf, name, true);
}

template <class Mesh>
void write_medit_file(const std::string& filename, const Mesh& mesh, const Write_options& given) {
  resolve_write_options(given, medit_write_support, "Medit .mesh", filename);
  check_mesh_for_writing(mesh, filename);
  std::ofstream out;
  open_for_writing(out, filename);
  write_medit_stream(out, mesh, given, filename);
  close_written(out, filename);
}

} // namespace internal

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to a stream in the Medit ASCII format (`MeshVersionFormatted 2`, `Dimension 3`,
/// `Vertices` with reference 0, `Tetrahedra` 1-based with the labels of the mesh as references,
/// or 1 when it has none, `End`).  Coordinates are written with the shortest decimal form that
/// reads back exactly.  Point data cannot be stored in a `.mesh` file and are not written.
/// \param out the stream
/// \param mesh the mesh
/// \param np the write options (`Write_options.h`); only text, uncompressed, version 2 is possible
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{use_binary_mode}
///     \cgalParamDescription{must be `false` (the binary form is `.meshb`, `write_meshb()`)}
///     \cgalParamType{Boolean}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{format_version}
///     \cgalParamDescription{`MeshVersionFormatted`: 2 only (double precision)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{2}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \param name the name of the stream in error messages
/// \throws Write_error when the stream fails, the mesh is inconsistent or an option is not possible.
template <class Mesh, class NamedParameters = parameters::Default_named_parameters>
void write_medit(std::ostream& out, const Mesh& mesh,
                 const NamedParameters& np = parameters::default_values(),
                 const std::string& name = "<stream>") {
  internal::write_medit_stream(out, mesh, internal::write_options(np), name);
}

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to the Medit ASCII file `filename`; see `write_medit(std::ostream&, const Mesh&, const
/// NamedParameters&, const std::string&)`, whose options it takes.
/// \throws Write_error when the file cannot be written, or for the reasons given there.
template <class Mesh, class NamedParameters = parameters::Default_named_parameters>
void write_medit(const std::string& filename, const Mesh& mesh,
                 const NamedParameters& np = parameters::default_values()) {
  internal::write_medit_file(filename, mesh, internal::write_options(np));
}

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_MEDIT_H
