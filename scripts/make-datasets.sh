#!/usr/bin/env bash
# Regenerates the shipped datasets bit-for-bit:
#   paper_arena/  the paper grid in the paper arena, three sensor noise levels, exact odometry
#   office/       a 12 x 12 grid in config/worlds/office.ini (interior walls, desks, chairs, tables
#                 of two sizes: issue 11), three sensor noise levels, exact odometry
#   slam/         continuous lawnmower paths with default odometry noise (doc/slam.md), in the
#                 paper arena and in config/worlds/eval/random_yaw/seed1.ini, both rawlog layouts
# Usage: scripts/make-datasets.sh [BUILD_DIR] [OUT_DIR]
#   BUILD_DIR  where whiskermap was built (default: build)
#   OUT_DIR    the datasets folder to write paper_arena/, office/ and slam/ into (default: datasets)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
out=${2:-$root/datasets}
sim="$build/apps/whisker-sim/whisker-sim"
[[ -x "$sim" ]] || { echo "make-datasets: $sim not found: build first" >&2; exit 1; }
mkdir -p "$out/paper_arena" "$out/office" "$out/slam"
for preset in noiseless default very-noisy; do
  "$sim" --world "$root/config/worlds/paper_arena.ini" --trajectory paper-grid \
         --robot scratchbot --noise "$preset" --seed 2011 -o "$out/paper_arena/$preset.rawlog"
  "$sim" --world "$root/config/worlds/office.ini" --trajectory paper-grid --grid 12 -q \
         --robot scratchbot --noise "$preset" --seed 2011 -o "$out/office/$preset.rawlog"
done
for world in paper_arena:paper_arena.ini random_yaw1:eval/random_yaw/seed1.ini; do
  for format in obs action-sf; do
    "$sim" --world "$root/config/worlds/${world#*:}" --trajectory lawnmower --speed 0.4 --rate 8 \
           --robot scratchbot --noise default --odometry default --seed 2011 --format "$format" \
           -o "$out/slam/${world%%:*}_$format.rawlog"
  done
done
