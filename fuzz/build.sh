#!/usr/bin/env bash
# Builds the libFuzzer targets (clang++-14, outside the main CMake build) into fuzz/build/ and
# writes their seed corpora (fuzz/make_seeds.py): one target fuzz_<key> per format of the format
# table (CGAL/PR_star_octree/IO/formats.h, listed by list_formats.cpp into build/formats.txt), all
# from fuzz_format.cpp.  Usage: bash fuzz/build.sh [key...]
# Run one target:  fuzz/build/fuzz_medit fuzz/build/corpus/medit -max_total_time=600 -timeout=10 -rss_limit_mb=2048
set -euo pipefail
cd "$(dirname "$0")"
CXX=${CXX:-clang++-14}
mkdir -p build
"$CXX" -std=c++17 -O1 -frounding-math -I../include list_formats.cpp -o build/list_formats -lgmp -lmpfr
build/list_formats > build/formats.txt
targets=("$@")
[ ${#targets[@]} -eq 0 ] && mapfile -t targets < build/formats.txt
for t in "${targets[@]}"; do
  echo "building fuzz_$t"
  "$CXX" -std=c++17 -g -O1 -fno-omit-frame-pointer -frounding-math \
    -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
    -I../include -DPRSTAR_FUZZ_FORMAT="\"$t\"" \
    -DCGAL_PR_STAR_OCTREE_HAS_ZLIB -DCGAL_PR_STAR_OCTREE_HAS_LZ4 -DCGAL_PR_STAR_OCTREE_HAS_LZMA \
    fuzz_format.cpp -o "build/fuzz_$t" -lgmp -lmpfr -lz -llz4 -llzma
done
python3 make_seeds.py build/corpus
/usr/bin/python3 fuzz_vtu_seeds.py build/corpus # compressed VTU, binary VTK (written by VTK)
