#!/usr/bin/env bash
# The mapping part of the main job (scripts/run-main.sh), also run by ctest (main_job_maps):
# maps the shipped default-noise paper-arena dataset with whisker-map's lasting map and
# evaluates it against the ground truth (OUT_DIR/paper_arena_default), then again in the
# paper's per-pose mode with its figures (montage, blackboard snapshots of pose 159:
# OUT_DIR/paper_arena_default_per_pose). doc/outputs.md lists the files.
# Usage: scripts/map-shipped.sh BUILD_DIR OUT_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$1 out=$2
map="$build/apps/whisker-map/whisker-map"
mkdir -p "$out"
"$map" -i "$root/datasets/paper_arena/default.rawlog" --world "$root/config/worlds/paper_arena.ini" \
  -o "$out/paper_arena_default"
"$map" -q -i "$root/datasets/paper_arena/default.rawlog" --world "$root/config/worlds/paper_arena.ini" \
  --mode per_pose --snapshot-pose 159 --snapshot-temperature 1 -o "$out/paper_arena_default_per_pose"
echo "the map: $out/paper_arena_default; the paper's per-pose mode: $out/paper_arena_default_per_pose (doc/outputs.md)"
