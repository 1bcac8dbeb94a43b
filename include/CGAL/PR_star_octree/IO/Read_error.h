// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_READ_ERROR_H
#define CGAL_PR_STAR_OCTREE_IO_READ_ERROR_H

#include <cstddef>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace PR_star_octree {
namespace IO {

/// \ingroup PkgPRStarOctreeIO
/// Thrown by every reader of `CGAL/PR_star_octree/IO/` on any problem with its input: missing or
/// unreadable file, syntax error, truncated data, count mismatch, index out of range or listed
/// twice in a tetrahedron, non-finite coordinate, unsupported feature of the format...
///
/// `what()` reads `FILE:LINE: message` when a line number is known, `FILE: message` otherwise
/// (binary data, whole-file problems); for binary data the message names the array and the index
/// of the offending element instead.
class Read_error : public std::runtime_error {
public:
  /// `line` is 1-based; 0 means "no line number applies".
  Read_error(const std::string& file, std::size_t line, const std::string& message)
      : std::runtime_error(format(file, line, message)), file_(file), line_(line), message_(message) {}

  /// the name of the file (or of the stream) being read
  const std::string& file() const { return file_; }
  /// the 1-based line number of the problem, or 0 when not applicable
  std::size_t line() const { return line_; }
  /// the message without the `FILE:LINE: ` prefix
  const std::string& message() const { return message_; }

private:
  static std::string format(const std::string& file, std::size_t line, const std::string& message) {
    if (line == 0) return file + ": " + message;
    return file + ":" + std::to_string(line) + ": " + message;
  }
  std::string file_;
  std::size_t line_;
  std::string message_;
};

/// \ingroup PkgPRStarOctreeIO
/// Thrown by the writers of `CGAL/PR_star_octree/IO/` when the file cannot be opened or written,
/// or when the mesh cannot be represented (inconsistent sizes of the data arrays, vertex index out
/// of range, non-finite coordinate...).  `what()` reads `FILE: message`.
class Write_error : public std::runtime_error {
public:
  Write_error(const std::string& file, const std::string& message)
      : std::runtime_error(file + ": " + message), file_(file), message_(message) {}

  /// the name of the file (or of the stream) being written
  const std::string& file() const { return file_; }
  /// the message without the `FILE: ` prefix
  const std::string& message() const { return message_; }

private:
  std::string file_;
  std::string message_;
};

} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_READ_ERROR_H
