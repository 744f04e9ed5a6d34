"""MuJoCo's passive viewer on the SIL world: the scene loaded by the mujoco package (the plugin
comes with ssc_twin's entry point) mirrors the plant's joint positions at up to 30 frames per
wall-clock second."""

import time


class Viewer:
    def __init__(self, world):
        import os

        if not (os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")):
            raise RuntimeError("no display (DISPLAY is not set; run under xvfb-run for none)")
        import mujoco
        import mujoco.viewer
        from .. import _core

        self.mujoco = mujoco
        self.model = mujoco.MjModel.from_xml_path(_core.scene_path(world.plant.scene))
        self.data = mujoco.MjData(self.model)
        self.handle = mujoco.viewer.launch_passive(self.model, self.data)
        self.last = 0.0

    def sync(self, world):
        now = time.perf_counter()
        if now - self.last < 1.0 / 30 or not self.handle.is_running():
            return
        self.last = now
        q = world.plant.qpos()
        if len(q) == self.model.nq:
            self.data.qpos[:] = q
        self.data.time = world.plant.time
        self.mujoco.mj_forward(self.model, self.data)
        self.handle.sync()

    def close(self):
        self.handle.close()
        # The viewer's thread releases its window after close returns; the interpreter must not
        # tear down the model under it.
        time.sleep(0.3)
