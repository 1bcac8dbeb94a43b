// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_TEXT_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_TEXT_H

// Shared machinery of the readers and writers: loading a file or a stream into memory, strict
// locale-independent number parsing, a line- and token-oriented text reader with line numbers,
// bounded reservation, index checks and exact number formatting.

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <iterator>
#include <limits>
#include <ostream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {

// ---------------------------------------------------------------------------------------------
// Loading
// ---------------------------------------------------------------------------------------------

/// Reads a whole file into memory; throws `Read_error` when it is missing, a directory or
/// unreadable.
inline std::string load_file(const std::string& filename) {
  std::error_code ec;
  const std::filesystem::path path(filename);
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) throw Read_error(filename, 0, "no such file");
  if (std::filesystem::is_directory(status)) throw Read_error(filename, 0, "is a directory, not a file");
  std::ifstream in(filename, std::ios::in | std::ios::binary);
  if (!in) throw Read_error(filename, 0, "cannot open the file for reading");
  std::string text;
  if (std::filesystem::is_regular_file(status)) {
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && size < std::uintmax_t(std::numeric_limits<std::size_t>::max() / 2)) {
      text.resize(static_cast<std::size_t>(size));
      in.read(&text[0], static_cast<std::streamsize>(size));
      if (in.bad() || static_cast<std::uintmax_t>(in.gcount()) != size)
        throw Read_error(filename, 0, "error while reading the file");
      return text;
    }
  }
  text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (in.bad()) throw Read_error(filename, 0, "error while reading the file");
  return text;
}

/// Reads what remains of a stream into memory.
inline std::string load_stream(std::istream& in, const std::string& name) {
  if (!in) throw Read_error(name, 0, "the input stream is not readable");
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw Read_error(name, 0, "error while reading the stream");
  return text;
}

// ---------------------------------------------------------------------------------------------
// Strings and numbers
// ---------------------------------------------------------------------------------------------

inline bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

inline char to_lower(char c) {
  return (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c;
}

inline std::string to_lower(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = to_lower(c);
  return r;
}

inline bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (to_lower(a[i]) != to_lower(b[i])) return false;
  return true;
}

inline bool istarts_with(std::string_view s, std::string_view prefix) {
  return s.size() >= prefix.size() && iequals(s.substr(0, prefix.size()), prefix);
}

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

/// A token quoted for an error message, shortened and with control bytes escaped.
inline std::string quote(std::string_view token) {
  std::string r = "'";
  const std::size_t n = std::min<std::size_t>(token.size(), 40);
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    if (c < 32 || c >= 127) {
      const char* hex = "0123456789abcdef";
      r += "\\x";
      r += hex[c >> 4];
      r += hex[c & 15];
    } else {
      r += char(c);
    }
  }
  if (token.size() > n) r += "...";
  return r + "'";
}

/// Parses a whole token as a finite double (locale-independent).  Returns `nullptr` on success,
/// otherwise what is wrong ("is not a number", "is not finite").
inline const char* parse_double(std::string_view token, double& value) {
  const char* first = token.data();
  const char* last = token.data() + token.size();
  if (first != last && *first == '+') {
    ++first;
    if (first == last || *first == '-' || *first == '+') return "is not a number";
  }
  if (first == last) return "is not a number";
  const std::from_chars_result r = std::from_chars(first, last, value, std::chars_format::general);
  if (r.ec == std::errc::result_out_of_range) {
    // from_chars reports overflow and underflow alike; tell them apart through strtod-free means
    // by parsing the exponent sign: an underflow is harmless (the value rounds to 0).
    if (r.ptr != last) return "is not a number";
    const std::string_view t(first, std::size_t(last - first));
    const std::size_t e = t.find_first_of("eE");
    if (e != std::string_view::npos && e + 1 < t.size() && t[e + 1] == '-') {
      value = 0.;
      return nullptr;
    }
    return "is not finite (overflow)";
  }
  if (r.ec != std::errc() || r.ptr != last) return "is not a number";
  if (!std::isfinite(value)) return "is not finite";
  return nullptr;
}

/// Parses a whole token as a signed 64-bit integer.  Returns `nullptr` on success, otherwise what
/// is wrong.
inline const char* parse_integer(std::string_view token, long long& value) {
  const char* first = token.data();
  const char* last = token.data() + token.size();
  if (first != last && *first == '+') {
    ++first;
    if (first != last && *first == '-') return "is not an integer";
  }
  if (first == last) return "is not an integer";
  const std::from_chars_result r = std::from_chars(first, last, value, 10);
  if (r.ec == std::errc::result_out_of_range) return "is out of the 64-bit integer range";
  if (r.ec != std::errc() || r.ptr != last) return "is not an integer";
  return nullptr;
}

/// Reserves at most `count` elements, and no more than the remaining input can possibly hold
/// (`available_bytes / min_bytes_per_element`): a header cannot make us allocate more than the
/// file justifies.
template <class Vector>
void capped_reserve(Vector& v, std::size_t count, std::size_t available_bytes,
                    std::size_t min_bytes_per_element) {
  const std::size_t cap = available_bytes / std::max<std::size_t>(min_bytes_per_element, 1) + 1;
  v.reserve(std::min(count, cap));
}

/// True when the 0-based vertex index `i` is representable in `Index`.
template <class Index>
bool fits_index(long long i) {
  return i >= 0 && static_cast<unsigned long long>(i) <=
                       static_cast<unsigned long long>(std::numeric_limits<Index>::max());
}

/// The maximal number of vertices a mesh with index type `Index` may have.
template <class Index>
unsigned long long max_vertices() {
  const unsigned long long m = static_cast<unsigned long long>(std::numeric_limits<Index>::max());
  return m == std::numeric_limits<unsigned long long>::max() ? m : m + 1;
}

// ---------------------------------------------------------------------------------------------
// Text reader
// ---------------------------------------------------------------------------------------------

/// Reads a text held in memory either line by line (`next_line()`: tokens of the next line that
/// is not blank once its comment is removed) or token by token across lines (`next_token()`).
/// Comments run from `comment` to the end of the line (no comment when `comment == 0`).  Every
/// returned line or token sets `line()`, used by `fail()` for the error message.
class Text_reader {
public:
  Text_reader(std::string_view text, std::string name, char comment = '#')
      : text_(text), name_(std::move(name)), comment_(comment) {}

  const std::string& name() const { return name_; }
  std::size_t line() const { return line_; }
  std::size_t remaining_bytes() const { return text_.size() - pos_; }
  bool at_end() const { return pos_ >= text_.size(); }

  /// Sets the item being read (e.g. "vertex", 12): `fail()` then prefixes its message with
  /// "vertex 12: ".  `kind` must outlive its use (a string literal).
  void set_context(const char* kind, std::size_t number) {
    context_kind_ = kind;
    context_number_ = number;
  }
  void clear_context() { context_kind_ = nullptr; }

  [[noreturn]] void fail(const std::string& message) const {
    throw Read_error(name_, line_, prefix() + message);
  }
  [[noreturn]] void fail_at(std::size_t line, const std::string& message) const {
    throw Read_error(name_, line, prefix() + message);
  }
  std::string prefix() const {
    if (context_kind_ == nullptr) return std::string();
    return std::string(context_kind_) + " " + std::to_string(context_number_) + ": ";
  }

  /// A position in the text, to come back to with `restore()` (look-ahead).
  struct Mark {
    std::size_t pos, current_line, line;
  };
  Mark mark() const { return Mark{pos_, current_line_, line_}; }
  void restore(const Mark& m) {
    pos_ = m.pos;
    current_line_ = m.current_line;
    line_ = m.line;
  }

  /// The next token without consuming it (empty at the end).
  std::string_view peek_token() {
    const Mark m = mark();
    std::string_view token;
    if (!next_token(token)) token = std::string_view();
    restore(m);
    return token;
  }

  /// The next raw line (no comment removal, `\r` removed), possibly empty; `false` at the end.
  bool next_raw_line(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    const std::size_t eol = text_.find('\n', pos_);
    const std::size_t end = (eol == std::string_view::npos) ? text_.size() : eol;
    line = text_.substr(pos_, end - pos_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    line_ = current_line_;
    pos_ = (eol == std::string_view::npos) ? text_.size() : eol + 1;
    if (eol != std::string_view::npos) ++current_line_;
    return true;
  }

  /// The tokens of the next line that has any once its comment is removed; `false` at the end.
  bool next_line(std::vector<std::string_view>& tokens) {
    std::string_view line;
    while (next_raw_line(line)) {
      if (comment_ != 0) {
        const std::size_t c = line.find(comment_);
        if (c != std::string_view::npos) line = line.substr(0, c);
      }
      split(line, tokens);
      if (!tokens.empty()) return true;
    }
    tokens.clear();
    return false;
  }

  /// The next token, across lines; `false` at the end.
  bool next_token(std::string_view& token) {
    for (;;) {
      while (pos_ < text_.size() && is_space(text_[pos_])) {
        if (text_[pos_] == '\n') ++current_line_;
        ++pos_;
      }
      if (pos_ >= text_.size()) {
        line_ = current_line_;
        return false;
      }
      if (comment_ != 0 && text_[pos_] == comment_) {
        const std::size_t eol = text_.find('\n', pos_);
        pos_ = (eol == std::string_view::npos) ? text_.size() : eol;
        continue;
      }
      break;
    }
    const std::size_t begin = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_]) && text_[pos_] != comment_) ++pos_;
    token = text_.substr(begin, pos_ - begin);
    line_ = current_line_;
    return true;
  }

  /// The next token; fails with "unexpected end of file, expected WHAT" at the end.
  std::string_view expect_token(const char* what) {
    std::string_view token;
    if (!next_token(token)) fail(std::string("unexpected end of file, expected ") + what);
    return token;
  }

  double expect_double(const char* what) {
    const std::string_view token = expect_token(what);
    double v = 0;
    if (const char* why = parse_double(token, v)) fail(std::string(what) + " " + quote(token) + " " + why);
    return v;
  }

  long long expect_integer(const char* what) {
    const std::string_view token = expect_token(what);
    long long v = 0;
    if (const char* why = parse_integer(token, v)) fail(std::string(what) + " " + quote(token) + " " + why);
    return v;
  }

  /// An integer count: non-negative.
  std::size_t expect_count(const char* what) {
    const long long v = expect_integer(what);
    if (v < 0) fail(std::string(what) + " " + std::to_string(v) + " is negative");
    if (static_cast<unsigned long long>(v) > std::numeric_limits<std::size_t>::max() / 64)
      fail(std::string(what) + " " + std::to_string(v) + " is too large");
    return static_cast<std::size_t>(v);
  }

  static void split(std::string_view line, std::vector<std::string_view>& tokens) {
    tokens.clear();
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && is_space(line[i])) ++i;
      const std::size_t b = i;
      while (i < line.size() && !is_space(line[i])) ++i;
      if (i > b) tokens.push_back(line.substr(b, i - b));
    }
  }

private:
  std::string_view text_;
  std::string name_;
  char comment_;
  std::size_t pos_ = 0;
  std::size_t current_line_ = 1; // line of pos_
  std::size_t line_ = 0;         // line of the last returned token or line
  const char* context_kind_ = nullptr;
  std::size_t context_number_ = 0;
};

// ---------------------------------------------------------------------------------------------
// Writing
// ---------------------------------------------------------------------------------------------

/// Appends the shortest decimal representation of `v` that reads back exactly (locale-independent).
/// Whether two of the 4 vertex indices of `t` are equal (a tetrahedron listing a vertex twice:
/// refused by the readers, as by `PR_star_octree_3`); `repeated` is then that index.
template <class Tetrahedron, class Int>
bool has_repeated_vertex(const Tetrahedron& t, Int& repeated) {
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (t[i] == t[j]) {
        repeated = static_cast<Int>(t[i]);
        return true;
      }
  return false;
}

inline void append_double(std::string& out, double v) {
  char buf[64];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof(buf), v);
  out.append(buf, r.ptr);
}

template <class Int>
void append_integer(std::string& out, Int v) {
  char buf[32];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof(buf), v);
  out.append(buf, r.ptr);
}

/// Writes `buffer` to `out` once it is large, or always when `force`; throws `Write_error` when the
/// stream fails.
inline void flush_buffer(std::ostream& out, std::string& buffer, const std::string& name,
                         bool force = false) {
  if (!force && buffer.size() < (1u << 16)) return;
  out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
  buffer.clear();
  if (!out) throw Write_error(name, "error while writing");
}

/// Checks that a point-data array has `nv` finite values.
inline void check_point_data_for_writing(const Point_data_array& a, std::size_t nv, const std::string& name) {
  if (a.values.size() != nv)
    throw Write_error(name, "point data '" + a.name + "' has " + std::to_string(a.values.size()) +
                                " values for " + std::to_string(nv) + " vertices");
  for (std::size_t i = 0; i < nv; ++i)
    if (!std::isfinite(a.values[i]))
      throw Write_error(name, "point data '" + a.name + "': value " + std::to_string(i) + " is not finite");
}

/// Checks what every writer needs: finite coordinates, indices in range, data arrays of the right
/// sizes.
template <class Mesh>
void check_mesh_for_writing(const Mesh& mesh, const std::string& name) {
  const std::size_t nv = mesh.points.size();
  for (std::size_t i = 0; i < nv; ++i) {
    const auto& p = mesh.points[i];
    if (!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) ||
        !std::isfinite(CGAL::to_double(p.z())))
      throw Write_error(name, "vertex " + std::to_string(i) + " has a non-finite coordinate");
  }
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t)
    for (const auto v : mesh.tetrahedra[t])
      if (static_cast<unsigned long long>(v) >= nv)
        throw Write_error(name, "tetrahedron " + std::to_string(t) + " has vertex index " +
                                    std::to_string(v) + " out of range (" + std::to_string(nv) +
                                    " vertices)");
  if (!mesh.tetrahedron_labels.empty() && mesh.tetrahedron_labels.size() != mesh.tetrahedra.size())
    throw Write_error(name, "the mesh has " + std::to_string(mesh.tetrahedron_labels.size()) +
                                " tetrahedron labels for " + std::to_string(mesh.tetrahedra.size()) +
                                " tetrahedra");
  for (const auto& a : mesh.point_data) check_point_data_for_writing(a, nv, name);
}

/// Opens `filename` for writing, throwing `Write_error` on failure.
inline void open_for_writing(std::ofstream& out, const std::string& filename) {
  std::error_code ec;
  if (std::filesystem::is_directory(std::filesystem::path(filename), ec))
    throw Write_error(filename, "is a directory, not a file");
  out.open(filename, std::ios::out | std::ios::binary | std::ios::trunc);
  if (!out) throw Write_error(filename, "cannot open the file for writing");
}

/// Closes a file opened by `open_for_writing()`, throwing `Write_error` on failure.
inline void close_written(std::ofstream& out, const std::string& filename) {
  out.flush();
  if (!out) throw Write_error(filename, "error while writing");
  out.close();
  if (out.fail()) throw Write_error(filename, "error while closing the file");
}

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_TEXT_H
