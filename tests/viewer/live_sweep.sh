#!/usr/bin/env bash
# Acceptance for progressive updates on blobs:128 (tests/viewer/live_sweep.isotrack):
# the sweep and the wait after it apply at least 30 extractions. Prints the
# median frame time while sweeping against the same window standing still.
#   live_sweep.sh ISOTRACK VIEWER_CHECK OUT_DIR
set -euo pipefail
isotrack=$1 check=$2 out=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$out"
cd "$out"
"$isotrack" --script "$here/live_sweep.isotrack" --size 960x600 --json > live_sweep.json
"$check" sweep live_sweep.json live_sweep_profile.json before still swept done --min-applied 30
