// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// libFuzzer target: CGAL::PR_star_octree::IO::read_tetgen (two streams), then the octree.
// The input is split at its first NUL byte: the .node text before, the .ele text after (an input
// without NUL is a .node with an empty .ele).

#include "fuzz_common.h"

#include <cstring>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const char* text = reinterpret_cast<const char*>(data);
  const void* nul = std::memchr(text, '\0', size);
  const std::size_t split = nul ? static_cast<std::size_t>(static_cast<const char*>(nul) - text) : size;
  std::istringstream node(std::string(text, split));
  std::istringstream ele(split < size ? std::string(text + split + 1, size - split - 1) : std::string());
  prstar_fuzz::Mesh mesh;
  try {
    CGAL::PR_star_octree::IO::read_tetgen(node, ele, mesh, "fuzz.node", "fuzz.ele");
  } catch (const CGAL::PR_star_octree::IO::Read_error&) {
    return 0;
  }
  prstar_fuzz::build_octree(mesh);
  return 0;
}
