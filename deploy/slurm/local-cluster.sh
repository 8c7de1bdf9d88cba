#!/usr/bin/env bash
# A single-node Slurm cluster on this machine for tests and demos: munged, slurmctld and slurmd
# bound to 127.0.0.1 only (CommunicationParameters=NoInAddrAny; every address in the config is
# loopback), no cgroups, no accounting database. Everything lives in one state directory; nothing
# under /etc is touched. Needs Debian's slurmctld, slurmd, slurm-client and munge (as root).
#
#   local-cluster.sh start DIR [CPUS]   writes DIR/slurm.conf, starts the daemons, waits for the node
#   local-cluster.sh stop DIR           stops the daemons started from DIR
#   local-cluster.sh env DIR            prints the environment clients need (SLURM_CONF=...)
#
# Ports: CYCLOPT_SLURM_PORT (slurmctld, default 16817) and the next one (slurmd).
set -euo pipefail

cmd=${1:?usage: local-cluster.sh start|stop|env DIR [CPUS]}
dir=${2:?usage: local-cluster.sh start|stop|env DIR [CPUS]}
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
port=${CYCLOPT_SLURM_PORT:-16817}

stop_pidfile() {
  local f=$1
  [ -s "$f" ] || return 0
  local pid; pid=$(cat "$f")
  if kill -0 "$pid" 2>/dev/null; then
    kill "$pid" 2>/dev/null || true
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
  fi
  rm -f "$f"
}

case "$cmd" in
  env)
    echo "SLURM_CONF=$dir/slurm.conf"
    ;;
  stop)
    stop_pidfile "$dir/slurmd.pid"
    stop_pidfile "$dir/slurmctld.pid"
    stop_pidfile "$dir/munge/munged.pid"
    ;;
  start)
    cpus=${3:-$(nproc)}
    for p in munged slurmctld slurmd sbatch; do
      command -v "$p" >/dev/null || [ -x "/usr/sbin/$p" ] || { echo "local-cluster: $p not installed (apt-get install slurmctld slurmd slurm-client munge)" >&2; exit 3; }
    done
    mkdir -p "$dir/munge" "$dir/state" "$dir/spool" "$dir/spool/d"
    chmod 700 "$dir/munge"
    [ -s "$dir/munge/munge.key" ] || { dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 status=none; chmod 400 "$dir/munge/munge.key"; }
    mem=$(awk '/MemTotal/ {printf "%d", $2 / 1024 * 0.9}' /proc/meminfo)
    cat > "$dir/slurm.conf" <<CONF
# Written by deploy/slurm/local-cluster.sh: one node, loopback only.
ClusterName=cyclopt-local
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
CommunicationParameters=NoInAddrAny
AuthType=auth/munge
AuthInfo=socket=$dir/munge/munge.socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
ReturnToService=2
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool/d
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
SlurmctldTimeout=30
SlurmdTimeout=30
MessageTimeout=10
InactiveLimit=0
KillWait=2
MinJobAge=300
NodeName=localhost NodeAddr=127.0.0.1 NodeHostname=localhost CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=local Nodes=localhost Default=YES MaxTime=INFINITE State=UP OverSubscribe=NO
CONF
    munged --force --socket="$dir/munge/munge.socket" --key-file="$dir/munge/munge.key" \
      --pid-file="$dir/munge/munged.pid" --log-file="$dir/munge/munged.log" --seed-file="$dir/munge/munged.seed"
    export SLURM_CONF="$dir/slurm.conf"
    /usr/sbin/slurmctld -c -f "$dir/slurm.conf"
    /usr/sbin/slurmd -f "$dir/slurm.conf" -N localhost
    for _ in $(seq 100); do
      state=$(sinfo -h -n localhost -o %T 2>/dev/null || true)
      case "$state" in idle*|mixed*|alloc*) echo "local-cluster: up ($dir, node localhost $state, $cpus CPUs)"; exit 0 ;; esac
      sleep 0.2
    done
    echo "local-cluster: node did not come up; logs in $dir" >&2
    tail -5 "$dir/slurmctld.log" "$dir/slurmd.log" >&2 || true
    exit 1
    ;;
  *) echo "usage: local-cluster.sh start|stop|env DIR [CPUS]" >&2; exit 1 ;;
esac
