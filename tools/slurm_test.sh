#!/usr/bin/env bash
# make test-slurm: a real Slurm run on this machine (doc/sweep.md). Installs slurm-wlm and
# munge when missing (root only), starts a one-node cluster (minimal slurm.conf, no cgroups,
# state in build/slurm), submits the S2 mesh series (input/sweeps/s2_mesh) as a job array
# with pecplas-sweep, waits, collects the head settlements, and stops the daemons it started.
set -euo pipefail
cd "$(dirname "$0")/.."
export PYTHONPATH=$PWD/tools${PYTHONPATH:+:$PYTHONPATH}  # pecplas_py (doc/tools.md)
ROOT=$PWD
FPM=${FPM:-fpm}
work=$ROOT/build/slurm
mkdir -p "$work"/{state,spool,log}

if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
  if [[ $(id -u) != 0 ]]; then
    echo "test-slurm: needs slurm-wlm and munge: apt-get install slurm-wlm munge (as root)" >&2
    exit 1
  fi
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q slurm-wlm munge >/dev/null
fi

pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; }
trap cleanup EXIT

# munge: a key if there is none, the daemon if it is not running
if [[ ! -s /etc/munge/munge.key ]]; then
  (command -v mungekey >/dev/null && mungekey -c -f) || \
    dd if=/dev/urandom of=/etc/munge/munge.key bs=1024 count=1 status=none
  chown munge:munge /etc/munge/munge.key 2>/dev/null || true
  chmod 400 /etc/munge/munge.key
fi
mkdir -p /run/munge && chown munge:munge /run/munge 2>/dev/null || true
if ! munge -n >/dev/null 2>&1; then
  runuser -u munge -- munged --force 2>/dev/null || munged --force
  sleep 1
fi

host=$(hostname -s)
cpus=$(nproc)
mem=$(awk '/MemTotal/ {print int($2/1024*0.8)}' /proc/meminfo)
conf=$work/slurm.conf
cat >"$conf" <<CONF
ClusterName=pecplas-test
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
ReturnToService=2
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
NodeName=$host CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$conf
slurmctld -D -f "$conf" >"$work/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$conf" >"$work/log/slurmd.out" 2>&1 &
pids+=($!)
for _ in $(seq 30); do
  sinfo -h -o %T 2>/dev/null | grep -qE 'idle|mixed' && break
  sleep 1
done
sinfo

# the program: $PECPLAS_BIN, else fpm's release build (make test-slurm builds it first)
exe=${PECPLAS_BIN:-$("$FPM" run --profile release --target pecplas --runner echo 2>/dev/null | tail -n 1)}
exe=$(realpath "$exe")
out=$work/s2_mesh
rm -rf "$out"
python3 -m pecplas_py.programs.pecplas_sweep make input/sweeps/s2_mesh/template.inp \
  input/sweeps/s2_mesh/table.csv -o "$out"
jobline=$(python3 -m pecplas_py.programs.pecplas_sweep slurm "$out" --partition test --time 00:30:00 \
  --pecplas "$exe" --submit)
echo "$jobline"
job=$(grep -oE 'submitted job [0-9]+' <<<"$jobline" | awk '{print $3}')
t0=$(date +%s)
while squeue -h -j "$job" 2>/dev/null | grep -q .; do
  (( $(date +%s) - t0 < 1200 )) || { echo "test-slurm: job $job still queued after 20 min" >&2; exit 1; }
  sleep 2
done
sacct -j "$job" 2>/dev/null || true
ls "$out"/slurm-*.out
python3 -m pecplas_py.programs.pecplas_sweep collect "$out" -q settlement=disp:0,0:y@head=1
cat "$out/collected.csv"
echo "test-slurm: job $job: $(grep -c completed "$out/collected.csv") of 3 array tasks completed in $(( $(date +%s) - t0 )) s"
