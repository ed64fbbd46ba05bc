#!/usr/bin/env bash
# check_eval_scale.sh WHISKER_EVAL WORK_DIR: whisker-eval on a 9,801-table world (99 x 99
# tables 2 m apart) with a map of one estimate per table and 200 per-pose rows finishes and
# matches every table. Before issue 8 this was one dense cubic Hungarian (hours); ctest's
# TIMEOUT on this test is the guard, not a benchmark (doc/benchmarks.md has the timing).
set -euo pipefail
eval=$1 work=$2
rm -rf "$work"; mkdir -p "$work"
awk 'BEGIN { print "[arena]\nx_min=0\nx_max=200\ny_min=0\ny_max=200";
  n = 0; for (i = 0; i < 99; i++) for (j = 0; j < 99; j++)
    printf "[table_%d]\nx=%d\ny=%d\nyaw_deg=0\nlength=1\nwidth=0.6\nleg_width=0.05\ntexture=0.5\n", n++, 2 * i + 2, 2 * j + 2 }' > "$work/world.ini"
awk 'BEGIN { print "id,x,y,yaw_deg,length,width,leg_width,texture,existence,contacts,legs";
  n = 0; for (i = 0; i < 99; i++) for (j = 0; j < 99; j++)
    printf "%d,%.2f,%d,1,1,0.6,0.05,0.5,0.9,25,3\n", n++, 2 * i + 2.03, 2 * j + 2 }' > "$work/map.csv"
awk 'BEGIN { print "pose,x,y,yaw_deg,length,width,leg_width,texture,log_posterior";
  for (p = 0; p < 200; p++) printf "%d,%d,%d,0,1,0.6,0.05,0.5,-1\n", p, 2 * (p % 99) + 2, 2 * int(p / 99) + 2 }' > "$work/per_pose.csv"
out=$("$eval" -w "$work/world.ini" -m "$work/map.csv" --per-pose "$work/per_pose.csv" --poses 200 --json)
grep -q '"matched": 9801' <<<"$out" || { echo "FAIL: not every table matched:"; echo "$out"; exit 1; }
grep -q '"poses": 200' <<<"$out" || { echo "FAIL: per-pose figures missing"; exit 1; }
echo "ok: 9801 tables evaluated"
