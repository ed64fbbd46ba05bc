#!/usr/bin/env bash
# Regenerates the shipped paper-arena datasets bit-for-bit (datasets/paper_arena/).
# Usage: scripts/make-datasets.sh [BUILD_DIR] [OUT_DIR]
#   BUILD_DIR  where whiskermap was built (default: build)
#   OUT_DIR    where to write (default: datasets/paper_arena)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
out=${2:-$root/datasets/paper_arena}
sim="$build/apps/whisker-sim/whisker-sim"
[[ -x "$sim" ]] || { echo "make-datasets: $sim not found: build first" >&2; exit 1; }
mkdir -p "$out"
for preset in noiseless default very-noisy; do
  "$sim" --world "$root/config/worlds/paper_arena.ini" --trajectory paper-grid \
         --robot scratchbot --noise "$preset" --seed 2011 -o "$out/$preset.rawlog"
done
