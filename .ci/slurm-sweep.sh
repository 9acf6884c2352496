#!/usr/bin/env bash
# A sweep of the batch model spread over a Slurm job array on a one-node
# cluster started here (munge, slurmctld and slurmd on 127.0.0.1), merged
# by a dependent job, and compared byte for byte with the same sweep run
# locally. The daemons are stopped at the end, whatever happens.
#
#   .ci/slurm-sweep.sh BINARY POINTS_PER_AXIS
set -euo pipefail
bin=$(realpath "$1")
n=${2:-100}
root="$(cd "$(dirname "$0")/.." && pwd)"

if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq slurm-wlm munge >/dev/null
fi

work=$(mktemp -d /tmp/grainscope-slurm.XXXXXX)
chmod 755 "$work"
host=$(hostname -s)
cpus=$(nproc)
mkdir -p "$work/spool" "$work/state" /run/munge
conf="$work/slurm.conf"
cat >"$conf" <<CONF
ClusterName=grainscope-ci
SlurmctldHost=$host(127.0.0.1)
AuthType=auth/munge
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
ReturnToService=2
MpiDefault=none
JobCompType=jobcomp/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmdSpoolDir=$work/spool
StateSaveLocation=$work/state
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=ci Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$conf

stop() {
    [ -f "$work/slurmd.pid" ] && kill "$(cat "$work/slurmd.pid")" 2>/dev/null || true
    [ -f "$work/slurmctld.pid" ] && kill "$(cat "$work/slurmctld.pid")" 2>/dev/null || true
    [ -n "${munge_pid:-}" ] && kill "$munge_pid" 2>/dev/null || true
    sleep 1
}
trap stop EXIT

if [ ! -s /etc/munge/munge.key ]; then
    mungekey --create --keyfile=/etc/munge/munge.key 2>/dev/null || dd if=/dev/urandom of=/etc/munge/munge.key bs=1024 count=1 2>/dev/null
fi
chown munge:munge /etc/munge/munge.key /run/munge 2>/dev/null || true
chmod 400 /etc/munge/munge.key
socket="$work/munge.socket"
munged --force --socket="$socket" --pid-file="$work/munged.pid" --log-file="$work/munged.log" --seed-file="$work/munge.seed"
munge_pid=$(cat "$work/munged.pid")
# Slurm's plugins find munge by its default socket: point it here.
mkdir -p /run/munge
ln -sf "$socket" /run/munge/munge.socket.2
slurmctld -f "$conf"
slurmd -f "$conf"
for _ in $(seq 60); do
    sinfo -h -o %T 2>/dev/null | grep -qE '^(idle|mixed|allocated)' && break
    sleep 1
done
sinfo || { cat "$work"/slurm*.log >&2; exit 1; }

# Waits (at most 30 minutes) until job $1 has left the queue.
wait_for() {
    for _ in $(seq 1800); do
        [ -z "$(squeue -h -j "$1" -o %T 2>/dev/null || true)" ] && return
        sleep 1
    done
}

# n² points of the batch model (10⁴ in CI): the largest midplane dust-to-gas
# ratio and the converted fraction against the disk's metallicity and turbulence.
vary=(--vary "metallicity=log:0.005:0.05:$n" --vary "alpha=log:1e-4:1e-2:$n")
args=(batch-fig-5-4 --set batches=20 "${vary[@]}" --scalars loading_top_tenth,converted)
start=$(date +%s)
merge=$(GRAINSCOPE="$bin" "$root/examples/slurm/submit.sh" 4 "$work/cluster" "${args[@]}")
echo "submitted an array of 4 tasks and merge job $merge"
wait_for "$merge"
echo "cluster run: $(( $(date +%s) - start )) s"
sacct_state=$(scontrol show job "$merge" 2>/dev/null | grep -o 'JobState=[A-Z]*' || true)
if [ ! -s "$work/cluster/merged/sweep.csv" ]; then
    echo "the merge job left no table ($sacct_state)" >&2
    tail -n 20 "$work"/cluster/slurm-*.out "$work"/slurm*.log >&2 || true
    exit 1
fi
start=$(date +%s)
"$bin" sweep "${args[@]}" --out "$work/local" >/dev/null 2>&1
echo "local run: $(( $(date +%s) - start )) s"
cmp "$work/local/sweep.csv" "$work/cluster/merged/sweep.csv"
echo "the merged table of $(( $(wc -l <"$work/local/sweep.csv") - 1 )) points equals the local run's byte for byte"

# Sobol' indices of the sticking velocity of equal ice spheres over four
# parameters (N = 256, 1 536 runs), as an array of 4 tasks whose merge job
# analyses the merged runs: the indices equal those of the same command run here.
sens=(sensitivity restitution-ice --method sobol --samples 256 --output v_stick --log-output
    --vary surface_energy=log:0.1:1 --vary radius_1=log:3e-7:3e-5 --vary t_vis=log:1e-13:1e-10
    --vary z0=log:1e-10:1e-9 --tie radius_2=radius_1)
start=$(date +%s)
merge=$(GRAINSCOPE="$bin" "$root/examples/slurm/submit.sh" 4 "$work/sobol" "${sens[@]}")
wait_for "$merge"
echo "cluster run of the Sobol' design: $(( $(date +%s) - start )) s"
if [ ! -s "$work/sobol/merged/indices.csv" ]; then
    echo "the merge job left no indices" >&2
    tail -n 20 "$work"/sobol/slurm-*.out >&2 || true
    exit 1
fi
start=$(date +%s)
"$bin" "${sens[@]}" --out "$work/sobol-local" >/dev/null 2>&1
echo "local run: $(( $(date +%s) - start )) s"
cmp "$work/sobol-local/sweep.csv" "$work/sobol/merged/sweep.csv"
cmp "$work/sobol-local/indices.csv" "$work/sobol/merged/indices.csv"
echo "the merged design's runs and Sobol' indices equal the local run's byte for byte:"
cat "$work/sobol/merged/indices.csv"
