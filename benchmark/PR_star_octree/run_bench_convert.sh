#!/usr/bin/env bash
# The series of results/convert.md: `prstar convert` and `prstar info` against meshio (Python) on a
# generated lattice, whole processes timed by GNU time (median of 3 after a warm-up, the two
# commands of a pair alternated run by run; peak RSS).
#
#   benchmark/PR_star_octree/run_bench_convert.sh BUILD_DIR WORK_DIR [CELLS]
#
# CELLS: the lattice size (default 120: 10.4M tetrahedra, a 460 MB appended-raw .vtu).  Needs
# /usr/bin/time (Debian package `time`) and python3-meshio; run it on a quiet machine.
set -euo pipefail
build=${1:?build directory}
work=${2:?work directory}
cells=${3:-120}
prstar=$build/tools/prstar/prstar
mkdir -p "$work"
mesh=$work/lattice_$cells.vtu
[ -f "$mesh" ] || "$prstar" generate --shape lattice --cells "$cells" -o "$mesh" --quiet
cat > "$work/meshio_convert.py" <<'PY'
import sys, meshio
m = meshio.read(sys.argv[1])
meshio.write(sys.argv[2], m, file_format=sys.argv[3], binary=True)
PY
# shellcheck source=timing.sh
source "$(dirname "$0")/timing.sh"
echo "machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), $(date -u +%FT%TZ)"
for target in msh:gmsh vtk:vtk; do
  ext=${target%%:*} fmt=${target#*:}
  echo "== .vtu -> .$ext (binary): prstar convert against meshio"
  timed "$prstar convert $mesh $work/prstar.$ext --binary --force --quiet" \
        "/usr/bin/python3 $work/meshio_convert.py $mesh $work/meshio.$ext $fmt"
done
echo "== prstar info (orientation and shape of every tetrahedron)"
timed "$prstar info $mesh --json"
