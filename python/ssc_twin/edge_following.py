"""Gymnasium environment: follow an object's edge with the Smart Suction Cup twin.

One step is one control iteration of the published controller (0.15 s): the cup, held at the
start-up compression, reads its four chamber pressures, the agent chooses a planar step, and the
arm moves by it. An episode starts where the published trials start (approach to the start-up
force, move inside the edge) and ends like a trial: success (the edge followed round, or to its
end), failure mode I (off the edge: every chamber at ambient), failure mode II (onto the object:
the cup grasps) or the trial's timeout. Episodes run on the 35 mm-radius disk of the benchmark or
on the test objects (disk_dNN, hole_dNN, corner_aNNN, volute, strips, fillet).

    import gymnasium as gym, ssc_twin
    env = gym.make("ssc_twin/EdgeFollowing-v0")                  # the disk benchmark (gantry)
    env = gym.make("ssc_twin/EdgeFollowing-v0", objects=["volute", "corner_a090"])
    env = gym.make("ssc_twin/EdgeFollowing-v0", scene="disk_benchmark", effects="off",
                   render_mode="rgb_array")                      # the UR-10 arm, the ideal loop
    env.unwrapped.model, env.unwrapped.data                      # mujoco.MjModel / MjData
    env = gym.make("ssc_twin/EdgeFollowing-v0", controller="fast")  # a residual on a controller
"""

import math
import os
import time

import gymnasium as gym
import numpy as np
from gymnasium import spaces

from . import _core, _gl

_LAW = _core.law_defaults()  # the C++ law's defaults (ContourLawParams{}), one home

ENV_ID = "ssc_twin/EdgeFollowing-v0"
# Filtered gauge vacuum per chamber: about -noise (in air) up to ambient (a full grasp), Pa.
PRESSURE_LOW_PA, PRESSURE_HIGH_PA = -1.0e4, 1.2e5
FT_LIMIT = 1.0e3  # N and N m; the start-up compression is 1.5 N
# Outcomes that end an episode with the failure penalty: off the edge (I), onto the object
# (II), or out of the band of following about the edge (lost_edge).
FAILURES = ("failure_I", "failure_II", "lost_edge")
CONTROL_PERIOD_S = _core.default_control_period_s  # one step: one control iteration
DEFAULT_SCENE = _core.default_scene()
# The rig's scenes a contour-following trial runs in (the others replay a log or hold a probe).
TRIAL_SCENES = tuple(
    t["scene"] for t in _core.scene_tiers() if t["kind"] in ("arm", "gantry", "flex")
)
CUP_VIEW_DISTANCE_M = 0.15  # the "cup" camera: the cup and the edge under it fill the frame
LIP_GEOM_GROUP = 4  # models/ssc_tool.xml: the lip segments


class EdgeFollowingEnv(gym.Env):
    """Observation: the four filtered chamber pressures (Pa; P1 SE, P2 NE, P3 NW, P4 SW in the
    tool frame), then with ``include_ft`` the F/T force (N) and torque (N m).
    Action: a planar step in the tool frame, in [-1, 1]^2 times ``max_step_mm``. With
    ``controller`` (a registered name, with ``controller_params`` as ``--controller-param``, or a
    Python callable or class, docs/controllers.md) the controller runs in the loop and the action
    is added to its command: a zero action runs the controller as it is
    (``info["controller_step_m"]`` holds its step).
    Reward: progress along the edge in units of ``max_step_mm`` per step (negative when going
    backwards), ``terminal_reward`` on success, ``-failure_penalty`` on failure mode I or II or a
    lost edge.
    """

    # render_fps: one step is one control iteration (CONTROL_PERIOD_S of simulated time), so a
    # video at this rate plays in real time.
    # Without a display there is no window to draw in: "human" is not offered there (so
    # gymnasium's check_env, which renders every mode it is offered, passes headless).
    metadata = {
        "render_modes": ["rgb_array"] + ([] if _gl.no_display() else ["human"]),
        "render_fps": 1.0 / CONTROL_PERIOD_S,
    }

    def __init__(
        self,
        objects=None,
        include_ft=False,
        max_step_mm=10.0,
        pref=_LAW["pref"],
        beta=_LAW["beta"],
        failure_penalty=10.0,
        terminal_reward=10.0,
        timeout_s=None,
        effects="default",
        scene=DEFAULT_SCENE,
        render_mode=None,
        width=640,
        height=480,
        camera="cup",
        controller=None,
        controller_params="",
        reset_cache=True,
    ):
        super().__init__()
        # The scene: one of TRIAL_SCENES (the rig's tiers, ssc_twin.scene_tiers()) or an MJCF
        # path. With test objects, the tier's kind (arm, gantry, flex) picks their scenes.
        self.scene = str(scene)
        if not os.path.exists(_core.scene_path(self.scene)):
            raise ValueError(
                f"scene {self.scene!r} not found: a name among {list_scenes()} or an MJCF file"
            )
        if render_mode == "human" and _gl.no_display():
            raise ValueError(
                "render_mode='human' needs a display (none here: DISPLAY and "
                "WAYLAND_DISPLAY are unset); use render_mode='rgb_array', or run "
                "under xvfb-run"
            )
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(
                f"render_mode must be one of {self.metadata['render_modes']} or "
                f"None, got {render_mode!r}"
            )
        self.render_mode = render_mode
        if not (16 <= int(width) <= 4096 and 16 <= int(height) <= 4096):
            raise ValueError(f"width and height must be in [16, 4096] pixels, got {width}x{height}")
        self.width, self.height = int(width), int(height)
        # "cup": a close-up that follows the cup; "free": MuJoCo's default view of the whole
        # scene; else a camera the model names.
        self.camera = str(camera)
        self._renderer = None  # mujoco.Renderer for rgb_array, per model
        self._viewer = None  # mujoco.viewer handle for human
        self._last_frame_wall_s = None
        # None: the disk benchmark scene; else test objects by name, one drawn per episode: a
        # list, or one string of comma-separated names as ``ssc objects --objects`` takes them.
        if isinstance(objects, str):
            objects = objects.split(",")
        self.objects = [None] if not objects else list(objects)
        for name in self.objects:
            if name is not None and name not in _core.object_names() and not _parametric(name):
                raise ValueError(
                    f"unknown test object {name!r}; ssc_twin.object_names() lists them"
                )
        self.include_ft = bool(include_ft)
        if not 0 < max_step_mm <= 50:
            raise ValueError(f"max_step_mm must be in (0, 50] mm, got {max_step_mm}")
        self.max_step_mm = float(max_step_mm)
        self.pref, self.beta = float(pref), float(beta)
        self.failure_penalty, self.terminal_reward = float(failure_penalty), float(terminal_reward)
        if not (math.isfinite(self.failure_penalty) and math.isfinite(self.terminal_reward)):
            raise ValueError(
                "failure_penalty and terminal_reward must be finite, got "
                f"{failure_penalty} and {terminal_reward}"
            )
        self.timeout_s = float(timeout_s) if timeout_s else 0.0
        # The robot effects (docs/fidelity.md): "default" (the fitted set: each step lands off
        # target), "off" (the ideal loop) or "key=value,...".
        self.effects = str(effects)
        if controller is None and controller_params:
            raise ValueError("controller_params apply to a registered controller; none given")
        self.controller, self.controller_params = controller, str(controller_params)
        # reset() starts from the kept end of the approach (the same episode as from scratch,
        # at once): SteppedTrial.reset. False: every reset simulates the approach.
        self.reset_cache = bool(reset_cache)
        if controller is not None:  # refused here, not at the first reset()
            _core.check_controller(controller, self.controller_params)
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
        # The first object's trial now, not at the first reset(): the law, the effects, the
        # timeout and the scene are refused here, with the C++ checks the command line runs.
        first = self._trial_for(self.objects[0])
        if render_mode is not None and self.camera not in ("cup", "free"):
            import mujoco

            model = first.model
            if mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_CAMERA, self.camera) < 0:
                names = [model.camera(k).name for k in range(model.ncam)]
                raise ValueError(
                    f"camera {self.camera!r}: use 'cup', 'free' or a camera of the model {names}"
                )

    # -- helpers ---------------------------------------------------------------------------
    def _trial_for(self, name):
        if name not in self._trials:
            t = _core.SteppedTrial(
                scene=self.scene,
                pref=self.pref,
                beta=self.beta,
                step_mm=_LAW["step_mm"],
                seed=1,
                object=name or "",
                timeout_s=self.timeout_s,
                effects=self.effects,
                controller=self.controller,
                controller_params=self.controller_params,
            )
            t.set_external_policy(True, controller_in_loop=self.controller is not None)
            t.set_reset_cache(self.reset_cache)
            self._trials[name] = t
        return self._trials[name]

    def _observation(self):
        p = np.asarray(self._trial.iteration_pressures(), dtype=np.float64)
        if self.include_ft:
            p = np.concatenate([p, np.asarray(self._trial.force_torque())])
        return np.clip(p, self.observation_space.low, self.observation_space.high).astype(
            np.float32
        )

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
        result = self._trial.result()
        return {
            "object": self._object or "disk_benchmark",
            "scene": self._trial.scene,
            "phase": self._trial.phase,
            "time_s": self._trial.time,
            "progress_mm": self._progress_mm,
            "tool_xy_m": (x, y),
            "contour_distance_mm": 1e3 * self._trial.contour_distance_m(x, y),
            "outcome": result["outcome"],
            # Why the episode ended (a controller's fault, the failing value), as run_trial
            # gives it; "" while it runs.
            "detail": result.get("detail", ""),
            "controller_step_m": (
                tuple(self._trial.controller_step()) if self.controller is not None else (0.0, 0.0)
            ),
        }

    # -- Gymnasium API ---------------------------------------------------------------------
    def reset(self, *, seed=None, options=None):
        # The package's one range for seeds (ssc --seed's), whatever gymnasium would take.
        super().reset(seed=None if seed is None else _core.check_seed(seed))
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
        if self.render_mode == "human":
            self.render()
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
        terminated = outcome in ("success", "unstable", "controller_fault") or outcome in FAILURES
        truncated = outcome == "timeout"
        if outcome == "success":
            reward += self.terminal_reward
        elif outcome in FAILURES:
            reward -= self.failure_penalty
        if self.render_mode == "human":
            self.render()
        return self._observation(), float(reward), terminated, truncated, self._info()

    # -- MuJoCo ----------------------------------------------------------------------------
    @property
    def model(self):
        """The current episode's mujoco.MjModel (one per object; None before reset())."""
        return self._trial.model if self._trial is not None else None

    @property
    def data(self):
        """The current episode's mujoco.MjData, as the trial steps it (None before reset())."""
        return self._trial.data if self._trial is not None else None

    def _camera(self):
        import mujoco

        cam = mujoco.MjvCamera()
        model, data = self.model, self.data
        if self.camera == "cup":
            mujoco.mjv_defaultFreeCamera(model, cam)
            cam.lookat[:] = data.site_xpos[self._trial.tool_site]
            cam.distance, cam.azimuth, cam.elevation = CUP_VIEW_DISTANCE_M, 135.0, -35.0
        elif self.camera == "free":
            mujoco.mjv_defaultFreeCamera(model, cam)
        else:
            cam_id = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_CAMERA, self.camera)
            if cam_id < 0:
                names = [model.camera(k).name for k in range(model.ncam)]
                raise ValueError(
                    f"camera {self.camera!r}: use 'cup', 'free' or a camera of the model {names}"
                )
            cam.type, cam.fixedcamid = mujoco.mjtCamera.mjCAMERA_FIXED, cam_id
        return cam

    def _scene_option(self):
        import mujoco

        option = mujoco.MjvOption()
        option.geomgroup[LIP_GEOM_GROUP] = 1  # the lip segments (the plugin colours them)
        return option

    def render(self):
        """rgb_array: an (height, width, 3) uint8 frame of the current state; human: a MuJoCo
        viewer window kept in step (about real time: one step per control period)."""
        if self.render_mode is None:
            gym.logger.warn(
                "render() called without a render_mode; gymnasium.make(..., "
                "render_mode='rgb_array' or 'human')"
            )
            return None
        if self._trial is None:
            raise RuntimeError("call reset() before render()")
        if self.render_mode == "rgb_array":
            return self._render_rgb()
        self._render_human()
        return None

    def _render_rgb(self):

        if self._renderer is None or self._renderer.model is not self.model:
            if self._renderer is not None:
                self._renderer.close()
            self._renderer = _Renderer(self.model, self.height, self.width)
        self._renderer.update_scene(
            self.data, camera=self._camera(), scene_option=self._scene_option()
        )
        return self._renderer.render()

    def _render_human(self):
        if self._viewer is not None and self._viewer.model is not self.model:
            self._viewer.close()  # another object's model: a new window for it
            self._viewer = None
        if self._viewer is None:
            self._viewer = _Window(self.model, self.width, self.height)
        if not self._viewer.closed:
            self._viewer.show(self.data, self._camera(), self._scene_option(), self._status())
        # About real time: a step stands for one control period of simulated time.
        now = time.perf_counter()
        if self._last_frame_wall_s is not None:
            wait = CONTROL_PERIOD_S - (now - self._last_frame_wall_s)
            if wait > 0:
                time.sleep(wait)
        self._last_frame_wall_s = time.perf_counter()

    def _status(self):
        p = self._trial.iteration_pressures()
        return (
            "object\ntime\nphase\nP1..P4\nprogress",
            f"{self._object or 'disk_benchmark'}\n{self._trial.time:.2f} s\n"
            f"{self._trial.phase}\n"
            + " ".join(f"{x:.0f}" for x in p)
            + f" Pa\n{self._progress_mm:.0f} mm",
        )

    def close(self):
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None
        if self._viewer is not None:
            self._viewer.close()
            self._viewer = None
        super().close()


class _Renderer:
    """mujoco.Renderer that remembers its model (one per test object's model)."""

    def __init__(self, model, height, width):
        import mujoco

        self.model = model
        try:
            self._renderer = mujoco.Renderer(model, height, width)
        except Exception as e:  # no GL at all: say what would make one
            raise RuntimeError(
                f"render_mode='rgb_array' cannot make an OpenGL context "
                f"({type(e).__name__}: {e}); {_gl.render_fix()}"
            ) from e

    def update_scene(self, data, camera, scene_option):
        self._renderer.update_scene(data, camera=camera, scene_option=scene_option)

    def render(self):
        return self._renderer.render()

    def close(self):
        self._renderer.close()


class _Window:
    """A GLFW window showing the scene (render_mode "human"); closing it stops the drawing, not
    the episode."""

    def __init__(self, model, width, height):
        import glfw
        import mujoco

        if not glfw.init():
            raise RuntimeError(
                "render_mode='human' needs a display (GLFW could not start); "
                "use render_mode='rgb_array' without one"
            )
        self.model = model
        self._glfw = glfw
        self._window = glfw.create_window(width, height, "ssc_twin EdgeFollowing", None, None)
        if not self._window:
            raise RuntimeError("render_mode='human': GLFW could not open a window")
        glfw.make_context_current(self._window)
        glfw.swap_interval(0)
        self._scene = mujoco.MjvScene(model, maxgeom=10000)
        self._context = mujoco.MjrContext(model, mujoco.mjtFontScale.mjFONTSCALE_100)
        self.closed = False

    def show(self, data, camera, option, status):
        import mujoco

        glfw = self._glfw
        if glfw.window_should_close(self._window):
            self.close()
            return
        glfw.make_context_current(self._window)
        mujoco.mjv_updateScene(
            self.model, data, option, None, camera, mujoco.mjtCatBit.mjCAT_ALL, self._scene
        )
        viewport = mujoco.MjrRect(0, 0, *glfw.get_framebuffer_size(self._window))
        mujoco.mjr_render(viewport, self._scene, self._context)
        mujoco.mjr_overlay(
            mujoco.mjtFont.mjFONT_NORMAL,
            mujoco.mjtGridPos.mjGRID_TOPLEFT,
            viewport,
            status[0],
            status[1],
            self._context,
        )
        glfw.swap_buffers(self._window)
        glfw.poll_events()

    def close(self):
        if self.closed:
            return
        self.closed = True
        self._glfw.make_context_current(self._window)
        self._context.free()
        self._glfw.destroy_window(self._window)


def list_scenes():
    """The scene names under the package's scenes/ folder that a trial can run."""
    folder = os.path.join(_core.resource_dir(), "scenes")
    return sorted(
        f[:-4] for f in os.listdir(folder) if f.endswith(".xml") and f[:-4] in TRIAL_SCENES
    )


def _parametric(name):
    return any(name.startswith(p) for p in ("disk_d", "hole_d", "corner_a"))


class PublishedLawPolicy:
    """The published contour law as a policy on the environment's observation (the baseline)."""

    def __init__(self, env, pref=_LAW["pref"], beta=_LAW["beta"], step_mm=_LAW["step_mm"]):
        self.max_step_mm = env.unwrapped.max_step_mm
        if step_mm > self.max_step_mm:
            raise ValueError("step_mm larger than the environment's max_step_mm")
        self.pref, self.beta, self.step_mm = pref, beta, step_mm

    def __call__(self, observation):
        step = _core.contour_step(
            observation[:4].astype(float).tolist(), self.pref, self.beta, self.step_mm
        )["step_m"]
        return (np.asarray(step) * 1e3 / self.max_step_mm).astype(np.float32)


def register_envs():
    if ENV_ID not in gym.registry:
        gym.register(
            id=ENV_ID, entry_point="ssc_twin.edge_following:EdgeFollowingEnv", max_episode_steps=400
        )
