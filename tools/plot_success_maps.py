#!/usr/bin/env python3
"""Success-rate maps per step length over (P_ref, beta), like the published maps.

usage: plot_success_maps.py sweep.csv out.png
"""

import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1], newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"{sys.argv[1]}: no rows")
    cells = defaultdict(list)
    for r in rows:
        cells[(float(r["step_mm"]), float(r["pref_pa"]), float(r["beta"]))].append(r["outcome"])
    steps = sorted({k[0] for k in cells})
    prefs = sorted({k[1] for k in cells})
    betas = sorted({k[2] for k in cells})
    # One panel per step length; beta labelled once, on the left (the panels share it). Cell
    # text is sized to the cell and white on dark cells so it reads at README width.
    fig, axes = plt.subplots(
        1,
        len(steps),
        figsize=(4.6 * len(steps) + 1.2, 5.2),
        squeeze=False,
        sharey=True,
        gridspec_kw={"wspace": 0.08},
    )
    cell_pt = min(12.0, 260.0 / max(len(prefs), len(betas)))
    for ax, step in zip(axes[0], steps):
        grid = [[float("nan")] * len(prefs) for _ in betas]
        for (s, p, b), outcomes in cells.items():
            if s != step:
                continue
            grid[betas.index(b)][prefs.index(p)] = outcomes.count("success") / len(outcomes)
        im = ax.imshow(grid, origin="lower", cmap="RdYlGn", vmin=0, vmax=1, aspect="auto")
        for (s, p, b), outcomes in cells.items():
            if s != step:
                continue
            n = len(outcomes)
            ok = outcomes.count("success")
            modes = {
                "I": outcomes.count("failure_I"),
                "II": outcomes.count("failure_II"),
                "L": outcomes.count("lost_edge"),
            }
            mark = "" if ok == n else max(modes, key=modes.get)
            if outcomes.count("unstable"):
                mark = "U"
            rate = ok / n
            colour = "white" if rate < 0.25 or rate > 0.8 else "black"
            ax.text(
                prefs.index(p),
                betas.index(b),
                f"{ok}/{n}" + (f" {mark}" if mark else ""),
                ha="center",
                va="center",
                fontsize=cell_pt,
                color=colour,
            )
        ax.set_xticks(range(len(prefs)))
        ax.set_xticklabels([f"{p:g}" for p in prefs], fontsize=10)
        ax.set_yticks(range(len(betas)))
        ax.set_yticklabels([f"{b:g}" for b in betas], fontsize=10)
        ax.set_xlabel("P_ref (Pa)", fontsize=11)
        ax.set_title(f"dL = {step:g} mm", fontsize=12)
    axes[0][0].set_ylabel("beta", fontsize=11)
    fig.colorbar(im, ax=axes[0].tolist(), label="success rate", fraction=0.025, pad=0.02)
    fig.suptitle(
        "success rate per cell: successes/trials; I / II / L (lost edge): dominant failure mode",
        fontsize=12,
    )
    fig.savefig(sys.argv[2], dpi=110, bbox_inches="tight")


if __name__ == "__main__":
    main()
