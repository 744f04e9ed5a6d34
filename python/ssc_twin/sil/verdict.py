"""What a SIL run did to the cup, decided as `ssc trial` decides a disk trial
(trial/trial_outcome.h): from the first touch on, each pressure sample (the mean of the
last few, as the lab's own filter) ends the trial at the first of

- success: the cup centre swept a loop (LOOP_SWEEP_DEG, either way) about the disk's centre;
- failure_II (grasp): every chamber above GRASP_PA;
- failure_I (off the edge): the mean vacuum below OFF_EDGE_PA.

never_touched: the cup never pressed on anything (the F/T force, tared at the first sample as the
lab tares it in air, stayed under TOUCH_N);
timeout: touched, but none of the above by the end. Without a disk in the scene there is no loop
to sweep: a touched run ends as timeout unless a failure decides it.
"""

import math

from .. import _core

OFF_EDGE_PA = float(_core.OFF_EDGE_PA)
GRASP_PA = float(_core.GRASP_PA)
LOOP_SWEEP_DEG = float(_core.LOOP_SWEEP_DEG)
# A touch: a third of the lab's 1.5 N approach preload on the F/T (noise is ~0.05 N).
TOUCH_N = 0.5
FILTER_SAMPLES = 7  # the lab's moving average (PressureHelp)
MIN_SWEEP_RADIUS_M = 0.005

# Outcome names as trials write them, with the words the summary uses.
WORDS = {
    "success": "success",
    "failure_I": "off the edge (failure I)",
    "failure_II": "grasp (failure II)",
    "never_touched": "never touched the object",
    "timeout": "timed out (touched, no outcome)",
}


class Verdict:
    def __init__(self, centre_xy=None):
        self.centre = centre_xy
        self.outcome = None  # decided: the first event after the touch
        self.touched_at_s = None
        self.peak_vacuum_pa = 0.0  # the mean of the four chambers, filtered
        self.peak_force_n = 0.0
        self.swept_deg = 0.0
        self._recent = []
        self._last_angle = None
        self._force_tare_n = None

    def add(self, t_s, vacuum_pa, tool_xy, force_n):
        """One sample: the four chamber vacuums (Pa), the cup centre (m), the F/T force (N)."""
        if self._force_tare_n is None:
            self._force_tare_n = force_n
        force_n -= self._force_tare_n
        self._recent = (self._recent + [list(vacuum_pa)])[-FILTER_SAMPLES:]
        p = [sum(v[k] for v in self._recent) / len(self._recent) for k in range(4)]
        mean = sum(p) / 4
        self.peak_vacuum_pa = max(self.peak_vacuum_pa, mean)
        self.peak_force_n = max(self.peak_force_n, abs(force_n))
        if self.touched_at_s is None:
            if abs(force_n) < TOUCH_N:
                return
            self.touched_at_s = t_s
        self._sweep(tool_xy)
        if self.outcome is not None:
            return
        if self.centre is not None and abs(self.swept_deg) >= LOOP_SWEEP_DEG:
            self.outcome = "success"
        elif all(v > GRASP_PA for v in p):
            self.outcome = "failure_II"
        elif mean < OFF_EDGE_PA:
            self.outcome = "failure_I"

    def _sweep(self, tool_xy):
        if self.centre is None:
            return
        dx, dy = tool_xy[0] - self.centre[0], tool_xy[1] - self.centre[1]
        if math.hypot(dx, dy) < MIN_SWEEP_RADIUS_M:  # over the centre the angle says nothing
            self._last_angle = None
            return
        a = math.atan2(dy, dx)
        if self._last_angle is not None:
            d = (a - self._last_angle + math.pi) % (2 * math.pi) - math.pi
            self.swept_deg += math.degrees(d)
        self._last_angle = a

    def final(self):
        """The outcome at the end of the run."""
        if self.outcome is not None:
            return self.outcome
        return "never_touched" if self.touched_at_s is None else "timeout"

    def summary(self):
        return {
            "outcome": self.final(),
            "touched_at_s": self.touched_at_s,
            "peak_vacuum_pa": round(self.peak_vacuum_pa, 1),
            "peak_force_n": round(self.peak_force_n, 3),
            "swept_deg": round(self.swept_deg, 1),
        }
