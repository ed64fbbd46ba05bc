#!/usr/bin/env bash
# Regenerates the reproduced paper figures in doc/img/ and prints the figures quoted in
# doc/results.md: whisker-map (fixed seed) on each shipped paper-arena dataset, in the paper's
# per-pose mode for its figures and in the (default) lasting mode for the map.
#   fig. 5: default noise, fig. 6: noiseless, fig. 7: very noisy  -> doc/img/fig{5,6,7}_*.png
#   figs. 1-2: one pose's blackboard hot and at its MAP            -> doc/img/fig{1,2}_*.png
#   the lasting map of each dataset                               -> doc/img/map_*.png
# Usage: scripts/make-figures.sh [BUILD_DIR] [WORK_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
work=${2:-$root/out/figures}
map="$build/apps/whisker-map/whisker-map"
world="$root/config/worlds/paper_arena.ini"
pose=${SNAPSHOT_POSE:-159} temp=${SNAPSHOT_TEMPERATURE:-1}
mkdir -p "$work" "$root/doc/img"
for entry in 5:default 6:noiseless 7:very-noisy; do
  fig=${entry%%:*} preset=${entry#*:}
  echo "== fig. $fig: $preset"
  "$map" -i "$root/datasets/paper_arena/$preset.rawlog" --world "$world" --seed 1 --mode per_pose \
         --snapshot-pose "$pose" --snapshot-temperature "$temp" -o "$work/$preset-per_pose"
  cp "$work/$preset-per_pose/montage.png" "$root/doc/img/fig${fig}_montage_${preset}.png"
  echo "== the lasting map: $preset"
  "$map" -i "$root/datasets/paper_arena/$preset.rawlog" --world "$world" --seed 1 -o "$work/$preset"
  cp "$work/$preset/map.png" "$root/doc/img/map_${preset}.png"
done
cp "$work/default-per_pose/blackboard_pose${pose}_t${temp}.png" "$root/doc/img/fig1_blackboard_hot.png"
cp "$work/default-per_pose/blackboard_pose${pose}_map.png" "$root/doc/img/fig2_blackboard_map.png"
echo "figures written to $root/doc/img"
