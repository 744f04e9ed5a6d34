#!/usr/bin/env python3
"""Compares two sweep CSVs trial by trial (same grid point and repeat, hence the same seed).

A trial is unchanged when the outcome is the same and, for successes, r_mean and sigma_r differ
by at most --dr-mm (default 0.1 mm) and the path length s by at most --ds-rel (default 2 %): the
published trial-to-trial spread the light scene must stay within (docs/scenes.md).

usage: compare_sweeps.py BEFORE.csv AFTER.csv [--dr-mm 0.1] [--ds-rel 0.02] [--markdown]
Exit status 0 whatever the result (a report, not a test); 2 on unreadable input.
"""

import argparse
import csv
import sys
from collections import defaultdict


def load(path):
    rows = {}
    try:
        with open(path, newline="") as f:
            for r in csv.DictReader(f):
                try:
                    key = (
                        float(r["pref_pa"]),
                        float(r["beta"]),
                        float(r["step_mm"]),
                        int(r["repeat"]),
                    )
                except (KeyError, ValueError):
                    continue
                rows[key] = r
    except OSError as e:
        sys.exit(f"compare_sweeps: {path}: {e.strerror}")
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("before")
    ap.add_argument("after")
    ap.add_argument("--dr-mm", type=float, default=0.1)
    ap.add_argument("--ds-rel", type=float, default=0.02)
    ap.add_argument("--markdown", action="store_true", help="print the table as Markdown")
    ap.add_argument("--list", action="store_true", help="list the changed trials")
    a = ap.parse_args()
    before, after = load(a.before), load(a.after)
    keys = sorted(set(before) & set(after))
    if not keys:
        sys.exit("compare_sweeps: no common trials")
    by_step = defaultdict(
        lambda: {
            "n": 0,
            "same_outcome": 0,
            "unchanged": 0,
            "succ": 0,
            "dr": [],
            "dsig": [],
            "ds": [],
        }
    )
    changed = []
    for k in keys:
        b, c = before[k], after[k]
        g = by_step[k[2]]
        g["n"] += 1
        ok = b["outcome"] == c["outcome"]
        if ok:
            g["same_outcome"] += 1
        if ok and b["outcome"] == "success":
            g["succ"] += 1
            dr = abs(float(c["r_mean_mm"]) - float(b["r_mean_mm"]))
            dsig = abs(float(c["sigma_r_mm"]) - float(b["sigma_r_mm"]))
            ds = abs(float(c["s_mm"]) / float(b["s_mm"]) - 1) if float(b["s_mm"]) else 0.0
            g["dr"].append(dr)
            g["dsig"].append(dsig)
            g["ds"].append(ds)
            ok = dr <= a.dr_mm and dsig <= a.dr_mm and ds <= a.ds_rel
        if ok:
            g["unchanged"] += 1
        else:
            changed.append((k, b, c))
    n_all = sum(g["n"] for g in by_step.values())
    unchanged_all = sum(g["unchanged"] for g in by_step.values())
    head = [
        "dL mm",
        "trials",
        "same outcome",
        "successes",
        "max |dr_mean| mm",
        "max |dsigma_r| mm",
        "max |ds|/s",
        "unchanged",
    ]
    lines = []
    for step in sorted(by_step):
        g = by_step[step]

        def mx(v):
            return max(v) if v else 0.0

        lines.append(
            [
                f"{step:g}",
                str(g["n"]),
                str(g["same_outcome"]),
                str(g["succ"]),
                f"{mx(g['dr']):.3f}",
                f"{mx(g['dsig']):.3f}",
                f"{100 * mx(g['ds']):.2f} %",
                f"{g['unchanged']} ({100 * g['unchanged'] / g['n']:.1f} %)",
            ]
        )
    lines.append(
        [
            "all",
            str(n_all),
            str(sum(g["same_outcome"] for g in by_step.values())),
            str(sum(g["succ"] for g in by_step.values())),
            "",
            "",
            "",
            f"{unchanged_all} ({100 * unchanged_all / n_all:.1f} %)",
        ]
    )
    if a.markdown:
        print("| " + " | ".join(head) + " |")
        print("|" + " --- |" * len(head))
        for cells in lines:
            print("| " + " | ".join(cells) + " |")
    else:
        w = [max(len(h), *(len(cells[i]) for cells in lines)) for i, h in enumerate(head)]
        print("  ".join(h.rjust(w[i]) for i, h in enumerate(head)))
        for cells in lines:
            print("  ".join(x.rjust(w[i]) for i, x in enumerate(cells)))
    print(
        f"unchanged within |dr|,|dsigma| <= {a.dr_mm} mm, |ds|/s <= {100 * a.ds_rel:g} %: "
        f"{unchanged_all}/{n_all} = {100 * unchanged_all / n_all:.1f} % "
        f"({len(set(before) ^ set(after))} trials in only one file)"
    )
    if a.list:
        for k, b, c in changed:
            print(
                f"  P_ref {k[0]:g} beta {k[1]:g} dL {k[2]:g} rep {k[3]}: {b['outcome']} -> "
                f"{c['outcome']}; r {b['r_mean_mm']} -> {c['r_mean_mm']}, sigma "
                f"{b['sigma_r_mm']} -> {c['sigma_r_mm']}, s {b['s_mm']} -> {c['s_mm']}"
            )


if __name__ == "__main__":
    main()
