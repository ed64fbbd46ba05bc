#!/usr/bin/env bash
# Existence calibration of whisker-map over the evaluation worlds (doc/evaluation.md,
# "Calibration"; doc/eval-worlds.md): simulates each category x seed x noise run (whisker-sim
# --path; the paper arena uses its shipped rawlogs), maps it (whisker-map --jobs 1 --world),
# and pools map_tables.csv + map_candidates.csv of all runs of a noise level with
# whisker-eval --calibration-runs: OUT_DIR/calibration-NOISE.{txt,json,png} (bins, ECE, the
# reliability diagram), the same over all noise levels (calibration-all.*), and
# OUT_DIR/runs.tsv (category, seed, noise, F1, median insertion time in ms, wall time in s).
# A run whose rawlog already exists is not simulated again.
# Usage: scripts/calibration.sh [BUILD_DIR] [OUT_DIR] [-- extra whisker-map options...]
# Environment: MAP_CONFIG (whisker-map's -c), CATEGORIES (default: paper_arena random_yaw
#   clutter side_by_side large sparse), SEEDS (default: 1 2 3 4 5), NOISES (default: default
#   very-noisy), PREFIXES (default none: e.g. "0.1 0.25" also maps the first 10% and 25% of
#   each run's sweeps, cut with rawlog-edit, and pools those maps too: objects seen in part,
#   whose existence may lie between 0 and 1).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
out=${2:-$root/out/calibration}
mkdir -p "$out" && out=$(cd "$out" && pwd)  # absolute: the run lists name absolute paths
shift $(( $# > 2 ? 2 : $# ))
[[ ${1:-} == -- ]] && shift
extra=("$@")
categories=${CATEGORIES:-paper_arena random_yaw clutter side_by_side large sparse}
seeds=${SEEDS:-1 2 3 4 5}
noises=${NOISES:-default very-noisy}
map_args=()
[[ -n "${MAP_CONFIG:-}" ]] && map_args=(-c "$MAP_CONFIG")
sim="$build/apps/whisker-sim/whisker-sim" map="$build/apps/whisker-map/whisker-map"
evl="$build/apps/whisker-eval/whisker-eval" obs_plugin="$build/libs/obs/libwhiskermap-obs.so"
for tool in "$sim" "$map" "$evl"; do
  [[ -x "$tool" ]] || { echo "calibration: $tool not found: build first" >&2; exit 1; }
done
mkdir -p "$out"
json_value() { sed -n "s/^ *\"$2\": \([0-9.]*\),*$/\1/p" "$1" | head -1; }
printf 'category\tseed\tnoise\tf1\tmedian_ms\twall_s\n' > "$out/runs.tsv"
: > "$out/runs-all.txt"
for n in $noises; do
  list="$out/runs-$n.txt"
  : > "$list"
  for c in $categories; do
    if [[ $c == paper_arena ]]; then s_list=2011; else s_list=$seeds; fi
    for s in $s_list; do
      dir="$out/runs/$c/seed$s-$n"
      mkdir -p "$dir"
      if [[ $c == paper_arena ]]; then
        world=$root/config/worlds/paper_arena.ini rawlog=$root/datasets/paper_arena/$n.rawlog
      else
        world=$root/config/worlds/eval/$c/seed$s.ini rawlog=$dir/run.rawlog
        [[ -f $rawlog ]] || "$sim" -q -w "$world" --path "$root/config/worlds/eval/$c/seed$s.path" --noise "$n" --seed "$s" -o "$rawlog"
      fi
      "$map" "${map_args[@]}" ${extra[@]+"${extra[@]}"} -q --jobs 1 -i "$rawlog" --world "$world" -o "$dir/map"
      printf '%s %s %s\n' "$world" "$dir/map/map_tables.csv" "$dir/map/map_candidates.csv" | tee -a "$list" >> "$out/runs-all.txt"
      for f in ${PREFIXES:-}; do  # the first fraction f of the sweeps: cut after the k-th sweep's time
        rawlog-edit --list-timestamps --text-file-output "$dir/stamps.txt" -i "$rawlog" -p "$obs_plugin" >/dev/null 2>&1 </dev/null
        cut_time=$(awk -v f="$f" '$2 == "WHISKERS" { t[++n] = $1 } END { k = int(f * n); if (k < 1) k = 1;
          printf "%.6f", k < n ? (t[k] + t[k + 1]) / 2 : t[n] + 1 }' "$dir/stamps.txt")
        rawlog-edit -w --cut --to-time "$cut_time" -i "$rawlog" -o "$dir/prefix-$f.rawlog" -p "$obs_plugin" >/dev/null 2>&1 </dev/null
        "$map" "${map_args[@]}" ${extra[@]+"${extra[@]}"} -q --jobs 1 -i "$dir/prefix-$f.rawlog" --world "$world" -o "$dir/map-prefix-$f"
        printf '%s %s %s\n' "$world" "$dir/map-prefix-$f/map_tables.csv" "$dir/map-prefix-$f/map_candidates.csv" | tee -a "$list" >> "$out/runs-all.txt"
      done
      "$evl" -w "$world" -m "$dir/map/map_tables.csv" --json > "$dir/eval.json"
      row="$c	$s	$n	$(json_value "$dir/eval.json" f1)	$(json_value "$dir/map/summary.json" median)	$(json_value "$dir/map/summary.json" wall_time_s)"
      echo "$row" >> "$out/runs.tsv"
      echo "calibration: $row"
    done
  done
  "$evl" --calibration-runs "$list" --reliability-plot "$out/calibration-$n.png" > "$out/calibration-$n.txt"
  "$evl" --calibration-runs "$list" --json > "$out/calibration-$n.json"
  cat "$out/calibration-$n.txt"
done
"$evl" --calibration-runs "$out/runs-all.txt" --reliability-plot "$out/calibration-all.png" > "$out/calibration-all.txt"
"$evl" --calibration-runs "$out/runs-all.txt" --json > "$out/calibration-all.json"
cat "$out/calibration-all.txt"
echo "calibration: $out/calibration-{$(echo $noises | tr ' ' ,),all}.{txt,json,png}, $out/runs.tsv"
