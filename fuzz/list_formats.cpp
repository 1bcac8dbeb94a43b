// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Prints the keys of the format table (CGAL/PR_star_octree/IO/formats.h), one per line: the fuzz
// targets build.sh builds (fuzz_<key>) and run_all.sh runs.

#include <CGAL/PR_star_octree/IO/formats.h>

#include <iostream>

int main() {
  for (const auto& f : CGAL::PR_star_octree::IO::mesh_formats<>) std::cout << f.key << "\n";
  return 0;
}
