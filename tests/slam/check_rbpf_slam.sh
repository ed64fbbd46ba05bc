#!/usr/bin/env bash
# check_rbpf_slam.sh LIBWHISKERMAP_MAPS LIBWHISKERMAP_OBS SRC_DIR WORK_DIR: stock MRPT
# rbpf-slam (mrpt-apps), given our map class by LD_PRELOAD, runs the shipped
# config/rbpf-slam.ini on a short action-sf rawlog (the first 120 sweeps of the shipped
# paper-arena log) and writes its path log and final map, with a hierarchicalObjectMap in
# its particles. Control: with only the observation class preloaded the .ini makes no map.
set -euo pipefail
maps=$1 obslib=$2 src=$3 work=$4
rm -rf "$work"; mkdir -p "$work"
command -v rbpf-slam >/dev/null || { echo "FAIL: rbpf-slam not installed (Debian package mrpt-apps)"; exit 1; }
# 120 sweeps = 240 entries (an action and a sensory frame each).
# In a sanitizer build the sanitizer runtime is preloaded first (scripts/sanitize-tests.sh).
preload=${WHISKERMAP_TOOL_PRELOAD:+$WHISKERMAP_TOOL_PRELOAD:}
LD_PRELOAD="${WHISKERMAP_TOOL_PRELOAD:-}" rawlog-edit -p "$obslib" --cut --to-index 239 -i "$src/datasets/slam/paper_arena_action-sf.rawlog" \
  -o "$work/short.rawlog" >/dev/null 2>&1 </dev/null
# The map sections are config/whisker-map.ini's, renamed, with keep_history off.
diff <(sed -n '/^\[MappingApplication_/,$p' "$src/config/rbpf-slam.ini") \
     <(sed -n '/^\[MetricMap_/,$p' "$src/config/whisker-map.ini" | sed 's/^\[MetricMap_/[MappingApplication_/; s/^keep_history = true/keep_history = false/') ||
  { echo "FAIL: config/rbpf-slam.ini's map sections differ from config/whisker-map.ini's"; exit 1; }
grep -q '^keep_history = false' "$src/config/rbpf-slam.ini" || { echo "FAIL: keep_history not off"; exit 1; }
cd "$work"
sed 's/^sampleSize=30$/sampleSize=8/' "$src/config/rbpf-slam.ini" > rbpf-slam-8.ini
code=0
LD_PRELOAD="$preload$maps" timeout "${WHISKERMAP_TOOL_TIMEOUT:-300}" rbpf-slam rbpf-slam-8.ini short.rawlog </dev/null >rbpf.log 2>&1 || code=$?
[[ $code -eq 0 ]] || { echo "FAIL: rbpf-slam exited $code"; tail -20 rbpf.log; exit 1; }
grep -q "whiskermap::maps::CHierarchicalObjectMap" rbpf.log || { echo "FAIL: no hierarchicalObjectMap in the particles"; tail -40 rbpf.log; exit 1; }
out=rbpf-slam-out
path="$out/log_estimated_path.txt"
[[ -s "$path" ]] || { echo "FAIL: $path missing"; ls -R "$out" | head -30; exit 1; }
n=$(grep -vc '^%' "$path")
[[ $n -ge 119 ]] || { echo "FAIL: $path has $n poses for 120 sweeps"; exit 1; }
[[ -s "$out/_finalmap_.simplemap" ]] || { echo "FAIL: _finalmap_.simplemap missing"; ls "$out"; exit 1; }
ls "$out" | grep -q "map_tables.csv" || { echo "FAIL: the final map's map_tables.csv missing"; ls "$out"; exit 1; }
echo "ok: rbpf-slam ran with hierarchicalObjectMap particles: $n poses, $(ls "$out" | grep map_tables.csv)"
