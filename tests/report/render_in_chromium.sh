#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Renders report.html (from a small fit of the bundled reference data) and diagnosis.html (from the
# bundled diagnosis sample) in headless Chromium, and checks that each page loads without console or
# network errors and that the screenshot is not blank. Exit 77 (CTest skip) without chromium.
# Usage: render_in_chromium.sh ADMITGEN RENDER_TOOL SAMPLES_DIR WORK_DIR
set -euo pipefail
admitgen=$1 render=$2 samples=$3 work=$4

browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
  echo "SKIP: chromium is not installed (apt-get install chromium; .ci/install-deps installs it)"
  exit 77
fi

rm -rf "$work" && mkdir -p "$work"
"$admitgen" fit "$samples/reference/q1s1_sigma0.01.csv" --qmax 1 --smax 1 --live 50 --threads 1 --quiet --out "$work/fit"
"$render" diagnosis "$samples/diagnosis/round_vs_rect_5cm/diagnosis.json" "$work/diagnosis" >/dev/null

status=0
for page in "$work/fit/report.html" "$work/diagnosis/diagnosis.html"; do
  name=$(basename "$page" .html)
  png="$work/$name.png" log="$work/$name.log"
  # Every host resolves to nothing: a page that tried to load anything from the network would log net::ERR_.
  if ! timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
      --disable-background-networking --disable-component-update --disable-sync --hide-scrollbars \
      --host-resolver-rules="MAP * ~NOTFOUND" --user-data-dir="$(mktemp -d "$work/profile.XXXXXX")" \
      --enable-logging=stderr --v=0 --window-size=1200,2400 --screenshot="$png" "file://$page" >"$log" 2>&1; then
    echo "FAIL: chromium exited with an error on $page (log: $log)"; status=1; continue
  fi
  if grep -E "CONSOLE|Uncaught|net::ERR_|Failed to load resource" "$log"; then
    echo "FAIL: $page logged console or network errors (above)"; status=1
  fi
  if ! python3 "$(dirname "$0")/check_png.py" "$png" 1200; then status=1; fi
done
[ $status -eq 0 ] && echo "PASS: both reports render in $browser; screenshots in $work"
exit $status
