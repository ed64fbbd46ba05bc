#!/usr/bin/env bash
# check_map_bad_input.sh WHISKER_MAP SRC_DIR WORK_DIR: on a truncated rawlog, a rawlog with
# no whisker sweeps, or a bad config, whisker-map prints one error line, exits non-zero and
# leaves the output folder exactly as it was.
set -euo pipefail
map=$1 src=$2 work=$3
expect_error="$(dirname "$0")/expect_error.sh"
rm -rf "$work"; mkdir -p "$work/out"
echo "previous result" > "$work/out/map_tables.csv"
data="$src/datasets/paper_arena/default.rawlog"
head -c 30000 "$data" > "$work/truncated.rawlog"
"$expect_error" "truncated.rawlog: truncated or corrupt gzip data" "$map" -i "$work/truncated.rawlog" -o "$work/out"
"$expect_error" "missing.rawlog: no such file" "$map" -i "$work/missing.rawlog" -o "$work/out"
rawlog-edit --remove-label WHISKERS -i "$data" -o "$work/odometry_only.rawlog" >/dev/null 2>&1 </dev/null
"$expect_error" "odometry_only.rawlog: holds no whisker observations" "$map" -i "$work/odometry_only.rawlog" -o "$work/out"
printf '[MetricMap]\nhierarchicalObjectMap_count=1\n[MetricMap_hierarchicalObjectMap_00_insertOpts]\nmemory=7\n' > "$work/bad.ini"
"$expect_error" "bad.ini: line 4: \[MetricMap_hierarchicalObjectMap_00_insertOpts\] memory: unknown key" "$map" -i "$data" -c "$work/bad.ini" -o "$work/out"
"$expect_error" "snapshot-temperature 99" "$map" -i "$data" -o "$work/out" --mode per_pose --snapshot-pose 1 --snapshot-temperature 99
"$expect_error" "snapshot-pose draws a per-pose blackboard: it needs --mode per_pose" "$map" -i "$data" -o "$work/out" --snapshot-pose 1
[[ "$(ls -A "$work/out")" == "map_tables.csv" ]] || { echo "FAIL: output folder changed:"; ls -A "$work/out"; exit 1; }
[[ "$(cat "$work/out/map_tables.csv")" == "previous result" ]] || { echo "FAIL: previous result overwritten"; exit 1; }
echo "ok: bad input changes nothing"
