// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_FILE_BYTES_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_FILE_BYTES_H

// The bytes of a file or of a buffer, as every reader and binary writer uses them: the file loader
// (`File_bytes`: mapped or read without zero-filling), the memory hints for large arrays, the byte
// order of the machine, byte swapping, and the one bounds-checked cursor over binary data
// (`Byte_cursor`: fixed-size values in either byte order, errors naming the file and the byte).

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <system_error>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#if defined(__linux__)
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {

/// Whether the machine stores integers least significant byte first.
inline bool host_is_little_endian() {
  const std::uint16_t one = 1;
  unsigned char c;
  std::memcpy(&c, &one, 1);
  return c == 1;
}

/// Reverses the bytes of a trivially copyable value (one instruction for 2, 4 and 8 bytes with GCC
/// and Clang).
template <class T>
T byte_swapped(T v) {
  static_assert(std::is_trivially_copyable<T>::value, "byte_swapped: trivially copyable types only");
#if defined(__GNUC__) || defined(__clang__)
  if constexpr (sizeof(T) == 2 || sizeof(T) == 4 || sizeof(T) == 8) {
    using U = std::conditional_t<sizeof(T) == 2, std::uint16_t,
                                 std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>;
    U u;
    std::memcpy(&u, &v, sizeof(T));
    if constexpr (sizeof(T) == 2)
      u = __builtin_bswap16(u);
    else if constexpr (sizeof(T) == 4)
      u = __builtin_bswap32(u);
    else
      u = __builtin_bswap64(u);
    std::memcpy(&v, &u, sizeof(T));
    return v;
  }
#endif
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  std::reverse(b, b + sizeof(T));
  std::memcpy(&v, b, sizeof(T));
  return v;
}

/// The value of type `T` stored at `p` (any alignment), byte-swapped when `swap`.
template <class T>
T load_value(const char* p, bool swap) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  return swap ? byte_swapped(v) : v;
}

/// A read position in a binary buffer held in memory: the one cursor of the binary readers (gmsh,
/// Medit binary, legacy VTK, appended VTU data).
class Byte_cursor {
public:
  Byte_cursor(std::string_view data, std::string name, bool swap = false)
      : data_(data), name_(std::move(name)), swap_(swap) {}

  const std::string& name() const { return name_; }
  bool swap() const { return swap_; }
  void set_swap(bool s) { swap_ = s; }
  std::size_t offset() const { return pos_; }
  std::size_t size() const { return data_.size(); }
  std::size_t remaining() const { return data_.size() - pos_; }
  const char* here() const { return data_.data() + pos_; }

  [[noreturn]] void fail(const std::string& message) const { fail_at(pos_, message); }
  [[noreturn]] void fail_at(std::size_t offset, const std::string& message) const {
    throw Read_error(name_, 0, "byte " + std::to_string(offset) + ": " + message);
  }

  /// Fails with "unexpected end of file" unless `n` more bytes are available.
  void need(std::size_t n, const char* what) const {
    if (n > remaining())
      fail(std::string("unexpected end of file in ") + what + " (" + std::to_string(n) + " bytes needed, " +
           std::to_string(remaining()) + " left)");
  }
  /// Whether `count` items of `item_bytes` bytes each fit in what is left (no overflow).
  bool fits(std::uint64_t count, std::size_t item_bytes) const {
    return item_bytes == 0 || count <= remaining() / item_bytes;
  }

  template <class T>
  T get(const char* what) {
    need(sizeof(T), what);
    const T v = load_value<T>(here(), swap_);
    pos_ += sizeof(T);
    return v;
  }
  /// An unsigned integer stored on `bytes` (1, 2, 4 or 8) bytes.
  std::uint64_t get_unsigned(std::size_t bytes, const char* what) {
    switch (bytes) {
    case 1:
      return get<std::uint8_t>(what);
    case 2:
      return get<std::uint16_t>(what);
    case 4:
      return get<std::uint32_t>(what);
    default:
      return get<std::uint64_t>(what);
    }
  }
  /// A signed integer stored on `bytes` (1, 2, 4 or 8) bytes.
  std::int64_t get_signed(std::size_t bytes, const char* what) {
    switch (bytes) {
    case 1:
      return get<std::int8_t>(what);
    case 2:
      return get<std::int16_t>(what);
    case 4:
      return get<std::int32_t>(what);
    default:
      return get<std::int64_t>(what);
    }
  }
  /// A real stored on `bytes` (4 or 8) bytes.
  double get_real(std::size_t bytes, const char* what) {
    return bytes == 4 ? double(get<float>(what)) : get<double>(what);
  }

  void skip(std::size_t n, const char* what) {
    need(n, what);
    pos_ += n;
  }
  void seek(std::size_t offset) { pos_ = std::min(offset, data_.size()); }

  /// Reads the integer 1 by which binary gmsh and Medit files announce their byte order, and takes
  /// the byte order from it; false (nothing read) when the next 4 bytes are not 1 in either order.
  bool take_byte_order_mark() {
    if (remaining() < 4) return false;
    const std::int32_t one = load_value<std::int32_t>(here(), false);
    if (one != 1 && byte_swapped(one) != 1) return false;
    swap_ = one != 1;
    pos_ += 4;
    return true;
  }

protected: // a reader of text and binary parts (gmsh) derives from it
  std::string_view data_;
  std::string name_;
  bool swap_;
  std::size_t pos_ = 0;
};

/// Asks the kernel to back the (not yet touched) memory of a large array with huge pages: for the
/// arrays of hundreds of megabytes a binary reader fills, the page faults of 4 kB pages cost more
/// than the parsing.  A hint only (Linux), without effect elsewhere or when refused.
inline void advise_huge_pages(const void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const std::size_t page = std::size_t(1) << 21;
  if (data == nullptr || bytes < 2 * page) return;
  const std::uintptr_t begin =
      (reinterpret_cast<std::uintptr_t>(data) + page - 1) & ~std::uintptr_t(page - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~std::uintptr_t(page - 1);
  if (end > begin) (void)::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

/// The byte ranges of the files this thread has mapped (`File_bytes`): only their pages may be
/// released by `release_file_pages()`.
inline std::vector<std::pair<const char*, const char*>>& mapped_files() {
  static thread_local std::vector<std::pair<const char*, const char*>> files;
  return files;
}

/// Tells that the bytes `[begin, end)` of a file read through `File_bytes` will not be read soon:
/// the whole pages among them leave the resident memory of the process (they stay in the page
/// cache, and are read back from it if touched again).  So reading a file of gigabytes costs a few
/// megabytes of resident memory, not the size of the file.  No effect on any other memory.
inline void release_file_pages(const char* begin, const char* end) {
#if defined(__linux__) && defined(MADV_DONTNEED)
  for (const auto& f : mapped_files()) {
    if (begin < f.first || end > f.second || begin >= end) continue;
    const std::uintptr_t page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
    const std::uintptr_t b = (reinterpret_cast<std::uintptr_t>(begin) + page - 1) / page * page;
    const std::uintptr_t e = reinterpret_cast<std::uintptr_t>(end) / page * page;
    if (e > b) (void)::madvise(reinterpret_cast<void*>(b), e - b, MADV_DONTNEED);
    return;
  }
#else
  (void)begin;
  (void)end;
#endif
}

/// The whole content of a file, like `load_file()` (same errors).  A regular file is mapped into
/// memory read-only (Linux): nothing is copied, pages are read from the page cache as the parser
/// reaches them, and the parser may give them back with `release_file_pages()`.  Otherwise (another
/// system, a pipe, a failed mapping) the file is read into a buffer that is not zero-filled first
/// and may be backed by huge pages.
class File_bytes {
public:
  explicit File_bytes(const std::string& filename) {
    std::error_code ec;
    const std::filesystem::path path(filename);
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (!ec && std::filesystem::is_regular_file(status)) {
      const std::uintmax_t size = std::filesystem::file_size(path, ec);
      if (!ec && size > 0 && size < std::uintmax_t(std::numeric_limits<std::size_t>::max() / 2)) {
        const std::size_t n = static_cast<std::size_t>(size);
#if defined(__linux__)
        if (map(filename, n)) return;
#endif
        const std::size_t align = std::size_t(1) << 21;
        const std::size_t rounded = (n + align - 1) / align * align;
        buffer_.reset(static_cast<char*>(std::aligned_alloc(align, rounded)));
        if (buffer_) {
          advise_huge_pages(buffer_.get(), rounded);
          std::ifstream in(filename, std::ios::in | std::ios::binary);
          if (!in) throw Read_error(filename, 0, "cannot open the file for reading");
          in.read(buffer_.get(), static_cast<std::streamsize>(n));
          if (in.bad() || static_cast<std::uintmax_t>(in.gcount()) != size)
            throw Read_error(filename, 0, "error while reading the file");
          view_ = std::string_view(buffer_.get(), n);
          return;
        }
      }
    }
    text_ = load_file(filename);
    view_ = text_;
  }
  File_bytes(const File_bytes&) = delete;
  File_bytes& operator=(const File_bytes&) = delete;
  ~File_bytes() {
#if defined(__linux__)
    if (mapped_) {
      auto& files = mapped_files();
      files.erase(
          std::remove(files.begin(), files.end(), std::make_pair(view_.data(), view_.data() + view_.size())),
          files.end());
      ::munmap(const_cast<char*>(view_.data()), view_.size());
    }
#endif
  }

  std::string_view view() const {
    return view_;
  }

private:
#if defined(__linux__)
  bool map(const std::string& filename, std::size_t n) {
    const int fd = ::open(filename.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    struct stat st;
    void* p = MAP_FAILED;
    if (::fstat(fd, &st) == 0 && static_cast<std::uintmax_t>(st.st_size) == n)
      p = ::mmap(nullptr, n, PROT_READ, MAP_PRIVATE, fd, 0);
    ::close(fd);
    if (p == MAP_FAILED) return false;
    (void)::madvise(p, n, MADV_SEQUENTIAL);
    view_ = std::string_view(static_cast<const char*>(p), n);
    mapped_ = true;
    mapped_files().emplace_back(view_.data(), view_.data() + n);
    return true;
  }
#endif
  struct Free {
    void operator()(char* p) const { std::free(p); }
  };
  std::unique_ptr<char, Free> buffer_;
  std::string text_;
  std::string_view view_;
  bool mapped_ = false;
};

/// Appends the bytes of `v` (machine byte order) to `out`.
template <class T>
void append_binary(std::string& out, T v) {
  static_assert(std::is_trivially_copyable<T>::value, "append_binary: trivially copyable types only");
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  out.append(b, sizeof(T));
}

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_FILE_BYTES_H
