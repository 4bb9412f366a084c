#!/bin/bash
# One large path of cosmo (a plate at small h/R, a fine section) on a SLURM
# cluster (doc/parallel-runs.md, "One path on several ranks"): rank 0
# assembles and drives the path on all the cores of its node; the other
# ranks, one per node, take part in its MUMPS factorizations and solves and
# hold their share of the factors. Give rank 0's node the memory of the
# mesh, the matrix and the vectors (about 1.7 GB per million unknowns) and
# every node its share of the factors (doc/parallel-runs.md, the cost
# model; summary.json "factorization_memory" of a smaller run tells).
# Stopped at the time limit (SIGTERM 120 s ahead), the run writes its
# checkpoint; submitting the script again goes on from there.
# (Written for SLURM with Open MPI; not run on a cluster here: tests/slurm_scripts.sh
# runs it under a stand-in srun.)
#
# usage: sbatch doc/slurm-path.sh FILE.prm [application = plate_rod]
#SBATCH --job-name=cosmo-path
#SBATCH --nodes=4
#SBATCH --ntasks-per-node=1
#SBATCH --cpus-per-task=32
#SBATCH --mem=0
#SBATCH --time=08:00:00
#SBATCH --signal=TERM@120
#SBATCH --output=cosmo-%j.out
set -euo pipefail
prm=$1 app=${2:-plate_rod}
exe=${COSMO_BUILD:-build}/$app
# Rank 0's assembly threads, and each rank's BLAS threads for its fronts.
export DEAL_II_NUM_THREADS=$SLURM_CPUS_PER_TASK OPENBLAS_NUM_THREADS=$SLURM_CPUS_PER_TASK
# Read whole, then searched: a reader that stops early would, under
# pipefail, turn the writer's SIGPIPE into a failure.
values=$("$exe" --print-parameters prm "$prm")
out=$(sed -n 's/^ *set Output directory *= *\([^ #]*\).*/\1/p;T;q' <<< "$values")
if [ -f "$out/checkpoint.cosmo" ]; then
  srun "$exe" --resume "$out"
else
  srun "$exe" "$prm"
fi
