#!/bin/bash
# A constitutive table (or a study) of cosmo over MPI ranks on a SLURM
# cluster (doc/parallel-runs.md): one rank per core, one thread per rank.
# At the time limit SLURM sends SIGTERM (120 s ahead, --signal), every
# rank writes its checkpoint, and submitting the script again goes on from
# there: with the same or another number of ranks.
#
# usage: sbatch doc/slurm-table.sh FILE.prm [application = strip]
#SBATCH --job-name=cosmo-table
#SBATCH --nodes=2
#SBATCH --ntasks-per-node=32
#SBATCH --cpus-per-task=1
#SBATCH --mem-per-cpu=1G
#SBATCH --time=04:00:00
#SBATCH --signal=TERM@120
#SBATCH --output=cosmo-%j.out
set -euo pipefail
prm=$1 app=${2:-strip}
# The build of this repository, made on the cluster (scripts/setup.sh or
# cmake -DCMAKE_BUILD_TYPE=Release); its MPI must be the cluster's.
exe=${COSMO_BUILD:-build}/$app
export DEAL_II_NUM_THREADS=$SLURM_CPUS_PER_TASK OPENBLAS_NUM_THREADS=1
# The output directory the parameter file names: a checkpoint there means
# an earlier job of this run was stopped.
# Read whole, then searched: a reader that stops early would, under
# pipefail, turn the writer's SIGPIPE into a failure.
values=$("$exe" --print-parameters prm "$prm")
out=$(sed -n 's/^ *set Output directory *= *\([^ #]*\).*/\1/p;T;q' <<< "$values")
if [ -f "$out/checkpoint.cosmo" ]; then
  srun "$exe" --resume "$out"
else
  srun "$exe" "$prm"
fi
