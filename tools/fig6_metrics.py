#!/usr/bin/env python3
"""The published Fig. 6 targets read off a run's trials (ssc validate's trials.csv or a sweep.csv).

Means over the successful trials at dL 5 mm: dr at beta 1.5 and P_ref 40 / 100 / 200 Pa, sigma_r at
beta 1.5 / 3.5 and s_c at beta 1.5 / 2.5 / 3.5 (P_ref 100 Pa), beside the published values, with
how many trials each mean is over and its standard error.

  tools/fig6_metrics.py out/validate/trials.csv [more.csv ...]
"""
import csv
import math
import sys

# (label, metric column, beta, P_ref, published); the reference's calibration table.
TARGETS = [
    ("dr beta 1.5 P 40", "dr_mm", 1.5, 40, -0.7),
    ("dr beta 1.5 P 100", "dr_mm", 1.5, 100, -2.5),
    ("dr beta 1.5 P 200", "dr_mm", 1.5, 200, -3.2),
    ("sigma_r beta 1.5", "sigma_r_mm", 1.5, 100, 1.36),
    ("sigma_r beta 3.5", "sigma_r_mm", 3.5, 100, 1.89),
    ("s_c beta 1.5", "s_c", 1.5, 100, 0.11),
    ("s_c beta 2.5", "s_c", 2.5, 100, 0.21),
    ("s_c beta 3.5", "s_c", 3.5, 100, 0.31),
]


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for path in sys.argv[1:]:
        try:
            with open(path, newline="") as f:
                rows = list(csv.DictReader(f))
        except OSError as e:
            sys.exit(f"fig6_metrics: {path}: {e.strerror}")
        print(path)
        print(f"  {'target':20s} {'twin':>8s} {'(se)':>7s} {'n':>3s} {'published':>9s}")
        for label, col, beta, pref, pub in TARGETS:
            try:
                vals = [float(r[col]) for r in rows
                        if float(r["step_mm"]) == 5.0 and float(r["beta"]) == beta
                        and float(r["pref_pa"]) == pref and r["outcome"] == "success"]
            except (KeyError, ValueError) as e:
                sys.exit(f"fig6_metrics: {path}: not a trials file ({e})")
            if not vals:
                print(f"  {label:20s} {'-':>8s} {'':>7s} {0:3d} {pub:9.2f}")
                continue
            m = sum(vals) / len(vals)
            se = (math.sqrt(sum((v - m) ** 2 for v in vals) / (len(vals) - 1) / len(vals))
                  if len(vals) > 1 else float("nan"))
            print(f"  {label:20s} {m:8.2f} ({se:5.2f}) {len(vals):3d} {pub:9.2f}")


if __name__ == "__main__":
    main()
