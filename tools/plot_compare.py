#!/usr/bin/env python3
"""Twin against robot log: pressures over time, the path, error histograms.

usage: plot_compare.py series.csv out.png   (series.csv written by `ssc compare`)
"""
import csv
import math
import sys

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
    t = [float(r["t_s"]) for r in rows]
    fig = plt.figure(figsize=(13, 7))
    for k in range(4):
        ax = fig.add_subplot(3, 4, k + 1)
        ax.plot(t, [float(r[f"log_p{k + 1}_pa"]) for r in rows], "k-", lw=0.8, label="robot")
        ax.plot(t, [float(r[f"sim_p{k + 1}_pa"]) for r in rows], "r-", lw=0.8, label="twin")
        ax.set_title(f"chamber {k + 1} (Pa)", fontsize=9)
        ax.set_xlabel("t (s)", fontsize=8)
        if k == 0:
            ax.legend(fontsize=7)
    ax = fig.add_subplot(3, 4, (5, 10))
    ax.plot([float(r["x_m"]) * 1e3 for r in rows], [float(r["y_m"]) * 1e3 for r in rows], "b-",
            lw=0.8)
    ax.set_aspect("equal")
    ax.set_title("logged tool-centre path (mm)", fontsize=9)
    for k in range(2):
        ax = fig.add_subplot(3, 4, 7 + 4 * k if k == 0 else 12)
        errs = [float(r[f"sim_p{c}_pa"]) - float(r[f"log_p{c}_pa"]) for r in rows
                for c in (range(1, 5))] if k == 0 else [
            math.log10(max(1.0, float(r[f"sim_p{c}_pa"]))) -
            math.log10(max(1.0, float(r[f"log_p{c}_pa"]))) for r in rows for c in range(1, 5)]
        ax.hist(errs, bins=60, color="gray")
        ax.set_title("error twin - robot, " + ("Pa" if k == 0 else "log10"), fontsize=9)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=100)


if __name__ == "__main__":
    main()
