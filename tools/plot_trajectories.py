#!/usr/bin/env python3
"""Cup-centre trajectories of disk trials over the disk outline, like the published figure.

usage: plot_trajectories.py out.png trial.csv [trial.csv ...]
       (trial.csv files written by `ssc trial`; the disk: radius 35 mm centred at (650, 0) mm)
"""

import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

CENTRE_MM = (650.0, 0.0)
RADIUS_MM = 35.0
CUP_BODY_MM = 23.0
OPENING_MM = 11.0


def read(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["phase"] == "follow"]
    if not rows:
        sys.exit(f"{path}: no follow-phase rows")
    xs = [float(r["x_m"]) * 1e3 - CENTRE_MM[0] for r in rows]
    ys = [float(r["y_m"]) * 1e3 - CENTRE_MM[1] for r in rows]
    pbar = [float(r["pbar_pa"]) for r in rows if r["iteration"] == "1"]
    return xs, ys, pbar


def trial_label(path):
    """The trial's parameters and outcome from the summary.json beside trial.csv (ssc trial
    writes both); else the file's name."""
    summary = os.path.join(os.path.dirname(os.path.abspath(path)), "summary.json")
    try:
        with open(summary) as f:
            s = json.load(f)
        p = s["parameters"]
        label = (
            f"P_ref {p['pref_pa']:g} Pa, β {p['beta']:g}, ΔL {p['step_mm']:g} mm, seed {s['seed']}"
        )
        return label + (f": {s['outcome']}" if s.get("outcome") else "")
    except (OSError, ValueError, KeyError, TypeError):
        return os.path.basename(path)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, paths = sys.argv[1], sys.argv[2:]
    fig, ax = plt.subplots(figsize=(6, 6))
    t = [i * 2 * math.pi / 360 for i in range(361)]
    ax.fill(
        [RADIUS_MM * math.cos(a) for a in t],
        [RADIUS_MM * math.sin(a) for a in t],
        color="0.85",
        label="disk (R = 35 mm)",
    )
    for i, path in enumerate(paths):
        xs, ys, _ = read(path)
        label = trial_label(path)
        ax.plot(xs, ys, "-", lw=1.2, color=f"C{i % 10}", label=label)
        ax.plot(xs[0], ys[0], "o", color=f"C{i % 10}")
        # The cup to scale at the start: body and opening.
        ax.add_patch(
            plt.Circle(
                (xs[0], ys[0]), CUP_BODY_MM / 2, fill=False, ls="--", color=f"C{i % 10}", lw=0.8
            )
        )
        ax.add_patch(
            plt.Circle((xs[0], ys[0]), OPENING_MM / 2, fill=False, color=f"C{i % 10}", lw=0.8)
        )
    ax.set_aspect("equal")
    ax.set_xlim(-50, 50)
    ax.set_ylim(-50, 50)
    ax.set_xlabel("x from disk centre (mm), east")
    ax.set_ylabel("y from disk centre (mm), north")
    ax.set_title("cup-centre path (start: circle; dashed = 23 mm cup body)")
    ax.legend(fontsize=7, loc="lower left")
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
