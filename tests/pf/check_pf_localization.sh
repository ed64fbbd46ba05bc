#!/usr/bin/env bash
# check_pf_localization.sh MAPS_LIB OBS_LIB SEED_SHIM WHISKER_SIM WHISKER_MAP SRC_DIR WORK_DIR
#
# Stock MRPT pf-localization, given our map plugin by LD_PRELOAD and the shipped
# config/pf-localization.ini, localises a whiskered robot against a saved whisker map:
#  1. whisker-map maps the shipped paper-arena dataset (default noise); its map.simplemap
#     is the saved map (the sweeps with their poses).
#  2. whisker-sim drives tests/pf/table_loop.path (113 poses, 5 cm steps, around table_2)
#     with default sensor noise, written as actions + sensory frames (exact odometry
#     increments; the filter's motion model adds the noise).
#  3. pf-localization rebuilds the map from map.simplemap with the .ini's [MetricMap] (the
#     map must come out identical to whisker-map's) and tracks the robot from an initial
#     box that is deliberately off: guess 0.13 m and 10 degrees from the true start.
#  4. Its per-step estimates (the "PDF estimation" log lines: pf-localization writes no
#     estimated-path file) are compared with whisker-sim's ground truth: from step
#     TRACK_FROM on, every estimate must be within MAX_POS_ERR metres and MAX_YAW_ERR degrees.
#  5. Control: the same run without our map library (the observation class only, so the
#     map file still loads but the [MetricMap] yields zero maps) must fail that same check:
#     the map, not the odometry or the prior, is what localises.
#
# The run is made reproducible by SEED_SHIM (tests/pf/fixed_seed.cpp), which seeds MRPT's
# generator from $WHISKERMAP_PF_SEED. Measured (doc/pf-localization.md): over 160 runs
# (filter seeds x sensor-noise seeds, two versions of the map) the worst was 0.059 m and
# 4.7 degrees; the control is 0.31 m and 10.4 degrees off.
# Env overrides, for measuring: WHISKERMAP_PF_SEED (filter seed, default 1),
# WHISKERMAP_PF_SIM_SEED (sensor-noise seed, default 7), WHISKERMAP_PF_SKIP_CONTROL=1.
set -euo pipefail
maps_lib=$1 obs_lib=$2 shim=$3 sim=$4 mapper=$5 src=$6 work=$7

MAX_POS_ERR=0.10   # metres: 1.7x the worst measured (0.059 m)
MAX_YAW_ERR=8      # degrees: 1.7x the worst measured (4.7 deg)
TRACK_FROM=20      # steps (1 m of travel) allowed to converge; all runs converge by step 10
pf_seed=${WHISKERMAP_PF_SEED:-1}
sim_seed=${WHISKERMAP_PF_SIM_SEED:-7}

command -v pf-localization >/dev/null ||
  { echo "pf-localization not installed (scripts/install-deps.sh --tools installs mrpt-apps)"; exit 1; }
ini=$src/config/pf-localization.ini
rm -rf "$work"; mkdir -p "$work"

# 0. The .ini's map definition is whisker-map's (keys and values; comments may differ).
map_keys() { sed -n '/^\[MetricMap\]/,$p' "$1" | sed -e 's/[;#].*//' -e 's/[[:space:]]//g' | grep -v '^$'; }
# (config/pf-global-localization.ini, the global-localisation variant, too, but for its
# use_swept_grid = true and its own sigma_contact: scoring keys, not the map's)
for f in "$ini" "$src/config/pf-global-localization.ini"; do
  own='^$'; [[ $f == "$ini" ]] || own='^sigma_contact='
  if ! diff <(map_keys "$src/config/whisker-map.ini" | grep -v "$own") \
      <(map_keys "$f" | grep -vx 'use_swept_grid=true' | grep -v "$own") >"$work/map_keys.diff"; then
    cat "$work/map_keys.diff"
    echo "FAIL: the [MetricMap...] sections of $f differ from config/whisker-map.ini's (< whisker-map, > pf-localization); copy them over (doc/pf-localization.md)"
    exit 1
  fi
done

# 1. The saved map.
# (whisker-map writes map.simplemap when asked with --simplemap; older builds always did.)
flag=$("$mapper" --help | grep -q -- '--simplemap' && echo --simplemap || true)
"$mapper" -i "$src/datasets/paper_arena/default.rawlog" -o "$work/map" -q $flag
[[ -s "$work/map/map.simplemap" ]] || { echo "FAIL: whisker-map wrote no map.simplemap"; exit 1; }

# 2. The run to localise.
rawlog=$work/table_loop.rawlog
"$sim" -w "$src/config/worlds/paper_arena.ini" --path "$src/tests/pf/table_loop.path" \
  --noise default --seed "$sim_seed" --format action-sf -o "$rawlog" -q
gt=$work/table_loop_ground_truth_robot_path.txt

# Runs pf-localization in DIR (holding map.simplemap) with LD_PRELOAD=LIBS; log in DIR/pf.log.
run_pf() {
  local dir=$1 libs=$2 code=0
  # In a sanitizer build the sanitizer runtime comes first (scripts/sanitize-tests.sh).
  (cd "$dir" && WHISKERMAP_PF_SEED=$pf_seed LD_PRELOAD="${WHISKERMAP_TOOL_PRELOAD:+$WHISKERMAP_TOOL_PRELOAD:}$libs" \
     timeout "${WHISKERMAP_TOOL_TIMEOUT:-120}" pf-localization "$ini" "$rawlog" </dev/null >pf.log 2>&1) || code=$?
  if [[ $code -ne 0 ]]; then
    tail -20 "$dir/pf.log"; echo "FAIL: pf-localization exited $code (log: $dir/pf.log)"; exit 1
  fi
}

# Prints the error table and "RESULT <ok|bad> <max_pos> <max_yaw> <final_pos> <final_yaw>";
# the estimates are the log's "PDF estimation: (x,y,phideg)" lines, one per sweep.
evaluate() {
  sed -n 's/.*PDF estimation: (\([-0-9.]*\),\([-0-9.]*\),\([-0-9.]*\)deg).*/\1 \2 \3/p' "$1" >"$1.est"
  awk -v from="$TRACK_FROM" -v maxp="$MAX_POS_ERR" -v maxa="$MAX_YAW_ERR" '
    NR == FNR { if ($1 !~ /^%/ && NF >= 4) { n++; gx[n] = $2; gy[n] = $3; ga[n] = $4 * 57.29577951308232 } next }
    { m++; ex[m] = $1; ey[m] = $2; ea[m] = $3 }
    END {
      if (m != n || n == 0) { printf "estimates: %d, ground-truth poses: %d\nRESULT bad\n", m, n; exit }
      wp = 0; wa = 0
      for (k = 1; k <= m; k++) {
        e = sqrt((ex[k] - gx[k]) ^ 2 + (ey[k] - gy[k]) ^ 2)
        a = ea[k] - ga[k]; while (a > 180) a -= 360; while (a < -180) a += 360; if (a < 0) a = -a
        if (k - 1 >= from) { if (e > wp) wp = e; if (a > wa) wa = a }
        if ((k - 1) % 10 == 0 || k == m) printf "  step %3d: error %.3f m %5.2f deg\n", k - 1, e, a
      }
      printf "RESULT %s %.4f %.2f %.4f %.2f\n", (wp <= maxp && wa <= maxa) ? "ok" : "bad", wp, wa, e, a
    }' "$gt" "$1.est"
}

# 3-4. With our map.
mkdir -p "$work/pf"; ln -s ../map/map.simplemap "$work/pf/map.simplemap"
run_pf "$work/pf" "$shim $maps_lib"
log=$work/pf/pf.log
grep -q "C++ Class: 'whiskermap::maps::CHierarchicalObjectMap'" "$log" ||
  { echo "FAIL: the log shows no CHierarchicalObjectMap in the metric map"; exit 1; }
out=$(ls -d "$work"/pf/pf-localization-out_000_*)
built=$out/map_whiskermap__maps__CHierarchicalObjectMap_00_map_tables.csv
cmp "$built" "$work/map/map_tables.csv" ||
  { echo "FAIL: the map pf-localization built differs from whisker-map's (are the [MetricMap] sections of config/pf-localization.ini and config/whisker-map.ini equal?)"; exit 1; }
echo "ok: pf-localization rebuilt whisker-map's map ($(($(wc -l <"$built") - 1)) objects) from map.simplemap"
res=$(evaluate "$log"); echo "$res" | grep -v '^RESULT'
read -r _ verdict pos yaw fpos fyaw <<<"$(grep '^RESULT' <<<"$res")"
echo "with the map (filter seed $pf_seed, noise seed $sim_seed): from step $TRACK_FROM on, max error $pos m, $yaw deg; final $fpos m, $fyaw deg (limits $MAX_POS_ERR m, $MAX_YAW_ERR deg)"
[[ $verdict == ok ]] || { echo "FAIL: pf-localization did not track the robot within the limits (log: $log)"; exit 1; }

# 5. Control: no map plugin, so no map; the same check must fail.
if [[ ${WHISKERMAP_PF_SKIP_CONTROL:-0} != 1 ]]; then
  mkdir -p "$work/control"; ln -s ../map/map.simplemap "$work/control/map.simplemap"
  run_pf "$work/control" "$shim $obs_lib"
  grep -q "Showing next the 0 internal maps" "$work/control/pf.log" ||
    { echo "FAIL: the control run still had a map"; exit 1; }
  read -r _ cverdict cpos cyaw cfpos cfyaw <<<"$(evaluate "$work/control/pf.log" | grep '^RESULT')"
  echo "control without the map: from step $TRACK_FROM on, max error $cpos m, $cyaw deg; final $cfpos m, $cfyaw deg"
  [[ $cverdict == bad ]] || { echo "FAIL: the check passes even without the map: it cannot tell"; exit 1; }
fi
echo "ok: stock pf-localization localises on the whisker map"
