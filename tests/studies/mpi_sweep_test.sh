#!/usr/bin/env bash
# ssc sweep under `mpirun -np 2 --oversubscribe`: rank 0 writes the same CSV (byte for byte) as a
# threaded run of the same grid and seed, and a re-run resumes the rows a lost run left out.
# Also the runner alone with results on every rank (2 ranks x 2 threads).
# Usage: mpi_sweep_test.sh SSC MPIEXEC MPI_FOUND RUNNER_CHECK. Exit 77 (CTest: skipped) without MPI.
set -euo pipefail
SSC="$1"; MPIEXEC="$2"; MPI_FOUND="$3"; RUNNER_CHECK="$4"
if ! [[ "$MPI_FOUND" =~ ^(TRUE|ON|1|YES)$ ]] || [ ! -x "$MPIEXEC" ]; then
  echo "SKIP: built without MPI (install libopenmpi-dev openmpi-bin and reconfigure)"
  exit 77
fi
# Open MPI refuses root unless told; CI containers run as root.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
DIR="$(mktemp -d)"
trap 'rm -rf "$DIR"' EXIT
"$MPIEXEC" -np 2 --oversubscribe "$RUNNER_CHECK" || { echo "FAIL: results on all ranks"; exit 1; }
GRID=(--pref 70,150 --beta 1,3 --step 5,7.5 --repeats 1 --seed 11 --timeout 6
      --no-plot --no-progress)

"$SSC" sweep "${GRID[@]}" --threads 2 --out "$DIR/threads" > "$DIR/threads.log"
"$MPIEXEC" -np 2 --oversubscribe "$SSC" sweep "${GRID[@]}" --threads 1 --out "$DIR/mpi" \
  > "$DIR/mpi.log"
cat "$DIR/mpi.log"
grep -q "on 2 rank(s) x 1 threads" "$DIR/mpi.log" || { echo "FAIL: not run on 2 ranks"; exit 1; }
rows=$(($(wc -l < "$DIR/mpi/sweep.csv") - 1))
[ "$rows" -eq 8 ] || { echo "FAIL: $rows rows, want 8"; exit 1; }
cmp "$DIR/threads/sweep.csv" "$DIR/mpi/sweep.csv" || { echo "FAIL: MPI rows differ from threaded rows"; exit 1; }

# Resume: drop three rows (as if their ranks died before reporting them) and run again.
head -n 6 "$DIR/mpi/sweep.csv" > "$DIR/cut.csv" && mv "$DIR/cut.csv" "$DIR/mpi/sweep.csv"
"$MPIEXEC" -np 2 --oversubscribe "$SSC" sweep "${GRID[@]}" --threads 1 --out "$DIR/mpi" \
  > "$DIR/resume.log"
grep -q "(5 already in" "$DIR/resume.log" || { echo "FAIL: resume did not skip 5 rows"; cat "$DIR/resume.log"; exit 1; }
diff <(sort "$DIR/threads/sweep.csv") <(sort "$DIR/mpi/sweep.csv") \
  || { echo "FAIL: resumed CSV differs"; exit 1; }
echo "mpi sweep: 2 ranks give the threaded rows; resume completes the CSV"
