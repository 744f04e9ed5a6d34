#!/usr/bin/env bash
# The shared approach (runtime/approach_cache.h) changes no row: small sweeps with and without
# it write the same CSV byte for byte, with the default settings and with the robot effects on
# (lip shear through the move, chamber spread and drift drawn from each seed), and the shared run
# did start trials from a shared approach.
# Usage: shared_approach_test.sh SSC
set -euo pipefail
SSC="$1"
DIR="$(mktemp -d)"
trap 'rm -rf "$DIR"' EXIT
COMMON=(--seed 11 --timeout 4 --threads 2 --no-plot --no-progress)
run_pair() {  # name, sweep options...
  local name="$1"; shift
  "$SSC" sweep "$@" "${COMMON[@]}" --out "$DIR/$name-shared" > "$DIR/$name-shared.log"
  "$SSC" sweep "$@" "${COMMON[@]}" --no-shared-approach --out "$DIR/$name-alone" \
    > "$DIR/$name-alone.log"
  cat "$DIR/$name-shared.log"
  local resumed
  resumed=$(sed -n 's/^approach: shared: [0-9]* simulated, \([0-9]*\) trials started from one.*/\1/p' \
    "$DIR/$name-shared.log")
  [ -n "$resumed" ] && [ "$resumed" -gt 0 ] \
    || { echo "FAIL ($name): no trial started from a shared approach"; exit 1; }
  grep -q "approach: not shared" "$DIR/$name-alone.log" \
    || { echo "FAIL ($name): --no-shared-approach still shared"; exit 1; }
  local rows
  rows=$(($(wc -l < "$DIR/$name-alone/sweep.csv") - 1))
  [ "$rows" -eq 8 ] || { echo "FAIL ($name): $rows rows, want 8"; exit 1; }
  cmp "$DIR/$name-shared/sweep.csv" "$DIR/$name-alone/sweep.csv" \
    || { echo "FAIL ($name): rows differ with the shared approach"; \
         diff "$DIR/$name-shared/sweep.csv" "$DIR/$name-alone/sweep.csv" | head; exit 1; }
}
run_pair default --pref 40,150 --beta 1,3 --step 2.5,7.5 --repeats 1
run_pair effects --pref 70,200 --beta 2,4 --step 5 --repeats 2 \
  --effects slip_mm=1,tilt_decades=0.08,drift_pa=1,gain_spread=0.1 --period 0.25 --smoothing 0.056
echo "shared approach: the same rows as every trial simulating its own approach"
