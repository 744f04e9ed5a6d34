"""The bounds of a SIL run, so that no script runs for ever: simulated time (--max-sim), wall-clock
time (--max-wall), and a script stuck in a loop that passes no simulated time (a busy loop; input()
or a sleep called over and over after the node shut down).

A bound stops the script by raising RunLimit in its thread. RunLimit is a BaseException, so a
script's `except Exception:` does not swallow it; one that swallows everything is stopped again at
every tick and, after a grace period, the runner writes its summary and leaves. Forked children of
the script end with the run.
"""

import ctypes
import os
import signal
import time

TICK_S = 0.5
_PR_SET_PDEATHSIG = 1


class RunLimit(BaseException):
    """The run hit a bound; str() says which and why."""


class Limits:
    def __init__(self, world, max_wall_s, stuck_wall_s, max_idle_calls, grace_s, give_up):
        self.world = world
        self.max_wall_s = max_wall_s
        self.stuck_wall_s = stuck_wall_s
        self.max_idle_calls = max_idle_calls
        self.grace_s = grace_s
        self.give_up = give_up  # called once the grace is over: writes, then leaves
        self.reason = None  # the bound hit, once hit
        self.waiting_for_operator = False
        self._start = time.monotonic()
        self._stopped_at = None
        self._idle_calls = 0
        self._idle_sim = world.sim_time
        self._last_sim = world.sim_time
        self._last_progress = self._start
        self._saved_handler = None

    def stop(self, reason):
        if self.reason is None:
            self.reason = reason
            self._stopped_at = time.monotonic()
        raise RunLimit(self.reason)

    def idle_call(self, what):
        """A call into the twin that passed no simulated time (input() answered, a sleep after
        shutdown): too many in a row and the script is looping on them."""
        if self.world.sim_time != self._idle_sim:
            self._idle_sim, self._idle_calls = self.world.sim_time, 0
        self._idle_calls += 1
        if self._idle_calls > self.max_idle_calls:
            self.stop(
                "%d calls to %s in a row with no simulated time passing: the script loops "
                "on them" % (self._idle_calls - 1, what)
            )

    def _tick(self, signum, frame):
        now = time.monotonic()
        sim = self.world.sim_time
        if sim != self._last_sim or self.waiting_for_operator:
            self._last_sim, self._last_progress = sim, now
        if self.reason is not None:
            if now - self._stopped_at > self.grace_s:
                self.give_up()
            raise RunLimit(self.reason)
        if now - self._start > self.max_wall_s:
            self.stop("the wall-clock limit (--max-wall %g s)" % self.max_wall_s)
        if now - self._last_progress > self.stuck_wall_s:
            self.stop(
                "no simulated time passed in %g s of wall clock (at %.2f s simulated): the "
                "script is stuck in a loop of its own" % (self.stuck_wall_s, sim)
            )

    def install(self):
        self._saved_handler = signal.signal(signal.SIGALRM, self._tick)
        signal.setitimer(signal.ITIMER_REAL, TICK_S, TICK_S)

    def uninstall(self):
        signal.setitimer(signal.ITIMER_REAL, 0, 0)
        if self._saved_handler is not None:
            signal.signal(signal.SIGALRM, self._saved_handler)


def _die_with_parent():
    """In a forked child: end when the runner ends (PR_SET_PDEATHSIG)."""
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    except (OSError, AttributeError):
        pass


def watch_forks():
    """Every child the script forks from Python ends with the run."""
    os.register_at_fork(after_in_child=_die_with_parent)


def descendants(pid):
    """The pids of every process below pid (read from /proc; empty where there is none)."""
    children = {}
    try:
        entries = os.listdir("/proc")
    except OSError:
        return []
    for entry in entries:
        if not entry.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % entry) as f:
                stat = f.read()
        except OSError:
            continue
        ppid = int(stat[stat.rfind(")") + 2 :].split()[1])
        children.setdefault(ppid, []).append(int(entry))
    found, todo = [], [pid]
    while todo:
        for child in children.get(todo.pop(), []):
            found.append(child)
            todo.append(child)
    return found


def end_children(pid, grace_s=1.0):
    """Ends every process the run started (subprocesses, forks, their children): SIGTERM, then
    SIGKILL for those still there after grace_s. Returns how many there were."""
    pids = descendants(pid)
    for p in pids:
        try:
            os.kill(p, signal.SIGTERM)
        except OSError:
            pass
    deadline = time.monotonic() + grace_s
    while time.monotonic() < deadline and any(_alive(p) for p in pids):
        time.sleep(0.02)
    for p in pids:
        if _alive(p):
            try:
                os.kill(p, signal.SIGKILL)
            except OSError:
                pass
    for p in pids:  # reap our own children
        try:
            os.waitpid(p, os.WNOHANG)
        except OSError:
            pass
    return len(pids)


def _alive(pid):
    try:
        with open("/proc/%d/stat" % pid) as f:
            state = f.read().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"
