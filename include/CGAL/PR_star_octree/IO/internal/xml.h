// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_XML_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_XML_H

// A small XML parser, enough for VTK XML files: elements, attributes (any order, single or double
// quotes, basic entities), text, comments, processing instructions, DOCTYPE, CDATA.  The text of
// the elements is not copied: elements keep ranges of the document.  The content of a VTK
// `<AppendedData>` element (raw binary after a `_`) is not parsed as XML: it runs to the last
// `</AppendedData>` of the document.

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {

struct Xml_element {
  std::string_view name;
  std::vector<std::pair<std::string_view, std::string>> attributes;
  std::vector<std::size_t> children;                           // indices in Xml_document::elements
  std::vector<std::pair<std::size_t, std::size_t>> text_parts; // [begin, end) of the direct text
  std::size_t line = 0;

  /// the value of attribute `key`, or `nullptr`
  const std::string* attribute(std::string_view key) const {
    for (const auto& a : attributes)
      if (a.first == key) return &a.second;
    return nullptr;
  }
};

class Xml_document {
public:
  /// Parses `text`; throws `Read_error` (with the line number) on malformed XML.
  Xml_document(std::string_view text, const std::string& name) : text_(text), name_(name) { parse(); }

  const std::vector<Xml_element>& elements() const { return elements_; }
  const Xml_element& root() const { return elements_.front(); }
  const Xml_element& element(std::size_t i) const { return elements_[i]; }
  std::string_view text() const { return text_; }

  /// the raw content of `<AppendedData>` after its `_` marker (empty view when absent)
  bool has_appended_data() const { return appended_element_ != npos; }
  const Xml_element& appended_element() const { return elements_[appended_element_]; }
  std::string_view appended_data() const {
    return text_.substr(appended_begin_, appended_end_ - appended_begin_);
  }

  /// the direct text of an element (copied only when it comes in several parts)
  std::string_view element_text(const Xml_element& e, std::string& storage) const {
    if (e.text_parts.empty()) return std::string_view();
    if (e.text_parts.size() == 1)
      return text_.substr(e.text_parts[0].first, e.text_parts[0].second - e.text_parts[0].first);
    storage.clear();
    for (const auto& p : e.text_parts) {
      storage.append(text_.data() + p.first, p.second - p.first);
      storage += ' ';
    }
    return storage;
  }

  /// the 1-based line of a position of the text
  std::size_t line_of(std::size_t offset) const {
    if (offset < line_pos_) {
      line_pos_ = 0;
      line_ = 1;
    }
    for (; line_pos_ < offset && line_pos_ < text_.size(); ++line_pos_)
      if (text_[line_pos_] == '\n') ++line_;
    return line_;
  }

  [[noreturn]] void fail(std::size_t offset, const std::string& message) const {
    throw Read_error(name_, line_of(offset), message);
  }

private:
  static constexpr std::size_t npos = std::size_t(-1);

  static bool is_name_char(char c) {
    return !is_space(c) && c != '/' && c != '>' && c != '=' && c != '<' && c != '"' && c != '\'';
  }

  std::size_t skip_to(std::size_t pos, std::string_view end_marker, const char* what) const {
    const std::size_t e = text_.find(end_marker, pos);
    if (e == std::string_view::npos) fail(pos, std::string("unterminated ") + what);
    return e + end_marker.size();
  }

  std::string decode_entities(std::size_t begin, std::size_t end) const {
    std::string r;
    for (std::size_t i = begin; i < end; ++i) {
      if (text_[i] != '&') {
        r += text_[i];
        continue;
      }
      const std::size_t semi = text_.find(';', i);
      if (semi == std::string_view::npos || semi >= end || semi - i > 10) {
        r += '&';
        continue;
      }
      const std::string_view ent = text_.substr(i + 1, semi - i - 1);
      if (ent == "lt")
        r += '<';
      else if (ent == "gt")
        r += '>';
      else if (ent == "amp")
        r += '&';
      else if (ent == "quot")
        r += '"';
      else if (ent == "apos")
        r += '\'';
      else if (ent.size() > 1 && ent[0] == '#') {
        long long code = 0;
        bool ok = true;
        const bool hex = ent[1] == 'x' || ent[1] == 'X';
        for (std::size_t k = hex ? 2 : 1; k < ent.size() && ok; ++k) {
          const char c = ent[k];
          const int d = (c >= '0' && c <= '9')          ? c - '0'
                        : hex && (c >= 'a' && c <= 'f') ? c - 'a' + 10
                        : hex && (c >= 'A' && c <= 'F') ? c - 'A' + 10
                                                        : -1;
          if (d < 0) ok = false;
          code = code * (hex ? 16 : 10) + d;
          if (code > 0x10FFFF) ok = false;
        }
        if (!ok || code == 0) fail(i, "invalid character reference &" + std::string(ent) + ";");
        if (code < 0x80) {
          r += char(code);
        } else if (code < 0x800) {
          r += char(0xC0 | (code >> 6));
          r += char(0x80 | (code & 0x3F));
        } else if (code < 0x10000) {
          r += char(0xE0 | (code >> 12));
          r += char(0x80 | ((code >> 6) & 0x3F));
          r += char(0x80 | (code & 0x3F));
        } else {
          r += char(0xF0 | (code >> 18));
          r += char(0x80 | ((code >> 12) & 0x3F));
          r += char(0x80 | ((code >> 6) & 0x3F));
          r += char(0x80 | (code & 0x3F));
        }
      } else {
        fail(i, "unknown XML entity &" + std::string(ent) + ";");
      }
      i = semi;
    }
    return r;
  }

  void add_text(std::size_t begin, std::size_t end, const std::vector<std::size_t>& stack) {
    bool blank = true;
    for (std::size_t i = begin; i < end && blank; ++i) blank = is_space(text_[i]);
    if (blank) return;
    if (stack.empty()) fail(begin, "text outside of the root element");
    elements_[stack.back()].text_parts.emplace_back(begin, end);
  }

  void parse() {
    std::size_t pos = 0;
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos = 3; // UTF-8 byte order mark
    std::vector<std::size_t> stack;
    bool root_closed = false;
    const std::size_t n = text_.size();
    while (pos < n) {
      if (text_[pos] != '<') {
        std::size_t e = text_.find('<', pos);
        if (e == std::string_view::npos) e = n;
        add_text(pos, e, stack);
        pos = e;
        continue;
      }
      const std::string_view rest = text_.substr(pos);
      if (rest.substr(0, 4) == "<!--") {
        pos = skip_to(pos + 4, "-->", "comment");
      } else if (rest.substr(0, 9) == "<![CDATA[") {
        const std::size_t e = skip_to(pos + 9, "]]>", "CDATA section");
        if (stack.empty()) fail(pos, "CDATA section outside of the root element");
        elements_[stack.back()].text_parts.emplace_back(pos + 9, e - 3);
        pos = e;
      } else if (rest.substr(0, 2) == "<?") {
        pos = skip_to(pos + 2, "?>", "processing instruction");
      } else if (rest.substr(0, 2) == "<!") {
        pos = skip_to(pos + 2, ">", "declaration");
      } else if (rest.substr(0, 2) == "</") {
        std::size_t p = pos + 2;
        const std::size_t b = p;
        while (p < n && is_name_char(text_[p])) ++p;
        const std::string_view tag = text_.substr(b, p - b);
        while (p < n && is_space(text_[p])) ++p;
        if (p >= n || text_[p] != '>') fail(pos, "malformed end tag </" + std::string(tag) + ">");
        if (stack.empty()) fail(pos, "end tag </" + std::string(tag) + "> without a start tag");
        const Xml_element& open = elements_[stack.back()];
        if (open.name != tag)
          fail(pos, "end tag </" + std::string(tag) + "> does not match <" + std::string(open.name) +
                        "> of line " + std::to_string(open.line));
        stack.pop_back();
        if (stack.empty()) root_closed = true;
        pos = p + 1;
      } else {
        pos = parse_start_tag(pos, stack, root_closed);
      }
    }
    if (!stack.empty()) {
      const Xml_element& open = elements_[stack.back()];
      throw Read_error(name_, line_of(n),
                       "unexpected end of file: element <" + std::string(open.name) + "> of line " +
                           std::to_string(open.line) + " is not closed");
    }
    if (elements_.empty()) throw Read_error(name_, 0, "no XML element (empty or not an XML file)");
  }

  std::size_t parse_start_tag(std::size_t pos, std::vector<std::size_t>& stack, bool root_closed) {
    const std::size_t n = text_.size();
    std::size_t p = pos + 1;
    const std::size_t b = p;
    while (p < n && is_name_char(text_[p])) ++p;
    if (p == b) fail(pos, "malformed tag (no element name after '<')");
    if (stack.empty() && (root_closed || !elements_.empty())) fail(pos, "more than one root element");
    Xml_element e;
    e.name = text_.substr(b, p - b);
    e.line = line_of(pos);
    bool empty_element = false;
    for (;;) {
      while (p < n && is_space(text_[p])) ++p;
      if (p >= n) fail(pos, "unterminated tag <" + std::string(e.name) + ">");
      if (text_[p] == '>') {
        ++p;
        break;
      }
      if (text_[p] == '/') {
        if (p + 1 >= n || text_[p + 1] != '>')
          fail(p, "malformed tag <" + std::string(e.name) + ">: '/' not followed by '>'");
        p += 2;
        empty_element = true;
        break;
      }
      const std::size_t ab = p;
      while (p < n && is_name_char(text_[p])) ++p;
      if (p == ab) fail(p, "malformed attribute in tag <" + std::string(e.name) + ">");
      const std::string_view key = text_.substr(ab, p - ab);
      while (p < n && is_space(text_[p])) ++p;
      if (p >= n || text_[p] != '=') fail(p, "attribute '" + std::string(key) + "' without a value");
      ++p;
      while (p < n && is_space(text_[p])) ++p;
      if (p >= n || (text_[p] != '"' && text_[p] != '\''))
        fail(p, "the value of attribute '" + std::string(key) + "' must be quoted");
      const char q = text_[p];
      const std::size_t ve = text_.find(q, p + 1);
      if (ve == std::string_view::npos) fail(p, "unterminated value of attribute '" + std::string(key) + "'");
      if (e.attribute(key) != nullptr) fail(ab, "duplicate attribute '" + std::string(key) + "'");
      e.attributes.emplace_back(key, decode_entities(p + 1, ve));
      p = ve + 1;
    }
    const std::size_t index = elements_.size();
    if (!stack.empty()) elements_[stack.back()].children.push_back(index);
    const bool appended = e.name == "AppendedData" && !empty_element;
    elements_.push_back(std::move(e));
    if (empty_element) return p;
    stack.push_back(index);
    if (appended) {
      if (appended_element_ != npos) fail(pos, "more than one <AppendedData> element");
      std::size_t q = p;
      while (q < n && is_space(text_[q])) ++q;
      const std::size_t end = text_.rfind("</AppendedData>");
      if (end == std::string_view::npos || end < q)
        fail(pos, "<AppendedData> is not closed by </AppendedData>");
      if (q == end) { // empty appended data
        appended_begin_ = appended_end_ = end;
      } else {
        if (text_[q] != '_') fail(q, "the content of <AppendedData> must start with '_'");
        appended_begin_ = q + 1;
        appended_end_ = end;
      }
      appended_element_ = index;
      return end;
    }
    return p;
  }

  std::string_view text_;
  std::string name_;
  std::vector<Xml_element> elements_;
  std::size_t appended_element_ = npos, appended_begin_ = 0, appended_end_ = 0;
  mutable std::size_t line_pos_ = 0, line_ = 1;
};

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_XML_H
