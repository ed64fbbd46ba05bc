#!/usr/bin/env bash
# Global localisation with stock MRPT pf-localization on a whisker map (issue 9; doc/slam.md,
# "Global localisation"): config/pf-global-localization.ini, a uniform prior over the whole
# paper arena (4 m x 4 m, any heading), KLD-adaptive sample size up to 20,000 particles.
# The map: whisker-map's, built at the true poses (the lawnmower of datasets/slam/ simulated
# again with exact odometry, as scripts/bench-grid.sh does). The run: the first STEPS sweeps
# (default 300) of datasets/slam/paper_arena_action-sf.rawlog (default odometry noise).
# WORLD=NAME (default paper_arena) runs another shipped SLAM world instead: random_yaw1 (its
# world config/worlds/eval/random_yaw/seed1.ini, its log datasets/slam/random_yaw1_action-sf;
# both worlds are 4 m x 4 m, the .ini's uniform prior).
# TRAJECTORY=explore|wall-follow|loop runs on another path instead of the shipped lawnmower
# log: whisker-sim's generator through the same world (default odometry noise, 8 Hz, 0.4 m/s,
# simulator seed PATH_SEED, default 7), the map still the lawnmower's at the true poses.
# For each filter seed of SEEDS (default 1..10) it prints whether the estimate converged
# (the last estimate, and every one from some step on, within MAX_POS m and MAX_YAW degrees
# of the truth: defaults 0.10 and 8), the step it converged at (the first from which all
# later estimates are within the bounds), the particles at the first and last step, and the
# wall time; then the fraction converged.
# Usage: scripts/global-localization.sh [BUILD_DIR] [WORK_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
work=${2:-$root/out/global-localization}
mkdir -p "$work"; work=$(cd "$work" && pwd)
steps=${STEPS:-300} max_pos=${MAX_POS:-0.10} max_yaw=${MAX_YAW:-8}
ini=${INI:-$root/config/pf-global-localization.ini}
sim=$build/apps/whisker-sim/whisker-sim map=$build/apps/whisker-map/whisker-map
shim=$build/tests/pf/libwhiskermap-test-fixed-seed.so maps=$build/libs/maps/libwhiskermap-maps.so
world=${WORLD:-paper_arena}
case $world in
  paper_arena) world_ini=$root/config/worlds/paper_arena.ini ;;
  random_yaw1) world_ini=$root/config/worlds/eval/random_yaw/seed1.ini ;;
  *) echo "global-localization.sh: unknown WORLD '$world' (paper_arena or random_yaw1)" >&2; exit 1 ;;
esac
data=$root/datasets/slam/${world}_action-sf
trajectory=${TRAJECTORY:-lawnmower}
cd "$work"
case $trajectory in
  lawnmower) ;;
  explore|wall-follow|loop)
    # Long enough for STEPS sweeps at 8 Hz (a pattern repeats until then).
    "$sim" -q --world "$world_ini" --trajectory "$trajectory" --speed 0.4 --rate 8 --duration $((steps / 8 + 2)) \
      --robot scratchbot --noise default --odometry default --seed "${PATH_SEED:-7}" --format action-sf -o path-run.rawlog
    data=$work/path-run ;;
  *) echo "global-localization.sh: unknown TRAJECTORY '$trajectory' (lawnmower, explore, wall-follow or loop)" >&2; exit 1 ;;
esac

if [[ ! -s map.simplemap ]]; then
  "$sim" -q --world "$world_ini" --trajectory lawnmower --speed 0.4 --rate 8 \
    --robot scratchbot --noise default --odometry exact --seed 2011 --format action-sf -o exact.rawlog
  "$map" -q -i exact.rawlog -o objmap --simplemap
  ln -sf objmap/map.simplemap map.simplemap
fi
LD_PRELOAD="${WHISKERMAP_TOOL_PRELOAD:-}" rawlog-edit -w --cut --to-index $((2 * steps - 1)) -i "$data.rawlog" -o run.rawlog \
  -p "$build/libs/obs/libwhiskermap-obs.so" >/dev/null 2>&1 </dev/null
awk -v n="$((steps + 1))" '/^%/ || ++k <= n' "${data}_ground_truth_robot_path.txt" >truth.txt

converged=0 total=0
for seed in ${SEEDS:-1 2 3 4 5 6 7 8 9 10}; do
  t0=$SECONDS
  WHISKERMAP_PF_SEED=$seed LD_PRELOAD="${WHISKERMAP_TOOL_PRELOAD:+$WHISKERMAP_TOOL_PRELOAD:}$shim:$maps" timeout 3600 \
    pf-localization "$ini" run.rawlog </dev/null >pf-$seed.log 2>&1 || { tail -5 pf-$seed.log; echo "seed $seed: pf-localization FAILED"; exit 1; }
  secs=$((SECONDS - t0))
  sed -n 's/.*PDF estimation: (\([-0-9.e]*\),\([-0-9.e]*\),\([-0-9.e]*\)deg).*/\1 \2 \3/p' pf-$seed.log >est-$seed.txt
  particles=$(sed -n 's/.* \([0-9]*\) particles\.\.\..*/\1/p' pf-$seed.log | awk 'NR == 1 { f = $1 } { l = $1; if ($1 > m) m = $1 } END { printf "%s..%s (max %s)", f, l, m }')
  line=$(awk -v maxp="$max_pos" -v maxa="$max_yaw" '
    NR == FNR { if ($1 !~ /^%/) { n++; gx[n] = $2; gy[n] = $3; ga[n] = $4 * 57.29577951308232 } next }
    { m++; ex[m] = $1; ey[m] = $2; ea[m] = $3 }
    END {
      conv = -1
      for (k = 1; k <= m && k <= n; k++) {
        e = sqrt((ex[k] - gx[k]) ^ 2 + (ey[k] - gy[k]) ^ 2)
        a = ea[k] - ga[k]; while (a > 180) a -= 360; while (a < -180) a += 360; if (a < 0) a = -a
        if (e <= maxp && a <= maxa) { if (conv < 0) conv = k - 1 } else conv = -1
      }
      printf "%s %d %.3f %.1f", (conv >= 0 ? "yes" : "no"), conv, e, a
    }' truth.txt est-$seed.txt)
  read -r ok at err yaw <<<"$line"
  total=$((total + 1)); [[ $ok == yes ]] && converged=$((converged + 1))
  echo "seed $seed: converged $ok (from step $at, $(awk -v s="$at" 'BEGIN { printf "%.1f", s / 8 }') s of travel at 8 Hz), final error $err m $yaw deg, particles $particles, $secs s"
done
echo "converged: $converged of $total seeds (within $max_pos m and $max_yaw deg at the end of $steps sweeps)"
