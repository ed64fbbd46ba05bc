#!/usr/bin/env bash
# check_rbpf_slam_odometry.sh LIBWHISKERMAP_MAPS WHISKER_EVAL SRC_DIR WORK_DIR: stock MRPT
# rbpf-slam with the shipped config/rbpf-slam.ini, unchanged (30 particles, RANDOM_SEED=1),
# on the whole shipped paper-arena SLAM log (action-sf layout, 882 sweeps, default odometry
# noise) beats the odometry: its path's raw ATE (whisker-eval --path) is below the
# odometry's. Measured 2026-12-03: 0.213 m against 0.477 m for RANDOM_SEED=1 (the shipped
# seed); seeds 2 and 3 give 0.426 and 0.886 m, so this guards the shipped seed, not every
# seed (doc/slam.md, "Stock rbpf-slam").
set -euo pipefail
maps=$1 eval=$2 src=$3 work=$4
rm -rf "$work"; mkdir -p "$work"; cd "$work"
command -v rbpf-slam >/dev/null || { echo "FAIL: rbpf-slam not installed (Debian package mrpt-apps)"; exit 1; }
data=$src/datasets/slam/paper_arena_action-sf
code=0
preload=${WHISKERMAP_TOOL_PRELOAD:+$WHISKERMAP_TOOL_PRELOAD:}
LD_PRELOAD="$preload$maps" timeout "${WHISKERMAP_TOOL_TIMEOUT:-600}" rbpf-slam "$src/config/rbpf-slam.ini" "$data.rawlog" </dev/null >rbpf.log 2>&1 || code=$?
[[ $code -eq 0 ]] || { echo "FAIL: rbpf-slam exited $code"; tail -20 rbpf.log; exit 1; }
# One pose per sweep (rbpf-slam logs one more step after the last, stamped 0: cut to the truth's length).
grep -v '^[%#]' "${data}_ground_truth_robot_path.txt" >truth.txt
grep -v '^[%#]' "${data}_odometry_path.txt" >odometry.txt
n=$(wc -l <truth.txt)
awk '!/^%/ { print $8, $2, $3, $5 }' rbpf-slam-out/log_estimated_path.txt | head -n "$n" >estimated.txt
[[ $(wc -l <estimated.txt) -eq $n ]] || { echo "FAIL: rbpf-slam logged $(wc -l <estimated.txt) poses for $n sweeps"; exit 1; }
ate() { "$eval" --path "$1" --truth truth.txt --json | sed -n 's/.*"ate_rmse_m": \([0-9.]*\).*/\1/p'; }
est=$(ate estimated.txt) odo=$(ate odometry.txt)
echo "ATE RMSE over $n sweeps: stock rbpf-slam $est m, odometry $odo m"
awk -v e="$est" -v o="$odo" 'BEGIN { exit !(e > 0 && o > 0 && e < o) }' || { echo "FAIL: stock rbpf-slam ($est m) does not beat the odometry ($odo m)"; exit 1; }
