"""A reliability round by classes (docs/reliability.md): each case runs a command or a Python
call that once gave a wrong answer, hung or left something behind, in a family per class, and
must end fast with its documented exit code and a message naming what is wrong, or the right
result, leaving nothing in its working folder or the temp folder.

    python3 tests/apps/reliability_round_test.py            # as a test: every case must pass
    python3 tests/apps/reliability_round_test.py --report   # the round as a table, with counts
"""

import csv
import glob
import json
import os
import shutil
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
PKG = os.path.abspath(os.path.join(BIN, "..", "python_pkg"))
PYTHON = os.environ.get("SSC_PYTHON") or os.path.join(SRC, ".venv", "bin", "python")
if not os.path.exists(PYTHON):
    PYTHON = sys.executable
TIMEOUT_S = 90

# Exit codes (common/exit_codes.h).
USAGE, MISSING, BAD_DATA, TRIAL_FAILED, INTERFACE = 2, 3, 4, 5, 6

# Whole-number keys (counts and switches) and the controllers' keys, as the registry lists them.
WHOLE_KEYS = [
    ("fast", "timing"),
    ("fast", "ramp_iterations"),
    ("fast", "tare_in_air"),
    ("edge_track", "fit_points"),
    ("edge_track", "start_iterations"),
    ("edge_track", "circle_points"),
    ("edge_track", "tare_in_air"),
    ("crimp_hop", "resume_iterations"),
]
KEYS = {
    "fast": [
        "step_max_mm",
        "step_min_mm",
        "strength_pa",
        "turn_slow_deg",
        "turn_filter",
        "lead",
        "lag_gain",
        "lateral_gain",
        "timing",
        "ramp_iterations",
        "tare_in_air",
        "tare_clearance_mm",
    ],
    "edge_track": ["speed_mm_s", "fit_points", "start_iterations", "circle_points", "tare_in_air"],
    "crimp_hop": [
        "seal_ratio",
        "lift_mm",
        "descend_mm",
        "resume_step_mm",
        "resume_iterations",
    ],
    "force_height": ["force_n", "gain_mm_per_n", "max_down_mm", "max_up_mm"],
    "example": ["gain"],
}
COMMANDS_WITH_CONTROLLERS = ["trial", "sweep", "validate", "objects", "tune"]
EFFECT_KEYS = [
    "jitter_s",
    "pose_delay_s",
    "step_error_relative",
    "step_error_max_mm",
    "step_error_corr",
    "slip_mm",
    "tilt_decades",
    "peel_decades",
    "gain_spread",
    "cup_seed",
    "offset_spread_pa",
    "drift_pa",
    "drift_relative",
    "drift_time_s",
]


class Case:
    def __init__(self, family, what, run, code, text="", check=None, traceback=False):
        self.family, self.what, self.run, self.code, self.text = family, what, run, code, text
        self.check = check  # optional: (result, folder) -> problem text or ""
        self.traceback = traceback  # the script's own exception: Python's traceback is right


def cli(*args):
    return lambda folder: subprocess.run(
        [SSC] + list(args), cwd=folder, capture_output=True, text=True, timeout=TIMEOUT_S
    )


def sil(*args):
    return cli("sil", "--out", "run", *args)


def py(code):
    def go(folder):
        env = dict(os.environ, PYTHONPATH=PKG + os.pathsep + os.environ.get("PYTHONPATH", ""))
        return subprocess.run(
            [PYTHON, "-c", code],
            cwd=folder,
            capture_output=True,
            text=True,
            timeout=TIMEOUT_S,
            env=env,
        )

    return go


def script(name, text, mode="w"):
    """A file in the case's folder, made when the case runs; returns its name."""

    def make(folder):
        with open(os.path.join(folder, name), mode) as f:
            f.write(text)
        return name

    return make


def with_files(makers, build):
    """A run that first makes files in the case's folder (each maker returns a name)."""

    def go(folder):
        names = [m(folder) for m in makers]
        return build(*names)(folder)

    return go


def cases():
    out = []
    add = out.append
    # Counts and switches take whole numbers only, on every command that runs a controller.
    for controller, key in WHOLE_KEYS:
        for value in ("0.5", "0.0001", "2.5"):
            add(
                Case(
                    "whole keys",
                    f"{controller} {key}={value}",
                    cli(
                        "trial",
                        "--controller",
                        controller,
                        "--controller-param",
                        f"{key}={value}",
                        "--out",
                        "o",
                    ),
                    USAGE,
                    "not a whole number",
                )
            )
    for command in COMMANDS_WITH_CONTROLLERS:
        add(
            Case(
                "whole keys",
                f"{command} tare_in_air=0.5",
                cli(
                    command,
                    "--controller",
                    "fast",
                    "--controller-param",
                    "tare_in_air=0.5",
                    "--out",
                    "o",
                ),
                USAGE,
                "not a whole number",
            )
        )
    # A key given twice is a typo, never an override.
    in_range = {"fit_points": "8", "circle_points": "4", "drift_time_s": "1", "seal_ratio": "20"}
    for controller, keys in KEYS.items():
        for key in keys:
            v = in_range.get(key, "1")
            add(
                Case(
                    "keys twice",
                    f"{controller} {key} twice",
                    cli(
                        "trial",
                        "--controller",
                        controller,
                        "--controller-param",
                        f"{key}={v},{key}={v}",
                        "--out",
                        "o",
                    ),
                    USAGE,
                    "given twice",
                )
            )
    for key in EFFECT_KEYS:
        v = in_range.get(key, "0")
        add(
            Case(
                "keys twice",
                f"effects {key} twice",
                cli("trial", "--effects", f"{key}={v},{key}={v}", "--out", "o"),
                USAGE,
                "given twice",
            )
        )
    for name in ("x", "Pref", "beta", "d_lat", "max_iteration"):
        add(
            Case(
                "keys twice",
                f"sil --set {name} twice",
                with_files(
                    [script("k.py", f"{name} = 0\n")],
                    lambda s, n=name: sil("--set", f"{n}=1", "--set", f"{n}=2", s),
                ),
                USAGE,
                "given twice",
            )
        )
    for key in ("rings", "thickness_mm"):
        add(
            Case(
                "keys twice",
                f"make_flex_tool --set {key} twice",
                lambda folder, k=key: subprocess.run(
                    [
                        PYTHON,
                        os.path.join(SRC, "tools", "make_flex_tool.py"),
                        "--set",
                        f"{k}=5",
                        "--set",
                        f"{k}=6",
                        "--out",
                        "v.xml",
                    ],
                    cwd=folder,
                    capture_output=True,
                    text=True,
                    timeout=TIMEOUT_S,
                ),
                USAGE,
                f"--set {key}: given twice",
            )
        )
    # A tune box over a whole key that holds fewer than two whole numbers.
    for box in ("fit_points=3.2:3.8", "start_iterations=1.1:1.9", "circle_points=4.5:4.9"):
        add(
            Case(
                "whole keys",
                f"tune {box}",
                cli("tune", "--controller", "edge_track", "--search", box, "--out", "o"),
                USAGE,
                "fewer than two",
            )
        )
    # A goal reached without a path: narrow wedges under the body at the start. A success must
    # have moved (s_mm > 0) over more than one iteration.
    for angle in range(1, 13):
        name = "corner_a%03d" % angle
        add(
            Case(
                "no path",
                name,
                cli("objects", "--objects", name, "--threads", "1", "--no-plot", "--out", "o"),
                0,
                "",
                check=success_has_a_path,
            )
        )
    # Scripts that are not scripts; options of ssc sil that cannot work.
    fifo = lambda folder: (os.mkfifo(os.path.join(folder, "f.py")), "f.py")[1]  # noqa: E731
    sil_inputs = [
        ("missing script", lambda: sil("absent.py"), MISSING, "no such file", []),
        ("a directory", lambda: sil("."), BAD_DATA, "is a directory", []),
        ("a FIFO", lambda s: sil(s), BAD_DATA, "not a regular file", [fifo]),
        ("a device", lambda: sil("/dev/null"), BAD_DATA, "not a regular file", []),
        (
            "binary",
            lambda s: sil(s),
            BAD_DATA,
            "binary data",
            [script("b.py", b"\x7fELF\x00", "wb")],
        ),
        (
            "latin-1",
            lambda s: sil(s),
            BAD_DATA,
            "not UTF-8",
            [script("l.py", "x = 'caf\xe9'\n".encode("latin-1"), "wb")],
        ),
        (
            "unclosed paren",
            lambda s: sil(s),
            BAD_DATA,
            "not valid Python",
            [script("p.py", "print((1)\n")],
        ),
        (
            "bad indent",
            lambda s: sil(s),
            BAD_DATA,
            "not valid Python",
            [script("i.py", "if True:\nprint(1)\n")],
        ),
        (
            "a name the stand-in lacks",
            lambda s: sil(s),
            INTERFACE,
            "stand-in lacks",
            [script("n.py", "from rospy import not_in_rospy\n")],
        ),
        (
            "a module nobody has",
            lambda s: sil(s),
            INTERFACE,
            "no stand-in",
            [script("m.py", "import rtde_io\n")],
        ),
        (
            "--report in a missing folder",
            lambda s: sil("--report", "no/r.json", s),
            USAGE,
            "--report",
            [script("ok.py", "x = 1\n")],
        ),
        (
            "--report is a folder",
            lambda s: sil("--report", ".", s),
            USAGE,
            "is a directory",
            [script("ok.py", "x = 1\n")],
        ),
        (
            "--set a bad expression",
            lambda s: sil("--set", "x=(", s),
            USAGE,
            "not a Python expression",
            [script("ok.py", "x = 1\n")],
        ),
        (
            "--set a name not assigned",
            lambda s: sil("--set", "y=1", s),
            USAGE,
            "no plain assignment",
            [script("ok.py", "x = 1\n")],
        ),
    ]
    for value in ("0", "-1", "nan", "inf", "abc", "1e9"):
        sil_inputs.append(
            (
                f"--max-wall {value}",
                lambda s, v=value: sil("--max-wall", v, s),
                USAGE,
                "--max-wall",
                [script("ok.py", "x = 1\n")],
            )
        )
    for what, build, code, text, makers in sil_inputs:
        add(Case("sil inputs", what, with_files(makers, build) if makers else build(), code, text))
    # Scripts that never end by themselves end at the bounds.
    loops = [
        (
            "sleep loop",
            "import time\nwhile True:\n    time.sleep(1)\n",
            ["--max-sim", "2"],
            "a sleep after the node shut down",
        ),
        # rospy.sleep after shutdown raises, as the real rospy does: the script ends.
        (
            "rospy sleep loop",
            "import rospy\nrospy.init_node('x')\nwhile True:\n    rospy.sleep(0.5)\n",
            ["--max-sim", "2"],
            "ROSInterruptException",
        ),
        ("input loop", "while True:\n    input()\n", [], "input()"),
        ("busy loop", "while True:\n    pass\n", ["--max-wall", "2"], "wall-clock limit"),
        (
            "busy loop catching Exception",
            "while True:\n    try:\n        while True:\n            pass\n"
            "    except Exception:\n        pass\n",
            ["--max-wall", "2"],
            "wall-clock limit",
        ),
    ]
    for what, text, options, expect in loops:
        add(
            Case(
                "sil bounds",
                what,
                with_files([script("s.py", text)], lambda s, o=options: sil(*o, s)),
                1,
                expect,
                traceback=expect == "ROSInterruptException",
            )
        )
    add(
        Case(
            "sil bounds",
            "a child left running",
            with_files(
                [script("c.py", "import subprocess\nsubprocess.Popen(['sleep', '300'])\n")],
                lambda s: sil(s),
            ),
            TRIAL_FAILED,
            "ended 1 process",
        )
    )
    add(
        Case(
            "sil bounds",
            "tempfile under OUT",
            with_files(
                [script("t.py", "import tempfile\nprint('TMP', tempfile.gettempdir())\n")],
                lambda s: sil(s),
            ),
            TRIAL_FAILED,
            "run/tmp",
        )
    )
    # The verdict: a script that never touches the disk is not a success.
    add(
        Case(
            "sil verdict",
            "never touched",
            with_files(
                [script("a.py", "import rospy\nrospy.init_node('x')\nrospy.sleep(1)\n")],
                lambda s: sil(s),
            ),
            TRIAL_FAILED,
            "never touched the object",
        )
    )
    add(Case("sil verdict", "--version", cli("sil", "--version"), 0, "MuJoCo"))
    # Free text through every writer and reader: read_sweep on a Python controller's faults.
    for n, message in enumerate(["a, b", 'say "hi"', "x\\ny", "caf\u00e9, 'q'", '","']):
        code = (
            "import ssc_twin\n"
            f"def f(r):\n    raise ValueError({message!r})\n"
            "ssc_twin.sweep(pref=[100], beta=[2], step_mm=[7.5], repeats=1, threads=1, "
            "out_csv='s.csv', controller=f, scene='disk_benchmark_fast')\n"
            "d = str(ssc_twin.read_sweep('s.csv')['detail'][0])\n"
            f"assert d.endswith('ValueError: ' + {message!r}.replace('\\n', ' ') + ')'), d\n"
            "print('READ BACK')\n"
        )
        add(Case("writers and readers", f"read_sweep fault {n}", py(code), 0, "READ BACK"))
    # Ctrl-C inside a Python controller raises, in every entry point that runs one.
    for entry in (
        "run_trial(scene='disk_benchmark_fast', controller=f, keep_log=False)",
        "sweep(pref=[100], beta=[2], step_mm=[7.5], repeats=1, threads=1, "
        "out_csv='s.csv', controller=f, scene='disk_benchmark_fast')",
    ):
        code = (
            "import ssc_twin\n"
            "def f(r):\n    raise KeyboardInterrupt\n"
            f"try:\n    ssc_twin.{entry}\nexcept KeyboardInterrupt:\n    print('RAISED')\n"
        )
        add(
            Case(
                "ctrl-c",
                entry.split("(")[0],
                py(code),
                0,
                "RAISED",
                check=lambda r, folder: (
                    ""
                    if "RAISED" in r.stdout or "controller_fault" not in r.stdout
                    else "swallowed into a controller fault"
                ),
            )
        )
    # SystemExit inside a Python controller is raised, not written as a fault.
    add(
        Case(
            "ctrl-c",
            "SystemExit in a controller",
            py(
                "import ssc_twin\ndef f(r):\n    raise SystemExit(3)\n"
                "try:\n    ssc_twin.run_trial(scene='disk_benchmark_fast', controller=f, "
                "keep_log=False)\nexcept SystemExit as e:\n    print('RAISED', e.code)\n"
            ),
            0,
            "RAISED 3",
        )
    )
    # read_sweep refuses what is not a whole sweep table, and reads the rest as written.
    header = (
        "scene,pref_pa,beta,step_mm,repeat,seed,outcome,s_mm,r_mean_mm,dr_mm,sigma_r_mm,"
        "s_c,duration_s,speed_mm_s,speed_body_d_s,contour_mean_mm,contour_max_mm,"
        "swept_deg,iterations,sim_time_s,detail"
    )
    row = "g,100,2,7.5,1,5,failure_I,1,2,3,4,5,6,7,8,9,10,11,12,13,"
    tables = [
        ("a short row", header + "\n" + row + "\nx,1\n", "ValueError", "line 3"),
        ("header only", header + "\n", "OK", "0 rows"),
        ("CRLF rows", header + "\r\n" + row + '"a, b"\r\n', "OK", "1 rows"),
        ("a quoted line break", header + "\n" + row + '"two\nlines"\n', "OK", "1 rows"),
        ("doubled quotes", header + "\n" + row + '"say ""hi"""\n', "OK", 'say "hi"'),
    ]
    for what, text, expect, shown in tables:
        code = (
            "import ssc_twin\n"
            f"open('t.csv', 'w', newline='').write({text!r})\n"
            "try:\n    t = ssc_twin.read_sweep('t.csv')\n"
            "    print('OK', len(t['seed']), 'rows', list(t['detail']))\n"
            "except ValueError as e:\n    print('ValueError', e)\n"
        )
        add(
            Case(
                "writers and readers",
                f"read_sweep {what}",
                py(code),
                0,
                shown,
                check=lambda r, f, e=expect: "" if r.stdout.startswith(e) else r.stdout[:200],
            )
        )
    # A folder a study owns: other options are refused before anything in it is touched.
    tune = [
        "tune",
        "--controller",
        "fast",
        "--search",
        "step_max_mm=8:12",
        "--seeds",
        "1",
        "--evals",
        "1",
        "--timeout",
        "1",
        "--threads",
        "1",
        "--reference",
        "none",
        "--no-plot",
        "--out",
        "o",
    ]
    for option, value, diff in (
        ("--seeds", "2", "seeds"),
        ("--evals", "2", "evaluations"),
        ("--min-success", "0.5", "min_success"),
        ("--algorithm", "sbplx", "algorithm"),
        ("--search", "step_max_mm=8:11", "search"),
        ("--reference", "published", "references"),
        ("--seed", "7", "seed"),
    ):
        add(
            Case(
                "owned folders",
                f"tune again with {option}",
                owned_rerun(tune, option, value),
                1,
                diff + ":",
            )
        )
    # A resumed objects.csv row changed by hand is not trusted: dropped, its trial run again.
    for column, value in (
        ("outcome", "failure_II"),
        ("detail", "edited"),
        ("s_mm", "99.9"),
        ("iterations", "1"),
        ("row_digest", "0000000000000000"),
    ):
        add(
            Case(
                "owned folders",
                f"objects row with {column} edited",
                edited_objects_row(column, value),
                0,
                "row_digest does not match",
            )
        )
    add(
        Case(
            "no path",
            "stability with nothing unchanged",
            cli(
                "stability",
                "--scene",
                "disk_benchmark_fast",
                "--steps-ms",
                "8",
                "--threads",
                "1",
                "--out",
                "o",
            ),
            0,
            "",
            check=lambda r, f: "" if "0.00 ms" not in r.stdout else r.stdout[-300:],
        )
    )
    # A child never hangs its parent: a trial under an address-space limit ends.
    add(
        Case(
            "children",
            "trial under ulimit -v",
            lambda folder: subprocess.run(
                [
                    "bash",
                    "-c",
                    'ulimit -v 3000000; exec "$0" trial --scene disk_benchmark_fast --out o',
                    SSC,
                ],
                cwd=folder,
                capture_output=True,
                text=True,
                timeout=TIMEOUT_S,
            ),
            0,
            "outcome",
        )
    )
    # A scene with two cups, on each command that follows with one.
    for command in ("trial", "sweep", "tune", "stability"):
        add(
            Case(
                "two cups",
                command,
                with_files([two_cups], lambda s, c=command: cli(c, "--scene", s, "--out", "o")),
                BAD_DATA,
                "2 ssc.chamber_pressure sensors",
            )
        )
    return out


def success_has_a_path(r, folder):
    with open(os.path.join(folder, "o", "objects.csv")) as f:
        for row in csv.DictReader(f):
            if row["outcome"] == "success" and (
                float(row["s_mm"]) <= 0 or int(row["iterations"]) <= 1
            ):
                return "a success with no path: " + str(row)[:200]
    return ""


def edited_objects_row(column, value):
    args = ["objects", "--objects", "disk_d14", "--threads", "1", "--no-plot", "--out", "o"]

    def go(folder):
        first = subprocess.run(
            [SSC] + args, cwd=folder, capture_output=True, text=True, timeout=TIMEOUT_S
        )
        if first.returncode != 0:
            return first
        table = os.path.join(folder, "o", "objects.csv")
        with open(table, newline="") as f:
            rows = list(csv.reader(f))
        at = rows[0].index(column)
        if rows[1][at] == value:
            value_now = value + "0"
        else:
            value_now = value
        rows[1][at] = value_now
        with open(table, "w", newline="") as f:
            csv.writer(f, lineterminator="\n").writerows(rows)
        r = subprocess.run(
            [SSC] + args, cwd=folder, capture_output=True, text=True, timeout=TIMEOUT_S
        )
        with open(table, newline="") as f:
            now = list(csv.reader(f))
        if now[1][at] == value_now or r.stdout.count(" seed 1 ") != 1:
            r.stderr += "\nTHE EDITED ROW WAS KEPT"
            r.returncode = 99
        return r

    return go


def owned_rerun(tune, option, value):
    """A tune run, then the same with one option changed: refused, the first's rows intact."""

    def go(folder):
        first = subprocess.run(
            [SSC] + tune, cwd=folder, capture_output=True, text=True, timeout=TIMEOUT_S
        )
        if first.returncode != 0:
            return first
        evals = os.path.join(folder, "o", "evals")
        before = {p: open(p).read() for p in glob.glob(os.path.join(evals, "*", "sweep.csv"))}
        args = list(tune)
        if option in args:
            args[args.index(option) + 1] = value
        else:
            args += [option, value]
        r = subprocess.run(
            [SSC] + args, cwd=folder, capture_output=True, text=True, timeout=TIMEOUT_S
        )
        after = {p: open(p).read() for p in glob.glob(os.path.join(evals, "*", "sweep.csv"))}
        if after != before:
            r.stderr += "\nTHE FIRST SEARCH'S ROWS CHANGED"
            r.returncode = 99
        return r

    return go


def two_cups(folder):
    with open(os.path.join(SRC, "scenes", "disk_benchmark_gantry.xml")) as f:
        xml = f.read()
    # The gantry scene written elsewhere: its parts and models by absolute paths.
    xml = xml.replace('file="../models/', 'file="%s/models/' % SRC)
    xml = xml.replace('file="parts/', 'file="%s/scenes/parts/' % SRC)
    second = '<body name="two" pos="0.3 0 0.3"><attach model="ssc_tool" body="tool" prefix="two_"/>'
    xml = xml.replace("</mujoco>", f"<worldbody>{second}</body></worldbody></mujoco>")
    with open(os.path.join(folder, "two.xml"), "w") as f:
        f.write(xml)
    return "two.xml"


def judge(case, folder):
    """(verdict, the result or None, seconds): ok, hang, crash, wrong, leftover (anything left
    in the case's own temp folder, TMPDIR for everything it runs)."""
    tmp = os.path.join(folder, ".tmp")
    os.makedirs(tmp)
    saved = os.environ.get("TMPDIR")
    os.environ["TMPDIR"] = tmp
    start = time.monotonic()
    try:
        r = case.run(folder)
    except subprocess.TimeoutExpired:
        return "hang", None, time.monotonic() - start
    finally:
        if saved is None:
            os.environ.pop("TMPDIR", None)
        else:
            os.environ["TMPDIR"] = saved
    dt = time.monotonic() - start
    text = r.stdout + r.stderr
    if r.returncode < 0 or "terminate called" in text or "Segmentation" in text:
        return "crash", r, dt
    if r.returncode != case.code or case.text not in text:
        return "wrong", r, dt
    if case.check and case.check(r, folder):
        return "wrong", r, dt
    if r.returncode not in (0, TRIAL_FAILED) and "Traceback" in r.stderr and not case.traceback:
        return "wrong", r, dt  # a failure is one line, not a traceback
    left = os.listdir(tmp)
    if left:
        return "leftover", r, dt
    return "ok", r, dt


class ReliabilityRoundTest(unittest.TestCase):
    def test_every_case_of_the_round(self):
        for case in cases():
            with self.subTest(family=case.family, case=case.what):
                folder = tempfile.mkdtemp(prefix="round_")
                try:
                    verdict, r, _ = judge(case, folder)
                    detail = (
                        "" if r is None else f"rc {r.returncode}: {(r.stdout + r.stderr)[-600:]}"
                    )
                    self.assertEqual(verdict, "ok", detail)
                finally:
                    shutil.rmtree(folder, ignore_errors=True)


def report():
    counts = {}
    families = {}
    for case in cases():
        folder = tempfile.mkdtemp(prefix="round_")
        try:
            verdict, r, dt = judge(case, folder)
        finally:
            shutil.rmtree(folder, ignore_errors=True)
        kind = verdict
        if verdict == "ok":
            kind = "refused" if case.code not in (0, TRIAL_FAILED) else "handled"
        counts[kind] = counts.get(kind, 0) + 1
        families.setdefault(case.family, {}).setdefault(kind, 0)
        families[case.family][kind] += 1
        line = (
            "" if r is None else ((r.stderr.strip() or r.stdout.strip()).splitlines() or [""])[-1]
        )
        print(
            f"{kind:9} rc={'-' if r is None else r.returncode:>3} {dt:5.1f}s  "
            f"{case.family:18} {case.what[:38]:38} {line[:80]}"
        )
    print()
    print("| family | cases | refused with a clear message | handled | anything else |")
    print("| --- | --- | --- | --- | --- |")
    for family, c in families.items():
        other = sum(v for k, v in c.items() if k not in ("refused", "handled"))
        print(
            f"| {family} | {sum(c.values())} | {c.get('refused', 0)} | {c.get('handled', 0)} | "
            f"{other} |"
        )
    total = sum(counts.values())
    other = total - counts.get("refused", 0) - counts.get("handled", 0)
    print(f"| all | {total} | {counts.get('refused', 0)} | {counts.get('handled', 0)} | {other} |")
    print(json.dumps(counts))


if __name__ == "__main__":
    if "--report" in sys.argv:
        report()
    else:
        unittest.main()
