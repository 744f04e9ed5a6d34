"""tools/objects_table.py on small synthetic objects.csv files: rows of one object gathered over
files and sorted by seed, outcome counts, mean +- sd of where the trials ended (mm along the
edge, degrees swept, the fillet's radius), the other tier beside, and a file that is not an
objects.csv refused."""

import contextlib
import csv
import io
import os
import sys
import tempfile
import unittest

ROOT = os.environ.get("SSC_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import objects_table  # noqa: E402

COLUMNS = [
    "object",
    "kind",
    "seed",
    "outcome",
    "end_arc_mm",
    "end_swept_deg",
    "end_fillet_radius_mm",
    "detail",
]


def write(path, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        w.writerows(rows)
    return path


def run(argv):
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        objects_table.main(argv)
    return out.getvalue().splitlines()


class ObjectsTableTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        d = self.dir.name
        self.seed2 = write(
            os.path.join(d, "s2.csv"),
            [
                ["corner_a270", "corner", 2, "success", 83.2, 0, -1, ""],
                ["fillet", "fillet", 2, "lost_edge", 140.0, 0, 14.8, ""],
            ],
        )
        self.seed1 = write(
            os.path.join(d, "s1.csv"),
            [
                ["corner_a270", "corner", 1, "lost_edge", 60.0, 0, -1, ""],
                ["fillet", "fillet", 1, "lost_edge", 130.0, 0, 14.4, ""],
                ["hole_d02", "hole", 1, "success", -1, -400.0, -1, ""],
            ],
        )
        self.other = write(
            os.path.join(d, "g.csv"),
            [
                ["fillet", "fillet", 1, "success", 170.2, 0, 15.7, ""],
            ],
        )

    def tearDown(self):
        self.dir.cleanup()

    def test_rows_over_files_with_counts_and_spread(self):
        lines = run([self.seed2, self.seed1])
        rows = {line.split(" | ")[0].lstrip("| "): line for line in lines[2:]}
        self.assertEqual(list(rows), ["corner_a270", "fillet", "hole_d02"])
        self.assertIn("`lost_edge` 1/2, `success` 1/2", rows["corner_a270"])
        # Per-seed values in seed order (seed 1 first though read second).
        self.assertIn("71.6 ± 16.4 mm (60.0, 83.2)", rows["corner_a270"])
        self.assertIn("135.0 ± 7.1 mm (130.0, 140.0); radius 14.60 ± 0.28 mm", rows["fillet"])
        self.assertIn("| 1 | `success` | -400.0 deg |", rows["hole_d02"])

    def test_the_other_tier_beside(self):
        lines = run([self.seed1, "--against", self.other, "--against-label", "gantry"])
        self.assertIn("gantry: outcome", lines[0])
        fillet = next(line for line in lines if line.startswith("| fillet"))
        self.assertTrue(fillet.endswith("| `success` | 170.2 mm; radius 15.70 mm |"), fillet)
        hole = next(line for line in lines if line.startswith("| hole_d02"))
        self.assertIn("not run", hole)

    def test_only_the_objects_named_by_prefix(self):
        lines = run([self.seed1, "--only", "corner_,hole"])
        self.assertEqual(
            [line.split(" | ")[0] for line in lines[2:]], ["| corner_a270", "| hole_d02"]
        )

    def test_the_t_interval_of_the_mean_end(self):
        d = self.dir.name
        path = write(
            os.path.join(d, "f.csv"),
            [
                ["fillet", "fillet", k, "lost_edge", end, 0, 14.0, ""]
                for k, end in [(1, 130.0), (2, 140.0), (3, 150.0)]
            ],
        )
        fillet = run([path, "--interval"])[2]
        # mean 140, sd 10, t(0.975, 2) 4.303: 140 +- 24.8
        self.assertIn("140.0 ± 10.0 mm (130.0, 140.0, 150.0), 95 % t interval 115.2–164.8", fillet)
        self.assertNotIn("t interval", run([self.seed2, self.seed1, "--interval"])[2])

    def test_where_the_tiers_disagree(self):
        d = self.dir.name
        flex = write(
            os.path.join(d, "flex.csv"),
            [["fillet", "fillet", k, "lost_edge", 140.0 + k, 0, 14.0, ""] for k in (1, 2, 3)]
            + [
                ["corner_a030", "corner", k, "lost_edge", 34.0 + 0.1 * k, 0, -1, ""]
                for k in (1, 2, 3)
            ]
            + [["corner_a015", "corner", k, "lost_edge", 5.0 + k, 0, -1, ""] for k in (1, 2, 3)]
            + [["hole_d02", "hole", k, "success", -1, -400.0, -1, ""] for k in (1, 2, 3)]
            + [["disk_d02", "disk", k, "failure_I", -1, 1.0, -1, ""] for k in (1, 2)]
            + [["disk_d02", "disk", 3, "lost_edge", -1, -130.0, -1, ""]],
        )
        gantry = [
            write(
                os.path.join(d, f"g{k}.csv"),
                [
                    ["fillet", "fillet", k, "success", 170.0, 0, 15.7, ""],
                    ["corner_a030", "corner", k, "lost_edge", 34.5 + 0.1 * k, 0, -1, ""],
                    ["corner_a015", "corner", k, "lost_edge", 1.0 + 0.1 * k, 0, -1, ""],
                    ["hole_d02", "hole", k, "success", -1, -380.0, -1, ""],
                    [
                        "disk_d02",
                        "disk",
                        k,
                        "lost_edge" if k == 3 else "failure_I",
                        -1,
                        170.0,
                        -1,
                        "",
                    ],
                ],
            )
            for k in (1, 2, 3)
        ]
        argv = [flex, "--disagree"] + sum((["--against", g] for g in gantry), [])
        rows = {line.split(" | ")[0].lstrip("| "): line for line in run(argv)[2:]}
        self.assertIn("**disagree**: outcome", rows["fillet"])
        self.assertTrue(rows["corner_a030"].endswith("| agree |"))  # 0.4 mm apart
        self.assertIn("**disagree**: end (+5.8", rows["corner_a015"])
        self.assertTrue(rows["hole_d02"].endswith("| agree |"))  # all success
        self.assertIn("| 3 / 3 |", rows["hole_d02"])
        # failure_I ends are the landing's; one followed trial a tier gives no interval
        self.assertTrue(rows["disk_d02"].endswith("| agree |"), rows["disk_d02"])
        with self.assertRaises(SystemExit):
            run([flex, "--disagree"])

    def test_fillet_profile_per_stretch_over_seeds(self):
        d = self.dir.name
        paths = []
        for k, (diff, end) in enumerate([(200.0, 140.0), (180.0, 120.0)]):
            path = os.path.join(d, f"profile{k}.csv")
            with open(path, "w", newline="") as f:
                w = csv.writer(f)
                w.writerow(["x_mm", "fillet_radius_mm", "pbar_pa", "diff_pa", "y_mm"])
                x = 10.0
                while x <= end:
                    # |dP| falls by 1 Pa per mm along the edge from `diff` at 10 mm
                    w.writerow([x, x / 10, 100.0, diff - (x - 10), 3.0])
                    x += 1.0
            paths.append(path)
        lines = run(["--fillet-profile"] + paths)
        first = next(line for line in lines if line.startswith("| 10–40 "))
        # seed means over 10..39 mm: 185.5 and 165.5 Pa
        self.assertIn("| 2 | 2.5 ± 0.0 | 100 ± 0 | 176 ± 14 |", first)
        late = next(line for line in lines if line.startswith("| 130–160 "))
        self.assertIn("| 1 |", late)  # the second seed ended at 120 mm
        start = next(line for line in lines if line.startswith("| the first 10"))
        # 10..19 mm: |dP| 200..191 and 180..171 Pa
        self.assertIn("| 2 | 1.4 ± 0.0 | 100 ± 0 | 186 ± 14 |", start)
        last = next(line for line in lines if line.startswith("| the last 10"))
        # the last 10 mm before each end: 130..140 and 110..120 mm, |dP| 80..70 Pa in both
        self.assertIn("| 2 | 12.5 ± 1.4 | 100 ± 0 | 75 ± 0 |", last)

    def test_a_file_that_is_not_an_objects_csv_is_refused(self):
        bad = os.path.join(self.dir.name, "bad.csv")
        with open(bad, "w") as f:
            f.write("x_m,y_m\n1,2\n")
        with self.assertRaises(SystemExit) as e:
            run([bad])
        self.assertIn("not an objects.csv", str(e.exception.code))


if __name__ == "__main__":
    unittest.main()
