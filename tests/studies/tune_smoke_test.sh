#!/usr/bin/env bash
# ssc tune, tiny: two evaluations of one seed each beside the published law, the chart drawn;
# tune.csv holds the reference and both evaluations, the reference first, each with its trial
# count, and at least one point on the Pareto front.
# Usage: tune_smoke_test.sh SSC
set -euo pipefail
SSC="$1"
DIR="$(mktemp -d)"
trap 'rm -rf "$DIR"' EXIT
"$SSC" tune --controller fast --search step_max_mm=7:9 --evals 2 --seeds 1 --timeout 4 \
  --threads 2 --out "$DIR/tune" | tee "$DIR/log"
CSV="$DIR/tune/tune.csv"
[ "$(wc -l < "$CSV")" -eq 4 ] || { echo "FAIL: want a header and 3 rows"; cat "$CSV"; exit 1; }
head -1 "$CSV" | grep -q '^label,controller,step_max_mm,trials,successes,' \
  || { echo "FAIL: header"; exit 1; }
sed -n 2p "$CSV" | grep -q '^published,' || { echo "FAIL: the reference first"; exit 1; }
[ "$(grep -c '^eval [12],' "$CSV")" -eq 2 ] || { echo "FAIL: two evaluations"; exit 1; }
# pareto is the column before outcome (the quoted controller holds commas: count from the end)
awk -F, 'NR > 1 && $(NF - 1) == 1 { n++ } END { exit !(n >= 1) }' "$CSV" \
  || { echo "FAIL: no Pareto point"; exit 1; }
[ -d "$DIR/tune/evals/eval_1" ] || { echo "FAIL: evals/eval_1 missing"; exit 1; }
if grep -q "wrote .*pareto.png" "$DIR/log"; then [ -s "$DIR/tune/pareto.png" ]; fi
echo PASS
