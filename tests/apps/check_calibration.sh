#!/usr/bin/env bash
# check_calibration.sh BUILD_DIR SRC_DIR WORK_DIR: scripts/calibration.sh on a small subset
# (the paper arena's shipped default rawlog, one sparse world at default noise: 12 tables, all
# found, all real, at existence 1) writes the pooled calibration (text, JSON, reliability PNG)
# and runs.tsv.
set -euo pipefail
build=$1 src=$2 work=$3
rm -rf "$work"; mkdir -p "$work"
CATEGORIES="paper_arena sparse" SEEDS=1 NOISES=default "$src/scripts/calibration.sh" "$build" "$work/out"
out=$work/out
grep -q '^calibration: 12 objects, 12 real; ECE 0.000000$' "$out/calibration-default.txt" || { echo "FAIL: calibration-default.txt"; cat "$out/calibration-default.txt"; exit 1; }
grep -q '^\[0.9, 1.0\]      12      12 ' "$out/calibration-all.txt" || { echo "FAIL: calibration-all.txt"; cat "$out/calibration-all.txt"; exit 1; }
grep -q '"ece": 0.000000,' "$out/calibration-default.json" || { echo "FAIL: calibration-default.json"; exit 1; }
for f in calibration-default.png calibration-all.png; do
  [[ $(head -c 4 "$out/$f" | tail -c 3) == PNG ]] || { echo "FAIL: $f is not a PNG"; exit 1; }
done
[[ $(grep -c $'\tdefault\t1.000000\t' "$out/runs.tsv") == 2 ]] || { echo "FAIL: runs.tsv"; cat "$out/runs.tsv"; exit 1; }
echo "ok: pooled calibration, reliability plots and runs.tsv written"
