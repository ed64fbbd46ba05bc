#!/usr/bin/env bash
# check_outputs_atomic.sh WHISKER_MAP WHISKER_SIM SRC_DIR WORK_DIR: regression tests of
# issue 8 for outputs: a failing, terminated or killed run leaves the output folder exactly
# as it was (no staging folder, no *.tmp), -o "" is refused, paths with quotes give valid
# JSON, and whisker-sim commits rawlog, ground truth and picture together.
set -euo pipefail
map=$1 sim=$2 src=$3 work=$4
expect_error="$(dirname "$0")/expect_error.sh"
data="$src/datasets/paper_arena/default.rawlog"
world="$src/config/worlds/paper_arena.ini"
rm -rf "$work"; mkdir -p "$work/out"
echo "previous result" > "$work/out/map_tables.csv"
unchanged() {
  [[ "$(ls -A "$work/out")" == "map_tables.csv" ]] || { echo "FAIL ($1): output folder changed:"; ls -A "$work/out"; exit 1; }
  [[ "$(cat "$work/out/map_tables.csv")" == "previous result" ]] || { echo "FAIL ($1): previous result overwritten"; exit 1; }
}

# A corrupt rawlog with --world (it used to fail after OUTDIR and .staging-PID existed).
printf '\x87nullptr\x88' > "$work/null.rawlog"
"$expect_error" "null.rawlog: corrupt rawlog at object #0: a null object" "$map" -i "$work/null.rawlog" --world "$world" -o "$work/out"
unchanged "corrupt rawlog"
"$expect_error" "the output folder name is empty" "$map" -i "$data" -o ""
"$expect_error" "new/deeper: .*null.rawlog|null.rawlog" "$map" -i "$work/null.rawlog" -o "$work/new/deeper"
[[ ! -e "$work/new" ]] || { echo "FAIL: a failing run left the folder it created"; exit 1; }
echo "ok: failures change nothing"

# Terminated mid-run: the folder is as it was; killed outright: the next run cleans up. (The
# per-pose mode stages its streamed per-pose table at the start: a folder to watch for.)
"$sim" -q -w "$world" --repeat 20 -o "$work/long.rawlog"   # 8000 sweeps: a run of many seconds
# Waits (up to 5 minutes: sanitizer builds are slow) until a run has staged its outputs.
staged() {
  for _ in $(seq 1500); do ls -A "$work/out" | grep -q staging && return 0; sleep 0.2; done
  echo "FAIL: the run never staged its outputs"; exit 1
}
for sig in TERM INT; do
  "$map" -q --mode per_pose -i "$work/long.rawlog" --world "$world" -o "$work/out" & pid=$!
  staged; sleep 1; kill -"$sig" "$pid"; wait "$pid" && { echo "FAIL: SIG$sig run exited 0"; exit 1; } || true
  unchanged "SIG$sig"
done
"$map" -q --mode per_pose -i "$work/long.rawlog" -o "$work/out" & pid=$!
staged; sleep 1; kill -KILL "$pid"; wait "$pid" || true
ls -A "$work/out" | grep -q staging || { echo "FAIL: expected the killed run's staging folder"; exit 1; }
cp "$data" "$work/in\"quote.rawlog"
"$map" -q -i "$work/in\"quote.rawlog" -o "$work/out"
ls -A "$work/out" | grep -q staging && { echo "FAIL: stale staging folder not cleaned"; exit 1; }
grep -q 'in\\"quote.rawlog' "$work/out/summary.json" || { echo "FAIL: quote not escaped in summary.json"; grep input "$work/out/summary.json"; exit 1; }
echo "ok: signals leave nothing, a killed run's leftovers are cleaned, quotes stay valid JSON"

# whisker-sim: a bad --png fails before the rawlog is touched.
echo "old rawlog" > "$work/sim.rawlog"
mkdir -p "$work/picture.png"
"$expect_error" "picture.png: is a folder, not a file" "$sim" -q -w "$world" -o "$work/sim.rawlog" --png "$work/picture.png"
[[ "$(cat "$work/sim.rawlog")" == "old rawlog" ]] || { echo "FAIL: whisker-sim replaced the rawlog"; exit 1; }
[[ -z "$(ls -A "$work" | grep -E 'staging|\.tmp|sim_ground_truth')" ]] || { echo "FAIL: whisker-sim left files"; ls -A "$work"; exit 1; }
"$sim" -q -w "$world" -o "$work/sim.rawlog" --png "$work/sim.png" --grid 2
for f in sim.rawlog sim_ground_truth_robot_path.txt sim_ground_truth_world.ini sim.png; do
  [[ -s "$work/$f" ]] || { echo "FAIL: whisker-sim did not write $f"; exit 1; }
done
echo "ok: whisker-sim commits its outputs together"
