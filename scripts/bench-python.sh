#!/usr/bin/env bash
# Calling the map from Python vs from C++ (doc/benchmarks.md, "Python"): the same loops in C++
# (build/python/bench/map_calls) and through the whiskermap module (python/bench/map_calls.py),
# interleaved so that both see the same machine load: every sweep of the shipped default
# rawlog inserted into a fresh map (shipped config, keep_history off), then each sweep's
# likelihood at 64 poses around its own (per call, and from Python also batched).
# Usage: scripts/bench-python.sh [BUILD_DIR] [REPEATS] [ROUNDS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
repeats=${2:-5}
rounds=${3:-3}
data="$root/datasets/paper_arena/default.rawlog"
python=$(sed -n 's/^Python3_EXECUTABLE:FILEPATH=//p' "$build/CMakeCache.txt")
cpp="$build/python/bench/map_calls"
[[ -x "$cpp" && -n "$python" ]] || { echo "bench-python: build first (with the Python module and benchmarks)" >&2; exit 1; }
lines=$(mktemp)
trap 'rm -f "$lines"' EXIT
for mode in lasting per_pose; do
  for ((r = 0; r < rounds; r++)); do
    "$cpp" "$data" "$mode" "$repeats"
    PYTHONPATH="$build/python/module" "$python" "$root/python/bench/map_calls.py" "$data" "$mode" "$repeats"
  done
done | tee "$lines"
awk '
  # Summary per mode: the best and the median CPU time per sweep, averaged over the rounds.
  $4 == "sweeps" { k = $1 " " $2; best[k] += $9; med[k] += $11; n[k]++ }
  $3 == "likelihood:" { k = $1 " " $2; like[k] += $4; batch[k] += $9; nl[k]++ }
  END {
    split("lasting per_pose", modes, " ")
    for (i = 1; i <= 2; i++) {
      c = "C++ " modes[i]; p = "Python " modes[i]
      printf "%-8s: best C++ %.1f, Python %.1f us/sweep (Python / C++ %.3f); median C++ %.1f, Python %.1f (%.3f)\n",
        modes[i], best[c] / n[c], best[p] / n[p], best[p] / best[c], med[c] / n[c], med[p] / n[p], med[p] / med[c]
      printf "%-8s: likelihood C++ %.2f, Python %.2f us/call (%.3f), Python batched %.2f us/pose (%.3f)\n", modes[i],
        like[c] / nl[c], like[p] / nl[p], like[p] / like[c], batch[p] / nl[p], batch[p] / like[c]
    }
  }' "$lines"
