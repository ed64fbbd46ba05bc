#!/usr/bin/env bash
# check_grid_pf_localization.sh SHIM SIM EXPORT EVAL SRC WORK
# Stock pf-localization with the shipped config/grid-pf-localization.ini on an occupancy grid
# built from whisker contacts (doc/slam.md, "Against an occupancy grid"): the grid from the
# rays of the paper-arena lawnmower at its true poses (the dataset's run re-simulated with
# exact odometry), the run the dataset's action-sf log (default odometry noise) as rays, its
# first STEPS sweeps. The estimate's ATE (whisker-eval) must stay under MAX_ATE, and the
# odometry's on the same prefix must not, so the check tells a localising run from dead
# reckoning. Filter seed: $WHISKERMAP_PF_SEED (default 1) through the fixed-seed shim.
set -euo pipefail
shim=$1 sim=$2 export=$3 eval=$4 src=$5 work=$6
STEPS=${WHISKERMAP_GRID_STEPS:-300}
MAX_ATE=0.06   # metres, raw ATE RMSE over the prefix: 2.6x the worst of filter seeds 1-4 (0.023 m; doc/slam.md)

command -v pf-localization >/dev/null || { echo "FAIL: pf-localization not installed (mrpt-apps)"; exit 1; }
command -v rawlog-edit >/dev/null || { echo "FAIL: rawlog-edit not installed (mrpt-apps)"; exit 1; }
rm -rf "$work"; mkdir -p "$work"; cd "$work"
data=$src/datasets/slam/paper_arena_action-sf
"$sim" --world "$src/config/worlds/paper_arena.ini" --trajectory lawnmower --speed 0.4 --rate 8 \
  --robot scratchbot --noise default --odometry exact --seed 2011 --format action-sf -o exact.rawlog -q
"$export" -i exact.rawlog --ranges-simplemap grid.simplemap -q
"$export" -i "$data.rawlog" --ranges ranges.rawlog -q
# the prefix: two rawlog entries (actions, sensory frame) per sweep
rawlog-edit --cut --to-index $((2 * STEPS - 1)) -i ranges.rawlog -o run.rawlog >/dev/null 2>&1 </dev/null
# (--to-index keeps one pair more than asked: count what it kept)
STEPS=$(( $(rawlog-edit --info -i run.rawlog 2>&1 </dev/null | sed -n 's/^Overall number of objects *: *\([0-9]*\).*/\1/p') / 2 ))
code=0
WHISKERMAP_PF_SEED=${WHISKERMAP_PF_SEED:-1} LD_PRELOAD="${WHISKERMAP_TOOL_PRELOAD:+$WHISKERMAP_TOOL_PRELOAD:}$shim" \
  timeout "${WHISKERMAP_TOOL_TIMEOUT:-300}" pf-localization "$src/config/grid-pf-localization.ini" run.rawlog \
  </dev/null >pf.log 2>&1 || code=$?
[[ $code -eq 0 ]] || { tail -20 pf.log; echo "FAIL: pf-localization exited $code (log: $work/pf.log)"; exit 1; }
grep -q "COccupancyGridMap2D" pf.log || { echo "FAIL: the log shows no occupancy grid"; exit 1; }
"$src/scripts/pf-path.sh" pf.log "${data}_ground_truth_robot_path.txt" est.txt truth.txt
n=$(grep -vc '^%' est.txt)
[[ $n -eq $STEPS ]] || { echo "FAIL: $n estimates for $STEPS sweeps"; exit 1; }
# (awk, not grep | head: under pipefail head's early exit can fail the pipeline)
awk -v n="$STEPS" '/^%/ || ++k <= n' "${data}_odometry_path.txt" >odo.txt
ate() { "$eval" --path "$1" --truth truth.txt --json | sed -n 's/.*"ate_rmse_m": *\([-0-9.e]*\).*/\1/p' | tail -1; }
grid=$(ate est.txt) odo=$(ate odo.txt)
echo "first $STEPS sweeps: ATE RMSE (raw) on the grid $grid m, odometry $odo m (limit $MAX_ATE m)"
awk -v a="$odo" -v m="$MAX_ATE" 'BEGIN { exit !(a > m) }' ||
  { echo "FAIL: the odometry alone is within the limit: the check cannot tell"; exit 1; }
awk -v a="$grid" -v m="$MAX_ATE" 'BEGIN { exit !(a <= m) }' ||
  { echo "FAIL: pf-localization on the grid is $grid m off (log: $work/pf.log)"; exit 1; }
echo "ok: stock pf-localization localises on the occupancy grid of the contacts"
