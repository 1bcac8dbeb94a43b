// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTU_READER_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTU_READER_H

// The VTK XML UnstructuredGrid (.vtu) reader: data arrays (ascii, base64 binary, appended raw and base64) and
// the mesh.

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/internal/base64.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>
#include <CGAL/PR_star_octree/IO/internal/vtk_cells.h>
#include <CGAL/PR_star_octree/IO/internal/xml.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <limits>
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

inline bool host_is_little_endian() {
  const std::uint16_t one = 1;
  unsigned char c;
  std::memcpy(&c, &one, 1);
  return c == 1;
}

/// Reads the data arrays of a parsed VTK XML file.
class Vtu_array_reader {
public:
  enum Kind { SIGNED, UNSIGNED, FLOAT };

  Vtu_array_reader(const Xml_document& doc, const std::string& name) : doc_(doc), name_(name) {
    const Xml_element& root = doc.root();
    if (const std::string* bo = root.attribute("byte_order")) {
      if (*bo == "BigEndian")
        swap_ = host_is_little_endian();
      else if (*bo == "LittleEndian")
        swap_ = !host_is_little_endian();
      else
        fail(root, "unknown byte_order '" + *bo + "'");
    } else {
      swap_ = !host_is_little_endian();
    }
    if (const std::string* ht = root.attribute("header_type")) {
      if (*ht == "UInt64")
        header_size_ = 8;
      else if (*ht == "UInt32")
        header_size_ = 4;
      else
        fail(root, "unsupported header_type '" + *ht + "' (UInt32 or UInt64)");
    }
    if (const std::string* c = root.attribute("compressor")) compressor_ = *c;
    if (doc.has_appended_data()) {
      const std::string* enc = doc.appended_element().attribute("encoding");
      if (enc == nullptr) fail(doc.appended_element(), "<AppendedData> without an encoding attribute");
      if (*enc == "raw")
        appended_base64_ = false;
      else if (*enc == "base64")
        appended_base64_ = true;
      else
        fail(doc.appended_element(), "unknown AppendedData encoding '" + *enc + "' (raw or base64)");
    }
  }

  [[noreturn]] void fail(const Xml_element& e, const std::string& message) const {
    throw Read_error(name_, e.line, message);
  }

  static std::string describe(const Xml_element& e) {
    const std::string* n = e.attribute("Name");
    return n ? "DataArray '" + *n + "'" : std::string("DataArray");
  }

  /// Reads the `count` values of a DataArray into `out` (`double` or `long long`).
  template <class T>
  void read(const Xml_element& e, std::size_t count, std::vector<T>& out) const {
    const std::string* type = e.attribute("type");
    if (type == nullptr) fail(e, describe(e) + " without a type attribute");
    std::size_t size = 0;
    Kind kind = SIGNED;
    if (!type_info(*type, size, kind)) fail(e, describe(e) + ": unknown type '" + *type + "'");
    if (std::is_integral<T>::value && kind == FLOAT)
      fail(e, describe(e) + " has type " + *type + " but must have an integer type");
    const std::string* format = e.attribute("format");
    const std::string fmt = format ? *format : std::string("ascii");
    out.clear();
    if (fmt == "ascii") {
      read_ascii(e, count, out);
    } else if (fmt == "binary" || fmt == "appended") {
      if (!compressor_.empty())
        fail(e, describe(e) + ": compressed data (compressor=\"" + compressor_ +
                    "\") is not supported; save the file uncompressed or in ascii");
      if (fmt == "binary") {
        std::string storage;
        const std::string_view text = doc_.element_text(e, storage);
        Base64_decoder dec(text);
        read_binary(e, count, size, kind, *type, dec, nullptr, 0, out);
      } else {
        const std::string* off = e.attribute("offset");
        if (off == nullptr) fail(e, describe(e) + ": appended data without an offset attribute");
        long long offset = 0;
        if (parse_integer(*off, offset) != nullptr || offset < 0)
          fail(e, describe(e) + ": invalid offset '" + *off + "'");
        if (!doc_.has_appended_data())
          fail(e, describe(e) + ": format=\"appended\" but the file has no <AppendedData>");
        const std::string_view data = doc_.appended_data();
        if (static_cast<unsigned long long>(offset) > data.size())
          fail(e, describe(e) + ": offset " + *off + " is beyond the end of the appended data (" +
                      std::to_string(data.size()) + " bytes)");
        const std::string_view block = data.substr(static_cast<std::size_t>(offset));
        if (appended_base64_) {
          Base64_decoder dec(block);
          read_binary(e, count, size, kind, *type, dec, nullptr, 0, out);
        } else {
          Base64_decoder unused{std::string_view()};
          read_binary(e, count, size, kind, *type, unused, block.data(), block.size(), out);
        }
      }
    } else {
      fail(e, describe(e) + ": unknown format '" + fmt + "' (ascii, binary or appended)");
    }
  }

private:
  static bool type_info(const std::string& t, std::size_t& size, Kind& kind) {
    static const struct {
      const char* name;
      std::size_t size;
      Kind kind;
    } table[] = {{"Int8", 1, SIGNED},     {"UInt8", 1, UNSIGNED},  {"Int16", 2, SIGNED},
                 {"UInt16", 2, UNSIGNED}, {"Int32", 4, SIGNED},    {"UInt32", 4, UNSIGNED},
                 {"Int64", 8, SIGNED},    {"UInt64", 8, UNSIGNED}, {"Float32", 4, FLOAT},
                 {"Float64", 8, FLOAT},   {"Char", 1, SIGNED},     {"UChar", 1, UNSIGNED},
                 {"Int", 4, SIGNED},      {"Float", 4, FLOAT},     {"Double", 8, FLOAT}};
    for (const auto& x : table)
      if (t == x.name) {
        size = x.size;
        kind = x.kind;
        return true;
      }
    return false;
  }

  template <class T>
  void read_ascii(const Xml_element& e, std::size_t count, std::vector<T>& out) const {
    capped_reserve(out, count, doc_.text().size(), 2);
    for (const auto& part : e.text_parts) {
      std::size_t p = part.first;
      while (p < part.second) {
        while (p < part.second && is_space(doc_.text()[p])) ++p;
        const std::size_t b = p;
        while (p < part.second && !is_space(doc_.text()[p])) ++p;
        if (p == b) break;
        const std::string_view tok = doc_.text().substr(b, p - b);
        if (out.size() == count)
          throw Read_error(name_, doc_.line_of(b),
                           describe(e) + ": more values than the " + std::to_string(count) + " expected");
        T v{};
        const char* why;
        if constexpr (std::is_integral<T>::value) {
          long long x = 0;
          why = parse_integer(tok, x);
          v = x;
        } else {
          why = parse_double(tok, v);
        }
        if (why)
          throw Read_error(name_, doc_.line_of(b),
                           describe(e) + ": value " + std::to_string(out.size()) + " " + quote(tok) + " " +
                               why);
        out.push_back(v);
      }
    }
    if (out.size() != count)
      fail(e, describe(e) + ": " + std::to_string(out.size()) + " values, expected " + std::to_string(count));
  }

  std::uint64_t load(const unsigned char* p, std::size_t size) const {
    unsigned char b[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    for (std::size_t i = 0; i < size; ++i) b[i] = swap_ ? p[size - 1 - i] : p[i];
    switch (size) {
    case 1:
      return b[0];
    case 2: {
      std::uint16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case 4: {
      std::uint32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    default: {
      std::uint64_t v;
      std::memcpy(&v, b, 8);
      return v;
    }
    }
  }

  // From a base64 decoder when `raw == nullptr`, else from raw bytes.
  template <class T>
  void read_binary(const Xml_element& e, std::size_t count, std::size_t size, Kind kind,
                   const std::string& type, Base64_decoder& dec, const char* raw, std::size_t raw_size,
                   std::vector<T>& out) const {
    std::size_t pos = 0;
    const auto get = [&](unsigned char* dst, std::size_t n, const char* what) {
      if (raw != nullptr) {
        if (raw_size - pos < n)
          fail(e, describe(e) + ": the appended data ends before the " + std::string(what) + " (" +
                      std::to_string(n) + " bytes needed, " + std::to_string(raw_size - pos) + " left)");
        std::memcpy(dst, raw + pos, n);
        pos += n;
      } else if (!dec.read(dst, n)) {
        fail(e, describe(e) + ": cannot decode the " + std::string(what) + ": " + dec.error());
      }
    };
    unsigned char h[8];
    get(h, header_size_, "header");
    const std::uint64_t nbytes = load(h, header_size_);
    if (count > std::numeric_limits<std::size_t>::max() / 8 ||
        nbytes != static_cast<std::uint64_t>(count) * size)
      fail(e, describe(e) + ": the binary block holds " + std::to_string(nbytes) + " bytes, expected " +
                  std::to_string(count) + " values of type " + type + " (" + std::to_string(count * size) +
                  " bytes)");
    const std::size_t available = raw != nullptr ? raw_size - pos : dec.max_remaining_bytes();
    if (nbytes > available)
      fail(e, describe(e) + ": the binary data is truncated (" + std::to_string(nbytes) +
                  " bytes announced, at most " + std::to_string(available) + " present)");
    out.reserve(count);
    unsigned char buf[4096];
    std::size_t done = 0;
    while (done < count) {
      const std::size_t chunk = std::min<std::size_t>(count - done, sizeof(buf) / size);
      get(buf, chunk * size, "data");
      for (std::size_t i = 0; i < chunk; ++i) {
        const std::uint64_t bits = load(buf + i * size, size);
        const std::size_t index = done + i;
        if constexpr (std::is_integral<T>::value) {
          if (kind == UNSIGNED) {
            if (bits > static_cast<std::uint64_t>(std::numeric_limits<long long>::max()))
              fail(e, describe(e) + ": value " + std::to_string(index) + " is too large");
            out.push_back(static_cast<long long>(bits));
          } else {
            out.push_back(sign_extend(bits, size));
          }
        } else {
          double v;
          if (kind == FLOAT) {
            if (size == 4) {
              const std::uint32_t b32 = static_cast<std::uint32_t>(bits);
              float f;
              std::memcpy(&f, &b32, 4);
              v = f;
            } else {
              std::memcpy(&v, &bits, 8);
            }
            if (!std::isfinite(v))
              fail(e, describe(e) + ": value " + std::to_string(index) + " is not finite");
          } else if (kind == UNSIGNED) {
            v = static_cast<double>(bits);
          } else {
            v = static_cast<double>(sign_extend(bits, size));
          }
          out.push_back(v);
        }
      }
      done += chunk;
    }
  }

  static long long sign_extend(std::uint64_t bits, std::size_t size) {
    if (size == 8) return static_cast<long long>(bits);
    const std::uint64_t sign = std::uint64_t(1) << (8 * size - 1);
    const std::uint64_t mask = (std::uint64_t(1) << (8 * size)) - 1;
    bits &= mask;
    return (bits & sign) ? static_cast<long long>(bits) - static_cast<long long>(mask) - 1
                         : static_cast<long long>(bits);
  }

  const Xml_document& doc_;
  const std::string& name_;
  bool swap_ = false;
  std::size_t header_size_ = 4;
  std::string compressor_;
  bool appended_base64_ = false;
};

inline std::vector<const Xml_element*> xml_children(const Xml_document& doc, const Xml_element& e,
                                                    std::string_view name) {
  std::vector<const Xml_element*> r;
  for (std::size_t c : e.children)
    if (doc.element(c).name == name) r.push_back(&doc.element(c));
  return r;
}

template <class Mesh>
void read_vtu_text(std::string_view text, const std::string& name, Mesh& result) {
  using Point_3 = typename Mesh::Point_3;
  using Index = typename Mesh::Index;
  const Xml_document doc(text, name);
  const Xml_element& root = doc.root();
  const auto fail = [&](const Xml_element& e, const std::string& m) { throw Read_error(name, e.line, m); };
  if (root.name != "VTKFile")
    fail(root, "not a VTK XML file: the root element is <" + std::string(root.name) + ">");
  const std::string* type = root.attribute("type");
  if (type == nullptr) fail(root, "<VTKFile> without a type attribute");
  if (*type != "UnstructuredGrid")
    fail(root, "VTKFile type '" + *type + "' is not supported (only UnstructuredGrid)");
  const Vtu_array_reader arrays(doc, name);
  const std::vector<const Xml_element*> grids = xml_children(doc, root, "UnstructuredGrid");
  if (grids.size() != 1)
    fail(root, "expected one <UnstructuredGrid> element, found " + std::to_string(grids.size()));
  const std::vector<const Xml_element*> pieces = xml_children(doc, *grids[0], "Piece");
  if (pieces.empty()) fail(*grids[0], "no <Piece> in <UnstructuredGrid>");

  Mesh mesh;
  bool labels_everywhere = true;
  for (std::size_t pi = 0; pi < pieces.size(); ++pi) {
    const Xml_element& piece = *pieces[pi];
    const auto count_attribute = [&](const char* key) {
      const std::string* v = piece.attribute(key);
      if (v == nullptr) fail(piece, std::string("<Piece> without ") + key);
      long long n = 0;
      if (parse_integer(*v, n) != nullptr || n < 0 ||
          static_cast<unsigned long long>(n) > std::numeric_limits<std::size_t>::max() / 64)
        fail(piece, std::string("invalid ") + key + " '" + *v + "'");
      return static_cast<std::size_t>(n);
    };
    const std::size_t nv = count_attribute("NumberOfPoints");
    const std::size_t nc = count_attribute("NumberOfCells");
    const std::size_t vertex_offset = mesh.points.size();
    if (static_cast<unsigned long long>(vertex_offset) + nv > max_vertices<Index>())
      fail(piece, "the points do not fit in the index type of the mesh");
    const auto single = [&](const Xml_element& parent, std::string_view child) -> const Xml_element* {
      const std::vector<const Xml_element*> c = xml_children(doc, parent, child);
      if (c.size() > 1)
        fail(parent, "more than one <" + std::string(child) + "> in <" + std::string(parent.name) + ">");
      return c.empty() ? nullptr : c.front();
    };
    const auto components = [&](const Xml_element& a) {
      const std::string* c = a.attribute("NumberOfComponents");
      if (c == nullptr) return std::size_t(1);
      long long n = 0;
      if (parse_integer(*c, n) != nullptr || n < 1 || n > 1000)
        fail(a, Vtu_array_reader::describe(a) + ": invalid NumberOfComponents '" + *c + "'");
      return static_cast<std::size_t>(n);
    };

    // points
    const Xml_element* points = single(piece, "Points");
    if (points == nullptr && nv > 0) fail(piece, "<Piece> without <Points>");
    if (points != nullptr) {
      const std::vector<const Xml_element*> da = xml_children(doc, *points, "DataArray");
      if (da.size() != 1)
        fail(*points, "<Points> must hold one DataArray, found " + std::to_string(da.size()));
      if (components(*da[0]) != 3) fail(*da[0], "the points DataArray must have NumberOfComponents=\"3\"");
      std::vector<double> xyz;
      arrays.read(*da[0], 3 * nv, xyz);
      mesh.points.reserve(mesh.points.size() + nv);
      for (std::size_t i = 0; i < nv; ++i)
        mesh.points.push_back(Point_3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]));
    }

    // cells
    const Xml_element* cells = single(piece, "Cells");
    if (cells == nullptr && nc > 0) fail(piece, "<Piece> without <Cells>");
    if (cells != nullptr) {
      const Xml_element *conn = nullptr, *offs = nullptr, *types = nullptr;
      for (const Xml_element* a : xml_children(doc, *cells, "DataArray")) {
        const std::string* n = a->attribute("Name");
        if (n == nullptr) continue;
        const Xml_element** slot = *n == "connectivity" ? &conn
                                   : *n == "offsets"    ? &offs
                                   : *n == "types"      ? &types
                                                        : nullptr;
        if (slot == nullptr) continue; // faces, faceoffsets: only for polyhedra, rejected by their type
        if (*slot != nullptr) fail(*a, "duplicate DataArray '" + *n + "' in <Cells>");
        *slot = a;
      }
      if (offs == nullptr) fail(*cells, "<Cells> without the DataArray 'offsets'");
      if (types == nullptr) fail(*cells, "<Cells> without the DataArray 'types'");
      if (conn == nullptr) fail(*cells, "<Cells> without the DataArray 'connectivity'");
      std::vector<long long> offsets, type_values, connectivity;
      arrays.read(*types, nc, type_values);
      arrays.read(*offs, nc, offsets);
      // the connectivity size is the last offset (checked to be sensible against the text size)
      const long long last = nc == 0 ? 0 : offsets.back();
      if (last < 0 || static_cast<unsigned long long>(last) > text.size())
        fail(*offs, "invalid last cell offset " + std::to_string(last));
      // cell types first: a non-tetrahedral mesh is reported as such
      for (std::size_t i = 0; i < nc; ++i)
        if (type_values[i] != 10)
          fail(*types, "cell " + std::to_string(i) + " has VTK type " + std::to_string(type_values[i]) +
                           " (" + vtk_cell_type_name(type_values[i]) +
                           "): only tetrahedra (type 10) are supported");
      arrays.read(*conn, static_cast<std::size_t>(last), connectivity);
      std::vector<long long> starts;
      starts.reserve(nc + 1);
      starts.push_back(0);
      starts.insert(starts.end(), offsets.begin(), offsets.end());
      mesh.tetrahedra.reserve(mesh.tetrahedra.size() + nc);
      vtk_cells_to_tetrahedra(starts, connectivity, type_values, nv, vertex_offset, mesh.tetrahedra,
                              [&](const std::string& m) { fail(*cells, "<Cells>: " + m); });
    }

    // point data
    std::size_t k = 0;
    if (const Xml_element* pd = single(piece, "PointData")) {
      for (const Xml_element* a : xml_children(doc, *pd, "DataArray")) {
        if (components(*a) != 1) continue; // vectors, tensors: not scalar fields
        const std::string* n = a->attribute("Name");
        const std::string array_name = n ? *n : "point_data_" + std::to_string(k);
        if (pi == 0) {
          for (const auto& existing : mesh.point_data)
            if (existing.name == array_name) fail(*a, "duplicate point data array '" + array_name + "'");
          mesh.point_data.push_back(Point_data_array{array_name, {}});
        } else if (k >= mesh.point_data.size() || mesh.point_data[k].name != array_name) {
          fail(*a, "the point data of piece " + std::to_string(pi) + " differ from those of the first piece");
        }
        std::vector<double> values;
        arrays.read(*a, nv, values);
        auto& dst = mesh.point_data[k].values;
        dst.insert(dst.end(), values.begin(), values.end());
        ++k;
      }
    }
    if (pi > 0 && k != mesh.point_data.size())
      fail(piece, "the point data of piece " + std::to_string(pi) + " differ from those of the first piece");

    // labels
    bool has_labels = false;
    if (const Xml_element* cd = single(piece, "CellData")) {
      for (const Xml_element* a : xml_children(doc, *cd, "DataArray")) {
        const std::string* n = a->attribute("Name");
        if (n == nullptr || !is_vtk_label_array_name(*n) || components(*a) != 1) continue;
        std::vector<double> values;
        arrays.read(*a, nc, values);
        vtk_labels_to_int(values, mesh.tetrahedron_labels, [&](const std::string& m) { fail(*a, m); });
        has_labels = true;
        break;
      }
    }
    if (!has_labels) labels_everywhere = false;
  }
  if (!labels_everywhere) mesh.tetrahedron_labels.clear();
  result = std::move(mesh);
}

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTU_READER_H
