"""ssc_twin.sil: the stand-ins' contracts, each alone, and the loop closed with a lab-style script.

    SSC_BIN=build/bin/ssc python sil_test.py [unittest arguments]

Runs where the ssc_twin package is installed (the python_package CTest's venv). The test that
runs the lab's own script needs a checkout of the lab's repository given as $SSC_LAB_REPO and is
skipped, saying so, without one.
"""

import importlib
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time
import unittest

import numpy as np

import ssc_twin
from ssc_twin.sil import world as world_mod

HERE = os.path.dirname(os.path.abspath(__file__))
LAB_STYLE = os.path.join(HERE, "..", "..", "tests", "sil", "lab_style_disk.py")
SSC = os.environ.get("SSC_BIN")  # the ssc CLI (else python -m ssc_twin.sil, no compare)


def fresh_world(tmp):
    """A new virtual-time world on the gantry disk scene, the stand-ins importable."""
    w = world_mod.install(world_mod.World(tmp_dir=tmp))
    for name in ("rospy", "tf", "rtde_control", "rtde_receive"):
        importlib.import_module(name)
    return w


class SilContracts(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="ssc_sil_test_")
        self.addCleanup(shutil.rmtree, self.tmp, True)
        self.world = fresh_world(self.tmp)

    def test_subscriber_receives_packets_at_sensor_rate(self):
        import rospy
        from suction_cup.msg import SensorPacket, cmdPacket

        got = []
        rospy.Subscriber("SensorPacket", SensorPacket, got.append)
        rospy.sleep(0.5)
        self.assertEqual(got, [], "the board streams only after its start command")
        rospy.Publisher("cmdPacket", cmdPacket, queue_size=1).publish(cmdPacket(cmdInput=2))
        t0 = rospy.get_time()
        rospy.sleep(2.0)
        rate = self.world.plant.sample_rate_hz
        self.assertAlmostEqual(len(got) / (rospy.get_time() - t0), rate, delta=1.0)
        stamps = np.array([m.header.stamp.to_sec() for m in got])
        self.assertTrue(np.allclose(np.diff(stamps), 1.0 / rate, atol=2.5e-3))
        # Absolute pressures in Pa near the ambient (the cup is in air), four chambers.
        self.assertEqual(got[-1].ch, 4)
        self.assertTrue(all(90000 < p < 110000 for p in got[-1].data), got[-1].data)

    def test_service_starts_and_stops_logger(self):
        import rospy
        from std_msgs.msg import Int8
        from suction_cup.msg import cmdPacket
        from suction_cup.srv import Enable

        pwm = rospy.Publisher("pwm", Int8, queue_size=1)
        rospy.Publisher("cmdPacket", cmdPacket, queue_size=1).publish(cmdPacket(cmdInput=2))
        rospy.wait_for_service("data_logging")
        enable = rospy.ServiceProxy("data_logging", Enable)
        rospy.sleep(0.2)
        self.assertEqual(os.listdir(self.tmp), [], "nothing is written before logging starts")
        names = enable(True).OutputFileName.split()
        pwm.publish(30)
        rospy.sleep(1.0)
        enable(False)
        rospy.sleep(1.0)
        files = sorted(os.listdir(self.tmp))
        self.assertEqual(len(files), 4, files)  # /sync has no publisher: no file
        self.assertEqual(sorted(os.path.basename(n) for n in names), files)
        by_topic = {f.split("__")[-1]: os.path.join(self.tmp, f) for f in files}
        with open(by_topic["SensorPacket.csv"]) as f:
            lines = f.read().splitlines()
        self.assertEqual(
            lines[0],
            "ROStimestamp,/SensorPacket.ch,/SensorPacket.data[0],"
            "/SensorPacket.data[1],/SensorPacket.data[2],/SensorPacket.data[3]",
        )
        rate = self.world.plant.sample_rate_hz
        self.assertAlmostEqual(len(lines) - 1, rate * 1.0, delta=2)  # only while enabled
        stamp, ch, rest = lines[1].split(",", 2)
        self.assertTrue(stamp.isdigit() and len(stamp) == 19 and ch == "4")
        self.assertEqual(len(rest.split(", ")), 4)  # array elements joined by ", "
        with open(by_topic["endEffectorPose.csv"]) as f:
            header = f.readline().strip().split(",")
        self.assertEqual(
            header[1:],
            [
                "/endEffectorPose.pose.orientation.w",
                "/endEffectorPose.pose.orientation.x",
                "/endEffectorPose.pose.orientation.y",
                "/endEffectorPose.pose.orientation.z",
                "/endEffectorPose.pose.position.x",
                "/endEffectorPose.pose.position.y",
                "/endEffectorPose.pose.position.z",
            ],
        )
        with open(by_topic["pwm.csv"]) as f:
            self.assertEqual(f.read().splitlines()[1].split(",")[1], "30")
        # A second start opens a new recording.
        rospy.sleep(1.1)
        enable(True)
        enable(False)
        self.assertEqual(len(os.listdir(self.tmp)), 8)

    def test_recording_saves_as_the_labs_mat(self):
        import rospy
        from suction_cup.msg import cmdPacket
        from suction_cup.srv import Enable
        from ssc_twin.sil import save_data_params

        rospy.Publisher("cmdPacket", cmdPacket, queue_size=1).publish(cmdPacket(cmdInput=2))
        enable = rospy.ServiceProxy("data_logging", Enable)
        enable(True)
        rospy.sleep(1.0)
        history = [
            [
                0.1,
                -0.63,
                0.097,
                np.array([1.0, 0.0]),
                np.array([0.0, 1.0]),
                np.array([1.0, 0.0]),
                -1.1,
                -90.0,
                -95.0,
                -100.0,
                -105.0,
            ]
        ]
        path = save_data_params(
            {"Pref": 100, "beta": 2.0, "d_lat": 7.5e-3, "edgeFollowing_history": history},
            "sil_test",
            mat_dir=self.tmp,
        )
        enable(False)
        self.assertRegex(os.path.basename(path), r"^DataLog_\d{4}_\d{4}_\d{6}_sil_test\.mat$")
        from scipy.io import loadmat

        m = loadmat(path)
        self.assertEqual(m["SensorPacket_data"].shape[1], 6)
        self.assertAlmostEqual(
            m["SensorPacket_data"].shape[0], self.world.plant.sample_rate_hz, delta=2
        )
        self.assertEqual(m["endEffectorPose_data"].shape[1], 8)
        self.assertEqual(int(np.ravel(m["Pref"])[0]), 100)
        self.assertAlmostEqual(float(np.ravel(m["d_lat"])[0]), 7.5e-3)
        self.assertEqual(m["edgeFollowing_history"].shape, (1, 11))

    def test_moveL_reaches_its_target(self):
        import rospy
        import rtde_control
        import rtde_receive

        c = rtde_control.RTDEControlInterface("10.0.0.1", 125)
        r = rtde_receive.RTDEReceiveInterface("10.0.0.1", 125)
        c.setTcp([0, 0, 0.146, 0, 0, 0])
        start = r.getActualTCPPose()
        goal = list(start)
        goal[0] += 0.02
        goal[2] += 0.01
        t0 = rospy.get_time()
        self.assertTrue(c.moveL(goal, 0.05, 0.5))
        took = rospy.get_time() - t0
        now = r.getActualTCPPose()
        self.assertLess(np.linalg.norm(np.subtract(now[:3], goal[:3])), 0.2e-3)
        # At 0.05 m/s the 22.4 mm move takes at least 0.45 s of simulated time.
        self.assertGreater(took, np.hypot(0.02, 0.01) / 0.05)
        # tf and RTDE agree: tool0 in base_link is the TCP turned 180 deg about z, 146 mm up.
        import tf

        trans, _ = tf.TransformListener().lookupTransform("/base_link", "/tool0", rospy.Time(0))
        self.assertAlmostEqual(trans[0], -now[0], places=6)
        self.assertAlmostEqual(trans[1], -now[1], places=6)
        self.assertAlmostEqual(trans[2], now[2] + 0.146, places=4)

    def test_virtual_time_advances_with_sleep(self):
        import rospy

        wall0, t0 = time.perf_counter(), rospy.get_time()
        rospy.sleep(3.0)
        self.assertAlmostEqual(rospy.get_time() - t0, 3.0, delta=self.world.plant.timestep)
        rate = rospy.Rate(10)
        t1 = rospy.get_time()
        for _ in range(5):
            rate.sleep()
        self.assertAlmostEqual(rospy.get_time() - t1, 0.5, delta=self.world.plant.timestep)
        # Virtual: the 3.5 simulated seconds took less wall time than they simulate.
        self.assertLess(time.perf_counter() - wall0, 3.5)

    def test_the_arm_and_the_packets_go_on_during_a_plot_pause(self):
        # The UR's servo thread keeps tracking the last servoL target and the board keeps
        # streaming while the script redraws its plot (plt.pause).
        import rospy
        import rtde_control
        import rtde_receive
        from suction_cup.msg import SensorPacket, cmdPacket
        from ssc_twin.sil import noop

        got = []
        rospy.Subscriber("SensorPacket", SensorPacket, got.append)
        rospy.Publisher("cmdPacket", cmdPacket, queue_size=1).publish(cmdPacket(cmdInput=2))
        c = rtde_control.RTDEControlInterface("10.0.0.1", 125)
        r = rtde_receive.RTDEReceiveInterface("10.0.0.1", 125)
        c.setTcp([0, 0, 0.146, 0, 0, 0])
        rospy.sleep(0.2)
        start = r.getActualTCPPose()
        goal = list(start)
        goal[0] += 0.005
        c.servoL(goal, 0.0, 0.0, 0.05, 0.2, 100.0)
        self.assertAlmostEqual(
            r.getActualTCPPose()[0],
            start[0],
            delta=1e-6,
            msg="servoL returns at once, as ur_rtde's does",
        )
        self.world.pause_cost_s = 0.1
        n0, t0 = len(got), rospy.get_time()
        noop._pause(0.01)
        self.assertAlmostEqual(rospy.get_time() - t0, 0.11, delta=self.world.plant.timestep)
        moved = r.getActualTCPPose()[0] - start[0]
        self.assertGreater(moved, 0.3 * 0.005, "the arm did not servo during the pause")
        self.assertLess(moved, 0.005)
        self.assertAlmostEqual(len(got) - n0, 0.11 * self.world.plant.sample_rate_hz, delta=1.5)

    def test_a_measured_pause_charges_the_scripts_cpu_time(self):
        import rospy
        from ssc_twin.sil import noop

        self.world.pause_cost_s = world_mod.MEASURED
        rospy.sleep(0.01)
        c0, x = time.process_time(), 0
        while time.process_time() - c0 < 0.05:  # the script building its plot
            x += 1
        t0 = rospy.get_time()
        noop._pause(0.01)
        took = rospy.get_time() - t0
        self.assertGreaterEqual(took, 0.06 - self.world.plant.timestep)
        self.assertLess(took, 0.5)
        self.assertEqual(len(self.world.pause_log), 1)
        self.assertGreaterEqual(self.world.pause_log[0][0], 0.05)


def run_sil(args, cwd):
    cmd = [SSC, "sil"] if SSC else [sys.executable, "-m", "ssc_twin.sil"]
    env = dict(os.environ, SSC_PYTHON=sys.executable)
    return subprocess.run(cmd + args, cwd=cwd, env=env, capture_output=True, text=True, timeout=600)


class SilBounds(unittest.TestCase):
    """Every script ends, every failure is one 'ssc sil:' line with its documented code, and
    nothing the script starts or writes outlives the run or lands outside OUT."""

    def setUp(self):
        self.out = tempfile.mkdtemp(prefix="ssc_sil_bounds_")
        self.addCleanup(shutil.rmtree, self.out, True)

    def script(self, text, name="s.py"):
        path = os.path.join(self.out, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def sil(self, *args, timeout=120):
        start = time.monotonic()
        p = run_sil(["--out", os.path.join(self.out, "run")] + list(args), self.out)
        self.assertLess(time.monotonic() - start, timeout, p.stdout + p.stderr)
        return p

    def assert_one_line(self, p, code, text):
        self.assertEqual(p.returncode, code, p.stdout + p.stderr)
        self.assertIn(text, p.stdout + p.stderr)
        self.assertNotIn("Traceback", p.stderr)

    def test_a_sleep_loop_after_shutdown_ends(self):
        p = self.sil("--max-sim", "2", self.script("import time\nwhile True:\n    time.sleep(1)\n"))
        self.assert_one_line(p, 1, "calls to a sleep after the node shut down in a row")

    def test_an_input_loop_ends(self):
        p = self.sil(self.script("while True:\n    input('go? ')\n"))
        self.assertEqual(p.returncode, 1, p.stderr[-2000:])
        self.assertIn("calls to input() in a row", p.stdout)

    def test_a_busy_loop_ends_at_the_wall_clock_limit(self):
        p = self.sil("--max-wall", "2", self.script("while True:\n    pass\n"), timeout=30)
        self.assertEqual(p.returncode, 1, p.stderr[-2000:])
        self.assertIn("the wall-clock limit (--max-wall 2 s)", p.stdout)

    def test_a_script_that_swallows_the_stop_still_ends(self):
        text = (
            "while True:\n    try:\n        while True:\n            pass\n"
            "    except BaseException:\n        pass\n"
        )
        report = os.path.join(self.out, "report.json")
        p = self.sil("--max-wall", "1", "--report", report, self.script(text), timeout=40)
        self.assertEqual(p.returncode, 1, p.stderr[-2000:])
        with open(report) as f:
            self.assertIn("wall-clock limit", json.load(f)["stopped_by"])

    def test_children_end_with_the_run_and_temp_files_stay_in_out(self):
        text = (
            "import subprocess, tempfile\n"
            "p = subprocess.Popen(['sleep', '300'])\n"
            "open('child.pid', 'w').write(str(p.pid))\n"
            "fd, path = tempfile.mkstemp()\n"
            "open('temp.path', 'w').write(path)\n"
        )
        p = self.sil(self.script(text))
        # The script ran to its end without touching anything: the trial failed (exit 5).
        self.assertEqual(p.returncode, 5, p.stdout + p.stderr)
        self.assertIn("the trial: never touched the object", p.stdout)
        self.assertIn("ended 1 process(es) the script left running", p.stdout)
        with open(os.path.join(self.out, "child.pid")) as f:
            pid = int(f.read())
        with open(os.path.join(self.out, "temp.path")) as f:
            temp = f.read()
        self.assertFalse(os.path.exists("/proc/%d" % pid), "the script's child outlived the run")
        self.assertTrue(temp.startswith(os.path.join(self.out, "run", "tmp") + os.sep), temp)

    def test_bad_scripts_and_reports_are_one_line_each(self):
        fifo = os.path.join(self.out, "fifo.py")
        os.mkfifo(fifo)
        binary = os.path.join(self.out, "bin.py")
        with open(binary, "wb") as f:
            f.write(b"\x7fELF\x00\x01")
        cases = [
            ([self.script("def (:\n", "syntax.py")], 4, "syntax.py:1: not valid Python"),
            ([binary], 4, "not Python source (binary data)"),
            ([self.out], 4, "is a directory, not a script"),
            ([fifo], 4, "not a regular file"),
            ([os.path.join(self.out, "absent.py")], 3, "no such file"),
            (
                [self.script("from rospy import no_such_name\n", "name.py")],
                6,
                "the twin's stand-in lacks it",
            ),
            (
                [
                    "--report",
                    os.path.join(self.out, "no", "r.json"),
                    self.script("x = 1\n", "ok.py"),
                ],
                2,
                "--report",
            ),
            (
                ["--set", "x=1", "--set", "x=2", self.script("x = 0\n", "knob.py")],
                2,
                "--set x: given twice",
            ),
        ]
        for args, code, text in cases:
            with self.subTest(args=args):
                start = time.monotonic()
                p = self.sil(*args)
                self.assert_one_line(p, code, text)
                self.assertIn("ssc sil: ", p.stdout + p.stderr)
                self.assertLess(time.monotonic() - start, 30)
        self.assertFalse(os.path.exists(os.path.join(self.out, "no")))

    def test_a_file_size_limit_is_named_not_a_traceback(self):
        text = "with open('big.bin', 'wb') as f:\n    f.write(b'x' * (1 << 20))\n"
        script = self.script(text)
        cmd = [SSC, "sil"] if SSC else [sys.executable, "-m", "ssc_twin.sil"]
        import resource

        def limit():
            resource.setrlimit(resource.RLIMIT_FSIZE, (1 << 16, 1 << 16))

        p = subprocess.run(
            cmd + ["--out", os.path.join(self.out, "run"), script],
            cwd=self.out,
            env=dict(os.environ, SSC_PYTHON=sys.executable),
            capture_output=True,
            text=True,
            timeout=120,
            preexec_fn=limit,
        )
        self.assert_one_line(p, 1, "the disk is full or a size limit was hit")


class VerdictUnit(unittest.TestCase):
    """The SIL's verdict alone, on made-up samples: the trial's outcomes in the trial's order."""

    def run_path(self, vacuum_of, force_n=1.8, turns=1.0, centre=(0.65, 0.0), r=0.033, n=400):
        from ssc_twin.sil.verdict import Verdict

        v = Verdict(centre)
        v.add(0.0, [0.0] * 4, (0, 0), 0.3)  # in air: the F/T's tare
        for i in range(n + 1):
            a = 2 * math.pi * turns * i / n
            xy = (centre[0] + r * math.cos(a), centre[1] + r * math.sin(a)) if centre else (0, 0)
            v.add(0.01 * i, vacuum_of(i), xy, force_n)
        return v

    def test_a_loop_in_contact_is_a_success_either_way_round(self):
        for turns in (1.0, -1.0):
            v = self.run_path(lambda i: [300, 150, 200, 250], turns=turns)
            self.assertEqual(v.final(), "success")
            self.assertGreater(abs(v.summary()["swept_deg"]), 355)

    def test_each_failure_and_the_untouched_cup(self):
        grasp = self.run_path(lambda i: [20000] * 4 if i > 100 else [300] * 4)
        self.assertEqual(grasp.final(), "failure_II")
        off = self.run_path(lambda i: [0.0] * 4 if i > 100 else [300] * 4)
        self.assertEqual(off.final(), "failure_I")
        air = self.run_path(lambda i: [8.2] * 4, force_n=0.3)  # the tare: nothing pressed
        self.assertEqual(air.final(), "never_touched")
        self.assertAlmostEqual(air.summary()["peak_vacuum_pa"], 8.2)
        half = self.run_path(lambda i: [300] * 4, turns=0.5)
        self.assertEqual(half.final(), "timeout")
        no_disk = self.run_path(lambda i: [300] * 4, centre=None)
        self.assertEqual(no_disk.final(), "timeout")


class LimitsUnit(unittest.TestCase):
    """The stuck rule alone: no simulated time for the stuck span stops the script; a waiting
    operator does not count."""

    class FakeWorld:
        sim_time = 0.0

    def test_no_simulated_time_for_the_stuck_span_stops(self):
        from ssc_twin.sil import limits

        w = self.FakeWorld()
        lim = limits.Limits(
            w, max_wall_s=60, stuck_wall_s=0.2, max_idle_calls=10, grace_s=1, give_up=lambda: None
        )
        lim._tick(None, None)
        w.sim_time = 1.0
        time.sleep(0.25)
        lim._tick(None, None)  # the clock moved: progress
        lim.waiting_for_operator = True
        time.sleep(0.25)
        lim._tick(None, None)  # waiting for a key press is not stuck
        lim.waiting_for_operator = False
        time.sleep(0.25)
        with self.assertRaises(limits.RunLimit) as e:
            lim._tick(None, None)
        self.assertIn("no simulated time passed", str(e.exception))
        with self.assertRaises(limits.RunLimit):  # raised again at every tick
            lim._tick(None, None)


class SilLoop(unittest.TestCase):
    def test_lab_style_script_completes_a_disk_trial_and_opens_in_compare(self):
        out = tempfile.mkdtemp(prefix="ssc_sil_loop_")
        self.addCleanup(shutil.rmtree, out, True)
        report = os.path.join(out, "report.json")
        p = run_sil(["--out", out, "--report", report, LAB_STYLE], out)
        self.assertEqual(p.returncode, 0, p.stdout[-3000:] + p.stderr[-3000:])
        self.assertIn("lab_style_disk: success 1", p.stdout)
        self.assertIn("the trial: success", p.stdout)
        with open(report) as f:
            summary = json.load(f)
        self.assertEqual(summary["verdict"]["outcome"], "success", summary)
        self.assertGreater(abs(summary["verdict"]["swept_deg"]), 355)
        self.assertEqual(len(summary["mat_files"]), 1, summary)
        mat = summary["mat_files"][0]
        self.assertRegex(
            os.path.basename(mat),
            r"^DataLog_\d{4}_\d{4}_\d{6}_seb_testEdgeFollowing_"
            r"refP_100.0_beta_2.0_step_0.0075_deleteMe\.mat$",
        )
        if SSC:
            c = subprocess.run(
                [SSC, "compare", mat, "--out", os.path.join(out, "compare")],
                capture_output=True,
                text=True,
                timeout=600,
            )
            self.assertEqual(c.returncode, 0, c.stdout[-3000:] + c.stderr[-3000:])

    def test_a_missing_interface_is_named(self):
        out = tempfile.mkdtemp(prefix="ssc_sil_missing_")
        self.addCleanup(shutil.rmtree, out, True)
        script = os.path.join(out, "needs_io.py")
        with open(script, "w") as f:
            f.write("import rospy\nimport rtde_io\n")
        p = run_sil(["--out", out, script], out)
        self.assertEqual(p.returncode, 6, p.stdout + p.stderr)
        self.assertIn("missing interface: module rtde_io", p.stdout)

    def test_the_real_plot_draws_and_its_pause_costs_simulated_time(self):
        out = tempfile.mkdtemp(prefix="ssc_sil_plots_")
        self.addCleanup(shutil.rmtree, out, True)
        script = os.path.join(out, "plots.py")
        with open(script, "w") as f:
            f.write(
                "import rospy\nimport matplotlib.pyplot as plt\n"
                "fig, ax = plt.subplots(figsize=(8, 4))\nt0 = rospy.get_time()\n"
                "ax.annotate('', xytext=(0, 0), xy=(0.5, 0.5), arrowprops={})\n"
                "plt.pause(0.01)\nprint('paused %.4f' % (rospy.get_time() - t0))\n"
            )
        report = os.path.join(out, "r.json")
        cmd = [SSC, "sil"] if SSC else [sys.executable, "-m", "ssc_twin.sil"]
        env = dict(os.environ, SSC_PYTHON=sys.executable, MPLBACKEND="Agg")
        p = subprocess.run(
            cmd + ["--plots", "--pause-cost", "0.2", "--report", report, "--out", out, script],
            cwd=out,
            env=env,
            capture_output=True,
            text=True,
            timeout=300,
        )
        # It draws and pauses, never touching anything: the trial's verdict is exit 5.
        self.assertEqual(p.returncode, 5, p.stdout + p.stderr)
        self.assertIn("the trial: never touched the object", p.stdout)
        # 0.01 s + the 0.2 s charged, realised to a whole physics step of the default scene.
        step_s = ssc_twin.SilPlant().timestep
        paused = float(p.stdout.split("paused ")[1].split()[0])
        self.assertLessEqual(paused, 0.21 + 1e-9, p.stdout)
        self.assertGreater(paused, 0.21 - step_s, p.stdout)
        with open(report) as f:
            pauses = json.load(f)["plt_pause"]
        self.assertEqual(pauses["pauses"], 1)
        self.assertGreater(pauses["draw_cpu_s_median"], 0.0, "the figure was not drawn")

    def test_a_method_missing_from_the_scripts_own_helper_is_named_as_its_bug(self):
        # The lab's HEAD: the script calls a helper method its own helper no longer defines.
        out = tempfile.mkdtemp(prefix="ssc_sil_labbug_")
        self.addCleanup(shutil.rmtree, out, True)
        os.makedirs(os.path.join(out, "lab", "helperFunction"))
        with open(os.path.join(out, "lab", "helperFunction", "__init__.py"), "w"):
            pass
        with open(os.path.join(out, "lab", "helperFunction", "robot_helper.py"), "w") as f:
            f.write("class robotHelp:\n    def setTCPoffset(self, o):\n        pass\n")
        script = os.path.join(out, "lab", "follow.py")
        with open(script, "w") as f:
            f.write(
                "import rospy\nfrom helperFunction.robot_helper import robotHelp\n"
                "h = robotHelp()\nh.setTCPoffset([0, 0, 0.146])\nh.setCalibrationMatrix()\n"
            )
        p = run_sil(["--out", out, script], out)
        self.assertEqual(p.returncode, 1, p.stdout + p.stderr)
        self.assertIn(
            "the lab's own code, not the twin: follow.py:5 uses "
            "robotHelp.setCalibrationMatrix, which class robotHelp "
            "(helperFunction/robot_helper.py) does not define",
            p.stdout,
        )
        self.assertNotIn("missing interface", p.stdout)


class SilViewer(unittest.TestCase):
    def test_viewer_follows_a_script_under_xvfb(self):
        import shutil

        if not shutil.which("xvfb-run"):
            self.skipTest("xvfb-run is not installed")
        out = tempfile.mkdtemp(prefix="ssc_sil_viewer_")
        self.addCleanup(shutil.rmtree, out, True)
        script = os.path.join(out, "moves.py")
        with open(script, "w") as f:
            f.write(
                "import rospy, rtde_control, rtde_receive\n"
                "rospy.init_node('v')\n"
                "c = rtde_control.RTDEControlInterface('10.0.0.1', 125)\n"
                "r = rtde_receive.RTDEReceiveInterface('10.0.0.1', 125)\n"
                "p = r.getActualTCPPose(); p[2] += 0.01\n"
                "print('moved', c.moveL(p, 0.05, 0.5))\n"
            )
        cmd = [SSC, "sil"] if SSC else [sys.executable, "-m", "ssc_twin.sil"]
        env = dict(os.environ, SSC_PYTHON=sys.executable)
        p = subprocess.run(
            ["xvfb-run", "-a"] + cmd + ["--viewer", "--out", out, script],
            cwd=out,
            env=env,
            capture_output=True,
            text=True,
            timeout=300,
        )
        self.assertEqual(p.returncode, 5, p.stdout[-2000:] + p.stderr[-2000:])  # never touched
        self.assertIn("moved True", p.stdout)

    def test_viewer_without_a_display_says_so(self):
        out = tempfile.mkdtemp(prefix="ssc_sil_viewer_")
        self.addCleanup(shutil.rmtree, out, True)
        script = os.path.join(out, "s.py")
        with open(script, "w") as f:
            f.write("import rospy\n")
        env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
        p = subprocess.run(
            [sys.executable, "-m", "ssc_twin.sil", "--viewer", "--out", out, script],
            cwd=out,
            env=env,
            capture_output=True,
            text=True,
            timeout=300,
        )
        self.assertEqual(p.returncode, 1, p.stdout + p.stderr)
        self.assertIn("no display", p.stderr)


def pressed_readings(scene, depths_m):
    """The plant's F/T and MuJoCo's raw F/T sensors (z, N) with the tool site held 5 mm over the
    disk's top and then at each depth below it (1 s each, the servo unsmoothed)."""
    plant = ssc_twin.SilPlant(scene, 1)
    plant.set_servo(0.0, 0.01)
    top = plant.geom_top("disk")
    readings = []
    for depth in [-5e-3] + list(depths_m):
        plant.set_target([top[0], top[1], top[2] - depth])
        plant.advance_to(plant.time + 1.0)
        readings.append((plant.force_torque(), plant.sensor_force_torque()))
    return readings


class SilForceTorque(unittest.TestCase):
    def test_on_a_rigid_lip_the_plant_reads_the_ft_sensors(self):
        for ft, raw in pressed_readings("disk_benchmark_gantry", [1.0e-3]):
            self.assertEqual(list(ft), list(raw))

    def test_on_the_flex_skirt_the_plant_reads_the_skirts_load(self):
        # The trial's contact balance (runtime/tool_force.h): pressing the skirt 1.5 mm deeper
        # into the disk adds its stiffness's push (about 0.9 N/mm), which MuJoCo's force sensor
        # misses (a flex's contacts are left out of its recursion).
        readings = pressed_readings("disk_benchmark_flex", [0.5e-3, 2.0e-3])
        (air, air_raw), (shallow, shallow_raw), (deep, deep_raw) = readings
        self.assertGreater(deep[2] - shallow[2], 0.5)
        self.assertLess(abs(deep_raw[2] - shallow_raw[2]), 0.05)
        # Over the disk, untouched: no contact and no seal to balance (the cup's weight is left out).
        self.assertLess(abs(air[2]), 0.05)
        for f in (air, shallow, deep):
            self.assertTrue(all(math.isfinite(v) for v in f))


class LabCheckout(unittest.TestCase):
    def test_lab_disk_script_starts(self):
        repo = os.environ.get("SSC_LAB_REPO")
        if not repo:
            self.skipTest("SSC_LAB_REPO is not set (a checkout of the lab's edg_suction_cup)")
        script = os.path.join(
            repo, "src", "SDL_ur_control_edgeFollowing_livePlot_oneDiskRevolution.py"
        )
        out = tempfile.mkdtemp(prefix="ssc_sil_lab_")
        self.addCleanup(shutil.rmtree, out, True)
        p = run_sil(["--out", out, "--max-sim", "5", script], out)
        # It starts: the node comes up and moves (at the time limit the trial has no outcome yet:
        # exit 5); at the lab's HEAD it stops on the lab's own missing setCalibrationMatrix,
        # named as the lab's bug.
        if p.returncode != 5:
            self.assertEqual(p.returncode, 1, p.stdout[-3000:] + p.stderr[-3000:])
            self.assertIn("the lab's own code, not the twin:", p.stdout)
            self.assertIn("rtdeHelp.setCalibrationMatrix", p.stdout)
        self.assertIn("ssc sil:", p.stdout)


if __name__ == "__main__":
    # A skip is not a pass: exit 77 (CTest SKIP_RETURN_CODE) when a case was skipped.
    result = unittest.main(exit=False).result
    if not result.wasSuccessful():
        sys.exit(1)
    sys.exit(77 if result.skipped else 0)
