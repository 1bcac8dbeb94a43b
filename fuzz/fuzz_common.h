// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Shared body of the libFuzzer targets: read with the stream form of a reader, accept only
// Read_error as a failure, then build a PR-star octree (small k_v) of every mesh that was read,
// accepting only std::invalid_argument from the constructor.  Anything else (another exception,
// a crash, a sanitizer report, a leak, a timeout) is a finding.

#ifndef PRSTAR_FUZZ_COMMON_H
#define PRSTAR_FUZZ_COMMON_H

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

namespace prstar_fuzz {

using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;
using Octree = CGAL::PR_star_octree_3<>;

inline void build_octree(const Mesh& mesh) {
  try {
    Octree octree(CGAL::PR_star_octree::make_input(mesh), CGAL::PR_star_octree::parameters::bucket_size(4));
    (void)octree.number_of_vertices();
  } catch (const std::invalid_argument&) {
  }
}

// `read(std::istream&, Mesh&)`: one stream reader call.
template <class Read>
int run(const std::uint8_t* data, std::size_t size, const Read& read) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  Mesh mesh;
  try {
    read(in, mesh);
  } catch (const CGAL::PR_star_octree::IO::Read_error&) {
    return 0;
  }
  build_octree(mesh);
  return 0;
}

} // namespace prstar_fuzz

#endif
