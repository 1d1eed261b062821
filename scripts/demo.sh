#!/usr/bin/env bash
# Installs what is missing, builds, and runs isotrack on a built-in volume:
# every surface of 125 metaballs, tracked one by one, written to blobs.ply.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$repo/scripts/setup.sh"
"$repo/build/app/isotrack" extract --field blobs:128 --method all --out "$repo/build/blobs.ply" "$@"
