#!/usr/bin/env bash
# check_grid_rbpf_slam.sh EXPORT SRC WORK: stock rbpf-slam with the shipped
# config/grid-rbpf-slam.ini (an occupancy grid per particle, no plugin) on the first 120
# sweeps (121: see below) of the paper-arena SLAM log as range rays (whisker-export --ranges), 8 particles:
# it runs, its particles hold a COccupancyGridMap2D, it writes one pose per sweep and a
# final grid, and the grid sections equal config/grid-pf-localization.ini's.
set -euo pipefail
export=$1 src=$2 work=$3
command -v rbpf-slam >/dev/null || { echo "FAIL: rbpf-slam not installed (Debian package mrpt-apps)"; exit 1; }
rm -rf "$work"; mkdir -p "$work"; cd "$work"
diff <(sed -n '/^\[MappingApplication_occupancyGrid/,$p' "$src/config/grid-rbpf-slam.ini") \
     <(sed -n '/^\[MetricMap_occupancyGrid/,$p' "$src/config/grid-pf-localization.ini" | sed 's/^\[MetricMap_/[MappingApplication_/') ||
  { echo "FAIL: the grid sections of config/grid-rbpf-slam.ini and config/grid-pf-localization.ini differ"; exit 1; }
"$export" -q -i "$src/datasets/slam/paper_arena_action-sf.rawlog" --ranges ranges.rawlog
LD_PRELOAD="${WHISKERMAP_TOOL_PRELOAD:-}" rawlog-edit --cut --to-index 239 -i ranges.rawlog -o short.rawlog >/dev/null 2>&1 </dev/null
# rawlog-edit's --to-index keeps one action-sf pair more than asked: count what it kept
sweeps=$(( $(LD_PRELOAD="${WHISKERMAP_TOOL_PRELOAD:-}" rawlog-edit --info -i short.rawlog 2>&1 </dev/null | sed -n 's/^Overall number of objects *: *\([0-9]*\).*/\1/p') / 2 ))
[[ $sweeps -ge 120 ]] || { echo "FAIL: short.rawlog holds $sweeps sweeps"; exit 1; }
sed 's/^sampleSize=30$/sampleSize=8/' "$src/config/grid-rbpf-slam.ini" >grid-rbpf-slam-8.ini
code=0
LD_PRELOAD="${WHISKERMAP_TOOL_PRELOAD:-}" timeout "${WHISKERMAP_TOOL_TIMEOUT:-300}" rbpf-slam grid-rbpf-slam-8.ini short.rawlog </dev/null >rbpf.log 2>&1 || code=$?
[[ $code -eq 0 ]] || { echo "FAIL: rbpf-slam exited $code"; tail -20 rbpf.log; exit 1; }
grep -q "COccupancyGridMap2D" rbpf.log || { echo "FAIL: no occupancy grid in the particles"; tail -40 rbpf.log; exit 1; }
path=grid-rbpf-slam-out/log_estimated_path.txt
n=$(grep -vc '^%' "$path" || true)
[[ $n -eq $sweeps ]] || { echo "FAIL: $path has $n poses for $sweeps sweeps"; exit 1; }
[[ -s grid-rbpf-slam-out/_finalmap_.simplemap ]] || { echo "FAIL: no _finalmap_.simplemap"; ls grid-rbpf-slam-out; exit 1; }
echo "ok: rbpf-slam ran with an occupancy grid per particle on the whisker rays: $n poses"
