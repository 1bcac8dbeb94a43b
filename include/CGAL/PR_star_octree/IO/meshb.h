// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_MESHB_H
#define CGAL_PR_STAR_OCTREE_IO_MESHB_H

/// \file
/// Reading and writing Medit binary `.meshb` files (versions 1 to 4).

#include <CGAL/PR_star_octree/IO/Memory_limit.h>
#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/Write_options.h>
#include <CGAL/PR_star_octree/IO/internal/file_bytes.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <istream>
#include <limits>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {

// Keyword codes of the Gamma Mesh Format used here.
constexpr std::int32_t meshb_dimension = 3;
constexpr std::int32_t meshb_vertices = 4;
constexpr std::int32_t meshb_tetrahedra = 8;
constexpr std::int32_t meshb_end = 54;

template <class Mesh>
void read_meshb_data(std::string_view data, const std::string& name, Mesh& result) {
  using Point_3 = typename Mesh::Point_3;
  using Index = typename Mesh::Index;
  Byte_cursor c(data, name);
  if (data.size() < 8) c.fail("not a Medit binary mesh: the file is shorter than its 8-byte header");
  if (!c.take_byte_order_mark())
    c.fail("not a Medit binary mesh: the first integer is " +
           std::to_string(load_value<std::int32_t>(data.data(), false)) + ", not 1 (in either byte order)");
  const std::int32_t version = c.get<std::int32_t>("version");
  if (version < 1 || version > 4)
    c.fail_at(4, "unsupported .meshb version " + std::to_string(version) + " (1 to 4)");
  const std::size_t real_bytes = version == 1 ? 4 : 8;
  const std::size_t int_bytes = version == 4 ? 8 : 4;
  const std::size_t pos_bytes = version >= 3 ? 8 : 4;

  Mesh mesh;
  bool has_dimension = false, has_vertices = false, has_tetrahedra = false;
  while (c.remaining() > 0) {
    const std::size_t at = c.offset();
    const std::int32_t keyword = c.get<std::int32_t>("keyword");
    if (keyword == meshb_end) break;
    const std::uint64_t next = c.get_unsigned(pos_bytes, "next keyword position");
    if (next != 0 && (next <= at || next > c.size()))
      c.fail_at(at, "keyword " + std::to_string(keyword) + ": next keyword position " + std::to_string(next) +
                        " is not after the keyword and inside the file (" + std::to_string(c.size()) +
                        " bytes)");
    if (keyword == meshb_dimension) {
      if (has_dimension) c.fail_at(at, "duplicate Dimension keyword");
      const std::int32_t dim = c.get<std::int32_t>("dimension");
      if (dim != 3)
        c.fail_at(at, "Dimension " + std::to_string(dim) + " is not supported (tetrahedral meshes need 3)");
      has_dimension = true;
    } else if (keyword == meshb_vertices || keyword == meshb_tetrahedra) {
      if (!has_dimension) c.fail_at(at, "keyword " + std::to_string(keyword) + " before Dimension");
      const std::int64_t n = c.get_signed(int_bytes, "entry count");
      if (n < 0) c.fail_at(at, "negative entry count " + std::to_string(n));
      const std::uint64_t count = static_cast<std::uint64_t>(n);
      if (keyword == meshb_vertices) {
        if (has_vertices) c.fail_at(at, "duplicate Vertices keyword");
        has_vertices = true;
        if (count >= static_cast<std::uint64_t>(std::numeric_limits<Index>::max()))
          c.fail_at(at, std::to_string(count) + " vertices do not fit in the index type of the mesh");
        const std::size_t per = 3 * real_bytes + int_bytes;
        if (!c.fits(count, per))
          c.fail_at(at, std::to_string(count) + " vertices announced, but only " +
                            std::to_string(c.remaining()) + " bytes are left (" + std::to_string(per) +
                            " bytes each)");
        check_memory(c.name(), 0, count, mesh.tetrahedra.size(), sizeof(Point_3),
                     sizeof(typename Mesh::Tetrahedron) + sizeof(int));
        const std::size_t nv = static_cast<std::size_t>(count);
        mesh.points.reserve(nv);
        advise_huge_pages(mesh.points.data(), nv * sizeof(Point_3));
        for (std::size_t i = 0; i < nv; ++i) {
          const double x = c.get_real(real_bytes, "vertex"), y = c.get_real(real_bytes, "vertex"),
                       z = c.get_real(real_bytes, "vertex");
          c.get_signed(int_bytes, "vertex reference");
          if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
            c.fail("vertex " + std::to_string(i + 1) + ": coordinate is not finite");
          mesh.points.push_back(Point_3(x, y, z));
        }
      } else {
        if (has_tetrahedra) c.fail_at(at, "duplicate Tetrahedra keyword");
        has_tetrahedra = true;
        const std::size_t per = 5 * int_bytes;
        if (!c.fits(count, per))
          c.fail_at(at, std::to_string(count) + " tetrahedra announced, but only " +
                            std::to_string(c.remaining()) + " bytes are left (" + std::to_string(per) +
                            " bytes each)");
        check_memory(c.name(), 0, mesh.points.size(), count, sizeof(Point_3),
                     sizeof(typename Mesh::Tetrahedron) + sizeof(int));
        const std::size_t nt = static_cast<std::size_t>(count);
        mesh.tetrahedra.reserve(nt);
        mesh.tetrahedron_labels.reserve(nt);
        advise_huge_pages(mesh.tetrahedra.data(), nt * sizeof(typename Mesh::Tetrahedron));
        advise_huge_pages(mesh.tetrahedron_labels.data(), nt * sizeof(int));
        for (std::size_t i = 0; i < nt; ++i) {
          typename Mesh::Tetrahedron t;
          for (int k = 0; k < 4; ++k) {
            const std::int64_t v = c.get_signed(int_bytes, "tetrahedron");
            if (v < 1 || !fits_index<Index>(v - 1))
              c.fail("tetrahedron " + std::to_string(i + 1) + ": vertex index " + std::to_string(v) +
                     " out of range (1-based)");
            t[k] = static_cast<Index>(v - 1);
          }
          const std::int64_t ref = c.get_signed(int_bytes, "tetrahedron reference");
          if (ref < std::numeric_limits<int>::min() || ref > std::numeric_limits<int>::max())
            c.fail("tetrahedron " + std::to_string(i + 1) + ": reference " + std::to_string(ref) +
                   " is out of the int range");
          Index twice;
          if (has_repeated_vertex(t, twice))
            c.fail("tetrahedron " + std::to_string(i + 1) + ": vertex index " + std::to_string(twice + 1) +
                   " listed twice");
          mesh.tetrahedra.push_back(t);
          mesh.tetrahedron_labels.push_back(static_cast<int>(ref));
        }
      }
    } else if (next == 0) {
      c.fail_at(at,
                "keyword " + std::to_string(keyword) + " cannot be skipped: its next keyword position is 0");
    }
    if (next != 0) {
      if (c.offset() > next)
        c.fail_at(at, "keyword " + std::to_string(keyword) +
                          ": its data runs past the next keyword position " + std::to_string(next));
      c.seek(static_cast<std::size_t>(next));
    }
  }
  if (!has_vertices) c.fail("no Vertices keyword");
  if (!has_tetrahedra) c.fail("no Tetrahedra keyword");
  set_float32_points(mesh, version == 1);
  for (std::size_t i = 0; i < mesh.tetrahedra.size(); ++i)
    for (const Index v : mesh.tetrahedra[i])
      if (static_cast<std::size_t>(v) >= mesh.points.size())
        c.fail("tetrahedron " + std::to_string(i + 1) + ": vertex index " +
               std::to_string(std::uint64_t(v) + 1) + " out of range (1-based, " +
               std::to_string(mesh.points.size()) + " vertices)");
  result = std::move(mesh);
}

} // namespace internal

/// \ingroup PkgPRStarOctreeIO
/// Reads a tetrahedral mesh from a Medit binary `.meshb` file held by a stream; `name` is used
/// in error messages.  See `read_meshb(const std::string&, Mesh&)`.
template <class Mesh>
void read_meshb(std::istream& in, Mesh& mesh, const std::string& name = "<stream>") {
  const std::string data = internal::load_stream(in, name);
  internal::read_meshb_data(data, name, mesh);
}

/// \ingroup PkgPRStarOctreeIO
/// Reads a tetrahedral mesh from a Medit binary `.meshb` file (Gamma Mesh Format, as written by
/// libMeshb, meshio, MMG...).
///
/// The file starts with the integer 1 (its byte order tells the file's; both orders are read) and
/// the version: 1 (32-bit reals and integers), 2 (64-bit reals), 3 (64-bit reals and keyword
/// positions) or 4 (64-bit reals, integers and positions).  Then come keywords, each followed by
/// the position of the next one: `Dimension` (must be 3), `Vertices` (`x y z ref`; the vertex
/// references are ignored), `Tetrahedra` (`a b c d ref`, 1-based; the references go to
/// `tetrahedron_labels`), `End`.  Every other keyword is skipped through its next-keyword
/// position.  A missing `End` is accepted.  Version 1 sets `mesh.float32_points`.
///
/// \throws Read_error (`FILE: byte N: message`) on any problem: bad first integer, unknown version,
/// truncated data, a count announcing more entries than the file holds (nothing is allocated for
/// it), a keyword position outside the file or going backwards, index out of range or listed twice,
/// non-finite coordinate.  `mesh` is left unchanged on error and replaced on success.
template <class Mesh>
void read_meshb(const std::string& filename, Mesh& mesh) {
  const internal::File_bytes data(filename);
  internal::read_meshb_data(data.view(), filename, mesh);
}

namespace internal {

/// What the Medit binary writer accepts: binary, versions 1 to 4 (by default the smallest that fits).
inline constexpr Write_support meshb_write_support{
    false,
    true,
    true,
    false,
    false,
    {"1", "2", "3", "4"},
    "1 for 32-bit coordinates (`float32_points`) and 2 otherwise when the file stays "
    "under 2 GB, else 3, else 4"};

template <class Mesh>
void write_meshb_stream(std::ostream& out, const Mesh& mesh, const Write_options& given,
                        const std::string& name) {
  const Write_options o = resolve_write_options(given, meshb_write_support, "Medit .meshb", name);
  int version = static_cast<int>(version_tenths(o.version) / 10);
  check_mesh_for_writing(mesh, name);
  const std::uint64_t nv = mesh.points.size(), nt = mesh.tetrahedra.size();
  if (version == 0) {
    // a mesh of 32-bit coordinates: version 1 (32-bit reals) when the file stays under 2 GB
    const std::uint64_t size = 100 + nv * 28 + nt * 20, size_1 = 100 + nv * 16 + nt * 20;
    version = size_1 < (std::uint64_t(1) << 31) && write_float32_points(mesh, name) ? 1
              : size < (std::uint64_t(1) << 31)                                     ? 2
              : (nv < (std::uint64_t(1) << 31) && nt < (std::uint64_t(1) << 31))    ? 3
                                                                                    : 4;
  }
  if (version < 1 || version > 4)
    throw Write_error(name, "unknown .meshb version " + std::to_string(version));
  const std::size_t real_bytes = version == 1 ? 4 : 8;
  const std::size_t int_bytes = version == 4 ? 8 : 4;
  const std::size_t pos_bytes = version >= 3 ? 8 : 4;
  const std::uint64_t int_max =
      int_bytes == 4 ? std::uint64_t(std::numeric_limits<std::int32_t>::max()) : ~std::uint64_t(0);
  const std::uint64_t pos_max =
      pos_bytes == 4 ? std::uint64_t(std::numeric_limits<std::int32_t>::max()) : ~std::uint64_t(0);
  if (nv >= int_max || nt >= int_max)
    throw Write_error(name, "too many vertices or tetrahedra for the integers of .meshb version " +
                                std::to_string(version));
  const std::uint64_t end_pos = 8 + (8 + pos_bytes) +
                                (4 + pos_bytes + int_bytes + nv * (3 * real_bytes + int_bytes)) +
                                (4 + pos_bytes + int_bytes + nt * 5 * int_bytes);
  if (end_pos >= pos_max)
    throw Write_error(name, "the file would be too large for the positions of .meshb version " +
                                std::to_string(version));

  std::string buf;
  const auto put_int = [&](std::int64_t v) {
    if (int_bytes == 4)
      append_binary<std::int32_t>(buf, static_cast<std::int32_t>(v));
    else
      append_binary<std::int64_t>(buf, v);
  };
  const auto put_pos = [&](std::uint64_t v) {
    if (pos_bytes == 4)
      append_binary<std::int32_t>(buf, static_cast<std::int32_t>(v));
    else
      append_binary<std::int64_t>(buf, static_cast<std::int64_t>(v));
  };
  const auto put_real = [&](double v) {
    if (real_bytes == 4)
      append_binary<float>(buf, static_cast<float>(v));
    else
      append_binary<double>(buf, v);
  };
  append_binary<std::int32_t>(buf, 1);
  append_binary<std::int32_t>(buf, version);
  std::uint64_t pos = 8 + 4 + pos_bytes + 4;
  append_binary<std::int32_t>(buf, meshb_dimension);
  put_pos(pos);
  append_binary<std::int32_t>(buf, 3);
  pos += 4 + pos_bytes + int_bytes + nv * (3 * real_bytes + int_bytes);
  append_binary<std::int32_t>(buf, meshb_vertices);
  put_pos(pos);
  put_int(static_cast<std::int64_t>(nv));
  for (const auto& p : mesh.points) {
    put_real(CGAL::to_double(p.x()));
    put_real(CGAL::to_double(p.y()));
    put_real(CGAL::to_double(p.z()));
    put_int(0);
    flush_buffer(out, buf, name);
  }
  pos += 4 + pos_bytes + int_bytes + nt * 5 * int_bytes;
  append_binary<std::int32_t>(buf, meshb_tetrahedra);
  put_pos(pos);
  put_int(static_cast<std::int64_t>(nt));
  const bool labels = !mesh.tetrahedron_labels.empty();
  for (std::size_t t = 0; t < nt; ++t) {
    for (const auto v : mesh.tetrahedra[t]) put_int(static_cast<std::int64_t>(v) + 1);
    put_int(labels ? mesh.tetrahedron_labels[t] : 1);
    flush_buffer(out, buf, name);
  }
  append_binary<std::int32_t>(buf, meshb_end);
  put_pos(0);
  flush_buffer(out, buf, name, true);
}

template <class Mesh>
void write_meshb_file(const std::string& filename, const Mesh& mesh, const Write_options& given) {
  resolve_write_options(given, meshb_write_support, "Medit .meshb", filename);
  check_mesh_for_writing(mesh, filename);
  if (!given.has_version) write_float32_points(mesh, filename); // its checks, before the file is created
  std::ofstream out;
  open_for_writing(out, filename);
  write_meshb_stream(out, mesh, given, filename);
  close_written(out, filename);
}

} // namespace internal

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to a stream in the Medit binary format; see
/// `write_meshb(const std::string&, const Mesh&, const NamedParameters&)`, whose options it takes.
template <class Mesh, class NamedParameters = parameters::Default_named_parameters>
void write_meshb(std::ostream& out, const Mesh& mesh,
                 const NamedParameters& np = parameters::default_values(),
                 const std::string& name = "<stream>") {
  internal::write_meshb_stream(out, mesh, internal::write_options(np), name);
}

/// \ingroup PkgPRStarOctreeIO
/// Writes `mesh` to the Medit binary file `filename`: `Dimension 3`, `Vertices` (reference 0),
/// `Tetrahedra` (1-based, the labels as references, or 1 when the mesh has none), `End`, in the
/// machine's byte order.  Version 1 stores the coordinates as 32-bit floats (rounded).  Point data
/// cannot be stored and are not written.  A mesh with `float32_points` set is written in version 1
/// unless `format_version` asks for another (64-bit reals) or the file would reach 2 GB.
/// \param filename the name of the file
/// \param mesh the mesh
/// \param np the write options (`Write_options.h`)
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{use_binary_mode}
///     \cgalParamDescription{must be `true` (the text form is `.mesh`, `write_medit()`)}
///     \cgalParamType{Boolean}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{format_version}
///     \cgalParamDescription{1 (32-bit reals and integers), 2 (64-bit reals), 3 (64-bit reals and
///       positions) or 4 (64-bit reals, integers and positions); see `read_meshb()`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1 for a mesh with `float32_points` set when the file stays under 2 GB, else 2
///       when it does, else 3 when the counts fit in 32 bits, else 4}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Write_error when the file cannot be written, the mesh is inconsistent or too large for
/// the requested version, or an option is not possible.
template <class Mesh, class NamedParameters = parameters::Default_named_parameters>
void write_meshb(const std::string& filename, const Mesh& mesh,
                 const NamedParameters& np = parameters::default_values()) {
  internal::write_meshb_file(filename, mesh, internal::write_options(np));
}

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_MESHB_H
