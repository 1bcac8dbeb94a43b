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
#include <CGAL/PR_star_octree/IO/internal/float32_points.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <algorithm>
#include <charconv>
#include <cerrno>
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

/// Whether `c` is one of the six ASCII blanks: space, `\t`, `\n`, `\v`, `\f`, `\r` (9 to 13).
inline bool is_space(char c) {
  return c == ' ' || static_cast<unsigned char>(c - '\t') < 5;
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

// Fast paths of `parse_double()` and `parse_integer()`, for a token starting at `p` in a text
// ending at `end`: they accept only the common spellings, give the same values, and return the end
// of the token, or `nullptr` for anything else (the caller then extracts the token and calls
// `parse_double()` or `parse_integer()`, which give the value or the message).  A token ends at a
// blank, at `comment` (when not 0) or at the end of the text.

inline bool ends_token(const char* p, const char* end, char comment) {
  return p == end || is_space(*p) || (comment != 0 && *p == comment);
}

/// Plain decimal digits (at most 18: no overflow), then the end of the token.
inline const char* scan_plain_integer(const char* p, const char* end, long long& value, char comment) {
  const char* const first = p;
  unsigned long long v = 0;
  while (p != end && static_cast<unsigned char>(*p - '0') < 10 && p - first < 19) {
    v = v * 10 + static_cast<unsigned char>(*p - '0');
    ++p;
  }
  if (p == first || p - first > 18 || !ends_token(p, end, comment)) return nullptr;
  value = static_cast<long long>(v);
  return p;
}

/// A finite number in `std::from_chars`'s general format starting with a digit, `-` or `.`, then
/// the end of the token.
inline const char* scan_plain_double(const char* p, const char* end, double& value, char comment) {
  if (p == end) return nullptr;
  const char c = *p;
  if (static_cast<unsigned char>(c - '0') >= 10 && c != '-' && c != '.') return nullptr;
  double v;
  const std::from_chars_result r = std::from_chars(p, end, v, std::chars_format::general);
  if (r.ec != std::errc() || !ends_token(r.ptr, end, comment) || !std::isfinite(v)) return nullptr;
  value = v;
  return r.ptr;
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
/// returned line or token sets `line()`, used by `fail()` for the error message.  Line numbers are
/// not counted while reading: `line()` counts the line breaks before the last returned item when
/// it is asked for (an error), so reading costs nothing for them.
class Text_reader {
public:
  Text_reader(std::string_view text, std::string name, char comment = '#')
      : text_(text), name_(std::move(name)), comment_(comment) {}

  const std::string& name() const { return name_; }
  std::size_t line() const { return item_line_ != computed ? item_line_ : line_at(item_pos_); }
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
    throw Read_error(name_, line(), prefix() + message);
  }
  [[noreturn]] void fail_at(std::size_t line, const std::string& message) const {
    throw Read_error(name_, line, prefix() + message);
  }
  std::string prefix() const {
    if (context_kind_ == nullptr) return std::string();
    return std::string(context_kind_) + " " + std::to_string(context_number_) + ": ";
  }

  /// A position in the text, to come back to with `restore()` (look-ahead).  `pos` may be moved
  /// forward over binary data before `restore()`: the line breaks in between are then not counted.
  struct Mark {
    std::size_t pos, current_line, line;
  };
  Mark mark() const { return Mark{pos_, line_at(pos_), line()}; }
  void restore(const Mark& m) {
    pos_ = m.pos;
    base_pos_ = m.pos;
    base_line_ = m.current_line;
    item_line_ = m.line;
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
    set_item(pos_);
    pos_ = (eol == std::string_view::npos) ? text_.size() : eol + 1;
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
    const std::size_t n = text_.size();
    for (;;) {
      while (pos_ < n && is_space(text_[pos_])) ++pos_;
      if (pos_ >= n) {
        set_item(pos_);
        return false;
      }
      if (comment_ != 0 && text_[pos_] == comment_) {
        const std::size_t eol = text_.find('\n', pos_);
        pos_ = (eol == std::string_view::npos) ? n : eol;
        continue;
      }
      break;
    }
    const std::size_t begin = pos_;
    while (pos_ < n && !is_space(text_[pos_]) && text_[pos_] != comment_) ++pos_;
    token = text_.substr(begin, pos_ - begin);
    set_item(begin);
    return true;
  }

  /// The next token; fails with "unexpected end of file, expected WHAT" at the end.
  std::string_view expect_token(const char* what) {
    std::string_view token;
    if (!next_token(token)) fail(std::string("unexpected end of file, expected ") + what);
    return token;
  }

  double expect_double(const char* what) {
    double v = 0;
    if (fast_double(v)) return v;
    const std::string_view token = expect_token(what);
    if (const char* why = parse_double(token, v)) fail(std::string(what) + " " + quote(token) + " " + why);
    return v;
  }

  long long expect_integer(const char* what) {
    long long v = 0;
    if (fast_integer(v)) return v;
    const std::string_view token = expect_token(what);
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

  /// The fast path of `expect_double()`: the next token when it is a plain finite number
  /// (`scan_plain_double()`), consumed; otherwise `false`, and the token is left to
  /// `expect_double()` (only blanks are consumed).
  bool fast_double(double& v) {
    const char* p = skip_blanks();
    if (p == nullptr) return false;
    const char* e = scan_plain_double(p, end(), v, comment_);
    if (e == nullptr) return false;
    take(p, e);
    return true;
  }
  /// The fast path of `expect_integer()` for plain decimal digits (`scan_plain_integer()`).
  bool fast_integer(long long& v) {
    const char* p = skip_blanks();
    if (p == nullptr) return false;
    const char* e = scan_plain_integer(p, end(), v, comment_);
    if (e == nullptr) return false;
    take(p, e);
    return true;
  }

  /// Fast path of the line-oriented readers: a cursor on the line at the current position, which
  /// reads its fields (`real()`, `integer()`) and its end (`end_of_line()`).  Any field that is not
  /// a plain number, a blank or comment line, a missing or an extra field make the cursor fail;
  /// nothing is then consumed, and the reader reads the same line with `next_line()` (which skips
  /// blank lines and gives the messages).  On success (`accept()`) the line is consumed and
  /// `line()` is its line.
  class Line_cursor {
  public:
    explicit Line_cursor(Text_reader& r)
        : r_(r), p_(r.text_.data() + r.pos_), end_(r.text_.data() + r.text_.size()) {}
    bool real(double& v) {
      if (!field()) return false;
      const char* e = scan_plain_double(p_, end_, v, r_.comment_);
      if (e == nullptr) return false;
      p_ = e;
      return true;
    }
    bool integer(long long& v) {
      if (!field()) return false;
      const char* e = scan_plain_integer(p_, end_, v, r_.comment_);
      if (e == nullptr) return false;
      p_ = e;
      return true;
    }
    /// Whether the next field is exactly `word`.
    bool word(std::string_view w) {
      if (!field() || static_cast<std::size_t>(end_ - p_) < w.size() || std::string_view(p_, w.size()) != w ||
          !ends_token(p_ + w.size(), end_, r_.comment_))
        return false;
      p_ += w.size();
      return true;
    }
    /// Whether only blanks, or a comment, follow on the line; then consumes the line.
    bool end_of_line() {
      while (p_ != end_ && *p_ != '\n' && is_space(*p_)) ++p_;
      if (p_ != end_ && *p_ != '\n') {
        if (r_.comment_ == 0 || *p_ != r_.comment_) return false;
        const void* eol = std::memchr(p_, '\n', static_cast<std::size_t>(end_ - p_));
        p_ = eol == nullptr ? end_ : static_cast<const char*>(eol);
      }
      const std::size_t begin = r_.pos_;
      r_.pos_ = static_cast<std::size_t>(p_ - r_.text_.data()) + (p_ != end_ ? 1 : 0);
      r_.set_item(begin);
      return true;
    }

  private:
    // skips the blanks before a field; false at the end of the line or at a comment
    bool field() {
      while (p_ != end_ && *p_ != '\n' && is_space(*p_)) ++p_;
      return p_ != end_ && *p_ != '\n' && (r_.comment_ == 0 || *p_ != r_.comment_);
    }
    Text_reader& r_;
    const char* p_;
    const char* end_;
  };

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
  const char* end() const { return text_.data() + text_.size(); }
  // skips blanks; the start of the next token, or nullptr at the end of the text or at a comment
  const char* skip_blanks() {
    const std::size_t n = text_.size();
    while (pos_ < n && is_space(text_[pos_])) ++pos_;
    if (pos_ >= n || (comment_ != 0 && text_[pos_] == comment_)) return nullptr;
    return text_.data() + pos_;
  }
  void take(const char* b, const char* e) {
    set_item(static_cast<std::size_t>(b - text_.data()));
    pos_ = static_cast<std::size_t>(e - text_.data());
  }
  void set_item(std::size_t pos) {
    item_pos_ = pos;
    item_line_ = computed;
  }
  // the line of position `pos`: the line breaks before it are counted from the last position
  // asked for (forward or backward), or from the last `restore()`
  std::size_t line_at(std::size_t pos) const {
    const char* t = text_.data();
    if (pos >= base_pos_)
      base_line_ += static_cast<std::size_t>(std::count(t + base_pos_, t + pos, '\n'));
    else
      base_line_ -= static_cast<std::size_t>(std::count(t + pos, t + base_pos_, '\n'));
    base_pos_ = pos;
    return base_line_;
  }

  std::string_view text_;
  std::string name_;
  char comment_;
  std::size_t pos_ = 0;
  static constexpr std::size_t computed = std::size_t(-1);
  std::size_t item_pos_ = 0;  // where the last returned token or line starts
  std::size_t item_line_ = 0; // its line, or `computed` from `item_pos_` (0 before the first item)
  mutable std::size_t base_pos_ = 0, base_line_ = 1; // a position and its line
  const char* context_kind_ = nullptr;
  std::size_t context_number_ = 0;
};

// ---------------------------------------------------------------------------------------------
// Writing
// ---------------------------------------------------------------------------------------------

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

/// Appends the shortest decimal representation of `v` that reads back exactly (locale-independent).
inline void append_double(std::string& out, double v) {
  char buf[64];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof(buf), v);
  out.append(buf, r.ptr);
}

/// Appends the shortest decimal representation of `v` rounded to a float that reads back exactly as
/// that float (at most 9 significant digits; locale-independent): the text of a 32-bit coordinate.
inline void append_float(std::string& out, double v) {
  char buf[64];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof(buf), static_cast<float>(v));
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
inline void check_point_data_for_writing(const Data_array& a, std::size_t nv, const std::string& name) {
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

/// Checks the cell-data arrays of a mesh before writing: one finite value per tetrahedron, a
/// name of its own, not `label` when the mesh has labels (the name the writers give them).
template <class Mesh>
void check_cell_data_for_writing(const Mesh& mesh, const std::string& name) {
  for (const Data_array& a : mesh.cell_data) {
    if (a.name.empty()) throw Write_error(name, "a cell data array has an empty name");
    if (a.values.size() != mesh.tetrahedra.size())
      throw Write_error(name, "cell data '" + a.name + "' has " + std::to_string(a.values.size()) +
                                  " values for " + std::to_string(mesh.tetrahedra.size()) + " tetrahedra");
    for (std::size_t i = 0; i < a.values.size(); ++i)
      if (!std::isfinite(a.values[i]))
        throw Write_error(name, "cell data '" + a.name + "': value " + std::to_string(i) + " is not finite");
    if (a.name == "label" && !mesh.tetrahedron_labels.empty())
      throw Write_error(name, "a cell data array is named 'label', the name of the labels");
  }
  for (std::size_t i = 0; i < mesh.cell_data.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (mesh.cell_data[i].name == mesh.cell_data[j].name)
        throw Write_error(name, "two cell data arrays are named '" + mesh.cell_data[i].name + "'");
}

/// The checks of the writers of named arrays (VTK legacy and XML): the mesh, its cell data, and the
/// point-data arrays of the mesh followed by `extra_point_data` (one finite value per vertex, a
/// name of its own).  Returns these point-data arrays, in that order.
template <class Mesh>
std::vector<const Data_array*> check_named_arrays_for_writing(const Mesh& mesh,
                                                              const std::vector<Data_array>& extra_point_data,
                                                              const std::string& name) {
  check_mesh_for_writing(mesh, name);
  check_cell_data_for_writing(mesh, name);
  std::vector<const Data_array*> data;
  for (const auto& a : mesh.point_data) data.push_back(&a);
  for (const auto& a : extra_point_data) {
    check_point_data_for_writing(a, mesh.points.size(), name);
    data.push_back(&a);
  }
  for (std::size_t i = 0; i < data.size(); ++i) {
    if (data[i]->name.empty()) throw Write_error(name, "a point data array has an empty name");
    for (std::size_t j = 0; j < i; ++j)
      if (data[i]->name == data[j]->name)
        throw Write_error(name, "two point data arrays are named '" + data[i]->name + "'");
  }
  return data;
}

/// Appends `s` to `out` as an XML attribute value (`&`, `<`, `>`, `"` and `'` escaped).
inline void xml_escape(std::string& out, const std::string& s) {
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

/// Opens `filename` for writing, throwing `Write_error` on failure.
inline void open_for_writing(std::ofstream& out, const std::string& filename) {
  std::error_code ec;
  if (std::filesystem::is_directory(std::filesystem::path(filename), ec))
    throw Write_error(filename, "is a directory, not a file");
  errno = 0;
  out.open(filename, std::ios::out | std::ios::binary | std::ios::trunc);
  if (!out)
    throw Write_error(filename, std::string("cannot open the file for writing") +
                                    (errno != 0 ? std::string(": ") + std::strerror(errno) : std::string()));
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
