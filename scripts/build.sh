#!/usr/bin/env bash
# Configures and builds everything (library target, prstar, tests, examples, benchmarks) in build/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build -j "${JOBS:-2}"
