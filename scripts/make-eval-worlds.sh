#!/usr/bin/env bash
# Regenerates the evaluation worlds and paths bit-for-bit (config/worlds/eval/, doc/eval-worlds.md):
# every category x seeds 1..5, as <category>/seed<N>.ini (world) and .path (whisker-sim --path).
# Usage: scripts/make-eval-worlds.sh [BUILD_DIR] [OUT_DIR]
#   BUILD_DIR  where whiskermap was built (default: build)
#   OUT_DIR    where to write (default: config/worlds/eval)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
out=${2:-$root/config/worlds/eval}
gen="$build/apps/whisker-worldgen/whisker-worldgen"
[[ -x "$gen" ]] || { echo "make-eval-worlds: $gen not found: build first" >&2; exit 1; }
for category in random_yaw clutter side_by_side large sparse walls mixed_classes near_walls sized_classes varied_legs; do
  mkdir -p "$out/$category"
  for seed in 1 2 3 4 5; do
    "$gen" -q --category "$category" --seed "$seed" -o "$out/$category/seed$seed"
  done
done
