// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTU_READER_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTU_READER_H

// The VTK XML UnstructuredGrid (.vtu) reader: data arrays (ascii, base64 binary, appended raw and base64) and
// the mesh.

#include <CGAL/PR_star_octree/IO/Memory_limit.h>
#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/internal/base64.h>
#include <CGAL/PR_star_octree/IO/internal/decompress.h>
#include <CGAL/PR_star_octree/IO/internal/file_bytes.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>
#include <CGAL/PR_star_octree/IO/internal/vtk_cells.h>
#include <CGAL/PR_star_octree/IO/internal/xml.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <istream>
#include <limits>
#include <map>
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

/// A sequential source of bytes: raw bytes of the file (appended raw data, read by the readers'
/// `Byte_cursor`) or base64 text.
class Vtu_byte_source {
public:
  /// raw bytes `data[0..size)`, at byte `file_offset` of the file
  Vtu_byte_source(const char* data, std::size_t size, std::size_t file_offset)
      : raw_(std::string_view(data, size), std::string()), is_raw_(true), base_(file_offset),
        dec_(std::string_view()), released_(data) {}
  /// base64 text at byte `file_offset` of the file (when it is one piece of the file)
  Vtu_byte_source(std::string_view base64, std::size_t file_offset)
      : raw_(std::string_view(), std::string()), base_(file_offset), dec_(base64), released_(base64.data()) {}

  bool is_raw() const { return is_raw_; }

  /// Fills `dst[0..n)`; false when the data end first or are not valid base64 (see `error()`).
  bool read(unsigned char* dst, std::size_t n) {
    release_consumed();
    if (is_raw_) {
      if (raw_.remaining() < n) return false;
      std::memcpy(dst, raw_.here(), n);
      raw_.skip(n, "data");
      return true;
    }
    return dec_.read(dst, n);
  }

  /// The next `n` bytes, in place for raw data, decoded into `storage` for base64; nullptr when
  /// they are not there.
  const unsigned char* take(std::size_t n, std::vector<unsigned char>& storage) {
    release_consumed(); // what earlier calls returned has been used
    if (is_raw_) {
      if (raw_.remaining() < n) return nullptr;
      const unsigned char* p = reinterpret_cast<const unsigned char*>(raw_.here());
      raw_.skip(n, "data");
      return p;
    }
    storage.resize(n);
    return dec_.read(storage.data(), n) ? storage.data() : nullptr;
  }

  /// An upper bound of the number of bytes that can still be read.
  std::size_t max_remaining() const { return is_raw_ ? raw_.remaining() : dec_.max_remaining_bytes(); }

  /// The byte offset in the file of the next byte (of its base64 text when encoded).
  std::size_t file_offset() const { return is_raw_ ? base_ + raw_.offset() : base_; }

  std::string error() const {
    if (is_raw_) return "the data end too early";
    return dec_.error() ? dec_.error() : "invalid base64 data";
  }

private:
  // The file bytes read so far leave the resident memory every 32 MB (a mapped file only: see
  // `release_file_pages()`), so that reading a file of gigabytes does not hold it all.
  void release_consumed() {
    const char* now = is_raw_ ? raw_.here() : dec_.position();
    if (now - released_ >= (std::ptrdiff_t(1) << 25)) {
      release_file_pages(released_, now);
      released_ = now;
    }
  }

  Byte_cursor raw_;
  bool is_raw_ = false;
  std::size_t base_ = 0;
  Base64_decoder dec_;
  const char* released_;
};

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
    if (const std::string* c = root.attribute("compressor")) {
      compressor_name_ = *c;
      if (!vtk_compressor_from_name(*c, compressor_))
        fail(root, "unknown compressor '" + *c +
                       "' (vtkZLibDataCompressor, vtkLZ4DataCompressor or vtkLZMADataCompressor)");
    }
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
    out.clear();
    Vector_sink<T> sink{out};
    read_into<T>(e, count, sink);
  }

  /// Appends to a vector.
  template <class T>
  struct Vector_sink {
    std::vector<T>& out;
    void reserve(std::size_t n) { out.reserve(out.size() + n); }
    void operator()(const T* v, std::size_t n) { out.insert(out.end(), v, v + n); }
  };

  /// Reads the `count` values of a DataArray as `T` (`double` or `long long`) and hands them to
  /// `sink` in order, in chunks: `sink.reserve(count)` once the data were found to hold them, then
  /// `sink(values, n)` for each chunk.
  template <class T, class Sink>
  void read_into(const Xml_element& e, std::size_t count, Sink& sink) const {
    const std::string* type = e.attribute("type");
    if (type == nullptr) fail(e, describe(e) + " without a type attribute");
    std::size_t size = 0;
    Kind kind = SIGNED;
    if (!type_info(*type, size, kind)) fail(e, describe(e) + ": unknown type '" + *type + "'");
    if (std::is_integral<T>::value && kind == FLOAT)
      fail(e, describe(e) + " has type " + *type + " but must have an integer type");
    const std::string* format = e.attribute("format");
    const std::string fmt = format ? *format : std::string("ascii");
    if (fmt == "ascii") {
      std::vector<T> out;
      read_ascii(e, count, out);
      sink.reserve(count);
      sink(out.data(), out.size());
    } else if (fmt == "binary" || fmt == "appended") {
      if (!compressor_available(compressor_))
        fail(e, describe(e) + ": compressed data (compressor=\"" + compressor_name_ + "\") cannot be read: " +
                    compressor_library(compressor_) + " was not found when this program was built");
      if (fmt == "binary") {
        if (e.text_parts.size() > 1) {
          std::string storage;
          Vtu_byte_source src(doc_.element_text(e, storage), e.text_parts.front().first);
          read_binary<T>(e, count, size, kind, *type, src, sink);
        } else {
          const std::size_t begin = e.text_parts.empty() ? 0 : e.text_parts[0].first;
          const std::size_t end = e.text_parts.empty() ? 0 : e.text_parts[0].second;
          Vtu_byte_source src(doc_.text().substr(begin, end - begin), begin);
          read_binary<T>(e, count, size, kind, *type, src, sink);
        }
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
        const std::size_t file_offset = static_cast<std::size_t>(block.data() - doc_.text().data());
        if (appended_base64_) {
          Vtu_byte_source src(block, file_offset);
          read_binary<T>(e, count, size, kind, *type, src, sink);
        } else {
          Vtu_byte_source src(block.data(), block.size(), file_offset);
          read_binary<T>(e, count, size, kind, *type, src, sink);
        }
      }
    } else {
      fail(e, describe(e) + ": unknown format '" + fmt + "' (ascii, binary or appended)");
    }
  }

  Vtk_compressor compressor() const { return compressor_; }

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
    advise_huge_pages(out.data(), out.capacity() * sizeof(T));
    const char* const text = doc_.text().data();
    for (const auto& part : e.text_parts) {
      std::size_t p = part.first;
      while (p < part.second) {
        while (p < part.second && is_space(text[p])) ++p;
        if (p < part.second && out.size() < count) { // fast path: a plain number
          T v{};
          const char* end = nullptr;
          if constexpr (std::is_integral<T>::value) {
            long long x = 0;
            end = scan_plain_integer(text + p, text + part.second, x, 0);
            v = static_cast<T>(x);
          } else {
            end = scan_plain_double(text + p, text + part.second, v, 0);
          }
          if (end != nullptr) {
            out.push_back(v);
            p = static_cast<std::size_t>(end - text);
            continue;
          }
        }
        const std::size_t b = p;
        while (p < part.second && !is_space(text[p])) ++p;
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

  /// The decompressed bytes of a compressed array, block by block (each block decompressed once,
  /// into a buffer of its announced size, which was bounded before).
  struct Block_stream {
    Vtk_compressor compressor;
    Vtu_byte_source* src;
    std::vector<std::uint64_t> compressed_sizes;
    std::uint64_t block_size = 0, last_block_size = 0;
    std::size_t next_block = 0;
    std::vector<unsigned char> block, storage;
    std::size_t block_pos = 0;
    std::string error;

    std::size_t uncompressed_size(std::size_t i) const {
      return static_cast<std::size_t>(
          i + 1 == compressed_sizes.size() && last_block_size != 0 ? last_block_size : block_size);
    }
    bool read(unsigned char* dst, std::size_t n) {
      while (n > 0) {
        if (block_pos == block.size()) {
          if (next_block == compressed_sizes.size()) {
            error = "the compressed blocks hold fewer bytes than announced";
            return false;
          }
          const std::size_t i = next_block++;
          const std::size_t at = src->file_offset();
          const unsigned char* c = src->take(static_cast<std::size_t>(compressed_sizes[i]), storage);
          if (c == nullptr) {
            error = "compressed block " + std::to_string(i) + " of " +
                    std::to_string(compressed_sizes.size()) + " (at byte " + std::to_string(at) +
                    "): " + src->error();
            return false;
          }
          block.resize(uncompressed_size(i));
          block_pos = 0;
          std::string why;
          if (const char* m = decompress_block(compressor, c, static_cast<std::size_t>(compressed_sizes[i]),
                                               block.data(), block.size(), why)) {
            error = "compressed block " + std::to_string(i) + " of " +
                    std::to_string(compressed_sizes.size()) + " (at byte " + std::to_string(at) + "): " + m +
                    (why.empty() ? "" : " (" + why + ")");
            return false;
          }
        }
        const std::size_t k = std::min(n, block.size() - block_pos);
        std::memcpy(dst, block.data() + block_pos, k);
        dst += k;
        n -= k;
        block_pos += k;
      }
      return true;
    }
  };

  /// `n` values stored as the unsigned integer type `U` of the size of the file's type, to `T`.
  template <class U, class T>
  void convert_as(const unsigned char* buf, std::size_t n, Kind kind, std::size_t done, const Xml_element& e,
                  T* dst) const {
    for (std::size_t i = 0; i < n; ++i) {
      U u;
      std::memcpy(&u, buf + i * sizeof(U), sizeof(U));
      if (swap_) {
        unsigned char b[sizeof(U)];
        std::memcpy(b, &u, sizeof(U));
        for (std::size_t k = 0; k < sizeof(U) / 2; ++k) std::swap(b[k], b[sizeof(U) - 1 - k]);
        std::memcpy(&u, b, sizeof(U));
      }
      if (kind == FLOAT) {
        if constexpr (sizeof(U) == 4 || sizeof(U) == 8) {
          using F = std::conditional_t<sizeof(U) == 4, float, double>;
          F f;
          std::memcpy(&f, &u, sizeof(U));
          dst[i] = static_cast<T>(f);
        }
      } else if (kind == SIGNED) {
        dst[i] = static_cast<T>(static_cast<std::make_signed_t<U>>(u));
      } else {
        if (sizeof(U) == 8 && u > static_cast<U>(std::numeric_limits<long long>::max()))
          fail(e, describe(e) + ": value " + std::to_string(done + i) + " is too large");
        dst[i] = static_cast<T>(u);
      }
    }
    if constexpr (std::is_floating_point<T>::value) {
      if (kind == FLOAT)
        for (std::size_t i = 0; i < n; ++i)
          if (!std::isfinite(dst[i]))
            fail(e, describe(e) + ": value " + std::to_string(done + i) + " is not finite");
    }
  }

  template <class T>
  void convert(const unsigned char* buf, std::size_t n, std::size_t size, Kind kind, std::size_t done,
               const Xml_element& e, T* dst) const {
    switch (size) {
    case 1:
      convert_as<std::uint8_t>(buf, n, kind, done, e, dst);
      break;
    case 2:
      convert_as<std::uint16_t>(buf, n, kind, done, e, dst);
      break;
    case 4:
      convert_as<std::uint32_t>(buf, n, kind, done, e, dst);
      break;
    default:
      convert_as<std::uint64_t>(buf, n, kind, done, e, dst);
    }
  }

  std::string at(const Vtu_byte_source& src) const {
    return " (at byte " + std::to_string(src.file_offset()) + " of the file)";
  }

  template <class T, class Sink>
  void read_binary(const Xml_element& e, std::size_t count, std::size_t size, Kind kind,
                   const std::string& type, Vtu_byte_source& src, Sink& sink) const {
    const auto word = [&](const char* what) {
      unsigned char h[8];
      const std::string where = at(src);
      if (!src.read(h, header_size_))
        fail(e, describe(e) + ": cannot read the " + std::string(what) + where + ": " + src.error());
      return load(h, header_size_);
    };
    if (count > std::numeric_limits<std::size_t>::max() / 8)
      fail(e, describe(e) + ": too many values (" + std::to_string(count) + ")");
    const std::uint64_t expected = static_cast<std::uint64_t>(count) * size;
    const auto wrong_size = [&](std::uint64_t nbytes, const char* what) {
      fail(e, describe(e) + ": " + what + " " + std::to_string(nbytes) + " bytes, expected " +
                  std::to_string(count) + " values of type " + type + " (" + std::to_string(expected) +
                  " bytes)");
    };
    Block_stream blocks{compressor_, &src, {}, 0, 0, 0, {}, {}, 0, {}};
    if (compressor_ == Vtk_compressor::NONE) {
      const std::uint64_t nbytes = word("header");
      if (nbytes != expected) wrong_size(nbytes, "the binary block holds");
      const std::size_t available = src.max_remaining();
      if (nbytes > available)
        fail(e, describe(e) + ": the binary data is truncated (" + std::to_string(nbytes) +
                    " bytes announced, at most " + std::to_string(available) + " present)" + at(src));
    } else {
      // header: number of blocks, uncompressed block size, size of the last partial block (0: full),
      // then the compressed size of each block
      const std::string header_at = at(src);
      const std::uint64_t nb = word("compression header (number of blocks)");
      const std::uint64_t bs = word("compression header (block size)");
      const std::uint64_t lbs = word("compression header (last block size)");
      const std::string where = describe(e) + ": compressed data" + header_at + ": ";
      if (nb > src.max_remaining() / header_size_)
        fail(e,
             where + std::to_string(nb) + " blocks announced, the file cannot hold their sizes (truncated?)");
      if (nb > 0 && bs == 0) fail(e, where + "the block size is 0 for " + std::to_string(nb) + " blocks");
      if (lbs > bs)
        fail(e, where + "the last block size " + std::to_string(lbs) + " exceeds the block size " +
                    std::to_string(bs));
      std::uint64_t total = 0;
      if (nb > 0) {
        if (bs > std::numeric_limits<std::uint64_t>::max() / nb)
          wrong_size(std::numeric_limits<std::uint64_t>::max(), "the compressed blocks announce more than");
        total = (nb - 1) * bs + (lbs != 0 ? lbs : bs);
      }
      if (total != expected) wrong_size(total, "the compressed blocks announce");
      blocks.block_size = bs;
      blocks.last_block_size = lbs;
      blocks.compressed_sizes.resize(static_cast<std::size_t>(nb));
      std::uint64_t sum = 0;
      for (std::size_t i = 0; i < nb; ++i) {
        const std::uint64_t c = word("compressed block sizes");
        blocks.compressed_sizes[i] = c;
        sum += std::min<std::uint64_t>(c, std::uint64_t(1) << 62);
        const std::uint64_t u = blocks.uncompressed_size(i);
        const std::uint64_t ratio = max_compression_ratio(compressor_);
        if (c == 0 && u > 0) fail(e, where + "block " + std::to_string(i) + " has a compressed size of 0");
        if (c < (std::uint64_t(1) << 40) && u > c * ratio + 64)
          fail(e, where + "block " + std::to_string(i) + " announces " + std::to_string(u) + " bytes from " +
                      std::to_string(c) + " compressed bytes, more than a ratio of " + std::to_string(ratio) +
                      ": refused (corrupt header or decompression bomb)");
      }
      if (sum > src.max_remaining())
        fail(e, where + "the compressed blocks are truncated (" + std::to_string(sum) +
                    " bytes announced, at most " + std::to_string(src.max_remaining()) + " present)");
    }
    const auto get = [&](unsigned char* dst, std::size_t n) {
      if (compressor_ == Vtk_compressor::NONE) {
        const std::string where = at(src);
        if (!src.read(dst, n)) fail(e, describe(e) + ": cannot read the data" + where + ": " + src.error());
      } else if (!blocks.read(dst, n)) {
        fail(e, describe(e) + ": " + blocks.error);
      }
    };
    sink.reserve(count);
    constexpr std::size_t chunk_values = 8192;
    std::vector<unsigned char> buf(chunk_values * size);
    std::vector<T> values(chunk_values);
    std::size_t done = 0;
    while (done < count) {
      const std::size_t chunk = std::min<std::size_t>(count - done, chunk_values);
      get(buf.data(), chunk * size);
      convert(buf.data(), chunk, size, kind, done, e, values.data());
      sink(values.data(), chunk);
      done += chunk;
    }
  }

  const Xml_document& doc_;
  const std::string& name_;
  bool swap_ = false;
  std::size_t header_size_ = 4;
  std::string compressor_name_;
  Vtk_compressor compressor_ = Vtk_compressor::NONE;
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
  // whether the points are 32-bit floats: every <Points> array of the pieces is Float32
  bool any_points = false, float32_points = true;
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
    // What the piece will hold (the cells counted as tetrahedra), checked against the memory
    // limit once its points were found in the file, before they are stored.
    const auto check_piece_memory = [&] {
      const auto arrays_of = [&](const char* data) {
        std::size_t n = 0;
        for (const Xml_element* d : xml_children(doc, piece, data))
          n += xml_children(doc, *d, "DataArray").size();
        return n;
      };
      check_memory(name, piece.line, vertex_offset + nv, mesh.tetrahedra.size() + nc, sizeof(Point_3),
                   sizeof(typename Mesh::Tetrahedron) + 1, arrays_of("PointData"), arrays_of("CellData"));
    };
    std::vector<char> kept; // which cells are tetrahedra (empty: all)
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
      const std::function<void()> check_points = check_piece_memory;
      struct Point_sink { // straight into the points, without an array of coordinates
        std::vector<Point_3>& points;
        double c[3];
        int k;
        const std::function<void()>& check;
        void reserve(std::size_t n) {
          check();
          points.reserve(points.size() + n / 3);
          advise_huge_pages(points.data() + points.size(),
                            (points.capacity() - points.size()) * sizeof(Point_3));
        }
        void operator()(const double* v, std::size_t n) {
          for (std::size_t i = 0; i < n; ++i) {
            c[k++] = v[i];
            if (k == 3) {
              points.emplace_back(c[0], c[1], c[2]);
              k = 0;
            }
          }
        }
      } point_sink{mesh.points, {0, 0, 0}, 0, check_points};
      arrays.read_into<double>(*da[0], 3 * nv, point_sink);
      const std::string* ptype = da[0]->attribute("type");
      const std::string* pformat = da[0]->attribute("format");
      bool float32 = ptype != nullptr && (*ptype == "Float32" || *ptype == "Float");
      // decimal text typed Float32: the floats nearest to the numbers (as VTK reads them), unless a
      // number is beyond the float range (then the piece is read as doubles)
      if (float32 && (pformat == nullptr || *pformat == "ascii"))
        float32 = round_points_to_float(mesh.points, vertex_offset);
      any_points = true;
      float32_points = float32_points && float32;
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
      std::vector<long long> offsets;
      std::vector<std::uint8_t> type_values; // VTK cell types are below 256 (others: "unknown cell type")
      struct Type_sink {
        std::vector<std::uint8_t>& out;
        void reserve(std::size_t n) { out.reserve(n); }
        void operator()(const long long* v, std::size_t n) {
          for (std::size_t i = 0; i < n; ++i)
            out.push_back(v[i] >= 0 && v[i] < 255 ? std::uint8_t(v[i]) : 255);
        }
      } type_sink{type_values};
      arrays.read_into<long long>(*types, nc, type_sink);
      // offsets 4, 8, 12... (only tetrahedra) are not stored
      struct Offset_sink {
        std::vector<long long>& out;
        std::size_t count, i;
        bool regular;
        void reserve(std::size_t n) { count = n; }
        void operator()(const long long* v, std::size_t n) {
          for (std::size_t j = 0; j < n; ++j, ++i) {
            if (regular && v[j] == 4 * static_cast<long long>(i + 1)) continue;
            if (regular) {
              regular = false;
              out.reserve(count);
              for (std::size_t k = 0; k < i; ++k) out.push_back(4 * static_cast<long long>(k + 1));
            }
            out.push_back(v[j]);
          }
        }
      } offset_sink{offsets, 0, 0, true};
      arrays.read_into<long long>(*offs, nc, offset_sink);
      // the connectivity size is the last offset (checked to be sensible against the text size)
      const long long last = nc == 0               ? 0
                             : offset_sink.regular ? 4 * static_cast<long long>(nc)
                                                   : offsets.back();
      if (last < 0 ||
          static_cast<unsigned long long>(last) / max_compression_ratio(arrays.compressor()) > text.size())
        fail(*offs, "invalid last cell offset " + std::to_string(last));
      const auto cell_fail = [&](const std::string& m) { fail(*cells, "<Cells>: " + m); };
      Vtk_tetrahedra_builder<typename Mesh::Tetrahedron, std::uint8_t> builder(
          offset_sink.regular ? nullptr : offsets.data(), type_values.data(), nc, nv, vertex_offset,
          mesh.tetrahedra, kept, mesh.skipped_cells, cell_fail);
      arrays.read_into<long long>(*conn, static_cast<std::size_t>(last), builder);
      builder.finish();
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
          mesh.point_data.push_back(Data_array{array_name, {}});
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

    // labels (the first integer-valued array with a label name) and cell data
    bool has_labels = false;
    std::size_t kc = 0;
    if (const Xml_element* cd = single(piece, "CellData")) {
      for (const Xml_element* a : xml_children(doc, *cd, "DataArray")) {
        if (components(*a) != 1) continue;
        const std::string* n = a->attribute("Name");
        const std::string array_name = n ? *n : "cell_data_" + std::to_string(kc);
        if (!has_labels && is_vtk_label_array_name(array_name)) {
          // straight into ints; an array with a value that is not an int is cell data after all
          struct Label_sink {
            std::vector<int>& out;
            const std::vector<char>& kept;
            std::size_t i;
            bool integers;
            void reserve(std::size_t n) {
              out.reserve(out.size() + n);
              advise_huge_pages(out.data() + out.size(), (out.capacity() - out.size()) * sizeof(int));
            }
            void operator()(const double* v, std::size_t n) {
              for (std::size_t j = 0; j < n; ++j, ++i) {
                if (!(v[j] == std::floor(v[j]) && v[j] >= double(std::numeric_limits<int>::min()) &&
                      v[j] <= double(std::numeric_limits<int>::max())))
                  integers = false;
                else if (kept.empty() || kept[i])
                  out.push_back(static_cast<int>(v[j]));
              }
            }
          };
          const std::size_t before = mesh.tetrahedron_labels.size();
          Label_sink label_sink{mesh.tetrahedron_labels, kept, 0, true};
          arrays.read_into<double>(*a, nc, label_sink);
          if (label_sink.integers) {
            has_labels = true;
            continue;
          }
          mesh.tetrahedron_labels.resize(before);
        }
        std::vector<double> values;
        arrays.read(*a, nc, values);
        vtk_keep_cells(values, kept);
        if (pi == 0) {
          for (const auto& existing : mesh.cell_data)
            if (existing.name == array_name) fail(*a, "duplicate cell data array '" + array_name + "'");
          mesh.cell_data.push_back(Data_array{array_name, {}});
        } else if (kc >= mesh.cell_data.size() || mesh.cell_data[kc].name != array_name) {
          fail(*a, "the cell data of piece " + std::to_string(pi) + " differ from those of the first piece");
        }
        auto& dst = mesh.cell_data[kc].values;
        dst.insert(dst.end(), values.begin(), values.end());
        ++kc;
      }
    }
    if (pi > 0 && kc != mesh.cell_data.size())
      fail(piece, "the cell data of piece " + std::to_string(pi) + " differ from those of the first piece");
    if (!has_labels) labels_everywhere = false;
  }
  if (!labels_everywhere) mesh.tetrahedron_labels.clear();
  set_float32_points(mesh, any_points && float32_points);
  result = std::move(mesh);
}

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTU_READER_H
