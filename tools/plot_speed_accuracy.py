#!/usr/bin/env python3
"""Speed against accuracy: the cup (from a sweep over step length) and the simulator.

usage: plot_speed_accuracy.py cup.csv simulator.csv out.png
"""

import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


# What a simulator setting changes (its colour in the cost-fidelity panel), in legend order.
KIND_COLOURS = {
    "default": "red",
    "reference": "black",
    "rays": "C0",
    "sensor": "C1",
    "step": "C2",
    "lip": "C4",
    "integrator": "C5",
    "scene": "C6",
    "other": "C7",
}
MARKERS = ["o", "s", "^", "D", "v", "P", "X"]


def setting_kind(name, is_default):
    if is_default or name.startswith("default"):
        return "default"
    for kind, words in (
        ("reference", ["reference"]),
        ("rays", ["rays"]),
        ("sensor", ["Hz"]),
        ("step", ["ms step"]),
        ("lip", ["lip segments"]),
        ("integrator", ["Euler", "RK4", "implicit"]),
        ("scene", ["scene"]),
    ):
        if any(w in name for w in words):
            return kind
    return "other"


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    with open(sys.argv[1], newline="") as f:
        cup = list(csv.DictReader(f))
    with open(sys.argv[2], newline="") as f:
        sim = list(csv.DictReader(f))
    groups = defaultdict(list)
    for r in cup:
        groups[(float(r["pref_pa"]), float(r["beta"]))].append(r)
    fig, ax = plt.subplots(
        1, 3, figsize=(19, 5.2), gridspec_kw={"width_ratios": [1, 1, 1.05], "right": 0.82}
    )
    points = []
    for (pref, beta), rows in sorted(groups.items()):
        steps = sorted({float(r["step_mm"]) for r in rows})
        speed, rate, err = [], [], []
        for s in steps:
            rs = [r for r in rows if float(r["step_mm"]) == s]
            ok = [r for r in rs if r["outcome"] == "success"]
            rate.append(len(ok) / len(rs))
            v = [float(r["speed_mm_s"]) for r in rs if float(r["speed_mm_s"]) > 0]
            speed.append(sum(v) / len(v) if v else 0)
            e = [float(r["contour_mean_mm"]) for r in ok]
            err.append(sum(e) / len(e) if e else float("nan"))
            if ok:
                points.append((speed[-1], err[-1], f"{pref:g}/{beta:g}/{s:g}"))
        label = f"P_ref {pref:g}, beta {beta:g}"
        ax[0].plot(speed, rate, "o-", label=label)
        ax[1].plot(speed, err, "o-", label=label)
    # Pareto front: no other point both faster and more accurate.
    front = sorted(
        [p for p in points if not any(q[0] >= p[0] and q[1] <= p[1] and q != p for q in points)]
    )
    ax[1].plot([p[0] for p in front], [p[1] for p in front], "k--", lw=2, label="Pareto front")
    # Published robot: ~10, 20, 30 mm/s at P_ref 100, beta 2 (success 3/3); its cup centre rode
    # 2.5 mm inside the edge (dr = -2.5 mm at P_ref 100).
    ax[1].plot([10, 20, 30], [2.5, 2.5, 2.5], "r*", ms=14, label="robot (published, |dr|)")
    ax[0].plot([10, 20, 30], [1, 1, 1], "r*", ms=14, label="robot 3/3 (P_ref 100, beta 2)")
    for a, title, ylabel in (
        (ax[0], "success rate vs speed", "success rate"),
        (ax[1], "tracking error vs speed", "mean distance from the edge (mm)"),
    ):
        a.set_xlabel("mean speed (mm/s)")
        a.set_ylabel(ylabel)
        a.set_title(title)
        a.grid(True, alpha=0.3)
    # One legend for both panels, under them: inside either it would cover lines.
    handles, labels = {}, []
    for a in ax[:2]:
        for h, lab in zip(*a.get_legend_handles_labels()):
            if lab not in handles:
                handles[lab] = h
                labels.append(lab)
    fig.legend(
        [handles[lab] for lab in labels],
        labels,
        loc="upper center",
        fontsize=8,
        ncol=4,
        bbox_to_anchor=(0.3, 0.0),
        frameon=False,
    )
    # Simulator settings: many sit on nearly the same point, so each has its own marker (colour:
    # what the setting changes; shape: which value) and the legend beside the axes names it.
    a = ax[2]
    kind_of = {}
    for r in sim:
        kind_of[r["setting"]] = setting_kind(r["setting"], r["is_default"] == "1")
    kinds = sorted(set(kind_of.values()), key=list(KIND_COLOURS).index)
    used = {k: 0 for k in kinds}
    rows = sorted(
        sim, key=lambda r: (kinds.index(kind_of[r["setting"]]), -float(r["rms_log10_vs_reference"]))
    )
    for r in rows:
        x, y = float(r["wall_per_sim_s"]), max(float(r["rms_log10_vs_reference"]), 1e-4)
        kind = kind_of[r["setting"]]
        marker = MARKERS[used[kind] % len(MARKERS)]
        used[kind] += 1
        is_default = kind == "default"
        a.plot(
            x,
            y,
            marker,
            ms=11 if is_default else 7,
            color=KIND_COLOURS[kind],
            mec="black" if is_default else "none",
            zorder=4 if is_default else 3,
            alpha=0.9,
            label=r["setting"],
            ls="none",
        )
    a.legend(
        loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=7.5, frameon=False, borderaxespad=0
    )
    a.set_xscale("log")
    a.set_yscale("log")
    a.set_xlabel("wall time per simulated second (s)")
    a.set_ylabel("pressure error vs reference (RMS log10)")
    a.set_title("simulator: cost vs pressure error (red: default)")
    a.grid(True, which="both", alpha=0.3)
    fig.tight_layout(rect=(0, 0.04, 0.83, 1))
    fig.savefig(sys.argv[3], dpi=100, bbox_inches="tight")


if __name__ == "__main__":
    main()
