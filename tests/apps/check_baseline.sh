#!/usr/bin/env bash
# check_baseline.sh WHISKER_BASELINE WHISKER_EVAL SRC_DIR WORK_DIR: whisker-baseline maps the
# shipped default dataset into a map_tables.csv that whisker-eval scores (F1 1.00); on bad
# input it prints one error line, exits non-zero and leaves the output folder as it was.
set -euo pipefail
base=$1 evl=$2 src=$3 work=$4
expect_error="$(dirname "$0")/expect_error.sh"
data="$src/datasets/paper_arena/default.rawlog" world="$src/config/worlds/paper_arena.ini"
rm -rf "$work"; mkdir -p "$work"
"$base" -q -i "$data" -c "$src/config/whisker-map.ini" -o "$work/map"
[[ "$(ls -A "$work/map")" == $'baseline_legs.csv\nmap_tables.csv' ]] || { echo "FAIL: outputs:"; ls -A "$work/map"; exit 1; }
"$evl" --world "$world" --map "$work/map/map_tables.csv" --json | grep -q '"f1": 1.000000' \
  || { echo "FAIL: F1 below 1:"; "$evl" --world "$world" --map "$work/map/map_tables.csv"; exit 1; }
[[ $(grep -cE ',1\.0000,[0-9]+,4$' "$work/map/map_tables.csv") -eq 6 ]] || { echo "FAIL: expected 6 tables with existence 1 and 4 legs"; exit 1; }
echo "ok: whisker-eval scores the baseline's map (F1 1.00, 6 tables on 4 legs)"

mkdir -p "$work/out"; echo "previous result" > "$work/out/map_tables.csv"
head -c 30000 "$data" > "$work/truncated.rawlog"
"$expect_error" "truncated.rawlog: truncated or corrupt gzip data" "$base" -i "$work/truncated.rawlog" -o "$work/out"
"$expect_error" "missing.rawlog: no such file" "$base" -i "$work/missing.rawlog" -o "$work/out"
"$expect_error" "paper_arena.ini: corrupt rawlog" "$base" -i "$world" -o "$work/out"
"$expect_error" "paper_arena.ini: not a whisker-map configuration" "$base" -i "$data" -c "$world" -o "$work/out"
printf '[MetricMap]\nhierarchicalObjectMap_count=1\n[MetricMap_hierarchicalObjectMap_00_model]\ntable_length=1\n' > "$work/short.ini"
"$expect_error" "short.ini: line [0-9]*: \[MetricMap_hierarchicalObjectMap_00_model\] .*missing required key" "$base" -i "$data" -c "$work/short.ini" -o "$work/out"
"$expect_error" "leg-width must be smaller" "$base" -i "$data" --leg-width 0.8 -o "$work/out"
"$expect_error" "cannot create output folder" "$base" -i "$data" -o /proc/whiskermap-nowhere
[[ "$(ls -A "$work/out")" == "map_tables.csv" ]] || { echo "FAIL: output folder changed:"; ls -A "$work/out"; exit 1; }
[[ "$(cat "$work/out/map_tables.csv")" == "previous result" ]] || { echo "FAIL: previous result overwritten"; exit 1; }
echo "ok: bad input changes nothing"
