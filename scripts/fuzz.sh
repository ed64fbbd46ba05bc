#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, clang with ASan + UBSan) in FUZZ_BUILD_DIR (default
# build-fuzz) and runs them one after the other on one core (doc/reliability.md).
# Usage: scripts/fuzz.sh [--seconds S | --runs N] [TARGET...]
#   --seconds S  fuzz each target for S seconds (the test command's short form uses 30)
#   --runs N     fuzz each target for N executions (the long form: 10000000)
#   TARGET       rawlog observation world_ini robot_ini noise_ini map_ini path_file path_log table_csv
#                contact_log odometry_ini
#                (default: all)
# Each target starts from its seed corpus fuzz/corpus/<target>/ plus what earlier runs
# found (FUZZ_BUILD_DIR/corpus/<target>/); a crash, leak, hang (>10 s) or out-of-memory (>2 GiB)
# stops the script with the reproducer saved as FUZZ_BUILD_DIR/<crash|leak|timeout|oom>-*.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${FUZZ_BUILD_DIR:-$root/build-fuzz}
limit=(-max_total_time=30)
all=(rawlog observation world_ini robot_ini noise_ini map_ini path_file path_log table_csv contact_log odometry_ini)
targets=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --seconds) limit=(-max_total_time="$2"); shift 2 ;;
    --runs) limit=(-runs="$2"); shift 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done
[[ ${#targets[@]} -eq 0 ]] && targets=("${all[@]}")

CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DWHISKERMAP_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DWHISKERMAP_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build "$build" -j "${JOBS:-2}" --target "${targets[@]/#/fuzz_}"
cd "$build"
for t in "${targets[@]}"; do
  mkdir -p "corpus/$t"
  echo "fuzz.sh: $t (${limit[*]})"
  "./fuzz/fuzz_$t" "${limit[@]}" -max_len=8192 -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$build/" "corpus/$t" "$root/fuzz/corpus/$t" 2>"fuzz-$t.log" \
    || { tail -n 40 "fuzz-$t.log"; echo "fuzz.sh: $t FAILED (log: $build/fuzz-$t.log)"; exit 1; }
  grep -E "^stat::number_of_executed_units|^Done" "fuzz-$t.log" | sed "s/^/  /"
done
echo "fuzz.sh: all ${#targets[@]} targets clean"
