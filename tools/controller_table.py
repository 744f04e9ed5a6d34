#!/usr/bin/env python3
"""One markdown row per controller from sweep CSVs (ssc sweep --controller ...): trials,
successes with the 95 % Wilson interval, and the mean follow speed of the successful trials
with its 95 % Student t interval.

    tools/controller_table.py NAME=out/ctl_published/sweep.csv NAME=out/ctl_fast/sweep.csv
"""
import csv
import math
import sys


def wilson(k, n, z=1.96):
    if n == 0:
        return (0.0, 1.0)
    p = k / n
    d = 1 + z * z / n
    c = (p + z * z / (2 * n)) / d
    h = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / d
    return (max(0.0, c - h), min(1.0, c + h))


# Two-sided 95 % Student t quantiles, dof 1..30; beyond, 1.96 + 2.4 / dof (within 0.002).
T95 = [12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179,
       2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060,
       2.056, 2.052, 2.048, 2.045, 2.042]


def t95(dof):
    return T95[dof - 1] if dof <= len(T95) else 1.96 + 2.4 / dof


def row(name, path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    ok = [float(r["speed_mm_s"]) for r in rows if r["outcome"] == "success"]
    lo, hi = wilson(len(ok), len(rows))
    fails = {}
    for r in rows:
        if r["outcome"] != "success":
            fails[r["outcome"]] = fails.get(r["outcome"], 0) + 1
    if ok:
        mean = sum(ok) / len(ok)
        sd = math.sqrt(sum((v - mean) ** 2 for v in ok) / (len(ok) - 1)) if len(ok) > 1 else 0
        half = t95(len(ok) - 1) * sd / math.sqrt(len(ok)) if len(ok) > 1 else float("nan")
        speed = f"{mean:.1f} ± {half:.1f}"
    else:
        speed = "–"
    others = ", ".join(f"{k} {v}" for k, v in sorted(fails.items())) or "–"
    return (f"| {name} | {len(ok)}/{len(rows)} ({100 * len(ok) / len(rows):.0f} %, "
            f"{100 * lo:.0f}–{100 * hi:.0f} %) | {speed} | {others} |")


def main(args):
    if not args:
        print(__doc__, file=sys.stderr)
        return 2
    print("| controller | success (95 % interval) | speed of successes, mm/s (95 %) | "
          "other outcomes |")
    print("| --- | --- | --- | --- |")
    for a in args:
        name, _, path = a.partition("=")
        print(row(name, path))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
