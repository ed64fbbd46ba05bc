#!/usr/bin/env bash
# The main job from a fresh machine: installs what it needs, builds, maps the shipped
# paper-arena dataset (default noise) with whisker-map, evaluates it against the ground
# truth, and writes everything under OUT_DIR/paper_arena_default (OUT_DIR default: out/).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
out=${OUT_DIR:-$root/out}
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
mkdir -p "$out"
# Map the shipped default-noise paper-arena dataset and evaluate it against the truth.
"$build/apps/whisker-map/whisker-map" -i "$root/datasets/paper_arena/default.rawlog" \
  --world "$root/config/worlds/paper_arena.ini" --snapshot-pose 159 --snapshot-temperature 1 -o "$out/paper_arena_default"
echo "run-main: outputs in $out/paper_arena_default (see doc/outputs.md)"
