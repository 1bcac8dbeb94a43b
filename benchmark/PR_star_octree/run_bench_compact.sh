#!/usr/bin/env bash
# The series of results/compact.md: the plain against the compact tetrahedron array (`--compact`),
# `prstar boundary` and `prstar curvature` on one mesh, whole processes timed by GNU time (median of
# 3 after a warm-up, the two forms alternated run by run; peak RSS), and `prstar stats` bytes per
# tetrahedron with the breakdown.
#
#   benchmark/PR_star_octree/run_bench_compact.sh BUILD_DIR WORK_DIR MESH [K_V...]
#
# K_V: the bucket thresholds (default 50 200).  Needs /usr/bin/time (Debian package `time`); run it
# on a quiet machine.
set -euo pipefail
build=${1:?build directory}
work=${2:?work directory}
mesh=${3:?mesh file}
shift 3
kvs=("$@")
[ ${#kvs[@]} -gt 0 ] || kvs=(50 200)
prstar=$build/tools/prstar/prstar
mkdir -p "$work"
# shellcheck source=timing.sh
source "$(dirname "$0")/timing.sh"
echo "machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), $(date -u +%FT%TZ)"
echo "mesh: $mesh"
for kv in "${kvs[@]}"; do
  for compact in "" "--compact"; do
    "$prstar" stats "$mesh" --kv "$kv" $compact --json | /usr/bin/python3 -c '
import json, sys
s = json.load(sys.stdin)["storage"]
d = s["bytes_per_tetrahedron_detail"]
print("  stats k_v %s%s: %.2f bytes/tet (%s)" % (sys.argv[1], " compact" if s["compact_tetrahedra"] else "",
      s["bytes_per_tetrahedron"], ", ".join("%s %.2f" % (k, v) for k, v in d.items() if v)))' "$kv"
  done
  echo "== k_v $kv: prstar boundary, plain then compact"
  timed "$prstar boundary $mesh --kv $kv --json" "$prstar boundary $mesh --kv $kv --compact --json"
  echo "== k_v $kv: prstar curvature, plain then compact"
  timed "$prstar curvature $mesh --field z --kv $kv --json" "$prstar curvature $mesh --field z --kv $kv --compact --json"
done
