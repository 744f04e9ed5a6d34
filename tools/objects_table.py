#!/usr/bin/env python3
"""Markdown table of object trials, one row per object over its seeds (docs/objects.md).

usage: objects_table.py OBJECTS_CSV [OBJECTS_CSV ...] [--against OBJECTS_CSV ...] [--label TEXT]
                        [--interval] [--disagree] [--only PREFIX,...]
       objects_table.py --fillet-profile FILLET_PROFILE_CSV [FILLET_PROFILE_CSV ...]

Reads the objects.csv files of `ssc objects` (rows of one object may be spread over several
files, e.g. runs of one seed each) and prints per object: the outcomes over its seeds, where
each trial ended (mm along the edge for open edges, degrees swept for closed ones; the fillet
also its radius there) as mean +- sd with the per-seed values, and, with --against (another
tier's objects.csv files, repeatable), that tier's outcomes and ends beside them. --interval adds
the 95 % Student-t interval of the mean end (3 or more seeds). --disagree prints instead, per
object, whether the two tiers disagree (DISAGREE_RULE below), the evidence `--scene-kind auto`
is decided from (studies/object_trials.cc).

With --fillet-profile, the fillet's along-edge profiles instead (fillet_profile.csv of `ssc
objects`, one per seed): per stretch along the edge, the mean fillet radius, mean P and |dP| of
each seed's control iterations there, as mean +- sd over the seeds; the first row is each seed's
first 10 mm (the fillet's sharp start), the last its last 10 mm before its trial ended.
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
    counts = outcomes_count(trials)
    n = len(trials)
    return ", ".join(f"`{o}` {c}/{n}" if n > 1 else f"`{o}`" for o, c in counts.items())


def ends(trials, interval=False):
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
    if interval and len(v) >= 3:
        lo, hi = t_interval(v)
        text += f", 95 % t interval {lo:.1f}–{hi:.1f}"
    radii = [float(r.get("end_fillet_radius_mm", -1)) for r in trials]
    if all(x >= 0 for x in radii):
        text += (
            f"; radius {statistics.mean(radii):.2f} ± {statistics.stdev(radii):.2f} mm"
            if len(radii) > 1
            else f"; radius {radii[0]:.2f} mm"
        )
    return text


def t_interval(v):
    """The 95 % Student-t interval of the mean of v (len >= 2)."""
    from scipy import stats  # a project requirement (requirements.txt)

    half = stats.t.ppf(0.975, len(v) - 1) * statistics.stdev(v) / len(v) ** 0.5
    return statistics.mean(v) - half, statistics.mean(v) + half


# Two tiers disagree on an object when an outcome is seen in one and not in the other over its
# seeds, or, when they are not all `success`, the ends of their followed trials (not failure_I;
# two or more in each tier) differ by more than END_TOLERANCE of the unit and the 95 % Welch
# interval of the difference of the mean ends excludes 0.
END_TOLERANCE = {"mm": 2.0, "deg": 5.0}
DISAGREE_RULE = (
    "an outcome is seen in one tier's seeds and not in the other's, or (not all success) the "
    "mean ends of the followed trials (not failure_I, two or more in each tier) differ by more "
    "than 2 mm / 5 deg with the 95 % Welch interval of the difference excluding 0"
)


def disagreement(trials, other):
    """'' when the tiers agree on the object, else why they do not."""
    mine, theirs = outcomes_count(trials), outcomes_count(other)
    if set(mine) != set(theirs):
        return "outcome"
    if set(mine) == {"success"}:
        return ""
    # Where the followed trials ended (a failure_I never followed: its end is the landing's).
    a = [end_value(r)[0] for r in trials if r["outcome"] != "failure_I"]
    b = [end_value(r)[0] for r in other if r["outcome"] != "failure_I"]
    if len(a) < 2 or len(b) < 2:
        return ""  # no interval from one trial: the outcomes decide
    unit = end_value(trials[0])[1]
    diff = statistics.mean(a) - statistics.mean(b)
    if abs(diff) <= END_TOLERANCE[unit]:
        return ""
    from scipy import stats

    va, vb = statistics.variance(a) / len(a), statistics.variance(b) / len(b)
    if va + vb == 0:
        return f"end ({diff:+.1f} {unit})"
    df = (va + vb) ** 2 / (va**2 / (len(a) - 1) + vb**2 / (len(b) - 1))
    half = stats.t.ppf(0.975, df) * (va + vb) ** 0.5
    return f"end ({diff:+.1f} ± {half:.1f} {unit})" if abs(diff) > half else ""


def outcomes_count(trials):
    counts = {}
    for r in trials:
        counts[r["outcome"]] = counts.get(r["outcome"], 0) + 1
    return counts


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
    first = ("the first 10 (the sharp start)", "first")
    for label, inside in [first] + stretches + [("the last 10 before the end", None)]:
        per_seed = []
        for rows in seeds:
            start, end = min(r["x_mm"] for r in rows), max(r["x_mm"] for r in rows)
            if inside == "first":
                sel = [r for r in rows if r["x_mm"] < start + 10]
            else:
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


def disagreement_table(rows, against, args):
    print(f"| object | seeds ({args.label} / {args.against_label}) | the tiers |")
    print("| --- | --- | --- |")
    for name, trials in rows.items():
        other = against.get(name)
        if not other:
            verdict = "not run in both"
            counts = f"{len(trials)} / 0"
        else:
            why = disagreement(trials, other)
            verdict = f"**disagree**: {why}" if why else "agree"
            counts = f"{len(trials)} / {len(other)}"
        print(f"| {name} | {counts} | {verdict} |")
    print(f"\nThe tiers disagree on an object when {DISAGREE_RULE}.")
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
    parser.add_argument(
        "--against",
        action="append",
        default=[],
        help="another tier's objects.csv, shown beside (repeatable: its seeds' files)",
    )
    parser.add_argument(
        "--interval", action="store_true", help="the 95 %% t interval of the mean end too"
    )
    parser.add_argument(
        "--only",
        help="comma-separated name prefixes: only the objects whose names start with one",
    )
    parser.add_argument(
        "--disagree",
        action="store_true",
        help="per object, whether the tiers disagree (needs --against)",
    )
    parser.add_argument("--label", default="flex", help="name of the first tier's columns")
    parser.add_argument(
        "--against-label", default="segment (gantry)", help="name of the --against tier's columns"
    )
    args = parser.parse_args(argv)
    if args.fillet_profile:
        return fillet_profile_table(args.csv)
    rows = read_rows(args.csv)
    if args.only:
        prefixes = tuple(args.only.split(","))
        rows = {k: v for k, v in rows.items() if k.startswith(prefixes)}
    against = read_rows(args.against) if args.against else {}
    if args.disagree:
        if not args.against:
            parser.error("--disagree needs --against")
        return disagreement_table(rows, against, args)
    head = ["object", "seeds", f"{args.label}: outcome", f"{args.label}: end"]
    if args.against:
        head += [f"{args.against_label}: outcome", f"{args.against_label}: end"]
    print("| " + " | ".join(head) + " |")
    print("| " + " | ".join("---" for _ in head) + " |")
    for name, trials in rows.items():
        cells = [name, str(len(trials)), outcomes(trials), ends(trials, args.interval)]
        if args.against:
            other = against.get(name)
            cells += [outcomes(other), ends(other, args.interval)] if other else ["not run", ""]
        print("| " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
