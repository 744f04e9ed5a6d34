"""The Python API is as strict as the command line: every bad argument raises ValueError with the
C++ check's message (the same check the CLI runs), before any work or file is made; finite
actions outside the box are clipped, non-finite ones refused. Run inside the venv the package
was installed into (tests/install/python_package_test.sh).

With Hypothesis installed (optional), property tests draw arguments from wide ranges and assert
that every call either returns finite numbers or raises ValueError."""

import math
import os
import shutil
import tempfile
import unittest

import numpy as np

import ssc_twin

try:
    from hypothesis import given, settings, strategies as st
except ImportError:  # optional test dependency
    given = None


class StrictArgumentsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="ssc_strict_")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def refused(self, text, fn, *args, **kw):
        with self.assertRaises(ValueError) as cm:
            fn(*args, **kw)
        self.assertIn(text, str(cm.exception))
        return str(cm.exception)

    def test_sweep_arguments(self):
        csv = os.path.join(self.tmp, "s", "sweep.csv")
        grid = dict(pref=[100], beta=[2], step_mm=[7.5], repeats=1)
        self.refused("threads", ssc_twin.sweep, threads=0, out_csv=csv, **grid)
        self.refused(
            "listed twice",
            ssc_twin.sweep,
            pref=[100, 100],
            beta=[2],
            step_mm=[7.5],
            repeats=1,
            out_csv=csv,
        )
        self.refused("out_csv", ssc_twin.sweep, out_csv="", **grid)
        self.refused(
            "repeat", ssc_twin.sweep, pref=[100], beta=[2], step_mm=[7.5], repeats=0, out_csv=csv
        )
        self.assertFalse(os.path.exists(os.path.dirname(csv)))

    def test_trial_arguments(self):
        self.refused("timeout_s", ssc_twin.run_trial, timeout_s=-5)
        self.refused("timeout_s", ssc_twin.run_trial, timeout_s=float("nan"))
        self.refused("stop_at_s", ssc_twin.run_trial, stop_at_s=-1)
        self.refused("timeout_s", ssc_twin.SteppedTrial, timeout_s=1e9)
        self.refused("pref", ssc_twin.run_trial, pref=float("inf"))

    def test_probe_arguments(self):
        probe = ssc_twin.Probe()
        self.refused("settle_s", probe.read, 0.0, 0.0, settle_s=-1)
        self.refused("settle_s", probe.read, 0.0, 0.0, settle_s=1e6)
        self.refused("x_m", probe.read, float("nan"), 0.0)
        r = probe.read(-0.003, 0.0, settle_s=0.05)
        self.assertTrue(np.all(np.isfinite(r["filtered_pa"])))

    def test_contour_step_arguments(self):
        self.refused("p_pa[0]", ssc_twin.contour_step, [float("nan"), 0, 0, 0])
        self.refused("p_pa[2]", ssc_twin.contour_step, [0, 0, 1e308, 0])
        s = ssc_twin.contour_step([300, 100, 100, 300])
        self.assertTrue(np.all(np.isfinite(s["step_m"])))

    def test_stepped_trial_refuses_non_finite_steps(self):
        t = ssc_twin.SteppedTrial(timeout_s=2)
        t.set_external_policy(True)
        while t.phase != "follow" and t.run_to_next_iteration():
            pass
        self.refused("not finite", t.apply_step, [float("nan"), 0.0])
        self.refused("not finite", t.apply_step, [0.0, float("inf")])
        t.apply_step([0.0, 0.001])  # a finite step is taken

    def test_every_seed_is_a_whole_number_in_the_cli_range(self):
        """Above 2^53 - 1 a seed would lose its last bits through doubles, above 2^64 it would
        wrap: every entry point refuses it, and a fraction, a negative or a bool, before any
        work, with ssc --seed's range."""
        cli_range = "a whole number in [0, 9007199254740991]"
        self.assertEqual(ssc_twin.max_seed, 2**53 - 1)
        csv = os.path.join(self.tmp, "seed_sweep", "sweep.csv")
        out = os.path.join(self.tmp, "seed_out")
        trial, plant = ssc_twin.SteppedTrial(), ssc_twin.SilPlant()
        calls = {
            "check_seed": ssc_twin.check_seed,
            "run_trial": lambda s: ssc_twin.run_trial(seed=s, keep_log=False),
            "sweep": lambda s: ssc_twin.sweep(
                pref=[100], beta=[2], step_mm=[7.5], repeats=1, seed=s, out_csv=csv
            ),
            "validate": lambda s: ssc_twin.validate(out_dir=out, seed=s),
            "objects": lambda s: ssc_twin.objects("disk_d14", out_dir=out, seed=s),
            "write_robot_log": lambda s: ssc_twin.write_robot_log(out, seed=s),
            "SteppedTrial": lambda s: ssc_twin.SteppedTrial(seed=s),
            "SteppedTrial.reset": lambda s: trial.reset(s),
            "SilPlant": lambda s: ssc_twin.SilPlant(seed=s),
            "SilPlant.reset": lambda s: plant.reset(s),
        }
        try:
            import gymnasium as gym

            env = gym.make("ssc_twin/EdgeFollowing-v0")
            calls["env.reset"] = lambda s: env.reset(seed=s)
        except ImportError:  # gymnasium is optional
            env = None
        for name, call in calls.items():
            for bad in (2**53, 2**53 + 1, 2**64 + 5, 2**70, -1, 1.5, float("nan"), True):
                with self.subTest(name, seed=bad):
                    message = self.refused(cli_range, call, bad)
                    self.assertIn("seed = ", message)
        self.assertFalse(os.path.exists(os.path.dirname(csv)))
        self.assertFalse(os.path.exists(out))
        # Whole numbers in range pass as ints, whatever their Python type.
        for good, want in (
            (0, 0),
            (2**53 - 1, 2**53 - 1),
            (2.0, 2),
            (np.int64(7), 7),
            (np.uint64(2**53 - 1), 2**53 - 1),
        ):
            self.assertEqual(ssc_twin.check_seed(good), want)
        if env is not None:
            self.assertIn("object", env.reset(seed=2**53 - 1)[1])
            env.close()

    def test_files_named_in_errors(self):
        self.refused(
            "/dev/zero", ssc_twin.validate, map="/dev/zero", out_dir=os.path.join(self.tmp, "v")
        )
        self.assertFalse(os.path.exists(os.path.join(self.tmp, "v")))
        self.refused("/etc/passwd", ssc_twin.read_sweep, "/etc/passwd")
        binary = os.path.join(self.tmp, "binary.csv")
        with open(binary, "wb") as f:
            f.write(bytes(range(256)) * 10)
        message = self.refused(
            "binary", ssc_twin.validate, map=binary, out_dir=os.path.join(self.tmp, "v")
        )
        self.assertTrue(message.isprintable(), message)

    def test_an_interrupted_sweep_raises_keyboard_interrupt_and_resumes(self):
        # SIGINT while the study runs (Ctrl-C, a notebook's interrupt) is taken by the job
        # runner, which keeps the finished rows; the call must not return as if complete.
        import signal

        csv = os.path.join(self.tmp, "interrupted.csv")
        grid = dict(pref=[100], beta=[2], step_mm=[7.5], repeats=4, threads=1, out_csv=csv)

        def interrupt_after_the_first(done, total, elapsed_s):
            if done == 1:
                os.kill(os.getpid(), signal.SIGINT)

        with self.assertRaises(KeyboardInterrupt) as cm:
            ssc_twin.sweep(progress=interrupt_after_the_first, **grid)
        self.assertIn("finished rows kept in " + csv, str(cm.exception))
        kept = len(ssc_twin.read_sweep(csv)["seed"])
        self.assertLess(kept, 4)
        self.assertEqual(ssc_twin.sweep(**grid)["skipped"], kept)

    def test_a_sweep_of_one_row_reads_as_arrays(self):
        csv = os.path.join(self.tmp, "one_row.csv")
        ssc_twin.sweep(pref=[100], beta=[2], step_mm=[7.5], repeats=1, out_csv=csv)
        table = ssc_twin.read_sweep(csv)
        self.assertEqual(table["seed"].shape, (1,))
        self.assertEqual(len(table["outcome"]), 1)

    def test_read_sweep_gives_back_every_fault_the_sweep_wrote(self):
        # A writer and its reader: details holding commas, quotes, line breaks and UTF-8, as a
        # Python controller's exception writes them, come back as text (no CSV quotes left).
        messages = [
            "plain",
            "a, b, c",
            'said "no", twice',
            "two\nlines",
            "caf\u00e9; \\x",
            '"',
            ",",
            "'quoted', \"both\"",
        ]

        for n, message in enumerate(messages):

            def faulty(reading, message=message):
                raise ValueError(message)

            csv = os.path.join(self.tmp, "faults_%d.csv" % n)
            ssc_twin.sweep(
                pref=[100],
                beta=[2],
                step_mm=[7.5],
                repeats=1,
                threads=1,
                out_csv=csv,
                controller=faulty,
            )
            table = ssc_twin.read_sweep(csv)
            self.assertEqual(list(table["outcome"]), ["controller_fault"])
            detail = str(table["detail"][0])
            self.assertTrue(
                detail.endswith("(Python ValueError: %s)" % message.replace("\n", " ")), detail
            )
            self.assertFalse(detail.startswith('"'), detail)

    def test_ctrl_c_inside_a_python_controller_raises(self):
        def interrupted(reading):
            raise KeyboardInterrupt

        with self.assertRaises(KeyboardInterrupt):
            ssc_twin.run_trial(scene="disk_benchmark_fast", controller=interrupted, keep_log=False)

    def test_compare_tcp_offset_in_mm(self):
        rec = os.path.join(self.tmp, "rec")
        ssc_twin.write_robot_log(rec)
        with self.assertRaises(Exception) as cm:
            ssc_twin.compare(rec, out_dir=os.path.join(self.tmp, "c"), tcp_offset_mm=1000)
        self.assertIn("1000 mm", str(cm.exception))


class EnvironmentActionsTest(unittest.TestCase):
    def test_bad_arguments_are_refused_at_make_with_the_cli_checks(self):
        try:
            import gymnasium as gym
        except ImportError:
            self.skipTest("gymnasium not installed")
        env_id = "ssc_twin/EdgeFollowing-v0"
        for kw, text in (
            (dict(pref=5), "pref_pa (P_ref) = 5"),
            (dict(effects="foo=1"), "unknown key 'foo'"),
            (dict(timeout_s=-5), "timeout_s = -5"),
            (dict(failure_penalty=float("nan")), "finite"),
            (dict(render_mode="rgb_array", camera="nope"), "camera 'nope'"),
        ):
            with self.subTest(**kw), self.assertRaises(ValueError) as cm:
                gym.make(env_id, **kw)
            self.assertIn(text, str(cm.exception))
        # One string of names, as ssc objects --objects takes them (not one name per letter).
        env = gym.make(env_id, objects="volute")
        self.assertEqual(env.reset(seed=1)[1]["object"], "volute")
        env.close()

    def test_non_finite_actions_are_refused_finite_ones_clipped(self):
        try:
            import gymnasium as gym
        except ImportError:
            self.skipTest("gymnasium not installed")
        env = gym.make("ssc_twin/EdgeFollowing-v0")
        env.reset(seed=1)
        with self.assertRaises(ValueError):
            env.step(np.array([np.nan, np.nan], dtype=np.float32))
        obs, reward, terminated, truncated, _ = env.step(np.array([5.0, -5.0], dtype=np.float32))
        self.assertTrue(np.all(np.isfinite(obs)) and math.isfinite(reward))
        env.close()


if given is not None:

    class PropertyTest(unittest.TestCase):
        """Every call returns finite numbers or raises ValueError, whatever the numbers."""

        @settings(max_examples=60, deadline=None)
        @given(
            st.lists(st.floats(allow_nan=True, allow_infinity=True), min_size=4, max_size=4),
            st.floats(),
            st.floats(),
            st.floats(),
        )
        def test_contour_step(self, p, pref, beta, step):
            try:
                s = ssc_twin.contour_step(p, pref, beta, step)
            except ValueError:
                return
            for key in ("step_m", "direction", "correction", "along_edge"):
                self.assertTrue(np.all(np.isfinite(s[key])), (key, p, pref, beta, step))
            self.assertTrue(math.isfinite(s["p_mean_pa"]))

        @settings(max_examples=40, deadline=None)
        @given(st.floats(), st.floats(), st.floats(), st.floats(min_value=-20, max_value=20))
        def test_probe_read(self, x, y, yaw, settle):
            if not hasattr(self, "probe"):
                PropertyTest.probe = ssc_twin.Probe()
            # Short settles only where valid, so the test stays fast.
            settle = min(settle, 0.02) if 0 < settle <= 10 else settle
            try:
                r = self.probe.read(x, y, yaw_rad=yaw, settle_s=settle)
            except ValueError:
                return
            self.assertTrue(np.all(np.isfinite(r["filtered_pa"])), (x, y, yaw, settle))

        @settings(max_examples=30, deadline=None)
        @given(st.lists(st.floats(), min_size=2, max_size=2))
        def test_apply_step(self, step):
            if not hasattr(self, "trial"):
                PropertyTest.trial = ssc_twin.SteppedTrial(timeout_s=30)
                PropertyTest.trial.set_external_policy(True)
                while (
                    PropertyTest.trial.phase != "follow"
                    and PropertyTest.trial.run_to_next_iteration()
                ):
                    pass
            try:
                self.trial.apply_step(step)
            except ValueError:
                self.assertFalse(all(map(math.isfinite, step)))
                return
            self.assertTrue(all(map(math.isfinite, step)))


if __name__ == "__main__":
    unittest.main()
