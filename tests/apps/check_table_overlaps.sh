#!/usr/bin/env bash
# check_table_overlaps.sh SRC_DIR WORK_DIR: scripts/table_overlaps.py on a map_tables.csv with a
# copy of a table 5 cm off (fewer contacts) and a table apart: the pair is found, the copy is the
# one eq. 16 made hard leaves out; a missing file and a NaN are one-line errors, exit 1.
set -euo pipefail
trap 'echo "FAIL: line $LINENO: $BASH_COMMAND (exit $?)"' ERR
src=$1 work=$2
rm -rf "$work"; mkdir -p "$work"
cat > "$work/map_tables.csv" <<'CSV'
id,x,y,yaw_deg,length,width,leg_width,texture,existence,contacts,legs,sd_x,sd_y,sd_yaw_deg
0,1.05,1.00,30,1,0.6,0.05,0.7,1,31,4,0,0,0
1,1.00,1.00,30,1,0.6,0.05,0.7,1,3238,4,0,0,0
2,3.00,3.00,-45,1,0.6,0.05,0.7,1,900,4,0,0,0
CSV
out=$("$src/scripts/table_overlaps.py" "$work/map_tables.csv")
echo "$out"
grep -q "3 tables, 1 pair(s) overlapping or touching (1 (3238 contacts) and 0 (31): depth 0.575 m)" <<<"$out" ||
  { echo "FAIL: the copy's pair not found"; exit 1; }
grep -q "keeps 2, leaves out 0 (31 contacts)$" <<<"$out" || { echo "FAIL: not the copy left out"; exit 1; }
grep -q "^total: 3 tables, 1 left out$" <<<"$out" || { echo "FAIL: total"; exit 1; }
if err=$("$src/scripts/table_overlaps.py" "$work/missing.csv" 2>&1); then echo "FAIL: a missing file passed"; exit 1; fi
grep -q "missing.csv: not a readable map_tables.csv" <<<"$err" || { echo "FAIL: $err"; exit 1; }
sed 's/^2,3.00/2,nan/' "$work/map_tables.csv" > "$work/nan.csv"
if err=$("$src/scripts/table_overlaps.py" "$work/nan.csv" 2>&1); then echo "FAIL: a NaN passed"; exit 1; fi
grep -q "nan.csv: not a readable map_tables.csv (x is nan)" <<<"$err" || { echo "FAIL: $err"; exit 1; }
echo "ok: the copy found and left out; bad input refused"
