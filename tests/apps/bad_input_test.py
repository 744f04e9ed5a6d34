"""Bad input as a careless user types it: every case must end quickly with a clear one-line error
(exit 2 for usage, 1 for unreadable files/scenes) naming the input, never a crash, a hang or a
silent run. Run directly with --report for the full round (timings and peak memory)."""

import os
import shutil
import signal
import subprocess
import sys
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
TMP = tempfile.mkdtemp(prefix="ssc_bad_input_")
A_FILE = os.path.join(TMP, "a_file")
with open(A_FILE, "w") as f:
    f.write("x")


def scene_with(old, new, name):
    """A copy of the gantry scene in TMP with one change; its parts and models by absolute path."""
    with open(os.path.join(SRC, "scenes", "disk_benchmark_gantry.xml")) as f:
        xml = f.read()
    assert old in xml, old
    xml = xml.replace(old, new, 1)
    xml = xml.replace('file="parts/', 'file="%s/scenes/parts/' % SRC)
    xml = xml.replace('file="../models/', 'file="%s/models/' % SRC)
    path = os.path.join(TMP, f"scene_{name}.xml")
    with open(path, "w") as f:
        f.write(xml)
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
STEP_TINY = scene_with('timestep="0.002"', 'timestep="1e-9"', "dttiny")
MALFORMED_XML = os.path.join(TMP, "malformed.xml")  # <body> never closed
with open(MALFORMED_XML, "w") as f:
    f.write("<mujoco>\n<worldbody>\n<body>\n</worldbody>\n</mujoco>\n")
FIFO = os.path.join(TMP, "pipe.csv")
os.mkfifo(FIFO)
DANGLING = os.path.join(TMP, "dangling")
os.symlink(os.path.join(TMP, "nothing_here"), DANGLING)
with open(os.path.join(SRC, "data", "published", "success_map_dl5.csv")) as f:
    MAP = f.read()
MAP_IN_M = os.path.join(TMP, "map_step_in_m.csv")  # steps in metres under step_mm
with open(MAP_IN_M, "w") as f:
    f.write(MAP.replace("\n5.0,", "\n0.005,"))


TINY_SCRIPT = os.path.join(TMP, "tiny_script.py")  # what ssc sil runs when its options pass
with open(TINY_SCRIPT, "w") as f:
    f.write("print('ran')\n")


def lab_recording():
    """A twin trial written as the lab records it (ssc trial --robot-log), in TMP/rec."""
    rec = os.path.join(TMP, "rec")
    r = subprocess.run(
        [SSC, "trial", "--no-plot", "--out", os.path.join(TMP, "rec_trial"), "--robot-log", rec],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert r.returncode == 0, r.stderr
    return rec


REC = lab_recording()


def rec_variant(name, topic, edit):
    """A copy of the recording's CSV files with one topic file's lines edited."""
    d = os.path.join(TMP, name)
    os.makedirs(d)
    for f in os.listdir(REC):
        if not f.endswith(".csv"):
            continue
        with open(os.path.join(REC, f)) as src:
            text = src.read()
        if topic in f:
            text = edit(text)
        with open(os.path.join(d, f), "w") as dst:
            dst.write(text)
    return d


def cut_mat():
    mat = [f for f in os.listdir(REC) if f.endswith(".mat")][0]
    with open(os.path.join(REC, mat), "rb") as f:
        data = f.read()
    path = os.path.join(TMP, "cut.mat")
    with open(path, "wb") as f:
        f.write(data[: len(data) // 2])
    return path


def flat_pressure(text):
    lines = text.split("\n")
    return "\n".join(
        lines[:1] + [",".join(l.split(",")[:2] + ["101325.0"] * 4) if l else l for l in lines[1:]]
    )


SHORT_POSE = rec_variant(
    "rec_short_pose", "endEffectorPose", lambda t: "\n".join(t.split("\n")[:21]) + "\n"
)
FLAT = rec_variant("rec_flat", "SensorPacket", flat_pressure)
CUT_MAT = cut_mat()

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
    # /proc passes the parse-time check for root (access() says writable): mkdir fails when
    # the outputs are made, after the inputs; still nothing is left and the message names it.
    (["trial", "--out", "/proc/ssc_no"], 1, "/proc/ssc_no"),
    (["trial", "--pref", "abc"], 2, "--pref"),
    (["trial", "--pref", "0x10"], 2, "not a decimal"),
    (["trial", "--pref", "1e400"], 2, "--pref"),
    (["trial", "--pref", "nan"], 2, "--pref"),
    (["trial", "--pref", "-100"], 2, "(0, 1000000)"),
    (["trial", "--pref", ""], 2, "empty"),
    (["trial", "--pref", "100Pa"], 2, "--pref"),
    (["trial", "--pref", "100", "--pref", "200"], 2, "--pref"),
    (["trial", "--beta", "101"], 2, "[0, 100]"),
    (["trial", "--step", "0"], 2, "[0.1, 100]"),
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
    (["trial", "--scene", "no_such_scene"], 3, "no_such_scene"),
    (["trial", "--scene", STEP0, "--no-plot", "--out", TMP], 4, "time step"),
    (["trial", "--scene", STEPNEG, "--no-plot", "--out", TMP], 4, "time step"),
    (["trial", "--scene", EMPTY_CFG, "--no-plot", "--out", TMP], 4, "empty value"),
    (["trial", "--scene", HEX_CFG, "--no-plot", "--out", TMP], 4, "0x10"),
    (
        ["trial", "--scene", MALFORMED_XML, "--no-plot", "--out", TMP],
        4,
        "malformed.xml: line 3: malformed XML: a closing tag does not match the open element <body>",
    ),
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
    (["sil"], 2, "usage: ssc sil"),
    (["sil", "/nonexistent/script.py"], 3, "no such file"),
    (["sil", "--seed", "-1", TINY_SCRIPT], 2, "--seed: '-1' is outside [0, 9007199254740991]"),
    (["sil", "--max-sim", "nan", TINY_SCRIPT], 2, "--max-sim: 'nan'"),
    (["sil", "--max-sim", "0", TINY_SCRIPT], 2, "(0, 86400]"),
    (
        ["sil", "--scene", "no_such_scene", TINY_SCRIPT],
        3,
        "--scene: no_such_scene: no such file here or in",
    ),
    (
        ["sil", "--out", A_FILE, TINY_SCRIPT],
        2,
        "--out: '%s' exists and is not a directory" % A_FILE,
    ),
    (["sil", "--out", A_FILE + "/sub", TINY_SCRIPT], 2, "Not a directory"),
    (["bench", "--block", "0"], 2, "--block"),
    (["bench", "--rounds", "0"], 2, "--rounds"),
    (["compare"], 2, "LOG"),
    (["compare", "a", "b"], 2, "b"),
    (["compare", LONG_LINE, "--offset-window", "1e6"], 2, "(0, 60]"),
    (["compare", LONG_LINE, "--average", "0"], 2, "--average"),
    (["compare", LONG_LINE, "--tcp-offset", "-5"], 2, "--tcp-offset"),
    (["compare", os.path.join(TMP, "missing_log")], 3, "missing_log"),
    (["compare", LONG_LINE, "--out", TMP], 4, "one_line.csv"),
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
    (["view", "no_such_object"], 3, "no_such_object"),
    (["view", "fillet", "--scene-kind", "robot"], 2, "gantry, arm, flex"),
    (["charts", "--tiers", "gantry,rigid"], 2, "unknown tier 'rigid'"),
    (["charts", "--tiers", "flex,flex"], 2, "twice"),
    (["charts", "--tier-objects", "fillet,nothing"], 2, "unknown object 'nothing'"),
    (["charts", "--tier-seeds", "0"], 2, "--tier-seeds"),
    (["view", "disk_benchmark", "--scene-kind", "flex"], 2, "disk_benchmark_flex"),
    (["nosuchcommand"], 2, "unknown command"),
    # Second round (docs/reliability.md): inputs found bad only after the output was made, and
    # the kinds that hung, crashed or ran silently.
    (["trial", "--scene", "no_such_scene", "--out", "new_out"], 3, "no_such_scene"),
    (["sweep", "--scene", "no_such_scene", "--out", "new_out"], 3, "no_such_scene"),
    (["probe", "--scene", "no_such_scene", "--out", "new_out"], 1, "no_such_scene"),
    # A probe scene without the plate and disk where the study probes: not a table of noise.
    (
        ["probe", "--scene", "disk_replay", "--out", "new_out"],
        1,
        "disk_replay: the probe's layout is not in this scene",
    ),
    (["stability", "--scene", "no_such_scene", "--out", "new_out"], 3, "no_such_scene"),
    (["validate", "--map", "missing.csv", "--out", "new_out"], 3, "missing.csv"),
    (["calibrate", "--dynamic", "--map", "missing.csv", "--out", "new_out"], 1, "missing.csv"),
    (["compare", "missing_log", "--out", "new_out"], 3, "missing_log"),
    (["sweep", "--pref", "300,40", "--pn", "200", "--out", "new_out"], 2, "P_ref 40 Pa"),
    (["trial", "--scene", "probe_edge", "--out", "new_out"], 4, "6 hinge joints"),
    (["sweep", "--scene", "probe_edge", "--out", "new_out"], 4, "6 hinge joints"),
    (["trial", "--out", "a" * 300], 2, "longer than"),
    (["trial", "--out", DANGLING], 2, "dangling"),
    (["trial", "--seed", "9007199254740993"], 2, "2^53"),
    (["trial", "--seed", "9007199254740990.6"], 2, "not a whole number"),
    (["trial", "--period", "10", "--timeout", "1"], 2, "longer than timeout_s"),
    (["trial", "--scene", STEP_TINY, "--out", "new_out"], 4, "below 0.05 ms"),
    (["stability", "--steps-ms", "0.001"], 2, "--steps-ms"),
    (["sweep", "--step", "0.005"], 2, "[0.1, 100]"),
    (["trial", "--scene", TMP, "--out", "new_out"], 4, "is a directory"),
    (["trial", "--scene", FIFO, "--out", "new_out"], 4, "not a regular file"),
    (["validate", "--map", MAP_IN_M, "--out", "new_out"], 4, "metres given as mm"),
    (["validate", "--map", FIFO, "--out", "new_out"], 4, "not a regular file"),
    (["calibrate", "--dynamic", "--dynamic-keys", "period_s,period_s"], 2, "twice"),
    (["calibrate", "--dynamic", "--dynamic-keys", "period_s,"], 2, "stray comma"),
    (["calibrate", "--dynamic", "--dynamic-keys", "bogus", "--out", "new_out"], 2, "bogus"),
    (["calibrate", "--depth-pa", "100,40,200", "--out", "new_out"], 2, "rise with depth"),
    (["calibrate", "--depth-pa", "40,100", "--out", "new_out"], 2, "three values"),
    (["calibrate", "--closed-loop", "51", "--out", "new_out"], 2, "--closed-loop"),
    (
        ["calibrate", "--closed-loop", "2", "--depth-pa", "40,100,200", "--out", "new_out"],
        2,
        "give one",
    ),
    (["calibrate", "--dynamic", "--holdout-seed", "-1", "--out", "new_out"], 2, "--holdout-seed"),
    (["trial", "--effects", "step_error_corr=0.99", "--out", "new_out"], 2, "step_error_corr"),
    (["trial", "--controller", "fastest", "--out", "new_out"], 2, "unknown controller 'fastest'"),
    (
        [
            "sweep",
            "--controller",
            "fast",
            "--controller-param",
            "step_max_mm=300",
            "--out",
            "new_out",
        ],
        2,
        "step_max_mm",
    ),
    (
        [
            "sweep",
            "--controller",
            "fast",
            "--controller-param",
            "step_min_mm=9",
            "--out",
            "new_out",
        ],
        2,
        "exceeds step_max_mm",
    ),
    (
        ["objects", "--controller", "fast", "--controller-param", "stepmax=3", "--out", "new_out"],
        2,
        "unknown key 'stepmax'",
    ),
    (["validate", "--controller-param", "beta=2", "--out", "new_out"], 2, "takes no parameters"),
    (
        ["tune", "--controller", "fast", "--search", "step_max_mm=9:8", "--out", "new_out"],
        2,
        "lo < hi",
    ),
    (
        ["tune", "--controller", "fast", "--search", "stepmax=3:9", "--out", "new_out"],
        2,
        "unknown key 'stepmax'",
    ),
    (
        ["tune", "--controller", "fast", "--search", "step_max_mm=3:99", "--out", "new_out"],
        2,
        "[0.5, 30]",
    ),
    (
        [
            "tune",
            "--controller",
            "fast",
            "--search",
            "step_min_mm=9:12,step_max_mm=5:8",
            "--out",
            "new_out",
        ],
        2,
        "rule: step_min_mm <= step_max_mm with step_min_mm in [9, 12] and step_max_mm in [5, 8]",
    ),
    (["tune", "--controller", "example", "--out", "new_out"], 2, "give the keys to search"),
    (["tune", "--reference", "fastest", "--out", "new_out"], 2, "unknown controller 'fastest'"),
    (["compare", FIFO, "--out", "new_out"], 4, "not a regular file"),
    (["compare", "/dev/zero"], 4, "not a regular file"),
    (["compare", CUT_MAT, "--out", "new_out"], 4, "cut short"),
    (["compare", SHORT_POSE, "--out", "new_out"], 4, "less than half"),
    (["compare", FLAT, "--out", "new_out"], 4, "never exceeds"),
]


def read_lines(path):
    with open(path) as f:
        return f.read().splitlines()


def run(args, timeout=60, prefix=()):
    env = dict(os.environ)
    env.pop("DISPLAY", None)
    t0 = time.time()
    try:
        r = subprocess.run(
            list(prefix) + [SSC] + args,
            capture_output=True,
            text=True,
            timeout=timeout,
            env=env,
            cwd=TMP,
        )
        return r, time.time() - t0, False
    except subprocess.TimeoutExpired:
        return None, time.time() - t0, True


class BadInputTest(unittest.TestCase):
    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(TMP, ignore_errors=True)

    def test_every_case_fails_fast_with_a_message_and_leaves_nothing_behind(self):
        for args, code, text in CASES:
            with self.subTest(args=args):
                before = set(os.listdir(TMP))
                r, _, hung = run(args)
                self.assertFalse(hung, "hang")
                self.assertGreaterEqual(r.returncode, 0, "killed by a signal (crash)")
                self.assertEqual(r.returncode, code, r.stderr)
                self.assertIn(text, r.stderr)
                self.assertNotIn("terminate called", r.stderr)
                # Inputs are checked before any output is made (out/..., --out new_out).
                self.assertEqual(set(os.listdir(TMP)) - before, set(), "left behind")

    def test_output_paths_reach_the_plot_script_as_one_argument(self):
        if not os.path.exists(os.path.join(SRC, ".venv", "bin", "python")):
            self.skipTest("no .venv: plots are skipped")
        out = os.path.join(TMP, "it's; touch PWNED; '")
        r, _, hung = run(["trial", "--out", out])
        self.assertFalse(hung)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertFalse(os.path.exists(os.path.join(TMP, "PWNED")), "ran through a shell")
        self.assertTrue(os.path.exists(os.path.join(out, "trajectory.png")), r.stderr)

    def test_interrupted_sweep_resumes_to_the_rows_of_an_uninterrupted_one(self):
        args = [
            "sweep",
            "--pref",
            "100,200",
            "--beta",
            "2",
            "--step",
            "7.5",
            "--repeats",
            "2",
            "--threads",
            "1",
            "--no-plot",
            "--no-progress",
        ]
        cut, whole = os.path.join(TMP, "sweep_cut"), os.path.join(TMP, "sweep_whole")
        env = dict(os.environ)
        p = subprocess.Popen(
            [SSC] + args + ["--out", cut],
            cwd=TMP,
            env=env,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        csv = os.path.join(cut, "sweep.csv")
        deadline = time.time() + 120
        while time.time() < deadline:  # Ctrl-C once the first row is in
            if os.path.exists(csv) and len(read_lines(csv)) >= 2:
                break
            time.sleep(0.05)
        p.send_signal(signal.SIGINT)
        _, err = p.communicate(timeout=120)
        self.assertEqual(p.returncode, 130, err)
        self.assertIn("interrupted", err)
        rows_cut = len(read_lines(csv)) - 1
        self.assertLess(rows_cut, 4)
        # Resuming with other robot effects would mix rows: refused, naming the difference.
        r, _, _ = run(args + ["--out", cut, "--effects", "pose_delay_s=0.02"])
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertIn("effects", r.stderr)
        r, _, _ = run(args + ["--out", cut])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn(f"{rows_cut} already in", r.stdout)
        r, _, _ = run(args + ["--out", whole])
        self.assertEqual(r.returncode, 0, r.stderr)

        # Rows carry no wall time: the resumed file holds exactly the uninterrupted one's rows.
        self.assertEqual(
            sorted(read_lines(csv)[1:]), sorted(read_lines(os.path.join(whole, "sweep.csv"))[1:])
        )

    def test_version(self):
        r, _, _ = run(["--version"])
        self.assertEqual(r.returncode, 0)
        self.assertRegex(r.stdout, r"^ssc \d+\.\d+\.\d+ \(MuJoCo \d+\.\d+\.\d+\)")


def report():
    """The round with each case's time and peak memory (GNU time's maximum RSS of that run)."""
    crashes = hangs = silent = left = 0
    worst = (0, None)
    rss_file = os.path.join(TMP, ".rss")
    for args, code, text in CASES:
        entries = set(os.listdir(TMP))
        r, dt, hung = run(args, prefix=("/usr/bin/time", "-f", "%M", "-o", rss_file))
        with open(rss_file) as f:
            rss_mb = int(f.read().split()[-1]) / 1024 if not hung else 0
        os.remove(rss_file)
        new = set(os.listdir(TMP)) - entries
        if rss_mb > worst[0]:
            worst = (rss_mb, args)
        if hung:
            hangs += 1
            verdict = "HANG"
        elif r.returncode < 0 or "terminate called" in r.stderr or "Command terminated" in r.stderr:
            crashes += 1
            verdict = "CRASH"
        elif r.returncode == 0 or text not in r.stderr:
            silent += 1
            verdict = "SILENT/WRONG"
        elif new:
            left += 1
            verdict = "LEFT " + ",".join(sorted(new))[:20]
        else:
            verdict = "ok"
        msg = (r.stderr.strip().splitlines() or [""])[0][:110] if r else ""
        print(
            f"{verdict:12} rc={r.returncode if r else '-':>3} {dt:5.1f}s {rss_mb:6.0f} MB  "
            f"{' '.join(args)[:60]:60}  {msg}"
        )
    print(
        f"\n{len(CASES)} cases: {crashes} crashes, {hangs} hangs, {silent} silent/wrong, "
        f"{left} left a directory behind; peak RSS of the worst case {worst[0]:.0f} MB "
        f"({' '.join(worst[1] or [])[:60]})"
    )
    BadInputTest.tearDownClass()


if __name__ == "__main__":
    if "--report" in sys.argv:
        report()
    else:
        unittest.main()
