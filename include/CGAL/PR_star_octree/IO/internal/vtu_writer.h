// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTU_WRITER_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTU_WRITER_H

// The VTK XML UnstructuredGrid (.vtu) writer: escaping and data arrays.

#include <CGAL/PR_star_octree/IO/internal/base64.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {

inline void vtu_escape(std::string& out, const std::string& s) {
  for (char c : s) {
    switch (c) {
    case '&':
      out += "&amp;";
      break;
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '"':
      out += "&quot;";
      break;
    case '\'':
      out += "&apos;";
      break;
    default:
      out += c;
    }
  }
}

/// Writes one DataArray: `get(i)` gives value `i` (of `count`) as `T`.
template <class T, class Get>
void vtu_write_array(std::ostream& out, std::string& buf, const std::string& file, const char* vtk_type,
                     const std::string& array_name, std::size_t components, std::size_t count, bool binary,
                     const Get& get) {
  buf += "        <DataArray type=\"";
  buf += vtk_type;
  buf += '"';
  if (!array_name.empty()) {
    buf += " Name=\"";
    vtu_escape(buf, array_name);
    buf += '"';
  }
  if (components != 1) {
    buf += " NumberOfComponents=\"";
    append_integer(buf, components);
    buf += '"';
  }
  buf += binary ? " format=\"binary\">\n" : " format=\"ascii\">\n";
  if (binary) {
    Base64_encoder enc(buf);
    const bool swap = !host_is_little_endian();
    const auto put = [&](const void* p, std::size_t n) {
      unsigned char b[8];
      std::memcpy(b, p, n);
      if (swap)
        for (std::size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
      enc.write(b, n);
    };
    const std::uint64_t nbytes = static_cast<std::uint64_t>(count) * sizeof(T);
    put(&nbytes, 8);
    for (std::size_t i = 0; i < count; ++i) {
      const T v = get(i);
      put(&v, sizeof(T));
      flush_buffer(out, buf, file);
    }
    enc.finish();
    buf += '\n';
  } else {
    const std::size_t per_line = components == 1 ? 6 : components;
    for (std::size_t i = 0; i < count; ++i) {
      if constexpr (std::is_floating_point<T>::value) {
        append_double(buf, get(i));
      } else {
        append_integer(buf, get(i));
      }
      buf += ((i + 1) % per_line == 0 || i + 1 == count) ? '\n' : ' ';
      flush_buffer(out, buf, file);
    }
  }
  buf += "        </DataArray>\n";
  flush_buffer(out, buf, file);
}

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTU_WRITER_H
