#!/usr/bin/env bash
# Spreads a grainscope sweep over a Slurm job array of TASKS tasks, then
# merges the shards in a job that starts when every task has succeeded:
#
#   examples/slurm/submit.sh TASKS OUT PRESET --vary NAME=lin|log:FROM:TO:N [--vary …] [--scalars a,b]
#   examples/slurm/submit.sh TASKS OUT sensitivity PRESET --method morris|sobol --vary NAME=log:FROM:TO … --output KEY
#
# OUT/merged/sweep.csv is then byte for byte the table of the same sweep run
# on one machine; for a sensitivity design the merge job also analyses it
# (OUT/merged/indices.csv, sensitivity.json and the figure), as
# `grainscope sensitivity` run on one machine writes them. GRAINSCOPE names the binary (default: grainscope on PATH);
# extra sbatch options go in SBATCH_OPTIONS (e.g. "--partition=short").
# Prints the merge job's id.
set -euo pipefail
if [ $# -lt 4 ]; then
    sed -n '2,14p' "$0" >&2
    exit 2
fi
tasks=$1
out=$2
shift 2
command=sweep
if [ "$1" = sensitivity ]; then
    command=sensitivity
    shift
fi
here="$(cd "$(dirname "$0")" && pwd)"
bin=${GRAINSCOPE:-$(command -v grainscope)}
mkdir -p "$out"
# shellcheck disable=SC2086
array=$(sbatch --parsable ${SBATCH_OPTIONS:-} --array="0-$((tasks - 1))" --chdir="$out" \
    --export=ALL,GRAINSCOPE="$bin",GRAINSCOPE_COMMAND="$command" "$here/sweep-array.sh" "$out" "$@")
shards=()
for ((i = 0; i < tasks; i++)); do shards+=("$out/shard-$i"); done
merge=$(printf '%q ' "$bin" sweep-merge "${shards[@]}" --out "$out/merged")
if [ "$command" = sensitivity ]; then
    # The design's analysis reads the merged runs; --log-output as the runs were asked.
    log=""
    for a in "$@"; do [ "$a" = --log-output ] && log=--log-output; done
    merge="$merge && $(printf '%q ' "$bin" sensitivity --analyse "$out/merged" $log)"
fi
# shellcheck disable=SC2086
sbatch --parsable ${SBATCH_OPTIONS:-} --dependency="afterok:$array" --job-name=grainscope-merge \
    --chdir="$out" --output=slurm-merge-%j.out \
    --wrap="$merge"
