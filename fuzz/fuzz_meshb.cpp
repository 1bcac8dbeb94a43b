// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// libFuzzer target: CGAL::PR_star_octree::IO::read_meshb (stream form; Medit binary, versions
// 1-4, both byte orders), then the octree.

#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return prstar_fuzz::run(data, size, [](std::istream& in, prstar_fuzz::Mesh& m) {
    CGAL::PR_star_octree::IO::read_meshb(in, m, "fuzz.meshb");
  });
}
