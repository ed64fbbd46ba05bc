#!/usr/bin/env python3
"""Tables a map holds on top of each other (doc/slam.md, "Tables keep their shape").

  table_overlaps.py MAP_TABLES.csv [...]

Per map_tables.csv (doc/file-formats.md): every pair of mapped tables whose footprints (length
x width at x, y, yaw) overlap or touch, with the depth of the overlap (metres along the axis
that separates them least; 0: touching), then what eq. 16 made hard would keep: the tables
taken best supported first (most contacts), each one that overlaps or touches a table already
taken left out, as the per-pose map's rule and the lasting map's likelihoodOpts
`disjoint_tables` do (doc/map-plugin.md). Prints one line per file and a total. A diagnostic
that needs no build: its footprints leave out the leg width the map's include, so a map written
with `disjoint_tables` always shows "0 left out" here.
"""
import csv
import math
import sys


def footprint(row):
    """The table's footprint corners, counter-clockwise."""
    x, y, yaw = float(row["x"]), float(row["y"]), math.radians(float(row["yaw_deg"]))
    hx, hy = float(row["length"]) / 2, float(row["width"]) / 2
    c, s = math.cos(yaw), math.sin(yaw)
    return [(x + c * sx * hx - s * sy * hy, y + s * sx * hx + c * sy * hy)
            for sx, sy in ((1, -1), (1, 1), (-1, 1), (-1, -1))]


def gap(a, b):
    """Separating-axis gap between two rectangles: > 0 apart, <= 0 touching or overlapping
    (minus the overlap's depth)."""
    best = -math.inf
    for r in (a, b):
        for k in range(2):
            ex, ey = r[k + 1][0] - r[k][0], r[k + 1][1] - r[k][1]
            n = math.hypot(ex, ey)
            ux, uy = ey / n, -ex / n
            pa = [ux * p[0] + uy * p[1] for p in a]
            pb = [ux * p[0] + uy * p[1] for p in b]
            best = max(best, min(pb) - max(pa), min(pa) - max(pb))
    return best


def read(path):
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
        for r in rows:
            for key in ("id", "x", "y", "yaw_deg", "length", "width", "contacts"):
                v = float(r[key])
                if not math.isfinite(v):
                    raise ValueError(f"{key} is {r[key]}")
        return rows
    except (OSError, KeyError, TypeError, ValueError) as e:
        sys.exit(f"table_overlaps.py: {path}: not a readable map_tables.csv ({e})")


def main(paths):
    total = left_total = 0
    for path in paths:
        rows = sorted(read(path), key=lambda r: -float(r["contacts"]))
        feet = [footprint(r) for r in rows]
        gaps = {(i, j): gap(feet[i], feet[j]) for j in range(len(rows)) for i in range(j)}  # once a pair
        pairs = [f"{rows[i]['id']} ({rows[i]['contacts']} contacts) and {rows[j]['id']} ({rows[j]['contacts']}): "
                 f"depth {max(0.0, -g):.3f} m" for (i, j), g in sorted(gaps.items()) if g <= 0]
        kept, left = [], []
        for i in range(len(rows)):
            (left if any(gaps[k, i] <= 0 for k in kept) else kept).append(i)
        total += len(rows)
        left_total += len(left)
        print(f"{path}: {len(rows)} tables, {len(pairs)} pair(s) overlapping or touching"
              + (f" ({'; '.join(pairs)})" if pairs else "")
              + f"; eq. 16 made hard keeps {len(kept)}, leaves out "
              + (", ".join(f"{rows[i]['id']} ({rows[i]['contacts']} contacts)" for i in left) or "none"))
    print(f"total: {total} tables, {left_total} left out")


if __name__ == "__main__":
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        sys.exit(0 if len(sys.argv) >= 2 else 1)
    main(sys.argv[1:])
