#!/usr/bin/env bash
# The main job from a fresh machine: installs what it needs, builds, then regenerates the
# paper-arena dataset with the simulator and maps it, writing everything under OUT_DIR
# (default: out/).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
out=${OUT_DIR:-$root/out}
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
mkdir -p "$out"
"$build/apps/whisker-sim/whisker-sim" --world "$root/config/worlds/paper_arena.ini" \
  --noise default --seed 2011 -o "$out/paper_arena_default.rawlog"
echo "run-main: outputs in $out"
