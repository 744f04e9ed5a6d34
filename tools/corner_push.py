#!/usr/bin/env python3
"""The scripted push into a concave corner (docs/pneumatics.md, "The flex skirt at a concave
corner") for the flex skirt as it is or a variant of tools/make_flex_tool.py's parameters.

The rig of tests/plugin/flex_lip_test.py: the tool on a stiff x/y/z servo, lowered 2 mm above a
plate to --press-mm into it with its centre 2.5 mm inside the edge y = 0, at x = 8 mm; then its
set point moves at 20 mm/s along the edge to --to-mm and holds 0.3 s. The plate has a 270-degree
corner at the origin (the quadrant x > 0, y > 0 is a 10 mm drop), so the stretch of lip hanging
over the drop meets the corner's other wall, x = 0. Printed per press: where the cup ended, the
rim's closest approach to the axis, its lowest vertex against the top face, and the four chamber
pressures pushed / lowered (the cup set straight down where the pushed one ended).

With --press-n the press is set by force instead, as the trial's approach sets it (1.5 N on the
F/T): the commanded press at which the settled contact force on the plate first reaches that
force (a scan in 0.1 mm steps, then bisection; each try a fresh rig). Printed first per force:
the press found, the skirt's compression (the lip plane below the top face), and how far the
rim's surface over the drop hangs below the top face, against the rim's contact radius: the rim
catches the corner's far wall only if it hangs lower than its radius (its vertex centres below
the wall's top edge), else it rides up over the edge.

Usage (from the repository, after a build):
  SSC_PLUGIN_LIB=build/lib/libssc_plugin.so .venv/bin/python tools/corner_push.py \\
      --press-mm 0.3,1.0 --to-mm 1 [--set contact_radius_mm=0.2 --set rings=5 ...]
  SSC_PLUGIN_LIB=build/lib/libssc_plugin.so .venv/bin/python tools/corner_push.py \\
      --press-n 1.5 --to-mm 1 --set young_mpa=0.6 --set thickness_mm=0.6 --set height_mm=4
"""
import argparse
import os
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[1]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--press-mm", default="0.3,1.0", help="commanded presses, comma-separated")
    p.add_argument("--press-n", default="",
                   help="presses set by the settled contact force instead, N, comma-separated")
    p.add_argument("--to-mm", type=float, default=1.0,
                   help="the set point's end along the edge, mm from the corner's wall")
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                   help="a skirt parameter of tools/make_flex_tool.py (repeatable)")
    a = p.parse_args()
    try:
        presses = [float(v) for v in a.press_mm.split(",")]
    except ValueError:
        p.error(f"--press-mm {a.press_mm!r}: expected numbers, comma-separated")
    if not all(0 < v <= 2 for v in presses):
        p.error("--press-mm: each in (0, 2] mm")
    try:
        forces = [float(v) for v in a.press_n.split(",")] if a.press_n else []
    except ValueError:
        p.error(f"--press-n {a.press_n!r}: expected numbers, comma-separated")
    if not all(0.1 <= v <= 10 for v in forces):
        p.error("--press-n: each in [0.1, 10] N")
    if not -5 <= a.to_mm <= 7:
        p.error("--to-mm: in [-5, 7] mm")
    import numpy as np

    import flex_rig

    mujoco, rig_module = flex_rig.load(p)
    tool, variant = "ssc_tool_flex.xml", None
    sectors = int(rig_module.skirt_parameters()["sectors"])
    if a.set:
        # The rig names the tool inside models/ (and picks the flex integrator by its name).
        fd, variant = tempfile.mkstemp(prefix="flex_push_", suffix=".xml", dir=ROOT / "models")
        os.close(fd)
        cmd = [sys.executable, str(ROOT / "tools" / "make_flex_tool.py"), "--out", variant]
        for item in a.set:
            cmd += ["--set", item]
            if item.startswith("sectors="):
                sectors = int(float(item.split("=", 1)[1]))
        subprocess.run(cmd, check=True)
        tool = os.path.basename(variant)

    def plate_force(rig):
        """Normal force of the contacts with the plate (world geoms), N: what the F/T reads."""
        total, wrench = 0.0, np.zeros(6)
        for i in range(rig.d.ncon):
            if any(g >= 0 and rig.m.geom_bodyid[g] == 0 for g in rig.d.contact.geom[i]):
                mujoco.mj_contactForce(rig.m, rig.d, i, wrench)
                total += wrench[0]
        return total

    def press_for_force(force_n):
        """The commanded press (mm) at which the settled plate force first reaches force_n, as
        the approach lowering the cup meets it: a scan in 0.1 mm steps, then bisection."""
        def settled(press_mm):
            rig = rig_module.Rig(rig_module.concave_corner(), tool=tool).press(
                start, press_mm, y_m=inset)
            return plate_force(rig) - force_n, rig
        low, high = 0.0, None
        for k in range(1, 21):
            f, rig = settled(0.1 * k)
            if f >= 0:
                high, best = 0.1 * k, rig
                break
            low = 0.1 * k
        if high is None:
            return low, rig
        for _ in range(5):
            mid = (low + high) / 2
            f, rig = settled(mid)
            if f >= 0:
                high, best = mid, rig
            else:
                low = mid
        return high, best

    try:
        inset, start, end = -2.5e-3, 8e-3, a.to_mm * 1e-3
        radius_mm = rig_module.skirt_parameters()["contact_radius_mm"]
        for item in a.set:
            if item.startswith("contact_radius_mm="):
                radius_mm = float(item.split("=", 1)[1])
        if forces:  # the pushes run at the presses that give these forces
            presses = []
        for force in forces:
            press, rig = press_for_force(force)
            adr, n = rig.m.flex_vertadr[0], rig.m.flex_vertnum[0]
            rim = rig.d.flexvert_xpos[adr:adr + n].reshape(-1, sectors, 3)[-1]
            # The rim's surface over the drop (y > 0): its lowest point below the top face. A
            # rim resting on the plate has its vertex centres one contact radius above it.
            hang = radius_mm - 1e3 * rim[rim[:, 1] > 0, 2].min()
            print(f"force {force:.2f} N (settled {plate_force(rig):.2f} N): commanded press "
                  f"{press:.3f} mm, compression {1e3 * (rig_module.TOOL_Z_M - rig.d.qpos[2]):.3f} "
                  f"mm; the rim over the drop hangs {hang:.3f} mm below the top face, against "
                  f"its contact radius {radius_mm:.2f} mm: "
                  f"{'catches the far wall' if hang > radius_mm else 'rides over it'}", flush=True)
            presses.append(press)
        for press in presses:
            pushed = rig_module.Rig(rig_module.concave_corner(), tool=tool).press(
                start, press, y_m=inset)
            pushed.push_x(end)
            adr, n = pushed.m.flex_vertadr[0], pushed.m.flex_vertnum[0]
            rim = pushed.d.flexvert_xpos[adr:adr + n].reshape(-1, sectors, 3)[-1]
            c = pushed.d.qpos[:2]
            closest = np.hypot(rim[:, 0] - c[0], rim[:, 1] - c[1]).min()
            lowered = rig_module.Rig(rig_module.concave_corner(), tool=tool).press(
                pushed.d.qpos[0], press, y_m=inset)
            print(f"press {press:.3f} mm: cup at x {1e3 * c[0]:.2f} mm (set {a.to_mm:.2f}); rim "
                  f"closest {1e3 * closest:.2f} mm, lowest {1e3 * rim[:, 2].min():+.2f} mm "
                  f"(vertex centre vs the top face); chambers pushed "
                  f"{np.round(pushed.pressures()).astype(int).tolist()} / lowered "
                  f"{np.round(lowered.pressures()).astype(int).tolist()} Pa", flush=True)
    finally:
        if variant:
            os.remove(variant)


if __name__ == "__main__":
    main()
