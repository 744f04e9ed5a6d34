#!/usr/bin/env python3
"""Trajectories over every test object (cup to scale) and the fillet's pressure profile.

usage: plot_objects.py objects.csv paths_dir out.png
       (written by `ssc objects`; also writes out_fillet.png when fillet_profile.csv exists)
"""

import csv
import math
import os
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

OPENING_MM, BODY_MM = 11.0, 23.0
COLOURS = {
    "success": "tab:green",
    "failure_I": "tab:orange",
    "failure_II": "tab:red",
    "timeout": "tab:purple",
    "unstable": "black",
    "lost_edge": "tab:brown",
    "stalled": "tab:pink",
}


def read_xy(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return [float(r["x_m"]) * 1e3 for r in rows], [float(r["y_m"]) * 1e3 for r in rows], rows


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    table, paths_dir, out = sys.argv[1:]
    with open(table, newline="") as f:
        rows = list(csv.DictReader(f))
    first = {}
    for r in rows:
        first.setdefault(r["object"], r)
    names = list(first)
    cols = min(7, len(names))
    nrows = math.ceil(len(names) / cols)
    fig, axes = plt.subplots(nrows, cols, figsize=(2.8 * cols, 2.9 * nrows), squeeze=False)
    for ax in axes.flat:
        ax.axis("off")
    for ax, name in zip(axes.flat, names):
        r = first[name]
        cx, cy, crows = read_xy(os.path.join(paths_dir, name + "_contour.csv"))
        if crows and crows[0]["closed"] == "1":
            cx.append(cx[0])
            cy.append(cy[0])
        ax.axis("on")
        ax.plot(cx, cy, "k-", lw=1.2)
        path = os.path.join(paths_dir, f"{name}_s{r['seed']}.csv")
        if os.path.exists(path):
            px, py, _ = read_xy(path)
            if px:
                colour = COLOURS.get(r["outcome"], "blue")
                ax.plot(px, py, "-", color=colour, lw=1)
                for d, ls in ((OPENING_MM, "-"), (BODY_MM, "--")):
                    ax.add_patch(
                        plt.Circle((px[0], py[0]), d / 2, fill=False, ls=ls, lw=0.6, color=colour)
                    )
                xs, ys = cx + px, cy + py
            else:
                xs, ys = cx, cy
        else:
            xs, ys = cx, cy
        span = max(max(xs) - min(xs), max(ys) - min(ys), 30) / 2 + 8
        mx, my = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
        ax.set_xlim(mx - span, mx + span)
        ax.set_ylim(my - span, my + span)
        ax.set_aspect("equal")
        # Axes in world mm (the workspace centre W is at 650, 0) and a 10 mm scale bar.
        ax.tick_params(labelsize=6, length=2, pad=1)
        ax.locator_params(nbins=4)
        bx, by = mx - span + 0.08 * 2 * span, my - span + 0.08 * 2 * span
        ax.plot([bx, bx + 10], [by, by], "k-", lw=2.5, solid_capstyle="butt")
        ax.text(bx + 5, by + 0.03 * 2 * span, "10 mm", ha="center", va="bottom", fontsize=6)
        ax.set_title(f"{name}: {r['outcome']}", fontsize=8)
    # The title wrapped to the figure's width (one object makes a narrow figure), with room
    # for its lines above the first row.
    title = textwrap.wrap(
        "cup-centre paths over the test objects (P_ref 100 Pa, beta 2, dL 0.5 "
        "mm); axes: world x, y (mm); circles: 11 mm opening and 23 mm body at "
        "the start",
        width=max(20, int(fig.get_figwidth() * 72 / 10 / 0.6)),
    )
    fig.suptitle("\n".join(title), fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 1 - (0.2 * len(title) + 0.1) / fig.get_figheight()))
    fig.savefig(out, dpi=90)

    profile = os.path.join(os.path.dirname(table), "fillet_profile.csv")
    if os.path.exists(profile):
        with open(profile, newline="") as f:
            prow = list(csv.DictReader(f))
        x = [float(p["x_mm"]) for p in prow]
        fig, ax = plt.subplots(figsize=(7, 3.5))
        ax.plot(x, [float(p["diff_pa"]) for p in prow], "b-", label="|(dPx, dPy)| (Pa)")
        ax.plot(x, [float(p["pbar_pa"]) for p in prow], "k-", lw=1, label="mean P (Pa)")
        ax.set_xlabel("position along the edge from the sharp end (mm)")
        ax.set_ylabel("Pa")
        ax2 = ax.twinx()
        ax2.plot(x, [float(p["fillet_radius_mm"]) for p in prow], "r--", label="fillet radius")
        ax2.set_ylabel("fillet radius (mm)", color="r")
        ax.legend(loc="upper left", fontsize=8)
        ax.set_title("variable fillet: differential and mean pressure along the edge")
        ax.grid(True, alpha=0.3)
        fig.tight_layout()
        fig.savefig(out.replace(".png", "_fillet.png"), dpi=100)


if __name__ == "__main__":
    main()
