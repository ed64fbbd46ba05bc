#!/usr/bin/env bash
# Peak memory and time of each app that reads a whole log, on a short and a very long log of
# the same world (issue 8: "a million-pose run of each app in bounded memory"; doc/reliability.md,
# "Scale and memory"). The paper arena's 400-pose grid, driven K times (whisker-sim --repeat K),
# default noise, seed 1. Every figure is GNU time's elapsed seconds and maximum resident set size.
# Usage: scripts/bench-million.sh [BUILD_DIR] [WORK_DIR]
# Environment: POSES (default "4000 1000000"; multiples of 400), APPS (default
#   "sim eval baseline export map"; map is the slowest: 2-5 ms a sweep, so one to two hours
#   for a million poses on one core).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
work=${2:-$root/out/bench-million}
poses=${POSES:-4000 1000000}
apps=${APPS:-sim eval baseline export map}
world="$root/config/worlds/paper_arena.ini"
app() { echo "$build/apps/whisker-$1/whisker-$1"; }
for a in sim eval baseline export map; do
  [[ -x "$(app $a)" ]] || { echo "bench-million: $(app $a) not found: build first" >&2; exit 1; }
done
mkdir -p "$work"
# measure LABEL COMMAND...: one line "LABEL: S s, KB KB" on stdout; the command's own output
# goes to WORK/LABEL.log and stops the script (with the log's tail) if the command fails.
measure() {
  local label=$1; shift
  if ! /usr/bin/time -f '%e %M' -o "$work/$label.time" "$@" >"$work/$label.log" 2>&1; then
    echo "bench-million: $label failed:" >&2; tail -5 "$work/$label.log" >&2; exit 1
  fi
  read -r s kb <"$work/$label.time"
  echo "$label: $s s, $kb KB"
}
for n in $poses; do
  (( n % 400 == 0 )) || { echo "bench-million: $n poses is not a multiple of 400" >&2; exit 1; }
  log="$work/poses$n.rawlog"
  if [[ " $apps " != *" sim "* && ! -s "$log" ]]; then  # the log, unmeasured, when sim is not asked for
    "$(app sim)" -q -w "$world" --repeat $((n / 400)) --seed 1 -o "$log"
  fi
  for a in $apps; do
    case $a in
      sim) measure "sim-$n" "$(app sim)" -q -w "$world" --repeat $((n / 400)) --seed 1 -o "$log" ;;
      eval) measure "eval-$n" "$(app eval)" -w "$world" -m "$root/tests/eval/data/paper_arena_map.csv" --rawlog "$log" ;;
      baseline) measure "baseline-$n" "$(app baseline)" -q -i "$log" -o "$work/baseline$n" ;;
      export) measure "export-$n" "$(app export)" -q -i "$log" -o "$work/contacts$n.csv" --ranges "$work/ranges$n.rawlog" ;;
      map) measure "map-$n" "$(app map)" -q -i "$log" --world "$world" -o "$work/map$n" ;;
      *) echo "bench-million: unknown app '$a' (sim eval baseline export map)" >&2; exit 1 ;;
    esac
  done
  rm -f "$work/contacts$n.csv" "$work/ranges$n.rawlog"  # hundreds of MB at a million poses
done
