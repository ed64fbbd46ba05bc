#!/usr/bin/env bash
# whisker-slam's memory and error over long runs (doc/slam.md, "Memory"; doc/benchmarks.md):
# per PATH_SEEDS (default "2011 2012") a 600 s random exploration of the paper arena
# (whisker-sim --trajectory explore, 4,801 sweeps) with `default` odometry, and the same path
# and sweeps with exact odometry; whisker-slam runs STEPS sweeps (default 4000) of each with
# PARTICLES (default 20), CONFIG (default config/whisker-slam.ini) and filter SEEDS (default
# 1; the exact log once, with seed 1), the exact one told so
# (`odometry_model = exact`: the filter runs one particle, on the true path, so the map is
# whisker-map's at the true poses and what grows is the map itself, not the filter's drift).
# Prints per run: the filter's peak resident memory and live heap after the first tenth of
# the sweeps and after the last (summary.json), what all the particles' maps held at those two
# points (tables, legs, explicit contacts), the map's tables (6 in the world), the raw
# ATE of the estimate, of the best particle and of the odometry, ms per step, wall time.
# Usage: scripts/bench-slam-memory.sh [BUILD_DIR] [WORK_DIR]   (a noisy 4,000-step run takes 1-11 minutes)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
work=${2:-$root/out/bench-slam-memory}
config=${CONFIG:-$root/config/whisker-slam.ini}
world=$root/config/worlds/paper_arena.ini
mkdir -p "$work"
# The same config told the odometry is exact, beside a copy of its map config (if any there).
sed 's/^odometry_model *=.*/odometry_model = exact/' "$config" > "$work/exact.ini"
map_config=$(sed -n 's/^map_config *= *\([^ ;]*\).*/\1/p' "$config")
[ -n "$map_config" ] && [ -f "$(dirname "$config")/$map_config" ] && cp "$(dirname "$config")/$map_config" "$work/"
run() {  # run PATH_SEED ODOMETRY FILTER_SEED
  local ini=$config log="$work/explore-$1-$2.rawlog" out="$work/$1-$2-$3"
  [ "$2" = exact ] && ini=$work/exact.ini
  "$build/apps/whisker-slam/whisker-slam" -q -c "$ini" -i "$log" --particles "${PARTICLES:-20}" \
    --sweeps "${STEPS:-4000}" --world "$world" --seed "$3" -o "$out"
  python3 - "$1" "$2" "$3" "$out" <<'PY'
import json, sys
path_seed, odo, seed, out = sys.argv[1:]
s = json.load(open(out + "/summary.json"))
rss, heap = s["filter_peak_rss_mb"], s["filter_heap_mb"]
ate = lambda k: s[k]["trajectory"]["ate_rmse_m"] if k in s else float("nan")
def maps(when):  # summed over the particles
    m = s["filter_maps"][when]
    return (f"{m['tables']} tables, {m['legs']} legs ({m.get('legs_without_table', '?')} without a table, "
            f"{m.get('legs_beside', '?')} beside another), "
            f"{m['contacts_explained'] + m['contacts_unexplained']} contacts ({m['contacts_unexplained']} unexplained), "
            f"{m.get('lasting_chunks_shared', 0)} of {m.get('lasting_chunks', 0)} chunks shared")
print(f"explore path {path_seed}, {odo} odometry, {s['particles_config']} particles asked ({s['particles']} ran), seed {seed}, {s['sweeps']} sweeps: filter peak RSS "
      f"{rss['first_tenth']:.1f} -> {rss['end']:.1f} MB, live heap {heap['first_tenth']:.1f} -> {heap['end']:.1f} MB "
      f"(after the first tenth -> the last sweep); the particles' maps {maps('first_tenth')} -> {maps('end')}; "
      f"{s['map_tables']} tables; raw ATE estimate {ate('estimated'):.3f} m, "
      f"best particle {ate('filter'):.3f} m, odometry {ate('odometry'):.3f} m; "
      f"{s['time_per_step_ms']['mean']:.1f} ms per step (mean), {s['wall_time_s']:.0f} s")
PY
}
for path_seed in ${PATH_SEEDS:-2011 2012}; do
  for odo in default exact; do
    log="$work/explore-$path_seed-$odo.rawlog"
    [ -f "$log" ] || "$build/apps/whisker-sim/whisker-sim" -q -w "$world" --trajectory explore --duration 600 \
      --odometry "$odo" --seed "$path_seed" -o "$log"
  done
  for seed in ${SEEDS:-1}; do run "$path_seed" default "$seed"; done
  run "$path_seed" exact 1  # once: every particle follows the true path
done
