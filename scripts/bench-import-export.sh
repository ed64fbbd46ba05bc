#!/usr/bin/env bash
# Measures whisker-import / whisker-export speed (rows per second, wall time including start-up)
# on the shipped datasets and on a long log of about 1,000,000 rows (the paper grid driven
# 417 times), with peak memory. Prints the lines doc/benchmarks.md quotes.
# Usage: scripts/bench-import-export.sh [BUILD_DIR] [WORK_DIR]     (about a minute)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
work=${2:-$root/out/bench-import-export}
sim=$build/apps/whisker-sim/whisker-sim
import=$build/apps/whisker-import/whisker-import
export=$build/apps/whisker-export/whisker-export
mkdir -p "$work"
# run LABEL ROWS CMD...: prints wall time, rows/s and peak RSS of one run of CMD.
run() {
  local label=$1 rows=$2; shift 2
  /usr/bin/time -f "%e %M" -o "$work/time.txt" "$@" >/dev/null
  read -r wall kb < "$work/time.txt"
  python3 -c "import sys; w=float(sys.argv[2]); print(f'{sys.argv[1]}: {sys.argv[3]} rows, {w:.2f} s, {int(sys.argv[3])/max(w,0.01):,.0f} rows/s, peak RSS {int(sys.argv[4])/1024:.1f} MB')" "$label" "$wall" "$rows" "$kb"
}
rows() { grep -vc '^#' "$1" | awk '{print $1 - 1}'; }

echo "== shipped datasets (2,400 rows each)"
for p in noiseless default very-noisy; do
  run "export $p" 2400 "$export" -q -i "$root/datasets/paper_arena/$p.rawlog" -o "$work/$p.csv"
  run "import $p" "$(rows "$work/$p.csv")" "$import" -q -i "$work/$p.csv" --robot scratchbot --noise "$p" -o "$work/$p.rawlog"
  cmp -s "$work/$p.rawlog" "$root/datasets/paper_arena/$p.rawlog" && echo "  round trip: byte-identical"
done

echo "== long log: the paper grid driven 417 times (166,800 sweeps)"
"$sim" -q -w "$root/config/worlds/paper_arena.ini" --repeat 417 --seed 1 -o "$work/long.rawlog"
run "export long" "$(( 166800 * 6 ))" "$export" -q -i "$work/long.rawlog" -o "$work/long.csv"
n=$(rows "$work/long.csv")
echo "  $(du -h "$work/long.rawlog" | cut -f1) rawlog -> $(du -h "$work/long.csv" | cut -f1) csv, $n rows"
run "import long" "$n" "$import" -q -i "$work/long.csv" --robot scratchbot -o "$work/long2.rawlog"
run "import long, action-sf" "$n" "$import" -q -i "$work/long.csv" --robot scratchbot --format action-sf -o "$work/long3.rawlog"
cmp -s "$work/long.rawlog" "$work/long2.rawlog" && echo "  round trip: byte-identical"
