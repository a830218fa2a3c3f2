#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Golden outputs: the main path on bundled samples with a fixed seed and small sizes must write exactly the
# committed files (tests/golden/expected/), byte for byte. A refactoring that changes no behaviour keeps them;
# a deliberate change of an output regenerates them with tools/update-golden and says why in the commit.
#
# What is compared: fit.json of a reduced-grid fit (Basotect round 5 cm, Q0-0 x S0-2 grown by one pair to S = 3,
# the cap of --grid-growth 1, so that the grid record with a step and an edge warning is covered; 40 live points), the
# headers emitted from it (48 kHz in f32, q31 and q15), the text of `check` on each header, a synthesised
# data file, and diagnosis.json of a diagnosis against a SPEC simulation (40 live points). Sizes keep the job
# to a few seconds; every value in these files passes through the code paths a default run uses.
# Generated files carry the admitgen version: a version bump regenerates the goldens.
#
# Usage: run_golden.sh ADMITGEN SAMPLES_DIR WORK_DIR EXPECTED_DIR [--update]
set -euo pipefail
admitgen=$(realpath "$1") samples=$(realpath "$2") work=$3 expected=$(realpath -m "$4") update=${5:-}
rm -rf "$work" && mkdir -p "$work/out"
# Files record the paths they were given: run inside the work folder on relative paths, so that the outputs
# do not depend on where the tree or the build lives.
cd "$work"
out=out
cp "$samples/basotect_tuberlin/round_5cm.csv" "$samples/basotect_tuberlin/LICENSE.txt" .

"$admitgen" fit round_5cm.csv --columns f,_,_,_,_,re,im,_ --qmax 0 --smax 2 --grid-growth 1 --live 40 \
  --seed 11 --threads 2 --quiet --out fit
cp fit/fit.json "$out/fit.json"
for format in f32 q31 q15; do
  "$admitgen" emit fit/fit.json --fs 48000 --format "$format" --quiet --out "$out/wall_48000_$format.h"
  "$admitgen" check "$out/wall_48000_$format.h" > "$out/check_48000_$format.txt"
done
"$admitgen" synth --material 'miki(sigma=10000, d=50mm)' --effect edge_gap:width_m=0.5mm,depth_m=50mm \
  --tube-diameter 0.1 --mic-spacing 0.05 --mic-distance 0.1 --noise 0.005 --seed 5 --out "$out/synth.csv"
# diagnose exits 1 when it found a gap (docs/cli.md, exit codes): expected here, the data carry an edge gap.
rc=0
"$admitgen" diagnose --real "$out/synth.csv" --sim 'miki(sigma=10000, d=50mm)' --tube-diameter 0.1 \
  --mic-spacing 0.05 --mic-distance 0.1 --live 40 --seed 5 --quiet --out diag || rc=$?
[ $rc -eq 1 ] || { echo "diagnose exited $rc, expected 1 (a gap found)"; exit 1; }
cp diag/diagnosis.json "$out/diagnosis.json"

if [ "$update" = "--update" ]; then
  rm -rf "$expected" && mkdir -p "$expected" && cp "$out"/* "$expected/"
  echo "golden outputs written to $expected"
  exit 0
fi
fail=0
for f in "$expected"/*; do
  name=$(basename "$f")
  if ! cmp -s "$f" "$out/$name"; then
    echo "DIFFERS: $name (expected $f, got $out/$name)"; diff "$f" "$out/$name" | head -20 || true; fail=1
  fi
done
for f in "$out"/*; do
  [ -e "$expected/$(basename "$f")" ] || { echo "NEW OUTPUT without a golden file: $(basename "$f")"; fail=1; }
done
[ $fail -eq 0 ] && echo "all $(ls "$expected" | wc -l) golden outputs byte-identical"
exit $fail
