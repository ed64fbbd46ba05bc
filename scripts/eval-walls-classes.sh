#!/usr/bin/env bash
# Issue 11's targets (doc/results.md, "Issue 11's targets on ten seeds"): maps every run of the
# categories with walls and object classes (walls, near_walls, sized_classes, mixed_classes;
# doc/eval-worlds.md) and the office (datasets/office, whisker-map --seed 1..5) with
# config/office-map.ini, scores each with whisker-eval --walls --json, and writes
# OUT_DIR/summary.md: per category and noise level the worst F1, class accuracy, dimension
# errors, centre RMSE, wall recall of the touched length and wall precision, and the objects
# standing on a wall. Seeds above 5 are generated into OUT_DIR/worlds (whisker-worldgen: the
# same category and seed give the same world). Runs two maps at a time.
# Usage: scripts/eval-walls-classes.sh [BUILD_DIR] [OUT_DIR]
#   BUILD_DIR  where whiskermap was built (default: build)
#   OUT_DIR    where to write (default: out/eval-walls-classes)
# Environment: SEEDS (default: 1 2 3 4 5 6 7 8 9 10), NOISES (default: default very-noisy),
#   CATEGORIES (default: walls near_walls sized_classes mixed_classes), JOBS (default: 2).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
out=${2:-$root/out/eval-walls-classes}
mkdir -p "$out" && out=$(cd "$out" && pwd)
seeds=${SEEDS:-1 2 3 4 5 6 7 8 9 10}
noises=${NOISES:-default very-noisy}
categories=${CATEGORIES:-walls near_walls sized_classes mixed_classes}
apps=$build/apps
for tool in whisker-sim whisker-map whisker-eval whisker-worldgen; do
  [[ -x $apps/$tool/$tool ]] || { echo "eval-walls-classes: $apps/$tool/$tool not found: build first" >&2; exit 1; }
done
runs=()
for c in $categories; do
  for s in $seeds; do
    w=$root/config/worlds/eval/$c/seed$s.ini
    if [[ ! -f $w ]]; then
      w=$out/worlds/$c/seed$s.ini
      [[ -f $w ]] || { mkdir -p "$out/worlds/$c"; "$apps/whisker-worldgen/whisker-worldgen" -q --category "$c" --seed "$s" -o "${w%.ini}"; }
    fi
    for n in $noises; do runs+=("$c $s $n $w ${w%.ini}.path"); done
  done
done
for s in 1 2 3 4 5; do
  for n in $noises; do runs+=("office $s $n $root/config/worlds/office.ini $root/datasets/office/$n.rawlog"); done
done
# one CATEGORY SEED NOISE WORLD PATH-OR-RAWLOG: simulates (a .path), maps, scores; prints the manifest line.
one() {
  local c=$1 s=$2 n=$3 w=$4 p=$5 d=$out/$1-$2-$3 rl
  mkdir -p "$d"
  if [[ $p == *.path ]]; then
    rl=$d/run.rawlog
    [[ -f $rl ]] || "$apps/whisker-sim/whisker-sim" -q -w "$w" --path "$p" --robot scratchbot --noise "$n" --seed "$s" -o "$rl"
  else
    rl=$p
  fi
  local t0=$EPOCHREALTIME
  "$apps/whisker-map/whisker-map" -q -c "$root/config/office-map.ini" -i "$rl" --world "$w" -o "$d/map" --seed "$s"
  local t; t=$(awk -v a="$t0" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.1f", b - a }')
  "$apps/whisker-eval/whisker-eval" -w "$w" -m "$d/map/map_tables.csv" --walls "$d/map/map_walls.csv" --rawlog "$rl" --json > "$d/eval.json"
  echo "$c $s $n $t $d/eval.json"
}
export -f one
export out apps root
printf '%s\n' "${runs[@]}" | xargs -P "${JOBS:-2}" -L 1 bash -c 'one "$@"' _ > "$out/manifest.txt"
python3 "$root/scripts/eval_walls_classes.py" "$out/manifest.txt" > "$out/summary.md"
cat "$out/summary.md"
