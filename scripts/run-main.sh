#!/usr/bin/env bash
# The main job from a fresh machine: installs what it needs, builds, maps the shipped
# paper-arena dataset (default noise) with whisker-map, evaluates it against the ground
# truth, and writes everything under OUT_DIR/paper_arena_default (the lasting map) and
# OUT_DIR/paper_arena_default_per_pose (the paper's per-pose mode) (OUT_DIR default: out/).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
out=${OUT_DIR:-$root/out}
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
# Map the shipped default-noise paper-arena dataset and evaluate it against the truth.
"$root/scripts/map-shipped.sh" "$build" "$out"
