#!/usr/bin/env python3
"""The scripted push into a concave corner (issue 25's crimp push; docs/flex_skirt.md, "The
skirt at a concave corner") for the flex skirt as it is or a variant of tools/make_flex_tool.py's
parameters, with an optional rendered sequence.

The rig of tests/plugin/flex_lip_test.py: the tool on a stiff x/y/z servo over a plate with a
270-degree corner at the origin (the quadrant x > 0, y > 0 is a 10 mm drop). The cup is lowered at
x = --from-mm, its centre 2.5 mm inside the edge y = 0, until the bellows carries the 1.5 N preload
(the approach's stop), then its set point moves at 20 mm/s along the edge to --to-mm and holds
0.3 s: the stretch of skirt hanging over the drop meets the corner's far wall, x = 0. Printed
every 2 mm and at the end: where the cup is, the chamber pressures, how many skirt vertices lie
inside the throat (a lobe folded in under the cup), the lowest vertex against the top face; at
the end the chambers of the cup lowered straight onto the same spot, for comparison. A chamber
is blocked when a lobe over its mouth lifts it to kPa where the lowered cup reads Pa.

With --frames DIR, PNG frames (a close-up from the drop's side, the chamber body drawn
translucent) every --frame-mm of the set point's travel; headless: MUJOCO_GL=egl (or osmesa).

Usage (from the repository, after a build):
  SSC_PLUGIN_LIB=build/lib/libssc_plugin.so .venv/bin/python tools/corner_push.py --to-mm -3
  MUJOCO_GL=egl SSC_PLUGIN_LIB=build/lib/libssc_plugin.so .venv/bin/python tools/corner_push.py \\
      --to-mm -3 --frames out/crimp --set thickness_mm=1.5
"""

import argparse
import os
import sys

import flex_rig

INSET_M = -2.5e-3  # the cup's centre inside the edge y = 0 (the static curve's 100 Pa point)
SPEED_M_S = 0.02


def parse(p):
    p.add_argument(
        "--from-mm",
        type=float,
        default=16.0,
        help="where the cup is lowered, mm from the corner's far wall (x)",
    )
    p.add_argument(
        "--to-mm",
        type=float,
        default=-3.0,
        help="the set point's end along the edge, mm from the far wall",
    )
    flex_rig.add_variant_arguments(
        p, "a MuJoCo <option> field for both cups, e.g. iterations=10 (the flex scenes' cap)"
    )
    p.add_argument("--frames", help="write PNG frames to this directory")
    p.add_argument("--frame-mm", type=float, default=2.0, help="set-point travel between frames")
    p.add_argument("--size", default="640x400", help="frame WIDTHxHEIGHT, px")
    p.add_argument(
        "--elevation",
        type=float,
        default=5,
        help="camera elevation, deg (+: from below the top face, under the cup)",
    )
    a = p.parse_args()
    if not 12 <= a.from_mm <= 30:
        p.error("--from-mm: in [12, 30] mm (the 23 mm rim clear of the far wall)")
    if not -8 <= a.to_mm < a.from_mm:
        p.error("--to-mm: in [-8, --from-mm) mm")
    if not -89 <= a.elevation <= 89:
        p.error("--elevation: in [-89, 89] deg")
    if not 0.2 <= a.frame_mm <= 10:
        p.error("--frame-mm: in [0.2, 10] mm")
    a.options = flex_rig.parse_options(p, a.option)
    try:
        a.width, a.height = (int(v) for v in a.size.split("x"))
    except ValueError:
        p.error(f"--size {a.size!r}: expected WIDTHxHEIGHT")
    if not (16 <= a.width <= 2048 and 16 <= a.height <= 2048):
        p.error("--size: each side in [16, 2048] px")
    return a


class Frames:
    """Close-ups of the skirt from the drop's side, the chamber body translucent."""

    def __init__(self, mujoco, rig, a):
        self.mujoco, self.rig, self.dir, self.n = mujoco, rig, a.frames, 0
        os.makedirs(self.dir, exist_ok=True)
        m = rig.m
        for g in range(m.ngeom):
            if m.geom_group[g] in (1, 3):
                m.geom_rgba[g, 3] = min(m.geom_rgba[g, 3], 0.2)
            elif m.geom_bodyid[g] == 0:  # the plate: light, so the skirt's blue shows against it
                m.geom_rgba[g] = [0.85, 0.82, 0.75, 1]
        m.vis.headlight.ambient[:] = 0.45
        m.vis.headlight.diffuse[:] = 0.6
        m.vis.global_.offwidth = max(m.vis.global_.offwidth, a.width)
        m.vis.global_.offheight = max(m.vis.global_.offheight, a.height)
        self.renderer = mujoco.Renderer(m, a.height, a.width)
        self.cam = mujoco.MjvCamera()
        self.cam.type = mujoco.mjtCamera.mjCAMERA_FREE
        # From down in the drop, looking back up at the far wall and under the cup.
        self.cam.distance, self.cam.azimuth, self.cam.elevation = 0.035, 225, a.elevation
        self.opt = mujoco.MjvOption()
        for group in range(6):
            self.opt.geomgroup[group] = 1
            self.opt.flexgroup[group] = 1
        self.opt.flags[mujoco.mjtVisFlag.mjVIS_FLEXVERT] = 0
        self.opt.flags[mujoco.mjtVisFlag.mjVIS_FLEXFACE] = 1
        self.opt.flags[mujoco.mjtVisFlag.mjVIS_FLEXEDGE] = 1

    def save(self, label):
        from PIL import Image  # matplotlib's dependency, in the project's requirements

        d = self.rig.d
        self.cam.lookat[:] = [d.qpos[0], d.qpos[1], 0.0]
        self.renderer.update_scene(d, self.cam, self.opt)
        path = os.path.join(self.dir, f"crimp_{self.n:02d}_{label}.png")
        Image.fromarray(self.renderer.render()).save(path)
        self.n += 1
        return path


def state(np, rig, throat_m):
    """(vertices inside the throat, lowest vertex z in mm) of the skirt's free rings now."""
    c = rig.d.qpos[:2]
    flat = rig.rings()[1:].reshape(-1, 3)
    r = np.hypot(flat[:, 0] - c[0], flat[:, 1] - c[1])
    return int((r < throat_m).sum()), 1e3 * flat[:, 2].min()


def main():
    a = parse(argparse.ArgumentParser(description=__doc__.split("\n")[0]))
    import numpy as np

    mujoco, rig_module = flex_rig.load(argparse.ArgumentParser())
    flex_rig.check_options(mujoco, a.options, lambda text: sys.exit(f"corner_push.py: {text}"))

    def with_options(rig):
        flex_rig.apply_options(rig.m, a.options)
        return rig

    tool, variant = flex_rig.variant_tool(a.set, "flex_push_")
    params = rig_module.skirt_parameters()
    if a.set:
        for item in a.set:
            key, _, text = item.partition("=")
            params[key] = float(text) if key in params else params.get(key)
        rig_module.skirt_parameters = lambda: params
    throat_m = params["throat_radius_mm"] * 1e-3
    try:
        rig = with_options(rig_module.Rig(rig_module.concave_corner(), tool=tool))
        rig.press_to_preload(a.from_mm * 1e-3, y_m=INSET_M)
        frames = Frames(mujoco, rig, a) if a.frames else None
        inside, lowest = state(np, rig, throat_m)
        print(
            f"lowered at x {a.from_mm:.1f} mm: bellows {rig.bellows_n():.2f} N, the lip plane "
            f"{1e3 * (rig_module.TOOL_Z_M - rig.d.qpos[2]):.2f} mm below the top face, lowest "
            f"vertex {lowest:+.2f} mm, chambers {np.round(rig.pressures()).astype(int).tolist()}"
            f" Pa",
            flush=True,
        )
        if frames:
            print(frames.save("lowered"))
        start, end = a.from_mm * 1e-3, a.to_mm * 1e-3
        steps = int(abs(end - start) / SPEED_M_S / rig.m.opt.timestep)
        per_report = max(1, int(round(2e-3 / SPEED_M_S / rig.m.opt.timestep)))
        per_frame = max(1, int(round(a.frame_mm * 1e-3 / SPEED_M_S / rig.m.opt.timestep)))
        for k in range(1, steps + 1):
            rig.d.ctrl[0] = start + (end - start) * k / steps
            mujoco.mj_step(rig.m, rig.d)
            if k % per_report == 0 or k == steps:
                inside, lowest = state(np, rig, throat_m)
                print(
                    f"set {1e3 * rig.d.ctrl[0]:+6.2f} cup {1e3 * rig.d.qpos[0]:+6.2f} mm: "
                    f"chambers {np.round(rig.pressures()).astype(int).tolist()} Pa, "
                    f"{inside} vertices inside the throat, lowest {lowest:+.2f} mm",
                    flush=True,
                )
            if frames and (k % per_frame == 0 or k == steps):
                print(frames.save(f"x{1e3 * rig.d.ctrl[0]:+.1f}mm"))
        mujoco.mj_step(rig.m, rig.d, int(round(0.3 / rig.m.opt.timestep)))
        inside, lowest = state(np, rig, throat_m)
        if frames:
            print(frames.save("held"))
        lowered = with_options(rig_module.Rig(rig_module.concave_corner(), tool=tool))
        lowered.press_to_preload(rig.d.qpos[0], y_m=INSET_M)
        print(
            f"held at x {1e3 * rig.d.qpos[0]:+.2f} mm: chambers pushed "
            f"{np.round(rig.pressures()).astype(int).tolist()} / lowered there "
            f"{np.round(lowered.pressures()).astype(int).tolist()} Pa; {inside} vertices "
            f"inside the throat, lowest {lowest:+.2f} mm",
            flush=True,
        )
    finally:
        if variant:
            variant.cleanup()


if __name__ == "__main__":
    main()
