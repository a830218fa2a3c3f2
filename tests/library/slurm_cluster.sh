#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A single-node Slurm cluster on this machine, from the Debian packages slurm-wlm and munge, for the library
# test (docs/library.md, "Testing on a real Slurm"). Root only. Everything lives under one directory:
#   slurm_cluster.sh up DIR     writes DIR/slurm.conf, starts munged (unless one runs), slurmctld and slurmd;
#                               waits until the node is idle; prints the SLURM_CONF to export
#   slurm_cluster.sh down DIR   stops the daemons it started (by their pid files)
# No cgroups: process tracking by /proc (proctrack/linuxproc), no task binding (task/none).
set -euo pipefail
cmd=$1 dir=$(realpath -m "$2")
case "$cmd" in
up)
  mkdir -p "$dir/state" "$dir/spool" "$dir/log"
  cpus=$(nproc)
  mem=$(awk '/MemTotal/ {print int($2 / 1024 / 2)}' /proc/meminfo)
  cat >"$dir/slurm.conf" <<CONF
ClusterName=admitgen-test
SlurmctldHost=localhost
SlurmctldPort=${ADMITGEN_SLURMCTLD_PORT:-16817}
SlurmdPort=${ADMITGEN_SLURMD_PORT:-16818}
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
SchedulerType=sched/backfill
SchedulerParameters=sched_interval=1
MinJobAge=300
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=test Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
  echo "# (no cgroups)" >"$dir/cgroup.conf"
  if ! pgrep -x munged >/dev/null; then
    mkdir -p /run/munge && chown munge:munge /run/munge
    runuser -u munge -- /usr/sbin/munged
    touch "$dir/munged.started"
  fi
  export SLURM_CONF=$dir/slurm.conf
  /usr/sbin/slurmctld -f "$dir/slurm.conf"
  /usr/sbin/slurmd -f "$dir/slurm.conf" -N localhost
  for _ in $(seq 60); do
    state=$(sinfo -h -N -o %t 2>/dev/null || true)
    case "$state" in idle*) echo "SLURM_CONF=$dir/slurm.conf"; exit 0 ;; esac
    sleep 1
  done
  echo "slurm_cluster.sh: the node did not become idle in 60 s; logs in $dir/log" >&2
  exit 1
  ;;
down)
  pids=()
  for d in slurmd slurmctld; do
    if [ -f "$dir/$d.pid" ]; then pids+=("$(cat "$dir/$d.pid")"); kill "${pids[-1]}" 2>/dev/null || true; fi
  done
  if [ -f "$dir/munged.started" ] && [ -f /run/munge/munged.pid ]; then
    pids+=("$(cat /run/munge/munged.pid)"); kill "${pids[-1]}" 2>/dev/null || true
  fi
  # Wait (at most 20 s) until they have exited, so that a next cluster can take the ports.
  for _ in $(seq 40); do
    alive=0
    for p in "${pids[@]}"; do kill -0 "$p" 2>/dev/null && alive=1; done
    [ $alive -eq 0 ] && exit 0
    sleep 0.5
  done
  echo "slurm_cluster.sh: daemons still running after 20 s: ${pids[*]}" >&2
  exit 1
  ;;
*) echo "usage: slurm_cluster.sh up|down DIR" >&2; exit 2 ;;
esac
