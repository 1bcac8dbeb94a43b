// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_WRITE_OPTIONS_H
#define CGAL_PR_STAR_OCTREE_IO_WRITE_OPTIONS_H

// clang-format off
/// \file Write_options.h
/// The options of every writer, as named parameters with the same names and meanings for every
/// format:
///
/// | named parameter | meaning |
/// |---|---|
/// | `CGAL::parameters::use_binary_mode(bool)` | binary (`true`) or text (`false`) |
/// | `CGAL::PR_star_octree::parameters::compression(IO::Compression)` | compression of the binary data: `Compression::zlib` or `Compression::none` |
/// | `CGAL::PR_star_octree::parameters::format_version(double)` | the version of the format written, e.g. 2.2 or 4.1 for gmsh |
///
/// Each format accepts what its record of the format table (`IO::mesh_formats`, `formats.h`) says
/// (`write_options_text()`, the README's table), uses its defaults for the options not given, and
/// throws `Write_error` for an option it cannot honour (a text-only format asked for binary, a
/// compression it does not have, a version it does not write).  The package's parameters chain
/// first, %CGAL's after: `parameters::format_version(2.2).use_binary_mode(true)`.
// clang-format on

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <type_traits>

namespace CGAL {
namespace PR_star_octree {
namespace IO {

/// \ingroup PkgPRStarOctreeIO
/// How a writer compresses the data (the named parameter `compression`).
enum class Compression {
  none, ///< no compression
  zlib  ///< zlib (VTK's `vtkZLibDataCompressor`); needs zlib to have been found by the build
};

namespace internal {

/// The write options given as named parameters; `has_*` false: not given (the format's default).
struct Write_options {
  bool has_binary = false, binary = false;
  bool has_compression = false;
  Compression compression = Compression::none;
  bool has_version = false;
  double version = 0;
};

/// What the writer of a format accepts, and its defaults (one per format, named in the format table).
struct Write_support {
  bool ascii;              ///< `use_binary_mode(false)` is possible
  bool binary;             ///< `use_binary_mode(true)` is possible
  bool binary_by_default;  ///< the default of `use_binary_mode`
  bool zlib;               ///< `compression(Compression::zlib)` is possible (with `use_binary_mode(true)`)
  bool zlib_by_default;    ///< compressed by default (when the build has zlib)
  const char* versions[4]; ///< the versions `format_version` accepts, e.g. "4.1"; the first is the default
  const char* default_version; ///< what the default is when not the first version (else nullptr)
};

/// The compression this build can write.
inline bool compression_available(Compression c) {
#ifdef CGAL_PR_STAR_OCTREE_HAS_ZLIB
  (void)c;
  return true;
#else
  return c == Compression::none;
#endif
}

inline void take_option(bool& has, bool& value, bool given) {
  has = true;
  value = given;
}
inline void take_option(bool& has, Compression& value, Compression given) {
  has = true;
  value = given;
}
inline void take_option(bool& has, double& value, double given) {
  has = true;
  value = given;
}
template <class T>
void take_option(bool&, T&, CGAL::internal_np::Param_not_found) {}

/// The write options of a named-parameter chain.
template <class NamedParameters>
Write_options write_options(const NamedParameters& np) {
  Write_options o;
  take_option(o.has_binary, o.binary,
              CGAL::parameters::get_parameter(np, CGAL::internal_np::use_binary_mode));
  take_option(o.has_compression, o.compression,
              CGAL::parameters::get_parameter(np, PR_star_octree::internal_np::compression));
  take_option(o.has_version, o.version,
              CGAL::parameters::get_parameter(np, PR_star_octree::internal_np::format_version));
  return o;
}

/// A version as an integer number of tenths (4.1 -> 41, 2 -> 20).
inline long version_tenths(double v) {
  return std::lround(v * 10);
}

/// The version written in a string ("4.1", "2") as tenths (locale-independent).
inline long version_tenths(const char* s) {
  long tenths = 0;
  for (; *s >= '0' && *s <= '9'; ++s) tenths = 10 * tenths + (*s - '0');
  tenths *= 10;
  if (*s == '.' && s[1] >= '0' && s[1] <= '9') tenths += s[1] - '0';
  return tenths;
}

/// The options a writer of `format` (a name for messages) uses: the given ones checked against
/// `support`, the others set to the format's defaults.  `version` is 0 when the format chooses
/// it itself (`support.default_version`).  Throws `Write_error` for an option the format cannot
/// honour.
inline Write_options resolve_write_options(const Write_options& given, const Write_support& support,
                                           const char* format, const std::string& name) {
  Write_options o = given;
  if (!o.has_binary) o.binary = support.binary_by_default;
  if (o.binary && !support.binary)
    throw Write_error(name,
                      std::string(format) + " files are text only: use_binary_mode(true) is not possible");
  if (!o.binary && !support.ascii)
    throw Write_error(name,
                      std::string(format) + " files are binary only: use_binary_mode(false) is not possible");
  if (o.has_compression && o.compression != Compression::none) {
    if (!support.zlib)
      throw Write_error(name, std::string(format) +
                                  " files are not compressed: only compression(none) is possible");
    if (!o.binary) throw Write_error(name, "compression needs use_binary_mode(true)");
    if (!compression_available(o.compression))
      throw Write_error(name,
                        "zlib compression is not available: zlib was not found when this program was built");
  }
  if (!o.has_compression)
    o.compression = o.binary && support.zlib_by_default && compression_available(Compression::zlib)
                        ? Compression::zlib
                        : Compression::none;
  o.has_binary = o.has_compression = true;
  if (o.has_version) {
    std::string list;
    for (const char* v : support.versions) {
      if (v == nullptr) break;
      if (version_tenths(v) == version_tenths(o.version)) {
        o.version = double(version_tenths(v)) / 10;
        return o;
      }
      list += (list.empty() ? "" : ", ") + std::string(v);
    }
    char given_text[32];
    std::snprintf(given_text, sizeof(given_text), "%g", o.version);
    throw Write_error(name, std::string(format) + " version " + given_text + " cannot be written (" +
                                (list.empty() ? std::string("the format has no version to choose") : list) +
                                ")");
  }
  o.has_version = true;
  o.version = support.default_version != nullptr || support.versions[0] == nullptr
                  ? 0
                  : double(version_tenths(support.versions[0])) / 10;
  return o;
}

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_WRITE_OPTIONS_H
