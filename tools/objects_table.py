#!/usr/bin/env python3
"""Markdown table of object trials, one row per object over its seeds (docs/objects.md).

usage: objects_table.py OBJECTS_CSV [OBJECTS_CSV ...] [--against OBJECTS_CSV] [--label TEXT]
       objects_table.py --fillet-profile FILLET_PROFILE_CSV [FILLET_PROFILE_CSV ...]

Reads the objects.csv files of `ssc objects` (rows of one object may be spread over several
files, e.g. runs of one seed each) and prints per object: the outcomes over its seeds, where
each trial ended (mm along the edge for open edges, degrees swept for closed ones; the fillet
also its radius there) as mean +- sd with the per-seed values, and, with --against (another
tier's objects.csv), that tier's outcomes and ends beside them.

With --fillet-profile, the fillet's along-edge profiles instead (fillet_profile.csv of `ssc
objects`, one per seed): per stretch along the edge, the mean fillet radius, mean P and |dP| of
each seed's control iterations there, as mean +- sd over the seeds; the last row is each seed's
last 10 mm before its trial ended.
"""

import argparse
import csv
import statistics
import sys


def read_rows(paths):
    rows = {}
    for path in paths:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            need = {"object", "seed", "outcome", "end_arc_mm", "end_swept_deg"}
            if not need <= set(reader.fieldnames or []):
                sys.exit(
                    f"{path}: not an objects.csv of ssc objects (needs columns "
                    f"{', '.join(sorted(need))})"
                )
            for r in reader:
                rows.setdefault(r["object"], []).append(r)
    for trials in rows.values():
        trials.sort(key=lambda r: int(r["seed"]))
    return rows


def end_value(r):
    """Where the trial ended: (value, unit); open edges mm along the edge, closed deg swept."""
    arc = float(r["end_arc_mm"])
    if arc >= 0:
        return arc, "mm"
    return float(r["end_swept_deg"]), "deg"


def outcomes(trials):
    counts = {}
    for r in trials:
        counts[r["outcome"]] = counts.get(r["outcome"], 0) + 1
    n = len(trials)
    return ", ".join(f"`{o}` {c}/{n}" if n > 1 else f"`{o}`" for o, c in counts.items())


def ends(trials):
    values = [end_value(r) for r in trials]
    unit = values[0][1]
    v = [x for x, _ in values]
    text = f"{v[0]:.1f} {unit}"
    if len(v) > 1:
        text = (
            f"{statistics.mean(v):.1f} ± {statistics.stdev(v):.1f} {unit} ("
            + ", ".join(f"{x:.1f}" for x in v)
            + ")"
        )
    radii = [float(r.get("end_fillet_radius_mm", -1)) for r in trials]
    if all(x >= 0 for x in radii):
        text += (
            f"; radius {statistics.mean(radii):.2f} ± {statistics.stdev(radii):.2f} mm"
            if len(radii) > 1
            else f"; radius {radii[0]:.2f} mm"
        )
    return text


FILLET_STRETCHES_MM = [(10, 40), (40, 70), (70, 100), (100, 130), (130, 160)]


def mean_sd(values, digits):
    if len(values) == 1:
        return f"{values[0]:.{digits}f}"
    return f"{statistics.mean(values):.{digits}f} ± {statistics.stdev(values):.{digits}f}"


def fillet_profile_table(paths):
    seeds = []
    for path in paths:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            need = {"x_mm", "fillet_radius_mm", "pbar_pa", "diff_pa"}
            if not need <= set(reader.fieldnames or []):
                sys.exit(
                    f"{path}: not a fillet_profile.csv of ssc objects (needs columns "
                    f"{', '.join(sorted(need))})"
                )
            rows = [{k: float(r[k]) for k in need} for r in reader]
        if not rows:
            sys.exit(f"{path}: no control iterations")
        seeds.append(rows)
    print("| stretch along the edge (mm) | seeds | fillet radius (mm) | P̄ (Pa) | \\|ΔP\\| (Pa) |")
    print("| --- | --- | --- | --- | --- |")
    stretches = [
        (f"{a}–{b}", lambda r, a=a, b=b: a <= r["x_mm"] < b) for a, b in FILLET_STRETCHES_MM
    ]
    for label, inside in stretches + [("the last 10 before the end", None)]:
        per_seed = []
        for rows in seeds:
            end = max(r["x_mm"] for r in rows)
            sel = [r for r in rows if (inside(r) if inside else r["x_mm"] >= end - 10)]
            if sel:
                per_seed.append(
                    {
                        k: statistics.mean(r[k] for r in sel)
                        for k in ("fillet_radius_mm", "pbar_pa", "diff_pa")
                    }
                )
        if not per_seed:
            continue
        print(
            f"| {label} | {len(per_seed)} | "
            f"{mean_sd([x['fillet_radius_mm'] for x in per_seed], 1)} | "
            f"{mean_sd([x['pbar_pa'] for x in per_seed], 0)} | "
            f"{mean_sd([x['diff_pa'] for x in per_seed], 0)} |"
        )
    return 0


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument(
        "csv",
        nargs="+",
        help="objects.csv files (ssc objects), or with --fillet-profile fillet_profile.csv files",
    )
    parser.add_argument(
        "--fillet-profile",
        action="store_true",
        help="the fillet's along-edge profile over seeds instead",
    )
    parser.add_argument("--against", help="another tier's objects.csv, shown beside")
    parser.add_argument("--label", default="flex", help="name of the first tier's columns")
    parser.add_argument(
        "--against-label", default="segment (gantry)", help="name of the --against tier's columns"
    )
    args = parser.parse_args(argv)
    if args.fillet_profile:
        return fillet_profile_table(args.csv)
    rows = read_rows(args.csv)
    against = read_rows([args.against]) if args.against else {}
    head = ["object", "seeds", f"{args.label}: outcome", f"{args.label}: end"]
    if args.against:
        head += [f"{args.against_label}: outcome", f"{args.against_label}: end"]
    print("| " + " | ".join(head) + " |")
    print("| " + " | ".join("---" for _ in head) + " |")
    for name, trials in rows.items():
        cells = [name, str(len(trials)), outcomes(trials), ends(trials)]
        if args.against:
            other = against.get(name)
            cells += [outcomes(other), ends(other)] if other else ["not run", ""]
        print("| " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
