#!/usr/bin/env bash
# check_export_ranges.sh EXPORT SRC WORK: whisker-export --ranges / --ranges-simplemap on the
# shipped SLAM logs (both layouts). Stock rawlog-edit, with no plugin (the rays are MRPT's own
# CObservationRange), must read every object: per sweep six rays (one per whisker) and the
# layout's odometry object kept. A failing run writes none of its outputs.
set -euo pipefail
export=$1 src=$2 work=$3
command -v rawlog-edit >/dev/null || { echo "FAIL: rawlog-edit not installed (mrpt-apps)"; exit 1; }
rm -rf "$work"; mkdir -p "$work"; cd "$work"
sweeps=882 whiskers=6
info() { LD_PRELOAD="${WHISKERMAP_TOOL_PRELOAD:-}" rawlog-edit --info -i "$1" 2>&1 </dev/null; }
count() { sed -n "s/^Overall number of objects *: *\([0-9]*\).*/\1/p" <<<"$1"; }

for layout in obs action-sf; do
  in=$src/datasets/slam/paper_arena_$layout.rawlog
  "$export" -i "$in" --ranges "$layout.rawlog" --ranges-simplemap "$layout.simplemap" -q
  [[ -s "$layout.simplemap" ]] || { echo "FAIL: no $layout.simplemap"; exit 1; }
  out=$(info "$layout.rawlog")
  if grep -q "not registered" <<<"$out"; then echo "$out"; echo "FAIL: a class stock rawlog-edit does not know"; exit 1; fi
  n=$(count "$out")
  # obs layout: odometry + 6 rays per sweep; action-sf: an action collection + a frame of 6 rays
  expected=$([[ $layout == obs ]] && echo $((sweeps * (1 + whiskers))) || echo $((2 * sweeps)))
  [[ "$n" == "$expected" ]] || { echo "$out"; echo "FAIL: $layout: read $n objects, expected $expected"; exit 1; }
  for i in 0 5; do grep -q "WHISKERS_RANGE_$i" <<<"$out" || { echo "$out"; echo "FAIL: no WHISKERS_RANGE_$i label"; exit 1; }; done
  echo "ok: $layout: rawlog-edit read $n objects"
done
# both layouts hold the same rays: their text exports agree (rawlog-edit --export-txt is per
# sensor label; compare one whisker)
# A failing run (unwritable contact log) writes neither of the other outputs.
if "$export" -i "$src/datasets/slam/paper_arena_obs.rawlog" --ranges fail.rawlog -o /dev/null/x.csv -q 2>err.txt; then
  echo "FAIL: exit 0 with an unwritable output"; exit 1
fi
[[ $(grep -c . err.txt) -eq 1 ]] || { cat err.txt; echo "FAIL: not one error line"; exit 1; }
[[ ! -e fail.rawlog ]] || { echo "FAIL: fail.rawlog left behind by a failed run"; exit 1; }
echo "ok: a failed run left no output ($(cat err.txt))"
