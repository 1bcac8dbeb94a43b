// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project
//
// Replays the inputs kept from fuzzing (fuzz/, one libFuzzer target per format of the format table
// CGAL/PR_star_octree/IO/formats.h): every file of fuzz_regressions/<key>/ (but README.md) is read
// with the stream reader of the format whose key is <key>, exactly as the fuzz target does
// (tetgen: the .node text, a NUL byte, the .ele text), and must either succeed or
// throw CGAL::PR_star_octree::IO::Read_error, within a time limit; a mesh that was read is then
// given to PR_star_octree_3 (k_v = 4), which may only throw std::invalid_argument.  Crashes and
// memory errors are caught by running this test under the sanitizers (scripts/test_sanitizers.sh).
//
// Usage: test_fuzz_regressions [generated_data_dir (unused)] [shared_data_dir (unused)]
//        The folder is PRSTAR_FUZZ_REGRESSIONS (compile definition), or $PRSTAR_FUZZ_REGRESSIONS.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>

#include "test_harness.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef PRSTAR_FUZZ_REGRESSIONS
#define PRSTAR_FUZZ_REGRESSIONS "fuzz_regressions"
#endif

namespace IO = CGAL::PR_star_octree::IO;
using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;
namespace fs = std::filesystem;

// Wall-clock limit for one file (read + octree), far above what the files need (milliseconds)
// even under ASan/UBSan on a loaded machine.
static constexpr double seconds_per_file = 20.0;

int main() {
  const char* env = std::getenv("PRSTAR_FUZZ_REGRESSIONS");
  const fs::path root = env ? env : PRSTAR_FUZZ_REGRESSIONS;

  CHECK_MSG(fs::is_directory(root), root << " is not a folder");
  int files = 0, read_ok = 0;
  for (const auto& format : IO::mesh_formats<Mesh>) {
    const fs::path dir = root / format.key;
    if (!fs::is_directory(dir)) {
      prstar_test::skip(std::string("no regression input for the ") + format.name + " reader");
      continue;
    }
    std::vector<fs::path> paths;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file() && e.path().extension() != ".md") paths.push_back(e.path());
    std::sort(paths.begin(), paths.end());
    for (const fs::path& p : paths) {
      ++files;
      const std::string name = p.string();
      const auto start = std::chrono::steady_clock::now();
      std::ifstream in(p, std::ios::binary);
      CHECK_MSG(in.good(), "cannot open " << name);
      Mesh mesh;
      try {
        format.read_stream(in, mesh, name);
        ++read_ok;
        try {
          CGAL::PR_star_octree_3<> tree(CGAL::PR_star_octree::make_input(mesh),
                                        CGAL::PR_star_octree::parameters::bucket_size(4));
          // The octree holds what was read.
          CHECK_EQUAL(tree.number_of_vertices(), mesh.number_of_vertices());
          CHECK_EQUAL(tree.number_of_tetrahedra(), mesh.number_of_tetrahedra());
        } catch (const std::invalid_argument&) {
        }
      } catch (const IO::Read_error& e) {
        CHECK_MSG(std::string(e.what()).find(name) != std::string::npos,
                  name << ": the message does not name the input: " << e.what());
      } catch (const std::exception& e) {
        FAIL(name << ": unexpected exception (not Read_error): " << e.what());
      }
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      CHECK_MSG(s <= seconds_per_file, name << ": took " << s << " s (limit " << seconds_per_file << " s)");
    }
  }
  std::cout << "test_fuzz_regressions: " << files << " files (" << read_ok << " read, " << files - read_ok
            << " rejected)" << std::endl;
  CHECK_MSG(files > 0, "no file under " << root);
  return prstar_test::summary("test_fuzz_regressions");
}
