"""Interop: the plugin library loads in the mujoco Python bindings and the scenes step there."""

import os
import sys
import unittest

import mujoco

ROOT = os.environ.get("SSC_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
PLUGIN = os.environ["SSC_PLUGIN_LIB"]


class PythonBindingsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        mujoco.mj_loadPluginLibrary(PLUGIN)

    def pressures(self, scene, steps, place=None):
        m = mujoco.MjModel.from_xml_path(os.path.join(ROOT, "scenes", scene))
        d = mujoco.MjData(m)
        if m.nkey:
            mujoco.mj_resetDataKeyframe(m, d, 0)
        if place:
            place(m, d)
        mujoco.mj_step(m, d, steps)
        sid = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_SENSOR, "ssc_chamber_pressure")
        self.assertGreaterEqual(sid, 0)
        adr, dim = m.sensor_adr[sid], m.sensor_dim[sid]
        self.assertEqual(dim, 4)
        return d.sensordata[adr : adr + 4].copy()

    def test_probe_scene_on_plate_grasps(self):
        def on_plate(m, d):
            d.mocap_pos[0] = [-0.03, 0.0, 0.010 - 0.001 + 0.146]

        p = self.pressures("probe_edge.xml", 200, on_plate)
        # The sealed cup's reading (tests/plugin/pneumatics/flow_network_test.cc,
        # SealedCupOnAPlate: the chamber
        # vacuum of four roughness leaks, 25644 Pa; that air enters as a sheet, so no tap recovery)
        # within the noise band of the filtered value (5 sigma of a 7-sample mean of 6 Pa: 11.3 Pa).
        self.assertTrue(all(abs(p - 25644) < 11.3), p)

    def test_probe_scene_in_air_reads_near_zero(self):
        def in_air(m, d):
            d.mocap_pos[0] = [0.0, 0.0, 0.4]

        p = self.pressures("probe_edge.xml", 200, in_air)
        # The open cup reads 0.253 Pa; the mean of four filtered chambers has 5 sigma = 5.7 Pa.
        self.assertLess(abs(p.mean() - 0.253), 5.7, p)

    def test_disk_benchmark_scene_compiles_and_steps(self):
        p = self.pressures("disk_benchmark.xml", 100)
        self.assertTrue(all(abs(x) < 1e6 for x in p), p)

    def test_loading_our_scene_writes_no_log_file(self):
        # MuJoCo's default handlers append to MUJOCO_LOG.TXT in the working directory; the plugin
        # installs printing ones where the host has none; our scenes load without a warning.
        import subprocess
        import tempfile

        scene = os.path.abspath(os.path.join(ROOT, "scenes", "disk_benchmark.xml"))
        script = (
            "import mujoco; mujoco.mj_loadPluginLibrary(%r); "
            "m = mujoco.MjModel.from_xml_path(%r); print('nbody', m.nbody)" % (PLUGIN, scene)
        )
        with tempfile.TemporaryDirectory() as cwd:
            r = subprocess.run(
                [sys.executable, "-c", script], cwd=cwd, capture_output=True, text=True, timeout=120
            )
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("nbody", r.stdout)
            self.assertEqual(os.listdir(cwd), [])
            self.assertNotIn("Attaching a spec", r.stdout + r.stderr)

    def test_scenes_attach_the_tool_with_a_prefix_and_save(self):
        # An empty attach prefix makes MuJoCo warn (a UserWarning from MjSpec) that the model may
        # not save correctly. Every scene parses without a warning, the tool's parts carry the
        # prefix, and the spec saved to MJCF compiles to the same model.
        import glob
        import warnings

        scenes = sorted(glob.glob(os.path.join(ROOT, "scenes", "*.xml")))
        self.assertGreaterEqual(len(scenes), 5)
        for path in scenes:
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                spec = mujoco.MjSpec.from_file(os.path.abspath(path))
                m = spec.compile()
            self.assertEqual([str(w.message) for w in caught], [], path)
            for kind, name in (
                (mujoco.mjtObj.mjOBJ_SITE, "ssc_tool_site"),
                (mujoco.mjtObj.mjOBJ_SENSOR, "ssc_ft_force"),
                (mujoco.mjtObj.mjOBJ_SENSOR, "ssc_chamber_pressure"),
            ):
                self.assertGreaterEqual(mujoco.mj_name2id(m, kind, name), 0, (path, name))
            # The lip: the segment tier's first slide, or the flex tier's skirt.
            lip = max(
                mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, "ssc_lip_0"),
                mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_FLEX, "ssc_skirt"),
            )
            self.assertGreaterEqual(lip, 0, (path, "ssc_lip_0 or ssc_skirt"))
            again = mujoco.MjModel.from_xml_string(spec.to_xml())
            self.assertEqual(
                (again.nbody, again.njnt, again.nsensor, again.nplugin),
                (m.nbody, m.njnt, m.nsensor, m.nplugin),
                path,
            )

    def test_bad_config_raises_with_the_key(self):
        with open(os.path.join(ROOT, "models", "ssc_tool.xml")) as f:
            xml = f.read()
        xml = xml.replace(
            '<instance name="pressure"/>',
            '<instance name="pressure"><config key="noise_pa" value="-2"/></instance>',
        )
        with self.assertRaises(Exception) as ctx:
            mujoco.MjModel.from_xml_string(xml)
        self.assertIn("noise_pa", str(ctx.exception))


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    # Exit 77 when anything was skipped: CTest reports it as skipped (SKIP_RETURN_CODE), never
    # as passed.
    sys.exit(1 if not result.wasSuccessful() else 77 if result.skipped else 0)
