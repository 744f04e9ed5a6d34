#!/usr/bin/env python3
"""A quick probe of candidate fidelity settings on 19 telling cells (docs/fidelity_options.md).

The cells: 14 of the published dL 5 mm map (the low-beta row the twin passes and the robot failed,
the high P_ref x beta corner where the robot grasped, and controls the robot passed 3/3), the
three published outcomes beside the map (the pilot at dL 2.5 mm; P_ref 100 / beta 2 at dL 2.5 and
7.5 mm) and beta 0.5 at dL 2.5 and 7.5 mm (the reference says beta <= 0.5 always failed). Every
configuration runs `ssc validate` with the same seeds (common random numbers); one line per
configuration gives how many cells land in their published class (successes scaled to 3 trials),
then each cell as step/beta/P_ref:published>twin successes and main failure mode.

  tools/fidelity_probe.py --out out/probe --seeds 3 \
      r1_tilt0.3="--effects slip_mm=1,tilt_decades=0.3" \
      f99_tilt0.1="--period 0.25 --smoothing 0.056 --effects slip_mm=1,tilt_decades=0.1"
"""

import argparse
import csv
import os
import shlex
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# (step_mm, beta, P_ref Pa, published class); the first 14 are rows of data/published/.
CELLS = [
    (5.0, 0.5, 40, "<=1"),
    (5.0, 0.5, 100, "<=1"),
    (5.0, 0.5, 250, "<=1"),
    (5.0, 1.0, 70, "<=1"),
    (5.0, 1.0, 100, "<=1"),
    (5.0, 1.0, 200, "2"),
    (5.0, 1.5, 70, "3"),
    (5.0, 1.5, 100, "3"),
    (5.0, 2.0, 70, "3"),
    (5.0, 2.0, 150, "3"),
    (5.0, 2.0, 250, "<=1"),
    (5.0, 3.0, 100, "3"),
    (5.0, 3.0, 200, "<=1"),
    (5.0, 4.0, 100, "<=1"),
    (2.5, 1.0, 70, "3"),
    (2.5, 2.0, 100, "3"),
    (2.5, 0.5, 100, "<=1"),
    (7.5, 2.0, 100, "3"),
    (7.5, 0.5, 100, "<=1"),
]
MODE = {"failure_I": "I", "failure_II": "II", "timeout": "T", "unstable": "U"}


def in_class(published, successes, trials):
    """The twin's successes, scaled to 3 trials, land in the published class ('3', '2', '<=1')."""
    k = round(3 * successes / trials)
    return {"3": k == 3, "2": k == 2, "<=1": k <= 1}[published]


def line(name, out):
    cells, hits = [], 0
    with open(os.path.join(out, "cells.csv")) as f:
        for r in csv.DictReader(f):
            hits += in_class(r["published"], int(r["successes"]), int(r["trials"]))
            cells.append(
                f"{float(r['step_mm']):g}/{float(r['beta']):g}/{float(r['pref_pa']):g}:"
                f"{r['published']}>{r['successes']}{MODE.get(r['main_failure'], '')}"
            )
    return f"{name} in-class {hits}/{len(cells)} " + " ".join(cells)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("configs", nargs="+", help='NAME="ssc validate options"')
    ap.add_argument("--out", default="out/probe")
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--ssc", default=os.path.join(ROOT, "build", "bin", "ssc"))
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    map_path = os.path.join(args.out, "probe_cells.csv")
    with open(map_path, "w") as f:
        f.write("step_mm,beta,pref_pa,successes_of_3\n")
        f.writelines(f"{s},{b},{p},{c}\n" for s, b, p, c in CELLS)
    for spec in args.configs:
        name, sep, opts = spec.partition("=")
        if not sep or not name or "/" in name:
            sys.exit(
                f"fidelity_probe.py: configuration '{spec}' must be NAME=\"options\" "
                "(NAME without '/')"
            )
        out = os.path.join(args.out, name)
        cmd = [
            args.ssc,
            "validate",
            "--map",
            map_path,
            "--seeds",
            str(args.seeds),
            "--threads",
            str(args.threads),
            "--out",
            out,
            "--no-plot",
            "--no-progress",
        ]
        run = subprocess.run(
            cmd + shlex.split(opts), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True
        )
        if run.returncode != 0:
            sys.exit(f"{name}: ssc validate failed ({run.returncode}): {run.stderr.strip()}")
        print(line(name, out), flush=True)


if __name__ == "__main__":
    main()
