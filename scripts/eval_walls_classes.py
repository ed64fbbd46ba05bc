#!/usr/bin/env python3
"""Summary of scripts/eval-walls-classes.sh: reads its manifest (category, seed, noise, wall
time, whisker-eval JSON per line) and prints a markdown table of the worst figures per
category and noise level."""
import collections
import json
import sys


def main(manifest):
    runs = collections.defaultdict(list)
    with open(manifest) as f:
        for line in f:
            category, seed, noise, seconds, path = line.split()
            with open(path) as j:
                e = json.load(j)
            walls = e.get("walls", {})
            runs[(noise, category)].append((int(seed), e, walls, float(seconds)))
    print("| category | noise | runs | F1 worst (runs below 1) | class accuracy worst | length / width error worst (mm) "
          "| centre RMSE worst (mm) | wall recall (touched) worst | wall precision worst | objects on a wall | wall time median (s) |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for (noise, category) in sorted(runs):
        v = sorted(runs[(noise, category)], key=lambda r: r[0])
        below = ", ".join("seed %d: %.3f" % (s, e["f1"]) for s, e, _, _ in v if e["f1"] < 1)
        times = sorted(t for _, _, _, t in v)
        print("| %s | %s | %d | %.3f%s | %.3f | %.1f / %.1f | %.2f | %.3f | %.3f | %d | %.1f |" % (
            category, noise, len(v), min(e["f1"] for _, e, _, _ in v), " (%s)" % below if below else "",
            min(e["class_accuracy"] for _, e, _, _ in v), 1000 * max(e["length_err_m"] for _, e, _, _ in v),
            1000 * max(e["width_err_m"] for _, e, _, _ in v), 1000 * max(e["rmse_m"] for _, e, _, _ in v),
            min(w.get("recall_touched", float("nan")) for _, _, w, _ in v),
            min(w.get("precision", float("nan")) for _, _, w, _ in v),
            sum(e["objects_on_walls"] for _, e, _, _ in v), times[len(times) // 2]))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: eval_walls_classes.py MANIFEST")
    main(sys.argv[1])
