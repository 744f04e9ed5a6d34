"""Runs a lab script against the twin: ``python -m ssc_twin.sil [options] SCRIPT [ARGS...]``.

The script runs unchanged, in this process, with the stand-ins first on its import path
(rospy, tf, rtde_control, rtde_receive, the message and service packages), harmless no-ops for
plots, cameras and learned models, its own folder next (its helperFunction package and local
modules), then everything installed. Around it:

- time: virtual by default (rospy.sleep, Rate, time.sleep, plt.pause and the robot's blocking
  calls step the simulation; time.time reads the simulation clock), or --realtime;
- files: the script's /tmp is OUT/tmp and its home (~, where the lab saves SuctionExperiment/) is
  OUT, so nothing outside OUT is written or deleted;
- input(): answered with Enter (the operator's key presses), unless --interactive.
"""

import argparse
import ast
import builtins
import errno
import inspect
import json
import os
import sys
import tempfile
import time as _time
import traceback
import types

from .. import _core
from . import limits as limits_mod, noop, verdict as verdict_mod, world as world_mod

STANDINS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "standins")

# The project's exit codes (common/exit_codes.h, docs/reliability.md).
_CODES = _core.EXIT_CODES
EXIT_OK, EXIT_ERROR, EXIT_USAGE = _CODES["ok"], _CODES["failed"], _CODES["usage"]
EXIT_MISSING_INPUT, EXIT_BAD_DATA = _CODES["missing_input"], _CODES["bad_data"]
EXIT_TRIAL_FAILED, EXIT_MISSING = _CODES["trial_failed"], _CODES["missing_interface"]
EXIT_INTERRUPTED = _CODES["interrupted"]


class BadInput(Exception):
    pass


def parse_args(argv):
    p = argparse.ArgumentParser(
        prog="ssc sil",
        description="Run a lab script (ROS 1 + ur_rtde) against the twin, unchanged.",
    )
    p.add_argument(
        "--scene",
        default=_core.default_scene(),
        help="scene name or MJCF path (default: %s)" % _core.default_scene(),
    )
    p.add_argument(
        "--seed",
        type=seed,
        default=1,
        help="sensor noise seed (default 1), a whole number in [0, %d]" % MAX_SEED,
    )
    p.add_argument(
        "--realtime",
        action="store_true",
        help="pace the simulation to the wall clock (default: virtual time)",
    )
    p.add_argument("--viewer", action="store_true", help="show the scene in MuJoCo's viewer")
    p.add_argument(
        "--out", default="sil_out", help="folder for the script's /tmp and home (default ./sil_out)"
    )
    p.add_argument(
        "--pause-cost",
        type=pause_cost,
        default=world_mod.DEFAULT_PAUSE_COST_S,
        metavar="S|measured",
        help="simulated seconds a plt.pause costs beyond its argument: the figure "
        "redraw the lab's loop paid (default %(default)s, measured: docs/sil.md), "
        "or 'measured': the script's own CPU time building and drawing its plot "
        "on this machine (with --plots: the real matplotlib draws)",
    )
    p.add_argument(
        "--max-sim",
        type=max_sim,
        default=600.0,
        metavar="S",
        help="shut the node down after S simulated seconds (default 600)",
    )
    p.add_argument(
        "--max-wall",
        type=max_wall,
        default=DEFAULT_MAX_WALL_S,
        metavar="S",
        help="end the script after S wall-clock seconds, whatever it does (default %(default)g)",
    )
    p.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="NAME=VALUE",
        help="run as if the script's knob line read NAME = VALUE (the first plain "
        "assignment to NAME in main(), else at module level); the file is "
        "not edited",
    )
    p.add_argument(
        "--plots", action="store_true", help="use the real matplotlib (default: plots are no-ops)"
    )
    p.add_argument(
        "--interactive",
        action="store_true",
        help="read input() from the terminal (default: answer Enter)",
    )
    p.add_argument("--report", metavar="FILE", help="write a JSON summary of the run")
    p.add_argument("--verbose", action="store_true", help="print what the twin's nodes do")
    p.add_argument(
        "--no-progress",
        action="store_true",
        help="no progress lines (default: one every %g s of wall clock)" % PROGRESS_WALL_S,
    )
    p.add_argument(
        "--version",
        action="version",
        version="ssc sil (ssc_twin %s, MuJoCo %s)" % (_package_version(), _core.mujoco_version()),
    )
    p.add_argument("script", help="the lab script (.py)")
    p.add_argument("args", nargs=argparse.REMAINDER, help="the script's own arguments")
    return p.parse_args(argv)


PROGRESS_WALL_S = 30.0


def _package_version():
    try:
        from importlib.metadata import version

        return version("ssc_twin")
    except Exception:  # a build tree's staged package has no metadata
        return "(build tree)"


# ssc's seeds: whole numbers doubles hold exactly (common/strict_number.h), as every ssc --seed.
MAX_SEED = _core.max_seed
MAX_SIM_S = 86400.0
DEFAULT_MAX_WALL_S = 3600.0
# A script that makes no simulated time pass for this long is stuck in a loop of its own (a busy
# loop, or input() or a sleep after the node shut down): it is ended.
STUCK_WALL_S = 60.0
# Calls into the twin that pass no simulated time (input() answered, a sleep after shutdown) in
# a row before the script counts as looping on them.
MAX_IDLE_CALLS = 1000
# After a limit is hit, a script that swallows the stop gets this long before the runner leaves.
STOP_GRACE_WALL_S = 10.0


def seed(text):
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError("%r is not a whole number in [0, %d]" % (text, MAX_SEED))
    if not 0 <= value <= MAX_SEED:
        raise argparse.ArgumentTypeError("%r is outside [0, %d]" % (text, MAX_SEED))
    return value


def max_sim(text):
    try:
        value = float(text)
    except ValueError:
        value = float("nan")
    if not 0.0 < value <= MAX_SIM_S:
        raise argparse.ArgumentTypeError("%r: simulated seconds in (0, %g]" % (text, MAX_SIM_S))
    return value


def max_wall(text):
    try:
        value = float(text)
    except ValueError:
        value = float("nan")
    if not 0.0 < value <= MAX_SIM_S:
        raise argparse.ArgumentTypeError("%r: wall-clock seconds in (0, %g]" % (text, MAX_SIM_S))
    return value


def pause_cost(text):
    if text == world_mod.MEASURED:
        return text
    try:
        value = float(text)
    except ValueError:
        value = float("nan")
    if not 0.0 <= value <= 10.0:
        raise argparse.ArgumentTypeError("%r: seconds in [0, 10], or 'measured'" % text)
    return value


def apply_knobs(tree, knobs, script):
    """Replaces the value of the first plain `NAME = ...` in main() (else at module level)."""
    seen = set()
    for knob in knobs:
        if "=" not in knob:
            raise BadInput("--set %r: expected NAME=VALUE" % knob)
        name, value = (s.strip() for s in knob.split("=", 1))
        if name in seen:  # a typo, not an override: which value was meant is unknowable
            raise BadInput("--set %s: given twice" % name)
        seen.add(name)
        try:
            new_value = ast.parse(value, mode="eval").body
        except SyntaxError:
            raise BadInput("--set %s: %r is not a Python expression" % (name, value))
        bodies = [n.body for n in tree.body if isinstance(n, ast.FunctionDef) and n.name == "main"]
        bodies.append(tree.body)
        done = False
        for body in bodies:
            for stmt in body:
                if (
                    isinstance(stmt, ast.Assign)
                    and len(stmt.targets) == 1
                    and isinstance(stmt.targets[0], ast.Name)
                    and stmt.targets[0].id == name
                ):
                    stmt.value = ast.copy_location(new_value, stmt.value)
                    done = True
                    break
            if done:
                break
        if not done:
            raise BadInput(
                "--set %s: %s has no plain assignment '%s = ...' in main() or at "
                "module level" % (name, script, name)
            )
    ast.fix_missing_locations(tree)
    return tree


class TmpRedirect:
    """Maps the script's /tmp onto a private folder (os, open): the lab's saver lists, reads,
    moves and deletes every CSV in /tmp."""

    def __init__(self, tmp_dir, out_dir):
        self.tmp_dir = tmp_dir
        self.out_dir = out_dir  # the run's own files stay where they are, even under /tmp
        self.saved = {}

    def map(self, p):
        if isinstance(p, os.PathLike):
            p = os.fspath(p)
        if (
            isinstance(p, str)
            and (p == "/tmp" or p.startswith("/tmp/"))
            and not (p == self.out_dir or p.startswith(self.out_dir + "/"))
        ):
            return self.tmp_dir + p[4:]
        return p

    def install(self):
        m = self.map

        def wrap1(fn):
            return lambda path, *a, **k: fn(m(path), *a, **k)

        def wrap2(fn):
            return lambda src, dst, *a, **k: fn(m(src), m(dst), *a, **k)

        for mod, names, wrap in (
            (
                os,
                (
                    "listdir",
                    "remove",
                    "unlink",
                    "makedirs",
                    "mkdir",
                    "stat",
                    "scandir",
                    "rmdir",
                    "lstat",
                ),
                wrap1,
            ),
            (os, ("rename", "replace"), wrap2),
            (builtins, ("open",), wrap1),
        ):
            for name in names:
                fn = getattr(mod, name)
                self.saved[(mod, name)] = fn
                setattr(mod, name, wrap(fn))
        # os.listdir() with no argument must keep working.
        listdir = self.saved[(os, "listdir")]
        os.listdir = lambda path=".": listdir(m(path))
        scandir = self.saved[(os, "scandir")]
        os.scandir = lambda path=".": scandir(m(path))

    def uninstall(self):
        for (mod, name), fn in self.saved.items():
            setattr(mod, name, fn)


def lab_code_inconsistency(e, script_dir):
    """The message for an AttributeError raised on an object of the script's own code (a class or
    module under the script's folder, e.g. the lab's helperFunction), else None: a method the
    script calls but its own helper no longer defines is the checkout's bug, not a missing
    stand-in."""
    obj, name = getattr(e, "obj", None), getattr(e, "name", None)
    if obj is None or not name:
        return None
    owner = obj if isinstance(obj, (type, types.ModuleType)) else type(obj)
    try:
        path = os.path.abspath(inspect.getfile(owner))
    except (TypeError, OSError):
        return None
    root = os.path.abspath(script_dir) + os.sep
    if not path.startswith(root):
        return None
    where = traceback.extract_tb(e.__traceback__)[-1]
    kind = "module" if isinstance(owner, types.ModuleType) else "class"
    return (
        "the lab's own code, not the twin: %s:%d uses %s.%s, which %s %s (%s) does not "
        "define; this checkout's script and helper disagree (docs/sil.md names a commit that "
        "runs)"
        % (
            os.path.basename(where.filename),
            where.lineno,
            owner.__name__,
            name,
            kind,
            owner.__name__,
            os.path.relpath(path, root),
        )
    )


def _virtual_time(w):
    saved = (_time.time, _time.sleep)
    _time.time = w.ros_time_s
    _time.sleep = w.sleep
    return saved


def _fail(message, status):
    print("ssc sil: %s" % message, file=sys.stderr)
    return status


def check_inputs(opts):
    """The script, --out and --report, checked before anything runs or is written: None, or the
    exit status after a 'ssc sil:' line."""
    script = opts.script
    if not os.path.lexists(script):
        return _fail("%s: no such file (the lab script to run)" % script, EXIT_MISSING_INPUT)
    if os.path.isdir(script):
        return _fail("%s: is a directory, not a script (give the .py file)" % script, EXIT_BAD_DATA)
    if not os.path.isfile(script):
        return _fail(
            "%s: not a regular file (a FIFO, device, socket or dangling link): give "
            "the .py file" % script,
            EXIT_BAD_DATA,
        )
    out = os.path.abspath(opts.out)
    if os.path.exists(out) and not os.path.isdir(out):
        return _fail("--out: %r exists and is not a directory" % opts.out, EXIT_USAGE)
    if opts.report:
        report = os.path.abspath(opts.report)
        parent = os.path.dirname(report)
        if os.path.isdir(report):
            return _fail(
                "--report: %r is a directory (give a file to write)" % opts.report, EXIT_USAGE
            )
        if not os.path.isdir(parent):
            return _fail(
                "--report: %r: its folder %s does not exist" % (opts.report, parent), EXIT_USAGE
            )
        if not os.access(parent, os.W_OK) or (
            os.path.exists(report) and not os.access(report, os.W_OK)
        ):
            return _fail(
                "--report: %r cannot be written (permission denied)" % opts.report, EXIT_USAGE
            )
    return None


def compile_script(opts):
    """The script's code with its knobs set, or (None, status) after a 'ssc sil:' line."""
    script = os.path.abspath(opts.script)
    try:
        with open(script, "rb") as f:
            raw = f.read()
    except OSError as e:
        return None, _fail("%s: cannot read: %s" % (opts.script, e.strerror), EXIT_MISSING_INPUT)
    if b"\0" in raw:
        return None, _fail("%s: not Python source (binary data)" % opts.script, EXIT_BAD_DATA)
    try:
        source = raw.decode("utf-8")
    except UnicodeDecodeError as e:
        return None, _fail(
            "%s: not Python source (not UTF-8 text at byte %d)" % (opts.script, e.start),
            EXIT_BAD_DATA,
        )
    try:
        tree = apply_knobs(ast.parse(source, filename=script), opts.set, opts.script)
        return compile(tree, script, "exec"), None
    except SyntaxError as e:
        return None, _fail(
            "%s:%s: not valid Python: %s" % (opts.script, e.lineno, e.msg), EXIT_BAD_DATA
        )
    except (BadInput, ValueError) as e:
        return None, _fail(str(e), EXIT_USAGE)


def make_world(opts, tmp_dir):
    """The twin's world, or (None, status) after a 'ssc sil:' line."""
    try:  # the scene, checked before anything is written (the C++ loader's message)
        w = world_mod.install(
            world_mod.World(
                scene=opts.scene,
                seed=opts.seed,
                realtime=opts.realtime,
                tmp_dir=tmp_dir,
                pause_cost_s=opts.pause_cost,
                verbose=opts.verbose,
            )
        )
    except (RuntimeError, ValueError) as e:
        missing = "no such file" in str(e)
        return None, _fail("--scene: %s" % e, EXIT_MISSING_INPUT if missing else EXIT_BAD_DATA)
    except OSError as e:  # the World makes OUT/tmp
        return None, _fail(
            "--out: cannot create %s: %s" % (e.filename or tmp_dir, e.strerror), EXIT_USAGE
        )
    if opts.viewer:
        from .viewer import Viewer

        try:
            w.viewer = Viewer(w)
        except Exception as e:  # no display, no OpenGL
            return None, _fail("--viewer: cannot open the viewer (%s)" % e, EXIT_ERROR)
    return w, None


STANDIN_MODULES = (
    "rospy",
    "tf",
    "rtde_control",
    "rtde_receive",
    "std_msgs",
    "geometry_msgs",
    "sensor_msgs",
    "suction_cup",
    "tae_psoc",
    "netft_utils",
)


def classify_failure(e, script):
    """(status, problem) for an exception that ended the script."""
    if isinstance(e, SystemExit):
        ok = e.code in (None, 0)
        return (EXIT_OK, "") if ok else (EXIT_ERROR, "SystemExit(%r)" % (e.code,))
    if isinstance(e, limits_mod.RunLimit):
        return EXIT_ERROR, "stopped: %s" % e
    if isinstance(e, ModuleNotFoundError):
        return EXIT_MISSING, "module %s (no stand-in, not installed)" % e.name
    if isinstance(e, ImportError) and (e.name or "").split(".")[0] in STANDIN_MODULES:
        return EXIT_MISSING, "%s (the twin's stand-in lacks it)" % e
    if isinstance(e, OSError) and e.errno in (errno.ENOSPC, errno.EDQUOT, errno.EFBIG):
        return EXIT_ERROR, "cannot write %s: %s (the disk is full or a size limit was hit)" % (
            e.filename or "a file",
            e.strerror,
        )
    if isinstance(e, (AttributeError, NotImplementedError)):
        traceback.print_exc()
        lab = lab_code_inconsistency(e, os.path.dirname(script))
        if lab:
            return EXIT_ERROR, lab
        where = traceback.extract_tb(e.__traceback__)[-1]
        return EXIT_MISSING, "%s at %s:%d: %s" % (
            type(e).__name__,
            os.path.basename(where.filename),
            where.lineno,
            e,
        )
    traceback.print_exc()  # the script's own failure: report it, as python would
    return EXIT_ERROR, "%s: %s" % (type(e).__name__, e)


class ScriptSandbox:
    """What the script sees while it runs, installed and taken back whole: the stand-ins on its
    path, /tmp and ~ under OUT (tempfile too), virtual time, input() answered, its argv."""

    def __init__(self, opts, w, limits, script, out, tmp_dir):
        self.opts, self.w, self.limits = opts, w, limits
        self.script, self.out, self.tmp_dir = script, out, tmp_dir
        self.saved = {}

    def install(self):
        opts, w = self.opts, self.w
        sys.path[:0] = [STANDINS, os.path.dirname(self.script)]
        for name in list(sys.modules):  # a real rospy imported earlier must not shadow ours
            if name.split(".")[0] in STANDIN_MODULES:
                del sys.modules[name]
        noop.install(plots=opts.plots)
        if opts.plots:
            import matplotlib.pyplot as pyplot

            pyplot.pause = noop.real_pause(pyplot)
        self.redirect = TmpRedirect(self.tmp_dir, self.out)
        self.saved["env"] = {k: os.environ.get(k) for k in ("HOME", "TMPDIR")}
        os.environ["HOME"] = self.out
        os.environ["TMPDIR"] = self.tmp_dir
        self.saved["tempdir"] = tempfile.tempdir
        tempfile.tempdir = self.tmp_dir
        self.saved["time"] = None if opts.realtime else _virtual_time(w)
        self.saved["input"] = builtins.input
        builtins.input = self._input
        self.saved["argv"] = sys.argv
        sys.argv = [self.script] + list(opts.args)
        w.on_idle = self.limits.idle_call
        self.redirect.install()
        self.limits.install()

    def _input(self, prompt=""):
        if self.opts.interactive:
            self.limits.waiting_for_operator = True
            try:
                return self.saved["input"](prompt)
            finally:
                self.limits.waiting_for_operator = False
        self.limits.idle_call("input()")
        print("%s[ssc sil: Enter]" % prompt)
        return ""

    def uninstall(self):
        self.limits.uninstall()
        self.redirect.uninstall()
        if self.saved["time"]:
            _time.time, _time.sleep = self.saved["time"]
        builtins.input = self.saved["input"]
        sys.argv = self.saved["argv"]
        tempfile.tempdir = self.saved["tempdir"]
        for k, v in self.saved["env"].items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v
        self.w.on_idle = None


def run_script(code, script, sandbox):
    """Runs the script in the sandbox: (status, problem)."""
    runner_pid = os.getpid()
    status, problem = EXIT_OK, ""
    sandbox.install()
    try:
        try:
            exec(code, {"__name__": "__main__", "__file__": script, "__builtins__": builtins})
        finally:
            if os.getpid() != runner_pid:  # a child the script forked: it ends here, silently
                os._exit(0)
    except BaseException as e:
        status, problem = classify_failure(e, script)
    finally:
        sandbox.uninstall()
    return status, problem


class Progress:
    """A line on stderr every PROGRESS_WALL_S of wall clock: how far the run is and what the cup
    did so far (called from the simulation's loop, in the script's thread)."""

    def __init__(self, w, max_sim_s):
        self.w, self.max_sim_s = w, max_sim_s
        self.start = self.last = _time.monotonic()

    def __call__(self):
        now = _time.monotonic()
        if now - self.last < PROGRESS_WALL_S:
            return
        self.last = now
        v = self.w.verdict.summary()
        state = (
            verdict_mod.WORDS[v["outcome"]]
            if self.w.verdict.outcome
            else ("not touched yet" if v["touched_at_s"] is None else "following")
        )
        print(
            "ssc sil: %.0f of %.0f s simulated in %.0f s wall: %s, peak vacuum %.1f Pa, swept "
            "%.0f deg"
            % (
                self.w.sim_time,
                self.max_sim_s,
                now - self.start,
                state,
                v["peak_vacuum_pa"],
                v["swept_deg"],
            ),
            file=sys.stderr,
            flush=True,
        )


def write_report(opts, summary):
    """--report, whole or not at all: False after a 'ssc sil:' line."""
    tmp = opts.report + ".tmp%d" % os.getpid()
    try:
        with open(tmp, "w") as f:
            json.dump(summary, f, indent=1)
        os.replace(tmp, opts.report)
        return True
    except OSError as e:
        if os.path.exists(tmp):
            os.remove(tmp)
        _fail("--report: cannot write %s: %s" % (opts.report, e.strerror), EXIT_ERROR)
        return False


def summarize(opts, script, out, w, status, problem, wall, limits, children):
    mats = sorted(
        os.path.join(dp, f) for dp, _, fs in os.walk(out) for f in fs if f.endswith(".mat")
    )
    verdict = w.verdict.summary()
    if status == EXIT_OK and verdict["outcome"] != "success":
        status = EXIT_TRIAL_FAILED
    summary = {
        "script": script,
        "status": status,
        "problem": problem,
        "verdict": verdict,
        "sim_time_s": round(w.sim_time, 4),
        "wall_time_s": round(wall, 3),
        "logger_recordings": w.logger.started,
        "mat_files": mats,
        "hit_time_limit": w.shutdown and w.sim_time >= opts.max_sim - 1e-9,
        "stopped_by": limits.reason,
        "children_ended": children,
        "plt_pause": w.pause_summary(),
    }
    ran = (
        "finished"
        if status in (EXIT_OK, EXIT_TRIAL_FAILED)
        else ("missing interface: " + problem if status == EXIT_MISSING else "failed: " + problem)
    )
    print(
        "ssc sil: %s: %s; the trial: %s (peak vacuum %.1f Pa, swept %.0f deg); %.2f s "
        "simulated in %.2f s wall%s"
        % (
            os.path.basename(script),
            ran,
            verdict_mod.WORDS[verdict["outcome"]],
            verdict["peak_vacuum_pa"],
            verdict["swept_deg"],
            w.sim_time,
            wall,
            " (stopped at --max-sim)" if summary["hit_time_limit"] else "",
        )
    )
    if children:
        print("ssc sil: ended %d process(es) the script left running" % children)
    ps = summary["plt_pause"]
    if ps:
        print(
            "ssc sil: plt.pause: %d calls; the script's CPU per call (median, this machine): "
            "%.1f ms building the plot, %.1f ms drawing it; charged: %s"
            % (
                ps["pauses"],
                1e3 * ps["build_cpu_s_median"],
                1e3 * ps["draw_cpu_s_median"],
                "that CPU time"
                if ps["cost"] == world_mod.MEASURED
                else "the argument + %g s" % ps["cost"],
            )
        )
    for m in mats:
        print("ssc sil: saved %s" % m)
    return summary, status


def run(opts):
    bad = check_inputs(opts)
    if bad is not None:
        return bad
    script = os.path.abspath(opts.script)
    out = os.path.abspath(opts.out)
    tmp_dir = os.path.join(out, "tmp")
    code, bad = compile_script(opts)
    if code is None:
        return bad
    w, bad = make_world(opts, tmp_dir)
    if w is None:
        return bad
    # The node shuts down at the simulated time limit (a script waiting forever ends).
    w._push(opts.max_sim, lambda: setattr(w, "shutdown", True), 0)
    wall0 = _time.perf_counter()
    finish = {}

    def give_up():  # a script that swallowed the stop: write what there is and leave
        sandbox.uninstall()
        finish["status"], finish["problem"] = EXIT_ERROR, "stopped: %s" % limits.reason
        return leave(_time.perf_counter() - wall0, hard=True)

    def leave(wall, hard=False):
        children = limits_mod.end_children(os.getpid())
        summary, status = summarize(
            opts, script, out, w, finish["status"], finish["problem"], wall, limits, children
        )
        ok = write_report(opts, summary) if opts.report else True
        status = status if ok else EXIT_ERROR
        if hard or w.viewer is not None:
            # The passive viewer's GL thread does not survive the interpreter's teardown (a hang
            # or a crash in about half the runs under Xvfb): everything is written; leave now.
            sys.stdout.flush()
            sys.stderr.flush()
            os._exit(status)
        return status

    limits = limits_mod.Limits(
        w, opts.max_wall, STUCK_WALL_S, MAX_IDLE_CALLS, STOP_GRACE_WALL_S, give_up
    )
    limits_mod.watch_forks()
    if not opts.no_progress:
        w.progress = Progress(w, opts.max_sim)
    sandbox = ScriptSandbox(opts, w, limits, script, out, tmp_dir)
    w.wall_start = _time.perf_counter() - w.sim_time  # real time is paced from the script's start
    finish["status"], finish["problem"] = run_script(code, script, sandbox)
    wall = _time.perf_counter() - wall0
    w.logger.set_enabled(False)
    if w.viewer is not None:
        w.viewer.close()
    return leave(wall)


def main(argv=None):
    opts = parse_args(sys.argv[1:] if argv is None else argv)
    return run(opts)
