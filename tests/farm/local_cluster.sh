#!/usr/bin/env bash
# Starts (or stops) a single-node Slurm cluster on this machine for the farm tests: munged, slurmctld and
# slurmd on localhost, with a slurm.conf and all state in a scratch folder.
#   local_cluster.sh start DIR   prints "SLURM_CONF=DIR/slurm.conf" once the node takes jobs; exit 77: cannot
#   local_cluster.sh stop DIR    stops the daemons started from DIR (whatever state they are in)
# Needs root (the daemons run as root, munged as user munge) and Debian's slurm-wlm and munge packages.
set -u
action=${1:?start|stop}; dir=${2:?scratch folder}

stop() {
  for pidfile in "$dir"/slurmd.pid "$dir"/slurmctld.pid; do
    [ -f "$pidfile" ] && kill "$(cat "$pidfile")" 2>/dev/null
  done
  sleep 0.5
  for pidfile in "$dir"/slurmd.pid "$dir"/slurmctld.pid; do
    [ -f "$pidfile" ] && kill -9 "$(cat "$pidfile")" 2>/dev/null
    rm -f "$pidfile"
  done
  if [ -f "$dir/munged.pid" ]; then kill "$(cat "$dir/munged.pid")" 2>/dev/null; rm -f "$dir/munged.pid"; fi
  return 0
}

skip() { echo "SKIP: $*" >&2; exit 77; }

if [ "$action" = stop ]; then stop; exit 0; fi

[ "$(id -u)" -eq 0 ] || skip "the Slurm daemons need root to start"
for tool in slurmctld slurmd munged sbatch sinfo; do command -v "$tool" >/dev/null || skip "$tool is not installed (apt-get install slurm-wlm munge)"; done

mkdir -p "$dir"/state "$dir"/spool "$dir"/log "$dir"/munge "$dir"/munge_socket
chmod 755 "$dir"
host=$(hostname -s)
cpus=$(nproc)
memory=$(( $(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 / 2 ))

# munge: a key of this cluster's own, a socket in the scratch folder.
key="$dir/munge/munge.key"
[ -f "$key" ] || head -c 1024 /dev/urandom > "$key"
chown -R munge:munge "$dir/munge" "$dir/munge_socket"; chmod 700 "$dir/munge"; chmod 400 "$key"
chmod 755 "$dir/munge_socket"  # clients (sbatch, the daemons) must reach the socket
socket="$dir/munge_socket/munge.socket"
runuser -u munge -- munged --key-file="$key" --socket="$socket" --pid-file="$dir/munge/munged.pid" \
  --log-file="$dir/munge/munged.log" --seed-file="$dir/munge/munged.seed" || skip "munged did not start"
cp "$dir/munge/munged.pid" "$dir/munged.pid"

port=$(( 16817 + RANDOM % 1000 ))
cat > "$dir/slurm.conf" <<CONF
ClusterName=softbody-test
SlurmctldHost=$host
SlurmctldPort=$port
SlurmdPort=$(( port + 1000 ))
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
SchedulerType=sched/backfill
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
SlurmctldTimeout=30
SlurmdTimeout=30
InactiveLimit=0
KillWait=5
MinJobAge=300
NodeName=$host CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP OverSubscribe=YES
CONF
export SLURM_CONF="$dir/slurm.conf"
slurmctld -f "$SLURM_CONF" || { stop; skip "slurmctld did not start (see $dir/log/slurmctld.log)"; }
slurmd -f "$SLURM_CONF" || { stop; skip "slurmd did not start (see $dir/log/slurmd.log)"; }
for _ in $(seq 1 60); do
  if sinfo -h -o %T 2>/dev/null | grep -qE '^(idle|mixed|allocated)'; then
    echo "SLURM_CONF=$SLURM_CONF"
    exit 0
  fi
  sleep 0.5
done
stop
skip "the node did not become idle within 30 s (see $dir/log/)"
