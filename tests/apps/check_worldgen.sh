#!/usr/bin/env bash
# check_worldgen.sh BUILD_DIR SRC_DIR WORK_DIR: scripts/make-eval-worlds.sh regenerates the
# shipped evaluation worlds and paths bit-for-bit; whisker-worldgen fails on bad input with
# one error line and leaves nothing behind.
set -euo pipefail
build=$1 src=$2 work=$3
gen="$build/apps/whisker-worldgen/whisker-worldgen"
expect_error="$(dirname "$0")/expect_error.sh"
rm -rf "$work"; mkdir -p "$work"
"$src/scripts/make-eval-worlds.sh" "$build" "$work/eval"
diff -r "$src/config/worlds/eval" "$work/eval" || { echo "FAIL: regenerated worlds differ from the shipped ones"; exit 1; }
echo "ok: config/worlds/eval regenerates bit-for-bit ($(ls "$work"/eval/*/* | wc -l) files)"
"$expect_error" "nowhere.ini: no such file" "$gen" --category clutter --robot "$work/nowhere.ini" -o "$work/bad/x"
"$expect_error" "noise/loud.ini: no such shipped config file" "$gen" --category clutter --noise loud -o "$work/bad/x"
"$expect_error" "cannot create output folder" "$gen" --category clutter -o /proc/whiskermap-nowhere/x
[[ ! -e "$work/bad" ]] || { echo "FAIL: files left behind:"; ls -R "$work/bad"; exit 1; }
echo "ok: bad input leaves nothing behind"
