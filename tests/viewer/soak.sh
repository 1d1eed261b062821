#!/usr/bin/env bash
# Soak: tests/viewer/soak.isotrack (~2300 frames of isovalue animation) in a
# 960x600 window (run it under xvfb-run). At the "warm*" and "end*"
# checkpoints, all at the same isovalue, the summary's CPU and GPU bytes must be
# equal, and the process's resident set (/proc/self/statm, after malloc_trim),
# lowest at the end against lowest after warm-up, may grow by at most 4 MiB.
# (It takes two values about 6 MiB apart, llvmpipe's scratch held or not, and
# shows no trend over 6700 frames; a leak of one surface per frame would be
# hundreds of MiB.)
#   soak.sh ISOTRACK VIEWER_CHECK OUT_DIR
set -euo pipefail
isotrack=$1 check=$2 out=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$out"
cd "$out"
"$isotrack" --script "$here/soak.isotrack" --size 960x600 --json > soak.json
"$check" summary soak.json --min-frames 2300
"$check" soak soak.json warm end --max-rss-growth $((4 * 1024 * 1024))
