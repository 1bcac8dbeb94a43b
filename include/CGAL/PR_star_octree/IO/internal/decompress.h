// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_DECOMPRESS_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_DECOMPRESS_H

// Decompression (and zlib compression) of the data blocks of VTK XML files: vtkZLibDataCompressor
// (zlib stream), vtkLZ4DataCompressor (LZ4 block), vtkLZMADataCompressor (xz stream).  Each library
// is used only when the build found it (CGAL_PR_STAR_OCTREE_HAS_ZLIB, _LZ4, _LZMA, defined by the
// CMake target CGAL::PR_star_octree); otherwise `compressor_available()` is false and the reader
// refuses the compressor by name.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

#ifdef CGAL_PR_STAR_OCTREE_HAS_ZLIB
#include <zlib.h>
#endif
#ifdef CGAL_PR_STAR_OCTREE_HAS_LZ4
#include <lz4.h>
#endif
#ifdef CGAL_PR_STAR_OCTREE_HAS_LZMA
#include <lzma.h>
#endif

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {

enum class Vtk_compressor { NONE, ZLIB, LZ4, LZMA };

/// The compressor named by a VTK `compressor` attribute; false for an unknown name.
inline bool vtk_compressor_from_name(const std::string& name, Vtk_compressor& c) {
  if (name.empty())
    c = Vtk_compressor::NONE;
  else if (name == "vtkZLibDataCompressor")
    c = Vtk_compressor::ZLIB;
  else if (name == "vtkLZ4DataCompressor")
    c = Vtk_compressor::LZ4;
  else if (name == "vtkLZMADataCompressor")
    c = Vtk_compressor::LZMA;
  else
    return false;
  return true;
}

/// Whether this build can decompress `c` (the library was found).
inline bool compressor_available(Vtk_compressor c) {
  switch (c) {
  case Vtk_compressor::NONE:
    return true;
  case Vtk_compressor::ZLIB:
#ifdef CGAL_PR_STAR_OCTREE_HAS_ZLIB
    return true;
#else
    return false;
#endif
  case Vtk_compressor::LZ4:
#ifdef CGAL_PR_STAR_OCTREE_HAS_LZ4
    return true;
#else
    return false;
#endif
  case Vtk_compressor::LZMA:
#ifdef CGAL_PR_STAR_OCTREE_HAS_LZMA
    return true;
#else
    return false;
#endif
  }
  return false;
}

inline const char* compressor_library(Vtk_compressor c) {
  return c == Vtk_compressor::ZLIB   ? "zlib"
         : c == Vtk_compressor::LZ4  ? "liblz4"
         : c == Vtk_compressor::LZMA ? "liblzma"
                                     : "none";
}

/// The largest ratio of decompressed to compressed size a sane block can have: 1032 is the
/// theoretical bound of deflate, LZ4 cannot exceed 255; for xz (no tight bound) 8192 is far above
/// what real data reaches with VTK's block sizes.  A block announcing more is refused (bomb).
inline std::uint64_t max_compression_ratio(Vtk_compressor c) {
  switch (c) {
  case Vtk_compressor::ZLIB:
    return 1032;
  case Vtk_compressor::LZ4:
    return 256;
  case Vtk_compressor::LZMA:
    return 8192;
  default:
    return 1;
  }
}

/// Decompresses `src[0..n)` into exactly `expected` bytes at `dst`; returns nullptr on success,
/// else what went wrong (`why` may receive the library's message).
inline const char* decompress_block(Vtk_compressor c, const unsigned char* src, std::size_t n,
                                    unsigned char* dst, std::size_t expected, std::string& why) {
  (void)src;
  (void)n;
  (void)dst;
  (void)expected;
  why.clear();
  switch (c) {
  case Vtk_compressor::ZLIB: {
#ifdef CGAL_PR_STAR_OCTREE_HAS_ZLIB
    z_stream z{};
    if (inflateInit(&z) != Z_OK) return "cannot initialise zlib";
    z.next_in = const_cast<Bytef*>(reinterpret_cast<const Bytef*>(src));
    z.next_out = reinterpret_cast<Bytef*>(dst);
    std::size_t in_left = n, out_left = expected;
    const char* result = nullptr;
    for (;;) {
      // fed in uInt-sized pieces (a block may in principle exceed 4 GB)
      if (z.avail_in == 0 && in_left > 0) {
        z.avail_in = static_cast<uInt>(std::min<std::size_t>(in_left, std::size_t(1) << 30));
        in_left -= z.avail_in;
      }
      if (z.avail_out == 0 && out_left > 0) {
        z.avail_out = static_cast<uInt>(std::min<std::size_t>(out_left, std::size_t(1) << 30));
        out_left -= z.avail_out;
      }
      const int r = inflate(&z, Z_NO_FLUSH);
      if (r == Z_OK) continue;
      if (r == Z_STREAM_END) {
        if (z.avail_out != 0 || out_left != 0)
          result = "the zlib stream decompresses to fewer bytes than announced";
      } else if (r == Z_BUF_ERROR) {
        result = (z.avail_out == 0 && out_left == 0)
                     ? "the zlib stream decompresses to more bytes than announced"
                     : "truncated zlib stream";
      } else if (r == Z_MEM_ERROR) {
        result = "zlib is out of memory";
      } else {
        result = "corrupt zlib stream";
        if (z.msg != nullptr) why = z.msg;
      }
      break;
    }
    inflateEnd(&z);
    return result;
#else
    return "zlib support was not built (zlib not found)";
#endif
  }
  case Vtk_compressor::LZ4: {
#ifdef CGAL_PR_STAR_OCTREE_HAS_LZ4
    if (n > static_cast<std::size_t>(LZ4_MAX_INPUT_SIZE) || expected > 0x7fffffffu)
      return "LZ4 block too large";
    const int r = LZ4_decompress_safe(reinterpret_cast<const char*>(src), reinterpret_cast<char*>(dst),
                                      static_cast<int>(n), static_cast<int>(expected));
    if (r < 0) return "corrupt or truncated LZ4 block (or larger than announced)";
    if (static_cast<std::size_t>(r) != expected)
      return "the LZ4 block decompresses to fewer bytes than announced";
    return nullptr;
#else
    return "LZ4 support was not built (liblz4 not found)";
#endif
  }
  case Vtk_compressor::LZMA: {
#ifdef CGAL_PR_STAR_OCTREE_HAS_LZMA
    std::uint64_t memlimit = std::uint64_t(1) << 30; // dictionary of at most 1 GB
    std::size_t in_pos = 0, out_pos = 0;
    const lzma_ret r =
        lzma_stream_buffer_decode(&memlimit, 0, nullptr, src, &in_pos, n, dst, &out_pos, expected);
    if (r == LZMA_OK) {
      if (out_pos != expected || in_pos != n) return "the xz stream does not have the announced size";
      return nullptr;
    }
    if (r == LZMA_BUF_ERROR)
      return out_pos == expected ? "the xz stream decompresses to more bytes than announced"
                                 : "truncated xz stream";
    if (r == LZMA_MEMLIMIT_ERROR) return "the xz stream needs more than 1 GB of memory";
    if (r == LZMA_FORMAT_ERROR) return "not an xz stream";
    return "corrupt xz stream";
#else
    return "LZMA support was not built (liblzma not found)";
#endif
  }
  default:
    return "not compressed";
  }
}

#ifdef CGAL_PR_STAR_OCTREE_HAS_ZLIB
/// zlib-compresses `src[0..n)` and appends the result to `out`; returns false on failure.
inline bool zlib_compress_append(const unsigned char* src, std::size_t n, int level, std::string& out) {
  uLongf size = compressBound(static_cast<uLong>(n));
  const std::size_t old = out.size();
  out.resize(old + size);
  if (compress2(reinterpret_cast<Bytef*>(&out[old]), &size, reinterpret_cast<const Bytef*>(src),
                static_cast<uLong>(n), level) != Z_OK) {
    out.resize(old);
    return false;
  }
  out.resize(old + size);
  return true;
}
#endif

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_DECOMPRESS_H
