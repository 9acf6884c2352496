#!/usr/bin/env bash
# Spreads a grainscope sweep over a Slurm job array of TASKS tasks, then
# merges the shards in a job that starts when every task has succeeded:
#
#   examples/slurm/submit.sh TASKS OUT PRESET --vary NAME=lin|log:FROM:TO:N [--vary …] [--scalars a,b]
#
# OUT/merged/sweep.csv is then byte for byte the table of the same sweep run
# on one machine. GRAINSCOPE names the binary (default: grainscope on PATH);
# extra sbatch options go in SBATCH_OPTIONS (e.g. "--partition=short").
# Prints the merge job's id.
set -euo pipefail
if [ $# -lt 4 ]; then
    sed -n '2,10p' "$0" >&2
    exit 2
fi
tasks=$1
out=$2
shift 2
here="$(cd "$(dirname "$0")" && pwd)"
bin=${GRAINSCOPE:-$(command -v grainscope)}
mkdir -p "$out"
# shellcheck disable=SC2086
array=$(sbatch --parsable ${SBATCH_OPTIONS:-} --array="0-$((tasks - 1))" --chdir="$out" \
    --export=ALL,GRAINSCOPE="$bin" "$here/sweep-array.sh" "$out" "$@")
shards=()
for ((i = 0; i < tasks; i++)); do shards+=("$out/shard-$i"); done
# shellcheck disable=SC2086
sbatch --parsable ${SBATCH_OPTIONS:-} --dependency="afterok:$array" --job-name=grainscope-merge \
    --chdir="$out" --output=slurm-merge-%j.out \
    --wrap="$(printf '%q ' "$bin" sweep-merge "${shards[@]}" --out "$out/merged")"
