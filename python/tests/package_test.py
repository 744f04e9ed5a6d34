"""The installed ssc_twin package (run inside the venv it was pip-installed into):
the plugin found by `import mujoco` alone, trials and validation equal to the CLI's, sweep /
probe / compare bindings, no MUJOCO_LOG.TXT, MuJoCo's own viewer on our scene, and the
edge-following environment (checker, the published law succeeds, a random policy does not).

    python package_test.py PATH/TO/ssc
"""

import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile
import textwrap
import unittest

import numpy as np

SSC = sys.argv.pop(1) if len(sys.argv) > 1 and not sys.argv[1].startswith("-") else None
XVFB = shutil.which("xvfb-run")
# validate test: the follow phase's limit, simulated s (a loop round the disk takes about 8 s).
VALIDATE_TIMEOUT_S = 30


def run(cmd, timeout=300, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, **kw)


class PackageTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="ssc_pkg_")
        os.chdir(cls.tmp)  # MUJOCO_LOG.TXT would land here

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_import_mujoco_alone_finds_the_plugin_and_writes_no_log(self):
        import ssc_twin

        scene = ssc_twin.scene_path("disk_benchmark")
        # A fresh interpreter that never imports ssc_twin: only the entry point can load it.
        script = (
            "import mujoco; m = mujoco.MjModel.from_xml_path(%r); d = mujoco.MjData(m); "
            "mujoco.mj_step(m, d, 50); print('plugins', m.nplugin)" % scene
        )
        r = run([sys.executable, "-c", script], cwd=self.tmp)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("plugins 1", r.stdout)
        self.assertNotIn("Attaching a spec", r.stderr + r.stdout)
        self.assertFalse(os.path.exists(os.path.join(self.tmp, "MUJOCO_LOG.TXT")))

    def test_resources_come_from_the_installed_package(self):
        import ssc_twin

        pkg = os.path.dirname(ssc_twin.__file__)
        self.assertEqual(os.path.realpath(ssc_twin.resource_dir()), os.path.realpath(pkg))
        self.assertTrue(ssc_twin.scene_path("probe_edge").startswith(pkg))
        self.assertTrue(os.path.exists(ssc_twin.plugin_library()))
        # validate's default map ships with the package.
        self.assertTrue(
            os.path.exists(os.path.join(pkg, "data", "published", "success_map_dl5.csv"))
        )

    @unittest.skipUnless(SSC, "no ssc executable given")
    def test_trial_equals_the_cli(self):
        import ssc_twin

        out = os.path.join(self.tmp, "cli")
        r = run([SSC, "trial", "--seed", "3", "--no-plot", "--out", out])
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "summary.json")) as f:
            cli = json.load(f)
        py = ssc_twin.run_trial(seed=3)
        self.assertEqual(py["outcome"], cli["outcome"])
        self.assertEqual(py["detail"], cli["detail"])
        for key, value in cli["metrics"].items():  # summary.json keeps 6 significant digits
            self.assertAlmostEqual(
                py["metrics"][key], value, delta=1e-5 * abs(value) + 1e-9, msg=key
            )
        with open(os.path.join(out, "trial.csv")) as f:
            rows = list(csv.DictReader(f))
        log = py["log"]
        self.assertEqual(len(rows), len(log["t_s"]))

        def col(name):
            return np.array([float(r[name]) for r in rows])

        # trial.csv keeps 6 significant digits (8 for positions): equal to that precision.
        np.testing.assert_allclose(log["t_s"], col("t_s"), atol=1e-9)
        for k in range(4):
            np.testing.assert_allclose(log["p_pa"][:, k], col(f"p{k + 1}_pa"), rtol=6e-6, atol=1e-6)
        np.testing.assert_allclose(log["tool_m"][:, 0], col("x_m"), rtol=6e-8, atol=1e-12)
        np.testing.assert_allclose(log["cf"], col("cf"), rtol=6e-6, atol=1e-9)

    def test_sweep_writes_its_rows(self):
        import ssc_twin

        path = os.path.join(self.tmp, "sweep.csv")
        s = ssc_twin.sweep(
            pref=[100, 1000], beta=[2], step_mm=[7.5], repeats=1, seed=5, threads=2, out_csv=path
        )
        self.assertEqual((s["total"], s["ran"]), (2, 2))
        rows = ssc_twin.read_sweep(path)
        self.assertEqual(sorted(rows["pref_pa"].tolist()), [100.0, 1000.0])
        self.assertTrue(set(rows["outcome"]) <= {"success", "failure_I", "failure_II", "timeout"})
        again = ssc_twin.sweep(
            pref=[100, 1000], beta=[2], step_mm=[7.5], repeats=1, seed=5, threads=1, out_csv=path
        )
        self.assertEqual(again["skipped"], 2)  # resumed: nothing runs twice

    def test_sweep_reports_progress(self):
        import ssc_twin

        calls = []
        path = os.path.join(self.tmp, "progress.csv")
        ssc_twin.sweep(
            pref=[100, 1000],
            beta=[2],
            step_mm=[7.5],
            repeats=1,
            seed=6,
            threads=2,
            out_csv=path,
            progress=lambda *a: calls.append(a),
        )
        self.assertEqual([c[:2] for c in calls], [(1, 2), (2, 2)])
        self.assertTrue(all(c[2] >= 0 for c in calls))
        # True: lines on stderr (a fresh interpreter, to read them).
        script = (
            "import ssc_twin; ssc_twin.sweep(pref=[100], beta=[2], step_mm=[7.5], "
            "repeats=2, seed=6, out_csv=%r, progress=True)"
            % os.path.join(self.tmp, "progress_lines.csv")
        )
        r = run([sys.executable, "-c", script], cwd=self.tmp)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("ssc_twin.sweep: 2/2 trials (100 %)", r.stderr)

        def fails(done, total, elapsed_s):
            raise KeyError("from the callback")

        with self.assertRaisesRegex(KeyError, "from the callback"):
            ssc_twin.sweep(
                pref=[100],
                beta=[2],
                step_mm=[7.5],
                repeats=1,
                seed=7,
                out_csv=os.path.join(self.tmp, "progress_fails.csv"),
                progress=fails,
            )
        with self.assertRaisesRegex(TypeError, "progress must be"):
            ssc_twin.sweep(
                pref=[100],
                beta=[2],
                step_mm=[7.5],
                repeats=1,
                out_csv=os.path.join(self.tmp, "progress_bad.csv"),
                progress="yes",
            )

    def test_a_python_controller_follows_the_disk_and_a_failing_one_is_an_outcome(self):
        import math
        import ssc_twin

        def own(r):  # along the edge, toward the object below P_ref
            p, law = r["p_pa"], r["law"]
            gx, gy = -0.5 * (p[1] + p[2] - p[0] - p[3]), 0.5 * (p[2] + p[3] - p[0] - p[1])
            g = math.hypot(gx, gy)
            if g < law["p_noise_pa"]:
                return (0.0, 0.0)
            toward = 2.0 * math.log10(law["pref_pa"] / max(sum(p) / 4, 1.0))
            fx, fy = -gy / g + toward * gx / g, gx / g + toward * gy / g
            f = math.hypot(fx, fy) / (law["step_mm"] * 1e-3)
            return (fx / f, fy / f)

        r = ssc_twin.run_trial(scene="disk_benchmark_gantry", controller=own, keep_log=False)
        self.assertEqual(r["outcome"], "success", r["detail"])

        def raises(r):
            if r["iteration"] == 2:
                raise RuntimeError("lost the plot")
            return (0.001, 0.0)

        r = ssc_twin.run_trial(scene="disk_benchmark_gantry", controller=raises, keep_log=False)
        self.assertEqual(r["outcome"], "controller_fault")
        self.assertIn("RuntimeError: lost the plot", r["detail"])
        self.assertEqual(r["metrics"]["iterations"], 3)
        r = ssc_twin.run_trial(
            scene="disk_benchmark_gantry", controller=lambda r: "step", keep_log=False, timeout_s=2
        )
        self.assertEqual(r["outcome"], "controller_fault")
        self.assertIn("returned a str", r["detail"])
        with self.assertRaisesRegex(ValueError, "unknown key 'nope'"):
            ssc_twin.run_trial(controller="fast", controller_params="nope=1")
        self.assertIn("fast", ssc_twin.controllers())

        class Leave:  # one instance per trial, answering with a dict: steps off the edge
            def __init__(self):
                self.calls = 0

            def __call__(self, r):
                self.calls += 1
                return {"step_m": (0.004, 0.0), "height_offset_m": 0.0, "lifted": False}

        path = os.path.join(self.tmp, "python_controller_sweep.csv")
        s = ssc_twin.sweep(
            pref=[100],
            beta=[2],
            step_mm=[7.5],
            repeats=2,
            seed=5,
            threads=2,
            out_csv=path,
            controller=Leave,
        )
        self.assertEqual(s["ran"], 2)
        outcomes = set(ssc_twin.read_sweep(path)["outcome"])
        self.assertTrue(outcomes <= {"failure_I", "failure_II", "lost_edge"}, outcomes)

    @unittest.skipUnless(SSC, "no ssc executable given")
    def test_validate_equals_the_cli(self):
        import ssc_twin

        # A tiny map: two cells, 3 seeds each (the least validate takes), a shorter follow limit.
        # The twin succeeds in the first and grasps (failure II) in the second: one class match.
        map_csv = os.path.join(self.tmp, "tiny_map.csv")
        with open(map_csv, "w") as f:
            f.write("step_mm,beta,pref_pa,successes_of_3\n7.5,2,100,3\n7.5,2,1000,2\n")
        seeds, seed, timeout_s = 3, 4, VALIDATE_TIMEOUT_S
        cli_dir = os.path.join(self.tmp, "validate_cli")
        r = run(
            [
                SSC,
                "validate",
                "--map",
                map_csv,
                "--seeds",
                str(seeds),
                "--seed",
                str(seed),
                "--timeout",
                str(timeout_s),
                "--threads",
                "2",
                "--no-plot",
                "--no-progress",
                "--out",
                cli_dir,
            ]
        )
        self.assertEqual(r.returncode, 0, r.stderr)
        py_dir = os.path.join(self.tmp, "validate_py")
        py = ssc_twin.validate(
            map_csv, out_dir=py_dir, seeds=seeds, seed=seed, threads=2, timeout_s=timeout_s
        )
        self.assertEqual(py["summary"]["ran"], 2 * seeds)

        # The same trials: every outcome and seed (rows land in finishing order; sort them).
        def trials(folder):
            with open(os.path.join(folder, "trials.csv")) as f:
                rows = list(csv.DictReader(f))

            def key(r):
                return (float(r["pref_pa"]), float(r["beta"]), int(r["repeat"]))

            return [(key(r), r["seed"], r["outcome"]) for r in sorted(rows, key=key)]

        self.assertEqual(trials(py_dir), trials(cli_dir))
        self.assertEqual(len(trials(cli_dir)), 2 * seeds)

        # The scores: validate.json's values, exactly (the same doubles).
        with open(os.path.join(cli_dir, "validate.json")) as f:
            cli = json.load(f)
        for key, value in py["scores"].items():
            self.assertEqual(value, cli[key], key)
        for key in ("seeds_per_cell", "base_seed", "effects", "scene"):
            self.assertEqual(py[key], cli[key], key)
        # The map's ceilings (what any twin can expect), the same doubles as validate.json's.
        self.assertEqual(len(py["ceilings"]), 3)
        for mine, theirs in zip(py["ceilings"], cli["ceilings"]):
            for key, value in mine.items():
                self.assertEqual(value, theirs[key], key)

        # The cells: every cells.csv column (printed to 6 significant digits), in map order.
        with open(os.path.join(cli_dir, "cells.csv")) as f:
            rows = list(csv.DictReader(f))
        cells = py["cells"]
        self.assertEqual(len(rows), 2)
        self.assertEqual(cells["p_success"].shape, (2,))
        for column in rows[0]:
            if column in ("published", "twin_class", "main_failure"):
                self.assertEqual(cells[column], [r[column] for r in rows], column)
            else:
                np.testing.assert_allclose(
                    cells[column],
                    [float(r[column]) for r in rows],
                    rtol=6e-6,
                    atol=1e-12,
                    err_msg=column,
                )
        self.assertEqual(cells["trials"].tolist(), [seeds, seeds])
        self.assertEqual(
            cells["class_match"].tolist(),
            [p == t for p, t in zip(cells["published"], cells["twin_class"])],
        )

        # Resumable like the CLI: a second call reruns nothing and scores the same.
        again = ssc_twin.validate(
            map_csv, out_dir=py_dir, seeds=seeds, seed=seed, timeout_s=timeout_s
        )
        self.assertEqual((again["summary"]["ran"], again["summary"]["skipped"]), (0, 2 * seeds))
        self.assertEqual(again["scores"], py["scores"])
        with self.assertRaisesRegex(Exception, "seeds = 2 is out of range"):
            ssc_twin.validate(map_csv, out_dir=py_dir, seeds=2)

    def test_probe_grasps_on_the_plate_and_reads_ambient_in_air(self):
        import ssc_twin

        probe = ssc_twin.Probe()
        on = probe.read(-0.03, 0.0)  # well inside the plate
        off = probe.read(0.05, 0.0)  # beyond its edge, over the table
        self.assertTrue(np.all(on["filtered_pa"] > 10000), on)
        self.assertLess(float(np.abs(off["filtered_pa"]).max()), 50.0, off)
        self.assertEqual(on["filtered_pa"].shape, (4,))

    def test_compare_replays_a_twin_log(self):
        import ssc_twin

        log_dir = os.path.join(self.tmp, "robot_log")
        # The ideal loop (effects off): the replay is compared with a run it can reproduce.
        self.assertEqual(ssc_twin.write_robot_log(log_dir, seed=2, effects="off"), "success")
        # average=1: the twin's pressures already carry the host's filter.
        c = ssc_twin.compare(log_dir, out_dir=os.path.join(self.tmp, "compare"), average=1)
        self.assertEqual(c["sim_pa"].shape, c["log_pa"].shape)
        self.assertGreater(c["sim_pa"].shape[0], 100)
        self.assertTrue(np.all(c["correlation"] > 0.9), c["correlation"])
        with self.assertRaisesRegex(Exception, "moving average of 0 samples"):
            ssc_twin.compare(log_dir, out_dir=os.path.join(self.tmp, "compare0"), average=0)

    def test_plugin_loads_once_when_asked_twice(self):
        # import mujoco registered the plugin (entry point); loading it again by hand is what
        # raised "already registered". load_plugin() is safe any number of times.
        script = (
            "import mujoco, ssc_twin\n"
            "print('loaded', ssc_twin.load_plugin(), ssc_twin.load_plugin(),\n"
            "      ssc_twin.load_plugin(ssc_twin.plugin_library()))\n"
            "m = mujoco.MjModel.from_xml_path(ssc_twin.scene_path('probe_edge'))\n"
            "print('plugins', m.nplugin)\n"
        )
        r = run([sys.executable, "-c", script], cwd=self.tmp)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("loaded False False False", r.stdout)
        self.assertIn("plugins 1", r.stdout)
        # Another copy of the library (e.g. build/lib's): load_plugin() leaves it alone, a bare
        # mj_loadPluginLibrary registers the name a second time, which MuJoCo refuses.
        copy = os.path.join(self.tmp, "libssc_plugin_copy.so")
        import ssc_twin

        shutil.copy(ssc_twin.plugin_library(), copy)
        script = "import mujoco, ssc_twin\nprint('loaded', ssc_twin.load_plugin(%r))\n" % copy
        r = run([sys.executable, "-c", script], cwd=self.tmp)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("loaded False", r.stdout)
        bare = "import mujoco\nmujoco.mj_loadPluginLibrary(%r)\n" % copy
        r = run([sys.executable, "-c", bare], cwd=self.tmp)
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("already registered", r.stderr)

    @unittest.skipUnless(XVFB, "xvfb-run not installed")
    def test_mujoco_viewer_opens_our_scene(self):
        import ssc_twin

        cmd = [
            XVFB,
            "-a",
            "-s",
            "-screen 0 1024x768x24",
            "timeout",
            "12",
            sys.executable,
            "-m",
            "mujoco.viewer",
            "--mjcf=" + ssc_twin.scene_path("disk_benchmark"),
        ]
        r = run(cmd, timeout=60, cwd=self.tmp)
        # Still running when the timeout ended it: the scene loaded and the window stayed up.
        self.assertEqual(r.returncode, 124, r.stderr[-2000:])
        self.assertNotIn("not found", r.stderr)
        self.assertNotIn("Error", r.stderr)


class EdgeFollowingTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        import gymnasium as gym
        from ssc_twin.edge_following import PublishedLawPolicy

        cls.gym, cls.policy = gym, PublishedLawPolicy

    def episode(self, env, policy, seed, options=None):
        obs, info = env.reset(seed=seed, options=options)
        total, steps = 0.0, 0
        while True:
            obs, reward, terminated, truncated, info = env.step(policy(obs))
            total += reward
            steps += 1
            if terminated or truncated:
                return info, total, steps

    def test_environment_passes_the_checker(self):
        from gymnasium.utils.env_checker import check_env

        env = self.gym.make("ssc_twin/EdgeFollowing-v0", include_ft=True)
        check_env(env.unwrapped, skip_render_check=True)  # rendering: the tests below
        self.assertEqual(env.observation_space.shape, (10,))

    def test_published_law_succeeds_on_the_disk(self):
        env = self.gym.make("ssc_twin/EdgeFollowing-v0")
        law = self.policy(env, pref=100, beta=2, step_mm=7.5)
        info, total, steps = self.episode(env, law, seed=1)
        self.assertEqual(info["outcome"], "success", info)
        self.assertGreater(info["progress_mm"], 200)  # ~2 pi x 33 mm round the disk
        self.assertGreater(total, 20)

    def test_random_policy_does_not(self):
        env = self.gym.make("ssc_twin/EdgeFollowing-v0")
        env.action_space.seed(7)

        def random_policy(obs):
            return env.action_space.sample()

        for seed in range(3):
            info, total, _ = self.episode(env, random_policy, seed=seed)
            self.assertNotEqual(info["outcome"], "success", info)
            self.assertLess(total, 5)

    def test_controller_runs_in_the_loop(self):
        def zero(obs):
            return np.zeros(2, dtype=np.float32)

        env = self.gym.make("ssc_twin/EdgeFollowing-v0", controller="published", effects="off")
        info, total, steps = self.episode(env, zero, seed=1)
        self.assertEqual(info["outcome"], "success", info)  # a zero action: the law as it is
        self.assertGreater(info["progress_mm"], 200)
        self.assertNotEqual(info["controller_step_m"], (0.0, 0.0))

        # The action adds to the controller's step: pushing off the object every step loses it.
        def outward(obs):
            return np.array([0.0, -1.0], dtype=np.float32)

        info, _, _ = self.episode(env, outward, seed=1)
        self.assertIn(info["outcome"], ("failure_I", "lost_edge"), info)

        class Broken:  # a Python controller: one instance per episode
            def __call__(self, reading):
                return (float("nan"), 0.0)

        env = self.gym.make("ssc_twin/EdgeFollowing-v0", controller=Broken)
        obs, info = env.reset(seed=1)
        obs, reward, terminated, truncated, info = env.step(zero(obs))
        self.assertTrue(terminated)
        self.assertEqual(info["outcome"], "controller_fault", info)
        with self.assertRaisesRegex(ValueError, "step_max_mm"):
            self.gym.make(
                "ssc_twin/EdgeFollowing-v0", controller="fast", controller_params="step_max_mm=99"
            )
        with self.assertRaisesRegex(ValueError, "controller"):
            self.gym.make("ssc_twin/EdgeFollowing-v0", controller="no_such")
        with self.assertRaisesRegex(ValueError, "controller_params"):
            self.gym.make("ssc_twin/EdgeFollowing-v0", controller_params="gain=1")

    def test_scene_option_runs_the_named_scene(self):
        import mujoco

        arm = self.gym.make("ssc_twin/EdgeFollowing-v0", scene="disk_benchmark", effects="off")
        obs, info = arm.reset(seed=1)
        model, data = arm.unwrapped.model, arm.unwrapped.data
        self.assertIsInstance(model, mujoco.MjModel)
        self.assertIsInstance(data, mujoco.MjData)

        def body(m, name):
            return mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, name)

        self.assertGreaterEqual(body(model, "shoulder_link"), 0)  # the UR-10
        self.assertLess(body(model, "gantry_x"), 0)
        # The live data: the trial's clock and the cup where the info says.
        self.assertEqual(data.time, info["time_s"])
        site = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_SITE, "ssc_tool_site")
        np.testing.assert_allclose(data.site_xpos[site][:2], info["tool_xy_m"])
        shoulder = data.joint(0).qpos.copy()
        law = self.policy(arm, pref=100, beta=2, step_mm=7.5)
        for _ in range(3):
            obs, reward, terminated, truncated, info = arm.step(law(obs))
        self.assertFalse(terminated or truncated, info)
        self.assertNotEqual(float(data.joint(0).qpos[0]), float(shoulder[0]))  # the arm moved
        gantry = self.gym.make("ssc_twin/EdgeFollowing-v0")
        gantry.reset(seed=1)
        self.assertGreaterEqual(body(gantry.unwrapped.model, "gantry_x"), 0)
        with self.assertRaisesRegex(ValueError, "scene 'no_such_scene' not found"):
            self.gym.make("ssc_twin/EdgeFollowing-v0", scene="no_such_scene")
        with self.assertRaisesRegex(ValueError, "render_mode"):
            self.gym.make("ssc_twin/EdgeFollowing-v0", render_mode="rgb")

    def render_in_subprocess(self, script, use_xvfb):
        env = dict(os.environ)
        cmd = [sys.executable, "-c", script]
        if use_xvfb:
            cmd = [XVFB, "-a", "-s", "-screen 0 1024x768x24"] + cmd
        else:
            env["MUJOCO_GL"] = "egl"
        return run(cmd, timeout=180, env=env)

    def test_rgb_array_frame_shows_the_cup_close_up(self):
        script = textwrap.dedent("""
            import json, gymnasium as gym, numpy as np, ssc_twin
            env = gym.make("ssc_twin/EdgeFollowing-v0", render_mode="rgb_array", width=160,
                           height=120)
            obs, info = env.reset(seed=1)
            frame = env.render()
            r, g, b = (frame[..., k].astype(float) for k in range(3))
            cup = (r > 90) & (r > 1.3 * g) & (g > 1.3 * b)   # the orange cup
            disk = (b > 120) & (b > 1.5 * r)                 # the blue disk
            ys, xs = np.nonzero(cup)
            print(json.dumps({"shape": frame.shape, "dtype": str(frame.dtype),
                              "cup_px": int(cup.sum()), "disk_px": int(disk.sum()),
                              "cup_centre": [float(xs.mean()), float(ys.mean())] if len(xs) else None,
                              "fps": env.metadata["render_fps"]}))
            env.close()
            """)
        r = self.render_in_subprocess(script, use_xvfb=False)
        if r.returncode != 0 and XVFB:  # no EGL: GLFW under Xvfb
            r = self.render_in_subprocess(script, use_xvfb=True)
        self.assertEqual(r.returncode, 0, r.stderr[-2000:])
        out = json.loads(r.stdout.strip().splitlines()[-1])
        self.assertEqual(out["shape"], [120, 160, 3])
        self.assertEqual(out["dtype"], "uint8")
        self.assertAlmostEqual(out["fps"], 1 / 0.15, places=6)
        # The close-up follows the cup: cup and disk large, the cup near the middle.
        self.assertGreater(out["cup_px"], 0.01 * 120 * 160, out)
        self.assertGreater(out["disk_px"], 0.03 * 120 * 160, out)
        self.assertLess(abs(out["cup_centre"][0] - 80), 40, out)

    @unittest.skipUnless(XVFB, "xvfb-run not installed")
    def test_human_mode_opens_a_window_and_closes_cleanly(self):
        script = textwrap.dedent("""
            import gymnasium as gym, numpy as np, ssc_twin
            env = gym.make("ssc_twin/EdgeFollowing-v0", render_mode="human", width=320,
                           height=240)
            obs, info = env.reset(seed=1)
            for _ in range(3):
                env.step(np.zeros(2, dtype=np.float32))
            print("window open", not env.unwrapped._viewer.closed)
            env.close()
            """)
        r = self.render_in_subprocess(script, use_xvfb=True)
        self.assertEqual(r.returncode, 0, r.stderr[-2000:])  # no crash at interpreter exit
        self.assertIn("window open True", r.stdout)

    def test_episodes_on_test_objects_start_at_their_edge(self):
        env = self.gym.make("ssc_twin/EdgeFollowing-v0", objects=["volute", "hole_d14"])
        for name in ("volute", "hole_d14"):
            obs, info = env.reset(seed=0, options={"object": name})
            self.assertEqual(info["object"], name)
            self.assertEqual(info["phase"], "follow")
            self.assertLess(abs(info["contour_distance_mm"]), 6.0, info)  # started at the edge
            obs, reward, *_ = env.step(np.zeros(2, dtype=np.float32))
            self.assertTrue(np.isfinite(reward))
            self.assertTrue(env.observation_space.contains(obs))


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
