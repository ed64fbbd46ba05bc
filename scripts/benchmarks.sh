#!/usr/bin/env bash
# Measures what doc/benchmarks.md reports, on this machine. Prints one line per figure.
# Usage: scripts/benchmarks.sh [BUILD_DIR] [WORK_DIR]     (takes a few minutes)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
work=${2:-$root/out/benchmarks}
sim="$build/apps/whisker-sim/whisker-sim" map="$build/apps/whisker-map/whisker-map"
world="$root/config/worlds/paper_arena.ini"
mkdir -p "$work"
field() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2], {}, d))" "$@"; }

echo "== per-pose time on the shipped datasets (whisker-map, 1 job)"
for p in noiseless default very-noisy; do
  "$map" -q -i "$root/datasets/paper_arena/$p.rawlog" --world "$world" -o "$work/$p"
  s="$work/$p/summary.json"
  echo "$p: median $(field "$s" 'time_per_pose_ms["median"]') ms, p95 $(field "$s" 'time_per_pose_ms["p95"]') ms, $(field "$s" 'proposals_per_second') proposals/s, F1 $(field "$s" 'metrics["f1"]')"
done

echo "== scaling: tables at the paper arena's density, 400 poses per 6 tables"
for t in "1 1" "5 2" "10 10"; do
  set -- $t; n=$(( $1 * $2 * 6 ))
  "$sim" -q -w "$world" --tiles $1 $2 --seed 1 -o "$work/tables$n.rawlog"
  "$map" -q -i "$work/tables$n.rawlog" -o "$work/tables$n"
  s="$work/tables$n/summary.json"
  echo "$n tables, $(field "$s" 'poses') poses: median $(field "$s" 'time_per_pose_ms["median"]') ms, p95 $(field "$s" 'time_per_pose_ms["p95"]') ms, peak RSS $(field "$s" 'peak_rss_mb') MB, $(field "$s" 'map_objects_supported') mapped tables"
done

echo "== memory: 6 tables, 4,000 vs 40,000 poses (the grid driven 10 and 100 times)"
for k in 10 100; do
  "$sim" -q -w "$world" --repeat $k --seed 1 -o "$work/repeat$k.rawlog"
  "$map" -q -i "$work/repeat$k.rawlog" -o "$work/repeat$k"
  s="$work/repeat$k/summary.json"
  echo "$(field "$s" 'poses') poses: peak RSS $(field "$s" 'peak_rss_mb') MB, median $(field "$s" 'time_per_pose_ms["median"]') ms"
done

echo "== --jobs: 40,000 poses, 600 tables"
for j in 1 2; do
  "$map" -q -j $j -i "$work/tables600.rawlog" -o "$work/jobs$j"
  echo "--jobs $j: wall $(field "$work/jobs$j/summary.json" 'wall_time_s') s"
done
for f in per_pose_tables.csv map_tables.csv montage.png map.png map.bt; do
  cmp -s "$work/jobs1/$f" "$work/jobs2/$f" && echo "$f identical" || echo "$f DIFFERS"
done

echo "== whole pipeline: whisker-sim then whisker-map on the paper arena"
start=$(date +%s.%N)
"$sim" -q -w "$world" --noise default --seed 2011 -o "$work/pipeline.rawlog"
"$map" -q -i "$work/pipeline.rawlog" --world "$world" -o "$work/pipeline"
echo "pipeline wall time: $(python3 -c "print(round($(date +%s.%N) - $start, 2))") s"

echo "== Google Benchmark: insertion and likelihood per sweep"
"$build/apps/whisker-bench/whisker-bench" --benchmark_min_time=1 2>/dev/null | grep BM_
