#!/usr/bin/env python3
"""The flex skirt against the static calibration, and its cost (docs/flex_skirt.md): the rig of
tests/plugin/flex_lip_test.py lowers the cup onto a plate with a straight sharp edge until the
bellows carries the 1.5 N preload, its centre --inside-mm inside the edge, holds, and prints the
mean over the next 0.1 s of P-bar and |(dPx, dPy)| (Pa), the segment lip's static figures'
columns. With --move-mm the cup then moves that far along the edge at 20 mm/s and holds 0.1 s:
printed are the chambers after it and the CPU per step of that part (this process's CPU time,
a paired ratio only within one run on a loaded machine).

Variants of tools/make_flex_tool.py's parameters with --set; MuJoCo options with --option
(iterations=5, solver=1, ...): the cheaper settings keep the outcome when their rows match.

Usage (from the repository, after a build):
  SSC_PLUGIN_LIB=build/lib/libssc_plugin.so .venv/bin/python tools/flex_edge_table.py \\
      --inside-mm 1.5,2.5,3.5 [--move-mm 4] [--set sectors=16 --set rings=4] [--option iterations=5]
"""

import argparse
import time

import flex_rig


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument(
        "--inside-mm",
        default="1.5,2.5,3.5",
        help="cup centre inside the edge, mm, comma-separated; each in [-5, 5.5]",
    )
    p.add_argument("--move-mm", type=float, default=0.0, help="then move along the edge, mm")
    flex_rig.add_variant_arguments(
        p, "a MuJoCo <option> field, e.g. iterations=5 or solver=1 (repeatable)"
    )
    a = p.parse_args()
    try:
        insets = [float(v) for v in a.inside_mm.split(",")]
    except ValueError:
        p.error(f"--inside-mm {a.inside_mm!r}: expected numbers, comma-separated")
    if not all(-5 <= v <= 5.5 for v in insets):
        p.error("--inside-mm: each in [-5, 5.5] mm")
    if not 0 <= a.move_mm <= 20:
        p.error("--move-mm: in [0, 20] mm")
    options = flex_rig.parse_options(p, a.option)
    import numpy as np

    mujoco, rig_module = flex_rig.load(p)
    flex_rig.check_options(mujoco, options, p.error)
    tool, variant = flex_rig.variant_tool(a.set, "flex_edge_")
    edge = rig_module.box((0.05, 0.025, 0.005), (0, -0.025, -0.005))  # the plate covers y < 0
    try:
        for inside in insets:
            rig = rig_module.Rig(edge, tool=tool)
            rig.m.opt.iterations = 10  # the flex scenes' cap
            flex_rig.apply_options(rig.m, options)
            rig.press_to_preload(0.0, y_m=-inside * 1e-3)
            samples = []
            for _ in range(50):
                mujoco.mj_step(rig.m, rig.d)
                samples.append(rig.pressures())
            pa = np.mean(samples, axis=0)
            dx, dy = (pa[0] + pa[3]) - (pa[1] + pa[2]), (pa[2] + pa[3]) - (pa[0] + pa[1])
            line = (
                f"{inside:.2f} mm inside: P-bar {pa.mean():.0f} Pa, |dP| "
                f"{np.hypot(dx, dy) / 2:.0f} Pa; the lip plane "
                f"{1e3 * (rig_module.TOOL_Z_M - rig.d.qpos[2]):.2f} mm below the top face"
            )
            if a.move_mm > 0:
                steps = int(round(a.move_mm * 1e-3 / 0.02 / rig.m.opt.timestep))
                hold = int(round(0.1 / rig.m.opt.timestep))
                start, cpu = rig.d.ctrl[0], time.process_time()
                for k in range(1, steps + 1):
                    rig.d.ctrl[0] = start + a.move_mm * 1e-3 * k / steps
                    mujoco.mj_step(rig.m, rig.d)
                mujoco.mj_step(rig.m, rig.d, hold)
                per_step = (time.process_time() - cpu) / (steps + hold)
                line += (
                    f"; moved {a.move_mm:g} mm: chambers "
                    f"{np.round(rig.pressures()).astype(int).tolist()} Pa, "
                    f"{per_step * 1e6:.0f} us CPU per step"
                )
            print(line, flush=True)
    finally:
        if variant:
            variant.cleanup()


if __name__ == "__main__":
    main()
