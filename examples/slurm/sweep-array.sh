#!/usr/bin/env bash
# One task of a sweep (or, with GRAINSCOPE_COMMAND=sensitivity, of a
# sensitivity design) spread over a Slurm job array: each task computes its
# deterministic slice of the points (`--shard auto` reads the task's number
# and the array's size from Slurm) into a folder of its own.
#
#   sbatch --array=0-N-1 examples/slurm/sweep-array.sh OUT PRESET --vary … [--set …] [--scalars …]
#
# submit.sh submits the array and a merge job that waits for it.
#SBATCH --job-name=grainscope-sweep
#SBATCH --ntasks=1
#SBATCH --output=slurm-%A_%a.out
set -euo pipefail
out=$1
shift
bin=${GRAINSCOPE:-grainscope}
exec "$bin" "${GRAINSCOPE_COMMAND:-sweep}" "$@" --shard auto --out "$out/shard-${SLURM_ARRAY_TASK_ID}"
