#!/usr/bin/env bash
# check_whisker_slam_100.sh WHISKER_SLAM WHISKER_EVAL SRC_DIR WORK_DIR: whisker-slam with the
# shipped config/whisker-slam-100.ini (100 particles, every particle's map annealing 4 sweeps
# together, eq. S7 in the smoother, no two tables overlapping in the map written) on a prefix of
# the shipped default-odometry random_yaw1 log (datasets/slam/): it runs that many particles in
# batches of 4, its smoothed path stays within a stated floor of the truth (doc/slam.md, "100
# particles in batches of 4"), and no two tables of the map written overlap.
set -euo pipefail
trap 'echo "FAIL: line $LINENO: $BASH_COMMAND (exit $?)"' ERR
slam=$1 eval=$2 src=$3 work=$4
rm -rf "$work"; mkdir -p "$work"
data="$src/datasets/slam/random_yaw1_obs"
# The first 300 sweeps (15 m: the first three rows, three tables touched), filter seed 1.
sweeps=300
"$slam" -q -c "$src/config/whisker-slam-100.ini" -i "$data.rawlog" -o "$work/a" --sweeps $sweeps --seed 1 ||
  { rc=$?; echo "FAIL: whisker-slam exited with $rc"; exit 1; }
python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); assert s["particles"] == 100 and s["batch_sweeps"] == 4 and s["disjoint_tables"], s' \
  "$work/a/summary.json" || { echo "FAIL: summary.json: not 100 particles in batches of 4 with disjoint tables"; exit 1; }
python3 "$src/scripts/table_overlaps.py" "$work/a/map_tables.csv" | tee "$work/overlaps.txt"
grep -q '^total: [1-9][0-9]* tables, 0 left out$' "$work/overlaps.txt" ||
  { echo "FAIL: map_tables.csv: no tables, or two overlapping"; exit 1; }
awk -v n=$sweeps '!/^%/ && k++ < n' "${data}_ground_truth_robot_path.txt" > "$work/truth_prefix.txt"
ate() { "$eval" --path "$1" --truth "$work/truth_prefix.txt" --json | sed -n 's/.*"ate_rmse_m": \([0-9.]*\).*/\1/p'; }
est=$(ate "$work/a/estimated_path.txt") odo=$(ate "$work/a/odometry_path.txt") filt=$(ate "$work/a/filter_path.txt")
echo "ATE RMSE over the first $sweeps sweeps: SLAM $est m (best particle $filt m), odometry $odo m"
# Measured 2026-12-07 (this prefix): seed 1 0.027 m, seeds 2-5 0.023-0.032 m, the best particle
# 0.098 m, the odometry 0.187 m; three tables. Asserted: the smoothed path's ATE below
# 4 cm (issue 9's worst case is 6 cm over a whole log) and at most a quarter of the odometry's.
awk -v e="$est" -v o="$odo" 'BEGIN { exit !(e > 0 && e < 0.04 && e <= 0.25 * o) }' ||
  { echo "FAIL: SLAM ATE $est m (odometry $odo m)"; exit 1; }
echo "ok: 100 particles in batches of 4 keep track"
