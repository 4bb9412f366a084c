#!/bin/bash
# One plate or section too large for one node, on a mesh distributed over
# the ranks (doc/parallel-runs.md, "Distributed meshes"; the parameter file
# sets 'Distributed = true', in 'Mesh' of plate_rod or 'Finite element' of
# rod_cross_section): one rank per core, each assembling its own
# cells and holding its rows and its share of MUMPS's factors. Memory per
# rank: its share of the factors plus the whole vectors of the drivers
# (doc/parallel-runs.md, the cost of distributed meshes; summary.json
# "factorization_memory" of a smaller run tells). Stopped at the time limit
# (SIGTERM 120 s ahead), every rank writes its checkpoint; submitting the
# script again with the same number of tasks goes on from there (another
# number of ranks is refused: the DoF numbering follows the ranks' parts).
# (Written for SLURM with Open MPI; not run on a cluster here: tests/slurm_scripts.sh
# runs it under a stand-in srun.)
#
# usage: sbatch doc/slurm-mesh.sh FILE.prm [application = plate_rod]
#SBATCH --job-name=cosmo-mesh
#SBATCH --nodes=4
#SBATCH --ntasks-per-node=32
#SBATCH --cpus-per-task=1
#SBATCH --mem=0
#SBATCH --time=08:00:00
#SBATCH --signal=TERM@120
#SBATCH --output=cosmo-%j.out
set -euo pipefail
prm=$1 app=${2:-plate_rod}
exe=${COSMO_BUILD:-build}/$app
# One core per rank: one assembly thread and one BLAS thread each.
export DEAL_II_NUM_THREADS=$SLURM_CPUS_PER_TASK OPENBLAS_NUM_THREADS=$SLURM_CPUS_PER_TASK
values=$("$exe" --print-parameters prm "$prm")
# A here-string, not a pipe: grep -q stops reading at its match, and under
# pipefail the writer's SIGPIPE would turn that match into a refusal.
if ! grep -Eq '^ *set Distributed *= *true' <<< "$values"; then
  echo "$prm: set 'Distributed = true' ('Mesh' of plate_rod, 'Finite element' of rod_cross_section) for a distributed mesh (or use doc/slurm-path.sh)" >&2
  exit 1
fi
out=$(sed -n 's/^ *set Output directory *= *\([^ #]*\).*/\1/p;T;q' <<< "$values")
if [ -f "$out/checkpoint.cosmo" ]; then
  srun "$exe" --resume "$out"
else
  srun "$exe" "$prm"
fi
