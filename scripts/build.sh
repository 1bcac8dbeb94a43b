#!/usr/bin/env bash
# Configures build/ and builds the prstar tool first, then everything else (tests, examples,
# benchmarks, the header check), JOBS (default 2) compilations at a time.  Installs what building
# needs first (scripts/install_dependencies.sh --build-only; the test-only packages are installed
# by scripts/test.sh).
#
#   scripts/build.sh              prstar, then everything
#   scripts/build.sh --tool-only  prstar only (what scripts/setup.sh needs for the demo)
set -euo pipefail
cd "$(dirname "$0")/.."
tool_only=false
case "${1:-}" in
  --tool-only) tool_only=true ;;
  "") ;;
  *) echo "build.sh: unknown option $1 (--tool-only, or nothing for everything)" >&2; exit 2 ;;
esac
bash scripts/install_dependencies.sh --build-only
mkdir -p build
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build/configure.log 2>&1 || { cat build/configure.log; exit 1; }
cmake --build build -j "${JOBS:-2}" --target prstar
if ! $tool_only; then
  cmake --build build -j "${JOBS:-2}"
fi
