"""A bundled scene loaded through the mujoco Python API, as docs/python.md and docs/viewer.md
say: from the `home` keyframe the cup hangs over the disk with the servos on it; at qpos0 the
gantry scenes have it under the table, which is why the docs say to reset to `home`."""

import glob
import os
import sys
import unittest

SRC = os.environ.get("SSC_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
PLUGIN = os.environ.get("SSC_PLUGIN_LIB")
DISK_TOP_M = 0.010  # the 10 mm disk on the table (scenes/disk_benchmark*.xml)


class RawSceneTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        try:
            import mujoco
        except ImportError:
            raise unittest.SkipTest("the mujoco package is not installed")
        cls.mujoco = mujoco
        if PLUGIN:
            try:
                mujoco.mj_loadPluginLibrary(PLUGIN)
            except Exception:  # registered already (the package's entry point)
                pass

    def scenes(self):
        found = sorted(
            glob.glob(os.path.join(os.path.abspath(SRC), "scenes", "disk_benchmark*.xml"))
        )
        self.assertTrue(found)
        return found

    def test_home_puts_the_cup_over_the_disk_in_every_trial_scene(self):
        mj = self.mujoco
        for path in self.scenes():
            with self.subTest(scene=os.path.basename(path)):
                m = mj.MjModel.from_xml_path(path)
                d = mj.MjData(m)
                mj.mj_resetDataKeyframe(m, d, m.key("home").id)  # as the docs write it
                mj.mj_forward(m, d)
                z = d.site("ssc_tool_site").xpos[2]
                self.assertGreater(z, DISK_TOP_M, "the cup at home is not above the disk")
                self.assertLess(z, DISK_TOP_M + 0.05)
                for _ in range(250):  # 0.5 s or more: the servos hold it there
                    mj.mj_step(m, d)
                self.assertGreater(d.site("ssc_tool_site").xpos[2], DISK_TOP_M)

    def test_qpos0_puts_the_gantry_cup_under_the_table(self):
        mj = self.mujoco
        gantries = 0
        for path in self.scenes():
            m = mj.MjModel.from_xml_path(path)
            if mj.mj_name2id(m, mj.mjtObj.mjOBJ_JOINT, "gantry_x") < 0:
                continue  # the arm: its qpos0 holds the arm up
            gantries += 1
            with self.subTest(scene=os.path.basename(path)):
                d = mj.MjData(m)
                mj.mj_forward(m, d)
                self.assertLess(d.site("ssc_tool_site").xpos[2], 0.0)
        self.assertGreater(gantries, 0)


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    skipped = result.skipped and not result.failures and not result.errors
    sys.exit(77 if skipped else (0 if result.wasSuccessful() else 1))
