#!/usr/bin/env bash
# The usual alternative (issue 9; doc/slam.md, "Against an occupancy grid"): stock MRPT tools
# with an occupancy grid built from the same whisker contacts (each whisker one range ray,
# whisker-export --ranges), against the same tools / whisker-slam on our object map.
# On the paper-arena lawnmower of datasets/slam/ (882 sweeps, default odometry noise,
# action-sf layout), for filter SEEDS (default "1 2 3"), the first STEPS sweeps (default all):
#  - localisation, stock pf-localization, 2000 particles, start box 0.1 m / 10 deg off:
#    config/grid-pf-localization.ini on the grid of the rays at the true poses, against
#    config/pf-localization.ini (start box moved to the lawnmower's) on whisker-map's object
#    map at the true poses;
#  - SLAM, stock rbpf-slam with config/grid-rbpf-slam.ini (a grid per particle, 30
#    particles); whisker-slam (30 particles) too when WHISKER_SLAM=1 (4-5 minutes a run).
# Every path is scored with `whisker-eval --path EST --truth GT` (raw ATE RMSE, aligned, max,
# final); the odometry on the same prefix is printed for reference.
# Usage: scripts/bench-grid.sh [BUILD_DIR] [WORK_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
work=${2:-$root/out/bench-grid}
mkdir -p "$work"; work=$(cd "$work" && pwd)
steps=${STEPS:-882}
sim=$build/apps/whisker-sim/whisker-sim export=$build/apps/whisker-export/whisker-export
map=$build/apps/whisker-map/whisker-map eval=$build/apps/whisker-eval/whisker-eval
slam=$build/apps/whisker-slam/whisker-slam
shim=$build/tests/pf/libwhiskermap-test-fixed-seed.so maps=$build/libs/maps/libwhiskermap-maps.so
data=$root/datasets/slam/paper_arena_action-sf
cd "$work"

# The maps at the true poses: the dataset's run simulated again with exact odometry (same
# truth, same sweeps), as rays (grid) and as whisker-map's object map.
"$sim" -q --world "$root/config/worlds/paper_arena.ini" --trajectory lawnmower --speed 0.4 --rate 8 \
  --robot scratchbot --noise default --odometry exact --seed 2011 --format action-sf -o exact.rawlog
"$export" -q -i exact.rawlog --ranges-simplemap grid.simplemap
"$map" -q -i exact.rawlog -o objmap --simplemap
# The run: the dataset's log (noisy odometry), its first $steps sweeps, whiskers and rays.
rawlog-edit -w --cut --to-index $((2 * steps - 1)) -i "$data.rawlog" -o run.rawlog -p "$build/libs/obs/libwhiskermap-obs.so" >/dev/null 2>&1 </dev/null
"$export" -q -i run.rawlog --ranges run_ranges.rawlog
# (--to-index keeps one pair more than asked: count what it kept)
steps=$(( $(rawlog-edit --info -i run_ranges.rawlog 2>&1 </dev/null | sed -n 's/^Overall number of objects *: *\([0-9]*\).*/\1/p') / 2 ))
awk -v n="$steps" '/^%/ || ++k <= n' "${data}_ground_truth_robot_path.txt" >truth.txt
awk -v n="$steps" '/^%/ || ++k <= n' "${data}_odometry_path.txt" >odometry.txt
# pf-localization.ini's start box is for tests/pf/table_loop.path: move it to the lawnmower's
# start, (0.25, 0.25, -5.2 deg), the same box as grid-pf-localization.ini's.
sed -n '/^init_PDF_m/p' "$root/config/grid-pf-localization.ini" >box.txt
awk 'NR == FNR { split($0, kv, "="); box[kv[1]] = $0; next }
     { split($0, kv, "="); print ((kv[1] in box) ? box[kv[1]] : $0) }' box.txt "$root/config/pf-localization.ini" >objmap-pf.ini
ln -sf objmap/map.simplemap map.simplemap

score() {  # LABEL PATH [TRUTH]: one line of whisker-eval's figures (also kept in scores.tsv)
  "$eval" --path "$2" --truth "${3:-truth.txt}" --json | python3 -c "
import json, sys
t = json.load(sys.stdin)['trajectory']
print(f\"$1: ATE RMSE raw {t['ate_rmse_m']:.3f} m, aligned {t['aligned_rmse_m']:.3f} m, max {t['ate_max_m']:.3f} m, final {t['final_error_m']:.3f} m / {t['final_yaw_err_deg']:.1f} deg\")
with open('scores.tsv', 'a') as f: print('$1', t['ate_rmse_m'], t['aligned_rmse_m'], t['final_error_m'], sep='\\t', file=f)"
}
timed() {  # LOG CMD...: runs CMD (stdin closed, output to LOG), prints its wall time
  local t0=$SECONDS; timeout 3600 "${@:2}" </dev/null >"$1" 2>&1 || { tail -5 "$1"; echo "FAILED: ${*:2}"; return 1; }
  echo "    ($((SECONDS - t0)) s)"
}
# rbpf-slam's log_estimated_path.txt (step x y z yaw pitch roll timestamp) in the truth's columns
# (on a cut log its last line carries timestamp 0: the truth's of that sweep is used)
rbpf_path() {
  awk 'NR == FNR { if (!/^%/) t[++n] = $1; next }
       !/^%/ { k++; print ($8 != 0 ? $8 : t[k]), $2, $3, $5 }' truth.txt "$1" >"$2"
}

rm -f scores.tsv
echo "== $steps sweeps of $(basename "$data").rawlog"
score "odometry alone" odometry.txt
for seed in ${SEEDS:-1 2 3}; do
  echo "== filter seed $seed"
  timed pf-grid-$seed.log env WHISKERMAP_PF_SEED=$seed LD_PRELOAD="$shim" \
    pf-localization "$root/config/grid-pf-localization.ini" run_ranges.rawlog
  "$root/scripts/pf-path.sh" pf-grid-$seed.log truth.txt pf-grid-$seed.txt /dev/null
  score "pf-localization, occupancy grid" pf-grid-$seed.txt
  timed pf-obj-$seed.log env WHISKERMAP_PF_SEED=$seed LD_PRELOAD="$shim:$maps" \
    pf-localization objmap-pf.ini run.rawlog
  "$root/scripts/pf-path.sh" pf-obj-$seed.log truth.txt pf-obj-$seed.txt /dev/null
  score "pf-localization, object map" pf-obj-$seed.txt
  sed -e "s/^RANDOM_SEED=.*/RANDOM_SEED=$seed/" -e "s/^logOutput_dir=.*/logOutput_dir=rbpf-grid-$seed/" \
    "$root/config/grid-rbpf-slam.ini" >grid-rbpf-slam-$seed.ini
  timed rbpf-grid-$seed.log rbpf-slam grid-rbpf-slam-$seed.ini run_ranges.rawlog
  rbpf_path rbpf-grid-$seed/log_estimated_path.txt rbpf-grid-$seed.txt
  score "rbpf-slam, occupancy grid per particle" rbpf-grid-$seed.txt
  if [[ ${WHISKER_SLAM:-0} == 1 ]]; then
    timed slam-$seed.log "$slam" -q -i run.rawlog -o slam-$seed --particles 30 --seed "$seed" --truth truth.txt
    # a short cut ends with a frame without a sweep (rbpf-slam's line of timestamp 0 above),
    # which whisker-slam skips: its poses are the truth's first ones
    awk -v n="$(grep -vc '^%' slam-$seed/estimated_path.txt)" '/^%/ || ++k <= n' truth.txt >truth-slam.txt
    score "whisker-slam, object map per particle" slam-$seed/estimated_path.txt truth-slam.txt
  fi
done
# Over the seeds: median and worst of each run, and how many seeds beat the odometry's raw ATE.
echo "== over filter seeds ${SEEDS:-1 2 3}"
python3 - <<'PY'
import csv, statistics as st
runs = {}
for label, raw, aligned, final in csv.reader(open("scores.tsv"), delimiter="\t"):
    runs.setdefault(label, []).append((float(raw), float(aligned), float(final)))
odometry = runs.pop("odometry alone")[0][0]
for label, v in runs.items():
    raw, aligned, final = ([r[i] for r in v] for i in range(3))
    print(f"{label}: raw ATE median {st.median(raw):.3f} worst {max(raw):.3f} m, aligned median {st.median(aligned):.3f} "
          f"worst {max(aligned):.3f} m, final median {st.median(final):.3f} m; {sum(r < odometry for r in raw)} of {len(raw)} "
          f"seeds below the odometry's {odometry:.3f} m")
PY
