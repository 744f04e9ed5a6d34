#!/usr/bin/env python3
"""Strong-scaling estimate for `ssc sweep` on P workers, on paper, from a finished sweep CSV.

Each trial's run time is taken as its simulated time (sim_time_s column) times the measured wall
cost per simulated second (--us-per-sim-s, from the sweep summary: busy trial-s / simulated s).
The trials are handed out as the job runner does: longest-first by the runner's estimate
(studies/sweep.cc: 5 s + lap / (4 dL)), each to the worker that frees up first (dynamic list
scheduling). The makespan adds a fixed start-up (--startup-s: MPI start + model load per rank)
and a round trip per trial (--latency-ms). Printed per P: makespan, speed-up over one worker,
efficiency, and the bounds W/P and the longest trial.

usage: scaling_estimate.py SWEEP.csv [--us-per-sim-s 21000] [--repeat-grid K] [--ranks 1,2,16,...]
"""

import argparse
import csv
import heapq
import math


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("csv")
    ap.add_argument(
        "--us-per-sim-s",
        type=float,
        required=True,
        help="wall microseconds of one worker per simulated second",
    )
    ap.add_argument("--ranks", default="1,2,16,32,64,128,256,512")
    ap.add_argument(
        "--repeat-grid",
        type=int,
        default=1,
        help="the grid K times over (K x the repeats), same trial-time distribution",
    )
    ap.add_argument("--startup-s", type=float, default=1.0)
    ap.add_argument("--latency-ms", type=float, default=1.0)
    ap.add_argument("--markdown", action="store_true")
    a = ap.parse_args()
    trials = []
    with open(a.csv, newline="") as f:
        for r in csv.DictReader(f):
            try:
                sim = float(r["sim_time_s"])
                step = float(r["step_mm"])
            except (KeyError, ValueError):
                continue
            est = 5.0 + 2 * math.pi * 35.0 / (4.0 * max(step, 0.1))
            trials.append((est, sim * a.us_per_sim_s * 1e-6))
    trials = trials * a.repeat_grid
    trials.sort(key=lambda t: -t[0])  # stable: the runner's handout order
    work = sum(t for _, t in trials)
    longest = max(t for _, t in trials)
    lat = a.latency_ms * 1e-3
    rows = []
    for p in [int(x) for x in a.ranks.split(",")]:
        free = [0.0] * p
        heapq.heapify(free)
        for _, t in trials:
            start = heapq.heappop(free)
            heapq.heappush(free, start + t + lat)
        makespan = max(free) + a.startup_s
        speedup = (work + a.startup_s) / makespan
        rows.append((p, makespan, speedup, speedup / p, work / p, longest))
    head = ["workers", "makespan s", "speed-up", "efficiency", "W/P s", "longest trial s"]
    print(
        f"{len(trials)} trials, total work W = {work:.1f} s on one worker, longest {longest:.2f} s "
        f"(W / longest = {work / longest:.0f}: no speed-up beyond that)"
    )

    def fmt(r):
        return [
            str(r[0]),
            f"{r[1]:.1f}",
            f"{r[2]:.1f}",
            f"{100 * r[3]:.0f} %",
            f"{r[4]:.2f}",
            f"{r[5]:.2f}",
        ]

    if a.markdown:
        print("| " + " | ".join(head) + " |")
        print("|" + " --- |" * len(head))
        for r in rows:
            print("| " + " | ".join(fmt(r)) + " |")
    else:
        print("  ".join(f"{h:>15}" for h in head))
        for r in rows:
            print("  ".join(f"{x:>15}" for x in fmt(r)))


if __name__ == "__main__":
    main()
