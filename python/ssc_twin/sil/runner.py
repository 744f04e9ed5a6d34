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
import inspect
import json
import os
import sys
import time as _time
import traceback
import types

from .. import _core
from . import noop, world as world_mod

STANDINS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "standins")

EXIT_OK, EXIT_ERROR, EXIT_BAD_INPUT, EXIT_MISSING = 0, 1, 2, 3


class BadInput(Exception):
    pass


def parse_args(argv):
    p = argparse.ArgumentParser(
        prog="ssc sil",
        description="Run a lab script (ROS 1 + ur_rtde) against the twin, unchanged.")
    p.add_argument("--scene", default="disk_benchmark_gantry",
                   help="scene name or MJCF path (default: disk_benchmark_gantry)")
    p.add_argument("--seed", type=seed, default=1,
                   help="sensor noise seed (default 1), a whole number in [0, %d]" % MAX_SEED)
    p.add_argument("--realtime", action="store_true",
                   help="pace the simulation to the wall clock (default: virtual time)")
    p.add_argument("--viewer", action="store_true", help="show the scene in MuJoCo's viewer")
    p.add_argument("--out", default="sil_out",
                   help="folder for the script's /tmp and home (default ./sil_out)")
    p.add_argument("--pause-cost", type=pause_cost, default=world_mod.DEFAULT_PAUSE_COST_S,
                   metavar="S|measured",
                   help="simulated seconds a plt.pause costs beyond its argument: the figure "
                        "redraw the lab's loop paid (default %(default)s, measured: docs/sil.md), "
                        "or 'measured': the script's own CPU time building and drawing its plot "
                        "on this machine (with --plots: the real matplotlib draws)")
    p.add_argument("--max-sim", type=max_sim, default=600.0, metavar="S",
                   help="shut the node down after S simulated seconds (default 600)")
    p.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                   help="run as if the script's knob line read NAME = VALUE (the first plain "
                        "assignment to NAME in main(), else at module level); the file is "
                        "not edited")
    p.add_argument("--plots", action="store_true",
                   help="use the real matplotlib (default: plots are no-ops)")
    p.add_argument("--interactive", action="store_true",
                   help="read input() from the terminal (default: answer Enter)")
    p.add_argument("--report", metavar="FILE", help="write a JSON summary of the run")
    p.add_argument("--verbose", action="store_true", help="print what the twin's nodes do")
    p.add_argument("script", help="the lab script (.py)")
    p.add_argument("args", nargs=argparse.REMAINDER, help="the script's own arguments")
    return p.parse_args(argv)


# ssc's seeds: whole numbers doubles hold exactly (common/strict_number.h), as every ssc --seed.
MAX_SEED = _core.max_seed
MAX_SIM_S = 86400.0


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
    for knob in knobs:
        if "=" not in knob:
            raise BadInput("--set %r: expected NAME=VALUE" % knob)
        name, value = (s.strip() for s in knob.split("=", 1))
        try:
            new_value = ast.parse(value, mode="eval").body
        except SyntaxError:
            raise BadInput("--set %s: %r is not a Python expression" % (name, value))
        bodies = [n.body for n in tree.body if isinstance(n, ast.FunctionDef) and n.name == "main"]
        bodies.append(tree.body)
        done = False
        for body in bodies:
            for stmt in body:
                if (isinstance(stmt, ast.Assign) and len(stmt.targets) == 1
                        and isinstance(stmt.targets[0], ast.Name) and stmt.targets[0].id == name):
                    stmt.value = ast.copy_location(new_value, stmt.value)
                    done = True
                    break
            if done:
                break
        if not done:
            raise BadInput("--set %s: %s has no plain assignment '%s = ...' in main() or at "
                           "module level" % (name, script, name))
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
        if (isinstance(p, str) and (p == "/tmp" or p.startswith("/tmp/"))
                and not (p == self.out_dir or p.startswith(self.out_dir + "/"))):
            return self.tmp_dir + p[4:]
        return p

    def install(self):
        m = self.map

        def wrap1(fn):
            return lambda path, *a, **k: fn(m(path), *a, **k)

        def wrap2(fn):
            return lambda src, dst, *a, **k: fn(m(src), m(dst), *a, **k)

        for mod, names, wrap in ((os, ("listdir", "remove", "unlink", "makedirs", "mkdir",
                                      "stat", "scandir", "rmdir", "lstat"), wrap1),
                                 (os, ("rename", "replace"), wrap2),
                                 (builtins, ("open",), wrap1)):
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
    return ("the lab's own code, not the twin: %s:%d uses %s.%s, which %s %s (%s) does not "
            "define; this checkout's script and helper disagree (docs/sil.md names a commit that "
            "runs)" % (os.path.basename(where.filename), where.lineno, owner.__name__, name, kind,
                       owner.__name__, os.path.relpath(path, root)))


def _virtual_time(w):
    saved = (_time.time, _time.sleep)
    _time.time = w.ros_time_s
    _time.sleep = w.sleep
    return saved


def run(opts):
    script = os.path.abspath(opts.script)
    if not os.path.isfile(script):
        print("ssc sil: no such script: %s" % opts.script, file=sys.stderr)
        return EXIT_BAD_INPUT
    out = os.path.abspath(opts.out)
    tmp_dir = os.path.join(out, "tmp")
    if os.path.exists(out) and not os.path.isdir(out):
        print("ssc sil: --out: %r exists and is not a directory" % opts.out, file=sys.stderr)
        return EXIT_BAD_INPUT
    with open(script) as f:
        source = f.read()
    try:
        tree = apply_knobs(ast.parse(source, filename=script), opts.set, opts.script)
    except BadInput as e:
        print("ssc sil: %s" % e, file=sys.stderr)
        return EXIT_BAD_INPUT
    code = compile(tree, script, "exec")

    try:  # the scene, checked before anything is written (the C++ loader's message)
        w = world_mod.install(world_mod.World(scene=opts.scene, seed=opts.seed,
                                              realtime=opts.realtime, tmp_dir=tmp_dir,
                                              pause_cost_s=opts.pause_cost, verbose=opts.verbose))
    except (RuntimeError, ValueError) as e:
        print("ssc sil: --scene: %s" % e, file=sys.stderr)
        return EXIT_ERROR
    except OSError as e:  # the World makes OUT/tmp
        print("ssc sil: --out: cannot create %s: %s" % (e.filename or tmp_dir, e.strerror),
              file=sys.stderr)
        return EXIT_BAD_INPUT
    if opts.viewer:
        from .viewer import Viewer
        try:
            w.viewer = Viewer(w)
        except Exception as e:  # no display, no OpenGL
            print("ssc sil: --viewer: cannot open the viewer (%s)" % e, file=sys.stderr)
            return EXIT_ERROR
    # The node shuts down at the simulated time limit (a script waiting forever ends).
    w._push(opts.max_sim, lambda: setattr(w, "shutdown", True), 0)

    sys.path[:0] = [STANDINS, os.path.dirname(script)]
    for name in list(sys.modules):  # a real rospy imported earlier must not shadow ours
        if name.split(".")[0] in ("rospy", "tf", "rtde_control", "rtde_receive", "std_msgs",
                                  "geometry_msgs", "sensor_msgs", "suction_cup", "tae_psoc",
                                  "netft_utils"):
            del sys.modules[name]
    noop.install(plots=opts.plots)
    if opts.plots:
        import matplotlib.pyplot as pyplot
        pyplot.pause = noop.real_pause(pyplot)
    redirect = TmpRedirect(tmp_dir, out)
    home = os.environ.get("HOME")
    os.environ["HOME"] = out
    saved_time = None if opts.realtime else _virtual_time(w)
    saved_input = builtins.input
    if not opts.interactive:
        def answer(prompt=""):
            print("%s[ssc sil: Enter]" % prompt)
            return ""
        builtins.input = answer
    saved_argv = sys.argv
    sys.argv = [script] + list(opts.args)
    status, problem = EXIT_OK, ""
    wall0 = _time.perf_counter()
    redirect.install()
    w.wall_start = _time.perf_counter() - w.sim_time  # real time is paced from the script's start
    try:
        exec(code, {"__name__": "__main__", "__file__": script, "__builtins__": builtins})
    except SystemExit as e:
        status = EXIT_OK if e.code in (None, 0) else EXIT_ERROR
        problem = "" if status == EXIT_OK else "SystemExit(%r)" % (e.code,)
    except ModuleNotFoundError as e:
        status, problem = EXIT_MISSING, "module %s (no stand-in, not installed)" % e.name
    except (AttributeError, NotImplementedError) as e:
        traceback.print_exc()
        lab = lab_code_inconsistency(e, os.path.dirname(script))
        if lab:
            status, problem = EXIT_ERROR, lab
        else:
            where = traceback.extract_tb(e.__traceback__)[-1]
            status, problem = EXIT_MISSING, "%s at %s:%d: %s" % (
                type(e).__name__, os.path.basename(where.filename), where.lineno, e)
    except BaseException as e:  # the script's own failure: report it, as python would
        status, problem = EXIT_ERROR, "%s: %s" % (type(e).__name__, e)
        traceback.print_exc()
    finally:
        redirect.uninstall()
        wall = _time.perf_counter() - wall0
        if saved_time:
            _time.time, _time.sleep = saved_time
        builtins.input = saved_input
        sys.argv = saved_argv
        if home is not None:
            os.environ["HOME"] = home
        w.logger.set_enabled(False)
        if w.viewer is not None:
            w.viewer.close()
    mats = sorted(os.path.join(dp, f) for dp, _, fs in os.walk(out) for f in fs
                  if f.endswith(".mat"))
    summary = {"script": script, "status": status, "problem": problem,
               "sim_time_s": round(w.sim_time, 4), "wall_time_s": round(wall, 3),
               "logger_recordings": w.logger.started, "mat_files": mats,
               "hit_time_limit": w.shutdown and w.sim_time >= opts.max_sim - 1e-9,
               "plt_pause": w.pause_summary()}
    print("ssc sil: %s: %s; %.2f s simulated in %.2f s wall%s" % (
        os.path.basename(script), "finished" if status == EXIT_OK else
        ("missing interface: " + problem if status == EXIT_MISSING else "failed: " + problem),
        w.sim_time, wall, " (stopped at --max-sim)" if summary["hit_time_limit"] else ""))
    ps = summary["plt_pause"]
    if ps:
        print("ssc sil: plt.pause: %d calls; the script's CPU per call (median, this machine): "
              "%.1f ms building the plot, %.1f ms drawing it; charged: %s" % (
                  ps["pauses"], 1e3 * ps["build_cpu_s_median"], 1e3 * ps["draw_cpu_s_median"],
                  "that CPU time" if ps["cost"] == world_mod.MEASURED
                  else "the argument + %g s" % ps["cost"]))
    for m in mats:
        print("ssc sil: saved %s" % m)
    if opts.report:
        with open(opts.report, "w") as f:
            json.dump(summary, f, indent=1)
    if w.viewer is not None:
        # The passive viewer's GL thread does not survive the interpreter's teardown (a hang or
        # a crash in about half the runs under Xvfb): everything is written; leave now.
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(status)
    return status


def main(argv=None):
    opts = parse_args(sys.argv[1:] if argv is None else argv)
    return run(opts)
