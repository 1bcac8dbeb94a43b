#!/usr/bin/env bash
# First README command: install the dependencies, build, and run the main job (prstar demo: the
# PR-star octree statistics of a unit ball meshed by CGAL Mesh_3, no input file needed).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
./build/tools/prstar/prstar demo "$@"
