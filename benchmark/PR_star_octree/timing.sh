# Shell functions shared by the run_bench_*.sh scripts (sourced; `work` must be set): whole
# processes timed by GNU time, the commands of a series alternated run by run.
# The median of the values on stdin, one a line.
median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
# Runs each command (one string each, split as the shell splits words) once as a warm-up, then 3
# times, the commands alternated; prints each one's median wall seconds and peak RSS.
timed() {
  local i c runs=3
  for c in "$@"; do $c > /dev/null 2>&1 || { echo "failed: $c" >&2; return 1; }; done
  for ((i = 0; i < runs; ++i)); do
    local k=0
    for c in "$@"; do
      /usr/bin/time -f "%e %M" -o "$work/time_$k.$i" $c > /dev/null 2>&1
      k=$((k + 1))
    done
  done
  local k=0
  for c in "$@"; do
    local wall peak
    wall=$(cat "$work"/time_$k.* | cut -d' ' -f1 | median)
    peak=$(cat "$work"/time_$k.* | cut -d' ' -f2 | median)
    printf '  %s\n    median wall %s s, peak %s MiB\n' "$c" "$wall" "$((peak / 1024))"
    rm -f "$work"/time_$k.*
    k=$((k + 1))
  done
}
