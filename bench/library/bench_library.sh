#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Material-library benchmark (docs/library.md, "Cost"): a synthetic library of 20 materials (Miki layers of
# different flow resistivity and thickness over an air gap, 200 points, noise 0.01), orders Q0-1 x S0-2
# (6 units each, 120 units), run
#   1. locally: admitgen library run -j 2 (the baseline), and
#   2. through Slurm on this machine (root only: a single-node cluster from tests/library/slurm_cluster.sh,
#      2 CPUs as the local run): one array task per unit, then the merge job;
# and prints the Slurm overhead per unit and the projected wall time on N nodes from the measured unit times.
# Usage: bench_library.sh ADMITGEN SOURCE_DIR WORK_DIR [LIVE]
set -euo pipefail
admitgen=$1 source=$2 work=$3 live=${4:-50}
rm -rf "$work" && mkdir -p "$work/data"
now() { date +%s.%N; }

manifest=$work/bench.toml
printf 'name = "bench"\n[defaults]\nqmax = 1\nsmax = 2\nlive = %s\nseed = 1\nfs = [48000]\nformat = "f32"\n' "$live" >"$manifest"
i=0
for sigma in 5000 10000 20000 40000 80000; do
  for d in 20 40 60 80; do
    i=$((i + 1))
    "$admitgen" synth -q --material "miki(sigma=$sigma, d=${d}mm) + air(d=20mm)" --noise 0.01 --seed $i \
      --out "$work/data/m$i.csv"
    printf '[[material]]\nname = "m%02d"\ndata = "data/m%d.csv"\n' $i $i >>"$manifest"
  done
done

"$admitgen" library plan -q "$manifest" --out "$work/local"
t0=$(now)
"$admitgen" library run -q -j 2 "$work/local"
t1=$(now)
"$admitgen" library merge -q -j 2 "$work/local"
t2=$(now)
local_units=$(echo "$t1 - $t0" | bc -l)
local_merge=$(echo "$t2 - $t1" | bc -l)
n=$(find "$work/local/units" -name '*.unit' | wc -l)

# Unit run times as measured inside each unit (the "seconds" line of its file).
python3 - "$work/local/units" >"$work/unit_seconds.txt" <<'PY'
import pathlib, sys
for p in sorted(pathlib.Path(sys.argv[1]).rglob("*.unit")):
    for line in p.read_text().splitlines():
        if line.startswith("seconds "):
            print(float.fromhex(line.split()[1]))
            break
PY
read -r sum_units max_unit < <(awk '{s += $1; if ($1 > m) m = $1} END {printf "%.3f %.3f\n", s, m}' "$work/unit_seconds.txt")

echo "library of 20 materials x 6 orders = $n units, $live live points"
printf "local, 2 threads:  units %.2f s wall (sum of unit times %.2f s, longest unit %.3f s), merge %.2f s\n" \
  "$local_units" "$sum_units" "$max_unit" "$local_merge"

slurm_units=""
if [ "$(id -u)" -eq 0 ] && command -v slurmctld >/dev/null; then
  cluster=$work/cluster
  "$source/tests/library/slurm_cluster.sh" up "$cluster" >/dev/null
  trap '"$source/tests/library/slurm_cluster.sh" down "$cluster"' EXIT
  export SLURM_CONF=$cluster/slurm.conf
  "$admitgen" library plan -q "$manifest" --out "$work/slurm"
  t0=$(now)
  merge=$("$admitgen" library slurm -q --merge-threads 2 "$work/slurm")
  array=$(sed -n 's/^array //p' "$work/slurm/slurm/submitted-1.txt")
  while [ -n "$(squeue -h -j "$array" 2>/dev/null)" ]; do sleep 0.2; done
  t1=$(now)
  while [ -n "$(squeue -h -j "$merge" 2>/dev/null)" ]; do sleep 0.2; done
  t2=$(now)
  slurm_units=$(echo "$t1 - $t0" | bc -l)
  same=identical
  for f in bench.h bands.json bands.csv; do cmp -s "$work/local/$f" "$work/slurm/$f" || same=DIFFERENT; done
  printf "Slurm, 1 node x 2 CPUs: array %.2f s wall, merge job %.2f s; outputs %s to the local run\n" \
    "$slurm_units" "$(echo "$t2 - $t1" | bc -l)" "$same"
  overhead=$(echo "($slurm_units - $local_units) * 2 / $n" | bc -l)
  printf "Slurm overhead per unit (2 slots): %.3f s (array wall / local wall = %.2f)\n" "$overhead" \
    "$(echo "$slurm_units / $local_units" | bc -l)"
else
  overhead=0.5
  echo "Slurm part skipped (needs root and slurm-wlm); projection below assumes $overhead s overhead per unit"
fi

# Projection: N nodes of 2 CPUs; units spread evenly, each costing its run time plus the per-unit overhead,
# bounded below by the longest unit; the merge runs once afterwards.
echo "projected wall time (units + merge) on N nodes of 2 CPUs, from the measured unit times:"
awk -v s="$sum_units" -v m="$max_unit" -v o="$overhead" -v n="$n" -v merge="$local_merge" 'BEGIN {
  for (N = 1; N <= 32; N *= 2) {
    w = (s + o * n) / (2 * N); if (w < m + o) w = m + o; w += merge
    if (N == 1) w1 = w
    printf "  N = %2d: %7.2f s  (%.1fx faster than 1 node)\n", N, w, w1 / w
  }
}'
