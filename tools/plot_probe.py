#!/usr/bin/env python3
"""Plot `ssc probe` output: the calibration view of the chamber-pressure sensor.

usage: plot_probe.py edge.csv disk.csv out.png [DEPTHS]

DEPTHS: the published depths to mark, "mm:Pa,mm:Pa,..." (`ssc probe` passes them from
calibration/published_targets.h); none marked when absent.
"""

import csv
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


def same_curve(a, b, rel=1e-3):
    """Whether two chambers' curves coincide (within `rel` of the larger value, or 1e-6 Pa)."""
    return all(abs(x - y) <= rel * max(abs(x), abs(y)) + 1e-6 for x, y in zip(a, b))


def main():
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    edge, disk, out = read(sys.argv[1]), read(sys.argv[2]), sys.argv[3]
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.5))

    # Mean pressure and chambers across the straight edge (log axis), calibration targets.
    a = ax[0]
    off = edge["offset_mm"]
    floor = 0.1
    a.semilogy(
        off, [max(v, floor) for v in edge["static_pbar_pa"]], "k-", lw=2, label="mean P (noiseless)"
    )
    a.semilogy(
        off, [max(v, floor) for v in edge["pbar_pa"]], "k.", ms=4, label="mean P (sensor output)"
    )
    # Chambers that read the same (a straight edge is symmetric: 1 = 4 and 2 = 3 when the edge
    # runs along the tool's x axis) share one line and one legend entry, so none hides another.
    shown = []
    for c in range(1, 5):
        values = edge[f"static_p{c}_pa"]
        twin = next((g for g in shown if same_curve(values, edge[f"static_p{g[0]}_pa"])), None)
        if twin:
            twin.append(c)
        else:
            shown.append([c])
    for group, col in zip(shown, ["C0", "C1", "C2", "C3"]):
        label = ("chamber " if len(group) == 1 else "chambers ") + " = ".join(map(str, group))
        a.semilogy(
            off,
            [max(v, floor) for v in edge[f"static_p{group[0]}_pa"]],
            "-",
            color=col,
            lw=1,
            label=label,
        )
    targets = [
        tuple(float(v) for v in item.split(":"))
        for item in (sys.argv[4].split(",") if len(sys.argv) == 5 else [])
    ]
    if targets:
        a.errorbar(
            [t[0] for t in targets],
            [t[1] for t in targets],
            xerr=0.3,
            fmt="rs",
            label="published disk results (+-0.3 mm)",
        )
    a.axhline(10000, color="r", ls=":", lw=1)
    a.text(off[0], 11000, "grasp 10 kPa", color="r", fontsize=8, va="bottom")
    a.set_xlabel("cup centre inside the edge (mm)")
    a.set_ylabel("vacuum (Pa)")
    a.set_title("straight edge: pressures")
    a.legend(fontsize=7, loc="lower right")  # the lines rise to the right: that corner is free
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
