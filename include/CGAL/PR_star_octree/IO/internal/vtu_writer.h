// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTU_WRITER_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTU_WRITER_H

// The VTK XML UnstructuredGrid (.vtu) writer: escaping and data arrays.

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/internal/decompress.h>
#include <CGAL/PR_star_octree/IO/internal/file_bytes.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {

/// Writes one ascii DataArray: `get(i)` gives value `i` (of `count`) as `T`.
template <class T, class Get>
void vtu_write_ascii_array(std::ostream& out, std::string& buf, const std::string& file, const char* vtk_type,
                           const std::string& array_name, std::size_t components, std::size_t count,
                           const Get& get) {
  buf += "        <DataArray type=\"";
  buf += vtk_type;
  buf += '"';
  if (!array_name.empty()) {
    buf += " Name=\"";
    xml_escape(buf, array_name);
    buf += '"';
  }
  if (components != 1) {
    buf += " NumberOfComponents=\"";
    append_integer(buf, components);
    buf += '"';
  }
  buf += " format=\"ascii\">\n";
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
  buf += "        </DataArray>\n";
  flush_buffer(out, buf, file);
}

/// The appended form (as ParaView writes): `header_type="UInt64"`, raw binary data, each array
/// in blocks of 32 KiB compressed by zlib (`vtkZLibDataCompressor`) when `zlib`, else in one piece.
class Vtu_appended_arrays {
public:
  static constexpr std::size_t block_size = 32768;

  Vtu_appended_arrays(bool zlib, int level) : zlib_(zlib), level_(level) {}

  bool compressed() const { return zlib_; }

  /// Adds one array (`get(i)` is value `i`, of `count`, as `T`); returns its offset.
  template <class T, class Get>
  std::size_t add(std::size_t count, const Get& get, const std::string& file) {
    (void)file; // for the error message of a failed compression
    const std::size_t offset = data_.size();
    const std::uint64_t nbytes = static_cast<std::uint64_t>(count) * sizeof(T);
    const bool swap = !host_is_little_endian();
    std::string raw;
    raw.reserve(compressed() ? block_size : static_cast<std::size_t>(nbytes));
    const auto put_word = [&](std::string& dst, std::uint64_t w) {
      unsigned char b[8];
      for (int i = 0; i < 8; ++i) b[i] = static_cast<unsigned char>(w >> (8 * i)); // little-endian
      dst.append(reinterpret_cast<const char*>(b), 8);
    };
    if (!compressed()) {
      put_word(data_, nbytes);
      for (std::size_t i = 0; i < count; ++i) append_value(data_, get(i), swap);
      return offset;
    }
#ifndef CGAL_PR_STAR_OCTREE_HAS_ZLIB
    throw Write_error(file,
                      "zlib compression is not available: zlib was not found when this program was built");
#else
    const std::size_t nb = static_cast<std::size_t>((nbytes + block_size - 1) / block_size);
    std::string blocks;
    std::vector<std::uint64_t> sizes;
    sizes.reserve(nb);
    std::size_t i = 0;
    const std::size_t per_block = block_size / sizeof(T);
    static_assert(block_size % 8 == 0, "whole values per block");
    while (i < count) {
      raw.clear();
      const std::size_t end = std::min(count, i + per_block);
      for (; i < end; ++i) append_value(raw, get(i), swap);
      const std::size_t before = blocks.size();
      if (!zlib_compress_append(reinterpret_cast<const unsigned char*>(raw.data()), raw.size(), level_,
                                blocks))
        throw Write_error(file, "zlib compression failed");
      sizes.push_back(blocks.size() - before);
    }
    put_word(data_, sizes.size());
    put_word(data_, block_size);
    put_word(data_, nbytes % block_size);
    for (std::uint64_t c : sizes) put_word(data_, c);
    data_ += blocks;
#endif
    return offset;
  }

  const std::string& data() const {
    return data_;
  }

private:
  template <class T>
  static void append_value(std::string& dst, T v, bool swap) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (swap)
      for (std::size_t k = 0; k < sizeof(T) / 2; ++k) std::swap(b[k], b[sizeof(T) - 1 - k]);
    dst.append(reinterpret_cast<const char*>(b), sizeof(T));
  }

  bool zlib_;
  int level_;
  std::string data_;
};

/// Writes the DataArray elements, ascii or appended (the appended data at the end).
class Vtu_array_writer {
public:
  Vtu_array_writer(std::ostream& out, std::string& buf, const std::string& file, bool binary, bool zlib,
                   int level = 1)
      : out_(out), buf_(buf), file_(file), binary_(binary), appended_(zlib, level) {}

  template <class T, class Get>
  void write(const char* vtk_type, const std::string& array_name, std::size_t components, std::size_t count,
             const Get& get) {
    if (!binary_) {
      vtu_write_ascii_array<T>(out_, buf_, file_, vtk_type, array_name, components, count, get);
      return;
    }
    const std::size_t offset = appended_.add<T>(count, get, file_);
    buf_ += "        <DataArray type=\"";
    buf_ += vtk_type;
    buf_ += '"';
    if (!array_name.empty()) {
      buf_ += " Name=\"";
      xml_escape(buf_, array_name);
      buf_ += '"';
    }
    if (components != 1) {
      buf_ += " NumberOfComponents=\"";
      append_integer(buf_, components);
      buf_ += '"';
    }
    buf_ += " format=\"appended\" offset=\"";
    append_integer(buf_, offset);
    buf_ += "\"/>\n";
  }

  /// the `compressor` attribute of `<VTKFile>` (with its leading space), possibly empty
  const char* compressor_attribute() const {
    return binary_ && appended_.compressed() ? " compressor=\"vtkZLibDataCompressor\"" : "";
  }

  /// Writes what follows `</UnstructuredGrid>`: the appended data, if any.
  void finish() {
    if (!binary_) return;
    buf_ += "  <AppendedData encoding=\"raw\">\n   _";
    flush_buffer(out_, buf_, file_, true);
    const std::string& d = appended_.data();
    out_.write(d.data(), static_cast<std::streamsize>(d.size()));
    if (!out_) throw Write_error(file_, "error while writing");
    buf_ += "\n  </AppendedData>\n";
  }

private:
  std::ostream& out_;
  std::string& buf_;
  const std::string& file_;
  bool binary_;
  Vtu_appended_arrays appended_;
};

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTU_WRITER_H
