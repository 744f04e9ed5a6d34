#!/usr/bin/env python3
"""Where the flex skirt's F/T balance (runtime/tool_force.h) comes from: holds the tool site of
scenes/disk_benchmark_flex.xml at each depth into the disk (mm; negative = above it) through the
gantry's z servo for 1.2 s and prints the terms the balance sums (contact forces on the tool, the
pressure plugin's vacuum pull), what reaches the gantry's z axis (its passive load without gravity
compensation, its constraint force, its actuator), and the bellows spring.

  PYTHONPATH=build/python_pkg .venv/bin/python tools/flex_ft_probe.py 0.5 1.0 2.0
"""

import os
import sys

import mujoco
import numpy as np

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def ids(m, kind, *names):
    return [mujoco.mj_name2id(m, kind, n) for n in names]


def tool_loads(m, d, cup):
    """World z of the contact forces on the tool's skirt and on its geoms, N."""

    def on_tool(body):
        while body > 0 and body != cup:
            body = m.body_parentid[body]
        return body == cup

    skirt, geoms, f6 = 0.0, 0.0, np.zeros(6)
    for i in range(d.ncon):
        c = d.contact[i]
        sides = [
            s
            for s in range(2)
            if c.flex[s] >= 0 or (c.geom[s] >= 0 and on_tool(m.geom_bodyid[c.geom[s]]))
        ]
        if c.efc_address < 0 or len(sides) != 1:
            continue
        mujoco.mj_contactForce(m, d, i, f6)
        fz = (c.frame.reshape(3, 3).T @ f6[:3])[2] * (1 if sides[0] == 1 else -1)
        if c.flex[sides[0]] >= 0:
            skirt += fz
        else:
            geoms += fz
    return skirt, geoms


def main(depths_mm):
    mujoco.mj_loadPluginLibrary(os.path.join(ROOT, "build", "lib", "libssc_plugin.so"))
    m = mujoco.MjModel.from_xml_path(os.path.join(ROOT, "scenes", "disk_benchmark_flex.xml"))
    d = mujoco.MjData(m)
    mujoco.mj_resetDataKeyframe(m, d, 0)
    mujoco.mj_forward(m, d)
    ft_site, tool_site = ids(m, mujoco.mjtObj.mjOBJ_SITE, "ssc_ft_site", "ssc_tool_site")
    gantry_z, bellows = ids(m, mujoco.mjtObj.mjOBJ_JOINT, "gantry_z", "ssc_bellows")
    (disk,) = ids(m, mujoco.mjtObj.mjOBJ_GEOM, "disk")
    cup = m.site_bodyid[ft_site]
    for a in range(m.nu):
        d.ctrl[a] = d.qpos[m.jnt_qposadr[m.actuator_trnid[a, 0]]]
    top = d.geom_xpos[disk][2] + m.geom_size[disk][1]
    az = [a for a in range(m.nu) if m.actuator_trnid[a, 0] == gantry_z][0]
    dz, qb = m.jnt_dofadr[gantry_z], m.jnt_qposadr[bellows]
    state_end = m.plugin_stateadr[0] + m.plugin_statenum[0]
    axis = d.site_xmat[ft_site].reshape(3, 3)[:, 2]
    # The ceiling: the disk inside the skirt's pinned ring (the vertices on the chamber body).
    verts = m.flex_vertbodyid[m.flex_vertadr[0] : m.flex_vertadr[0] + m.flex_vertnum[0]]
    ring = d.flexvert_xpos[: len(verts)][verts == np.bincount(verts).argmax()]
    ceiling_m2 = np.pi * np.mean(np.hypot(*(ring[:, :2] - d.site_xpos[tool_site][:2]).T)) ** 2
    for depth in depths_mm:
        d.ctrl[az] += top - 1e-3 * depth - d.site_xpos[tool_site][2]
        mujoco.mj_step(m, d, 600)
        skirt, geoms = tool_loads(m, d, cup)
        vacuum = d.plugin_state[state_end - 3 : state_end]
        balance = -(skirt + geoms + vacuum[2]) * axis[2]
        print(
            f"depth {depth:+.2f} mm (site {1e3 * (top - d.site_xpos[tool_site][2]):+.3f} mm): "
            f"vacuum {np.mean(d.sensordata[:4]):.0f} Pa (on the ceiling "
            f"{np.mean(d.sensordata[:4]) * ceiling_m2:.2f} N); contacts z skirt {skirt:.3f} N, "
            f"geoms {geoms:.3f} N; vacuum pull z {vacuum[2]:.3f} N; balance {balance:.3f} N | "
            f"gantry z: passive {d.qfrc_passive[dz] - d.qfrc_gravcomp[dz]:.3f} N, "
            f"constraint {d.qfrc_constraint[dz]:.3f} N, actuator {d.qfrc_actuator[dz]:.3f} N | "
            f"bellows {1e3 * d.qpos[qb]:+.3f} mm, spring "
            f"{-m.jnt_stiffness[bellows] * (d.qpos[qb] - m.qpos_spring[qb]):.3f} N"
        )


if __name__ == "__main__":
    main([float(a) for a in sys.argv[1:]] or [0.5, 1.0, 2.0])
