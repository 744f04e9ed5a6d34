#!/usr/bin/env python3
"""Published | twin | difference | smooth surface for `ssc validate` (cells.csv), a row per step.

The fourth panel (when validate fitted one) is the smooth surface's success rate: 6 numbers
fitted to the published classes alone (studies/map_ceiling.h), a robot without the noise of
one 3-trial draw. Where the twin departs from it, physics is missing.
"""

import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.cm import ScalarMappable  # noqa: E402
from matplotlib.colors import BoundaryNorm, ListedColormap, Normalize  # noqa: E402

CLASS_VALUE = {"<=1": 0, "2": 1, "3": 2}


def colour_bar(fig, ax, panel, class_cmap):
    """What the panel's colours mean, beside it."""
    if panel == 0:
        mappable = ScalarMappable(BoundaryNorm([-0.5, 0.5, 1.5, 2.5], 3), class_cmap)
        bar = fig.colorbar(
            mappable, ax=ax, fraction=0.046, pad=0.04, ticks=[0, 1, 2], label="successes of 3"
        )
        bar.ax.set_yticklabels(["<=1", "2", "3"])
    elif panel in (1, 3):
        fig.colorbar(
            ScalarMappable(Normalize(0, 1), plt.cm.RdYlGn),
            ax=ax,
            fraction=0.046,
            pad=0.04,
            label="success rate",
        )
    else:
        fig.colorbar(
            ScalarMappable(Normalize(-3, 3), plt.cm.coolwarm),
            ax=ax,
            fraction=0.046,
            pad=0.04,
            label="twin - published (successes of 3)",
        )


def main(cells_csv, out_png):
    rows = list(csv.DictReader(open(cells_csv)))
    steps = sorted({float(r["step_mm"]) for r in rows})
    surface = any(not math.isnan(float(r.get("surface_p", "nan") or "nan")) for r in rows)
    panels = 4 if surface else 3
    fig, axes = plt.subplots(
        len(steps), panels, figsize=(5.0 * panels, 4.2 * len(steps)), squeeze=False
    )
    cmap = ListedColormap(["#d7301f", "#fdae61", "#1a9850"])
    for si, step in enumerate(steps):
        sub = [r for r in rows if float(r["step_mm"]) == step]
        betas = sorted({float(r["beta"]) for r in sub})
        prefs = sorted({float(r["pref_pa"]) for r in sub})
        grids = [[[None] * len(prefs) for _ in betas] for _ in range(panels)]
        for r in sub:
            i, j = betas.index(float(r["beta"])), prefs.index(float(r["pref_pa"]))
            grids[0][i][j] = CLASS_VALUE[r["published"]]
            grids[1][i][j] = float(r["p_success"])
            grids[2][i][j] = float(r["p_success"]) * 3 - (CLASS_VALUE[r["published"]] + 1)
            if surface:
                grids[3][i][j] = float(r["surface_p"])
        titles = [
            "published (class of 3 trials)",
            "twin: success rate over seeds",
            "twin minus published (expected successes of 3)",
            "smooth surface fitted to the published classes",
        ]
        for k, ax in enumerate(axes[si]):
            for i, _ in enumerate(betas):
                for j, _ in enumerate(prefs):
                    v = grids[k][i][j]
                    if v is None:
                        ax.add_patch(plt.Rectangle((j - 0.5, i - 0.5), 1, 1, color="#eeeeee"))
                        continue
                    if k == 0:
                        color = cmap(v / 2)
                        text = ["<=1", "2", "3"][v]
                    elif k in (1, 3):
                        color = plt.cm.RdYlGn(v)
                        text = f"{v:.1f}"
                    else:
                        color = plt.cm.coolwarm((v + 3) / 6)
                        text = f"{v:+.1f}"
                    ax.add_patch(plt.Rectangle((j - 0.5, i - 0.5), 1, 1, color=color))
                    ax.text(j, i, text, ha="center", va="center", fontsize=10)
                    r = next(
                        x
                        for x in sub
                        if float(x["beta"]) == betas[i] and float(x["pref_pa"]) == prefs[j]
                    )
                    if k == 2 and r["opposite"] == "1":
                        ax.add_patch(
                            plt.Rectangle(
                                (j - 0.45, i - 0.45), 0.9, 0.9, fill=False, lw=2.5, ec="black"
                            )
                        )
                    if k == 1 and r["main_failure"]:
                        ax.text(
                            j,
                            i - 0.32,
                            {"failure_I": "I", "failure_II": "II"}.get(
                                r["main_failure"], r["main_failure"][:2]
                            ),
                            ha="center",
                            va="center",
                            fontsize=7,
                            color="#333333",
                        )
            ax.set_xlim(-0.5, len(prefs) - 0.5)
            ax.set_ylim(-0.5, len(betas) - 0.5)
            ax.set_xticks(range(len(prefs)))
            ax.set_xticklabels([f"{p:g}" for p in prefs])
            ax.set_yticks(range(len(betas)))
            ax.set_yticklabels([f"{b:g}" for b in betas])
            ax.set_xlabel("P_ref (Pa)")
            ax.set_ylabel("beta")
            ax.set_title(f"dL {step:g} mm: {titles[k]}", fontsize=10)
            ax.set_aspect("equal")
            colour_bar(fig, ax, k, cmap)
    fig.text(
        0.5,
        0.005,
        "small letters: the twin's most common failure (I off the edge, II "
        "grasped); black frame: opposite cell",
        ha="center",
        fontsize=9,
    )
    fig.tight_layout(rect=(0, 0.02, 1, 1))
    fig.savefig(out_png, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
