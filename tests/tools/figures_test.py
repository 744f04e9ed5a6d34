"""The figure scripts (tools/plot_*.py) on small synthetic inputs: each renders, and no legend
box overlaps another legend, a text of the figure (titles, labels, tick labels, annotations) or
a data point of a line in its axes, where matplotlib can tell (window extents after drawing).

SSC_FIGURES_DIR=DIR keeps the rendered PNGs there (to look at them).
"""

import csv
import json
import math
import os
import runpy
import shutil
import sys
import tempfile
import unittest

import matplotlib

matplotlib.use("Agg")
import matplotlib.figure  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.environ.get("SSC_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
TOOLS = os.path.join(ROOT, "tools")


def write_csv(path, columns, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(columns)
        w.writerows(rows)
    return path


def legend_problems(fig):
    """Each overlap of a legend box with another legend, a text or a line's data point."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    legends = [ax.get_legend() for ax in fig.axes if ax.get_legend() is not None]
    legends += list(fig.legends)
    boxes = [(leg, leg.get_window_extent(renderer)) for leg in legends if leg.get_visible()]
    problems = []
    for i, (a, box_a) in enumerate(boxes):
        for b, box_b in boxes[i + 1 :]:
            if box_a.overlaps(box_b):
                problems.append("two legends overlap")
    texts = list(fig.texts)
    for ax in fig.axes:
        texts += list(ax.texts) + [
            ax.title,
            ax._left_title,
            ax._right_title,
            ax.xaxis.label,
            ax.yaxis.label,
        ]
        texts += ax.get_xticklabels() + ax.get_yticklabels()
    for leg, box in boxes:
        inner = box.padded(-2)  # touching edges is not covering
        for t in texts:
            if not t.get_visible() or not t.get_text().strip():
                continue
            if inner.overlaps(t.get_window_extent(renderer)):
                problems.append(f"legend over the text {t.get_text()!r}")
        # The legend's own axes and its twins (twinx/twiny: the same place), else all of them.
        if leg.axes is not None and leg.axes in fig.axes:
            place = leg.axes.get_position().bounds
            axes = [ax for ax in fig.axes if ax.get_position().bounds == place]
        else:
            axes = fig.axes
        for ax in axes:
            for line in ax.get_lines():
                xy = np.asarray(line.get_xydata(), dtype=float)
                xy = xy[np.all(np.isfinite(xy), axis=1)]
                if len(xy) == 0 or not line.get_visible():
                    continue
                points = line.get_transform().transform(xy)
                inside = (
                    (points[:, 0] > inner.x0)
                    & (points[:, 0] < inner.x1)
                    & (points[:, 1] > inner.y0)
                    & (points[:, 1] < inner.y1)
                )
                # A line's segments can cross the box between points; points are what
                # matplotlib can tell cheaply, and what a reader loses under a legend.
                if inside.any():
                    problems.append(
                        f"legend over {int(inside.sum())} point(s) of the line {line.get_label()!r}"
                    )
    return problems


def clipped_texts(fig):
    """The titles and labels that run past the figure's edge (cut off in the saved image)."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    canvas = fig.bbox.padded(1)
    texts = list(fig.texts)
    for ax in fig.axes:
        texts += [ax.title, ax._left_title, ax._right_title, ax.xaxis.label, ax.yaxis.label]
    cut = []
    for t in texts:
        if not t.get_visible() or not t.get_text().strip():
            continue
        box = t.get_window_extent(renderer)
        if box.x0 < canvas.x0 or box.x1 > canvas.x1 or box.y0 < canvas.y0 or box.y1 > canvas.y1:
            cut.append(f"the text {t.get_text()[:50]!r} runs past the figure's edge")
    return cut


class FigureScriptsTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="ssc_figures_")
        self.addCleanup(shutil.rmtree, self.tmp, True)
        self.keep = os.environ.get("SSC_FIGURES_DIR")

    def render(self, script, argv):
        """Runs tools/<script> with argv; returns the legend problems of each figure saved."""
        problems = []
        original = matplotlib.figure.Figure.savefig

        def checked_savefig(fig, path, *args, **kwargs):
            problems.extend(legend_problems(fig))
            if kwargs.get("bbox_inches") != "tight":  # a tight box grows to hold every text
                problems.extend(clipped_texts(fig))
            original(fig, path, *args, **kwargs)
            if self.keep:
                os.makedirs(self.keep, exist_ok=True)
                original(
                    fig, os.path.join(self.keep, script.replace(".py", ".png")), *args, **kwargs
                )

        matplotlib.figure.Figure.savefig = checked_savefig
        saved_argv = sys.argv
        sys.argv = [script] + argv
        try:
            runpy.run_path(os.path.join(TOOLS, script), run_name="__main__")
        finally:
            sys.argv = saved_argv
            matplotlib.figure.Figure.savefig = original
            import matplotlib.pyplot as plt

            plt.close("all")
        return problems

    def out(self, name):
        return os.path.join(self.tmp, name)

    def test_probe(self):
        offsets = np.arange(-6, 7.01, 0.25)
        pbar = np.where(offsets < -1, 0.3, np.minimum(25000, 30 * np.exp(np.maximum(0, offsets))))
        # Chambers 1 and 4 equal, 2 and 3 equal: symmetric about a straight edge.
        p14, p23 = pbar * 1.6, pbar * 0.4
        edge = write_csv(
            self.out("edge.csv"),
            [
                "offset_mm",
                "static_pbar_pa",
                "pbar_pa",
                "diff_pa",
                "static_p1_pa",
                "static_p2_pa",
                "static_p3_pa",
                "static_p4_pa",
            ],
            [
                [o, p, p * 1.01, abs(a - b), a, b, b, a]
                for o, p, a, b in zip(offsets, pbar, p14, p23)
            ],
        )
        angles = np.arange(0, 360, 15.0)
        disk = write_csv(
            self.out("disk.csv"),
            ["angle_deg", "travel_world_deg", "offset_mm"],
            [[a, a + 90 + 20 * math.sin(math.radians(4 * a)), 2.5] for a in angles],
        )
        png = self.out("probe.png")
        problems = self.render("plot_probe.py", [edge, disk, png])
        self.assertTrue(os.path.getsize(png) > 0)
        self.assertEqual(problems, [])

    def test_compare(self):
        t = np.arange(0, 12, 0.05)
        on = (t > 2.3) & (t < 4.1)
        log = np.where(on, 25500.0, 50 + 30 * np.sin(t))
        sim = log * (1 + 0.03 * np.sin(7 * t)) + 5 * np.cos(3 * t)
        sim[np.argmax(on)] += 3000  # one large error at the touch-down: a long histogram tail
        angle = np.clip(t - 4.1, 0, None)
        x = 0.65 + np.where(t < 4.1, 0.0, 0.033 * np.cos(angle))
        y = np.where(t < 4.1, 0.0, 0.033 * np.sin(angle))
        cols = (
            ["t_s", "x_m", "y_m"]
            + [f"log_p{k}_pa" for k in range(1, 5)]
            + [f"sim_p{k}_pa" for k in range(1, 5)]
        )
        series = write_csv(
            self.out("series.csv"),
            cols,
            [[a, b, c] + [d] * 4 + [e] * 4 for a, b, c, d, e in zip(t, x, y, log, sim)],
        )
        report = self.out("report.json")
        with open(report, "w") as f:
            json.dump(
                {
                    "frames": {
                        "log_frame": "base_link",
                        "scene_object": {
                            "name": "disk",
                            "x_m": 0.65,
                            "y_m": 0.0,
                            "radius_m": 0.035,
                        },
                        "closest_approach_mm": 0.4,
                        "closest_approach_t_s": 2.4,
                        "closest_approach_tcp_m": [0.65, 0.0, 0.131],
                    }
                },
                f,
            )
        png = self.out("compare.png")
        self.assertEqual(self.render("plot_compare.py", [series, png, report]), [])

    def test_speed_accuracy(self):
        rows = []
        for pref in (70, 100, 200):
            for beta in (1, 2, 3):
                for step in (2.5, 5, 7.5, 10, 12.5):
                    for rep in range(3):
                        ok = (step < 10 or beta == 2) and (rep + beta + step) % 4 != 0
                        rows.append(
                            [
                                pref,
                                beta,
                                step,
                                "success" if ok else "failure_I",
                                4 * step + rep * 0.3 + beta * 0.2,
                                2 + 0.1 * beta + 0.002 * pref + 0.02 * step,
                            ]
                        )
        cup = write_csv(
            self.out("cup.csv"),
            ["pref_pa", "beta", "step_mm", "outcome", "speed_mm_s", "contour_mean_mm"],
            rows,
        )
        names = [
            "1 rays",
            "2 rays",
            "8 rays",
            "16 rays",
            "40 Hz sensor",
            "80 Hz sensor",
            "320 Hz sensor",
            "0.5 ms step",
            "1.0 ms step",
            "4.0 ms step",
            "8.0 ms step",
            "8 lip segments",
            "32 lip segments",
            "64 lip segments",
            "Euler",
            "RK4",
            "gantry scene vs arm",
            "arm scene (UR-10)",
            "reference",
            "default",
        ]
        sim_rows = [
            [
                n,
                0.01 * (1.3 ** (i % 7)),
                0.05 * (1 + 0.02 * i) if i % 3 else 0.3 / (i + 1),
                1 if n == "default" else 0,
            ]
            for i, n in enumerate(names)
        ]
        sim = write_csv(
            self.out("sim.csv"),
            ["setting", "wall_per_sim_s", "rms_log10_vs_reference", "is_default"],
            sim_rows,
        )
        png = self.out("speed_accuracy.png")
        self.assertEqual(self.render("plot_speed_accuracy.py", [cup, sim, png]), [])

    def test_tune(self):
        cols = [
            "label",
            "controller",
            "step_max_mm",
            "trials",
            "successes",
            "success_rate",
            "success_lo",
            "success_hi",
            "speed_mm_s",
            "speed_ci_mm_s",
            "score",
            "pareto",
        ]
        rows = [["published", "published", "", 6, 5, 0.83, 0.44, 0.97, 30.6, 0.4, 15, 0]]
        for k in range(12):
            ok = 6 - k // 2
            rows.append(
                [
                    f"eval {k + 1}",
                    "fast",
                    7 + k,
                    6,
                    ok,
                    ok / 6,
                    max(0, ok / 6 - 0.3),
                    min(1, ok / 6 + 0.2),
                    35 + 1.5 * k,
                    0.8,
                    35 - 20 * k,
                    int(k % 3 == 0),
                ]
            )
        table = write_csv(self.out("tune.csv"), cols, rows)
        png = self.out("pareto.png")
        self.assertEqual(self.render("plot_tune.py", [table, png, "0.9"]), [])
        self.assertTrue(os.path.getsize(png) > 0)

    def test_validation_has_colour_bars(self):
        rows = []
        for step in (5.0,):
            for beta in (0, 1, 2, 3):
                for pref in (40, 70, 100, 200):
                    p = min(1.0, 0.2 * beta + pref / 400)
                    rows.append(
                        [
                            step,
                            beta,
                            pref,
                            ["<=1", "2", "3"][int(p * 2.99)],
                            p,
                            1 if p < 0.2 and beta > 2 else 0,
                            "failure_I" if p < 1 else "",
                            p * 0.9,
                        ]
                    )
        cells = write_csv(
            self.out("cells.csv"),
            [
                "step_mm",
                "beta",
                "pref_pa",
                "published",
                "p_success",
                "opposite",
                "main_failure",
                "surface_p",
            ],
            rows,
        )
        png = self.out("validate.png")
        captured = []
        original = matplotlib.figure.Figure.colorbar

        def counting_colorbar(fig, *args, **kwargs):
            captured.append(kwargs.get("label", ""))
            return original(fig, *args, **kwargs)

        matplotlib.figure.Figure.colorbar = counting_colorbar
        try:
            self.assertEqual(self.render("plot_validation.py", [cells, png]), [])
        finally:
            matplotlib.figure.Figure.colorbar = original
        self.assertEqual(len(captured), 4, captured)  # one per panel: what each colour means

    def test_trajectories_name_the_trials_not_their_folders(self):
        paths = []
        for k, step in enumerate((2.5, 7.5)):
            folder = os.path.join(self.tmp, f"out_{k}")
            os.makedirs(folder)
            a = np.linspace(0, 2 * math.pi, 200)
            write_csv(
                os.path.join(folder, "trial.csv"),
                ["t_s", "x_m", "y_m", "pbar_pa", "iteration", "phase"],
                [
                    [
                        i * 0.1,
                        0.65 + 0.033 * math.cos(v),
                        0.033 * math.sin(v),
                        100 if i % 5 == 0 else "nan",
                        1 if i % 5 == 0 else 0,
                        "follow",
                    ]
                    for i, v in enumerate(a)
                ],
            )
            with open(os.path.join(folder, "summary.json"), "w") as f:
                json.dump(
                    {
                        "outcome": "success",
                        "seed": 1,
                        "parameters": {"pref_pa": 100, "beta": 2, "step_mm": step},
                    },
                    f,
                )
            paths.append(os.path.join(folder, "trial.csv"))
        png = self.out("trajectory.png")
        labels = []
        original = matplotlib.figure.Figure.savefig

        def grab(fig, path, *args, **kwargs):
            for ax in fig.axes:
                if ax.get_legend():
                    labels.extend(t.get_text() for t in ax.get_legend().get_texts())
            original(fig, path, *args, **kwargs)

        matplotlib.figure.Figure.savefig = grab
        try:
            problems = self.render("plot_trajectories.py", [png] + paths)
        finally:
            matplotlib.figure.Figure.savefig = original
        self.assertEqual(problems, [])
        self.assertFalse(any("out_" in s for s in labels), labels)
        self.assertTrue(any("7.5" in s for s in labels), labels)

    def test_success_maps(self):
        rows = [
            [step, pref, beta, ["success", "failure_I", "failure_II"][(k + int(beta)) % 3]]
            for step in (2.5, 5, 7.5)
            for pref in (40, 100, 300)
            for beta in (0, 1, 2)
            for k in range(3)
        ]
        sweep = write_csv(self.out("sweep.csv"), ["step_mm", "pref_pa", "beta", "outcome"], rows)
        self.assertEqual(self.render("plot_success_maps.py", [sweep, self.out("maps.png")]), [])

    def test_objects_and_the_fillet_profile(self):
        """`ssc objects`: the paths over each object and, beside the table, the fillet's profile
        (plot_objects.py writes both: OUT.png and OUT_fillet.png)."""
        paths = self.out("paths")
        os.makedirs(paths)
        rows = []
        for k, (name, closed, outcome) in enumerate(
            [
                ("disk_d10", 1, "success"),
                ("hole_d10", 1, "failure_I"),
                ("corner_a090", 0, "lost_edge"),
            ]
        ):
            n = 40
            contour = [
                (
                    0.65 + 0.005 * math.cos(2 * math.pi * i / n),
                    0.005 * math.sin(2 * math.pi * i / n),
                    closed,
                )
                for i in range(n)
            ]
            write_csv(os.path.join(paths, name + "_contour.csv"), ["x_m", "y_m", "closed"], contour)
            path = [
                (0.65 + 0.008 * math.cos(0.1 * i), 0.008 * math.sin(0.1 * i))
                for i in range(30 + 10 * k)
            ]
            write_csv(os.path.join(paths, name + "_s1.csv"), ["x_m", "y_m"], path)
            rows.append([name, 1, outcome])
        table = write_csv(self.out("objects.csv"), ["object", "seed", "outcome"], rows)
        # Along a 60 mm edge whose fillet grows from 0 to 10 mm: the differential fades, the mean
        # vacuum rises a little.
        profile = [(x, 40 * math.exp(-x / 20), 100 + 0.3 * x, x / 6) for x in range(0, 61, 2)]
        write_csv(
            self.out("fillet_profile.csv"),
            ["x_mm", "diff_pa", "pbar_pa", "fillet_radius_mm"],
            profile,
        )
        png = self.out("objects.png")
        self.assertEqual(self.render("plot_objects.py", [table, paths, png]), [])
        # One object: the narrowest figure, where the title was cut at both edges.
        one = write_csv(self.out("one.csv"), ["object", "seed", "outcome"], rows[:1])
        self.assertEqual(self.render("plot_objects.py", [one, paths, self.out("one.png")]), [])
        self.assertTrue(os.path.exists(png))
        self.assertTrue(os.path.exists(self.out("objects_fillet.png")))


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
