"""Bad input as a careless user types it: every case must end quickly with a clear one-line error
(exit 2 for usage, 1 for unreadable files/scenes) naming the input, never a crash, a hang or a
silent run. Run directly with --report for the full round (timings and peak memory)."""
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
import unittest

BIN = os.environ.get("SSC_BIN_DIR", os.path.join(os.path.dirname(__file__), "..", "build", "bin"))
SRC = os.environ.get("SSC_SOURCE_DIR", os.path.join(os.path.dirname(__file__), ".."))
SSC = os.path.join(BIN, "ssc")
TMP = tempfile.mkdtemp(prefix="ssc_bad_input_")
A_FILE = os.path.join(TMP, "a_file")
with open(A_FILE, "w") as f:
    f.write("x")


def scene_with(old, new, name):
    """A copy of the gantry scene beside the original (its includes resolve) with one change."""
    with open(os.path.join(SRC, "scenes", "disk_benchmark_gantry.xml")) as f:
        xml = f.read()
    assert old in xml, old
    path = os.path.join(SRC, "scenes", f".bad_{os.getpid()}_{name}.xml")
    with open(path, "w") as f:
        f.write(xml.replace(old, new, 1))
    return path


STEP0 = scene_with('timestep="0.002"', 'timestep="0"', "dt0")
STEPNEG = scene_with('timestep="0.002"', 'timestep="-0.001"', "dtneg")


def tool_with(config, name):
    """The tool model with one config line, in TMP; a scene that attaches it."""
    with open(os.path.join(SRC, "models", "ssc_tool.xml")) as f:
        xml = f.read()
    old = '<instance name="pressure"/>'
    assert old in xml, old
    tool = os.path.join(TMP, f"tool_{name}.xml")
    with open(tool, "w") as f:
        f.write(xml.replace(old, f'<instance name="pressure">{config}</instance>'))
    return scene_with('file="../models/ssc_tool.xml"', f'file="{tool}"', name)


EMPTY_CFG = tool_with('<config key="noise_pa" value=""/>', "empty")
HEX_CFG = tool_with('<config key="noise_pa" value="0x10"/>', "hex")
LONG_LINE = os.path.join(TMP, "one_line.csv")
with open(LONG_LINE, "w") as f:
    f.write("t_s,x_m,y_m,z_m," + "9" * 20_000_000)  # 20 MB, no newline

# (args, expected exit code, text the message must contain)
CASES = [
    (["trial", "--out", A_FILE], 2, "not a directory"),
    (["trial", "--out", A_FILE + "/sub"], 2, "a_file"),
    (["sweep", "--out", A_FILE], 2, "not a directory"),
    (["probe", "--out", A_FILE], 2, "not a directory"),
    (["calibrate", "--out", A_FILE], 2, "not a directory"),
    (["stability", "--out", A_FILE], 2, "not a directory"),
    (["charts", "--out", A_FILE], 2, "not a directory"),
    (["compare", LONG_LINE, "--out", A_FILE], 2, "not a directory"),
    (["objects", "--out", A_FILE], 2, "not a directory"),
    (["trial", "--robot-log", A_FILE], 2, "--robot-log"),
    (["view", "--screenshot", TMP], 2, "is a directory"),
    (["trial", "--out", "/proc/ssc_no"], 2, "/proc/ssc_no"),
    (["trial", "--pref", "abc"], 2, "--pref"),
    (["trial", "--pref", "0x10"], 2, "not a decimal"),
    (["trial", "--pref", "1e400"], 2, "--pref"),
    (["trial", "--pref", "nan"], 2, "--pref"),
    (["trial", "--pref", "-100"], 2, "(0, 1000000)"),
    (["trial", "--pref", ""], 2, "empty"),
    (["trial", "--pref", "100Pa"], 2, "--pref"),
    (["trial", "--pref", "100", "--pref", "200"], 2, "--pref"),
    (["trial", "--beta", "101"], 2, "[0, 100]"),
    (["trial", "--step", "0"], 2, "(0, 100]"),
    (["trial", "--seed", "-1"], 2, "--seed"),
    (["trial", "--seed", "1.5"], 2, "--seed"),
    (["trial", "--seed", "1e30"], 2, "--seed"),
    (["trial", "--timeout", "0"], 2, "--timeout"),
    (["trial", "--timeout", "inf"], 2, "--timeout"),
    (["trial", "--period", "0.0001"], 2, "--period"),
    (["trial", "--object-on", "up"], 2, "left|right"),
    (["trial", "--pn", "200", "--pref", "100"], 2, "P_n"),
    (["trial", "stray"], 2, "stray"),
    (["trial", "--unknown"], 2, "--unknown"),
    (["trial", "--pref"], 2, "--pref"),
    (["trial", "-pref", "100"], 2, "-pref"),
    (["trial", "--stop-at", "0"], 2, "--stop-at"),
    (["trial", "--scene", "no_such_scene"], 1, "no_such_scene"),
    (["trial", "--scene", STEP0, "--no-plot", "--out", TMP], 1, "time step"),
    (["trial", "--scene", STEPNEG, "--no-plot", "--out", TMP], 1, "time step"),
    (["trial", "--scene", EMPTY_CFG, "--no-plot", "--out", TMP], 1, "empty value"),
    (["trial", "--scene", HEX_CFG, "--no-plot", "--out", TMP], 1, "0x10"),
    (["sweep", "--pref", "40,70,"], 2, "stray comma"),
    (["sweep", "--pref", ",40"], 2, "empty"),
    (["sweep", "--pref", "40,,70"], 2, "empty"),
    (["sweep", "--beta", "1,1"], 2, "twice"),
    (["sweep", "--step", "2.5;5"], 2, "--step"),
    (["sweep", "--repeats", "0"], 2, "--repeats"),
    (["sweep", "--repeats", "2.5"], 2, "--repeats"),
    (["sweep", "--threads", "0"], 2, "--threads"),
    (["sweep", "--threads", "100000"], 2, "--threads"),
    (["stability", "--steps-ms", "0"], 2, "--steps-ms"),
    (["stability", "--steps-ms", "-1,2"], 2, "--steps-ms"),
    (["stability", "--steps-ms", "1,2,"], 2, "--steps-ms"),
    (["bench", "--block", "0"], 2, "--block"),
    (["bench", "--rounds", "0"], 2, "--rounds"),
    (["compare"], 2, "LOG"),
    (["compare", "a", "b"], 2, "b"),
    (["compare", LONG_LINE, "--offset-window", "1e6"], 2, "(0, 60]"),
    (["compare", LONG_LINE, "--average", "0"], 2, "--average"),
    (["compare", LONG_LINE, "--tcp-offset", "-5"], 2, "--tcp-offset"),
    (["compare", os.path.join(TMP, "missing_log")], 1, "missing_log"),
    (["compare", LONG_LINE, "--out", TMP], 1, "one_line.csv"),
    (["probe", "--step", "0"], 2, "--step"),
    (["probe", "--from", "5", "--to", "-5"], 2, "--to"),
    (["probe", "--disk-step", "0"], 2, "--disk-step"),
    (["probe", "--from", "-50", "--to", "50", "--step", "1e-9"], 2, "100000"),
    (["objects", "--objects", "disk_d06,"], 2, "unknown object"),
    (["objects", "--objects", "disk_d06,disk_d06"], 2, "twice"),
    (["objects", "--scene-kind", "robot"], 2, "gantry|arm"),
    (["objects", "--seeds", "0"], 2, "--seeds"),
    (["calibrate", "--start-scale", "0"], 2, "--start-scale"),
    (["calibrate", "--wander-evals", "2"], 2, "--wander-evals"),
    (["view", "--width", "10"], 2, "--width"),
    (["view", "--speed", "0"], 2, "--speed"),
    (["view", "no_such_object"], 2, "no_such_object"),
    (["nosuchcommand"], 2, "unknown command"),
]


def run(args, timeout=60):
    env = dict(os.environ)
    env.pop("DISPLAY", None)
    t0 = time.time()
    try:
        r = subprocess.run([SSC] + args, capture_output=True, text=True, timeout=timeout, env=env,
                           cwd=TMP)
        return r, time.time() - t0, False
    except subprocess.TimeoutExpired:
        return None, time.time() - t0, True


class BadInputTest(unittest.TestCase):
    @classmethod
    def tearDownClass(cls):
        for p in (STEP0, STEPNEG, EMPTY_CFG, HEX_CFG):
            os.remove(p)
        shutil.rmtree(TMP, ignore_errors=True)

    def test_every_case_fails_fast_with_a_message(self):
        for args, code, text in CASES:
            with self.subTest(args=args):
                r, _, hung = run(args)
                self.assertFalse(hung, "hang")
                self.assertGreaterEqual(r.returncode, 0, "killed by a signal (crash)")
                self.assertEqual(r.returncode, code, r.stderr)
                self.assertIn(text, r.stderr)
                self.assertNotIn("terminate called", r.stderr)

    def test_version(self):
        r, _, _ = run(["--version"])
        self.assertEqual(r.returncode, 0)
        self.assertRegex(r.stdout, r"^ssc \d+\.\d+\.\d+ \(MuJoCo \d+\.\d+\.\d+\)")


def report():
    crashes = hangs = silent = 0
    worst = (0, None)
    for args, code, text in CASES:
        before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
        r, dt, hung = run(args)
        rss_mb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
        if rss_mb > worst[0] and resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss > before:
            worst = (rss_mb, args)
        if hung:
            hangs += 1
            verdict = "HANG"
        elif r.returncode < 0 or "terminate called" in r.stderr:
            crashes += 1
            verdict = "CRASH"
        elif r.returncode == 0 or text not in r.stderr:
            silent += 1
            verdict = "SILENT/WRONG"
        else:
            verdict = "ok"
        msg = (r.stderr.strip().splitlines() or [""])[0][:110] if r else ""
        print(f"{verdict:12} rc={r.returncode if r else '-':>3} {dt:5.1f}s  {' '.join(args)[:60]:60}  {msg}")
    print(f"\n{len(CASES)} cases: {crashes} crashes, {hangs} hangs, {silent} silent/wrong; "
          f"peak RSS of the worst case {worst[0]:.0f} MB ({' '.join(worst[1] or [])[:60]})")
    BadInputTest.tearDownClass()


if __name__ == "__main__":
    if "--report" in sys.argv:
        report()
    else:
        unittest.main()
