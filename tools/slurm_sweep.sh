#!/usr/bin/env bash
# Slurm batch script: the published grid (or any `ssc sweep` options) across nodes with MPI.
#   sbatch --nodes=4 --ntasks-per-node=16 tools/slurm_sweep.sh --out out/sweep_big --repeats 10
# One MPI rank per task, one worker thread per rank (SSC_THREADS to change); rank 0 hands out
# trials longest-first and writes OUT/sweep.csv as rows arrive. Re-submitting the same command
# resumes: rows already in the CSV are skipped (keep OUT on a shared file system).
#SBATCH --job-name=ssc-sweep
#SBATCH --time=01:00:00
#SBATCH --cpus-per-task=1
#SBATCH --output=ssc-sweep-%j.log
set -euo pipefail
ROOT="${SLURM_SUBMIT_DIR:-$(cd "$(dirname "$0")/.." && pwd)}"
SSC="${SSC:-$ROOT/build/bin/ssc}"
THREADS="${SSC_THREADS:-${SLURM_CPUS_PER_TASK:-1}}"
# srun starts the ranks where Slurm's PMI is wired to Open MPI; mpirun otherwise.
if [ -n "${SLURM_JOB_ID:-}" ] && srun --mpi=list 2>/dev/null | grep -q pmix; then
  exec srun --mpi=pmix "$SSC" sweep --threads "$THREADS" --no-progress --no-plot "$@"
fi
exec mpirun "$SSC" sweep --threads "$THREADS" --no-progress --no-plot "$@"
