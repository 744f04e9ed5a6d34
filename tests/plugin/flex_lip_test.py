"""The flex skirt lip (models/ssc_tool_flex.xml): MuJoCo's shell against plate theory, and the
pressure plugin reading the deformed skirt under its chambers' vacuum: a seal on a plate that the
chamber walls hold, a notch the vacuum pulls the rim into, a leak into a groove, the same run
twice. The cup hangs from a stiff x/y/z position servo (a flex cannot hang from a mocap body)."""
import importlib.util
import os
import tempfile
import unittest

import mujoco
import numpy as np

ROOT = os.environ.get("SSC_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
PLUGIN = os.environ["SSC_PLUGIN_LIB"]
TOOL_Z_M = 0.146  # flange to lip plane (geometry/dimensions.h)
SEALED_PA = 25644.0  # a sealed cup on a plate (tests/plugin/pneumatics/flow_network_test.cc)


def make_flex_tool():
    spec = importlib.util.spec_from_file_location(
        "make_flex_tool", os.path.join(ROOT, "tools", "make_flex_tool.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def skirt_parameters():
    return {k: v[0] for k, v in make_flex_tool().SKIRT.items()}


VARIANTS = tempfile.TemporaryDirectory()


def tool_variant(walls=True, vacuum_load=True):
    """Path of the flex tool built without its chamber walls or its vacuum load."""
    path = os.path.join(VARIANTS.name, "flex_w%d_v%d.xml" % (walls, vacuum_load))
    if not os.path.exists(path):
        with open(path, "w") as f:
            f.write(make_flex_tool().tool_xml(walls=walls, vacuum_load=vacuum_load))
    return path


def box(size, pos):
    return ('<geom type="box" size="%g %g %g" pos="%g %g %g" group="2" contype="1" '
            'conaffinity="1"/>' % (tuple(size) + tuple(pos)))


PLATE = box((0.05, 0.05, 0.005), (0, 0, -0.005))


def notch(width_m, depth_m, inner_end_m=0.004):
    """A plate (top z = 0) with a slot along +x from x = inner_end_m outward: under the rim at
    +x, but not across the opening."""
    size = 0.05
    side = (size - width_m / 2) / 2
    return (box((size, size, 0.005 - depth_m / 2), (0, 0, -0.005 - depth_m / 2)) +
            box((size, side, depth_m / 2), (0, -(width_m / 2 + side), -depth_m / 2)) +
            box((size, side, depth_m / 2), (0, width_m / 2 + side, -depth_m / 2)) +
            box(((inner_end_m + size) / 2, width_m / 2, depth_m / 2),
                ((inner_end_m - size) / 2, 0, -depth_m / 2)))


def concave_corner():
    """A plate (top z = 0) with a 270-degree corner at the origin: the quadrant x > 0, y > 0 is a
    10 mm drop."""
    return box((0.05, 0.025, 0.005), (0, -0.025, -0.005)) + box((0.025, 0.025, 0.005),
                                                                  (-0.025, 0.025, -0.005))


def groove(width_m, depth_m):
    """A plate (top z = 0) with a groove along y through x = 0."""
    half = 0.025 - width_m / 4
    return (box((0.05, 0.05, 0.005 - depth_m / 2), (0, 0, -0.005 - depth_m / 2)) +
            box((half, 0.05, depth_m / 2), (-(width_m / 2 + half), 0, -depth_m / 2)) +
            box((half, 0.05, depth_m / 2), (width_m / 2 + half, 0, -depth_m / 2)))


class Rig:
    """The tool on a stiff x/y/z servo over `objects` (MJCF geoms, top faces at z = 0)."""

    def __init__(self, objects, tool="ssc_tool_flex.xml"):
        integrator = "discrete" if "flex" in tool else "implicitfast"
        servo = '<position joint="%s" kp="20000" kv="400"/>'
        bodies = ""
        for axis, vec, mass in (("x", "1 0 0", 2), ("y", "0 1 0", 2), ("z", "0 0 1", 1)):
            bodies += ('<body name="g%s" gravcomp="1"><joint name="g%s" type="slide" axis="%s" '
                       'damping="20" armature="1"/><inertial pos="0 0 0" mass="%d" '
                       'diaginertia="0.01 0.01 0.01"/>' % (axis, axis, vec, mass))
        xml = f"""<mujoco><compiler angle="radian" autolimits="true"/>
<option timestep="0.002" integrator="{integrator}"/>
<asset><model name="ssc_tool" file="{os.path.join(ROOT, 'models', tool)}"/></asset>
<worldbody>{objects}{bodies}
<body name="probe" quat="0 0.70710678 -0.70710678 0" gravcomp="1">
<attach model="ssc_tool" body="tool" prefix="ssc_"/></body></body></body></body></worldbody>
<actuator>{servo % 'gx'}{servo % 'gy'}{servo % 'gz'}</actuator></mujoco>"""
        self.m = mujoco.MjModel.from_xml_string(xml)
        self.d = mujoco.MjData(self.m)
        sensor = mujoco.mj_name2id(self.m, mujoco.mjtObj.mjOBJ_SENSOR, "ssc_chamber_pressure")
        self.adr = self.m.sensor_adr[sensor]

    def press(self, x_m, press_mm, seconds=0.4, y_m=0.0):
        """Lowers the lip from 2 mm above the top face to press_mm into it, and holds."""
        self.d.qpos[:3] = [x_m, y_m, TOOL_Z_M + 0.002]
        self.d.ctrl[:3] = self.d.qpos[:3]
        mujoco.mj_step(self.m, self.d, 25)
        self.d.ctrl[2] = TOOL_Z_M - press_mm * 1e-3
        mujoco.mj_step(self.m, self.d, int(round(seconds / self.m.opt.timestep)))
        return self

    def push_x(self, to_m, speed_m_s=0.02, hold_s=0.3):
        """Moves the set point along x at constant speed, then holds; returns the smallest
        distance of a rim vertex from the cup's axis on the way."""
        start = self.d.ctrl[0]
        steps = int(abs(to_m - start) / speed_m_s / self.m.opt.timestep)
        closest = np.inf
        for k in range(1, steps + 1):
            self.d.ctrl[0] = start + (to_m - start) * k / steps
            mujoco.mj_step(self.m, self.d)
            rim = self.rim()
            closest = min(closest, np.hypot(rim[:, 0] - self.d.qpos[0],
                                            rim[:, 1] - self.d.qpos[1]).min())
        mujoco.mj_step(self.m, self.d, int(round(hold_s / self.m.opt.timestep)))
        return closest

    def pressures(self):
        return self.d.sensordata[self.adr:self.adr + 4].copy()

    def rings(self):
        """World positions of the skirt's vertices, ring by ring from the pinned top."""
        adr, n = self.m.flex_vertadr[0], self.m.flex_vertnum[0]
        sectors = int(skirt_parameters()["sectors"])
        return self.d.flexvert_xpos[adr:adr + n].reshape(-1, sectors, 3)

    def rim(self):
        """World positions of the skirt's free rim (its last ring)."""
        return self.rings()[-1]

    def hold_vertices(self, targets, seconds=0.2):
        """Holds the cup where it is and skirt vertices at world positions (a dict: index in
        rings().reshape(-1, 3) -> xyz) while the rest of the skirt moves as the engine makes it:
        a shape the test chooses, read by the pressure plugin as it reads any other."""
        adr = self.m.flex_vertadr[0]
        cup = self.m.body_parentid[self.m.flex_vertbodyid[adr + next(iter(targets))]]
        qadr, dof = {}, {}
        for v in targets:
            body = self.m.flex_vertbodyid[adr + v]
            assert self.m.body_jntnum[body] == 3, "a free skirt vertex: 3 slides"
            qadr[v] = self.m.jnt_qposadr[self.m.body_jntadr[body]]
            dof[v] = self.m.jnt_dofadr[self.m.body_jntadr[body]]
        for _ in range(3):  # the slides run along the cup's axes: a few corrections converge
            mujoco.mj_fwdPosition(self.m, self.d)
            rotation = self.d.xmat[cup].reshape(3, 3)
            for v, target in targets.items():
                shift = rotation.T @ (np.asarray(target) - self.d.flexvert_xpos[adr + v])
                self.d.qpos[qadr[v]:qadr[v] + 3] += shift
        qpos = {v: (qadr[v], self.d.qpos[qadr[v]:qadr[v] + 3].copy()) for v in targets}
        cup_qpos = self.d.qpos[:3].copy()  # the cup held too: the vacuum would lift the rest
        for _ in range(int(round(seconds / self.m.opt.timestep))):
            self.d.qpos[:3] = cup_qpos
            self.d.qvel[:3] = 0
            for v, (q, value) in qpos.items():
                self.d.qpos[q:q + 3] = value
                self.d.qvel[dof[v]:dof[v] + 3] = 0
            mujoco.mj_step(self.m, self.d)
        return self

    def middle_sag_mm(self):
        """How far the skirt's middle ring stands below half-way between its top and its rim."""
        rings = self.rings()
        half_way = (rings[0][:, 2].mean() + rings[-1][:, 2].mean()) / 2
        return 1e3 * (half_way - rings[len(rings) // 2][:, 2].mean())


class ShellTest(unittest.TestCase):
    def test_the_model_and_its_doc_table_are_generated_from_the_skirt_parameters(self):
        import subprocess
        import sys
        run = subprocess.run([sys.executable, os.path.join(ROOT, "tools", "make_flex_tool.py"),
                              "--check"], capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, run.stderr)

    def test_a_strip_of_the_skirt_material_bends_as_plate_theory_predicts(self):
        # A clamped strip of the skirt's silicone under a uniform load q: tip deflection
        # q L^4 / (8 D), D = E t^3 / (12 (1 - nu^2)), with the tool's shell correction applied as
        # in models/ssc_tool_flex.xml.
        s = skirt_parameters()
        young = s["young_mpa"] * 1e6
        t, nu = s["thickness_mm"] * 1e-3, s["poisson"]
        nx, ny, length, width, q = 12, 3, 0.010, 0.004, 50.0
        pts = [(length * i / nx, width * j / ny, 0) for i in range(nx + 1) for j in range(ny + 1)]
        vid = lambda i, j: i * (ny + 1) + j
        tris = []
        for i in range(nx):
            for j in range(ny):
                tris += [(vid(i, j), vid(i + 1, j), vid(i + 1, j + 1)),
                         (vid(i, j), vid(i + 1, j + 1), vid(i, j + 1))]
        pin = [vid(i, j) for i in (0, 1) for j in range(ny + 1)]
        xml = f"""<mujoco><option timestep="0.001" integrator="discrete"/><worldbody>
<body name="b"><flexcomp name="s" type="direct" dim="2" radius="0.0002"
 mass="{q * length * width / 9.81}" point="{' '.join('%g %g %g' % p for p in pts)}"
 element="{' '.join('%d %d %d' % e for e in tris)}">
<elasticity young="{young * s['shell_bending_correction']}" poisson="{nu}" thickness="{t}"
 damping="{s['damping_s']}" elastic2d="both"/><contact contype="0" conaffinity="0"/>
<pin id="{' '.join(map(str, pin))}"/></flexcomp></body></worldbody></mujoco>"""
        m = mujoco.MjModel.from_xml_string(xml)
        d = mujoco.MjData(m)
        mujoco.mj_step(m, d, 2000)
        tip_m = -d.flexvert_xpos[[vid(nx, j) for j in range(ny + 1)], 2].mean()
        free = length - length / nx
        theory_m = q * free ** 4 / (8 * young * t ** 3 / (12 * (1 - nu ** 2)))
        self.assertAlmostEqual(tip_m / theory_m, 1.0, delta=0.10)


class SkirtSensorTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        try:
            mujoco.mj_loadPluginLibrary(PLUGIN)
        except Exception:  # already registered (the ssc_twin package loads it too)
            pass

    def test_pressed_on_a_plate_every_chamber_seals_and_the_walls_hold_the_skirt(self):
        rig = Rig(PLATE).press(0.0, 1.0)
        p = rig.pressures()
        self.assertTrue(np.all(np.abs(p - SEALED_PA) < 0.02 * SEALED_PA), p)
        rim = rig.rim()
        # The rim rests on the plate (within 0.05 mm of one contact radius above it) ...
        radius = skirt_parameters()["contact_radius_mm"] * 1e-3
        self.assertTrue(np.all(np.abs(rim[:, 2] - radius) < 0.05e-3), rim[:, 2])
        # ... and stays on its circle (the opening's 5.5 mm within 0.5 mm) ...
        r = np.hypot(rim[:, 0], rim[:, 1])
        self.assertTrue(np.all(np.abs(r - 5.5e-3) < 0.5e-3), r)
        # ... under the chambers' vacuum, which loads it (its force on the tool is the chamber
        # pressure over the cavity's projected area, to the rim's circle within 10 %) ...
        end = rig.m.plugin_stateadr[0] + rig.m.plugin_statenum[0]
        pull = -rig.d.plugin_state[end - 1]  # the last of the plugin's state: the force's world z
        area = np.pi * np.mean(r) ** 2
        self.assertAlmostEqual(pull / (p.mean() * area), 1.0, delta=0.10)
        # ... while the skirt keeps its shape: its middle ring within 0.25 mm of half-way up (the
        # walls' lower edges take the press beyond their recess; without them a sealed cup's
        # vacuum buckles the skirt pressed 1 mm, docs/pneumatics.md).
        self.assertLess(abs(rig.middle_sag_mm()), 0.25)
        recess = skirt_parameters()["wall_recess_mm"] * 1e-3
        self.assertLess(abs((TOOL_Z_M - rig.d.qpos[2]) - recess), 0.1e-3)

    def test_over_a_notch_the_vacuum_pulls_the_rim_into_it_and_the_cup_leaks(self):
        plate = Rig(PLATE).press(0.0, 1.0)
        loaded = Rig(notch(0.004, 0.001)).press(0.0, 1.0)
        unloaded = Rig(notch(0.004, 0.001), tool=tool_variant(vacuum_load=False)).press(0.0, 1.0)

        def over(rig):  # rim vertices over the slot
            rim = rig.rim()
            return rim[(np.abs(rim[:, 1]) < 2.0e-3) & (rim[:, 0] > 0), 2]

        self.assertTrue(len(over(loaded)) > 0)
        # The unsupported stretch sags into the slot, further with the vacuum pulling it ...
        self.assertLess(over(loaded).max(), plate.rim()[:, 2].min() - 0.2e-3)
        self.assertLess(over(loaded).max(), over(unloaded).min() - 0.03e-3)
        # ... and the cup leaks through it (but still holds a vacuum).
        self.assertLess(loaded.pressures().mean(), 0.6 * plate.pressures().mean())
        self.assertGreater(loaded.pressures().mean(), 0.1 * plate.pressures().mean())

    def test_over_a_groove_the_rim_drops_into_it_and_the_cup_leaks(self):
        plate = Rig(PLATE).press(0.0, 1.0)
        over = Rig(groove(0.006, 0.003)).press(0.0, 1.0)
        rim = over.rim()
        in_groove = np.abs(rim[:, 0]) < 2.9e-3  # the groove is 6 mm wide
        self.assertTrue(in_groove.any() and (~in_groove).any())
        # Unsupported rim sags into the groove; the rim on the plate rests on it.
        self.assertLess(rim[in_groove, 2].min(), rim[~in_groove, 2].min() - 0.2e-3)
        self.assertLess(over.pressures().mean(), 0.5 * plate.pressures().mean())

    def test_pushed_into_a_concave_corner_the_lip_wedges_but_does_not_fold_shut(self):
        # The cup runs 2.5 mm inside the edge y = 0 toward the corner's other edge, x = 0; the
        # stretch of rim that hangs over the drop meets that edge's wall.
        inset, start, end = -2.5e-3, 8e-3, 1e-3
        light = Rig(concave_corner()).press(start, 0.3, y_m=inset)  # the approach's press
        deep = Rig(concave_corner()).press(start, 1.0, y_m=inset)  # onto the walls (0.5 mm)
        closest = {"light": light.push_x(end), "deep": deep.push_x(end)}
        # The wall pushes that stretch in over the opening (the rim at 5.5-6 mm from the axis) ...
        for name, r_m in closest.items():
            self.assertLess(r_m, 4.8e-3, name)
        # ... and, pressed onto the walls, the lip wedged in the corner holds the cup back
        # behind its set point (at the approach's press it slides by).
        self.assertGreater(deep.d.qpos[0] - end, 0.15e-3)
        self.assertLess(light.d.qpos[0] - end, 0.05e-3)
        # It does not fold over on itself: the chamber that faces the drop (3 in this rig's
        # frame) reads what it reads with the cup lowered straight onto the same spot (no
        # stretch of lip covers its opening; docs/pneumatics.md: what stops the crimp).
        lowered = Rig(concave_corner()).press(deep.d.qpos[0], 1.0, y_m=inset)
        self.assertLess(abs(deep.pressures()[2] - lowered.pressures()[2]),
                        0.3 * lowered.pressures()[2] + 10.0)
        # Pushed on toward a set point 2.5 mm past that wall, the wedged lip is dragged down into
        # the corner's gap (its rim well below the top face) and holds the cup back; the cup then
        # leaks more than one lowered straight onto the same spot: the wedge opens the lip, no
        # stretch folds shut over the open chamber.
        far_end = -2.5e-3
        far = Rig(concave_corner()).press(start, 1.0, y_m=inset)
        far.push_x(far_end)
        self.assertGreater(far.d.qpos[0] - far_end, 0.5e-3)
        self.assertLess(far.rim()[:, 2].min(), -0.5e-3)
        lowered_far = Rig(concave_corner()).press(far.d.qpos[0], 1.0, y_m=inset)
        self.assertLess(far.pressures().mean(), 0.8 * lowered_far.pressures().mean())

    def quadrant_columns(self, rig):
        """The skirt vertices (flat indices) of the chamber whose rim points lie at world angles
        0-90 deg about the cup: its rim vertices and the middle ring's strictly inside."""
        rings = rig.rings()
        c = rig.d.qpos[:2]
        angle = np.degrees(np.arctan2(rings[..., 1] - c[1], rings[..., 0] - c[0]))
        inside = (angle > 1) & (angle < 89)
        sectors = rings.shape[1]
        flat = lambda ring, which: [ring * sectors + j for j in np.flatnonzero(which[ring])]
        return flat(len(rings) - 1, inside), flat(len(rings) // 2, inside), flat(
            len(rings) - 1, ~inside)

    def hold_the_rest(self, rig, rest):
        """The rest of the rim held where it is (on the plate), so only the chosen chamber's
        stretch of lip changes."""
        flat = rig.rings().reshape(-1, 3)
        return {v: flat[v].copy() for v in rest}

    def test_a_crease_that_touches_the_surface_seals_while_a_lifted_rim_leaks(self):
        # One chamber's stretch of lip held 1 mm up: the chamber leaks under it. Folded in on
        # itself, the same rim held up and curled in, its crease (the middle ring) on the plate:
        # the crease seals (each column is read at its lowest point, not only at its rim).
        radius = skirt_parameters()["contact_radius_mm"] * 1e-3
        shapes = {}
        for shape in ("lifted", "creased"):
            rig = Rig(PLATE).press(0.0, 0.3)
            rim, middle, rest = self.quadrant_columns(rig)
            flat = rig.rings().reshape(-1, 3)
            targets = self.hold_the_rest(rig, rest)
            for v in rim:
                p = flat[v].copy()
                p[2] += 1e-3
                if shape == "creased":
                    p[:2] *= 4.5e-3 / np.hypot(p[0], p[1])
                targets[v] = p
            if shape == "creased":
                for v in middle:
                    p = flat[v].copy()
                    p[:2] *= 5.0e-3 / np.hypot(p[0], p[1])
                    p[2] = radius
                    targets[v] = p
            shapes[shape] = rig.hold_vertices(targets).pressures()
        lifted, creased = shapes["lifted"], shapes["creased"]
        held = np.argmin(lifted)
        self.assertLess(lifted[held], 0.5 * SEALED_PA, lifted)
        self.assertGreater(creased[held], 0.9 * SEALED_PA, creased)

    def test_a_stretch_of_lip_folded_over_an_open_chamber_blocks_it(self):
        # The cup 1.5 mm inside a straight edge (the plate covers y < 0): the chambers facing +y
        # stand half over the drop and leak. One of them with its stretch of lip folded in across
        # its opening onto the plate (the rim at 1 mm from the axis) is blocked: its vacuum rises
        # to the sealed chambers' while the other one facing the drop stays open.
        edge = box((0.05, 0.025, 0.005), (0, -0.025, -0.005))
        radius = skirt_parameters()["contact_radius_mm"] * 1e-3
        open_cup = Rig(edge).press(0.0, 0.3, y_m=-1.5e-3)
        folded = Rig(edge).press(0.0, 0.3, y_m=-1.5e-3)
        rim, _, rest = self.quadrant_columns(folded)
        c = folded.d.qpos[:2]
        flat = folded.rings().reshape(-1, 3)
        targets = self.hold_the_rest(folded, rest)
        for v in rim:
            p = flat[v].copy()
            p[:2] = c + (p[:2] - c) * 1.0e-3 / np.hypot(*(p[:2] - c))
            p[2] = radius
            self.assertLess(p[1], 0.0)  # on the plate
            targets[v] = p
        folded.hold_vertices(targets)
        before, after = open_cup.pressures(), folded.pressures()
        facing = np.flatnonzero(before < 0.1 * before.max())  # the two chambers over the drop
        self.assertEqual(len(facing), 2, before)
        blocked = facing[np.argmax(after[facing])]
        other = facing[facing != blocked][0]
        on_plate = np.setdiff1d(np.arange(4), facing)
        # The blocked chamber reads what the chambers on the plate read (the cup as a whole
        # still leaks through the other one, and the chambers share the supply) ...
        self.assertGreater(after[blocked], 0.9 * after[on_plate].min(), after)
        self.assertGreater(after[blocked], 10 * before[blocked], (before, after))
        # ... the other stays open.
        self.assertLess(after[other], 0.1 * after[on_plate].min(), after)

    def test_the_same_run_twice_is_the_same(self):
        a = Rig(groove(0.003, 0.003)).press(0.001, 1.0, seconds=0.2)
        b = Rig(groove(0.003, 0.003)).press(0.001, 1.0, seconds=0.2)
        np.testing.assert_array_equal(a.d.qpos, b.d.qpos)
        np.testing.assert_array_equal(a.pressures(), b.pressures())


if __name__ == "__main__":
    unittest.main()
