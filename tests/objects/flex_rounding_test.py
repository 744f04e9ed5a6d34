"""The flex skirt lip over a rounded edge (the fillet's mechanism, docs/flex_objects.md): the cup
pressed at the preload onto a plate whose straight edge is rounded with radius r, its centre the
same distance inside where the rounding starts. Over a rounding the skirt stands off the falling
surface instead of draping onto it, and the larger the radius, the smaller the differential."""

import importlib.util
import os
import unittest

import mujoco
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location(
    "flex_lip_test", os.path.join(HERE, "..", "plugin", "flex_lip_test.py")
)
flex = importlib.util.module_from_spec(spec)
spec.loader.exec_module(flex)

INSIDE_M = 0.0025  # cup centre inside the edge (the static calibration's 100 Pa point)
RADII_MM = (2.0, 4.0, 8.0)


def rounded_edge(radius_m):
    """A plate (top z = 0) over x < 0, its edge along y at x = 0 rounded with radius_m."""
    r = radius_m
    return (
        flex.box(((0.05 - r) / 2, 0.05, 0.005), (-(0.05 + r) / 2, 0, -0.005))
        + flex.box((r / 2, 0.05, (0.01 - r) / 2), (-r / 2, 0, -r - (0.01 - r) / 2))
        + '<geom type="cylinder" size="%g 0.05" pos="%g 0 %g" euler="1.5707963 0 0" '
        'group="2" contype="1" conaffinity="1"/>' % (r, -r, -r)
    )


def surface_z(x_m, radius_m):
    """Height of the rounded plate's top at x (NaN beyond the edge)."""
    r = radius_m
    if x_m <= -r:
        return 0.0
    if x_m >= 0:
        return np.nan
    return -r + np.sqrt(r * r - (x_m + r) ** 2)


class RoundingTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        try:
            mujoco.mj_loadPluginLibrary(flex.PLUGIN)
        except Exception:  # already registered
            pass
        cls.runs = {}
        for r_mm in RADII_MM:
            rig = flex.Rig(rounded_edge(r_mm * 1e-3)).press_to_preload(-INSIDE_M)
            p = rig.pressures()
            skirt = rig.rings().reshape(-1, 3)
            gaps = [
                v[2] - rig.m.flex_radius[0] - surface_z(v[0], r_mm * 1e-3)
                for v in skirt
                if -r_mm * 1e-3 < v[0] < 0
            ]
            cls.runs[r_mm] = (p, np.array(gaps))

    def test_the_skirt_over_the_rounding_lifts_off_the_surface(self):
        for r_mm in RADII_MM[1:]:
            _, gaps = self.runs[r_mm]
            self.assertGreater(len(gaps), 0)
            # Draped, it would rest on it (contacts hold it within 0.01 mm of a surface).
            self.assertGreater(gaps.max(), 0.1e-3, (r_mm, gaps))

    def test_the_differential_falls_with_the_radius(self):
        spread = [self.runs[r][0].max() - self.runs[r][0].min() for r in RADII_MM]
        self.assertGreater(spread[0], 50, spread)  # the sharp-ish edge reads it
        for tighter, wider in zip(spread, spread[1:]):
            self.assertLess(wider, tighter, spread)
        self.assertLess(spread[-1], 0.5 * spread[0], spread)


if __name__ == "__main__":
    unittest.main()
