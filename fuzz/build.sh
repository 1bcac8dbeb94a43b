#!/usr/bin/env bash
# Builds the libFuzzer targets (clang++-14, outside the main CMake build) into fuzz/build/ and
# writes their seed corpora (fuzz/make_seeds.py).  Usage: bash fuzz/build.sh [target...]
# Run one target:  fuzz/build/fuzz_medit fuzz/build/corpus/medit -max_total_time=600 -timeout=10 -rss_limit_mb=2048
set -euo pipefail
cd "$(dirname "$0")"
CXX=${CXX:-clang++-14}
mkdir -p build
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(medit tetgen vtk vtu tet_off msh meshb)
for t in "${targets[@]}"; do
  echo "building fuzz_$t"
  "$CXX" -std=c++17 -g -O1 -fno-omit-frame-pointer -frounding-math \
    -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
    -I../include \
    -DCGAL_PR_STAR_OCTREE_HAS_ZLIB -DCGAL_PR_STAR_OCTREE_HAS_LZ4 -DCGAL_PR_STAR_OCTREE_HAS_LZMA \
    "fuzz_$t.cpp" -o "build/fuzz_$t" -lgmp -lmpfr -lz -llz4 -llzma
done
python3 make_seeds.py build/corpus
/usr/bin/python3 fuzz_vtu_seeds.py build/corpus # compressed VTU, binary VTK (written by VTK)
