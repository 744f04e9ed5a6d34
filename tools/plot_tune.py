#!/usr/bin/env python3
"""The speed-success chart of `ssc tune`: every evaluation of the search (success rate with its
95 % Wilson interval against the mean speed of the successful trials with its 95 % t interval),
the Pareto front through them, the reference controllers run on the same seeds, and the success
target.

usage: plot_tune.py tune.csv out.png min_success
"""

import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    table, out, target = sys.argv[1], sys.argv[2], float(sys.argv[3])
    with open(table, newline="") as f:
        rows = list(csv.DictReader(f))
    # A refused point (it broke a rule between the controller's keys) was not run: no speed.
    refused = [r for r in rows if r.get("outcome", "ran").startswith("refused")]
    rows = [r for r in rows if r not in refused]
    search = [r for r in rows if r["label"].startswith("eval ")]
    refs = [r for r in rows if not r["label"].startswith("eval ")]

    def num(r, k):
        return float(r[k])

    fig, ax = plt.subplots(figsize=(7.5, 5))
    ax.axhline(100 * target, color="0.6", ls=":", lw=1, label=f"target {100 * target:.0f} %")
    xs = [num(r, "speed_mm_s") for r in search]
    ys = [100 * num(r, "success_rate") for r in search]
    yerr = [
        [y - 100 * num(r, "success_lo") for y, r in zip(ys, search)],
        [100 * num(r, "success_hi") - y for y, r in zip(ys, search)],
    ]
    xerr = [num(r, "speed_ci_mm_s") for r in search]
    ax.errorbar(
        xs,
        ys,
        yerr=yerr,
        xerr=xerr,
        fmt="o",
        color="tab:blue",
        ms=4,
        lw=0.6,
        alpha=0.7,
        label="search evaluations",
    )
    front = sorted(
        ((num(r, "speed_mm_s"), 100 * num(r, "success_rate")) for r in rows if r["pareto"] == "1")
    )
    if front:
        ax.plot(
            [p[0] for p in front],
            [p[1] for p in front],
            "-",
            color="tab:blue",
            lw=1.5,
            label="Pareto front (all points)",
        )
    markers = ["s", "D", "^", "v", "P", "X"]
    for k, r in enumerate(refs):
        x, y = num(r, "speed_mm_s"), 100 * num(r, "success_rate")
        ax.errorbar(
            [x],
            [y],
            yerr=[[y - 100 * num(r, "success_lo")], [100 * num(r, "success_hi") - y]],
            xerr=[num(r, "speed_ci_mm_s")],
            fmt=markers[k % len(markers)],
            ms=8,
            color=f"C{(k + 1) % 10}",
            label=r["label"],
        )
    ax.set_xlabel("mean follow speed of the successful trials, mm/s (95 % t interval)")
    ax.set_ylabel("success, % (95 % Wilson interval)")
    ax.set_ylim(-5, 115)
    n = rows[0]["trials"] if rows else "?"
    note = f"; {len(refused)} points refused, not run" if refused else ""
    ax.set_title(f"ssc tune: speed and success, {n} seeds per point{note}")
    ax.grid(alpha=0.3)
    # Outside the axes: the points may fill any corner.
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=8, borderaxespad=0)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


if __name__ == "__main__":
    main()
