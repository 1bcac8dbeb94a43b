#!/usr/bin/env bash
# Second README command: install the test-only packages too, build everything (if needed) and run
# the whole test suite (CTest).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
bash scripts/build.sh
cd build && ctest --output-on-failure -j "${JOBS:-2}" "$@"
