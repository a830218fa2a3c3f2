#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Usage: check_completion.sh COMPLETION_FILE ADMITGEN_EXE
# The completion script loads in a plain bash (no bash-completion package needed), registers itself
# for admitgen, and completes subcommands, options and option choices from the program's own help.
set -euo pipefail
file=$1 exe=$2
bash --norc --noprofile -c '
  set -u
  source "$1"
  complete -p admitgen
  expect() {  # expect WANTED WORD... : completes the last WORD and requires WANTED among the candidates
    local wanted=$1; shift
    COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); COMPREPLY=()
    _admitgen
    [[ " ${COMPREPLY[*]} " == *" $wanted "* ]] || { echo "FAIL: ${*} -> [${COMPREPLY[*]}], wanted $wanted"; exit 1; }
    echo "ok: ${*} -> ${COMPREPLY[*]}"
  }
  expect fit "$2" fi
  expect diagnose "$2" di
  expect --live "$2" fit data.csv --li
  expect --fs "$2" emit fit.json --f
  expect q15 "$2" emit fit.json --format q
  expect reflection "$2" fit data.csv --quantity r
' check_completion "$file" "$exe"
echo "PASS"
