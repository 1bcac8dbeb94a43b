#!/usr/bin/env bash
# Second README command: build if needed and run the whole test suite (CTest).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
cd build && ctest --output-on-failure -j "${JOBS:-2}" "$@"
