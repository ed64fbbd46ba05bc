#!/usr/bin/env bash
# Scores whisker-map and the batch baseline (whisker-baseline) side by side on every evaluation
# category x seed x noise level (doc/eval-worlds.md): simulates each run (whisker-sim --path),
# maps it (whisker-map --jobs 1), runs the baseline, scores both with whisker-eval --json
# (--rawlog: identifiability bound), and writes OUT_DIR/summary.csv (one row per run and method)
# and OUT_DIR/summary.md. If whisker-map has --reverse, each default-noise run is also mapped in
# reverse order and compared with the forward map (OUT_DIR/reversal.csv). Needs python3.
# The paper arena runs on its shipped rawlogs (datasets/paper_arena, category paper_arena).
# Usage: scripts/eval-categories.sh [BUILD_DIR] [OUT_DIR]
#   BUILD_DIR  where whiskermap was built (default: build)
#   OUT_DIR    where to write (default: out/eval-categories)
# Environment: MAP_CONFIG (whisker-map's -c), and to run a subset: CATEGORIES (default: paper_arena random_yaw clutter
#   side_by_side large sparse), SEEDS (default: 1 2 3 4 5), NOISES (default: noiseless default
#   very-noisy).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
out=${2:-$root/out/eval-categories}
categories=${CATEGORIES:-paper_arena random_yaw clutter side_by_side large sparse}
seeds=${SEEDS:-1 2 3 4 5}
noises=${NOISES:-noiseless default very-noisy}
map_args=()  # MAP_CONFIG: whisker-map's config (default: the shipped config/whisker-map.ini)
[[ -n "${MAP_CONFIG:-}" ]] && map_args=(-c "$MAP_CONFIG")
sim="$build/apps/whisker-sim/whisker-sim" map="$build/apps/whisker-map/whisker-map"
base="$build/apps/whisker-baseline/whisker-baseline" evl="$build/apps/whisker-eval/whisker-eval"
helper="$root/scripts/eval_categories.py"
for tool in "$sim" "$map" "$base" "$evl"; do
  [[ -x "$tool" ]] || { echo "eval-categories: $tool not found: build first" >&2; exit 1; }
done
reverse=no
help=$("$map" --help)  # (not piped into grep -q: with pipefail an early exit fails the pipe)
[[ $help == *--reverse* ]] && reverse=yes
mkdir -p "$out"
manifest="$out/manifest.tsv"
: > "$manifest"

# Runs: "category seed noise world rawlog-or-path".
runs=()
for c in $categories; do
  for n in $noises; do
    if [[ $c == paper_arena ]]; then
      runs+=("$c 2011 $n $root/config/worlds/paper_arena.ini $root/datasets/paper_arena/$n.rawlog")
    else
      for s in $seeds; do runs+=("$c $s $n $root/config/worlds/eval/$c/seed$s.ini $root/config/worlds/eval/$c/seed$s.path"); done
    fi
  done
done

elapsed() { awk -v a="$1" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.2f", b - a }'; }
f1of() { sed -n 's/^ *"f1": \([0-9.]*\),*$/\1/p' "$1"; }
# score METHOD DIR CMD...: runs CMD (which writes DIR/map_tables.csv), scores it, records it.
score() {
  local method=$1 dir=$2; shift 2
  local t0=$EPOCHREALTIME
  "$@"
  local t; t=$(elapsed "$t0")
  "$evl" --world "$world" --map "$dir/map_tables.csv" --rawlog "$rawlog" --json > "$dir/eval.json"
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$category" "$seed" "$noise" "$method" "$dir" "$dir/eval.json" "$t" >> "$manifest"
  echo -n " $method F1 $(f1of "$dir/eval.json") (${t} s);"
}

start=$EPOCHREALTIME
i=0
for r in "${runs[@]}"; do
  read -r category seed noise world source <<< "$r"
  i=$((i + 1))
  dir="$out/runs/$category/seed$seed-$noise"
  mkdir -p "$dir"
  if [[ $source == *.rawlog ]]; then
    rawlog=$source
  else
    rawlog="$dir/run.rawlog"
    "$sim" -q -w "$world" --path "$source" --noise "$noise" --seed "$seed" -o "$rawlog"
  fi
  echo -n "[$i/${#runs[@]}] $category seed $seed $noise:"
  score whisker-map "$dir/map" "$map" "${map_args[@]}" -q --jobs 1 -i "$rawlog" --world "$world" -o "$dir/map"
  score baseline "$dir/baseline" "$base" -q -i "$rawlog" -o "$dir/baseline"
  if [[ $reverse == yes && $noise == default ]]; then
    score whisker-map-reversed "$dir/map-reversed" "$map" "${map_args[@]}" -q --jobs 1 --reverse -i "$rawlog" --world "$world" -o "$dir/map-reversed"
  fi
  echo
done

[[ $reverse == yes ]] || echo "eval-categories: whisker-map has no --reverse option: the order test is skipped"
python3 "$helper" build "$manifest" "$out"
echo "eval-categories: ${#runs[@]} runs in $(elapsed "$start") s -> $out/summary.csv, $out/summary.md"
