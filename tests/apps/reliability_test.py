"""Reliability of the command line against its own outputs and the data options act on: sweeps
that trust no row on resume and run one at a time per folder, writes that fail whole (a file-size
limit, SIGTERM), scenes with non-finite numbers or a FIFO include, maps that are not text, and
compare options checked against the log. Each case ends quickly with a clear message or the
right result; nothing is left behind."""

import csv
import glob
import io
import json
import math
import os
import resource
import shutil
import signal
import subprocess
import tempfile
import time
import unittest

BIN = os.environ.get(
    "SSC_BIN_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "build", "bin")
)
SRC = os.path.abspath(
    os.environ.get("SSC_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
)
SSC = os.path.abspath(os.path.join(BIN, "ssc"))
# Short trials: the follow phase is cut at 1 s simulated (rows still whole trials).
SWEEP = [
    "sweep",
    "--pref",
    "100",
    "--beta",
    "2",
    "--step",
    "7.5",
    "--timeout",
    "1",
    "--threads",
    "1",
    "--no-plot",
    "--no-progress",
]


def run(args, timeout=120, **kw):
    return subprocess.run([SSC] + args, capture_output=True, text=True, timeout=timeout, **kw)


def rows(csv_path):
    with open(csv_path) as f:
        return list(csv.DictReader(f))


def leftovers(folder):
    return [
        p
        for p in glob.glob(os.path.join(folder, "**", "*"), recursive=True)
        if ".tmp" in os.path.basename(p) or p.endswith(".lock")
    ]


class ReliabilityTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="ssc_reliability_")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def scene_with(self, old, new, name):
        """A copy of the gantry scene in the test's folder with one change; its parts and models
        by absolute path."""
        with open(os.path.join(SRC, "scenes", "disk_benchmark_gantry.xml")) as f:
            xml = f.read()
        self.assertIn(old, xml)
        xml = xml.replace(old, new, 1)
        xml = xml.replace('file="parts/', 'file="%s/scenes/parts/' % SRC)
        xml = xml.replace('file="../models/', 'file="%s/models/' % SRC)
        path = os.path.join(self.tmp, f"scene_{name}.xml")
        with open(path, "w") as f:
            f.write(xml)
        return path

    # Sweeps trust no row.

    def test_resume_reruns_edited_duplicated_and_impossible_rows(self):
        out = os.path.join(self.tmp, "resume")
        r = run(SWEEP + ["--repeats", "2", "--out", out])
        self.assertEqual(r.returncode, 0, r.stderr)
        path = os.path.join(out, "sweep.csv")
        with open(path) as f:
            header, row1, row2 = f.read().splitlines()
        good = rows(path)
        f1, f2 = row1.split(","), row2.split(",")
        edited_seed = ",".join(f1[:5] + [str(int(f1[5]) + 1)] + f1[6:])
        nan_success = ",".join(f2[:6] + ["success", "nan"] + f2[8:])
        with open(path, "w") as f:
            f.write("\n".join([header, edited_seed, nan_success, row2, row2]) + "\n")
        r = run(SWEEP + ["--repeats", "2", "--out", out])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertRegex(
            r.stderr, r"line 2 .*seed %d is not this grid point's seed %s" % (int(f1[5]) + 1, f1[5])
        )
        self.assertRegex(r.stderr, r"line 3 .*success with s_mm = nan")
        self.assertRegex(r.stderr, r"line 5 .*second row for the trial of line 4")
        self.assertIn("1 already in", r.stdout)  # the one good row kept, the other rerun
        again = rows(path)
        self.assertEqual(
            sorted((x["repeat"], x["seed"]) for x in again),
            sorted((x["repeat"], x["seed"]) for x in good),
        )
        self.assertEqual(leftovers(out), [])

    def test_two_sweeps_on_one_folder_and_sigterm_mid_sweep(self):
        out = os.path.join(self.tmp, "shared")
        # Enough trials that the signal lands mid-sweep however fast the default scene runs.
        repeats = 16
        args = [SSC] + SWEEP + ["--repeats", str(repeats), "--out", out]
        first = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        csv_path = os.path.join(out, "sweep.csv")
        deadline = time.time() + 120
        while time.time() < deadline and not (
            os.path.exists(csv_path + ".lock") and os.path.exists(csv_path)
        ):
            time.sleep(0.05)
        second = run(SWEEP + ["--repeats", str(repeats), "--out", out])
        self.assertEqual(second.returncode, 1, second.stderr)
        self.assertIn("being written by another sweep (pid %d" % first.pid, second.stderr)
        # SIGTERM once a row is in: the finished rows stay, whole; the lock goes.
        while time.time() < deadline and len(rows(csv_path)) < 1:
            time.sleep(0.05)
        first.send_signal(signal.SIGTERM)
        _, err = first.communicate(timeout=120)
        self.assertEqual(first.returncode, 130, err)
        kept = rows(csv_path)
        self.assertGreaterEqual(len(kept), 1)
        self.assertLess(
            len(kept), repeats, "the sweep ended before SIGTERM: no interruption tested"
        )
        with open(csv_path) as f:
            self.assertTrue(f.read().endswith("\n"))
        self.assertEqual(leftovers(out), [])
        r = run(SWEEP + ["--repeats", str(repeats), "--out", out])
        self.assertEqual(r.returncode, 0, r.stderr)
        final = rows(csv_path)
        self.assertEqual(sorted(int(x["repeat"]) for x in final), list(range(repeats)))
        self.assertEqual([x["seed"] for x in final[: len(kept)]], [x["seed"] for x in kept])

    # Writes fail whole.

    def limited(self, limit_bytes):
        def set_limit():
            resource.setrlimit(resource.RLIMIT_FSIZE, (limit_bytes, limit_bytes))

        return set_limit

    def test_a_file_size_limit_fails_the_trial_whole(self):
        out = os.path.join(self.tmp, "fsize_trial")
        r = run(
            ["trial", "--no-plot", "--timeout", "1", "--out", out], preexec_fn=self.limited(4096)
        )
        self.assertEqual(r.returncode, 1, r.stderr)  # not 153 (SIGXFSZ)
        self.assertIn("trial.csv: cannot write: File too large", r.stderr)
        self.assertFalse(os.path.exists(os.path.join(out, "trial.csv")))
        self.assertEqual(leftovers(self.tmp + "/fsize_trial"), [])

    def test_a_file_size_limit_keeps_the_sweep_csv_whole(self):
        out = os.path.join(self.tmp, "fsize_sweep")
        r = run(SWEEP + ["--repeats", "3", "--out", out])
        self.assertEqual(r.returncode, 0, r.stderr)
        csv_path = os.path.join(out, "sweep.csv")
        with open(csv_path) as f:
            before = f.read()
        # Room for less than one more row: the next append fails with EFBIG.
        r = run(
            SWEEP + ["--repeats", "5", "--out", out], preexec_fn=self.limited(len(before) + 100)
        )
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertIn("sweep.csv: cannot append a row: File too large", r.stderr)
        with open(csv_path) as f:
            self.assertEqual(f.read(), before)  # the partial row cut off again
        self.assertEqual(leftovers(out), [])

    def test_a_file_size_limit_fails_calibrate_whole(self):
        # params.json (about 0.8 kB) fits under the limit, the calibrated tool (about 11 kB) not.
        out = os.path.join(self.tmp, "fsize_calibrate")
        r = run(["calibrate", "--out", out], preexec_fn=self.limited(4096))
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertIn("ssc_tool_calibrated.xml: cannot write: File too large", r.stderr)
        self.assertFalse(os.path.exists(os.path.join(out, "ssc_tool_calibrated.xml")))
        with open(os.path.join(out, "params.json")) as f:
            json.load(f)  # whole
        self.assertEqual(leftovers(out), [])

    def test_sigterm_during_a_trial_leaves_no_empty_folder(self):
        out = os.path.join(self.tmp, "term_trial", "new")
        p = subprocess.Popen(
            [SSC, "trial", "--no-plot", "--timeout", "60", "--out", out],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE,
        )
        deadline = time.time() + 60
        while time.time() < deadline and not os.path.isdir(out):
            time.sleep(0.02)
        self.assertTrue(os.path.isdir(out))
        p.send_signal(signal.SIGTERM)
        p.communicate(timeout=60)
        self.assertEqual(p.returncode, -signal.SIGTERM)
        self.assertFalse(os.path.exists(os.path.dirname(out)))

    def test_sigterm_mid_objects_keeps_the_finished_rows_and_says_so(self):
        out = os.path.join(self.tmp, "term_objects")
        names = ["disk_d14", "disk_d12", "hole_d14", "hole_d12", "corner_a090", "corner_a270"]
        p = subprocess.Popen(
            [
                SSC,
                "objects",
                "--objects",
                ",".join(names),
                "--threads",
                "1",
                "--no-plot",
                "--out",
                out,
            ],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        first = p.stdout.readline()  # a trial's line: one row finished
        self.assertIn("seed 1", first)
        p.send_signal(signal.SIGTERM)
        rest, err = p.communicate(timeout=120)
        self.assertEqual(p.returncode, 130, err)
        finished = 1 + rest.count(" seed 1 ")
        self.assertLess(finished, len(names), "every trial ended before SIGTERM")
        self.assertIn("interrupted; %d of %d trials finished" % (finished, len(names)), err)
        with open(os.path.join(out, "objects.csv")) as f:
            lines = f.read().splitlines()
        self.assertEqual(len(lines), 1 + finished)  # the header and whole rows, no blank ones
        widths = {len(row) for row in csv.reader(lines)}
        self.assertEqual(widths, {len(next(csv.reader(lines[:1])))}, lines)
        self.assertEqual(leftovers(out), [])

    def test_sigterm_mid_stability_keeps_only_judged_rows(self):
        out = os.path.join(self.tmp, "term_stability")
        p = subprocess.Popen(
            [
                SSC,
                "stability",
                "--scene",
                "disk_benchmark_fast",
                "--steps-ms",
                "4,8",
                "--threads",
                "1",
                "--out",
                out,
            ],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        time.sleep(1)  # the 0.5 ms reference alone takes longer
        p.send_signal(signal.SIGTERM)
        printed, err = p.communicate(timeout=120)
        self.assertEqual(p.returncode, 130, err)
        self.assertIn("interrupted", err)
        self.assertNotIn("largest time step", printed)
        csv_path = os.path.join(out, "stability.csv")
        if os.path.exists(csv_path):  # the reference finished: only its judged rows
            self.assertNotIn("running", "".join(r["outcome"] for r in rows(csv_path)))
        else:
            self.assertIn("before the reference trial finished", err)

    # ssc objects and ssc stability resume as ssc sweep does.

    def test_objects_killed_midway_resumes_to_the_uninterrupted_rows(self):
        args = [
            "objects",
            "--objects",
            "disk_d14,hole_d14,corner_a090",
            "--threads",
            "1",
            "--no-plot",
        ]
        whole = os.path.join(self.tmp, "objects_whole")
        self.assertEqual(run(args + ["--out", whole]).returncode, 0)
        out = os.path.join(self.tmp, "objects_killed")
        table = os.path.join(out, "objects.csv")
        p = subprocess.Popen(
            [SSC] + args + ["--out", out], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
        )
        self.assertIn("seed 1", p.stdout.readline())  # a trial's line: its row is in
        p.kill()  # SIGKILL: no handler runs, only what was appended stays
        p.communicate(timeout=60)
        kept = rows(table)
        self.assertTrue(1 <= len(kept) < 3, kept)
        r = run(args + ["--out", out])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("%d of 3 trials already in" % len(kept), r.stdout)
        self.assertEqual(r.stdout.count(" seed 1 "), 3 - len(kept))  # only the others ran
        final = rows(table)
        timing = ("step_cost_us", "row_digest")  # the digest seals the timing too

        def same(t):
            return [{k: v for k, v in x.items() if k not in timing} for x in t]

        self.assertEqual(same(final), same(rows(os.path.join(whole, "objects.csv"))))
        for x in kept:  # the rows of the killed run, not recomputed
            self.assertIn(x, final)
        # A row this run cannot have made is dropped, named, and its trial alone rerun.
        with open(table) as f:
            lines = f.read().splitlines()
        edited = lines[1].split(",")
        edited[3] = "7"
        with open(table, "w") as f:
            f.write("\n".join([lines[0], ",".join(edited)] + lines[2:]) + "\n")
        r = run(args + ["--out", out])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("seed '7' is not one of this run's", r.stderr)
        self.assertEqual(r.stdout.count(" seed 1 "), 1)
        self.assertEqual(same(rows(table)), same(final))
        # An outcome edited to contradict its own detail: the row is not as the study wrote it.
        with open(table) as f:
            lines = f.read().splitlines()
        edited = next(csv.reader([lines[1]]))
        self.assertNotEqual(edited[4], "failure_I", edited)
        edited[4] = "failure_I"
        buf = io.StringIO()
        csv.writer(buf, lineterminator="").writerow(edited)
        with open(table, "w") as f:
            f.write("\n".join([lines[0], buf.getvalue()] + lines[2:]) + "\n")
        r = run(args + ["--out", out])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("row_digest does not match the row", r.stderr)
        self.assertEqual(r.stdout.count(" seed 1 "), 1)
        self.assertEqual(same(rows(table)), same(final))
        # Other options would mix rows: refused, naming the difference.
        r = run(args + ["--step", "0.6", "--out", out])
        self.assertEqual(r.returncode, 1)
        self.assertIn("step_mm: 0.5 in the file, 0.6 now", r.stderr)
        self.assertEqual(leftovers(out), [])

    def test_objects_refuses_rows_made_with_another_tool_model(self):
        # The object scenes include the tool model from the resource folder: a copy of it here.
        res = os.path.join(self.tmp, "tool_model_resources")
        for folder in ("models", "scenes"):
            shutil.copytree(os.path.join(SRC, folder), os.path.join(res, folder))
        env = dict(os.environ, SSC_RESOURCE_DIR=res)
        out = os.path.join(self.tmp, "objects_tool_model")
        args = ["objects", "--objects", "disk_d14", "--threads", "1", "--no-plot", "--out", out]
        r = run(args, env=env)
        self.assertEqual(r.returncode, 0, r.stderr)
        table = os.path.join(out, "objects.csv")
        made = rows(table)
        self.assertEqual(len(made), 1)
        r = run(args, env=env)  # unchanged files: the row is kept, no trial runs
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("1 of 1 trials already in", r.stdout)
        # Only a value in the included tool model changes: the scene XML is the same text.
        tool = os.path.join(res, "models", "ssc_tool.xml")
        with open(tool) as f:
            xml = f.read()
        old = 'friction="0.4 0.005 0.0001"'
        self.assertIn(old, xml)
        with open(tool, "w") as f:
            f.write(xml.replace(old, 'friction="0.6 0.005 0.0001"', 1))
        r = run(args, env=env)
        self.assertEqual(r.returncode, 1, r.stdout)
        self.assertIn("holds rows made with other options (file " + tool, r.stderr)
        self.assertNotIn("already in", r.stdout)
        self.assertEqual(rows(table), made)  # refused whole: the table is left as it was
        self.assertEqual(leftovers(out), [])

    def test_stability_resumes_from_its_trials_file(self):
        args = [
            "stability",
            "--scene",
            "disk_benchmark_fast",
            "--steps-ms",
            "4,8",
            "--threads",
            "1",
        ]
        whole = os.path.join(self.tmp, "stability_whole")
        self.assertEqual(run(args + ["--out", whole]).returncode, 0)
        out = os.path.join(self.tmp, "stability_cut")
        shutil.copytree(whole, out)
        trials = os.path.join(out, "stability_trials.csv")
        with open(trials) as f:
            lines = f.read().splitlines()
        self.assertEqual(len(lines), 1 + 9)  # the reference and 4 integrators x 2 steps
        # Cut as a killed run leaves it: three rows whole, the fourth torn.
        with open(trials, "w") as f:
            f.write("\n".join(lines[:4]) + "\n" + lines[4][:20])
        os.remove(os.path.join(out, "stability.csv"))
        r = run(args + ["--out", out])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("dropped 1 torn or malformed line", r.stderr)
        self.assertIn("3 of 9 trials already in", r.stdout)
        with open(trials) as f:
            now = f.read().splitlines()
        self.assertEqual(now[:4], lines[:4])  # the finished trials kept as they were
        self.assertEqual(len(now), 10)
        timing = ("wall_s",)

        def same(t):
            return [{k: v for k, v in x.items() if k not in timing} for x in t]

        self.assertEqual(
            same(rows(os.path.join(out, "stability.csv"))),
            same(rows(os.path.join(whole, "stability.csv"))),
        )

    # A search point that breaks a rule between the controller's keys is refused, not run.

    def test_tune_refuses_points_that_break_a_rule_between_keys(self):
        out = os.path.join(self.tmp, "tune_rule")
        # Part of this box keeps step_min_mm <= step_max_mm; BOBYQA's first points straddle it.
        r = run(
            [
                "tune",
                "--controller",
                "fast",
                "--search",
                "step_min_mm=6:12,step_max_mm=5:8",
                "--seeds",
                "1",
                "--evals",
                "6",
                "--timeout",
                "4",
                "--threads",
                "1",
                "--reference",
                "none",
                "--no-plot",
                "--out",
                out,
            ]
        )
        self.assertEqual(r.returncode, 0, r.stderr)
        table = rows(os.path.join(out, "tune.csv"))
        self.assertEqual(len(table), 6)
        refused = [x for x in table if x["outcome"].startswith("refused")]
        ran = [x for x in table if x["outcome"] == "ran"]
        self.assertEqual(len(refused) + len(ran), len(table))
        self.assertTrue(refused and ran, "the search did not straddle the rule: nothing tested")
        for x in refused:
            self.assertGreater(float(x["step_min_mm"]), float(x["step_max_mm"]), x)
            self.assertIn("step_min_mm <= step_max_mm", x["outcome"])
            self.assertEqual((x["trials"], x["speed_mm_s"], x["pareto"]), ("0", "", "0"))
            self.assertFalse(
                os.path.exists(os.path.join(out, "evals", x["label"].replace(" ", "_"))),
                "a refused point ran",
            )
        for x in ran:
            self.assertLessEqual(float(x["step_min_mm"]), float(x["step_max_mm"]), x)
            self.assertEqual(x["trials"], "1")
        self.assertIn("refused: %d of the search's points" % len(refused), r.stdout)
        best = [line for line in r.stdout.splitlines() if line.startswith("best score: ")]
        if best:
            self.assertIn(best[0].split(",")[0][len("best score: ") :], [x["label"] for x in ran])

    # A command owns its folder before it touches anything in it.

    def test_tune_owns_its_folder_before_touching_an_evaluation(self):
        out = os.path.join(self.tmp, "tune_own")

        def tune(seeds, folder=out):
            return [
                "tune",
                "--controller",
                "fast",
                "--search",
                "step_max_mm=8:12",
                "--seeds",
                str(seeds),
                "--evals",
                "2",
                "--timeout",
                "2",
                "--threads",
                "1",
                "--reference",
                "none",
                "--no-plot",
                "--out",
                folder,
            ]

        args = tune(1)
        first = run(args)
        self.assertEqual(first.returncode, 0, first.stderr)
        eval1 = os.path.join(out, "evals", "eval_1", "sweep.csv")
        with open(eval1) as f:
            kept = f.read()
        table = rows(os.path.join(out, "tune.csv"))
        # Other options: refused before an evaluation's rows are touched, naming the difference.
        r = run(tune(2))
        self.assertEqual(r.returncode, 1, r.stdout)
        self.assertIn("seeds: 1 in the file, 2 now", r.stderr)
        with open(eval1) as f:
            self.assertEqual(f.read(), kept)
        self.assertEqual(rows(os.path.join(out, "tune.csv")), table)
        # A second search on a folder while one runs there: refused, naming the first.
        busy = os.path.join(self.tmp, "tune_busy")
        p = subprocess.Popen(
            [SSC] + tune(1, busy), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
        )
        try:
            deadline = time.time() + 30
            while not os.path.exists(os.path.join(busy, "tune.csv.lock")):
                self.assertLess(time.time(), deadline, "the first search never took the lock")
                time.sleep(0.01)
            r = run(tune(1, busy))
            self.assertEqual(r.returncode, 1, r.stdout)
            self.assertIn("pid %d" % p.pid, r.stderr)
        finally:
            p.communicate(timeout=120)
        # The same options again: the search's own rows resume, every evaluation as before.
        again = run(args)
        self.assertEqual(again.returncode, 0, again.stderr)
        self.assertEqual(rows(os.path.join(out, "tune.csv")), table)
        self.assertEqual(leftovers(out), [])

    # Results that cannot be right are refused.

    def test_a_scene_with_two_cups_is_refused(self):
        second = (
            '<body name="two" pos="0.3 0 0.3"><attach model="ssc_tool" body="tool" prefix="two_"/>'
        )
        path = self.scene_with(
            "</mujoco>", f"<worldbody>{second}</body></worldbody></mujoco>", "two"
        )
        r = run(["trial", "--scene", path, "--out", os.path.join(self.tmp, "two_cups")])
        self.assertEqual(r.returncode, 4, r.stdout)
        self.assertIn("2 ssc.chamber_pressure sensors", r.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.tmp, "two_cups")))

    def test_stability_with_no_step_unchanged_says_so(self):
        # Euler at 8 ms against the RK4 0.5 ms reference: nothing unchanged, or a real step.
        out = os.path.join(self.tmp, "stability_none")
        r = run(
            [
                "stability",
                "--scene",
                "disk_benchmark_fast",
                "--steps-ms",
                "8",
                "--threads",
                "1",
                "--out",
                out,
            ]
        )
        self.assertEqual(r.returncode, 0, r.stderr)
        judged = rows(os.path.join(out, "stability.csv"))
        for integrator in {x["integrator"] for x in judged}:
            unchanged = [
                x for x in judged if x["integrator"] == integrator and x["unchanged"] == "1"
            ]
            line = [ln for ln in r.stdout.splitlines() if ln.startswith(integrator + ": ")]
            self.assertEqual(len(line), 1, r.stdout)
            if unchanged:
                self.assertIn("largest time step with unchanged results: 8.00 ms", line[0])
            else:
                self.assertIn("no time step tried gave unchanged results", line[0])
        self.assertNotIn("0.00 ms", r.stdout)

    def test_a_full_disk_fails_compare_whole(self):
        disk = os.path.join(self.tmp, "full")
        os.makedirs(disk)
        # A 64 KiB tmpfs where the machine allows mounting (root in a container often does).
        if (
            subprocess.run(
                ["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", disk], capture_output=True
            ).returncode
            != 0
        ):
            self.skipTest("cannot mount a small tmpfs here (ulimit -f cases cover EFBIG)")
        try:
            out = os.path.join(disk, "c", "d")
            r = run(["compare", self.plain_log(0.0), "--no-plot", "--out", out])
            self.assertEqual(r.returncode, 1, r.stderr)
            self.assertIn("cannot write: No space left on device", r.stderr)
            self.assertEqual(os.listdir(disk), [])  # no partial file, no empty folder
        finally:
            subprocess.run(["umount", disk])

    def plain_log(self, t0_s, rows=4000):
        """A plain CSV: the cup circling inside the disk edge at 1 kHz from t0_s."""
        path = os.path.join(self.tmp, f"plain_{t0_s:+g}.csv")
        with open(path, "w") as f:
            f.write("t_s,x_m,y_m,z_m,qw,qx,qy,qz,p1_pa,p2_pa,p3_pa,p4_pa\n")
            for i in range(rows):
                a = 2 * math.pi * i / rows
                p = [4000 + 300 * math.sin(a + k * math.pi / 2) for k in range(4)]
                f.write(
                    "%.4f,%.6f,%.6f,0.009,0,0.70710678,-0.70710678,0,%.2f,%.2f,%.2f,%.2f\n"
                    % (t0_s + i * 1e-3, 0.65 + 0.033 * math.cos(a), 0.033 * math.sin(a), *p)
                )
        return path

    def test_compare_does_not_depend_on_where_the_clock_starts(self):
        reports = []
        for t0 in (0.0, -5.0, 1.7e9):
            out = os.path.join(self.tmp, f"clock_{t0:+g}")
            r = run(["compare", self.plain_log(t0), "--no-plot", "--out", out])
            self.assertEqual(r.returncode, 0, r.stderr)
            reports.append([l for l in r.stdout.splitlines() if l.startswith(("chamber", "mean"))])
        self.assertEqual(reports[0], reports[1])
        self.assertEqual(reports[0], reports[2])

    # Scenes.

    def test_a_fifo_include_is_refused_without_blocking(self):
        d = os.path.join(self.tmp, "fifo_scene")
        os.makedirs(d)
        os.mkfifo(os.path.join(d, "part.xml"))
        scene = os.path.join(d, "scene.xml")
        with open(scene, "w") as f:
            f.write('<mujoco>\n  <include file="part.xml"/>\n</mujoco>\n')
        r = run(["trial", "--no-plot", "--scene", scene, "--out", d], timeout=30)
        self.assertEqual(r.returncode, 4, r.stderr)
        self.assertIn('scene.xml:2: <include file="part.xml">', r.stderr)
        self.assertIn("not a regular file", r.stderr)

    def test_a_nan_in_the_scene_is_refused_naming_the_element(self):
        disk = '<geom name="disk" type="cylinder" size="0.035 0.005" pos="nan 0 0.005"/>'
        scene = self.scene_with(
            '<include file="parts/disk.xml"/>', f"<worldbody>{disk}</worldbody>", "nan_disk"
        )
        r = run(["trial", "--no-plot", "--scene", scene, "--out", self.tmp], timeout=60)
        self.assertEqual(r.returncode, 4, r.stderr)
        self.assertIn("geom 'disk': geom_pos holds nan", r.stderr)

    def test_a_vanishing_approach_force_is_refused(self):
        r = run(["trial", "--approach-force", "1e-300"])
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("--approach-force", r.stderr)

    @unittest.skipUnless(shutil.which("xvfb-run"), "xvfb-run not installed")
    def test_a_screenshot_has_the_size_asked_for(self):
        png = os.path.join(self.tmp, "shot.png")
        r = subprocess.run(
            [
                "xvfb-run",
                "-a",
                SSC,
                "view",
                "--screenshot",
                png,
                "--width",
                "1920",
                "--height",
                "1080",
                "--time",
                "0.1",
            ],
            capture_output=True,
            text=True,
            timeout=120,
        )
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(png, "rb") as f:
            head = f.read(24)
        self.assertEqual(
            (int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")), (1920, 1080)
        )

    # Maps that are not text.

    def test_binary_and_utf16_maps_are_refused_saying_why(self):
        with open(os.path.join(SRC, "data", "published", "success_map_dl5.csv"), "rb") as f:
            text = f.read()
        cases = {
            "utf16": (b"\xff\xfe" + text.decode().encode("utf-16-le"), "UTF-16"),
            "nul": (text[:40] + b"\0" + text[40:], "NUL"),
            "random": (os.urandom(200_000), "not text"),
        }
        for name, (data, why) in cases.items():
            path = os.path.join(self.tmp, f"map_{name}.csv")
            with open(path, "wb") as f:
                f.write(data)
            r = subprocess.run(
                [SSC, "validate", "--map", path, "--out", os.path.join(self.tmp, f"v_{name}")],
                capture_output=True,
                timeout=60,
            )
            err = r.stderr.decode("utf-8", "replace")
            self.assertNotEqual(r.returncode, 0, name)
            self.assertIn(path, err, name)
            self.assertRegex(err, "UTF-16|NUL|binary", name)
            self.assertLess(len(r.stderr), 600, name)
            self.assertTrue(all(32 <= b < 127 or b in (9, 10) for b in r.stderr), (name, err))
            self.assertFalse(os.path.exists(os.path.join(self.tmp, f"v_{name}")), name)


class CompareOptionsTest(unittest.TestCase):
    """compare's options checked against the log: a twin trial written as the lab records it."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="ssc_reliability_cmp_")
        cls.rec = os.path.join(cls.tmp, "rec")
        r = run(
            ["trial", "--no-plot", "--out", os.path.join(cls.tmp, "trial"), "--robot-log", cls.rec],
            timeout=300,
        )
        assert r.returncode == 0, r.stderr

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def compare(self, *extra):
        return run(
            ["compare", self.rec, "--no-plot", "--out", os.path.join(self.tmp, "cmp")]
            + list(extra),
            timeout=300,
        )

    def test_the_closed_loop_names_the_controller_that_ran(self):
        r = self.compare("--closed-loop", "--controller", "fast")
        self.assertEqual(r.returncode, 0, r.stderr)
        line = [ln for ln in r.stdout.splitlines() if ln.startswith("closed loop (")]
        self.assertEqual(len(line), 1, r.stdout)
        self.assertIn("controller fast:", line[0])
        with open(os.path.join(self.tmp, "cmp", "report.json")) as f:
            closed = json.load(f)["closed_loop"]
        self.assertTrue(closed["controller"].startswith("fast:"), closed)
        with open(os.path.join(self.tmp, "cmp", "report.md")) as f:
            self.assertIn("controller `fast:", f.read())

    def test_a_tcp_offset_out_of_range_is_refused_in_mm(self):
        r = self.compare("--tcp-offset", "1000")
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("--tcp-offset", r.stderr)
        self.assertIn("mm", r.stderr)

    def test_a_replay_off_the_object_is_flagged_naming_the_options(self):
        good = self.compare()
        self.assertEqual(good.returncode, 0, good.stderr)
        self.assertNotIn("replay disagrees", good.stderr)
        off = self.compare("--tcp-offset", "100")
        self.assertEqual(off.returncode, 0, off.stderr)
        self.assertIn("the replay disagrees with the log", off.stderr)
        for option in ("--tcp-offset", "--log-frame", "--object-pose"):
            self.assertIn(option, off.stderr)
        # No sample where both sides read a differential: no direction error, not a perfect 0.
        with open(os.path.join(self.tmp, "cmp", "report.json")) as f:
            replay = json.load(f)["replay"]
        self.assertEqual(replay["direction_samples"], 0)
        self.assertIsNone(replay["direction_rms_deg"])
        self.assertIsNone(replay["direction_median_deg"])
        self.assertIn("direction error RMS nan deg", off.stdout)

    def test_windows_longer_than_the_log_are_refused(self):
        r = self.compare("--offset-window", "59")
        self.assertEqual(r.returncode, 4, r.stderr)
        self.assertIn("--offset-window", r.stderr)
        r = self.compare("--average", "1000")
        self.assertIn("--average", r.stderr)


if __name__ == "__main__":
    unittest.main()
