#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The library header (docs/library.md, "Outputs") compiles as strict C99 with every warning an error, and its
# enum, rate list, names and model table point at each material's own models.
# Usage: library_header.sh ADMITGEN SOURCE_DIR WORK_DIR CC
set -euo pipefail
admitgen=$1 source=$2 work=$3 cc=$4
rm -rf "$work" && mkdir -p "$work"
"$admitgen" library plan -q "$source/tests/library/three_materials.toml" --out "$work/lib"
"$admitgen" library run -q "$work/lib"
"$admitgen" library merge -q "$work/lib"
cat >"$work/main.c" <<'C'
#include <string.h>
#include "walls.h"
int main(void) {
  if (WALLS_MATERIAL_COUNT != 3 || WALLS_RATE_COUNT != 1 || walls_rates[0] != 48000) return 1;
  if (WALLS_REFERENCE != 0 || WALLS_GLASS_BEADS != 1 || WALLS_MPP != 2) return 2;  /* manifest order */
  if (walls_model(WALLS_MPP, 48000) != &walls_mpp_48000) return 3;
  if (walls_model(WALLS_REFERENCE, 44100) != 0) return 4;  /* a rate the library lacks */
  if (walls_models[WALLS_GLASS_BEADS][0] != &walls_glass_beads_48000) return 5;
  if (walls_models[WALLS_REFERENCE][0] != walls_reference_model(48000)) return 6;  /* the material's own lookup */
  if (strcmp(walls_names[WALLS_MPP], "mpp") != 0 || strcmp(walls_names[WALLS_REFERENCE], "reference") != 0) return 7;
  return 0;
}
C
"$cc" -std=c99 -pedantic -Wall -Wextra -Werror -I"$source/runtime/include" -I"$work/lib" "$work/main.c" -o "$work/main"
"$work/main"
echo "library header: compiles as C99 without warnings; enum, rates, names and table correct"
