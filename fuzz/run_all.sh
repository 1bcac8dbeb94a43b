#!/usr/bin/env bash
# Runs the fuzz targets one after the other (one core), SECONDS_PER_TARGET each (default 600).
# A crash does not end a target's time: the finding is kept in build/artifacts/<reader>/ and the
# target restarts on its (growing) corpus for the remaining time.  Logs: build/logs/<reader>.log.
# Format keywords come from dict/<reader>.dict.
# Usage: bash fuzz/run_all.sh [key...]   (after bash fuzz/build.sh; default: every format of the
# format table, build/formats.txt)
set -uo pipefail
cd "$(dirname "$0")/build"
per=${SECONDS_PER_TARGET:-600}
targets=("$@")
[ ${#targets[@]} -eq 0 ] && mapfile -t targets < formats.txt
mkdir -p logs
for t in "${targets[@]}"; do
  mkdir -p "artifacts/$t" "corpus/$t"
  : > "logs/$t.log"
  dict=()
  [ -f "../dict/$t.dict" ] && dict=(-dict="../dict/$t.dict")
  end=$(( $(date +%s) + per ))
  while :; do
    left=$(( end - $(date +%s) ))
    [ "$left" -le 5 ] && break
    ./"fuzz_$t" "corpus/$t" -max_total_time="$left" -timeout=10 -rss_limit_mb=2048 -max_len=8192 "${dict[@]}" \
      -print_final_stats=1 -artifact_prefix="artifacts/$t/" >> "logs/$t.log" 2>&1
    echo "=== exit $? at $(date -u +%T)" >> "logs/$t.log"
  done
done
