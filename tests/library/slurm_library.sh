#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The library on a real Slurm cluster (docs/library.md, "Testing on a real Slurm"): brings up a single-node
# cluster (slurm_cluster.sh), runs tests/library/three_materials.toml (3 materials x 4 orders) locally and on
# Slurm, cancels one array task, re-submits, and compares every output byte for byte with the local run.
# Exit 77 (CTest SKIP_RETURN_CODE) only when not root: starting slurmctld, slurmd and munged needs root.
# Usage: slurm_library.sh ADMITGEN SOURCE_DIR WORK_DIR
set -euo pipefail
admitgen=$1 source=$2 work=$3
if [ "$(id -u)" -ne 0 ]; then
  echo "SKIPPED: the Slurm library test brings up slurmctld, slurmd and munged, which needs root (run ctest as root;"
  echo "         .ci/install-deps --tests installs slurm-wlm and munge)"
  exit 77
fi
for tool in slurmctld slurmd munged sbatch squeue scancel scontrol; do
  command -v "$tool" >/dev/null || { echo "FAIL: $tool not found: run .ci/install-deps --tests (slurm-wlm, munge)"; exit 1; }
done
rm -rf "$work" && mkdir -p "$work"
cluster=$work/cluster
"$source/tests/library/slurm_cluster.sh" up "$cluster" >/dev/null
trap '"$source/tests/library/slurm_cluster.sh" down "$cluster"' EXIT
export SLURM_CONF=$cluster/slurm.conf
manifest=$source/tests/library/three_materials.toml

# Waits until job $1 has left the queue (at most 180 s); prints its final state.
wait_job() {
  for _ in $(seq 360); do
    if [ -z "$(squeue -h -j "$1" 2>/dev/null)" ]; then
      scontrol show job "$1" 2>/dev/null | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | head -1
      return 0
    fi
    sleep 0.5
  done
  echo "FAIL: job $1 still queued after 180 s" >&2; squeue >&2; exit 1
}

# The local run: the reference.
"$admitgen" library plan -q "$manifest" --out "$work/local"
"$admitgen" library run -q -j 2 "$work/local"
"$admitgen" library merge -q "$work/local"

# Slurm, first submission held, so that one task is cancelled before it can run.
"$admitgen" library plan -q "$manifest" --out "$work/slurm"
merge1=$("$admitgen" library slurm -q --sbatch=--hold "$work/slurm")
array1=$(sed -n 's/^array //p' "$work/slurm/slurm/submitted-1.txt")
[ "$(wc -l <"$work/slurm/slurm/units-1.list")" -eq 12 ] || { echo "FAIL: first submission should hold 12 units"; exit 1; }
scancel "${array1}_5"
# While the first submission is queued, a second one is refused (its held tasks would run units twice).
if "$admitgen" library slurm -q "$work/slurm" >"$work/refused.txt" 2>&1; then
  echo "FAIL: a second submission was accepted while the first was queued"; exit 1
fi
grep -q "still queued or running" "$work/refused.txt" || { echo "FAIL: refusal message"; cat "$work/refused.txt"; exit 1; }
scontrol release "$array1"
state=$(wait_job "$array1")
echo "array job $array1 (task 5 cancelled) left the queue"
# The merge can never start (one task did not succeed): Slurm keeps it pending; cancel it.
sleep 1
scancel "$merge1" || true
wait_job "$merge1" >/dev/null
units=$(find "$work/slurm/units" -name '*.unit' | wc -l)
[ "$units" -eq 11 ] || { echo "FAIL: expected 11 unit results after cancelling one task, found $units"; exit 1; }
[ ! -e "$work/slurm/walls.h" ] || { echo "FAIL: the merge ran although a task was cancelled"; exit 1; }

# Re-submission: exactly the missing unit, then the merge.
merge2=$("$admitgen" library slurm -q "$work/slurm")
[ "$(cat "$work/slurm/slurm/units-2.list")" = "$(sed -n 6p "$work/slurm/slurm/units-1.list")" ] ||
  { echo "FAIL: the re-submission should hold exactly the cancelled unit"; cat "$work/slurm/slurm/units-2.list"; exit 1; }
state=$(wait_job "$merge2")
[ "$state" = COMPLETED ] || { echo "FAIL: merge job $merge2 ended $state"; cat "$work"/slurm/slurm/logs/merge-*.out; exit 1; }

# Nothing lost or duplicated: every unit ran exactly once over both submissions.
ran=$(cat "$work"/slurm/slurm/logs/unit-*.out | grep -c ' done: ' || true)
[ "$ran" -eq 12 ] || { echo "FAIL: $ran unit runs over both submissions, expected 12"; exit 1; }
dups=$(cat "$work"/slurm/slurm/logs/unit-*.out | sed -n 's/ done: .*//p' | sort | uniq -d)
[ -z "$dups" ] || { echo "FAIL: units run twice: $dups"; exit 1; }

# Byte for byte equal to the local run.
status=0
for f in walls.h bands.json bands.csv report.html; do
  cmp "$work/local/$f" "$work/slurm/$f" || status=1
done
for m in reference glass_beads mpp; do
  for f in fit.json "$m.h" bands.json posterior.json predictive.csv report.html; do
    cmp "$work/local/materials/$m/$f" "$work/slurm/materials/$m/$f" || status=1
  done
done
[ $status -eq 0 ] || { echo "FAIL: the Slurm run differs from the local run"; exit 1; }
echo "Slurm library: 12 units (one cancelled, re-submitted alone), merged by Slurm; every output equals the local run"
