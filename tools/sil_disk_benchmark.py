#!/usr/bin/env python3
"""The lab's one-disk-revolution script under `ssc sil` beside `ssc trial` on the same settings.

    tools/sil_disk_benchmark.py --lab-repo CHECKOUT [--seeds 1-5] [--step-mm 7.5] [--ssc build/bin/ssc]

For each seed: runs CHECKOUT/src/SDL_ur_control_edgeFollowing_livePlot_oneDiskRevolution.py in
virtual time with its knob d_lat set to the step (--set d_lat=...; its P_ref 100 Pa and beta 2
are the script's own), reads the .mat it saves (success, edgeFollowing_history) and reports the
outcome, dr = mean distance of the history's TCP from the disk centre minus 35 mm, the CPU time
(user + sys of the run) and the wall time; then `ssc trial --scene SCENE` with the same P_ref,
beta, step and seed, once with the twin's own protocol (start 32 mm, approach 1.5 N) and once with
the script's (start_offset 31 mm, F_normalThres 1.1-1.2 N: --start-offset 31 --approach-force
1.15). Needs scipy (the lab's saver writes the .mat with it).
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


def seeds(text):
    a, _, b = text.partition("-")
    return list(range(int(a), int(b or a) + 1))


def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def sil_run(ssc, script, seed, step_m, scene, out):
    report = os.path.join(out, "report.json")
    cpu0, wall0 = child_cpu(), time.perf_counter()
    p = subprocess.run([ssc, "sil", "--out", out, "--scene", scene, "--seed", str(seed),
                        "--set", "d_lat=%r" % step_m, "--report", report, script],
                       cwd=out, capture_output=True, text=True)
    cpu, wall = child_cpu() - cpu0, time.perf_counter() - wall0
    with open(report) as f:
        summary = json.load(f)
    row = {"seed": seed, "cpu_s": cpu, "wall_s": wall, "sim_s": summary["sim_time_s"],
           "status": summary["status"], "problem": summary["problem"]}
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
    row["outcome"] = ("success" if row.get("success") else "failure I (off the edge)" if off_edge
                      else "failure II (grasp)" if grasp else "incomplete")
    return row


def trial_run(ssc, seed, step_mm, scene, out, extra=()):
    p = subprocess.run([ssc, "trial", "--scene", scene, "--pref", "100", "--beta", "2",
                        "--step", str(step_mm), "--seed", str(seed), "--no-plot", "--out", out]
                       + list(extra), capture_output=True, text=True)
    outcome = re.search(r"outcome: (\S+)", p.stdout)
    dr = re.search(r"dr = (-?[\d.]+) mm", p.stdout)
    return {"outcome": outcome.group(1) if outcome else "?",
            "dr_mm": float(dr.group(1)) if dr else float("nan")}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("--lab-repo", required=True, help="a checkout of the lab's edg_suction_cup")
    ap.add_argument("--seeds", default="1-5", type=seeds)
    ap.add_argument("--step-mm", type=float, default=7.5)
    ap.add_argument("--scene", default="disk_benchmark_gantry")
    ap.add_argument("--ssc", default=os.path.join(os.path.dirname(__file__), "..", "build", "bin", "ssc"))
    a = ap.parse_args()
    script = os.path.join(os.path.abspath(a.lab_repo), SCRIPT)
    print("| seed | ssc sil: outcome | iterations | dr (mm) | simulated (s) | CPU (s) | wall (s) "
          "| ssc trial (twin protocol): outcome | dr (mm) | ssc trial (script's protocol): "
          "outcome | dr (mm) |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    rows = []
    for seed in a.seeds:
        with tempfile.TemporaryDirectory(prefix="sil_bench_") as out:
            s = sil_run(os.path.abspath(a.ssc), script, seed, a.step_mm * 1e-3, a.scene, out)
            t = trial_run(os.path.abspath(a.ssc), seed, a.step_mm, a.scene, os.path.join(out, "t1"))
            u = trial_run(os.path.abspath(a.ssc), seed, a.step_mm, a.scene, os.path.join(out, "t2"),
                          ["--start-offset", "31", "--approach-force", "1.15"])
        rows.append((s, t, u))
        print("| %d | %s | %s | %.2f | %.1f | %.1f | %.1f | %s | %.2f | %s | %.2f |" % (
            seed, s["outcome"] if s["status"] == 0 else "error: " + s["problem"],
            s.get("iterations", "-"), s.get("dr_mm", float("nan")), s["sim_s"], s["cpu_s"],
            s["wall_s"], t["outcome"], t["dr_mm"], u["outcome"], u["dr_mm"]), flush=True)

    def stat(values):
        values = [v for v in values if np.isfinite(v)]
        if not values:
            return "-"
        sd = np.std(values, ddof=1) if len(values) > 1 else 0.0
        return "%.2f +- %.2f mm (%d)" % (np.mean(values), sd, len(values))
    print("\ndr over successful runs (mean +- SD, n): ssc sil %s; ssc trial twin protocol %s; "
          "script's protocol %s; ssc sil CPU per run %.1f-%.1f s" % (
              stat([s.get("dr_mm", np.nan) for s, _, _ in rows if s["outcome"] == "success"]),
              stat([t["dr_mm"] for _, t, _ in rows if t["outcome"] == "success"]),
              stat([u["dr_mm"] for _, _, u in rows if u["outcome"] == "success"]),
              min(s["cpu_s"] for s, _, _ in rows), max(s["cpu_s"] for s, _, _ in rows)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
