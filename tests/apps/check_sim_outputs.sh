#!/usr/bin/env bash
# check_sim_outputs.sh SIM SRC_DIR WORK_DIR: whisker-sim regenerates the shipped datasets
# bit-for-bit, is deterministic, and leaves nothing behind when it fails.
set -euo pipefail
sim=$1 src=$2 work=$3
rm -rf "$work"; mkdir -p "$work"
"$src/scripts/make-datasets.sh" "$(dirname "$(dirname "$(dirname "$sim")")")" "$work" >/dev/null
for f in "$src"/datasets/paper_arena/*; do
  cmp "$f" "$work/$(basename "$f")" || { echo "FAIL: $(basename "$f") differs from the shipped file"; exit 1; }
done
echo "ok: shipped datasets regenerate bit-for-bit"
# A failing run (blocked poses only) leaves no rawlog, temporary or final.
printf '%s\n' "0.0 0.0 0" > "$work/blocked.path"
if "$sim" -w "$src/config/worlds/paper_arena.ini" --path "$work/blocked.path" -o "$work/blocked.rawlog" -q 2>/dev/null; then
  echo "FAIL: a run with every pose blocked succeeded"; exit 1
fi
if ls "$work"/blocked* 2>/dev/null | grep -v 'blocked.path$'; then echo "FAIL: files left behind"; exit 1; fi
echo "ok: a failed run leaves nothing behind"
