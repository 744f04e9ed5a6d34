#!/usr/bin/env python3
"""Twin against robot log: pressures over time, the path over the object, error histograms.

usage: plot_compare.py series.csv out.png [report.json]   (all written by `ssc compare`)
With report.json the path panel draws the scene's object (a disk as its circle, other shapes as
their bounding box) and marks the tool centre's closest approach.
"""

import csv
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Circle, Rectangle  # noqa: E402


def draw_object(ax, report):
    frames = report.get("frames", {})
    obj = frames.get("scene_object")
    if not obj:
        return
    x, y = obj["x_m"] * 1e3, obj["y_m"] * 1e3
    if obj.get("radius_m") is not None:
        ax.add_patch(
            Circle(
                (x, y),
                obj["radius_m"] * 1e3,
                color="#3a6fc4",
                alpha=0.25,
                label=f"object '{obj['name']}'",
            )
        )
    else:
        hx, hy = (v * 1e3 for v in obj.get("half_size_m", [0, 0]))
        ax.add_patch(
            Rectangle(
                (x - hx, y - hy),
                2 * hx,
                2 * hy,
                color="#3a6fc4",
                alpha=0.25,
                label=f"object '{obj['name']}' (bounding box)",
            )
        )
    # The tool centre's closest approach to the object is measured in 3D: for a cup landing on
    # the object that is the touch-down, seen from above wherever the cup landed (on a disk,
    # its centre). Named so, with its time and distance.
    tcp = frames.get("closest_approach_tcp_m")
    if tcp:
        when = frames.get("closest_approach_t_s")
        dist = frames.get("closest_approach_mm")
        detail = ", ".join(
            x
            for x in (
                f"t = {when:.2f} s" if when is not None else "",
                f"{dist:.1f} mm" if dist is not None else "",
            )
            if x
        )
        ax.plot(
            tcp[0] * 1e3,
            tcp[1] * 1e3,
            "rx",
            ms=8,
            label="closest to the object in 3D (touch-down)" + (f": {detail}" if detail else ""),
        )


def error_histogram(ax, errs, unit):
    """The errors' central 98 % (most samples sit near 0; a few large ones would stretch the
    axis until the bulk is one bar), counts on a log axis; the samples beyond, counted."""
    errs = sorted(e for e in errs if math.isfinite(e))
    if not errs:
        return
    lo, hi = errs[int(0.01 * (len(errs) - 1))], errs[int(0.99 * (len(errs) - 1))]
    span = max(abs(lo), abs(hi))
    if span <= 0:  # more than 98 % exactly 0: the full range
        span = max(abs(errs[0]), abs(errs[-1])) or 1.0
    inside = [e for e in errs if -span <= e <= span]
    ax.hist(inside, bins=60, range=(-span, span), color="gray")
    ax.set_yscale("log")
    beyond = len(errs) - len(inside)
    ax.set_title(f"error twin - robot ({unit}), all chambers", fontsize=9)
    ax.set_xlabel(
        f"{unit}; {beyond} of {len(errs)} samples beyond ±{span:.3g}" if beyond else unit,
        fontsize=8,
    )
    ax.set_ylabel("samples", fontsize=8)


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    with open(sys.argv[1], newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"{sys.argv[1]}: no rows")
    report = {}
    if len(sys.argv) == 4:
        with open(sys.argv[3]) as f:
            report = json.load(f)
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
    draw_object(ax, report)
    ax.plot(
        [float(r["x_m"]) * 1e3 for r in rows],
        [float(r["y_m"]) * 1e3 for r in rows],
        "b-",
        lw=0.8,
        label="logged tool centre",
    )
    ax.set_aspect("equal")
    frame = report.get("frames", {}).get("log_frame", "?")
    ax.set_title(f"path in the scene frame (mm); log frame {frame}", fontsize=9)
    # Below the panel: the path fills it, so the legend goes under the axes.
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.08), ncol=2)
    for k in range(2):
        ax = fig.add_subplot(3, 4, (7, 8) if k == 0 else (11, 12))
        errs = (
            [
                float(r[f"sim_p{c}_pa"]) - float(r[f"log_p{c}_pa"])
                for r in rows
                for c in (range(1, 5))
            ]
            if k == 0
            else [
                math.log10(max(1.0, float(r[f"sim_p{c}_pa"])))
                - math.log10(max(1.0, float(r[f"log_p{c}_pa"])))
                for r in rows
                for c in range(1, 5)
            ]
        )
        error_histogram(ax, errs, "Pa" if k == 0 else "log10")
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=100)


if __name__ == "__main__":
    main()
