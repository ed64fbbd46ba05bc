#!/usr/bin/env bash
# Odometry-only trajectory error and simulation speed (doc/slam.md, doc/benchmarks.md): the
# datasets/slam runs (lawnmower, 0.4 m/s, 8 Hz, default sensor noise) in the paper arena and
# random_yaw/seed1, for each odometry preset over SEEDS seeds; whisker-eval --path scores the
# recorded odometry against the truth. Prints one line per world and preset (median and worst
# over the seeds), then simulation speed.
# Usage: scripts/bench-odometry.sh [BUILD_DIR] [WORK_DIR]    (SEEDS=10 by default; about a minute)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
work=${2:-$root/out/bench-odometry}
seeds=${SEEDS:-10}
sim=$build/apps/whisker-sim/whisker-sim
eval=$build/apps/whisker-eval/whisker-eval
mkdir -p "$work"
worlds="paper_arena:paper_arena.ini random_yaw1:eval/random_yaw/seed1.ini"

echo "== odometry alone against the truth, $seeds seeds (seed 1..$seeds): median / worst"
for world in $worlds; do
  for preset in default poor; do
    for seed in $(seq 1 "$seeds"); do
      out="$work/${world%%:*}_${preset}_$seed"
      "$sim" -q -w "$root/config/worlds/${world#*:}" --trajectory lawnmower --odometry "$preset" --seed "$seed" -o "$out.rawlog"
      "$eval" --json --path "${out}_odometry_path.txt" --truth "${out}_ground_truth_robot_path.txt" > "$out.json"
    done
    python3 - "${world%%:*}" "$preset" "$work/${world%%:*}_${preset}_"*.json <<'PY'
import json, statistics, sys
runs = [json.load(open(f))["trajectory"] for f in sys.argv[3:]]
def col(key, scale=1.0):
    v = [r[key] * scale for r in runs]
    return f"{statistics.median(v):.3f} / {max(v):.3f}"
print(f"{sys.argv[1]} {sys.argv[2]} ({len(runs)} runs, {runs[0]['poses']} sweeps, {runs[0]['length_m']:.1f} m): "
      f"ATE RMSE {col('ate_rmse_m')} m, aligned {col('aligned_rmse_m')} m, max {col('ate_max_m')} m, "
      f"RPE {col('rpe_trans', 100)} %, {col('rpe_rot_deg_per_m')} deg/m, final {col('final_error_m')} m")
PY
  done
done

echo "== simulation speed (fastest of 3 runs, wall time including start-up, obs layout)"
speed() {
  local label=$1 best="" kb wall; shift
  for _ in 1 2 3; do
    /usr/bin/time -f "%e %M" -o "$work/time.txt" "$sim" -q "$@" -o "$work/speed.rawlog"
    read -r wall kb < "$work/time.txt"
    best=$(python3 -c "import sys; print(min(float(x) for x in sys.argv[1:] if x))" "$wall" $best)
  done
  local n; n=$(grep -vc '^%' "$work/speed_ground_truth_robot_path.txt")
  python3 -c "import sys; w=float(sys.argv[2]); n=int(sys.argv[3]); print(f'{sys.argv[1]}: {n} sweeps in {w:.2f} s, {n/max(w,0.01):,.0f} sweeps/s, peak RSS {int(sys.argv[4])/1024:.1f} MB')" "$label" "$best" "$n" "$kb"
}
speed "paper grid, exact odometry" -w "$root/config/worlds/paper_arena.ini"
speed "lawnmower, default odometry" -w "$root/config/worlds/paper_arena.ini" --trajectory lawnmower --odometry default
speed "explore 600 s, default odometry" -w "$root/config/worlds/paper_arena.ini" --trajectory explore --duration 600 --odometry default
speed "lawnmower in 60 tables (5 x 2 tiles)" -w "$root/config/worlds/paper_arena.ini" --tiles 5 2 --trajectory lawnmower --odometry default
best=""
for _ in 1 2 3; do
  /usr/bin/time -f "%e" -o "$work/time.txt" "$sim" --help >/dev/null
  best=$(python3 -c "import sys; print(min(float(x) for x in sys.argv[1:] if x))" "$(cat "$work/time.txt")" $best)
done
echo "start-up (whisker-sim --help): $best s"
