#!/usr/bin/env python3
"""Markdown table of object trials, one row per object over its seeds (docs/objects.md).

usage: objects_table.py OBJECTS_CSV [OBJECTS_CSV ...] [--against OBJECTS_CSV] [--label TEXT]

Reads the objects.csv files of `ssc objects` (rows of one object may be spread over several
files, e.g. runs of one seed each) and prints per object: the outcomes over its seeds, where
each trial ended (mm along the edge for open edges, degrees swept for closed ones; the fillet
also its radius there) as mean +- sd with the per-seed values, and, with --against (another
tier's objects.csv), that tier's outcomes and ends beside them.
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
                sys.exit(f"{path}: not an objects.csv of ssc objects (needs columns "
                         f"{', '.join(sorted(need))})")
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
        text = (f"{statistics.mean(v):.1f} ± {statistics.stdev(v):.1f} {unit} ("
                + ", ".join(f"{x:.1f}" for x in v) + ")")
    radii = [float(r.get("end_fillet_radius_mm", -1)) for r in trials]
    if all(x >= 0 for x in radii):
        text += (f"; radius {statistics.mean(radii):.2f} ± {statistics.stdev(radii):.2f} mm"
                 if len(radii) > 1 else f"; radius {radii[0]:.2f} mm")
    return text


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("csv", nargs="+", help="objects.csv files (ssc objects)")
    parser.add_argument("--against", help="another tier's objects.csv, shown beside")
    parser.add_argument("--label", default="flex", help="name of the first tier's columns")
    parser.add_argument("--against-label", default="segment (gantry)",
                        help="name of the --against tier's columns")
    args = parser.parse_args(argv)
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
