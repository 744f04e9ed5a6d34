#!/usr/bin/env python3
"""How the flex skirt's M+K solve fares against <option iterations> (docs/flex_cost.md, "The
skirt's M+K solve and MuJoCo's inertia warning"): the corner push of tools/corner_push.py (cup
pressed 1 mm 2.5 mm inside an edge, pushed 7 mm toward a 270-degree corner's wall) run once per
cap. Printed per cap: the steps on which the solve stopped short of MuJoCo's tolerance (MuJoCo
counts them as inertia warnings), the fewest constraint rows on such a step (the constraint solver
finishes the solve only where there are rows), the constraint solver's iterations, and how far
the end state lies from the run at the last cap given.

Usage (from the repository, after a build):
  SSC_PLUGIN_LIB=build/lib/libssc_plugin.so .venv/bin/python tools/flex_solve_check.py \\
      --iterations 10,12,15,20,100
"""

import argparse


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument(
        "--iterations",
        default="10,12,20,100",
        help="caps to run, comma-separated; the last is the reference",
    )
    a = p.parse_args()
    try:
        caps = [int(v) for v in a.iterations.split(",")]
    except ValueError:
        p.error(f"--iterations {a.iterations!r}: expected whole numbers, comma-separated")
    if not all(1 <= v <= 10000 for v in caps):
        p.error("--iterations: each in [1, 10000]")
    import numpy as np

    import flex_rig

    mujoco, rig_module = flex_rig.load(p)
    inertia = mujoco.mjtWarning.mjWARN_INERTIA
    runs = []
    for cap in caps:
        rig = rig_module.Rig(rig_module.concave_corner())
        rig.m.opt.iterations = cap
        steps = {"n": 0, "short": 0, "rows": [], "solver": []}
        step = mujoco.mj_step

        def counted(m, d, nstep=1):
            for _ in range(nstep):
                before = d.warning[inertia].number
                step(m, d)
                steps["n"] += 1
                steps["solver"].append(d.solver_niter[0])
                if d.warning[inertia].number > before:
                    steps["short"] += 1
                    steps["rows"].append(d.nefc)

        mujoco.mj_step = counted
        try:
            rig.press(8e-3, 1.0, y_m=-2.5e-3)
            rig.push_x(1e-3)
        finally:
            mujoco.mj_step = step
        runs.append((cap, steps, rig.d.qpos.copy(), rig.pressures()))
    reference = runs[-1][2]
    for cap, s, qpos, p_pa in runs:
        solver = np.array(s["solver"])
        print(
            f"iterations {cap:4d}: solve stopped short on {s['short']} of {s['n']} steps "
            f"(fewest constraint rows then {min(s['rows']) if s['rows'] else '-'}); constraint "
            f"solver {solver.mean():.2f} iterations a step, at the cap on "
            f"{np.mean(solver >= cap):.1%}; end state from iterations {caps[-1]}: "
            f"{1e6 * np.abs(qpos - reference).max():.4g} um, chambers "
            f"{np.round(p_pa).astype(int).tolist()} Pa",
            flush=True,
        )


if __name__ == "__main__":
    main()
