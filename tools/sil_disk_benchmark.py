#!/usr/bin/env python3
"""The lab's one-disk-revolution script under `ssc sil` beside `ssc trial` on the same settings.

    tools/sil_disk_benchmark.py --lab-repo CHECKOUT [--seeds 1-5] [--step-mm 7.5]
                                [--pause-cost S] [--ssc build/bin/ssc]

For each seed: runs CHECKOUT/src/SDL_ur_control_edgeFollowing_livePlot_oneDiskRevolution.py in
virtual time with its knob d_lat set to the step (--set d_lat=...; its P_ref 100 Pa and beta 2
are the script's own), reads the .mat it saves (success, edgeFollowing_history) and reports the
outcome, dr = mean distance of the history's TCP from the disk centre minus 35 mm, the CPU time
(user + sys of the run) and the wall time; then `ssc trial --scene SCENE` with the same P_ref,
beta, step and seed, three ways:
  - twin: the twin's own protocol and loop (start 32 mm, approach 1.5 N, period 0.15 s, the
    default robot effects);
  - script: the script's protocol (start_offset 31 mm, F_normalThres 1.1-1.2 N:
    --start-offset 31 --approach-force 1.15), the twin's loop;
  - same loop: the script's protocol and the script's loop timing on the SIL's robot. The loop
    reads the pressures 10 ms after its top (rospy.sleep), redraws (plt.pause: 10 ms + the pause
    cost C), reads the pose and sends servoL, waits out the 8 ms RTDE period and sleeps 10 ms:
    period 0.038 s + C, and the step is added to a pose read 0.01 s + C after the pressures
    (--period, --effects pose_delay_s); the SIL's arm lands where it servos, so the step landing
    errors and the tare residual are off (step_error_relative=0, offset_spread_pa=0).
Needs scipy (the lab's saver writes the .mat with it).
"""

import argparse
import json
import os
import re
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np

SCRIPT = "src/SDL_ur_control_edgeFollowing_livePlot_oneDiskRevolution.py"
DISK_CENTRE_BASE_LINK = (-0.630, 0.097)  # where ssc sil puts the lab's disk (docs/sil.md)
DISK_RADIUS_M = 0.035
sys.path.insert(
    0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build", "python_pkg")
)
from ssc_twin._core import EXIT_CODES  # noqa: E402  the one exit-code table (common/exit_codes.h)

# ssc sil ran the script: the trial succeeded, or it did not (docs/reliability.md).
SIL_RAN = (EXIT_CODES["ok"], EXIT_CODES["trial_failed"])


def seeds(text):
    a, _, b = text.partition("-")
    return list(range(int(a), int(b or a) + 1))


def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


# The script's loop without the pause cost (see the docstring): the sleeps, plt.pause's argument
# and the RTDE period; and from the pressure read to the pose read: plt.pause's argument. s.
LOOP_SLEEPS_S = 0.01 + 0.01 + 1.0 / 125 + 0.01
PRESSURE_TO_POSE_SLEEPS_S = 0.01


def scene_args(scene):
    """--scene SCENE, or nothing for the default scene of both commands."""
    return ["--scene", scene] if scene else []


def sil_run(ssc, script, seed, step_m, scene, out, pause_cost):
    report = os.path.join(out, "report.json")
    cpu0, wall0 = child_cpu(), time.perf_counter()
    p = subprocess.run(
        [ssc, "sil", "--out", out]
        + scene_args(scene)
        + [
            "--seed",
            str(seed),
            "--pause-cost",
            str(pause_cost),
            "--set",
            "d_lat=%r" % step_m,
            "--report",
            report,
            script,
        ],
        cwd=out,
        capture_output=True,
        text=True,
    )
    cpu, wall = child_cpu() - cpu0, time.perf_counter() - wall0
    with open(report) as f:
        summary = json.load(f)
    row = {
        "seed": seed,
        "cpu_s": cpu,
        "wall_s": wall,
        "sim_s": summary["sim_time_s"],
        "status": summary["status"],
        "problem": summary["problem"],
    }
    off_edge = "went off edge" in p.stdout
    grasp = "Suction engage succeeded" in p.stdout
    if summary["mat_files"]:
        from scipy.io import loadmat

        m = loadmat(summary["mat_files"][0])
        h = m["edgeFollowing_history"]
        xy = np.array([[float(np.ravel(r[1])[0]), float(np.ravel(r[2])[0])] for r in h])
        r = np.hypot(xy[:, 0] - DISK_CENTRE_BASE_LINK[0], xy[:, 1] - DISK_CENTRE_BASE_LINK[1])
        row["iterations"] = len(h)
        row["dr_mm"] = (r.mean() - DISK_RADIUS_M) * 1e3
        row["success"] = int(np.ravel(m["success"])[0])
    # The script's own flags first (its success and its printed failures); the SIL's verdict,
    # decided as `ssc trial` decides, for a run the script left undecided.
    verdict = summary.get("verdict", {}).get("outcome", "incomplete")
    row["outcome"] = (
        "success"
        if row.get("success")
        else "failure I (off the edge)"
        if off_edge
        else "failure II (grasp)"
        if grasp
        else verdict
    )
    return row


def trial_run(ssc, seed, step_mm, scene, out, extra=()):
    p = subprocess.run(
        [ssc, "trial"]
        + scene_args(scene)
        + [
            "--pref",
            "100",
            "--beta",
            "2",
            "--step",
            str(step_mm),
            "--seed",
            str(seed),
            "--no-plot",
            "--out",
            out,
        ]
        + list(extra),
        capture_output=True,
        text=True,
    )
    outcome = re.search(r"outcome: (\S+)", p.stdout)
    dr = re.search(r"dr = (-?[\d.]+) mm", p.stdout)
    return {
        "outcome": outcome.group(1) if outcome else "?",
        "dr_mm": float(dr.group(1)) if dr else float("nan"),
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("--lab-repo", required=True, help="a checkout of the lab's edg_suction_cup")
    ap.add_argument("--seeds", default="1-5", type=seeds)
    ap.add_argument("--step-mm", type=float, default=7.5)
    ap.add_argument(
        "--scene", default=None, help="scene of both runs (default: the rig's default scene)"
    )
    ap.add_argument(
        "--pause-cost",
        type=float,
        default=None,
        help="ssc sil's --pause-cost (default: ssc sil's own)",
    )
    ap.add_argument(
        "--ssc", default=os.path.join(os.path.dirname(__file__), "..", "build", "bin", "ssc")
    )
    a = ap.parse_args()
    script = os.path.join(os.path.abspath(a.lab_repo), SCRIPT)
    ssc = os.path.abspath(a.ssc)
    if a.pause_cost is None:
        h = subprocess.run([ssc, "sil", "--help"], capture_output=True, text=True).stdout
        a.pause_cost = float(re.search(r"default ([\d.]+), measured", " ".join(h.split())).group(1))
    protocol = ["--start-offset", "31", "--approach-force", "1.15"]
    same_loop = protocol + [
        "--period",
        "%.4f" % (LOOP_SLEEPS_S + a.pause_cost),
        "--effects",
        "pose_delay_s=%.4f,step_error_relative=0,offset_spread_pa=0"
        % (PRESSURE_TO_POSE_SLEEPS_S + a.pause_cost),
    ]
    print("ssc sil --pause-cost %g; same loop: ssc trial %s" % (a.pause_cost, " ".join(same_loop)))
    print(
        "| seed | ssc sil: outcome | iterations | dr (mm) | simulated (s) | CPU (s) | wall (s) "
        "| ssc trial, twin: outcome | dr (mm) | script's protocol: outcome | dr (mm) "
        "| same loop: outcome | dr (mm) |"
    )
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    rows = []
    for seed in a.seeds:
        with tempfile.TemporaryDirectory(prefix="sil_bench_") as out:
            s = sil_run(ssc, script, seed, a.step_mm * 1e-3, a.scene, out, a.pause_cost)
            t = trial_run(ssc, seed, a.step_mm, a.scene, os.path.join(out, "t1"))
            u = trial_run(ssc, seed, a.step_mm, a.scene, os.path.join(out, "t2"), protocol)
            v = trial_run(ssc, seed, a.step_mm, a.scene, os.path.join(out, "t3"), same_loop)
        rows.append((s, t, u, v))
        print(
            "| %d | %s | %s | %.2f | %.1f | %.1f | %.1f | %s | %.2f | %s | %.2f | %s | %.2f |"
            % (
                seed,
                s["outcome"] if s["status"] in SIL_RAN else "error: " + s["problem"],
                s.get("iterations", "-"),
                s.get("dr_mm", float("nan")),
                s["sim_s"],
                s["cpu_s"],
                s["wall_s"],
                t["outcome"],
                t["dr_mm"],
                u["outcome"],
                u["dr_mm"],
                v["outcome"],
                v["dr_mm"],
            ),
            flush=True,
        )

    def stat(values):
        values = [v for v in values if np.isfinite(v)]
        if not values:
            return "-"
        sd = np.std(values, ddof=1) if len(values) > 1 else 0.0
        return "%.2f +- %.2f mm (%d)" % (np.mean(values), sd, len(values))

    print(
        "\ndr over successful runs (mean +- SD, n): ssc sil %s; ssc trial twin %s; "
        "script's protocol %s; same loop %s; ssc sil CPU per run %.1f-%.1f s"
        % (
            stat([r[0].get("dr_mm", np.nan) for r in rows if r[0]["outcome"] == "success"]),
            stat([r[1]["dr_mm"] for r in rows if r[1]["outcome"] == "success"]),
            stat([r[2]["dr_mm"] for r in rows if r[2]["outcome"] == "success"]),
            stat([r[3]["dr_mm"] for r in rows if r[3]["outcome"] == "success"]),
            min(r[0]["cpu_s"] for r in rows),
            max(r[0]["cpu_s"] for r in rows),
        )
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
