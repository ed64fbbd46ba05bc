#!/usr/bin/env bash
# whisker-slam over many filter seeds on a shipped SLAM log (doc/slam.md, doc/benchmarks.md):
# per seed the raw and aligned ATE, final error, map F1, mean ms per step and resamplings, and
# the best particle's raw ATE before smoothing; then the median and worst over the seeds, how
# many beat the odometry alone, and the floor: the same figures for whisker-slam --oracle.
# Usage: scripts/bench-slam-seeds.sh [BUILD_DIR] [WORK_DIR]
#   CONFIG=FILE.ini  the whisker-slam config (default config/whisker-slam.ini)
#   LOG=paper_arena|random_yaw1   the datasets/slam/ log (obs layout; default paper_arena)
#   SEEDS="1 ... 10"  filter seeds (default 1-10); JOBS=2 runs two at once
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
work=${2:-$root/out/bench-slam-seeds}
config=${CONFIG:-$root/config/whisker-slam.ini}
log=${LOG:-paper_arena}
case "$log" in
  paper_arena) world=$root/config/worlds/paper_arena.ini ;;
  random_yaw1) world=$root/config/worlds/eval/random_yaw/seed1.ini ;;
  *) echo "bench-slam-seeds: LOG must be paper_arena or random_yaw1, not '$log'" >&2; exit 1 ;;
esac
mkdir -p "$work"
export build work config log world
run() {
  "$build/apps/whisker-slam/whisker-slam" -q -c "$config" -i "$root/datasets/slam/${log}_obs.rawlog" \
    -o "$work/seed$1" --world "$world" --seed "$1"
}
export -f run
export root
printf '%s\n' ${SEEDS:-1 2 3 4 5 6 7 8 9 10} | xargs -P "${JOBS:-1}" -I{} bash -c 'run {}'
# The floor: the true path smoothed against the true solids (--oracle; no filter, no seed).
"$build/apps/whisker-slam/whisker-slam" -q -c "$config" -i "$root/datasets/slam/${log}_obs.rawlog" \
  -o "$work/oracle" --world "$world" --oracle
python3 - "$work" ${SEEDS:-1 2 3 4 5 6 7 8 9 10} <<'PY'
import json, statistics, sys
work, seeds = sys.argv[1], sys.argv[2:]
rows = []
for s in seeds:
    S = json.load(open(f"{work}/seed{s}/summary.json"))
    M = json.load(open(f"{work}/seed{s}/metrics.json"))
    e, o = S["estimated"]["trajectory"], S["odometry"]["trajectory"]
    f = S["filter"]["trajectory"] if "filter" in S else e  # before 2026-12-05: no smoothing
    al = M.get("rmse_aligned_m")  # before 2026-12-05 evening: not written
    rows.append((e["ate_rmse_m"], e["aligned_rmse_m"], e["final_error_m"], M["f1"], S["time_per_step_ms"]["mean"], S["resamplings"], o["ate_rmse_m"], f["ate_rmse_m"], M["rmse_m"], al if al is not None else float("nan")))
    print(f"seed {s}: ATE raw {e['ate_rmse_m']:.3f} m, aligned {e['aligned_rmse_m']:.3f} m, final {e['final_error_m']:.3f} m; "
          f"map F1 {M['f1']:.2f}, centre RMSE {M['rmse_m']:.3f} m (aligned {rows[-1][9]:.3f} m); {S['time_per_step_ms']['mean']:.0f} ms per step (mean); "
          f"{S['resamplings']} resamplings; best particle ATE raw {f['ate_rmse_m']:.3f} m")
med = lambda k: statistics.median(r[k] for r in rows)
print(f"median over {len(rows)} seeds: ATE raw {med(0):.3f} m (worst {max(r[0] for r in rows):.3f}), aligned {med(1):.3f} m, "
      f"final {med(2):.3f} m, map F1 {med(3):.2f} (worst {min(r[3] for r in rows):.2f}), centre RMSE {med(8):.3f} m (aligned {med(9):.3f} m), "
      f"{med(4):.0f} ms per step (mean); best particle ATE raw {med(7):.3f} m (worst {max(r[7] for r in rows):.3f}); "
      f"better than the odometry ({rows[0][6]:.3f} m) on {sum(r[0] < r[6] for r in rows)} of {len(rows)}")
S, M = json.load(open(f"{work}/oracle/summary.json")), json.load(open(f"{work}/oracle/metrics.json"))
e = S["estimated"]["trajectory"]
print(f"floor (--oracle: the true path smoothed against the true solids): ATE raw {e['ate_rmse_m']:.3f} m, "
      f"aligned {e['aligned_rmse_m']:.3f} m, final {e['final_error_m']:.3f} m, map F1 {M['f1']:.2f}, "
      f"centre RMSE {M['rmse_m']:.3f} m (aligned {M['rmse_aligned_m']:.3f} m)")
PY
