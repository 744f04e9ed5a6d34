#!/usr/bin/env python3
"""Ablation of the fidelity mechanisms (docs/fidelity.md): the training scores with each
mechanism of the default robot effects alone and with all but one.

Runs `ssc validate` once per configuration on the published dL 5 mm map plus the published
outcomes beside it (the pilot at dL 2.5 mm, P_ref 100 / beta 2 at dL 2.5 and 7.5 mm, beta 0.5
failing at dL 2.5 and 7.5 mm), with the
same seeds for every configuration (common random numbers). Each run lives in OUT/<name>/ and
resumes if interrupted; the table goes to OUT/ablation.csv and OUT/ablation.md.

  tools/fidelity_ablation.py --out out/ablation --seeds 3
"""

import argparse
import csv
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# The default robot effects (FittedRobotEffects; their values: docs/defaults.md) split into
# mechanisms by their keys. A mechanism "on" keeps the default's values (--effects sets keys over
# the defaults); "off" sets its keys to 0, the ideal loop's value. The loop's timing is the
# default's in every configuration.
MECHANISMS = {
    "step_error": ["step_error_relative", "step_error_max_mm"],
    "step_corr": ["step_error_corr"],
    "tare_offset": ["offset_spread_pa"],
}
# The published outcomes beside the map (PublishedOutcomeCells in studies/success_map_fit.cc).
OUTCOME_CELLS = [
    (2.5, 1.0, 70, "3"),
    (2.5, 2.0, 100, "3"),
    (7.5, 2.0, 100, "3"),
    (2.5, 0.5, 100, "<=1"),
    (7.5, 0.5, 100, "<=1"),
]


def configurations():
    names = list(MECHANISMS)
    yield "none", set()
    yield "all", set(names)
    for n in names:
        yield "only_" + n, {n}
    for n in names:
        yield "all_but_" + n, set(names) - {n}


def command(ssc, map_path, out, seeds, on, threads):
    off = [key for name, keys in MECHANISMS.items() if name not in on for key in keys]
    effects = ",".join(f"{key}=0" for key in off) or "default"
    return [
        ssc,
        "validate",
        "--map",
        map_path,
        "--seeds",
        str(seeds),
        "--threads",
        str(threads),
        "--effects",
        effects,
        "--out",
        out,
        "--no-plot",
        "--no-progress",
    ]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--out", default="out/ablation")
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--ssc", default=os.path.join(ROOT, "build", "bin", "ssc"))
    ap.add_argument("--map", default=os.path.join(ROOT, "data", "published", "success_map_dl5.csv"))
    ap.add_argument("--only", default="", help="comma-separated configuration names to run")
    ap.add_argument(
        "--rerun",
        action="store_true",
        help="run configurations again even when OUT/<name>/validate.json exists",
    )
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    map_path = os.path.join(args.out, "training_cells.csv")
    with open(args.map) as f:
        text = f.read().rstrip("\n") + "\n"
    with open(map_path, "w") as f:
        f.write(text + "".join(f"{s},{b},{p},{c}\n" for s, b, p, c in OUTCOME_CELLS))
    wanted = set(filter(None, args.only.split(",")))
    rows = []
    for name, on in configurations():
        if wanted and name not in wanted:
            continue
        out = os.path.join(args.out, name)
        done = os.path.exists(os.path.join(out, "validate.json"))
        if done and not args.rerun:
            print(name, "(finished earlier: its scores are reused)", flush=True)
        else:
            cmd = command(args.ssc, map_path, out, args.seeds, on, args.threads)
            print(name, flush=True)
            run = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            if run.returncode != 0:
                sys.exit(f"{name}: ssc validate failed ({run.returncode}): {run.stderr.strip()}")
        rows.append(score(name, on, out))
    fields = [
        "config",
        "mechanisms_on",
        "map_class_match",
        "map_opposite",
        "map_expected_agreement",
        "outcomes_matched",
        "failure_I",
        "failure_II",
        "other_failures",
        "wall_s",
    ]
    with open(os.path.join(args.out, "ablation.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(args.out, "ablation.md"), "w") as f:
        f.write(
            "| configuration | class match (45) | opposite | expected agreement | "
            "published outcomes (5) | failure I | failure II |\n|---|---|---|---|---|---|---|\n"
        )
        for r in rows:
            f.write(
                f"| {r['config']} | {r['map_class_match']}/45 | {r['map_opposite']} | "
                f"{r['map_expected_agreement']:.3f} | "
                f"{r['outcomes_matched']}/{len(OUTCOME_CELLS)} | "
                f"{r['failure_I']} | {r['failure_II']} |\n"
            )
    print(open(os.path.join(args.out, "ablation.md")).read())


def score(name, on, out):
    """Scores the 45 map cells and the outcome cells apart, from the run's cells.csv."""
    with open(os.path.join(out, "cells.csv")) as f:
        cells = list(csv.DictReader(f))
    with open(os.path.join(out, "validate.json")) as f:
        wall = json.load(f)["wall_s"]
    outcome_keys = {(s, b, p) for s, b, p, _ in OUTCOME_CELLS}

    def is_outcome(c):
        return (float(c["step_mm"]), float(c["beta"]), float(c["pref_pa"])) in outcome_keys

    grid = [c for c in cells if not is_outcome(c)]
    extra = [c for c in cells if is_outcome(c)]
    match = sum(c["published"] == c["twin_class"] for c in grid)
    return {
        "config": name,
        "mechanisms_on": "+".join(sorted(on)) or "-",
        "map_class_match": match,
        "map_opposite": sum(int(c["opposite"]) for c in grid),
        "map_expected_agreement": sum(float(c["expected_agreement"]) for c in grid) / len(grid),
        "outcomes_matched": sum(c["published"] == c["twin_class"] for c in extra),
        "failure_I": sum(int(c["failure_I"]) for c in cells),
        "failure_II": sum(int(c["failure_II"]) for c in cells),
        "other_failures": sum(int(c["timeout"]) + int(c["unstable"]) for c in cells),
        "wall_s": round(wall, 1),
    }


if __name__ == "__main__":
    main()
