#!/usr/bin/env bash
# check_slam_bad_input.sh WHISKER_SLAM SRC_DIR WORK_DIR: a missing rawlog, a bad config key (in
# [slam] or [smooth]), --particles 0, a truth file shorter than the run, --oracle without a
# world or without a true path: one error line, non-zero exit, and the output folder left
# exactly as it was.
set -euo pipefail
slam=$1 src=$2 work=$3
expect_error="$(dirname "$0")/../apps/expect_error.sh"
rm -rf "$work"; mkdir -p "$work/out"
echo "previous result" > "$work/out/estimated_path.txt"
data="$src/datasets/slam/paper_arena_obs.rawlog"
"$expect_error" "missing.rawlog: no such file" "$slam" -i "$work/missing.rawlog" -o "$work/out"
printf '[slam]\nparticles = 10\nparticle = 3\n' > "$work/bad_key.ini"
"$expect_error" "bad_key.ini: line 3: \[slam\] particle: unknown key" "$slam" -i "$data" -c "$work/bad_key.ini" -o "$work/out"
printf '[slam]\nparticles = 10\nresampling = best\n' > "$work/bad_method.ini"
"$expect_error" "bad_method.ini: line 3: \[slam\] resampling: 'best' is not one of" "$slam" -i "$data" -c "$work/bad_method.ini" -o "$work/out"
printf '[slam]\nparticles = 10\n[smooth]\ngate = 0.05\nrond = 3\n' > "$work/bad_smooth.ini"
"$expect_error" "bad_smooth.ini: line 5: \[smooth\] rond: unknown key" "$slam" -i "$data" -c "$work/bad_smooth.ini" -o "$work/out"
printf '[slam]\nparticles = 10\n[smooth]\npasses = 0\n' > "$work/bad_passes.ini"
"$expect_error" "bad_passes.ini: line 4: \[smooth\] passes" "$slam" -i "$data" -c "$work/bad_passes.ini" -o "$work/out"
printf '[slam]\nparticles = 0\n' > "$work/zero.ini"
"$expect_error" "zero.ini: line 2: \[slam\] particles" "$slam" -i "$data" -c "$work/zero.ini" -o "$work/out"
"$expect_error" "--particles 0: the filter needs at least one particle" "$slam" -i "$data" --particles 0 -o "$work/out"
head -5 "$src/datasets/slam/paper_arena_obs_ground_truth_robot_path.txt" > "$work/short_truth.txt"
"$expect_error" "short_truth.txt: 3 poses for 882 sweeps" "$slam" -i "$data" --truth "$work/short_truth.txt" -o "$work/out"
world="$src/config/worlds/paper_arena.ini"
"$expect_error" "--oracle needs --world" "$slam" -i "$data" --oracle -o "$work/out"
ln -s "$data" "$work/no_truth.rawlog"  # no _ground_truth_robot_path.txt beside it
"$expect_error" "--oracle needs the true path .*no_truth.rawlog" "$slam" -i "$work/no_truth.rawlog" --world "$world" --oracle -o "$work/out"
[[ "$(ls -A "$work/out")" == "estimated_path.txt" ]] || { echo "FAIL: output folder changed:"; ls -A "$work/out"; exit 1; }
[[ "$(cat "$work/out/estimated_path.txt")" == "previous result" ]] || { echo "FAIL: previous result overwritten"; exit 1; }
echo "ok: bad input changes nothing"
