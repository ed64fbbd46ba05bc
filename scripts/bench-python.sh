#!/usr/bin/env bash
# Inserting a sweep from Python vs from C++ (doc/benchmarks.md, "Python"): the same loop,
# every sweep of the shipped default rawlog into a fresh map (shipped config, keep_history
# off), in C++ (build/python/bench/insert_loop) and through the whiskermap module
# (python/bench/insert_loop.py), interleaved so that both see the same machine load.
# Usage: scripts/bench-python.sh [BUILD_DIR] [REPEATS] [ROUNDS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
repeats=${2:-5}
rounds=${3:-3}
data="$root/datasets/paper_arena/default.rawlog"
python=$(sed -n 's/^Python3_EXECUTABLE:FILEPATH=//p' "$build/CMakeCache.txt")
cpp="$build/python/bench/insert_loop"
[[ -x "$cpp" && -n "$python" ]] || { echo "bench-python: build first (with the Python module and benchmarks)" >&2; exit 1; }
for mode in lasting per_pose; do
  for ((r = 0; r < rounds; r++)); do
    "$cpp" "$data" "$mode" "$repeats"
    PYTHONPATH="$build/python/module" "$python" "$root/python/bench/insert_loop.py" "$data" "$mode" "$repeats"
  done
done
