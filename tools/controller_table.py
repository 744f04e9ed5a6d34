#!/usr/bin/env python3
"""One markdown row per controller from sweep CSVs (ssc sweep --controller ...): trials,
successes with the 95 % Wilson interval, and the mean follow speed of the successful trials
with its 95 % Student t interval.

    tools/controller_table.py NAME=out/ctl_published/sweep.csv NAME=out/ctl_fast/sweep.csv
"""

import csv
import math
import os
import sys


sys.path.insert(
    0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build", "python_pkg")
)
from ssc_twin import student_t95, wilson_interval  # noqa: E402  the project's one home of both


def row(name, path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    ok = [float(r["speed_mm_s"]) for r in rows if r["outcome"] == "success"]
    lo, hi = wilson_interval(len(ok), len(rows))
    fails = {}
    for r in rows:
        if r["outcome"] != "success":
            fails[r["outcome"]] = fails.get(r["outcome"], 0) + 1
    if ok:
        mean = sum(ok) / len(ok)
        sd = math.sqrt(sum((v - mean) ** 2 for v in ok) / (len(ok) - 1)) if len(ok) > 1 else 0
        half = student_t95(len(ok) - 1) * sd / math.sqrt(len(ok)) if len(ok) > 1 else float("nan")
        speed = f"{mean:.1f} ± {half:.1f}"
    else:
        speed = "–"
    others = ", ".join(f"{k} {v}" for k, v in sorted(fails.items())) or "–"
    return (
        f"| {name} | {len(ok)}/{len(rows)} ({100 * len(ok) / len(rows):.0f} %, "
        f"{100 * lo:.0f}–{100 * hi:.0f} %) | {speed} | {others} |"
    )


def main(args):
    if not args:
        print(__doc__, file=sys.stderr)
        return 2
    print(
        "| controller | success (95 % interval) | speed of successes, mm/s (95 %) | "
        "other outcomes |"
    )
    print("| --- | --- | --- | --- |")
    for a in args:
        name, _, path = a.partition("=")
        print(row(name, path))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
