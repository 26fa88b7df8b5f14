#!/usr/bin/env bash
# A real single-node Slurm cluster on this machine (issue 17): starts munged, slurmctld and slurmd
# (Debian's munge and slurm-wlm) with their configuration, state and sockets in a temporary
# folder and their own ports, submits a sharded stability run with scripts/slurm/submit.sh (a
# job array of 4 shards and the merge job after it, --dependency=afterok) and a small passing run
# with scripts/slurm/passing.sh (3 shards), waits for the merges and compares the reports with
# the unsharded runs' bytes. Stops the daemons it started.
#
# The daemons need root (slurmd runs jobs as their users): without root, or without the
# packages, the test is skipped (exit 77). By hand, as root: tests/shard/slurm_test.sh build/app/foresight
#
# Usage: slurm_test.sh FORESIGHT_BINARY
set -euo pipefail
foresight=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
skip() { echo "slurm_test: skipped: $1"; exit 77; }
[ "$(id -u)" -eq 0 ] || skip "starting slurmd needs root (run this script as root by hand)"
for tool in munged mungekey slurmctld slurmd sbatch squeue sacct; do
  command -v "$tool" >/dev/null || [ -x "/usr/sbin/$tool" ] || skip "$tool missing (scripts/setup.sh installs munge and slurm-wlm)"
done
export PATH=$PATH:/usr/sbin

work=$(mktemp -d /tmp/foresight-slurm.XXXXXX)
chmod 755 "$work"
pids=()
stop() {
  for pid_file in "$work"/slurmd.pid "$work"/slurmctld.pid "$work"/munged.pid; do
    [ -s "$pid_file" ] && kill "$(cat "$pid_file")" 2>/dev/null || true
  done
  sleep 1
  rm -rf "$work"
}
trap stop EXIT

# Munge: a key of our own, a socket in the work folder.
mkdir -m 700 "$work/munge"
mungekey --create --force --keyfile "$work/munge/munge.key"
munged --force --key-file "$work/munge/munge.key" --socket "$work/munge/munge.sock" \
  --pid-file "$work/munged.pid" --log-file "$work/munged.log" --seed-file "$work/munge/seed"

# Ports above the usual 6817/6818, so that a cluster already on the machine is not touched.
node=$(hostname -s)
cpus=$(nproc)
mkdir -p "$work/state" "$work/spool"
cat >"$work/slurm.conf" <<CONF
ClusterName=foresight-test
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=16817
SlurmdPort=16818
AuthType=auth/munge
AuthInfo=socket=$work/munge/munge.sock
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
MpiDefault=none
ReturnToService=2
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
PlugStackConfig=$work/plugstack.conf
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
: >"$work/plugstack.conf"
export SLURM_CONF=$work/slurm.conf
slurmctld -f "$SLURM_CONF" -i
slurmd -f "$SLURM_CONF"

# Wait (at most 60 s) until the node is idle.
for _ in $(seq 60); do
  sinfo -h -o %T 2>/dev/null | grep -q idle && break
  sleep 1
done
sinfo -h -o %T | grep -q idle || { echo "slurm_test: the node did not come up"; tail -5 "$work"/slurm*.log; exit 1; }

# The unsharded run, then the same as 4 shards of 1 CPU each and the merge through Slurm.
run=(experiment stability --quick --repeats 10)
"$foresight" "${run[@]}" --threads 1 --out "$work/whole" >/dev/null
cd "$work"
FORESIGHT=$foresight SBATCH_ARGS="--cpus-per-task=1" \
  bash "$root/scripts/slurm/submit.sh" 4 "$work/sharded" "${run[@]}" | tee "$work/submit.txt"
merge_job=$(sed -n 's/.*merge job \([0-9]*\).*/\1/p' "$work/submit.txt")
# Wait (at most 300 s) until the merge job has left the queue.
for _ in $(seq 300); do
  squeue -h -j "$merge_job" 2>/dev/null | grep -q . || break
  sleep 1
done
if [ ! -f "$work/sharded/report/stability.json" ]; then
  echo "slurm_test: the merge job wrote no report"
  tail -n 3 "$work"/sharded/slurm-*.out "$work"/slurm*.log 2>/dev/null
  exit 1
fi
bash "$here/same_report.sh" "$work/whole" "$work/sharded/report"

# The passing experiment through its own script (scripts/slurm/passing.sh): 3 shards of both teams
# against DG and the merge job.
passing=(--scenarios 1,4 --trials 4)
"$foresight" experiment passing --config dg --team both "${passing[@]}" --threads 1 \
  --out "$work/passing-whole" >/dev/null
FORESIGHT=$foresight SBATCH_ARGS="--cpus-per-task=1" CONFIGS=dg \
  bash "$root/scripts/slurm/passing.sh" 3 "$work/passing" "${passing[@]}" | tee "$work/passing.txt"
merge_job=$(sed -n 's/.*merge job \([0-9]*\).*/\1/p' "$work/passing.txt")
for _ in $(seq 300); do
  squeue -h -j "$merge_job" 2>/dev/null | grep -q . || break
  sleep 1
done
if [ ! -f "$work/passing/dg/report/passing_comparison.json" ]; then
  echo "slurm_test: the passing merge job wrote no report"
  tail -n 3 "$work"/passing/dg/slurm-*.out 2>/dev/null
  exit 1
fi
bash "$here/same_report.sh" "$work/passing-whole" "$work/passing/dg/report"
echo "slurm_test: stability (4 array tasks) and passing (3) with their merge jobs on a one-node Slurm cluster: the unsharded bytes"
