#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Every data file in samples/ through the main path with defaults: admitgen fit (100 live points) ->
# admitgen emit at 44.1, 48 and 96 kHz in f32, q31 and q15 (default estimate: passive) -> exit 0, and
# admitgen check passes on every header written. docs/passivity.md describes what makes this hold.
#
# Sizes (CI budget): 100 live points, one missed-mode retry round; the 1025-point Basotect files over
# Q0-2 x S0-2 without growing it (--grid-growth 0; the selected Q3S3 of the full grid is exercised by the
# Basotect selection test; what is tested here is that whatever order is selected ends in a safe filter),
# the synthetic and reference files over their documented grids.
# Usage: every_sample_emits_safely.sh ADMITGEN SAMPLES_DIR WORK_DIR
set -euo pipefail
admitgen=$1 samples=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail=0
run_case() {  # name data fit-options...
  local name=$1 data=$2; shift 2
  local dir="$work/$name"
  if ! "$admitgen" fit "$data" --live 100 --missed-mode-retries 1 --quiet --out "$dir" "$@"; then
    echo "FAIL $name: fit exited $?"; fail=1; return
  fi
  for fs in 44100 48000 96000; do
    for format in f32 q31 q15; do
      local h="$dir/wall_${fs}_${format}.h"
      if ! "$admitgen" emit "$dir/fit.json" --fs "$fs" --format "$format" --quiet --out "$h"; then
        echo "FAIL $name: emit --fs $fs --format $format refused"; fail=1; continue
      fi
      if ! "$admitgen" check "$h" > "$h.check.txt"; then
        echo "FAIL $name: check $h"; cat "$h.check.txt"; fail=1; continue
      fi
    done
  done
  "$admitgen" check "$dir/fit.json" > "$dir/fit.check.txt" || { echo "FAIL $name: check fit.json"; fail=1; }
  echo "ok   $name: $(grep -o '"order": "Q[0-9]S[0-9]"' "$dir/fit.json" | tail -1), 9 headers emitted and checked"
}
b="$samples/basotect_tuberlin"
for f in round_10cm round_5cm rect_5cm rect_10cm; do
  run_case "basotect_$f" "$b/$f.csv" --columns f,_,_,_,_,re,im,_ --qmax 2 --smax 2 --grid-growth 0
done
run_case reference "$samples/reference/q1s1_sigma0.01.csv"
run_case glass_beads "$samples/synthetic/glass_beads_40mm.csv" --qmax 2 --smax 2 --grid-growth 0
run_case mpp_three_layer "$samples/synthetic/mpp_three_layer.csv" --qmax 1 --smax 3 --priors "$samples/synthetic/mpp_priors.json"
exit $fail
