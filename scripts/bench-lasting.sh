#!/usr/bin/env bash
# Measures the lasting map's figures in doc/benchmarks.md ("Lasting map: insertion time and
# scaling"), on this machine, default noise:
#  1. time per insertion on the shipped dataset (whisker-insert-bench: median, p95, max, mean;
#     wall and thread CPU time), over REPEAT runs (default 5), then per insertion the least time
#     of the runs (load elsewhere on the machine only adds time);
#  2. scaling: the paper arena tiled to 6, 60 and 600 tables (whisker-sim --tiles, the same
#     density, 400 poses per 6 tables), time per insertion;
#  3. memory: whisker-map's peak RSS (summary.json) on the 6-table world driven over its grid
#     10 and 100 times (4,000 and 40,000 poses; whisker-sim --repeat).
# Usage: scripts/bench-lasting.sh [BUILD_DIR] [WORK_DIR]   (about 10 minutes on an idle machine)
# Environment: MAP_CONFIG (the map configuration; default: the shipped config/whisker-map.ini),
#   REPEAT (section 1's runs; default 5).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
work=${2:-$root/out/bench-lasting}
config=${MAP_CONFIG:-$root/config/whisker-map.ini}
sim="$build/apps/whisker-sim/whisker-sim" map="$build/apps/whisker-map/whisker-map"
bench="$build/apps/whisker-bench/whisker-insert-bench"
world="$root/config/worlds/paper_arena.ini"
for tool in "$sim" "$map" "$bench"; do
  [[ -x "$tool" ]] || { echo "bench-lasting: $tool not found: build first" >&2; exit 1; }
done
mkdir -p "$work"
field() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2], {}, d))" "$@"; }

echo "== 1. per insertion, shipped dataset (datasets/paper_arena/default.rawlog)"
"$bench" -c "$config" --repeat "${REPEAT:-5}" "$root/datasets/paper_arena/default.rawlog"

echo "== 2. scaling: the paper arena tiled, 400 poses per 6 tables"
for t in "1 1" "5 2" "10 10"; do
  set -- $t; n=$(( $1 * $2 * 6 ))
  [[ -s "$work/tables$n.rawlog" ]] || "$sim" -q -w "$world" --tiles $1 $2 --seed 1 -o "$work/tables$n.rawlog"
  "$bench" -c "$config" "$work/tables$n.rawlog"
done

echo "== 3. memory: whisker-map on the 6-table world, its grid driven 10 and 100 times"
for k in 10 100; do
  [[ -s "$work/repeat$k.rawlog" ]] || "$sim" -q -w "$world" --repeat $k --seed 1 -o "$work/repeat$k.rawlog"
  "$map" -q -c "$config" -i "$work/repeat$k.rawlog" -o "$work/repeat$k"
  s="$work/repeat$k/summary.json"
  echo "$(field "$s" 'poses') poses: whisker-map peak RSS $(field "$s" 'peak_rss_mb') MB, median $(field "$s" 'time_per_pose_ms["median"]') ms, p95 $(field "$s" 'time_per_pose_ms["p95"]') ms per pose, $(field "$s" 'map_tables') mapped tables, state: $(field "$s" 'state')"
done
