#!/usr/bin/env bash
# The series of results/topology.md: bench_topology (critical points, Forman gradient, Morse
# complexes of the PR-star octree against compute_boundary and a global implementation on the
# extended IA) on a small, a 1M and a 10M-tetrahedra mesh, 2 threads.
#
#   benchmark/PR_star_octree/run_bench_topology.sh BUILD_DIR [OUT.md] [DATA_DIR]
#
# BUILD_DIR holds benchmark/PR_star_octree/bench_topology (Release); OUT.md defaults to
# results/topology.md next to this script; DATA_DIR (default /work/benchdata) holds torus_111k.mesh,
# sphere_1m.mesh and mpi/lattice_120.vtu (`prstar generate --shape lattice --cells 120`).
# Before each run it waits (polling every 20 s, up to 15 minutes) until no compiler runs
# (`pgrep -c cc1plus` is 0), and records /proc/loadavg.  Every phase runs in its own process;
# bench_topology kills an IA child over 12 GB of RSS or 10 minutes and reports that baseline phase
# as skipped.  The "Discussion" section at the end of the results file is written by hand after a
# run: this script writes everything above it.
set -euo pipefail
build=${1:?build directory}
here=$(cd "$(dirname "$0")" && pwd)
out=${2:-$here/results/topology.md}
data=${3:-/work/benchdata}
bench=$build/benchmark/PR_star_octree/bench_topology
threads=2
[ -x "$bench" ] || { echo "no $bench: build the target bench_topology first" >&2; exit 1; }

# mesh | options (reps: more on the small meshes, whose phases last milliseconds)
runs=(
  "$data/torus_111k.mesh|--reps 5"
  "$data/sphere_1m.mesh|--reps 3"
  "$data/mpi/lattice_120.vtu|--field scalar --reps 3"
  "$data/mpi/lattice_120.vtu|--field analytic --reps 3"
)

wait_quiet() {
  local n
  for _ in $(seq 45); do
    n=$(pgrep -c cc1plus || true)
    [ "$n" = 0 ] && return 0
    echo "waiting: $n compilations running" >&2
    sleep 20
  done
  return 1
}

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
commit=$(git -C "$here" rev-parse --short HEAD 2>/dev/null || echo unknown)
dirty=$(git -C "$here" status --porcelain -- ../../include 2>/dev/null | head -c1)
compiler=$(grep -m1 '^CMAKE_CXX_COMPILER:' "$build/CMakeCache.txt" | cut -d= -f2)
build_type=$(grep -m1 '^CMAKE_BUILD_TYPE:' "$build/CMakeCache.txt" | cut -d= -f2)
{
  echo "# Scalar-field topology: PR-star octree vs compute_boundary vs a global extended IA"
  echo
  echo "Produced by \`benchmark/PR_star_octree/run_bench_topology.sh\` ($(date -u +%F), $(date -u +%H:%M) UTC start) with"
  echo "\`bench_topology\` built from commit $commit${dirty:+ (library headers modified in the working tree)},"
  echo "$build_type, $($compiler --version | head -1)."
  echo
  echo "Machine: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores, $(awk '/MemTotal/ {printf "%.1f GiB", $2/1048576}' /proc/meminfo) RAM,"
  echo "$(. /etc/os-release && echo "$PRETTY_NAME"), Linux $(uname -r).  $threads threads (TBB) for the package's phases and"
  echo "for the baseline's per-vertex phases; the IA's construction (baselines/Extended_IA.h) is sequential."
  echo
  echo "What is measured (see the header of bench_topology.cpp): each phase in a fresh forked process"
  echo "(the best time of the repetitions; the largest peaks), the structure built untimed before the"
  echo "phase except in the build rows.  *peak RSS*: the process's whole peak (mesh and field, structure"
  echo "with its construction transients, phase); *phase peak RSS*: the peak during the phase alone;"
  echo "*phase extra*: that peak minus the RSS just before the phase.  The octree takes the mesh over"
  echo "(lean construction, no tetrahedron permutation, k_v = 50); the IA references the mesh's arrays."
  echo "The IA runs on the file's vertex order and on the PR-star order (the mesh re-indexed by an"
  echo "octree with k_v = 100).  The baseline's results are checked against the package's: critical"
  echo "type of every vertex, critical simplices per dimension and their checksum, ascending cell of"
  echo "every vertex, descending cell of every tetrahedron."
  echo
} > "$tmp/out.md"

for entry in "${runs[@]}"; do
  mesh=${entry%%|*}
  read -r -a opts <<< "${entry#*|}"
  if [ ! -f "$mesh" ]; then
    echo "missing $mesh: skipped" >&2
    continue
  fi
  quiet=yes
  wait_quiet || quiet=no
  load=$(cut -d' ' -f1-3 /proc/loadavg)
  cmd="bench_topology --threads $threads ${opts[*]} --json-file RUN.json $(basename "$mesh")"
  echo "== $cmd (load $load)" >&2
  status=0
  "$bench" --threads "$threads" "${opts[@]}" --json-file "$tmp/run.json" "$mesh" > "$tmp/table.md" || status=$?
  {
    shown=$(echo "${opts[*]}" | sed 's/--reps [0-9]*//; s/^ *//; s/ *$//')
    echo "## $(basename "$mesh")${shown:+ ($shown)}"
    echo
    echo "Load average before the run: $load$([ "$quiet" = no ] && echo " (**compilations still running after 15 minutes of waiting**)")."
    echo
    echo "    $cmd"
    echo
    sed 's/^### /#### /' "$tmp/table.md"
    [ "$status" = 0 ] || echo "**bench_topology exited with status $status$([ "$status" = 3 ] && echo ": a MISMATCH between the package and the baseline")**"
    echo
    echo "<details><summary>JSON</summary>"
    echo
    echo '```json'
    cat "$tmp/run.json"
    echo '```'
    echo
    echo "</details>"
    echo
  } >> "$tmp/out.md"
done
mkdir -p "$(dirname "$out")"
cp "$tmp/out.md" "$out"
echo "wrote $out" >&2
