#!/usr/bin/env bash
# check_whisker_slam.sh WHISKER_SLAM WHISKER_EVAL SRC_DIR WORK_DIR HEAP: whisker-slam on a prefix
# of the shipped default-odometry paper-arena log (datasets/slam/) writes every documented
# output; its estimated path beats the odometry's ATE (whisker-eval --path) by a stated
# margin, and smoothing the best particle's path beats that path; the same seed gives the same
# bytes, in either rawlog layout; without smoothing the map it writes is the best particle's
# own; particles that merge legs within a gap hold fewer legs beside another and are smoothed
# as well; disjoint_tables changes the map written, not the paths. HEAP: `measured`, or
# `unmeasured` in a build with AddressSanitizer (summary.json's live heap is then null).
set -euo pipefail
trap 'echo "FAIL: line $LINENO: $BASH_COMMAND (exit $?)"' ERR
slam=$1 eval=$2 src=$3 work=$4 heap=$5
rm -rf "$work"; mkdir -p "$work"
data="$src/datasets/slam/paper_arena"
world="$src/config/worlds/paper_arena.ini"
# A prefix keeps the test short (about 30 s in Release on a shared core): the first 240
# sweeps (12 m of the lawnmower, three rows and their turns) with 20 particles.
sweeps=240 particles=20
"$slam" -q -i "${data}_obs.rawlog" -o "$work/a" --world "$world" --particles $particles --sweeps $sweeps --seed 7 || { rc=$?; echo "FAIL: whisker-slam exited with $rc"; exit 1; }
for f in estimated_path.txt filter_path.txt odometry_path.txt paths.png summary.json map_tables.csv map_candidates.csv \
         map_walls.csv map.png map.3Dscene map.bt map_summary.json metrics.json; do
  [[ -s "$work/a/$f" ]] || { echo "FAIL: $f missing or empty"; exit 1; }
done
[[ -z "$(ls -A "$work/a" | grep staging || true)" ]] || { echo "FAIL: staging folder left"; exit 1; }
for f in estimated_path.txt filter_path.txt odometry_path.txt; do
  n=$(grep -vc '^%' "$work/a/$f")
  [[ $n -eq $sweeps ]] || { echo "FAIL: $f has $n poses for $sweeps sweeps"; exit 1; }
done
python3 - "$work/a/summary.json" "$particles" "$sweeps" "$heap" <<'PY' || { echo "FAIL: summary.json"; cat "$work/a/summary.json"; exit 1; }
import json, sys
s = json.load(open(sys.argv[1]))  # valid JSON, with every key the doc lists
assert s["particles"] == s["particles_config"] == int(sys.argv[2]) and s["sweeps"] == int(sys.argv[3]), "particles/sweeps"
fm = s["filter_maps"]  # summed over the particles: 240 sweeps map a table in every particle's map
keys = {"tables", "legs", "legs_without_table", "legs_beside", "walls", "contacts_explained", "contacts_unexplained",
        "swept_chunks", "swept_chunks_shared", "lasting_chunks", "lasting_chunks_shared"}
assert set(fm) == {"first_tenth", "end"} and all(set(fm[k]) == keys for k in fm), "filter_maps keys"
assert all(0 < fm[k]["lasting_chunks_shared"] < fm[k]["lasting_chunks"] for k in fm), "filter_maps lasting chunks"
assert fm["end"]["legs"] >= fm["end"]["tables"] >= s["particles"] and fm["end"]["contacts_explained"] >= fm["end"]["legs"], "filter_maps"
assert all(fm[k]["legs_without_table"] <= fm[k]["legs"] and fm[k]["legs_beside"] <= fm[k]["legs"] for k in fm), "filter_maps legs"
assert set(s["time_per_step_ms"]) == {"mean", "median", "p95", "max"}, "time_per_step_ms"
assert len(s["ess"]) == s["sweeps"] and all(0 < e <= 1 for e in s["ess"]), "ess"
assert s["resamplings"] >= 0, "resamplings"
assert all("trajectory" in s[k] for k in ("estimated", "filter", "odometry")), "estimated/filter/odometry"
# Smoothed (the shipped config): the map is rebuilt at the smoothed path, so it is not the
# particle's (null); the smoother tied contacts and lowered its objective.
sm = s["smoothing"]
assert s["map_matches_best_particle"] is None, "map_matches_best_particle (smoothed)"
assert sm["contacts_tied"] > 100 and 0 < sm["cost_after"] < sm["cost_before"], "smoothing"
assert sm["rounds"] >= 1 and sm["iterations"] >= 1 and sm["seconds"] > 0, "smoothing"
for k in ("duplicate_legs", "duplicate_legs_apart", "duplicate_walls", "duplicate_walls_apart", "bridges", "bridges_tried"):
    assert isinstance(sm[k], int) and sm[k] >= 0, f"smoothing: {k}"
assert sm["bridges"] <= sm["bridges_tried"] and sm["stray_max"] >= 0, "smoothing: bridges (eq. S8)"
m = s["filter_peak_rss_mb"]  # a high-water mark: it can only grow, and the outputs come after
assert 0 < m["first_tenth"] <= m["end"] <= s["peak_rss_mb"], "filter_peak_rss_mb"
h = s["filter_heap_mb"]  # live heap at the same points: part of the resident memory, never all of it
if sys.argv[4] == "measured":
    assert all(0 < h[k] < m[k] for k in ("first_tenth", "end")), "filter_heap_mb"
else:
    assert sys.argv[4] == "unmeasured" and h == {"first_tenth": None, "end": None}, "filter_heap_mb (unmeasured)"
PY
# The recorded odometry is the rawlog's, as whisker-sim wrote it (same poses, same columns).
awk -v n=$sweeps '!/^%/ && k++ < n' "${data}_obs_odometry_path.txt" > "$work/odometry_prefix.txt"
grep -v '^%' "$work/a/odometry_path.txt" | cmp - "$work/odometry_prefix.txt" || { echo "FAIL: odometry_path.txt differs from the dataset's"; exit 1; }

# ATE against the truth, scored by whisker-eval.
awk -v n=$sweeps '!/^%/ && k++ < n' "${data}_obs_ground_truth_robot_path.txt" > "$work/truth_prefix.txt"
ate() { "$eval" --path "$1" --truth "$work/truth_prefix.txt" --json | sed -n 's/.*"ate_rmse_m": \([0-9.]*\).*/\1/p'; }
est=$(ate "$work/a/estimated_path.txt") odo=$(ate "$work/a/odometry_path.txt") filt=$(ate "$work/a/filter_path.txt")
echo "ATE RMSE over the first $sweeps sweeps: SLAM $est m (best particle $filt m), odometry $odo m"
# Measured 2026-11-28 (this seed, 20 particles, 240 sweeps): SLAM 0.136 m against 0.173 m
# for the odometry before the lasting map's shorter local schedule was merged, 0.329 m after
# it, 0.163 m with equal weights after resampling (2026-12-02): on short prefixes whisker-slam
# is not reliably better than the odometry (doc/slam.md); 0.083 m with Manhattan walls and the
# likelihood's wall extension (2026-12-04, shipped).
# Asserted: the filter keeps track (ATE below 0.5 m and at most 2.5 x the odometry's).
awk -v e="$est" -v o="$odo" 'BEGIN { exit !(e > 0 && o > 0 && e < 0.5 && e <= 2.5 * o) }' || { echo "FAIL: SLAM ATE $est m: lost track (odometry $odo m)"; exit 1; }
# Smoothed (2026-12-05, this seed): 0.022 m against the best particle's 0.083 m. Asserted: the
# smoothed path's ATE is below 4 cm and at most half the particle's.
awk -v e="$est" -v f="$filt" 'BEGIN { exit !(e > 0 && e < 0.04 && e <= 0.5 * f) }' || { echo "FAIL: smoothed ATE $est m, best particle $filt m"; exit 1; }
# [smooth] enabled = false: the estimate is the best particle's path and the map written is
# that particle's own (rebuilt at its path: the same insertions, the same tables).
sed -e 's#^map_config = .*#map_config = '"$src"'/config/whisker-map.ini#' -e 's#^enabled = true #enabled = false #' \
  "$src/config/whisker-slam.ini" > "$work/unsmoothed.ini"
grep -q '^enabled = false ' "$work/unsmoothed.ini" || { echo "FAIL: the shipped config has no [smooth] enabled = true"; exit 1; }
"$slam" -q -c "$work/unsmoothed.ini" -i "${data}_obs.rawlog" -o "$work/u" --particles $particles --sweeps $sweeps --seed 7
diff <(grep -v '^%' "$work/u/estimated_path.txt") <(grep -v '^%' "$work/u/filter_path.txt") >/dev/null || { echo "FAIL: unsmoothed estimate is not the best particle's path"; exit 1; }
diff <(grep -v '^%' "$work/u/filter_path.txt") <(grep -v '^%' "$work/a/filter_path.txt") >/dev/null || { echo "FAIL: smoothing changed the filter"; exit 1; }
python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); assert s["map_matches_best_particle"] is True and s["smoothing"] is None, s' "$work/u/summary.json" || { echo "FAIL: unsmoothed summary.json"; exit 1; }

# [slam] leg_merge_gap (shipped 0: off): the particles' maps merge legs within 2 cm of each
# other, so few legs stand beside another (2026-12-07, this seed: 2 of 281 against 192 of 387
# in the particles' maps at the end), and the smoother, from a map rebuilt at the particle's
# path, still brings the estimate under 4 cm (0.021 m against 0.022 m).
sed -e 's#^map_config = .*#map_config = '"$src"'/config/whisker-map.ini#' \
  -e 's#^leg_merge_gap = 0 #leg_merge_gap = 0.02 #' "$src/config/whisker-slam.ini" > "$work/gap.ini"
grep -q '^leg_merge_gap = 0.02 ' "$work/gap.ini" || { echo "FAIL: the shipped config has no leg_merge_gap = 0"; exit 1; }
"$slam" -q -c "$work/gap.ini" -i "${data}_obs.rawlog" -o "$work/g" --particles $particles --sweeps $sweeps --seed 7
python3 - "$work/a/summary.json" "$work/g/summary.json" <<'PY' || { echo "FAIL: leg_merge_gap"; exit 1; }
import json, sys
a, g = (json.load(open(f)) for f in sys.argv[1:])
assert a["leg_merge_gap"] == 0 and g["leg_merge_gap"] == 0.02, "leg_merge_gap in summary.json"
ba, bg = a["filter_maps"]["end"]["legs_beside"], g["filter_maps"]["end"]["legs_beside"]
assert 10 * bg < ba, f"legs beside another: {bg} with the gap, {ba} without"
PY
est_g=$(ate "$work/g/estimated_path.txt")
echo "leg_merge_gap 0.02: SLAM $est_g m"
awk -v e="$est_g" 'BEGIN { exit !(e > 0 && e < 0.04) }' || { echo "FAIL: leg_merge_gap: smoothed ATE $est_g m"; exit 1; }

# [slam] disjoint_tables (shipped true) holds for the map written only: without it the
# particles and the smoother run the same (the same filter and estimated paths), and the map
# written with it holds no two tables that overlap (scripts/table_overlaps.py).
sed -e 's#^map_config = .*#map_config = '"$src"'/config/whisker-map.ini#' \
  -e 's#^disjoint_tables = true #disjoint_tables = false #' "$src/config/whisker-slam.ini" > "$work/soft.ini"
grep -q '^disjoint_tables = false ' "$work/soft.ini" || { echo "FAIL: the shipped config has no disjoint_tables = true"; exit 1; }
"$slam" -q -c "$work/soft.ini" -i "${data}_obs.rawlog" -o "$work/s" --particles $particles --sweeps $sweeps --seed 7
python3 -c 'import json, sys; a, s = (json.load(open(f)) for f in sys.argv[1:]); assert a["disjoint_tables"] and not s["disjoint_tables"]' \
  "$work/a/summary.json" "$work/s/summary.json" || { echo "FAIL: disjoint_tables in summary.json"; exit 1; }
for f in filter_path.txt estimated_path.txt; do
  cmp "$work/a/$f" "$work/s/$f" || { echo "FAIL: disjoint_tables changed $f (it is for the map written only)"; exit 1; }
done
python3 "$src/scripts/table_overlaps.py" "$work/a/map_tables.csv" | grep -q '^total: [1-9][0-9]* tables, 0 left out$' ||
  { echo "FAIL: map_tables.csv: no tables, or two overlapping"; exit 1; }

# Same seed, same bytes.
"$slam" -q -i "${data}_obs.rawlog" -o "$work/b" --world "$world" --particles $particles --sweeps $sweeps --seed 7
for f in estimated_path.txt filter_path.txt map_tables.csv map_candidates.csv; do
  cmp "$work/a/$f" "$work/b/$f" || { echo "FAIL: $f differs between two runs with the same seed"; exit 1; }
done
# The action-sf layout holds the same odometry (as increments: the poses composed from them
# differ in the last bits, so the particle clouds part after a few hundred steps) and sweeps.
"$slam" -q -i "${data}_action-sf.rawlog" -o "$work/c" --particles $particles --sweeps $sweeps --seed 7
cmp "$work/a/odometry_path.txt" "$work/c/odometry_path.txt" || { echo "FAIL: the layouts give different odometry"; exit 1; }
est_c=$(ate "$work/c/estimated_path.txt")
echo "action-sf layout: SLAM $est_c m"
# Measured 2026-12-05: 0.024 m (best particle 0.109 m). Asserted: below 4 cm, as above.
awk -v e="$est_c" 'BEGIN { exit !(e > 0 && e < 0.04) }' || { echo "FAIL: action-sf: smoothed ATE $est_c m"; exit 1; }
awk -v e="$est_c" -v o="$odo" 'BEGIN { exit !(e > 0 && e < 0.5 && e <= 2.5 * o) }' || { echo "FAIL: action-sf: SLAM ATE $est_c m: lost track (odometry $odo m)"; exit 1; }
# Another seed, another particle cloud: the path must differ (the seed is used).
"$slam" -q -i "${data}_obs.rawlog" -o "$work/d" --particles $particles --sweeps 60 --seed 8
head -62 "$work/a/estimated_path.txt" > "$work/a_prefix.txt"
if cmp -s "$work/a_prefix.txt" "$work/d/estimated_path.txt"; then echo "FAIL: --seed 8 gave seed 7's path"; exit 1; fi

# Odometry told exact (on a log whose odometry is exact): the filter runs one particle, since
# every particle would follow the same path and build the same map; summary.json says so, the
# terminal too, and the estimate is the recorded path.
sed -e 's#^map_config = .*#map_config = '"$src"'/config/whisker-map.ini#' -e 's#^odometry_model = .*#odometry_model = exact#' \
  "$src/config/whisker-slam.ini" > "$work/exact.ini"
"$slam" -c "$work/exact.ini" -i "$src/datasets/paper_arena/default.rawlog" -o "$work/e" --particles $particles --sweeps 60 \
  2> "$work/e.err" > /dev/null
grep -q "odometry told exact: 1 particle (the $particles asked for" "$work/e.err" || { echo "FAIL: no told-exact note"; cat "$work/e.err"; exit 1; }
python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); assert s["particles"] == 1 and s["particles_config"] == int(sys.argv[2]) and s["filter"]["trajectory"]["ate_rmse_m"] < 1e-9, s' \
  "$work/e/summary.json" $particles || { echo "FAIL: told exact: summary.json"; exit 1; }

# [slam] manhattan_walls (shipped on): every particle's map holds walls, each along the axis or
# at right angles to it, and the map written holds them (map_walls.csv: x0 = x1 or y0 = y1).
[[ $(grep -c . "$work/a/map_walls.csv") -ge 2 ]] || { echo "FAIL: no wall in the Manhattan map"; exit 1; }
awk -F, 'NR > 1 && ($1 - $3) ^ 2 > 1e-12 && ($2 - $4) ^ 2 > 1e-12 { bad++ } END { exit bad > 0 }' "$work/a/map_walls.csv" ||
  { echo "FAIL: a wall off the axes"; cat "$work/a/map_walls.csv"; exit 1; }
echo "manhattan walls: $(($(grep -c . "$work/a/map_walls.csv") - 1)) walls, all on the axes"
echo "ok: whisker-slam outputs, the filter keeps track, reproducible; both layouts"
