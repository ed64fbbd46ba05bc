#!/usr/bin/env bash
# check_import_error.sh WHISKER_IMPORT SRC_DIR WORK_DIR CASE: whisker-import on the
# hand-written log with one defect (CASE, made below with sed, so each case reads as a one-line
# diff) exits 1 with one error line naming the file, line and column, and writes nothing.
set -euo pipefail
import=$1 src=$2 work=$3 name=$4
good=$src/tests/data/contact_logs/one_table.csv
case $name in
  empty)               edit='1,$d'                   want="line 1, column 1: empty file" ;;
  not_a_log)           edit='1s/.*/time,x/'          want="line 1, column 1: not a contact log" ;;
  version)             edit='1s/v1/v2/'              want="line 1, column 1: unsupported format version 'v2'" ;;
  missing_column)      edit='7s/,texture//'          want="line 7, column 'texture': missing from the header row" ;;
  unknown_column)      edit='7s/$/,force/'           want="line 7, field 11: unknown column 'force'" ;;
  repeated_column)     edit='7s/$/,r/'               want="line 7, field 11: column 'r' repeats field 8" ;;
  no_rows)             edit='8,$d'                   want="line 7, column 1: no data rows" ;;
  short_row)           edit='19s/,0.70$//'           want="line 19, column 'texture' \(field 10\): missing value: the row has 9 fields, the header 10" ;;
  extra_value)         edit='19s/$/,1/'              want="line 19, field 11: extra value '1'" ;;
  not_a_number)        edit='12s/0.590/0.59O/'       want="line 12, column 'r' \(field 8\): '0.59O' is not a number" ;;
  nan)                 edit='11s/^0.0,1.500/0.0,nan/' want="line 11, column 'odom_x' \(field 2\): 'nan' is not finite" ;;
  bad_time)            edit='11s/^0.0,/0.0.0,/'      want="line 11, column 'time' \(field 1\): '0.0.0' is not a number" ;;
  touched_flag)        edit='10s/,0,1,36.8/,0,yes,36.8/' want="line 10, column 'touched' \(field 6\): 'yes' is not 0 or 1" ;;
  angle_outside_sweep) edit='13s/-36.8/36.8/'        want="line 13, column 'angle_deg' \(field 7\): '36.8' deg is outside whisker 3's sweep \[-170, -10\] deg" ;;
  r_past_length)       edit='12s/0.590/0.7/'         want="line 12, column 'r' \(field 8\): '0.7' m is past whisker 2's length 0.6 m" ;;
  r_negative)          edit='12s/0.590/-0.1/'        want="line 12, column 'r' \(field 8\): '-0.1' m is negative" ;;
  texture_range)       edit='10s/0.70$/1.2/'         want="line 10, column 'texture' \(field 10\): '1.2' is not in \[0, 1\]" ;;
  unknown_whisker)     edit='15s/,0,5,1,/,0,6,1,/'   want="line 15, column 'whisker' \(field 5\): whisker 6 is not one of the robot's 6 \(0..5\)" ;;
  repeated_whisker)    edit='15s/,0,5,1,/,0,4,1,/'   want="line 15, column 'whisker' \(field 5\): whisker 4 appears twice in the sweep starting at line 10 \(first at line 14\)" ;;
  time_disagrees)      edit='20s/^0.5/0.6/'          want="line 20, column 'time' \(field 1\): '0.6' differs from the sweep starting at line 18, which still lacks whiskers 2, 3, 4, 5" ;;
  odometry_disagrees)  edit='20s/2.050/2.051/'       want="line 20, column 'odom_y' \(field 3\): '2.051' differs from the sweep starting at line 18" ;;
  time_backwards)      edit='25,30s/^1.0,/0.4,/'     want="line 25, column 'time' \(field 1\): time goes backwards: '0.4' is before the previous sweep's \(line 18\)" ;;
  incomplete_sweep)    edit='38d'                    want="line 33, column 'whisker': the file ends before this sweep lists whiskers 5" ;;
  *) echo "unknown case $name"; exit 2 ;;
esac
mkdir -p "$work"
log=$work/$name.csv out=$work/$name.rawlog
sed "$edit" "$good" > "$log"
if cmp -s "$good" "$log"; then echo "FAIL: the edit '$edit' changed nothing"; exit 1; fi
rm -f "$out" "$out.tmp"
set +e
err=$("$import" -q -i "$log" --robot scratchbot -o "$out" 2>&1 >/dev/null); code=$?
set -e
[[ $code -eq 1 ]] || { echo "FAIL: exit $code, expected 1"; echo "$err"; exit 1; }
[[ $(printf '%s\n' "$err" | grep -c .) -eq 1 ]] || { echo "FAIL: expected one error line:"; echo "$err"; exit 1; }
printf '%s\n' "$err" | grep -Eq -- "^whisker-import: error: .*/$name\.csv: $want" ||
  { echo "FAIL: '$err' does not match '$want'"; exit 1; }
if ls "$out"* 2>/dev/null; then echo "FAIL: output written despite the error"; exit 1; fi
echo "ok: $err"
