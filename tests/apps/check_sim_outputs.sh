#!/usr/bin/env bash
# check_sim_outputs.sh SIM SRC_DIR WORK_DIR: whisker-sim regenerates the shipped datasets
# (datasets/paper_arena, datasets/office, datasets/slam) bit-for-bit, is deterministic, and leaves nothing
# behind when it fails.
set -euo pipefail
sim=$1 src=$2 work=$3
rm -rf "$work"; mkdir -p "$work"
"$src/scripts/make-datasets.sh" "$(dirname "$(dirname "$(dirname "$sim")")")" "$work" >/dev/null
for dir in paper_arena office slam; do
  n=0
  for f in "$src/datasets/$dir"/*; do
    cmp "$f" "$work/$dir/$(basename "$f")" || { echo "FAIL: $dir/$(basename "$f") differs from the shipped file"; exit 1; }
    n=$((n + 1))
  done
  [[ $n -eq $(ls "$work/$dir" | wc -l) ]] || { echo "FAIL: $dir: the script writes files that are not shipped"; exit 1; }
done
echo "ok: shipped datasets regenerate bit-for-bit"
# A failing run (a blocked pose on --path) leaves no rawlog, temporary or final.
printf '%s\n' "1.0 2.0 0" "0.0 0.0 0" > "$work/blocked.path"
if "$sim" -w "$src/config/worlds/paper_arena.ini" --path "$work/blocked.path" -o "$work/blocked.rawlog" --odometry default -q 2>/dev/null; then
  echo "FAIL: a run with a blocked pose succeeded"; exit 1
fi
if ls "$work"/blocked* 2>/dev/null | grep -v 'blocked.path$'; then echo "FAIL: files left behind"; exit 1; fi
echo "ok: a failed run leaves nothing behind"
