#!/usr/bin/env bash
# check_eval_categories.sh BUILD_DIR SRC_DIR WORK_DIR: scripts/eval-categories.sh on a small
# subset (the paper arena's shipped default rawlog, one sparse world) writes summary.csv and
# summary.md with whisker-map and the baseline side by side, and the order test (--reverse).
set -euo pipefail
build=$1 src=$2 work=$3
rm -rf "$work"; mkdir -p "$work"
CATEGORIES="paper_arena sparse" SEEDS=1 NOISES=default "$src/scripts/eval-categories.sh" "$build" "$work/out"
csv="$work/out/summary.csv"
grep -q '^paper_arena,2011,default,baseline,1.0,1.0,1.0,' "$csv" || { echo "FAIL: baseline row"; cat "$csv"; exit 1; }
for m in whisker-map baseline whisker-map-reversed; do
  grep -q "^sparse,1,default,$m," "$csv" || { echo "FAIL: no sparse $m row"; cat "$csv"; exit 1; }
done
grep -q '^| sparse | default | baseline | 1 | 1.000 |' "$work/out/summary.md" || { echo "FAIL: summary.md"; cat "$work/out/summary.md"; exit 1; }
grep -q '^| paper_arena | 1 | ' "$work/out/summary.md" || { echo "FAIL: order section"; cat "$work/out/summary.md"; exit 1; }
echo "ok: summary.csv and summary.md written, order test run"
