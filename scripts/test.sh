#!/usr/bin/env bash
# Installs what is missing, builds, makes the CT sample, and runs every test.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$repo/scripts/setup.sh"
"$repo/scripts/get_ct.sh" >/dev/null
cd "$repo/build"
ctest --output-on-failure -j"$(nproc)" "$@"
