#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Usage: check_man_pages.sh ADMITGEN_EXE MAN1_DIR
# Every page renders with man -l (man-db + groff) without warnings, there is one page per subcommand
# of `admitgen --help`, and admitgen-fit(1) documents every long option of `admitgen fit --help`.
set -euo pipefail
exe=$1 dir=$2
command -v man >/dev/null || { echo "FAIL: man (Debian package man-db) is not installed"; exit 1; }
subcommands=$("$exe" --help | sed -n '/^\(SUBCOMMANDS\|Subcommands\):/,/^$/s/^  \([a-z][a-z0-9-]*\).*/\1/p')
[[ -n $subcommands ]] || { echo "FAIL: no subcommands in admitgen --help"; exit 1; }
for page in admitgen $(printf 'admitgen-%s ' $subcommands); do
  [[ -f $dir/$page.1 ]] || { echo "FAIL: no page $dir/$page.1"; exit 1; }
  text=$(MANWIDTH=100 man --warnings -l "$dir/$page.1" 2>"$dir/../$page.warnings" | col -b)
  [[ ! -s $dir/../$page.warnings ]] || { echo "FAIL: groff warnings for $page:"; cat "$dir/../$page.warnings"; exit 1; }
  grep -q "^NAME" <<<"$text" && grep -qE "^ *$page +- " <<<"$text" || { echo "FAIL: $page has no NAME line '$page - ...'"; exit 1; }
done
fit_page=$(MANWIDTH=100 man -l "$dir/admitgen-fit.1" | col -b)
for opt in $("$exe" fit --help | grep -oE -- '--[a-z][a-z0-9-]+' | sort -u); do
  grep -q -- "$opt" <<<"$fit_page" || { echo "FAIL: admitgen-fit(1) does not mention $opt"; exit 1; }
done
echo "PASS: $(wc -w <<<"$subcommands") subcommand pages and admitgen(1) render; admitgen-fit(1) lists every option"
