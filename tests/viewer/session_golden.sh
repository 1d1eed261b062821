#!/usr/bin/env bash
# A scripted viewer session compared against a golden screenshot.
#   session_golden.sh ISOTRACK VIEWER_CHECK OUT_DIR NAME
# Runs tests/viewer/NAME.isotrack with --deterministic in a 960x600 window (run
# it under xvfb-run), then checks NAME.png against tests/golden/viewer_NAME.png
# (metric: tests/viewer/viewer_check.cpp) and the --json summary.
set -euo pipefail
isotrack=$1 check=$2 out=$3 name=$4
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$out"
cd "$out"
rm -f "$name.png" "$name.json"
"$isotrack" --script "$here/$name.isotrack" --deterministic --size 960x600 --json > "$name.json"
"$check" summary "$name.json"
"$check" golden "$out/$name.png" "viewer_$name"
