#!/usr/bin/env bash
# check_sim_trajectories.sh SIM EVAL EXPORT SRC_DIR WORK_DIR: whisker-sim's continuous trajectories
# and odometry presets end to end: outputs, fractional timestamps, determinism (same seed,
# same bytes), the odometry path file only with noisy odometry, and whisker-eval --path on it.
set -euo pipefail
sim=$1 eval=$2 export=$3 src=$4 work=$5
rm -rf "$work"; mkdir -p "$work"; cd "$work"
world="$src/config/worlds/paper_arena.ini"
fail() { echo "FAIL: $*"; exit 1; }
for kind in lawnmower explore wall-follow loop; do
  for run in a b; do
    "$sim" -w "$world" --trajectory "$kind" --duration 20 --odometry default --format action-sf --seed 7 -o "$kind-$run.rawlog" -q
  done
  for f in "$kind-a"*; do cmp "$f" "${f/-a/-b}" || fail "$kind: same seed, different $f"; done
  [[ -f "$kind-a_odometry_path.txt" ]] || fail "$kind: no odometry path"
  lines=$(grep -vc '^%' "$kind-a_ground_truth_robot_path.txt")
  [[ $lines -eq 161 ]] || fail "$kind: $lines sweeps in 20 s at 8 Hz, expected 161"
  sed -n 4p "$kind-a_ground_truth_robot_path.txt" | grep -q '^1300000000.125000 ' || fail "$kind: second sweep not 1/8 s after the first"
  "$eval" --path "$kind-a_odometry_path.txt" --truth "$kind-a_ground_truth_robot_path.txt" --json >"$kind.json"
  grep -q '"poses": 161' "$kind.json" || fail "$kind: whisker-eval: $(cat "$kind.json")"
done
echo "ok: four trajectory kinds, deterministic, 8 Hz, evaluated"
# Exact odometry writes no odometry path; another seed changes the explore path.
"$sim" -w "$world" --trajectory explore --duration 5 --seed 8 -o exact.rawlog -q
[[ ! -e exact_odometry_path.txt ]] || fail "exact odometry wrote an odometry path"
cmp -s exact_ground_truth_robot_path.txt explore-a_ground_truth_robot_path.txt && fail "seed 8 gave seed 7's path"
# Odometry noise has its own random stream: the sweeps do not change with the preset.
"$sim" -w "$world" --trajectory lawnmower --length 5 --seed 3 --odometry exact -o e.rawlog -q
"$sim" -w "$world" --trajectory lawnmower --length 5 --seed 3 --odometry poor -o p.rawlog -q
cmp -s e.rawlog p.rawlog && fail "poor odometry recorded the exact odometry"
"$export" -i e.rawlog -o e.csv; "$export" -i p.rawlog -o p.csv
cmp -s e.csv p.csv && fail "the exported odometry does not differ"
cmp <(grep -v '^#' e.csv | cut -d, -f1,5-) <(grep -v '^#' p.csv | cut -d, -f1,5-) || fail "the sweeps changed with the odometry preset"
"$eval" --path p_odometry_path.txt --truth e_ground_truth_robot_path.txt >/dev/null || fail "poor odometry path does not pair with the truth"
echo "ok: odometry only with noise, on its own stream"
