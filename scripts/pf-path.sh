#!/usr/bin/env bash
# pf-path.sh PF_LOG GT EST_OUT GT_OUT
# Turns stock pf-localization's log (one "PDF estimation: (x,y,phideg)" line per rawlog step:
# pf-localization 2.5.8 writes no path file, doc/pf-localization.md) into a path file in the
# ground-truth columns (timestamp x y yaw_rad, timestamps from GT), and GT_OUT the first as
# many poses of GT, so that `whisker-eval --path EST_OUT --truth GT_OUT` scores a run on a
# prefix of the log. Fails when the log holds no estimate or more than GT has poses.
set -euo pipefail
log=$1 gt=$2 est_out=$3 gt_out=$4
est=$(sed -n 's/.*PDF estimation: (\([-0-9.e]*\),\([-0-9.e]*\),\([-0-9.e]*\)deg).*/\1 \2 \3/p' "$log")
n=$(printf '%s\n' "$est" | grep -c . || true)
total=$(grep -vc '^%' "$gt")
[[ $n -gt 0 ]] || { echo "pf-path: $log: no 'PDF estimation' line" >&2; exit 1; }
[[ $n -le $total ]] || { echo "pf-path: $log: $n estimates, but $gt holds $total poses" >&2; exit 1; }
# (awk, not grep | head: under pipefail head's early exit can fail the pipeline)
awk -v n="$n" '/^%/ || ++k <= n' "$gt" >"$gt_out"
awk -v n="$n" '!/^%/ && ++k <= n { print $1 }' "$gt" |
  paste -d' ' - <(printf '%s\n' "$est") |
  awk 'BEGIN { print "% pf-localization estimate, one line per sweep"; print "% timestamp(s)  x(m)  y(m)  yaw(rad)" }
       { printf "%s %.9f %.9f %.9f\n", $1, $2, $3, $4 * 3.14159265358979 / 180 }' >"$est_out"
