// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_GMSH_READER_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_GMSH_READER_H

// The gmsh `.msh` reader (versions 2.2 and 4.1, ASCII and binary), behind `read_gmsh()` of
// `CGAL/PR_star_octree/IO/gmsh.h`.  The file is held in memory; one cursor (the readers' `Byte_cursor`)
// reads its text parts (tokens, with line numbers) and its binary parts (fixed-size values, with byte
// offsets).

#include <CGAL/PR_star_octree/IO/Memory_limit.h>
#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/internal/file_bytes.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {

/// Number of nodes and name of a gmsh element type; `{0, nullptr}` for a type this reader does
/// not know.
struct Gmsh_element_type {
  int nodes;
  const char* name;
};

inline Gmsh_element_type gmsh_element_type(long long type) {
  switch (type) {
  case 1:
    return {2, "line"};
  case 2:
    return {3, "triangle"};
  case 3:
    return {4, "quadrangle"};
  case 4:
    return {4, "tetrahedron"};
  case 5:
    return {8, "hexahedron"};
  case 6:
    return {6, "prism"};
  case 7:
    return {5, "pyramid"};
  case 8:
    return {3, "line3"};
  case 9:
    return {6, "triangle6"};
  case 10:
    return {9, "quadrangle9"};
  case 11:
    return {10, "tetrahedron10"};
  case 12:
    return {27, "hexahedron27"};
  case 13:
    return {18, "prism18"};
  case 14:
    return {14, "pyramid14"};
  case 15:
    return {1, "point"};
  case 16:
    return {8, "quadrangle8"};
  case 17:
    return {20, "hexahedron20"};
  case 18:
    return {15, "prism15"};
  case 19:
    return {13, "pyramid13"};
  case 20:
    return {9, "triangle9"};
  case 21:
    return {10, "triangle10"};
  case 22:
    return {12, "triangle12"};
  case 23:
    return {15, "triangle15"};
  case 24:
    return {15, "triangle15i"};
  case 25:
    return {21, "triangle21"};
  case 26:
    return {4, "line4"};
  case 27:
    return {5, "line5"};
  case 28:
    return {6, "line6"};
  case 29:
    return {20, "tetrahedron20"};
  case 30:
    return {35, "tetrahedron35"};
  case 31:
    return {56, "tetrahedron56"};
  case 92:
    return {64, "hexahedron64"};
  case 93:
    return {125, "hexahedron125"};
  default:
    return {0, nullptr};
  }
}

/// Whether elements of this gmsh type are tetrahedra (linear or of higher order: their first 4
/// nodes are the corners).
inline bool is_gmsh_tetrahedron(long long type) {
  return type == 4 || type == 11 || type == 29 || type == 30 || type == 31;
}

/// Node tag -> 0-based vertex index: a dense table when the tags are compact enough, otherwise a
/// sorted array searched by bisection.
template <class Index>
class Gmsh_node_map {
public:
  static constexpr Index none = std::numeric_limits<Index>::max();

  /// Builds the map from the tags in file order; returns the first duplicated tag, or 0.
  std::uint64_t build(const std::vector<std::uint64_t>& tags) {
    dense_.clear();
    sorted_.clear();
    if (tags.empty()) return 0;
    const auto mm = std::minmax_element(tags.begin(), tags.end());
    min_ = *mm.first;
    const std::uint64_t span = *mm.second - min_;
    if (span < 4 * std::uint64_t(tags.size()) + 1024) {
      dense_.assign(static_cast<std::size_t>(span + 1), none);
      for (std::size_t i = 0; i < tags.size(); ++i) {
        Index& slot = dense_[static_cast<std::size_t>(tags[i] - min_)];
        if (slot != none) return tags[i];
        slot = static_cast<Index>(i);
      }
    } else {
      sorted_.resize(tags.size());
      for (std::size_t i = 0; i < tags.size(); ++i) sorted_[i] = {tags[i], static_cast<Index>(i)};
      std::sort(sorted_.begin(), sorted_.end());
      for (std::size_t i = 1; i < sorted_.size(); ++i)
        if (sorted_[i].first == sorted_[i - 1].first) return sorted_[i].first;
    }
    return 0;
  }

  /// The vertex index of `tag`, or `none`.
  Index find(std::uint64_t tag) const {
    if (!dense_.empty()) {
      const std::uint64_t k = tag - min_; // wraps for tag < min_
      return (tag >= min_ && k < dense_.size()) ? dense_[static_cast<std::size_t>(k)] : none;
    }
    const auto it = std::lower_bound(sorted_.begin(), sorted_.end(), std::make_pair(tag, Index(0)));
    return (it != sorted_.end() && it->first == tag) ? it->second : none;
  }

private:
  std::uint64_t min_ = 0;
  std::vector<Index> dense_;
  std::vector<std::pair<std::uint64_t, Index>> sorted_;
};

/// Reads a whole `.msh` file held in memory into `result`.
template <class Mesh>
class Gmsh_reader : private Byte_cursor {
  using Point_3 = typename Mesh::Point_3;
  using Index = typename Mesh::Index;

public:
  Gmsh_reader(std::string_view data, std::string name) : Byte_cursor(data, std::move(name)) {}

  void read(Mesh& result) {
    read_mesh_format();
    bool& has_nodes = has_nodes_;
    bool& has_elements = has_elements_;
    std::string_view section;
    while (next_section(section)) {
      if (section == "$PhysicalNames") {
        read_physical_names();
      } else if (section == "$Entities" && version_ == 41) {
        if (has_entities_) fail("duplicate $Entities section");
        if (has_elements) fail("$Entities after $Elements");
        read_entities(false);
        has_entities_ = true;
      } else if (section == "$PartitionedEntities" && version_ == 41) {
        if (has_elements) fail("$PartitionedEntities after $Elements");
        read_entities(true);
      } else if (section == "$Nodes") {
        if (has_nodes) fail("duplicate $Nodes section");
        if (version_ == 41)
          read_nodes_41();
        else
          read_nodes_22();
        build_node_map();
        has_nodes = true;
      } else if (section == "$Elements") {
        if (has_elements) fail("duplicate $Elements section");
        if (!has_nodes) fail("$Elements before $Nodes");
        if (version_ == 41)
          read_elements_41();
        else
          read_elements_22();
        sort_by_element_tag();
        has_elements = true;
      } else if (section == "$NodeData") {
        read_data(false);
      } else if (section == "$ElementData") {
        read_data(true);
      } else if (section == "$MeshFormat") {
        fail("duplicate $MeshFormat section");
      } else {
        skip_section(section);
        continue;
      }
      expect_end(section);
    }
    if (!has_nodes) fail("no $Nodes section");
    if (!has_elements) fail("no $Elements section");
    if (!any_label_) mesh_.tetrahedron_labels.clear();
    // the views with a value for every node or tetrahedron become data arrays, the others are dropped
    const auto complete = [](const std::vector<double>& v) {
      return std::none_of(v.begin(), v.end(), [](double x) { return std::isnan(x); });
    };
    for (Data_view& v : node_views_)
      if (complete(v.values)) mesh_.point_data.push_back({std::move(v.name), std::move(v.values)});
    for (Data_view& v : element_views_)
      if (complete(v.values)) mesh_.cell_data.push_back({std::move(v.name), std::move(v.values)});
    result = std::move(mesh_);
  }

private:
  // ---- errors: FILE:LINE for text files, FILE: byte N for binary ones
  [[noreturn]] void fail(const std::string& message) const {
    if (binary_) throw Read_error(name_, 0, "byte " + std::to_string(pos_) + ": " + message);
    // the line is counted only now: reading does not count line breaks
    const std::size_t at = std::min(pos_, data_.size());
    throw Read_error(name_, 1 + static_cast<std::size_t>(std::count(data_.begin(), data_.begin() + at, '\n')),
                     message);
  }
  [[noreturn]] void fail_eof(const char* what) const {
    fail(std::string("unexpected end of file, expected ") + what);
  }

  // ---- text
  static bool space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
  }

  /// Skips white space; false at the end of the data.
  bool skip_space() {
    const std::size_t n = data_.size();
    while (pos_ < n && space(data_[pos_])) ++pos_;
    return pos_ < n;
  }
  std::string_view token(const char* what) {
    if (!skip_space()) fail_eof(what);
    const std::size_t b = pos_;
    while (pos_ < data_.size() && !space(data_[pos_])) ++pos_;
    return data_.substr(b, pos_ - b);
  }
  long long integer(const char* what) {
    long long v;
    if (skip_space()) { // fast path: plain digits
      if (const char* e = scan_plain_integer(data_.data() + pos_, data_.data() + data_.size(), v, 0)) {
        pos_ = static_cast<std::size_t>(e - data_.data());
        return v;
      }
    }
    const std::string_view t = token(what);
    if (const char* why = parse_integer(t, v)) fail(std::string(what) + " " + quote(t) + " " + why);
    return v;
  }
  /// A non-negative integer.
  std::uint64_t count(const char* what) {
    const long long v = integer(what);
    if (v < 0) fail(std::string(what) + " " + std::to_string(v) + " is negative");
    return static_cast<std::uint64_t>(v);
  }
  /// An integer that fits in an int (entity and physical tags, dimensions...).
  int small_int(const char* what) {
    const long long v = integer(what);
    if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
      fail(std::string(what) + " " + std::to_string(v) + " is out of the int range");
    return static_cast<int>(v);
  }
  double real(const char* what) {
    double v;
    if (skip_space()) { // fast path: a plain finite number
      if (const char* e = scan_plain_double(data_.data() + pos_, data_.data() + data_.size(), v, 0)) {
        pos_ = static_cast<std::size_t>(e - data_.data());
        return v;
      }
    }
    const std::string_view t = token(what);
    if (const char* why = parse_double(t, v)) fail(std::string(what) + " " + quote(t) + " " + why);
    return v;
  }
  /// Consumes the rest of the current line, which must be blank.
  void end_line(const char* after) {
    while (pos_ < data_.size() && (data_[pos_] == ' ' || data_[pos_] == '\t' || data_[pos_] == '\r')) ++pos_;
    if (pos_ >= data_.size()) fail_eof("a line break");
    if (data_[pos_] != '\n')
      fail(std::string("unexpected data after ") + after + ": " + quote(data_.substr(pos_, 20)));
    ++pos_;
  }
  /// Moves past the next line break.
  void skip_line(const char* what) {
    const std::size_t eol = data_.find('\n', pos_);
    if (eol == std::string_view::npos) fail_eof(what);
    pos_ = eol + 1;
  }

  // ---- binary
  template <class T>
  T bin(const char* what) {
    return get<T>(what); // binary parts only: the cursor's error is the one of fail() ("byte N: ...")
  }
  /// A gmsh 4.1 `size_t` (data-size bytes).
  std::uint64_t bin_size(const char* what) {
    return size_bytes_ == 4 ? std::uint64_t(bin<std::uint32_t>(what)) : bin<std::uint64_t>(what);
  }
  /// Fails unless `count` items of `bytes` bytes each fit in what remains of the file.
  void need_items(std::uint64_t count, std::size_t bytes, const char* what) {
    if (!fits(count, bytes))
      fail(std::to_string(count) + " " + what + " announced, but only " + std::to_string(remaining()) +
           " bytes are left in the file (" + std::to_string(bytes) + " bytes each)");
  }

  // ---- sections
  bool next_section(std::string_view& section) {
    if (!skip_space()) return false;
    section = token("a section");
    if (section.empty() || section[0] != '$' || section.size() < 2 || section.substr(0, 4) == "$End")
      fail("expected a section such as $Nodes or $Elements, found " + quote(section));
    return true;
  }
  void expect_end(std::string_view section) {
    const std::string end = "$End" + std::string(section.substr(1));
    const std::string_view t = token(end.c_str());
    if (t != end)
      fail("expected " + end + ", found " + quote(t) + " (the counts of the section disagree with its data)");
  }
  void skip_section(std::string_view section) {
    const std::string end = "\n$End" + std::string(section.substr(1));
    std::size_t at = data_.find(end, pos_);
    // the end marker must end its line
    while (at != std::string_view::npos && at + end.size() < data_.size() && !space(data_[at + end.size()]))
      at = data_.find(end, at + 1);
    if (at == std::string_view::npos)
      fail("unexpected end of file: no " + end.substr(1) + " for " + std::string(section));
    pos_ = at + end.size();
  }

  void read_mesh_format() {
    if (!skip_space()) fail("empty file: expected $MeshFormat");
    const std::string_view first = token("$MeshFormat");
    if (first != "$MeshFormat") fail("not a gmsh .msh file: expected $MeshFormat, found " + quote(first));
    const std::string_view v = token("the format version");
    if (v == "4.1")
      version_ = 41;
    else if (v == "2.2" || v == "2.1" || v == "2" || v == "2.0")
      version_ = 22;
    else
      fail("unsupported .msh format version " + quote(v) +
           " (2.2 and 4.1 are read; gmsh converts with -format msh41)");
    const long long type = integer("the file type");
    if (type != 0 && type != 1) fail("file type " + std::to_string(type) + " (0 for ASCII, 1 for binary)");
    const long long size = integer("the data size");
    if (version_ == 22 && size != 8)
      fail("data size " + std::to_string(size) + " is not supported (8 for doubles)");
    if (version_ == 41 && size != 8 && size != 4)
      fail("data size " + std::to_string(size) + " is not supported (size_t of 4 or 8 bytes)");
    size_bytes_ = static_cast<std::size_t>(size);
    if (type == 1) {
      end_line("the format line");
      binary_ = true;
      if (remaining() < 4) fail_eof("the endianness integer 1");
      if (!take_byte_order_mark())
        fail("bad endianness integer " + std::to_string(load_value<std::int32_t>(here(), false)) +
             " (must be 1 in either byte order)");
    }
    expect_end("$MeshFormat");
  }

  void read_physical_names() {
    const std::uint64_t n = count("number of physical names");
    for (std::uint64_t i = 0; i < n; ++i) {
      const int dim = small_int("physical dimension");
      const int tag = small_int("physical tag");
      if (!skip_space()) fail_eof("a physical name");
      if (data_[pos_] != '"') fail("expected a quoted physical name, found " + quote(data_.substr(pos_, 20)));
      const std::size_t close = data_.find_first_of("\"\n", pos_ + 1);
      if (close == std::string_view::npos || data_[close] != '"') fail("unterminated physical name");
      const std::string_view name = data_.substr(pos_ + 1, close - pos_ - 1);
      pos_ = close + 1;
      if (dim == 3) mesh_.label_names[tag] = std::string(name);
    }
  }

  // $Entities, or $PartitionedEntities (`partitioned`): the first physical tag of each volume is kept
  int entity_int(const char* what) { return binary_ ? bin<std::int32_t>(what) : small_int(what); }
  std::uint64_t entity_count(const char* what, std::size_t item_bytes) {
    const std::uint64_t n = binary_ ? bin_size(what) : count(what);
    if (binary_) need_items(n, item_bytes, what);
    return n;
  }
  void read_entities(bool partitioned) {
    if (binary_) end_line(partitioned ? "$PartitionedEntities" : "$Entities");
    if (partitioned) {
      volume_physical_.clear(); // the element blocks name partitioned entities
      entity_count("number of partitions", 0);
      const std::uint64_t ghosts = entity_count("number of ghost entities", 8);
      for (std::uint64_t k = 0; k < 2 * ghosts; ++k) entity_int("ghost entity");
    }
    std::uint64_t n[4];
    for (std::uint64_t& k : n) k = entity_count("number of entities", 0);
    for (int dim = 0; dim < 4; ++dim) {
      for (std::uint64_t i = 0; i < n[dim]; ++i) {
        const int tag = entity_int("entity tag");
        if (partitioned) {
          entity_int("parent dimension");
          entity_int("parent tag");
          const std::uint64_t parts = entity_count("number of partitions", 4);
          for (std::uint64_t k = 0; k < parts; ++k) entity_int("partition tag");
        }
        for (int k = 0; k < (dim == 0 ? 3 : 6); ++k)
          binary_ ? bin<double>("entity box") : real("entity coordinate");
        const std::uint64_t nphys = entity_count("number of physical tags", 4);
        int first = 0;
        for (std::uint64_t k = 0; k < nphys; ++k) {
          const int p = entity_int("physical tag");
          if (k == 0) first = p;
        }
        if (dim == 3 && nphys > 0) volume_physical_[tag] = first;
        if (dim > 0) {
          const std::uint64_t nb = entity_count("number of bounding entities", 4);
          for (std::uint64_t k = 0; k < nb; ++k) entity_int("bounding entity tag");
        }
      }
    }
  }

  void advise_node_arrays() {
    advise_huge_pages(mesh_.points.data(), mesh_.points.capacity() * sizeof(Point_3));
    advise_huge_pages(tags_.data(), tags_.capacity() * sizeof(std::uint64_t));
  }
  void check_node_count(std::uint64_t n) {
    if (n >= static_cast<std::uint64_t>(std::numeric_limits<Index>::max()))
      fail(std::to_string(n) + " nodes do not fit in the index type of the mesh");
  }
  void add_point(double x, double y, double z, std::size_t i) {
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      fail("node " + std::to_string(i + 1) + ": coordinate is not finite");
    mesh_.points.push_back(Point_3(x, y, z));
  }

  void read_nodes_41() {
    std::uint64_t blocks, total;
    if (binary_) {
      end_line("$Nodes");
      blocks = bin_size("$Nodes header");
      total = bin_size("$Nodes header");
      bin_size("$Nodes header");
      bin_size("$Nodes header");
      check_node_count(total);
      need_items(total, size_bytes_ + 24, "nodes");
    } else {
      blocks = count("number of node blocks");
      total = count("number of nodes");
      count("minimum node tag");
      count("maximum node tag");
      check_node_count(total);
    }
    const std::size_t left = data_.size() - pos_;
    check_memory_if_present(name_, 0, total, 0, sizeof(typename Mesh::Point_3) + 8,
                            sizeof(typename Mesh::Tetrahedron) + sizeof(int), total,
                            binary_ ? size_bytes_ + 24 : 8, left);
    capped_reserve(mesh_.points, static_cast<std::size_t>(std::min<std::uint64_t>(total, left)), left,
                   binary_ ? size_bytes_ + 24 : 8);
    capped_reserve(tags_, static_cast<std::size_t>(std::min<std::uint64_t>(total, left)), left,
                   binary_ ? size_bytes_ + 24 : 8);
    advise_node_arrays();
    for (std::uint64_t b = 0; b < blocks; ++b) {
      int dim, parametric;
      std::uint64_t n;
      if (binary_) {
        dim = bin<std::int32_t>("node block header");
        bin<std::int32_t>("node block header");
        parametric = bin<std::int32_t>("node block header");
        n = bin_size("node block header");
      } else {
        dim = small_int("entity dimension");
        small_int("entity tag");
        parametric = small_int("parametric flag");
        n = count("number of nodes in the block");
      }
      if (dim < 0 || dim > 3) fail("entity dimension " + std::to_string(dim) + " (0 to 3)");
      if (parametric != 0 && parametric != 1)
        fail("parametric flag " + std::to_string(parametric) + " (0 or 1)");
      if (n > total - tags_.size())
        fail("node block of " + std::to_string(n) + " nodes: more nodes than the " + std::to_string(total) +
             " announced");
      const std::size_t values = 3 + (parametric ? static_cast<std::size_t>(dim) : 0);
      const std::size_t first = tags_.size();
      if (binary_) {
        need_items(n, size_bytes_ + 8 * values, "nodes");
        const std::size_t nn = static_cast<std::size_t>(n);
        const char* p = data_.data() + pos_;
        for (std::size_t i = 0; i < nn; ++i) {
          const std::uint64_t tag = size_bytes_ == 8 ? load_value<std::uint64_t>(p + 8 * i, swap_)
                                                     : load_value<std::uint32_t>(p + 4 * i, swap_);
          if (tag == 0) fail("node tag 0 (tags start at 1)");
          tags_.push_back(tag);
        }
        pos_ += nn * size_bytes_;
        p = data_.data() + pos_;
        for (std::size_t i = 0; i < nn; ++i, p += 8 * values)
          add_point(load_value<double>(p, swap_), load_value<double>(p + 8, swap_),
                    load_value<double>(p + 16, swap_), first + i);
        pos_ += nn * 8 * values;
      } else {
        for (std::uint64_t i = 0; i < n; ++i) {
          const std::uint64_t tag = count("node tag");
          if (tag == 0) fail("node tag 0 (tags start at 1)");
          tags_.push_back(tag);
        }
        for (std::uint64_t i = 0; i < n; ++i) {
          const double x = real("x coordinate"), y = real("y coordinate"), z = real("z coordinate");
          for (std::size_t k = 3; k < values; ++k) real("parametric coordinate");
          add_point(x, y, z, static_cast<std::size_t>(first + i));
        }
      }
    }
    if (tags_.size() != total)
      fail(std::to_string(tags_.size()) + " nodes in the blocks, " + std::to_string(total) + " announced");
  }

  void read_nodes_22() {
    const std::uint64_t n = count("number of nodes");
    check_node_count(n);
    if (binary_) {
      end_line("the number of nodes");
      need_items(n, 28, "nodes");
    }
    const std::size_t left = data_.size() - pos_;
    check_memory_if_present(name_, 0, n, 0, sizeof(typename Mesh::Point_3) + 8,
                            sizeof(typename Mesh::Tetrahedron) + sizeof(int), n, binary_ ? 28 : 8, left);
    const std::size_t cap = static_cast<std::size_t>(std::min<std::uint64_t>(n, left));
    capped_reserve(mesh_.points, cap, left, binary_ ? 28 : 8);
    capped_reserve(tags_, cap, left, binary_ ? 28 : 8);
    advise_node_arrays();
    if (binary_) {
      const char* p = data_.data() + pos_;
      for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i, p += 28) {
        const std::int32_t tag = load_value<std::int32_t>(p, swap_);
        if (tag <= 0)
          fail("node " + std::to_string(i + 1) + ": tag " + std::to_string(tag) + " (tags start at 1)");
        tags_.push_back(static_cast<std::uint64_t>(tag));
        add_point(load_value<double>(p + 4, swap_), load_value<double>(p + 12, swap_),
                  load_value<double>(p + 20, swap_), i);
      }
      pos_ += static_cast<std::size_t>(n) * 28;
    } else {
      for (std::uint64_t i = 0; i < n; ++i) {
        const std::uint64_t tag = count("node tag");
        if (tag == 0) fail("node tag 0 (tags start at 1)");
        tags_.push_back(tag);
        const double x = real("x coordinate"), y = real("y coordinate"), z = real("z coordinate");
        add_point(x, y, z, static_cast<std::size_t>(i));
      }
    }
  }

  void build_node_map() {
    if (const std::uint64_t dup = nodes_.build(tags_))
      fail("node tag " + std::to_string(dup) + " defined twice");
    tags_.clear();
    tags_.shrink_to_fit();
  }

  Index node(std::uint64_t tag, std::uint64_t element) const {
    const Index v = nodes_.find(tag);
    if (v == nodes_.none)
      fail("element " + std::to_string(element) + ": node tag " + std::to_string(tag) + " is not in $Nodes");
    return v;
  }
  void add_tetrahedron(const std::uint64_t (&tags)[4], std::uint64_t element, int physical) {
    typename Mesh::Tetrahedron t;
    for (int k = 0; k < 4; ++k) t[k] = node(tags[k], element);
    Index twice;
    if (has_repeated_vertex(t, twice))
      fail("element " + std::to_string(element) + ": a tetrahedron listing a node twice");
    note_tetrahedron_tag(element);
    mesh_.tetrahedra.push_back(t);
    mesh_.tetrahedron_labels.push_back(physical);
    if (physical != 0) any_label_ = true;
  }
  /// Reserves room for at most `n` tetrahedra, and no more than the rest of the file can hold at
  /// `min_bytes` bytes per tetrahedron.
  void reserve_tetrahedra(std::uint64_t n, std::size_t min_bytes) {
    const std::size_t left = data_.size() - pos_;
    check_memory_if_present(name_, 0, mesh_.points.size(), n, sizeof(typename Mesh::Point_3) + 8,
                            sizeof(typename Mesh::Tetrahedron) + sizeof(int), n, min_bytes, left);
    const std::size_t k = static_cast<std::size_t>(std::min<std::uint64_t>(n, left / min_bytes + 1));
    mesh_.tetrahedra.reserve(k);
    mesh_.tetrahedron_labels.reserve(k);
    advise_huge_pages(mesh_.tetrahedra.data(),
                      mesh_.tetrahedra.capacity() * sizeof(typename Mesh::Tetrahedron));
    advise_huge_pages(mesh_.tetrahedron_labels.data(), mesh_.tetrahedron_labels.capacity() * sizeof(int));
  }
  void skipped(const char* name, std::uint64_t n) {
    if (n != 0) mesh_.skipped_cells[name] += static_cast<std::size_t>(n);
  }

  void read_elements_41() {
    std::uint64_t blocks, total;
    if (binary_) {
      end_line("$Elements");
      blocks = bin_size("$Elements header");
      total = bin_size("$Elements header");
      bin_size("$Elements header");
      bin_size("$Elements header");
    } else {
      blocks = count("number of element blocks");
      total = count("number of elements");
      count("minimum element tag");
      count("maximum element tag");
    }
    reserve_tetrahedra(total, binary_ ? 5 * size_bytes_ : 10);
    std::uint64_t seen = 0;
    for (std::uint64_t b = 0; b < blocks; ++b) {
      int dim, entity;
      long long type;
      std::uint64_t n;
      if (binary_) {
        dim = bin<std::int32_t>("element block header");
        entity = bin<std::int32_t>("element block header");
        type = bin<std::int32_t>("element block header");
        n = bin_size("element block header");
      } else {
        dim = small_int("entity dimension");
        entity = small_int("entity tag");
        type = integer("element type");
        n = count("number of elements in the block");
      }
      if (n > total - seen)
        fail("element block of " + std::to_string(n) + " elements: more elements than the " +
             std::to_string(total) + " announced");
      seen += n;
      const Gmsh_element_type et = gmsh_element_type(type);
      if (et.nodes == 0) {
        if (binary_) fail("unknown element type " + std::to_string(type));
        skip_element_lines(n);
        mesh_.skipped_cells["type " + std::to_string(type)] += static_cast<std::size_t>(n);
        continue;
      }
      const std::size_t npt = static_cast<std::size_t>(et.nodes);
      const bool tet = is_gmsh_tetrahedron(type);
      int physical = 0;
      if (tet && dim == 3) {
        const auto it = volume_physical_.find(entity);
        if (it != volume_physical_.end()) physical = it->second;
      }
      if (binary_) {
        const std::size_t per = (1 + npt) * size_bytes_;
        need_items(n, per, "elements");
        if (!tet) {
          for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i, pos_ += per)
            saw_element(size_bytes_ == 8 ? load_value<std::uint64_t>(data_.data() + pos_, swap_)
                                         : load_value<std::uint32_t>(data_.data() + pos_, swap_));
          skipped(et.name, n);
          continue;
        }
        std::uint64_t v[4];
        for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
          const char* p = data_.data() + pos_;
          const std::uint64_t tag =
              size_bytes_ == 8 ? load_value<std::uint64_t>(p, swap_) : load_value<std::uint32_t>(p, swap_);
          for (int k = 0; k < 4; ++k)
            v[k] = size_bytes_ == 8 ? load_value<std::uint64_t>(p + 8 * (k + 1), swap_)
                                    : load_value<std::uint32_t>(p + 4 * (k + 1), swap_);
          add_tetrahedron(v, tag, physical);
          pos_ += per;
        }
      } else {
        if (!tet) {
          skip_element_lines(n);
          skipped(et.name, n);
          continue;
        }
        std::uint64_t v[4];
        for (std::uint64_t i = 0; i < n; ++i) {
          const std::uint64_t tag = count("element tag");
          for (std::size_t k = 0; k < npt; ++k) {
            const std::uint64_t t = count("node tag");
            if (k < 4) v[k] = t;
          }
          add_tetrahedron(v, tag, physical);
        }
      }
    }
    if (seen != total)
      fail(std::to_string(seen) + " elements in the blocks, " + std::to_string(total) + " announced");
  }

  void read_elements_22() {
    const std::uint64_t total = count("number of elements");
    if (binary_) {
      end_line("the number of elements");
      need_items(total, 8, "elements");
      reserve_tetrahedra(total, 20);
      std::uint64_t seen = 0;
      while (seen < total) {
        const long long type = bin<std::int32_t>("element header");
        const std::int32_t follow = bin<std::int32_t>("element header");
        const std::int32_t ntags = bin<std::int32_t>("element header");
        const Gmsh_element_type et = gmsh_element_type(type);
        if (et.nodes == 0) fail("unknown element type " + std::to_string(type));
        if (follow <= 0 || ntags < 0)
          fail("element header: bad counts " + std::to_string(follow) + " " + std::to_string(ntags));
        if (static_cast<std::uint64_t>(follow) > total - seen)
          fail(std::to_string(follow) + " elements in a header: more elements than the " +
               std::to_string(total) + " announced");
        seen += static_cast<std::uint64_t>(follow);
        const std::size_t per =
            4 * (1 + static_cast<std::size_t>(ntags) + static_cast<std::size_t>(et.nodes));
        need_items(static_cast<std::uint64_t>(follow), per, "elements");
        if (!is_gmsh_tetrahedron(type)) {
          for (std::int32_t i = 0; i < follow; ++i, pos_ += per) {
            const std::int32_t tag = load_value<std::int32_t>(data_.data() + pos_, swap_);
            if (tag > 0) saw_element(static_cast<std::uint64_t>(tag));
          }
          skipped(et.name, static_cast<std::uint64_t>(follow));
          continue;
        }
        std::uint64_t v[4];
        for (std::int32_t i = 0; i < follow; ++i) {
          const char* p = data_.data() + pos_;
          const std::int32_t tag = load_value<std::int32_t>(p, swap_);
          const int physical = ntags > 0 ? load_value<std::int32_t>(p + 4, swap_) : 0;
          const char* nodes = p + 4 * (1 + static_cast<std::size_t>(ntags));
          for (int k = 0; k < 4; ++k) {
            const std::int32_t t = load_value<std::int32_t>(nodes + 4 * k, swap_);
            v[k] = t > 0 ? static_cast<std::uint64_t>(t) : 0;
          }
          add_tetrahedron(v, static_cast<std::uint64_t>(tag), physical);
          pos_ += per;
        }
      }
      return;
    }
    reserve_tetrahedra(total, 14);
    for (std::uint64_t i = 0; i < total; ++i) {
      const std::uint64_t tag = count("element tag");
      const long long type = integer("element type");
      const Gmsh_element_type et = gmsh_element_type(type);
      saw_element(tag);
      if (!is_gmsh_tetrahedron(type)) {
        if (et.nodes == 0)
          mesh_.skipped_cells["type " + std::to_string(type)] += 1;
        else
          skipped(et.name, 1);
        skip_line("an element");
        continue;
      }
      const std::uint64_t ntags = count("number of tags");
      int physical = 0;
      for (std::uint64_t k = 0; k < ntags; ++k) {
        const int t = small_int("element tag");
        if (k == 0) physical = t;
      }
      std::uint64_t v[4];
      for (int k = 0; k < et.nodes; ++k) {
        const std::uint64_t t = count("node tag");
        if (k < 4) v[k] = t;
      }
      add_tetrahedron(v, tag, physical);
    }
  }

  /// Skips the rest of an element block header line and `n` element lines (ASCII 4.1), noting the
  /// element tag that starts each.
  void skip_element_lines(std::uint64_t n) {
    skip_line("an element");
    for (std::uint64_t i = 0; i < n; ++i) {
      saw_element(count("element tag"));
      skip_line("an element");
    }
  }
  void saw_element(std::uint64_t tag) { max_element_tag_ = std::max(max_element_tag_, tag); }

  /// Records the element tag of the tetrahedron about to be added: `first_tet_tag_ + index` while
  /// they run consecutively (no array), then in `tet_tags_`.
  void note_tetrahedron_tag(std::uint64_t tag) {
    saw_element(tag);
    const std::size_t i = mesh_.tetrahedra.size();
    if (tags_consecutive_) {
      if (i == 0) first_tet_tag_ = tag;
      if (tag == first_tet_tag_ + i) return;
      check_memory(name_, 0, mesh_.points.size(), mesh_.tetrahedra.capacity(), sizeof(Point_3),
                   sizeof(typename Mesh::Tetrahedron) + sizeof(int), 0, 1);
      tet_tags_.reserve(mesh_.tetrahedra.capacity());
      for (std::size_t k = 0; k < i; ++k) tet_tags_.push_back(first_tet_tag_ + k);
      tags_consecutive_ = false;
    }
    tet_tags_.push_back(tag);
  }

  /// Puts the tetrahedra in the order of their element tags when the file does not list them so
  /// (a stable sort: equal tags keep the order of the file).  Tags that are a permutation of
  /// consecutive integers (the files of `write_gmsh()`, whose blocks group the tetrahedra by label)
  /// are put in place in linear time, and are then consecutive again.
  void sort_by_element_tag() {
    if (tags_consecutive_ || std::is_sorted(tet_tags_.begin(), tet_tags_.end())) return;
    const std::size_t n = tet_tags_.size();
    const auto mm = std::minmax_element(tet_tags_.begin(), tet_tags_.end());
    const std::uint64_t min = *mm.first;
    std::vector<std::size_t> order;               // order[i]: the index in the file of the i-th tetrahedron
    bool permutation = *mm.second - min == n - 1; // unless a tag repeats
    if (permutation) {
      order.assign(n, n);
      for (std::size_t i = 0; i < n && permutation; ++i) {
        std::size_t& slot = order[static_cast<std::size_t>(tet_tags_[i] - min)];
        permutation = slot == n;
        slot = i;
      }
    }
    if (!permutation) {
      order.resize(n);
      for (std::size_t i = 0; i < n; ++i) order[i] = i;
      std::stable_sort(order.begin(), order.end(),
                       [this](std::size_t a, std::size_t b) { return tet_tags_[a] < tet_tags_[b]; });
    }
    {
      std::vector<typename Mesh::Tetrahedron> t(n);
      for (std::size_t i = 0; i < n; ++i) t[i] = mesh_.tetrahedra[order[i]];
      mesh_.tetrahedra.swap(t);
    }
    {
      std::vector<int> l(n);
      for (std::size_t i = 0; i < n; ++i) l[i] = mesh_.tetrahedron_labels[order[i]];
      mesh_.tetrahedron_labels.swap(l);
    }
    if (permutation) {
      tags_consecutive_ = true;
      first_tet_tag_ = min;
      tet_tags_ = std::vector<std::uint64_t>();
      return;
    }
    std::vector<std::uint64_t> g(n);
    for (std::size_t i = 0; i < n; ++i) g[i] = tet_tags_[order[i]];
    tet_tags_.swap(g);
  }

  /// The tetrahedra whose element tag is `tag`, as a range of indices `[first, second)` (after
  /// `sort_by_element_tag()`).
  std::pair<std::size_t, std::size_t> tetrahedra_of_tag(std::uint64_t tag) const {
    const std::size_t n = mesh_.tetrahedra.size();
    if (tags_consecutive_) {
      if (n == 0 || tag < first_tet_tag_ || tag - first_tet_tag_ >= n) return {0, 0};
      const std::size_t k = static_cast<std::size_t>(tag - first_tet_tag_);
      return {k, k + 1};
    }
    const auto r = std::equal_range(tet_tags_.begin(), tet_tags_.end(), tag);
    return {static_cast<std::size_t>(r.first - tet_tags_.begin()),
            static_cast<std::size_t>(r.second - tet_tags_.begin())};
  }

  // ---- $NodeData and $ElementData

  /// A string tag: a quoted string, or the rest of the line when it does not start with a quote.
  std::string string_tag() {
    if (!skip_space()) fail_eof("a string tag");
    if (data_[pos_] == '"') {
      const std::size_t close = data_.find_first_of("\"\n", pos_ + 1);
      if (close == std::string_view::npos || data_[close] != '"') fail("unterminated string tag");
      const std::string r(data_.substr(pos_ + 1, close - pos_ - 1));
      pos_ = close + 1;
      return r;
    }
    const std::size_t eol = std::min(data_.find('\n', pos_), data_.size());
    const std::string r(trim(data_.substr(pos_, eol - pos_)));
    pos_ = eol;
    return r;
  }

  /// One `$NodeData` or `$ElementData` section (`elements`): a view of scalars is merged into the
  /// values of its name (a new time step replaces them), other views are skipped.
  void read_data(bool elements) {
    const std::string section = elements ? "$ElementData" : "$NodeData";
    if (!(elements ? has_elements_ : has_nodes_))
      fail(section + " before " + (elements ? "$Elements" : "$Nodes"));
    const std::uint64_t nstrings = count("number of string tags");
    std::string view;
    for (std::uint64_t k = 0; k < nstrings; ++k) {
      std::string t = string_tag();
      if (k == 0) view = std::move(t);
    }
    const std::uint64_t nreals = count("number of real tags");
    for (std::uint64_t k = 0; k < nreals; ++k) real("real tag");
    const std::uint64_t nints = count("number of integer tags");
    if (nints < 3)
      fail(section + " '" + view + "': " + std::to_string(nints) +
           " integer tags, at least 3 expected (time step, number of components, number of entries)");
    long long step = 0, components = 0;
    std::uint64_t n = 0;
    for (std::uint64_t k = 0; k < nints; ++k) {
      if (k == 0)
        step = integer("time step");
      else if (k == 1)
        components = integer("number of components");
      else if (k == 2)
        n = count("number of entries");
      else
        integer("integer tag");
    }
    if (components < 1 || components > (1 << 20))
      fail(section + " '" + view + "': " + std::to_string(components) + " components per entry");
    const std::size_t entry_bytes = 4 + 8 * static_cast<std::size_t>(components);
    if (binary_) {
      end_line("the integer tags");
      need_items(n, entry_bytes, "entries");
    }
    const char* what = elements ? "element tag" : "node tag";
    if (components != 1 || view.empty()) { // not a named scalar view: skipped
      if (binary_) {
        pos_ += static_cast<std::size_t>(n) * entry_bytes;
        return;
      }
      for (std::uint64_t i = 0; i < n; ++i) {
        count(what);
        for (long long c = 0; c < components; ++c) real("value");
      }
      return;
    }
    std::vector<Data_view>& views = elements ? element_views_ : node_views_;
    const std::size_t size = elements ? mesh_.tetrahedra.size() : mesh_.points.size();
    auto it = std::find_if(views.begin(), views.end(), [&](const Data_view& v) { return v.name == view; });
    if (it == views.end()) {
      check_memory(name_, 0, mesh_.points.size(), mesh_.tetrahedra.size(), sizeof(Point_3),
                   sizeof(typename Mesh::Tetrahedron) + sizeof(int), node_views_.size() + (elements ? 0 : 1),
                   element_views_.size() + (elements ? 1 : 0));
      views.push_back({view, step, std::vector<double>(size, std::numeric_limits<double>::quiet_NaN())});
      it = views.end() - 1;
    } else if (it->step != step) { // another time step: the last one in the file is kept
      it->step = step;
      std::fill(it->values.begin(), it->values.end(), std::numeric_limits<double>::quiet_NaN());
    }
    std::vector<double>& values = it->values;
    const auto where = [&](std::uint64_t tag) {
      return section + " '" + view + "': " + what + " " + std::to_string(tag);
    };
    for (std::uint64_t i = 0; i < n; ++i) {
      std::uint64_t tag;
      double value;
      if (binary_) {
        const std::int32_t t = load_value<std::int32_t>(data_.data() + pos_, swap_);
        if (t <= 0)
          fail(section + " '" + view + "': " + what + " " + std::to_string(t) + " (tags start at 1)");
        tag = static_cast<std::uint64_t>(t);
        value = load_value<double>(data_.data() + pos_ + 4, swap_);
      } else {
        tag = count(what);
        value = real("value");
      }
      if (!std::isfinite(value)) fail(where(tag) + ": the value is not finite");
      if (elements) {
        if (tag == 0 || tag > max_element_tag_) fail(where(tag) + " is not in $Elements");
        const auto r = tetrahedra_of_tag(tag); // empty for an element that is not a tetrahedron
        for (std::size_t k = r.first; k < r.second; ++k) values[k] = value;
      } else {
        const Index v = nodes_.find(tag);
        if (v == nodes_.none) fail(where(tag) + " is not in $Nodes");
        values[static_cast<std::size_t>(v)] = value;
      }
      if (binary_) pos_ += entry_bytes;
    }
  }

  /// The values of a view read so far (NaN: no value yet) and the time step they belong to.
  struct Data_view {
    std::string name;
    long long step;
    std::vector<double> values;
  };

  int version_ = 0;
  bool binary_ = false;
  std::size_t size_bytes_ = 8;
  bool has_entities_ = false;
  bool any_label_ = false;
  bool has_nodes_ = false, has_elements_ = false;
  bool tags_consecutive_ = true; // the element tags of the tetrahedra are first_tet_tag_ + index
  std::uint64_t first_tet_tag_ = 0;
  std::vector<std::uint64_t> tet_tags_; // otherwise, the element tag of each tetrahedron
  std::uint64_t max_element_tag_ = 0;   // the largest element tag of $Elements (every type)
  std::vector<Data_view> node_views_, element_views_;
  std::map<int, int> volume_physical_;
  std::vector<std::uint64_t> tags_;
  Gmsh_node_map<Index> nodes_;
  Mesh mesh_;
};

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_GMSH_READER_H
