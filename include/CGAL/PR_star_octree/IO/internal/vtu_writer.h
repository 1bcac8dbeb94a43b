// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTU_WRITER_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTU_WRITER_H

// The VTK XML UnstructuredGrid (.vtu) writer: escaping and data arrays.

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/internal/base64.h>
#include <CGAL/PR_star_octree/IO/internal/decompress.h>
#include <CGAL/PR_star_octree/IO/internal/file_bytes.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>

#include <algorithm>
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
    if constexpr (std::is_same<T, float>::value) {
      append_float(buf, get(i)); // the shortest text that reads back as the same float
    } else if constexpr (std::is_floating_point<T>::value) {
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

/// Streams bytes as one base64 stream into `buf`, flushed to `out` every 64 KiB.
class Vtu_base64_stream {
public:
  Vtu_base64_stream(std::ostream& out, std::string& buf, const std::string& file)
      : out_(out), buf_(buf), file_(file), enc_(buf) {}
  void write(const char* bytes, std::size_t n) {
    constexpr std::size_t slice = std::size_t(3) << 14; // 48 KiB of bytes, 64 KiB of text
    for (std::size_t done = 0; done < n; done += slice) {
      enc_.write(reinterpret_cast<const unsigned char*>(bytes + done), std::min(slice, n - done));
      flush_buffer(out_, buf_, file_);
    }
  }
  void write_word(std::uint64_t w) { // little-endian
    char b[8];
    for (int i = 0; i < 8; ++i) b[i] = static_cast<char>(static_cast<unsigned char>(w >> (8 * i)));
    write(b, 8);
  }
  /// Pads the end of the stream (the next write starts a new stream).
  void finish() { enc_.finish(); }

private:
  std::ostream& out_;
  std::string& buf_;
  const std::string& file_;
  Base64_encoder enc_;
};

/// Appends value `v` to `dst` in little-endian byte order.
template <class T>
void vtu_append_little_endian(std::string& dst, T v) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if (!host_is_little_endian())
    for (std::size_t k = 0; k < sizeof(T) / 2; ++k) std::swap(b[k], b[sizeof(T) - 1 - k]);
  dst.append(reinterpret_cast<const char*>(b), sizeof(T));
}

/// Writes the DataArray elements, ascii or binary.  Binary data are written inline
/// (`format="binary"`), base64-encoded, with `UInt64` headers, as VTK's writers do in their binary
/// data mode: uncompressed, the byte count and the data as one base64 stream; compressed by zlib
/// (`vtkZLibDataCompressor`, blocks of 32 KiB), the block header as one stream and the compressed
/// blocks as another.  Not the appended form: VTK 9.1/9.2 (ParaView 5.11, Debian 12's VTK) read no
/// appended data, raw or base64, with the libexpat of Debian 12's current point releases (its
/// reparse deferral), while inline data are read by every VTK version.  Uncompressed data are
/// streamed; compressed ones are held in memory one array at a time.
class Vtu_array_writer {
public:
  static constexpr std::size_t block_size = 32768;

  Vtu_array_writer(std::ostream& out, std::string& buf, const std::string& file, bool binary, bool zlib,
                   int level = 1)
      : out_(out), buf_(buf), file_(file), binary_(binary), zlib_(zlib), level_(level) {}

  template <class T, class Get>
  void write(const char* vtk_type, const std::string& array_name, std::size_t components, std::size_t count,
             const Get& get) {
    if (!binary_) {
      vtu_write_ascii_array<T>(out_, buf_, file_, vtk_type, array_name, components, count, get);
      return;
    }
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
    buf_ += " format=\"binary\">\n          ";
    const std::uint64_t nbytes = static_cast<std::uint64_t>(count) * sizeof(T);
    Vtu_base64_stream stream(out_, buf_, file_);
    std::string raw;
    raw.reserve(block_size);
    const std::size_t per_block = block_size / sizeof(T);
    static_assert(block_size % 8 == 0, "whole values per block");
    if (!zlib_) {
      stream.write_word(nbytes);
      for (std::size_t i = 0; i < count;) {
        raw.clear();
        const std::size_t end = std::min(count, i + per_block);
        for (; i < end; ++i) vtu_append_little_endian<T>(raw, get(i));
        stream.write(raw.data(), raw.size());
      }
      stream.finish();
    } else {
#ifndef CGAL_PR_STAR_OCTREE_HAS_ZLIB
      throw Write_error(file_,
                        "zlib compression is not available: zlib was not found when this program was built");
#else
      std::string blocks;
      std::vector<std::uint64_t> sizes;
      sizes.reserve(static_cast<std::size_t>((nbytes + block_size - 1) / block_size));
      for (std::size_t i = 0; i < count;) {
        raw.clear();
        const std::size_t end = std::min(count, i + per_block);
        for (; i < end; ++i) vtu_append_little_endian<T>(raw, get(i));
        const std::size_t before = blocks.size();
        if (!zlib_compress_append(reinterpret_cast<const unsigned char*>(raw.data()), raw.size(), level_,
                                  blocks))
          throw Write_error(file_, "zlib compression failed");
        sizes.push_back(blocks.size() - before);
      }
      stream.write_word(sizes.size());
      stream.write_word(block_size);
      stream.write_word(nbytes % block_size);
      for (std::uint64_t c : sizes) stream.write_word(c);
      stream.finish();
      stream.write(blocks.data(), blocks.size());
      stream.finish();
#endif
    }
    buf_ += "\n        </DataArray>\n";
    flush_buffer(out_, buf_, file_);
  }

  /// the `compressor` attribute of `<VTKFile>` (with its leading space), possibly empty
  const char* compressor_attribute() const {
    return binary_ && zlib_ ? " compressor=\"vtkZLibDataCompressor\"" : "";
  }

private:
  std::ostream& out_;
  std::string& buf_;
  const std::string& file_;
  bool binary_, zlib_;
  int level_;
};

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTU_WRITER_H
