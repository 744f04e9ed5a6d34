"""Gymnasium environment: follow an object's edge with the Smart Suction Cup twin.

One step is one control iteration of the published controller (0.15 s): the cup, held at the
start-up compression, reads its four chamber pressures, the agent chooses a planar step, and the
arm moves by it. An episode starts where the published trials start (approach to the start-up
force, move inside the edge) and ends like a trial: success (the edge followed round, or to its
end), failure mode I (off the edge: every chamber at ambient), failure mode II (onto the object:
the cup grasps) or the trial's timeout. Episodes run on the 35 mm-radius disk of the benchmark or
on the test objects (disk_dNN, hole_dNN, corner_aNNN, volute, strips, fillet).

    import gymnasium as gym, ssc_twin
    env = gym.make("ssc_twin/EdgeFollowing-v0")                  # the disk benchmark
    env = gym.make("ssc_twin/EdgeFollowing-v0", objects=["volute", "corner_a090"])
"""
import math

import gymnasium as gym
import numpy as np
from gymnasium import spaces

from . import _core

ENV_ID = "ssc_twin/EdgeFollowing-v0"
# Filtered gauge vacuum per chamber: about -noise (in air) up to ambient (a full grasp), Pa.
PRESSURE_LOW_PA, PRESSURE_HIGH_PA = -1.0e4, 1.2e5
FT_LIMIT = 1.0e3  # N and N m; the start-up compression is 1.5 N
# Outcomes that end an episode with the failure penalty: off the edge (I), onto the object
# (II), or out of the band of following about the edge (lost_edge).
FAILURES = ("failure_I", "failure_II", "lost_edge")


class EdgeFollowingEnv(gym.Env):
    """Observation: the four filtered chamber pressures (Pa; P1 SE, P2 NE, P3 NW, P4 SW in the
    tool frame), then with ``include_ft`` the F/T force (N) and torque (N m).
    Action: a planar step in the tool frame, in [-1, 1]^2 times ``max_step_mm``.
    Reward: progress along the edge in units of ``max_step_mm`` per step (negative when going
    backwards), ``terminal_reward`` on success, ``-failure_penalty`` on failure mode I or II or a
    lost edge.
    """

    metadata = {"render_modes": []}

    def __init__(self, objects=None, include_ft=False, max_step_mm=10.0, pref=100.0, beta=2.0,
                 failure_penalty=10.0, terminal_reward=10.0, timeout_s=None, effects="default"):
        super().__init__()
        # None: the disk benchmark scene; else test objects by name, one drawn per episode.
        self.objects = [None] if not objects else list(objects)
        for name in self.objects:
            if name is not None and name not in _core.object_names() and not _parametric(name):
                raise ValueError(f"unknown test object {name!r}; ssc_twin.object_names() lists them")
        self.include_ft = bool(include_ft)
        if not 0 < max_step_mm <= 50:
            raise ValueError(f"max_step_mm must be in (0, 50] mm, got {max_step_mm}")
        self.max_step_mm = float(max_step_mm)
        self.pref, self.beta = float(pref), float(beta)
        self.failure_penalty, self.terminal_reward = float(failure_penalty), float(terminal_reward)
        self.timeout_s = float(timeout_s) if timeout_s else 0.0
        # The robot effects (docs/fidelity.md): "default" (the fitted set: each step lands off
        # target), "off" (the ideal loop) or "key=value,...".
        self.effects = str(effects)
        n = 10 if self.include_ft else 4
        low = np.full(n, PRESSURE_LOW_PA, dtype=np.float32)
        high = np.full(n, PRESSURE_HIGH_PA, dtype=np.float32)
        if self.include_ft:
            low[4:], high[4:] = -FT_LIMIT, FT_LIMIT
        self.observation_space = spaces.Box(low, high, dtype=np.float32)
        self.action_space = spaces.Box(-1.0, 1.0, shape=(2,), dtype=np.float32)
        self._trials = {}  # one loaded model per object, reused across episodes
        self._trial = None
        self._object = None
        self._progress_mm = 0.0

    # -- helpers ---------------------------------------------------------------------------
    def _trial_for(self, name):
        if name not in self._trials:
            t = _core.SteppedTrial(scene="disk_benchmark_gantry", pref=self.pref, beta=self.beta,
                                   step_mm=7.5, seed=1, object=name or "", timeout_s=self.timeout_s,
                                   effects=self.effects)
            t.set_external_policy(True)
            self._trials[name] = t
        return self._trials[name]

    def _observation(self):
        p = np.asarray(self._trial.iteration_pressures(), dtype=np.float64)
        if self.include_ft:
            p = np.concatenate([p, np.asarray(self._trial.force_torque())])
        return np.clip(p, self.observation_space.low, self.observation_space.high).astype(np.float32)

    def _progress(self):
        """Distance travelled along the edge in the followed sense, mm."""
        target = self._trial.target()
        if target["goal"] == "goal_point":  # open contours: the tracked arc position
            return self._trial.tracked_arc_m * 1e3
        sense = 1.0 if target["sweep_deg"] >= 0 else -1.0
        radius_m = target["disk_radius_m"]
        if radius_m <= 0:  # no circle: the cup's distance from the sweep centre
            x, y, _ = self._trial.tool_position()
            cx, cy = target["centre"]
            radius_m = math.hypot(x - cx, y - cy)
        return sense * math.radians(self._trial.swept_deg) * radius_m * 1e3

    def _info(self):
        x, y, _ = self._trial.tool_position()
        return {"object": self._object or "disk_benchmark", "phase": self._trial.phase,
                "time_s": self._trial.time, "progress_mm": self._progress_mm,
                "tool_xy_m": (x, y), "contour_distance_mm": 1e3 * self._trial.contour_distance_m(x, y),
                "outcome": self._trial.result()["outcome"]}

    # -- Gymnasium API ---------------------------------------------------------------------
    def reset(self, *, seed=None, options=None):
        super().reset(seed=seed)
        options = options or {}
        if "object" in options:
            name = options["object"]
        else:
            name = self.objects[int(self.np_random.integers(len(self.objects)))]
        self._object = name
        self._trial = self._trial_for(name)
        self._trial.reset(int(self.np_random.integers(2**31 - 1)))
        # Approach and move to the start; stop when the first following iteration has read the
        # sensor (its step is the agent's first action).
        self._trial.run_to_next_iteration()
        self._progress_mm = self._progress()
        return self._observation(), self._info()

    def step(self, action):
        if self._trial is None:
            raise RuntimeError("call reset() before step()")
        a = np.clip(np.asarray(action, dtype=np.float64).reshape(2), -1.0, 1.0)
        self._trial.apply_step((a * self.max_step_mm * 1e-3).tolist())
        self._trial.run_to_next_iteration()
        progress = self._progress()
        reward = (progress - self._progress_mm) / self.max_step_mm
        self._progress_mm = progress
        outcome = self._trial.result()["outcome"]
        terminated = outcome == "success" or outcome in FAILURES or outcome == "unstable"
        truncated = outcome == "timeout"
        if outcome == "success":
            reward += self.terminal_reward
        elif outcome in FAILURES:
            reward -= self.failure_penalty
        return self._observation(), float(reward), terminated, truncated, self._info()


def _parametric(name):
    return any(name.startswith(p) for p in ("disk_d", "hole_d", "corner_a"))


class PublishedLawPolicy:
    """The published contour law as a policy on the environment's observation (the baseline)."""

    def __init__(self, env, pref=100.0, beta=2.0, step_mm=7.5):
        self.max_step_mm = env.unwrapped.max_step_mm
        if step_mm > self.max_step_mm:
            raise ValueError("step_mm larger than the environment's max_step_mm")
        self.pref, self.beta, self.step_mm = pref, beta, step_mm

    def __call__(self, observation):
        step = _core.contour_step(observation[:4].astype(float).tolist(), self.pref, self.beta,
                                  self.step_mm)["step_m"]
        return (np.asarray(step) * 1e3 / self.max_step_mm).astype(np.float32)


def register_envs():
    if ENV_ID not in gym.registry:
        gym.register(id=ENV_ID, entry_point="ssc_twin.edge_following:EdgeFollowingEnv",
                     max_episode_steps=400)
