#!/usr/bin/env python3
"""Renders the flex skirt lip at a decisive moment of an object trial, off-screen (MuJoCo's
renderer through the mujoco Python package; MUJOCO_GL=egl or osmesa on a headless machine).

The trial is the object's flex-tier trial (ssc_twin.SteppedTrial on disk_benchmark_flex: the
published law, P_ref 100 Pa, beta 2, dL --step-mm (0.5 mm), default effects), run until its tracked position
first passes --at-arc-mm along the edge (or it ends); the picture is a close-up of the cup and
the skirt from a low oblique camera, the cup body drawn translucent so the skirt shows. The
pressure plugin marks each rim point: green sealed (in contact), amber a gap within the open
depth, red open.

Usage:
  MUJOCO_GL=egl PYTHONPATH=build/python_pkg .venv/bin/python tools/render_lip.py \\
      --object corner_a270 --at-arc-mm 58 --azimuth 225 --out out/lip_corner_a270.png
"""

import argparse
import os
import sys

import mujoco


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--object", required=True, help="a test object (ssc objects --help)")
    p.add_argument(
        "--at-arc-mm",
        type=float,
        required=True,
        help="stop when the tracked position first passes this, mm along the edge",
    )
    p.add_argument("--seed", type=int, default=1)
    p.add_argument(
        "--step-mm",
        type=float,
        default=0.5,
        help="the law's step dL, mm (range: the law's, checked by the trial)",
    )
    p.add_argument("--azimuth", type=float, default=200, help="camera azimuth, deg")
    p.add_argument("--elevation", type=float, default=-30, help="camera elevation, deg")
    p.add_argument("--distance", type=float, default=0.04, help="camera distance, m")
    p.add_argument("--size", default="960x640", help="WIDTHxHEIGHT, px")
    p.add_argument("--out", required=True, help="PNG to write")
    a = p.parse_args()
    try:
        width, height = (int(v) for v in a.size.split("x"))
    except ValueError:
        p.error(f"--size {a.size!r}: expected WIDTHxHEIGHT")
    if not (16 <= width <= 4096 and 16 <= height <= 4096):
        p.error("--size: each side in [16, 4096] px")
    if not (0 < a.at_arc_mm < 1000):
        p.error("--at-arc-mm: in (0, 1000) mm")
    from ssc_twin import _core  # noqa: E402  (after argument checks: the import is slow)

    trial = _core.SteppedTrial(
        scene="disk_benchmark_flex", object=a.object, seed=a.seed, step_mm=a.step_mm
    )
    while trial.tracked_arc_m * 1e3 < a.at_arc_mm:
        if not trial.run_to_next_iteration():
            break
    m, d = trial.model, trial.data
    p_pa = trial.iteration_pressures()
    # The rigid cup drawn translucent (the skirt stays opaque): every geom of the tool's bodies
    # but the lip's group 4.
    for g in range(m.ngeom):
        if m.geom_group[g] in (1, 3) or "ssc_" in (
            mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_GEOM, g) or ""
        ):
            if m.geom_group[g] != 4:
                m.geom_rgba[g, 3] = min(m.geom_rgba[g, 3], 0.15)
    m.vis.global_.offwidth = max(m.vis.global_.offwidth, width)
    m.vis.global_.offheight = max(m.vis.global_.offheight, height)
    renderer = mujoco.Renderer(m, height, width)
    cam = mujoco.MjvCamera()
    cam.type = mujoco.mjtCamera.mjCAMERA_FREE
    cam.lookat[:] = d.site_xpos[trial.tool_site]
    cam.lookat[2] -= 0.002
    cam.distance, cam.azimuth, cam.elevation = a.distance, a.azimuth, a.elevation
    opt = mujoco.MjvOption()
    for group in range(6):
        opt.geomgroup[group] = 1
        opt.flexgroup[group] = 1
    # The skirt as its surface and edges (not a sphere per vertex).
    opt.flags[mujoco.mjtVisFlag.mjVIS_FLEXVERT] = 0
    opt.flags[mujoco.mjtVisFlag.mjVIS_FLEXFACE] = 1
    opt.flags[mujoco.mjtVisFlag.mjVIS_FLEXEDGE] = 1
    renderer.update_scene(d, cam, opt)
    image = renderer.render()
    from PIL import Image  # matplotlib's dependency, in the project's requirements

    os.makedirs(os.path.dirname(os.path.abspath(a.out)), exist_ok=True)
    Image.fromarray(image).save(a.out)
    tool = d.site_xpos[trial.tool_site]
    print(
        f"{a.out}: {a.object} seed {a.seed}, t {trial.time:.2f} s, phase {trial.phase}, "
        f"{trial.tracked_arc_m * 1e3:.1f} mm along the edge, cup at "
        f"({(tool[0] - 0.65) * 1e3:.1f}, {tool[1] * 1e3:.1f}) mm from W, chambers "
        + "/".join(f"{v:.0f}" for v in p_pa)
        + " Pa"
    )


if __name__ == "__main__":
    sys.exit(main())
