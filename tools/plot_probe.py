#!/usr/bin/env python3
"""Plot `ssc probe` output: the calibration view of the chamber-pressure sensor.

usage: plot_probe.py edge.csv disk.csv out.png
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"{path}: no rows")
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    edge, disk, out = read(sys.argv[1]), read(sys.argv[2]), sys.argv[3]
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.5))

    # Mean pressure and chambers across the straight edge (log axis), calibration targets.
    a = ax[0]
    off = edge["offset_mm"]
    floor = 0.1
    a.semilogy(off, [max(v, floor) for v in edge["static_pbar_pa"]], "k-", lw=2,
               label="mean P (noiseless)")
    a.semilogy(off, [max(v, floor) for v in edge["pbar_pa"]], "k.", ms=4,
               label="mean P (sensor output)")
    for c, col in zip(range(1, 5), ["C0", "C1", "C2", "C3"]):
        a.semilogy(off, [max(v, floor) for v in edge[f"static_p{c}_pa"]], "-", color=col,
                   lw=1, label=f"chamber {c}")
    targets = [(0.7, 40), (2.5, 100), (3.2, 200)]
    a.errorbar([t[0] for t in targets], [t[1] for t in targets], xerr=0.3, fmt="rs",
               label="published disk results (+-0.3 mm)")
    a.axhline(10000, color="r", ls=":", lw=1)
    a.text(off[0], 11000, "grasp 10 kPa", color="r", fontsize=8)
    a.set_xlabel("cup centre inside the edge (mm)")
    a.set_ylabel("vacuum (Pa)")
    a.set_title("straight edge: pressures")
    a.legend(fontsize=7, loc="upper left")
    a.grid(True, which="both", alpha=0.3)

    # Differential magnitude across the edge.
    a = ax[1]
    a.plot(off, edge["diff_pa"], "b-", label="|(dPx, dPy)| sensor output")
    a.plot(off, edge["pbar_pa"], "k--", lw=1, label="mean P")
    a.axhspan(150, 250, color="g", alpha=0.15, label="published ~200 Pa at mean 100 Pa")
    a.set_xlim(-1, 4.5)
    a.set_ylim(0, 800)
    a.set_xlabel("cup centre inside the edge (mm)")
    a.set_ylabel("Pa")
    a.set_title("straight edge: differential")
    a.legend(fontsize=7)
    a.grid(True, alpha=0.3)

    # Direction error around the disk.
    a = ax[2]
    ang = disk["angle_deg"]
    err = [((t - (g + 90) + 180) % 360) - 180 for t, g in zip(disk["travel_world_deg"], ang)]
    a.plot(ang, err, "o-")
    a.axhline(0, color="k", lw=0.5)
    a.set_xlabel("position around the disk (deg)")
    a.set_ylabel("travel direction - CCW tangent (deg)")
    inset = disk["offset_mm"][0]
    a.set_title(f"35 mm disk, cup {inset:.1f} mm inside the edge")
    a.grid(True, alpha=0.3)

    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
