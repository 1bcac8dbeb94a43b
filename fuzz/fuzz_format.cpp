// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// libFuzzer target for one format of the format table (CGAL/PR_star_octree/IO/formats.h): the one
// whose key is PRSTAR_FUZZ_FORMAT (build.sh builds fuzz_<key> for every key).  The input is read
// by the record's stream reader (TetGen: the .node text, a NUL byte, the .ele text), then the octree.

#include "fuzz_common.h"

#include <cstdlib>
#include <cstring>

#ifndef PRSTAR_FUZZ_FORMAT
#error "define PRSTAR_FUZZ_FORMAT as the key of a format of CGAL/PR_star_octree/IO/formats.h, e.g. \"vtu\""
#endif

static const CGAL::PR_star_octree::IO::Mesh_format<prstar_fuzz::Mesh>& fuzzed_format() {
  for (const auto& f : CGAL::PR_star_octree::IO::mesh_formats<prstar_fuzz::Mesh>)
    if (std::strcmp(f.key, PRSTAR_FUZZ_FORMAT) == 0) return f;
  std::abort(); // not a key of the table
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const auto& format = fuzzed_format();
  static const std::string name = std::string("fuzz.") + format.extensions[0];
  return prstar_fuzz::run(data, size,
                          [](std::istream& in, prstar_fuzz::Mesh& m) { format.read_stream(in, m, name); });
}
