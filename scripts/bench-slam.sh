#!/usr/bin/env bash
# whisker-slam against the odometry alone (doc/slam.md, doc/benchmarks.md): the paper-arena
# lawnmower (0.4 m/s, 8 Hz, default sensor noise, seed 2011) with `default` odometry (the
# shipped datasets/slam/paper_arena_obs.rawlog) and `poor` odometry (simulated here, same
# truth and sweeps), for PARTICLES (default "30 100") and filter SEEDS (default "1").
# Prints per run: ATE RMSE raw / aligned of the estimate and of the odometry, the map's F1
# and centre RMSE (whisker-eval), time per step, resamplings and the lowest ESS.
# Usage: scripts/bench-slam.sh [BUILD_DIR] [WORK_DIR]   (a 100-particle run takes minutes)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
work=${2:-$root/out/bench-slam}
sim=$build/apps/whisker-sim/whisker-sim
slam=$build/apps/whisker-slam/whisker-slam
world=$root/config/worlds/paper_arena.ini
mkdir -p "$work"
cp "$root/datasets/slam/paper_arena_obs"* "$work/"
for f in "$work"/paper_arena_obs*; do mv "$f" "${f/paper_arena_obs/default}"; done
"$sim" -q -w "$world" --trajectory lawnmower --odometry poor --seed 2011 -o "$work/poor.rawlog"
for odo in default poor; do
  for n in ${PARTICLES:-30 100}; do
    for seed in ${SEEDS:-1}; do
      out="$work/${odo}_${n}_$seed"
      "$slam" -q -i "$work/$odo.rawlog" -o "$out" --world "$world" --particles "$n" --seed "$seed"
      python3 - "$odo" "$n" "$seed" "$out" <<'PY'
import json, sys
odo, n, seed, out = sys.argv[1:]
s = json.load(open(out + "/summary.json"))
m = json.load(open(out + "/metrics.json"))
e, o = s["estimated"]["trajectory"], s["odometry"]["trajectory"]
t = s["time_per_step_ms"]
print(f"{odo} odometry, {n} particles, seed {seed}: ATE RMSE SLAM {e['ate_rmse_m']:.3f} / {e['aligned_rmse_m']:.3f} m "
      f"(max {e['ate_max_m']:.3f}, final {e['final_error_m']:.3f}), odometry {o['ate_rmse_m']:.3f} / {o['aligned_rmse_m']:.3f} m "
      f"(max {o['ate_max_m']:.3f}, final {o['final_error_m']:.3f}); map F1 {m['f1']:.2f}, centre RMSE {m['rmse_m']}, "
      f"{s['map_tables']} tables; {t['mean']:.1f} ms per step (median {t['median']:.1f}, p95 {t['p95']:.1f}), "
      f"{s['resamplings']} resamplings, min ESS {s['ess_min']:.3f}, {s['wall_time_s']:.0f} s, {s['peak_rss_mb']:.0f} MB")
PY
    done
  done
done
