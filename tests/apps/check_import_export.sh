#!/usr/bin/env bash
# check_import_export.sh WHISKER_IMPORT WHISKER_EXPORT WHISKER_SIM WHISKER_MAP SRC_DIR WORK_DIR:
# - export then import gives back each shipped dataset byte for byte (every sweep, every pose);
# - the action/sensory-frame layout survives export, import --format action-sf, export;
# - the hand-written log imports and maps (whisker-map runs on it and writes its map);
# - a failed export leaves nothing behind.
set -euo pipefail
import=$1 export=$2 sim=$3 map=$4 src=$5 work=$6
rm -rf "$work"; mkdir -p "$work"
for preset in noiseless default very-noisy; do
  "$export" -q -i "$src/datasets/paper_arena/$preset.rawlog" -o "$work/$preset.csv"
  "$import" -q -i "$work/$preset.csv" --robot scratchbot --noise "$preset" -o "$work/$preset.rawlog"
  cmp "$src/datasets/paper_arena/$preset.rawlog" "$work/$preset.rawlog" ||
    { echo "FAIL: $preset: export + import differs from the shipped rawlog"; exit 1; }
  [[ ! -e "$work/${preset}_ground_truth_robot_path.txt" ]] ||
    { echo "FAIL: an import wrote a ground truth file"; exit 1; }
done
echo "ok: export + import reproduces the shipped datasets byte for byte"

"$sim" -q -w "$src/config/worlds/paper_arena.ini" --grid 4 --seed 5 --format action-sf -o "$work/sf.rawlog"
"$export" -q -i "$work/sf.rawlog" -o "$work/sf.csv"
"$import" -q -i "$work/sf.csv" --robot scratchbot --format action-sf -o "$work/sf2.rawlog"
"$export" -q -i "$work/sf2.rawlog" -o "$work/sf2.csv"
diff <(grep -v '^# exported from' "$work/sf.csv") <(grep -v '^# exported from' "$work/sf2.csv") ||
  { echo "FAIL: action-sf: the second export differs from the first"; exit 1; }
echo "ok: action-sf rawlogs survive export + import + export"

log=$src/tests/data/contact_logs/one_table.csv
"$import" -q -i "$log" --robot scratchbot -o "$work/one_table.rawlog"
"$map" -q -i "$work/one_table.rawlog" -o "$work/one_table_map"
[[ "$(head -1 "$work/one_table_map/map_tables.csv")" == id,x,y,* ]] ||
  { echo "FAIL: whisker-map wrote no map_tables.csv with a header"; exit 1; }
echo "ok: the hand-written log maps; map_tables.csv:"; cat "$work/one_table_map/map_tables.csv"

printf 'not a rawlog\n' > "$work/junk.rawlog"
if "$export" -q -i "$work/junk.rawlog" -o "$work/junk.csv" 2>/dev/null; then echo "FAIL: exported junk"; exit 1; fi
if ls "$work"/junk.csv* 2>/dev/null; then echo "FAIL: a failed export left files"; exit 1; fi
echo "ok: a failed export leaves nothing behind"
