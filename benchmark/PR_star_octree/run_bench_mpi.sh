#!/usr/bin/env bash
# The series of results/mpi.md: the distributed octree (bench_mpi, phase by phase, peak RSS per
# rank) and `prstar boundary` under mpirun, against one process, on generated lattices.
#
#   benchmark/PR_star_octree/run_bench_mpi.sh BUILD_DIR WORK_DIR [CELLS ...]
#
# CELLS: the lattice sizes (default 120 260: 10.4M and 105.5M tetrahedra); the lattices are written
# to WORK_DIR once (5 GB for 260).  Run it on a quiet machine; it prints JSON lines and /usr/bin/time
# figures, one block per run.
set -euo pipefail
build=${1:?build directory}
work=${2:?work directory}
shift 2
cells=("$@")
[ ${#cells[@]} -eq 0 ] && cells=(120 260)
prstar=$build/tools/prstar/prstar
bench=$build/benchmark/PR_star_octree/bench_mpi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
mkdir -p "$work"
echo "machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), $(date -u +%FT%TZ)"
for n in "${cells[@]}"; do
  mesh=$work/lattice_$n.vtu
  [ -f "$mesh" ] || "$prstar" generate --shape lattice --cells "$n" -o "$mesh" --quiet
  echo "== lattice $n: $(du -h "$mesh" | cut -f1)"
  for threads in 2 1; do
    echo "-- one process, prstar boundary, $threads threads"
    /usr/bin/time -f "wall %e s, peak RSS %M KB" "$prstar" boundary "$mesh" --json --threads "$threads"
  done
  for np in 1 2 4; do
    echo "-- mpirun -np $np bench_mpi (1 thread per rank)"
    mpirun -np "$np" "$bench" "$mesh" --threads 1 --out "$work/lattice_${n}_np$np.pvtu"
    echo "-- mpirun -np $np prstar boundary (1 thread per rank)"
    /usr/bin/time -f "wall %e s, peak RSS of mpirun %M KB" mpirun -np "$np" "$prstar" boundary "$mesh" --json --threads 1
  done
done
