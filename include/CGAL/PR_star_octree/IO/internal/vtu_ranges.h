// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTU_RANGES_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTU_RANGES_H

// Byte ranges of a .vtu file: the points [first, last) or the cells [first, last) of a file whose
// arrays are appended raw and uncompressed, read with positioned reads of just their bytes (for
// processes that each read their own part of one file), with the results and the checks of the
// whole-file reader (`read_vtu_text`, vtu_reader.h).  Also the piece files of a .pvtu file.

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/internal/decompress.h>
#include <CGAL/PR_star_octree/IO/internal/file_bytes.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>
#include <CGAL/PR_star_octree/IO/internal/vtk_cells.h>
#include <CGAL/PR_star_octree/IO/internal/vtu_reader.h>
#include <CGAL/PR_star_octree/IO/internal/xml.h>
#include <CGAL/PR_star_octree/internal/huge_pages.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {

/// Reads ranges of points and of cells of a `.vtu` file without reading the whole file: the
/// constructor reads the XML header only (the bytes up to the `_` that starts the appended data),
/// the 4 or 8 bytes that give the size of each array and the last cell offset; only when a label
/// array could hold values that are not ints (a floating-point, `UInt32` or 64-bit type) does it
/// read that array whole, in chunks, to choose it as `read_vtu` does.  `read_points()` and
/// `read_cells()` read the bytes of the requested range of each array with positioned reads, in
/// chunks of at most 2^20 values; they are const and open the file themselves (threads may call
/// them at once).
///
/// The ranges can be read (`ranges_supported()`) when the file is one `<Piece>` of an
/// UnstructuredGrid whose data arrays are all `format="appended"`, in `<AppendedData
/// encoding="raw">`, without a compressor; otherwise `reason()` says why, and the file must be read
/// whole (`read_vtu`).  A file with a data array stored in the XML anywhere in its `<Piece>` is
/// recognized before its data are read (this reader then stops reading), and said unsupported even
/// when the array is one `read_vtu` ignores.  The results are those of the whole-file reader: same points
/// (converted to double), same one-component point-data arrays with the same names, same choice of the label
/// array, tetrahedra (VTK type 10) in file order, the other cells (the quadratic tetrahedron too)
/// counted by type name.  Every call throws `Read_error` naming the file, the array and the value
/// or cell for bad data.  Not checked here, because it needs every cell: that the file has at
/// least one tetrahedron, and the cell-data arrays other than the labels.
class Vtu_range_reader {
public:
  /// Reads the header of `file`; throws `Read_error` when it is missing or its header malformed.
  explicit Vtu_range_reader(const std::string& file) : file_(file) {
    std::error_code ec;
    file_size_ = std::filesystem::file_size(file, ec);
    if (ec) throw Read_error(file, 0, "cannot read the file: " + ec.message());
    std::string header;
    if (!read_header(header)) return;
    parse(header);
  }

  /// whether the ranges of this file can be read; when not, only `reason()` is meaningful
  bool ranges_supported() const { return reason_.empty(); }
  /// why the ranges cannot be read, in words (empty when they can)
  const std::string& reason() const { return reason_; }

  std::uint64_t number_of_points() const { return nv_; }
  /// whether the points are 32-bit floats (`Float32`), when `read_vtu` would set
  /// `float32_points` (the values `read_points()` gives are then floats)
  bool float32_points() const { return points_.kind == Kind::FLOAT && points_.size == 4; }
  std::uint64_t number_of_cells() const { return nc_; }
  /// the file, and the line of its `<Piece>` (for messages about the whole mesh)
  const std::string& file() const { return file_; }
  std::size_t piece_line() const { return piece_line_; }

  /// the point-data arrays `read_vtu` keeps (one component, any numeric type), in file order
  const std::vector<std::string>& point_array_names() const { return point_names_; }

  /// whether a cell-data array gives the labels of the tetrahedra (as `read_vtu` chooses it)
  bool has_labels() const { return has_labels_; }
  /// its name (empty without labels)
  const std::string& label_array_name() const { return label_name_; }

  /// Appends the points `[first, last)` to `xyz` (3 values each) and their values of each
  /// point-data array `i` to `arrays[i]`; `arrays` must be empty (no point data read) or have one
  /// vector per name of `point_array_names()`.  Throws `Read_error` for bad data or a range that
  /// is not in `[0, number_of_points()]`, the outputs then left as they were.
  void read_points(std::uint64_t first, std::uint64_t last, std::vector<double>& xyz,
                   std::vector<std::vector<double>>& arrays) const {
    const std::size_t n = xyz.size();
    std::vector<std::size_t> sizes;
    for (const auto& a : arrays) sizes.push_back(a.size());
    try {
      append_points(first, last, xyz, arrays);
    } catch (...) {
      xyz.resize(n);
      for (std::size_t i = 0; i < sizes.size(); ++i) arrays[i].resize(sizes[i]);
      throw;
    }
  }

  /// Reads the cells `[first, last)`: appends each tetrahedron (VTK type 10) to `tets` (4 vertex
  /// indices), its cell index to `cell_ids` and, when `has_labels()` and `labels != nullptr`, its
  /// label to `*labels`; counts the other cells in `skipped` by type name (as `read_vtu` counts
  /// them in `skipped_cells`).  Throws `Read_error` for bad data (naming the cell) or a range that
  /// is not in `[0, number_of_cells()]`, the outputs then left as they were.
  void read_cells(std::uint64_t first, std::uint64_t last, std::vector<std::uint64_t>& tets,
                  std::vector<std::uint64_t>& cell_ids, std::vector<int>* labels,
                  std::map<std::string, std::size_t>& skipped) const {
    const std::size_t nt = tets.size(), ni = cell_ids.size(), nl = labels ? labels->size() : 0;
    std::map<std::string, std::size_t> skipped_before = skipped;
    try {
      append_cells(first, last, tets, cell_ids, labels, skipped);
    } catch (...) {
      tets.resize(nt);
      cell_ids.resize(ni);
      if (labels) labels->resize(nl);
      skipped.swap(skipped_before);
      throw;
    }
  }

  /// the number of cells of VTK type `type`, from the array of cell types alone
  std::uint64_t number_of_cells_of_type(unsigned char type) const {
    std::ifstream in = open();
    Cursor types(*this, in, types_, 0, nc_);
    std::uint64_t n = 0;
    for (std::uint64_t i = 0; i < nc_; ++i)
      if (types.integer() == type) ++n;
    return n;
  }

  /// The cells' summary from their types and offsets alone: the number of tetrahedra, and
  /// whether every cell is a tetrahedron whose four vertices follow the previous cell's in the
  /// connectivity (cell `i` ends at offset `4 (i + 1)`), when `read_tetrahedra()` can read them.
  struct Cell_summary {
    std::uint64_t tetrahedra = 0;
    bool only_tetrahedra_in_order = false;
  };
  Cell_summary summarize_cells() const {
    Cell_summary r;
    std::ifstream in = open();
    Cursor types(*this, in, types_, 0, nc_);
    for (std::uint64_t i = 0; i < nc_; ++i)
      if (types.integer() == 10) ++r.tetrahedra;
    r.only_tetrahedra_in_order = r.tetrahedra == nc_ && offsets_.count >= nc_;
    if (r.only_tetrahedra_in_order) {
      Cursor offsets(*this, in, offsets_, 0, nc_);
      long long four[4];
      std::uint64_t i = 0;
      for (; i + 4 <= nc_ && r.only_tetrahedra_in_order; i += 4) {
        offsets.integers(four, 4);
        for (int k = 0; k < 4; ++k)
          if (four[k] < 0 || static_cast<std::uint64_t>(four[k]) != 4 * (i + k + 1))
            r.only_tetrahedra_in_order = false;
      }
      for (; i < nc_ && r.only_tetrahedra_in_order; ++i)
        if (offsets.integer() != static_cast<long long>(4 * (i + 1))) r.only_tetrahedra_in_order = false;
    }
    return r;
  }

  /// Reads the cells `[first, last)` of a file whose `summarize_cells()` said
  /// `only_tetrahedra_in_order`, as `read_cells()` would (the cell index of tetrahedron `k` is
  /// `first + k`), from the connectivity (and the labels) alone.  Throws `Read_error` for bad data
  /// (naming the cell) or a range that is not in `[0, number_of_cells()]`, the outputs then left as
  /// they were.
  void read_tetrahedra(std::uint64_t first, std::uint64_t last, std::vector<std::uint64_t>& tets,
                       std::vector<int>* labels) const {
    const std::size_t nt = tets.size(), nl = labels ? labels->size() : 0;
    try {
      append_tetrahedra(first, last, tets, labels);
    } catch (...) {
      tets.resize(nt);
      if (labels) labels->resize(nl);
      throw;
    }
  }

private:
  void append_points(std::uint64_t first, std::uint64_t last, std::vector<double>& xyz,
                     std::vector<std::vector<double>>& arrays) const {
    check_range("points", first, last, nv_);
    if (!arrays.empty() && arrays.size() != point_arrays_.size())
      throw std::invalid_argument("Vtu_range_reader::read_points: " + std::to_string(arrays.size()) +
                                  " vectors for " + std::to_string(point_arrays_.size()) +
                                  " point-data arrays");
    std::ifstream in = open();
    Cursor p(*this, in, points_, 3 * first, 3 * last);
    xyz.reserve(xyz.size() + 3 * (last - first));
    for (std::uint64_t i = 3 * first; i < 3 * last; ++i) xyz.push_back(p.real());
    for (std::size_t k = 0; k < arrays.size(); ++k) {
      Cursor a(*this, in, point_arrays_[k], first, last);
      arrays[k].reserve(arrays[k].size() + (last - first));
      for (std::uint64_t i = first; i < last; ++i) arrays[k].push_back(a.real());
    }
  }

  void append_cells(std::uint64_t first, std::uint64_t last, std::vector<std::uint64_t>& tets,
                    std::vector<std::uint64_t>& cell_ids, std::vector<int>* labels,
                    std::map<std::string, std::size_t>& skipped) const {
    check_range("cells", first, last, nc_);
    if (first == last) return;
    std::ifstream in = open();
    Cursor offsets(*this, in, offsets_, first == 0 ? 0 : first - 1, last);
    Cursor types(*this, in, types_, first, last);
    std::unique_ptr<Cursor> label_values;
    if (labels != nullptr && has_labels_)
      label_values = std::make_unique<Cursor>(*this, in, label_array_, first, last);
    long long start = 0; // where cell `first` starts in the connectivity
    if (first > 0) {
      start = offsets.integer();
      if (start < 0) fail_cells("the offset of cell " + std::to_string(first - 1) + " is negative");
    }
    std::vector<long long> ends;
    std::vector<unsigned char> cell_types;
    for (std::uint64_t b = first; b < last;) { // blocks of at most `chunk` cells
      const std::uint64_t e = std::min<std::uint64_t>(last, b + chunk);
      ends.clear();
      cell_types.clear();
      long long prev = start;
      for (std::uint64_t i = b; i < e; ++i) {
        const long long end = offsets.integer();
        const long long t = types.integer();
        cell_types.push_back(t >= 0 && t < 255 ? static_cast<unsigned char>(t) : 255);
        if (end < prev) fail_cells("cell offsets decrease at cell " + std::to_string(i));
        if (cell_types.back() == 10 && end - prev != 4)
          fail_cells("cell " + std::to_string(i) + " is a tetrahedron with " + std::to_string(end - prev) +
                     " vertices instead of 4");
        if (static_cast<unsigned long long>(end) > connectivity_.count)
          fail_cells("cell " + std::to_string(i) + " ends at " + std::to_string(end) +
                     ", beyond the connectivity (" + std::to_string(connectivity_.count) + " entries)");
        ends.push_back(end);
        prev = end;
      }
      Cursor conn(*this, in, connectivity_, static_cast<std::uint64_t>(start),
                  static_cast<std::uint64_t>(prev));
      long long cell_start = start;
      for (std::uint64_t i = b; i < e; ++i) {
        const long long end = ends[i - b];
        const unsigned char t = cell_types[i - b];
        const double label = label_values ? label_values->real() : 0;
        if (t != 10) {
          conn.skip(static_cast<std::uint64_t>(end - cell_start));
          ++skipped[vtk_cell_type_name(t)];
        } else {
          append_tetrahedron(conn, i, tets);
          cell_ids.push_back(i);
          if (label_values) labels->push_back(static_cast<int>(label));
        }
        cell_start = end;
      }
      start = prev;
      b = e;
    }
  }

  // The next four values of `conn`, the vertices of the tetrahedron of cell `i`, checked and
  // appended to `tets`.
  template <class Cursor>
  void append_tetrahedron(Cursor& conn, std::uint64_t i, std::vector<std::uint64_t>& tets) const {
    std::array<std::uint64_t, 4> v;
    long long four[4];
    conn.integers(four, 4);
    for (int j = 0; j < 4; ++j) {
      const long long k = four[j];
      if (k < 0 || static_cast<unsigned long long>(k) >= nv_)
        fail_cells("cell " + std::to_string(i) + ": vertex index " + std::to_string(k) +
                   " out of range (0-based, " + std::to_string(nv_) + " points)");
      v[j] = static_cast<std::uint64_t>(k);
    }
    std::uint64_t twice;
    if (has_repeated_vertex(v, twice))
      fail_cells("cell " + std::to_string(i) + ": vertex index " + std::to_string(twice) + " listed twice");
    tets.insert(tets.end(), v.begin(), v.end());
  }

  void append_tetrahedra(std::uint64_t first, std::uint64_t last, std::vector<std::uint64_t>& tets,
                         std::vector<int>* labels) const {
    check_range("cells", first, last, nc_);
    if (first == last) return;
    if (4 * last > connectivity_.count)
      fail_cells("cell " + std::to_string(last - 1) + " ends at " + std::to_string(4 * last) +
                 ", beyond the connectivity (" + std::to_string(connectivity_.count) + " entries)");
    std::ifstream in = open();
    Cursor conn(*this, in, connectivity_, 4 * first, 4 * last);
    std::unique_ptr<Cursor> label_values;
    if (labels != nullptr && has_labels_)
      label_values = std::make_unique<Cursor>(*this, in, label_array_, first, last);
    tets.reserve(tets.size() + 4 * (last - first));
    for (std::uint64_t i = first; i < last; ++i) {
      append_tetrahedron(conn, i, tets);
      if (label_values) labels->push_back(static_cast<int>(label_values->real()));
    }
  }

  using Kind = Vtu_array_reader::Kind;
  static constexpr std::uint64_t chunk = std::uint64_t(1) << 20; // values read at once
  static constexpr std::size_t max_header = std::size_t(64) << 20;

  /// A data array of the appended data: where its values are in the file.
  struct Array {
    std::string what; // "DataArray 'name'", for messages
    std::string type;
    std::size_t size = 0; // bytes per value
    Kind kind = Kind::SIGNED;
    std::uint64_t count = 0; // number of values
    std::uint64_t data = 0;  // the byte of the file where the first value is
    std::size_t line = 0;    // of its element
  };

  /// Sequential reads of the values `[first, last)` of an array, `chunk` at a time.
  class Cursor {
  public:
    Cursor(const Vtu_range_reader& r, std::ifstream& in, const Array& a, std::uint64_t first,
           std::uint64_t last)
        : r_(r), in_(in), a_(a), next_(first), last_(last) {}

    /// the next value as an integer
    long long integer() {
      const unsigned char* p = take();
      if (a_.kind == Kind::SIGNED) {
        switch (a_.size) {
        case 1:
          return load_value<std::int8_t>(reinterpret_cast<const char*>(p), false);
        case 2:
          return load_value<std::int16_t>(reinterpret_cast<const char*>(p), r_.swap_);
        case 4:
          return load_value<std::int32_t>(reinterpret_cast<const char*>(p), r_.swap_);
        default:
          return load_value<std::int64_t>(reinterpret_cast<const char*>(p), r_.swap_);
        }
      }
      const std::uint64_t u = unsigned_value(p);
      if (u > static_cast<std::uint64_t>(std::numeric_limits<long long>::max()))
        r_.fail(a_.line, a_.what + ": value " + std::to_string(index_ - 1) + " is too large");
      return static_cast<long long>(u);
    }

    /// the next `n` values as integers, as `integer()` would give them (faster when they are
    /// 32- or 64-bit signed integers already read)
    void integers(long long* out, std::size_t n) {
      if (a_.kind == Kind::SIGNED && (a_.size == 8 || a_.size == 4) && buffer_.size() - pos_ >= n * a_.size) {
        const char* p = reinterpret_cast<const char*>(buffer_.data() + pos_);
        if (a_.size == 8)
          for (std::size_t k = 0; k < n; ++k) out[k] = load_value<std::int64_t>(p + 8 * k, r_.swap_);
        else
          for (std::size_t k = 0; k < n; ++k) out[k] = load_value<std::int32_t>(p + 4 * k, r_.swap_);
        pos_ += n * a_.size;
        index_ += n;
        return;
      }
      for (std::size_t k = 0; k < n; ++k) out[k] = integer();
    }

    /// the next value as a double (finite)
    double real() {
      if (a_.kind != Kind::FLOAT) return static_cast<double>(integer());
      const char* p = reinterpret_cast<const char*>(take());
      const double v =
          a_.size == 4 ? double(load_value<float>(p, r_.swap_)) : load_value<double>(p, r_.swap_);
      if (!std::isfinite(v))
        r_.fail(a_.line, a_.what + ": value " + std::to_string(index_ - 1) + " is not finite");
      return v;
    }

    /// Skips `n` values.
    void skip(std::uint64_t n) {
      const std::uint64_t buffered = (buffer_.size() - pos_) / a_.size;
      if (n <= buffered) {
        pos_ += static_cast<std::size_t>(n) * a_.size;
      } else {
        next_ += n - buffered;
        pos_ = buffer_.size();
      }
      index_ += n;
    }

  private:
    std::uint64_t unsigned_value(const unsigned char* p) const {
      const char* c = reinterpret_cast<const char*>(p);
      switch (a_.size) {
      case 1:
        return *p;
      case 2:
        return load_value<std::uint16_t>(c, r_.swap_);
      case 4:
        return load_value<std::uint32_t>(c, r_.swap_);
      default:
        return load_value<std::uint64_t>(c, r_.swap_);
      }
    }

    const unsigned char* take() {
      if (pos_ == buffer_.size()) {
        if (next_ >= last_) // a caller error: more values taken than the range holds
          throw std::logic_error("Vtu_range_reader: read past the range of " + a_.what);
        const std::uint64_t n = std::min(chunk, last_ - next_);
        PR_star_octree::internal::resize_huge(buffer_, static_cast<std::size_t>(n) * a_.size);
        const std::uint64_t at = a_.data + next_ * a_.size;
        in_.clear();
        in_.seekg(static_cast<std::streamoff>(at));
        in_.read(reinterpret_cast<char*>(buffer_.data()), static_cast<std::streamsize>(buffer_.size()));
        if (static_cast<std::size_t>(in_.gcount()) != buffer_.size())
          r_.fail(0, a_.what + ": the file ends before value " +
                         std::to_string(next_ + in_.gcount() / a_.size) + " (byte " +
                         std::to_string(at + std::uint64_t(in_.gcount())) + ")");
        next_ += n;
        pos_ = 0;
      }
      const unsigned char* p = buffer_.data() + pos_;
      pos_ += a_.size;
      ++index_;
      return p;
    }

    const Vtu_range_reader& r_;
    std::ifstream& in_;
    const Array& a_;
    std::uint64_t next_, last_; // the next value to read from the file, the end of the range
    std::uint64_t index_ = next_;
    std::vector<unsigned char> buffer_;
    std::size_t pos_ = 0;
  };

  [[noreturn]] void fail(std::size_t line, const std::string& message) const {
    throw Read_error(file_, line, message);
  }
  [[noreturn]] void fail_cells(const std::string& message) const { fail(cells_line_, "<Cells>: " + message); }

  void check_range(const char* what, std::uint64_t first, std::uint64_t last, std::uint64_t n) const {
    if (!reason_.empty()) fail(0, "the ranges of this file cannot be read: " + reason_);
    if (first > last || last > n)
      fail(0, std::string(what) + " [" + std::to_string(first) + ", " + std::to_string(last) +
                  ") requested, the file has " + std::to_string(n));
  }

  std::ifstream open() const {
    std::ifstream in(file_, std::ios::in | std::ios::binary);
    if (!in) fail(0, "cannot open the file for reading");
    return in;
  }

  /// Reads the bytes up to and including the `_` that starts the appended data into `header`;
  /// false (and `reason_` set) when the file has no appended data, or inline data before it.
  bool read_header(std::string& header) {
    std::ifstream in = open();
    std::string text;
    std::size_t appended = std::string::npos, data_array = 0, piece = std::string::npos;
    for (;;) {
      const std::size_t old = text.size();
      text.resize(old + (std::size_t(1) << 16));
      in.read(&text[old], static_cast<std::streamsize>(text.size() - old));
      text.resize(old + static_cast<std::size_t>(in.gcount()));
      const bool end = text.size() == old;
      if (piece == std::string::npos) piece = text.find("<Piece");
      if (appended == std::string::npos) appended = text.find("<AppendedData", old < 13 ? 0 : old - 13);
      // an array written in the XML before the appended data: no need to read further
      const std::size_t scan_end = std::min(appended, text.size());
      while (piece != std::string::npos) {
        const std::size_t d = text.find("<DataArray", std::max(data_array, piece));
        if (d == std::string::npos || d >= scan_end) break;
        const std::size_t gt = tag_end(text, d);
        if (gt == std::string::npos) break;
        data_array = gt;
        std::string tag = text.substr(d, gt + 1 - d);
        if (tag.size() < 2 || tag[tag.size() - 2] != '/') tag += "</DataArray>";
        try {
          const Xml_document doc(tag, file_);
          const std::string* format = doc.root().attribute("format");
          if (format == nullptr || *format != "appended") {
            reason_ = Vtu_array_reader::describe(doc.root()) + " is stored in the XML (format=\"" +
                      (format ? *format : std::string("ascii")) + "\"), not appended";
            return false;
          }
        } catch (const Read_error&) {
          // malformed: the parse of the whole header will say where
        }
      }
      if (appended != std::string::npos) {
        const std::size_t gt = tag_end(text, appended);
        if (gt != std::string::npos) {
          std::size_t q = gt + 1;
          while (q < text.size() && is_space(text[q])) ++q;
          if (q < text.size()) {
            if (text[gt - 1] == '/' || text[q] != '_') {
              reason_ = "the <AppendedData> element is empty or does not start with '_'";
              return false;
            }
            header = text.substr(0, q + 1);
            return true;
          }
        }
      }
      if (end) break;
      if (text.size() > max_header) {
        reason_ = "no <AppendedData> in the first " + std::to_string(max_header >> 20) + " MiB of the file";
        return false;
      }
    }
    std::size_t p = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
    while (p < text.size() && is_space(text[p])) ++p;
    if (p == text.size() || text[p] != '<') fail(0, "not a VTK XML file (no XML element)");
    const Xml_document doc(text, file_); // the whole file is here: malformed XML is an error
    reason_ = "the file has no appended data (its arrays are stored in the XML)";
    return false;
  }

  /// the `>` that ends the tag starting at `begin` (quoted values skipped), or npos
  static std::size_t tag_end(const std::string& text, std::size_t begin) {
    char quote = 0;
    for (std::size_t i = begin; i < text.size(); ++i) {
      const char c = text[i];
      if (quote != 0) {
        if (c == quote) quote = 0;
      } else if (c == '"' || c == '\'') {
        quote = c;
      } else if (c == '>') {
        return i;
      }
    }
    return std::string::npos;
  }

  void parse(const std::string& header) {
    data_begin_ = header.size();
    const std::string text = header + "</AppendedData></VTKFile>";
    const Xml_document doc(text, file_);
    const Xml_element& root = doc.root();
    if (root.name != "VTKFile")
      fail(root.line, "not a VTK XML file: the root element is <" + std::string(root.name) + ">");
    const std::string* type = root.attribute("type");
    if (type == nullptr) fail(root.line, "<VTKFile> without a type attribute");
    if (*type != "UnstructuredGrid") {
      reason_ = "VTKFile type '" + *type + "' is not UnstructuredGrid";
      return;
    }
    // byte order, header type, compressor, encoding: as the whole-file reader (same errors)
    const Vtu_array_reader arrays(doc, file_);
    const std::string* bo = root.attribute("byte_order");
    swap_ = (bo != nullptr && *bo == "BigEndian") == host_is_little_endian();
    const std::string* ht = root.attribute("header_type");
    header_size_ = ht != nullptr && *ht == "UInt64" ? 8 : 4;
    if (arrays.compressor() != Vtk_compressor::NONE) {
      const std::string name = *root.attribute("compressor");
      reason_ = std::string("the arrays are ") +
                (arrays.compressor() == Vtk_compressor::ZLIB  ? "zlib"
                 : arrays.compressor() == Vtk_compressor::LZ4 ? "lz4"
                                                              : "lzma") +
                "-compressed (compressor=\"" + name + "\")";
      return;
    }
    if (*doc.appended_element().attribute("encoding") != "raw") {
      reason_ = "the appended data are base64-encoded, not raw";
      return;
    }
    const std::vector<const Xml_element*> grids = xml_children(doc, root, "UnstructuredGrid");
    if (grids.size() != 1)
      fail(root.line, "expected one <UnstructuredGrid> element, found " + std::to_string(grids.size()));
    const std::vector<const Xml_element*> pieces = xml_children(doc, *grids[0], "Piece");
    if (pieces.empty()) fail(grids[0]->line, "no <Piece> in <UnstructuredGrid>");
    if (pieces.size() > 1) {
      reason_ = "the file has " + std::to_string(pieces.size()) + " pieces";
      return;
    }
    const Xml_element& piece = *pieces[0];
    piece_line_ = piece.line;
    const auto count_attribute = [&](const char* key) {
      const std::string* v = piece.attribute(key);
      if (v == nullptr) fail(piece.line, std::string("<Piece> without ") + key);
      long long n = 0;
      if (parse_integer(*v, n) != nullptr || n < 0 ||
          static_cast<unsigned long long>(n) > std::numeric_limits<std::size_t>::max() / 64)
        fail(piece.line, std::string("invalid ") + key + " '" + *v + "'");
      return static_cast<std::uint64_t>(n);
    };
    nv_ = count_attribute("NumberOfPoints");
    nc_ = count_attribute("NumberOfCells");
    const auto single = [&](const Xml_element& parent, std::string_view child) -> const Xml_element* {
      const std::vector<const Xml_element*> c = xml_children(doc, parent, child);
      if (c.size() > 1)
        fail(parent.line, "more than one <" + std::string(child) + "> in <" + std::string(parent.name) + ">");
      return c.empty() ? nullptr : c.front();
    };
    const auto components = [&](const Xml_element& a) {
      const std::string* c = a.attribute("NumberOfComponents");
      if (c == nullptr) return std::size_t(1);
      long long n = 0;
      if (parse_integer(*c, n) != nullptr || n < 1 || n > 1000)
        fail(a.line, Vtu_array_reader::describe(a) + ": invalid NumberOfComponents '" + *c + "'");
      return static_cast<std::size_t>(n);
    };

    // points
    if (const Xml_element* points = single(piece, "Points")) {
      const std::vector<const Xml_element*> da = xml_children(doc, *points, "DataArray");
      if (da.size() != 1)
        fail(points->line, "<Points> must hold one DataArray, found " + std::to_string(da.size()));
      if (components(*da[0]) != 3)
        fail(da[0]->line, "the points DataArray must have NumberOfComponents=\"3\"");
      if (!locate(*da[0], 3 * nv_, false, points_)) return;
    } else if (nv_ > 0) {
      fail(piece.line, "<Piece> without <Points>");
    }

    // cells
    if (const Xml_element* cells = single(piece, "Cells")) {
      cells_line_ = cells->line;
      const Xml_element *conn = nullptr, *offs = nullptr, *types = nullptr;
      for (const Xml_element* a : xml_children(doc, *cells, "DataArray")) {
        const std::string* n = a->attribute("Name");
        if (n == nullptr) continue;
        const Xml_element** slot = *n == "connectivity" ? &conn
                                   : *n == "offsets"    ? &offs
                                   : *n == "types"      ? &types
                                                        : nullptr;
        if (slot == nullptr) continue;
        if (*slot != nullptr) fail(a->line, "duplicate DataArray '" + *n + "' in <Cells>");
        *slot = a;
      }
      if (offs == nullptr) fail(cells->line, "<Cells> without the DataArray 'offsets'");
      if (types == nullptr) fail(cells->line, "<Cells> without the DataArray 'types'");
      if (conn == nullptr) fail(cells->line, "<Cells> without the DataArray 'connectivity'");
      if (!locate(*types, nc_, true, types_) || !locate(*offs, nc_, true, offsets_) ||
          !locate(*conn, std::numeric_limits<std::uint64_t>::max(), true, connectivity_))
        return;
      // the connectivity has as many entries as the last offset says
      long long last = 0;
      if (nc_ > 0) {
        std::ifstream in = open();
        last = Cursor(*this, in, offsets_, nc_ - 1, nc_).integer();
      }
      if (last < 0 || static_cast<unsigned long long>(last) != connectivity_.count)
        fail_cells("the cell offsets end at " + std::to_string(last) + " but the connectivity has " +
                   std::to_string(connectivity_.count) + " entries");
    } else if (nc_ > 0) {
      fail(piece.line, "<Piece> without <Cells>");
    }

    // point data: every one-component array
    if (const Xml_element* pd = single(piece, "PointData")) {
      for (const Xml_element* a : xml_children(doc, *pd, "DataArray")) {
        if (components(*a) != 1) continue;
        const std::string* n = a->attribute("Name");
        const std::string name = n ? *n : "point_data_" + std::to_string(point_names_.size());
        if (std::find(point_names_.begin(), point_names_.end(), name) != point_names_.end())
          fail(a->line, "duplicate point data array '" + name + "'");
        point_names_.push_back(name);
        point_arrays_.emplace_back();
        if (!locate(*a, nv_, false, point_arrays_.back())) return;
      }
    }

    // labels: the first one-component array with a label name whose values are all ints
    if (const Xml_element* cd = single(piece, "CellData")) {
      std::size_t k = 0;
      for (const Xml_element* a : xml_children(doc, *cd, "DataArray")) {
        if (components(*a) != 1) continue;
        const std::string* n = a->attribute("Name");
        const std::string name = n ? *n : "cell_data_" + std::to_string(k);
        ++k;
        if (!is_vtk_label_array_name(name)) continue;
        Array candidate;
        if (!locate(*a, nc_, false, candidate)) return;
        if (int_valued(candidate)) {
          label_array_ = candidate;
          has_labels_ = true;
          label_name_ = name;
          break;
        }
      }
    }
  }

  /// Whether every value of `a` is an int (read only for the types that can hold others).
  bool int_valued(const Array& a) const {
    if (a.kind != Kind::FLOAT && (a.size < 4 || (a.size == 4 && a.kind == Kind::SIGNED))) return true;
    std::ifstream in = open();
    Cursor c(*this, in, a, 0, a.count);
    for (std::uint64_t i = 0; i < a.count; ++i) {
      const double v = c.real();
      if (!(v == std::floor(v) && v >= double(std::numeric_limits<int>::min()) &&
            v <= double(std::numeric_limits<int>::max())))
        return false;
    }
    return true;
  }

  /// Finds the values of the appended array `e` (`count` values; the max of the type: any number
  /// whole values) in the file, checking their size against the file; false (and `reason_` set)
  /// when they are not appended.
  bool locate(const Xml_element& e, std::uint64_t count, bool integer, Array& a) {
    a.what = Vtu_array_reader::describe(e);
    a.line = e.line;
    const std::string* type = e.attribute("type");
    if (type == nullptr) fail(e.line, a.what + " without a type attribute");
    a.type = *type;
    if (!type_info(*type, a.size, a.kind)) fail(e.line, a.what + ": unknown type '" + *type + "'");
    if (integer && a.kind == Kind::FLOAT)
      fail(e.line, a.what + " has type " + *type + " but must have an integer type");
    const std::string* format = e.attribute("format");
    if (format == nullptr || *format != "appended") {
      reason_ = a.what + " is stored in the XML (format=\"" + (format ? *format : std::string("ascii")) +
                "\"), not appended";
      return false;
    }
    const std::string* off = e.attribute("offset");
    if (off == nullptr) fail(e.line, a.what + ": appended data without an offset attribute");
    long long offset = 0;
    if (parse_integer(*off, offset) != nullptr || offset < 0)
      fail(e.line, a.what + ": invalid offset '" + *off + "'");
    const std::uint64_t at = data_begin_ + static_cast<std::uint64_t>(offset);
    if (at > file_size_ || file_size_ - at < header_size_)
      fail(e.line, a.what + ": offset " + *off + " is beyond the end of the file (" +
                       std::to_string(file_size_) + " bytes)");
    std::ifstream in = open();
    in.seekg(static_cast<std::streamoff>(at));
    char word[8];
    in.read(word, static_cast<std::streamsize>(header_size_));
    if (static_cast<std::size_t>(in.gcount()) != header_size_)
      fail(0, a.what + ": cannot read the header at byte " + std::to_string(at));
    const std::uint64_t nbytes =
        header_size_ == 8 ? load_value<std::uint64_t>(word, swap_) : load_value<std::uint32_t>(word, swap_);
    const bool any = count == std::numeric_limits<std::uint64_t>::max();
    if (any ? nbytes % a.size != 0 : count > nbytes / a.size || count * a.size != nbytes)
      fail(e.line, a.what + ": the binary block holds " + std::to_string(nbytes) + " bytes, expected " +
                       (any ? std::string("whole") : std::to_string(count)) + " values of type " + *type +
                       (any ? std::string()
                            : " (" + std::to_string(count) + " x " + std::to_string(a.size) + " bytes)"));
    a.count = nbytes / a.size;
    a.data = at + header_size_;
    if (nbytes > file_size_ - a.data)
      fail(e.line, a.what + ": the binary data is truncated (" + std::to_string(nbytes) +
                       " bytes announced, at most " + std::to_string(file_size_ - a.data) +
                       " present) (at byte " + std::to_string(a.data) + " of the file)");
    return true;
  }

  /// The size and kind of a VTK type name (those `Vtu_array_reader` reads).
  static bool type_info(const std::string& t, std::size_t& size, Kind& kind) {
    static const struct {
      const char* name;
      std::size_t size;
      Kind kind;
    } table[] = {{"Int8", 1, Kind::SIGNED},     {"UInt8", 1, Kind::UNSIGNED},  {"Int16", 2, Kind::SIGNED},
                 {"UInt16", 2, Kind::UNSIGNED}, {"Int32", 4, Kind::SIGNED},    {"UInt32", 4, Kind::UNSIGNED},
                 {"Int64", 8, Kind::SIGNED},    {"UInt64", 8, Kind::UNSIGNED}, {"Float32", 4, Kind::FLOAT},
                 {"Float64", 8, Kind::FLOAT},   {"Char", 1, Kind::SIGNED},     {"UChar", 1, Kind::UNSIGNED},
                 {"Int", 4, Kind::SIGNED},      {"Float", 4, Kind::FLOAT},     {"Double", 8, Kind::FLOAT}};
    for (const auto& x : table)
      if (t == x.name) {
        size = x.size;
        kind = x.kind;
        return true;
      }
    return false;
  }

  std::string file_;
  std::uint64_t file_size_ = 0;
  std::string reason_;
  std::uint64_t data_begin_ = 0; // the byte after the `_`
  bool swap_ = false;
  std::size_t header_size_ = 4;
  std::uint64_t nv_ = 0, nc_ = 0;
  std::size_t cells_line_ = 0;
  std::size_t piece_line_ = 0;
  Array points_, connectivity_, offsets_, types_, label_array_;
  bool has_labels_ = false;
  std::string label_name_;
  std::vector<std::string> point_names_;
  std::vector<Array> point_arrays_;
};

/// The piece files of a `.pvtu` file (`<VTKFile type="PUnstructuredGrid">`): the `Source` of each
/// `<Piece>`, in file order, relative ones resolved against the directory of `pvtu_file`.  Throws
/// `Read_error` when the file is missing or malformed.
inline std::vector<std::string> read_pvtu_piece_files(const std::string& pvtu_file) {
  const std::string text = load_file(pvtu_file);
  const Xml_document doc(text, pvtu_file);
  const Xml_element& root = doc.root();
  const auto fail = [&](const Xml_element& e, const std::string& m) {
    throw Read_error(pvtu_file, e.line, m);
  };
  if (root.name != "VTKFile")
    fail(root, "not a VTK XML file: the root element is <" + std::string(root.name) + ">");
  const std::string* type = root.attribute("type");
  if (type == nullptr || *type != "PUnstructuredGrid")
    fail(root, "not a parallel unstructured grid: VTKFile type '" + (type ? *type : std::string()) +
                   "' (expected PUnstructuredGrid)");
  const std::vector<const Xml_element*> grids = xml_children(doc, root, "PUnstructuredGrid");
  if (grids.size() != 1)
    fail(root, "expected one <PUnstructuredGrid> element, found " + std::to_string(grids.size()));
  const std::vector<const Xml_element*> pieces = xml_children(doc, *grids[0], "Piece");
  if (pieces.empty()) fail(*grids[0], "no <Piece> in <PUnstructuredGrid>");
  const std::filesystem::path dir = std::filesystem::path(pvtu_file).parent_path();
  std::vector<std::string> files;
  for (const Xml_element* p : pieces) {
    const std::string* source = p->attribute("Source");
    if (source == nullptr || source->empty()) fail(*p, "<Piece> without a Source attribute");
    const std::filesystem::path s(*source);
    files.push_back(s.is_absolute() || dir.empty() ? s.string() : (dir / s).string());
  }
  return files;
}

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_VTU_RANGES_H
