#!/usr/bin/env python3
"""Helper of scripts/eval-categories.sh (doc/eval-worlds.md): turns the runs' whisker-eval
--json reports into summary.csv (one row per run and method), compares forward and reversed
maps (reversal.csv), and writes summary.md.

  eval_categories.py build MANIFEST OUT_DIR

MANIFEST: one run and method per line, tab-separated: category, seed, noise, method, the
folder holding the method's map_tables.csv, its JSON report (whisker-eval --json), seconds.
"""
import csv
import json
import math
import os
import sys

COLUMNS = ["category", "seed", "noise", "method", "precision", "recall", "f1", "rmse_mm",
           "yaw_err_deg", "count_error", "estimated", "truth", "identifiable", "bound",
           "recall_identifiable", "seconds"]
CATEGORY_ORDER = ["paper_arena", "random_yaw", "clutter", "side_by_side", "large", "sparse"]
NOISE_ORDER = ["noiseless", "default", "very-noisy"]
METHODS = ["whisker-map", "baseline", "whisker-map-reversed"]


def row(category, seed, noise, method, path, seconds):
    """One summary.csv row from a whisker-eval --json report."""
    with open(path) as f:
        e = json.load(f)
    rmse = e.get("rmse_m")
    ident = e.get("identifiable_tables")
    truth = e["truth"]
    values = {
        "category": category, "seed": seed, "noise": noise, "method": method,
        "precision": e["precision"], "recall": e["recall"], "f1": e["f1"],
        "rmse_mm": "" if rmse is None else round(rmse * 1000, 3),
        "yaw_err_deg": "" if e.get("yaw_err_deg") is None else e["yaw_err_deg"],
        "count_error": e["count_error"], "estimated": e["estimated"], "truth": truth,
        "identifiable": "" if ident is None else ident,
        # The best recall any mapper could reach: identifiable / true tables.
        "bound": "" if ident is None else round(ident / truth, 6) if truth else 1,
        "recall_identifiable": e.get("recall_identifiable", ""),
        "seconds": seconds,
    }
    return values


def read_map(path):
    """(x, y, yaw) of each row of a map_tables.csv (the first columns: id,x,y,yaw_deg)."""
    with open(path) as f:
        rows = list(csv.reader(f))[1:]
    return [(float(r[1]), float(r[2]), math.radians(float(r[3]))) for r in rows]


def compare(path_a, path_b, gate=0.25, gate_yaw=math.radians(20)):
    """Greedy one-to-one matching, nearest pairs first, within whisker-eval's default gates:
    F1 of B against A and the largest centre shift over matched pairs (mm)."""
    a, b = read_map(path_a), read_map(path_b)
    pairs = []
    for i, p in enumerate(a):
        for j, q in enumerate(b):
            d = math.hypot(p[0] - q[0], p[1] - q[1])
            dyaw = abs((p[2] - q[2] + math.pi / 2) % math.pi - math.pi / 2)
            if d <= gate and dyaw <= gate_yaw:
                pairs.append((d, i, j))
    used_a, used_b, shifts = set(), set(), []
    for d, i, j in sorted(pairs):
        if i not in used_a and j not in used_b:
            used_a.add(i), used_b.add(j), shifts.append(d)
    m = len(shifts)
    f1 = 1.0 if not a and not b else 2 * m / (len(a) + len(b))
    return f1, (max(shifts) * 1000 if shifts else float("nan"))


def fmt(v, digits):
    return "n/a" if v is None or (isinstance(v, float) and math.isnan(v)) else "%.*f" % (digits, v)


def num(s):
    return float(s) if s not in ("", None) else None


def mean(xs):
    xs = [x for x in xs if x is not None]
    return sum(xs) / len(xs) if xs else None


def report(summary_csv, summary_md, reversal_csv=None):
    with open(summary_csv) as f:
        rows = list(csv.DictReader(f))
    methods = [m for m in METHODS if any(r["method"] == m for r in rows)]
    out = ["# Evaluation categories: whisker-map against the batch baseline", "",
           "Written by `scripts/eval-categories.sh` (doc/eval-worlds.md). Per category and noise "
           "level, over the seeds: mean and worst F1, centre RMSE (mm, mean and worst), mean yaw "
           "error (deg), mean recall and the identifiability bound (identifiable / true tables: "
           "the best recall any mapper can reach), recall on the identifiable tables. "
           "`whisker-map`: its map_tables.csv scored as written (the lasting map); `baseline`: "
           "whisker-baseline; `whisker-map-reversed`: whisker-map on the same sweeps in reverse order.", ""]
    header = ("| category | noise | method | runs | F1 mean | F1 worst | RMSE mm mean | RMSE mm worst "
              "| yaw deg | recall | bound | recall on identifiable |")
    out += [header, "|" + " --- |" * 12]
    cats = sorted({r["category"] for r in rows}, key=lambda c: (CATEGORY_ORDER + [c]).index(c))
    for c in cats:
        for n in [n for n in NOISE_ORDER if any(r["noise"] == n for r in rows)]:
            for m in methods:
                sel = [r for r in rows if r["category"] == c and r["noise"] == n and r["method"] == m]
                if not sel:
                    continue
                f1 = [num(r["f1"]) for r in sel]
                rmse = [num(r["rmse_mm"]) for r in sel]
                worst_rmse = max([x for x in rmse if x is not None], default=None)
                out.append("| %s | %s | %s | %d | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                    c, n, m, len(sel), fmt(mean(f1), 3), fmt(min(f1), 3), fmt(mean(rmse), 2),
                    fmt(worst_rmse, 2), fmt(mean([num(r["yaw_err_deg"]) for r in sel]), 3),
                    fmt(mean([num(r["recall"]) for r in sel]), 3),
                    fmt(mean([num(r["bound"]) for r in sel]), 3),
                    fmt(mean([num(r["recall_identifiable"]) for r in sel]), 3)))
    if reversal_csv:
        with open(reversal_csv) as f:
            rev = list(csv.DictReader(f))
        out += ["", "## Order of the sweeps: forward against reversed (default noise, whisker-map --reverse)", "",
                "| category | runs | F1 forward mean | F1 reversed mean | F1 reversed vs forward map, worst "
                "| max centre shift mm |", "|" + " --- |" * 6]
        for c in cats:
            sel = [r for r in rev if r["category"] == c]
            if not sel:
                continue
            shifts = [num(r["max_shift_mm"]) for r in sel]
            shifts = [s for s in shifts if s is not None and not math.isnan(s)]
            out.append("| %s | %d | %s | %s | %s | %s |" % (
                c, len(sel), fmt(mean([num(r["f1_forward"]) for r in sel]), 3),
                fmt(mean([num(r["f1_reversed"]) for r in sel]), 3),
                fmt(min(num(r["f1_between"]) for r in sel), 3), fmt(max(shifts, default=None), 2)))
    write(summary_md, "\n".join(out) + "\n")


def write(path, text):
    """Staged: the file appears complete or not at all."""
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def build(manifest, out):
    rows, dirs = [], {}
    with open(manifest) as f:
        for line in f:
            category, seed, noise, method, folder, report_json, seconds = line.rstrip("\n").split("\t")
            rows.append(row(category, seed, noise, method, report_json, seconds))
            dirs[(category, seed, noise, method)] = folder
    lines = [",".join(COLUMNS)] + [",".join(str(r[c]) for c in COLUMNS) for r in rows]
    write(os.path.join(out, "summary.csv"), "\n".join(lines) + "\n")
    reversal = []
    for (category, seed, noise, method), folder in dirs.items():
        forward = dirs.get((category, seed, noise, "whisker-map"))
        if method != "whisker-map-reversed" or forward is None:
            continue
        f1_between, shift = compare(os.path.join(forward, "map_tables.csv"), os.path.join(folder, "map_tables.csv"))
        f1 = {r["method"]: r["f1"] for r in rows if (r["category"], r["seed"], r["noise"]) == (category, seed, noise)}
        reversal.append({"category": category, "seed": seed, "f1_forward": f1["whisker-map"],
                         "f1_reversed": f1[method], "f1_between": round(f1_between, 6), "max_shift_mm": round(shift, 3)})
    reversal_csv = None
    if reversal:
        keys = list(reversal[0])
        reversal_csv = os.path.join(out, "reversal.csv")
        write(reversal_csv, "\n".join([",".join(keys)] + [",".join(str(r[k]) for k in keys) for r in reversal]) + "\n")
    report(os.path.join(out, "summary.csv"), os.path.join(out, "summary.md"), reversal_csv)


if __name__ == "__main__":
    if len(sys.argv) != 4 or sys.argv[1] != "build":
        sys.exit("usage: eval_categories.py build MANIFEST OUT_DIR")
    build(sys.argv[2], sys.argv[3])
