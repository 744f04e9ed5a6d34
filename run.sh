#!/usr/bin/env bash
# Set everything up on a fresh machine and run the main job.
set -euo pipefail
cd "$(dirname "$0")"
tools/setup.sh
mkdir -p out
# One disk trial with the published best controller (P_ref 100 Pa, beta 2, dL 7.5 mm) on
# the UR-10: prints the outcome and metrics, writes out/trial/{trial.csv,summary.json,trajectory.png}.
build/bin/ssc trial --scene disk_benchmark --pref 100 --beta 2 --step 7.5 --seed 1 --out out/trial "$@"
