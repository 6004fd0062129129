#!/usr/bin/env bash
# `coolinggen sweep --emit slurm` on a real single-node Slurm (Debian slurm-wlm + munge): configures
# munge and Slurm for localhost in a scratch directory (own key, socket, ports, state; runs as the
# calling user), starts munged, slurmctld and slurmd, submits the study's job array (4 variants of the
# light study, at most 2 at a time), merges the results with `sweep --collect`, checks results.csv, and
# stops the daemons it started. Opt-in (ctest -L slurm after configuring with -DCOOLINGGEN_TEST_SLURM=ON).
# Usage: tests/study/slurm_test.sh PATH/TO/coolinggen
set -euo pipefail
bin=$(readlink -f "$1")
here=$(cd "$(dirname "$0")" && pwd)
for tool in munged mungekey slurmctld slurmd sbatch sinfo; do
  command -v "$tool" >/dev/null || { echo "slurm_test: $tool not found (apt-get install slurm-wlm munge)"; exit 1; }
done
work=$(mktemp -d /tmp/cg_slurm_XXXXXX)
pids=()
cleanup() {
  for f in "$work"/slurmd.pid "$work"/slurmctld.pid "$work"/munged.pid; do
    [ -s "$f" ] && kill "$(cat "$f")" 2>/dev/null || true
  done
  sleep 1
  rm -rf "$work"
}
trap cleanup EXIT
user=$(id -un)
node=$(hostname -s)
# Ports: a free-looking pair derived from the PID, away from Slurm's defaults (6817/6818).
base=$((20000 + ($$ % 20000) * 2))

mungekey -c -k "$work/munge.key" 2>/dev/null || dd if=/dev/urandom of="$work/munge.key" bs=1024 count=1 status=none
chmod 0400 "$work/munge.key"
mkdir -p "$work/munge" "$work/state" "$work/spool"
chmod 0700 "$work/munge"
munged --force --key-file="$work/munge.key" --socket="$work/munge/munge.socket" \
  --pid-file="$work/munged.pid" --log-file="$work/munged.log" --seed-file="$work/munge/seed"

cat > "$work/slurm.conf" <<CONF
ClusterName=cgtest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$base
SlurmdPort=$((base + 1))
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
AuthInfo=socket=$work/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/pgid
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
MpiDefault=none
ReturnToService=2
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
SlurmctldTimeout=30
SlurmdTimeout=30
NodeName=$node NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$work/slurm.conf"
slurmctld -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF"
for _ in $(seq 60); do
  state=$(sinfo -h -n "$node" -o %T 2>/dev/null || true)
  [ "$state" = "idle" ] && break
  sleep 0.5
done
[ "$state" = "idle" ] || { echo "slurm_test: node not idle (state '$state')"; tail -5 "$work"/slurm*.log; exit 1; }

# The study: 4 variants of the light base (rib position x wall thickness grid).
cat > "$work/study.json" <<STUDY
{"name": "slurm4", "base": "$here/light_base.json",
 "parameters": [{"path": "cooling.core.ribs[0].suction_chord", "values": [0.44, 0.48]},
                {"path": "cooling.core.wall_thickness", "values": [0.9, 1.1]}],
 "design": {"type": "grid"}}
STUDY
"$bin" sweep "$work/study.json" -o "$work/out" --emit slurm --jobs 2
grep -q '^#SBATCH --array=0-3%2$' "$work/out/study.sbatch"
sbatch --wait "$work/out/study.sbatch"
"$bin" sweep --collect "$work/out"

# Every variant ran as its own array task and was built.
n_logs=$(ls "$work"/out/slurm/*_{0,1,2,3}.out 2>/dev/null | wc -l)
[ "$n_logs" -eq 4 ] || { echo "slurm_test: $n_logs array task logs, expected 4"; exit 1; }
status_col=$(head -1 "$work/out/results.csv" | tr ',' '\n' | grep -n '^status$' | cut -d: -f1)
built=$(tail -n +2 "$work/out/results.csv" | cut -d, -f"$status_col" | grep -c '^built$' || true)
rows=$(tail -n +2 "$work/out/results.csv" | wc -l)
cat "$work/out/results.csv" | cut -d, -f1-8
[ "$rows" -eq 4 ] && [ "$built" -eq 4 ] || { echo "slurm_test: $built of $rows variants built, expected 4 of 4"; exit 1; }
echo "slurm_test: 4 array tasks built 4 variants"
