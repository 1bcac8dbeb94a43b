#!/usr/bin/env bash
# First README command: install what building needs (not the test-only packages), build the prstar
# tool only, and run the main job (prstar demo: the PR-star octree statistics of a unit ball meshed
# by CGAL Mesh_3, no input file needed).  scripts/test.sh installs and builds the rest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh --tool-only
./build/tools/prstar/prstar demo "$@"
