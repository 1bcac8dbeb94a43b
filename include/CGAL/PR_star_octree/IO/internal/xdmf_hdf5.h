// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_XDMF_HDF5_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_XDMF_HDF5_H

// The heavy data of XDMF files in HDF5 files, through the HDF5 C API: datasets read (rank, dimensions
// and type checked, values converted by HDF5 to double or long long, in chunks of rows) and written.
// Compiled only when CGAL_PR_STAR_OCTREE_USE_HDF5 is defined (the program then includes the HDF5
// headers and links the HDF5 C library); otherwise `xdmf_hdf5_available()` is false and every entry
// point throws the "no HDF5 support" error.  HDF5's own error printing is turned off: every failure
// becomes a Read_error or a Write_error naming the file and the dataset.

#include <CGAL/PR_star_octree/IO/Read_error.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#ifdef CGAL_PR_STAR_OCTREE_USE_HDF5
#include <hdf5.h>
#endif

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {
// The two builds (with and without HDF5) have different code under the same names: an inline
// namespace of each keeps a program that mixes them from merging one with the other.
#ifdef CGAL_PR_STAR_OCTREE_USE_HDF5
inline namespace xdmf_with_hdf5 {
#else
inline namespace xdmf_without_hdf5 {
#endif

/// Whether this build reads and writes HDF5 files.
inline constexpr bool xdmf_hdf5_available() {
#ifdef CGAL_PR_STAR_OCTREE_USE_HDF5
  return true;
#else
  return false;
#endif
}

/// The message of a build without HDF5.
inline std::string xdmf_no_hdf5_message() {
  return "this build of the package has no HDF5 support (rebuild with libhdf5-dev installed)";
}

/// The numbers of a dataset: what kind, how many bytes each.
enum class Xdmf_number_kind { FLOAT, INT, UINT };

inline const char* xdmf_kind_name(Xdmf_number_kind k) {
  return k == Xdmf_number_kind::FLOAT ? "Float" : k == Xdmf_number_kind::INT ? "Int" : "UInt";
}

/// What a dataset holds.
struct Xdmf_h5_info {
  std::vector<unsigned long long> dims;
  Xdmf_number_kind kind = Xdmf_number_kind::FLOAT;
  std::size_t size = 8; ///< bytes per value
  unsigned long long count() const {
    unsigned long long n = 1;
    for (unsigned long long d : dims) n = (d != 0 && n > (~0ull) / d) ? ~0ull : n * d;
    return n;
  }
};

#ifdef CGAL_PR_STAR_OCTREE_USE_HDF5

/// An HDF5 identifier closed by its destructor.
class H5_id {
public:
  H5_id() = default;
  H5_id(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  H5_id(H5_id&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = -1; }
  H5_id& operator=(H5_id&& o) noexcept {
    std::swap(id_, o.id_);
    std::swap(close_, o.close_);
    return *this;
  }
  H5_id(const H5_id&) = delete;
  H5_id& operator=(const H5_id&) = delete;
  ~H5_id() {
    if (id_ >= 0 && close_ != nullptr) close_(id_);
  }
  hid_t get() const { return id_; }
  /// gives the identifier up (not closed by the destructor)
  hid_t release() {
    const hid_t id = id_;
    id_ = -1;
    return id;
  }
  bool valid() const { return id_ >= 0; }

private:
  hid_t id_ = -1;
  herr_t (*close_)(hid_t) = nullptr;
};

inline void xdmf_silence_hdf5() {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

/// The HDF5 files an XDMF file refers to, opened read-only once each.  Errors are reported as
/// `Read_error(xdmf, line, "<h5>:<dataset>: what")`, `line` being the one of the `DataItem`.
class Xdmf_h5_reader {
public:
  explicit Xdmf_h5_reader(const std::string& xdmf_name) : xdmf_(xdmf_name) { xdmf_silence_hdf5(); }

  /// Opens `dataset` of `file` (`shown` is the text of the reference, for messages) and describes it.
  Xdmf_h5_info info(const std::string& file, const std::string& dataset, const std::string& shown,
                    std::size_t line) {
    const H5_id d = open_dataset(file, dataset, shown, line);
    return describe(d, shown, line);
  }

  /// Reads the `count` values of a dataset as `T` (double or long long), in chunks of about
  /// `chunk_values` values handed to `sink(values, n)`.
  template <class T>
  void read(const std::string& file, const std::string& dataset, const std::string& shown, std::size_t line,
            const std::function<void(const T*, std::size_t)>& sink) {
    const H5_id d = open_dataset(file, dataset, shown, line);
    const Xdmf_h5_info in = describe(d, shown, line);
    const H5_id space(H5Dget_space(d.get()), &H5Sclose);
    if (!space.valid()) fail(shown, line, "cannot read its dataspace");
    // rows of the first dimension, as many as make about 1M values per chunk
    const int rank = static_cast<int>(in.dims.size());
    unsigned long long row_values = 1;
    for (int i = 1; i < rank; ++i) row_values *= in.dims[static_cast<std::size_t>(i)];
    const unsigned long long rows = rank == 0 ? 1 : in.dims[0];
    if (row_values == 0 || rows == 0) return;
    const unsigned long long chunk_rows = std::max<unsigned long long>(1, (1ull << 20) / row_values);
    const hid_t mem_type = std::is_same<T, double>::value ? H5T_NATIVE_DOUBLE : H5T_NATIVE_LLONG;
    std::vector<T> buffer;
    for (unsigned long long r = 0; r < rows; r += chunk_rows) {
      const unsigned long long n = std::min(chunk_rows, rows - r);
      buffer.resize(static_cast<std::size_t>(n * row_values));
      std::vector<hsize_t> start(static_cast<std::size_t>(std::max(rank, 1)), 0), cnt;
      for (int i = 0; i < rank; ++i)
        cnt.push_back(static_cast<hsize_t>(in.dims[static_cast<std::size_t>(i)]));
      hid_t file_space = H5S_ALL;
      H5_id mem_space;
      if (rank > 0) {
        start[0] = static_cast<hsize_t>(r);
        cnt[0] = static_cast<hsize_t>(n);
        if (H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start.data(), nullptr, cnt.data(), nullptr) < 0)
          fail(shown, line, "cannot select rows " + std::to_string(r) + " to " + std::to_string(r + n));
        const hsize_t flat = static_cast<hsize_t>(n * row_values);
        mem_space = H5_id(H5Screate_simple(1, &flat, nullptr), &H5Sclose);
        if (!mem_space.valid()) fail(shown, line, "cannot create a memory dataspace");
        file_space = space.get();
      }
      if (H5Dread(d.get(), mem_type, rank > 0 ? mem_space.get() : H5S_ALL, file_space, H5P_DEFAULT,
                  buffer.data()) < 0)
        fail(shown, line,
             "cannot read the values of rows " + std::to_string(r) + " to " + std::to_string(r + n) +
                 " (corrupt or truncated file, or a filter this HDF5 library does not have)");
      sink(buffer.data(), buffer.size());
    }
  }

private:
  [[noreturn]] void fail(const std::string& shown, std::size_t line, const std::string& what) const {
    throw Read_error(xdmf_, line, shown + ": " + what);
  }

  H5_id open_dataset(const std::string& file, const std::string& dataset, const std::string& shown,
                     std::size_t line) {
    auto it = files_.find(file);
    if (it == files_.end()) {
      std::FILE* f = std::fopen(file.c_str(), "rb");
      if (f == nullptr)
        throw Read_error(xdmf_, line,
                         "HDF5 file '" + file + "' (of " + shown + "): no such file or not readable");
      std::fclose(f);
      if (H5Fis_hdf5(file.c_str()) <= 0)
        throw Read_error(xdmf_, line, "'" + file + "' (of " + shown + ") is not an HDF5 file");
      H5_id id(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), &H5Fclose);
      if (!id.valid())
        throw Read_error(xdmf_, line, "cannot open the HDF5 file '" + file + "' (of " + shown + ")");
      it = files_.emplace(file, std::move(id)).first;
    }
    if (dataset.empty() || dataset[0] != '/') fail(shown, line, "the dataset path must start with '/'");
    // (H5Lexists fails, < 0, when a group of the path is missing)
    if (H5Lexists(it->second.get(), dataset.c_str(), H5P_DEFAULT) <= 0)
      fail(shown, line, "no dataset '" + dataset + "' in the HDF5 file");
    H5_id d(H5Dopen2(it->second.get(), dataset.c_str(), H5P_DEFAULT), &H5Dclose);
    if (!d.valid()) fail(shown, line, "'" + dataset + "' is not a dataset");
    return d;
  }

  Xdmf_h5_info describe(const H5_id& d, const std::string& shown, std::size_t line) const {
    Xdmf_h5_info r;
    const H5_id type(H5Dget_type(d.get()), &H5Tclose);
    if (!type.valid()) fail(shown, line, "cannot read the type of the dataset");
    const H5T_class_t c = H5Tget_class(type.get());
    const std::size_t size = H5Tget_size(type.get());
    if (c == H5T_FLOAT) {
      r.kind = Xdmf_number_kind::FLOAT;
      if (size != 4 && size != 8)
        fail(shown, line,
             "floating-point values of " + std::to_string(size) + " bytes (float32 or float64 only)");
    } else if (c == H5T_INTEGER) {
      r.kind = H5Tget_sign(type.get()) == H5T_SGN_NONE ? Xdmf_number_kind::UINT : Xdmf_number_kind::INT;
      if (size != 4 && size != 8)
        fail(shown, line,
             "integers of " + std::to_string(size) + " bytes (int32, int64, uint32 or uint64 only)");
    } else {
      fail(shown, line, "the dataset does not hold numbers (float32/64, int32/64, uint32/64)");
    }
    r.size = size;
    const H5_id space(H5Dget_space(d.get()), &H5Sclose);
    if (!space.valid()) fail(shown, line, "cannot read the dataspace of the dataset");
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank < 0 || rank > 8) fail(shown, line, "unsupported dataspace (rank " + std::to_string(rank) + ")");
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
    if (rank > 0 && H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0)
      fail(shown, line, "cannot read the dimensions of the dataset");
    for (hsize_t x : dims) r.dims.push_back(static_cast<unsigned long long>(x));
    return r;
  }

  std::string xdmf_;
  std::map<std::string, H5_id> files_;
};

/// Writes the datasets of an XDMF file into a new HDF5 file (replaced when it exists).
class Xdmf_h5_writer {
public:
  explicit Xdmf_h5_writer(const std::string& filename) : name_(filename) {
    xdmf_silence_hdf5();
    file_ = H5_id(H5Fcreate(filename.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), &H5Fclose);
    if (!file_.valid()) throw Write_error(filename, "cannot create the HDF5 file");
  }

  /// Writes a dataset `path` (its groups are created) of dimensions `rows` x `columns` (`columns`
  /// 0: one dimension) whose value `i` (row-major) is `value(i)`, as float64 (`T` = double), float32
  /// (`T` = float), int32 or int64, in chunks of rows.
  template <class T, class Value>
  void write(const std::string& path, std::size_t rows, std::size_t columns, const Value& value) {
    const hid_t type = std::is_same<T, double>::value         ? H5T_IEEE_F64LE
                       : std::is_same<T, float>::value        ? H5T_IEEE_F32LE
                       : std::is_same<T, std::int32_t>::value ? H5T_STD_I32LE
                                                              : H5T_STD_I64LE;
    const hid_t mem_type = std::is_same<T, double>::value         ? H5T_NATIVE_DOUBLE
                           : std::is_same<T, float>::value        ? H5T_NATIVE_FLOAT
                           : std::is_same<T, std::int32_t>::value ? H5T_NATIVE_INT32
                                                                  : H5T_NATIVE_INT64;
    const int rank = columns == 0 ? 1 : 2;
    const std::size_t per_row = columns == 0 ? 1 : columns;
    const hsize_t dims[2] = {static_cast<hsize_t>(rows), static_cast<hsize_t>(per_row)};
    const H5_id space(H5Screate_simple(rank, dims, nullptr), &H5Sclose);
    if (!space.valid()) fail(path, "cannot create its dataspace");
    const H5_id lcpl(H5Pcreate(H5P_LINK_CREATE), &H5Pclose);
    if (!lcpl.valid() || H5Pset_create_intermediate_group(lcpl.get(), 1) < 0)
      fail(path, "cannot create its groups");
    const H5_id d(
        H5Dcreate2(file_.get(), path.c_str(), type, space.get(), lcpl.get(), H5P_DEFAULT, H5P_DEFAULT),
        &H5Dclose);
    if (!d.valid()) fail(path, "cannot create the dataset");
    const std::size_t chunk_rows = std::max<std::size_t>(1, (std::size_t(1) << 20) / per_row);
    std::vector<T> buffer;
    for (std::size_t r = 0; r < rows; r += chunk_rows) {
      const std::size_t n = std::min(chunk_rows, rows - r);
      buffer.resize(n * per_row);
      for (std::size_t i = 0; i < buffer.size(); ++i) buffer[i] = static_cast<T>(value(r * per_row + i));
      const hsize_t start[2] = {static_cast<hsize_t>(r), 0},
                    count[2] = {static_cast<hsize_t>(n), static_cast<hsize_t>(per_row)};
      if (H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr) < 0)
        fail(path, "cannot select rows");
      const hsize_t flat = static_cast<hsize_t>(buffer.size());
      const H5_id mem(H5Screate_simple(1, &flat, nullptr), &H5Sclose);
      if (!mem.valid() || H5Dwrite(d.get(), mem_type, mem.get(), space.get(), H5P_DEFAULT, buffer.data()) < 0)
        fail(path, "error while writing the dataset (disk full?)");
    }
  }

  /// Flushes and closes the file.
  void close() {
    if (H5Fflush(file_.get(), H5F_SCOPE_LOCAL) < 0)
      throw Write_error(name_, "error while writing (disk full?)");
    if (H5Fclose(file_.release()) < 0) throw Write_error(name_, "error while closing the HDF5 file");
  }

private:
  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw Write_error(name_, "dataset " + path + ": " + what);
  }
  std::string name_;
  H5_id file_;
};

#else // no HDF5: the same interface, every call refused

class Xdmf_h5_reader {
public:
  explicit Xdmf_h5_reader(const std::string& xdmf_name) : xdmf_(xdmf_name) {}
  Xdmf_h5_info info(const std::string&, const std::string&, const std::string&, std::size_t) {
    throw Read_error(xdmf_, 0, xdmf_no_hdf5_message());
  }
  template <class T>
  void read(const std::string&, const std::string&, const std::string&, std::size_t,
            const std::function<void(const T*, std::size_t)>&) {
    throw Read_error(xdmf_, 0, xdmf_no_hdf5_message());
  }

private:
  std::string xdmf_;
};

class Xdmf_h5_writer {
public:
  explicit Xdmf_h5_writer(const std::string& filename) {
    throw Write_error(filename, xdmf_no_hdf5_message());
  }
  template <class T, class Value>
  void write(const std::string&, std::size_t, std::size_t, const Value&) {}
  void close() {}
};

#endif // CGAL_PR_STAR_OCTREE_USE_HDF5

} // namespace xdmf_with_hdf5 / xdmf_without_hdf5
} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_XDMF_HDF5_H
