#!/usr/bin/env bash
# Installs what a fresh Debian 12 machine lacks for isotrack (apt, idempotent) and
# builds it into build/ (Release). Usage: scripts/setup.sh [extra cmake args...]
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

packages=(cmake g++ make pkg-config libglfw3-dev libglm-dev libosmesa6-dev libegl-dev libegl-mesa0 libgl1-mesa-dri catch2 libstb-dev zlib1g-dev
          xvfb xauth libcli11-dev nlohmann-json3-dev libbenchmark-dev invesalius-examples
          clang clang-format-14 libclang-rt-14-dev libgdcm-dev libexpat1-dev python3-pydicom libmeshoptimizer-dev
          pybind11-dev python3-dev python3-numpy python3-pytest python3-skimage python3-nibabel
          python3-scipy python3-dask python3-distributed python3-zarr)
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
    echo "setup: installing ${missing[*]}"
    sudo=""
    [[ $(id -u) -eq 0 ]] || sudo="sudo"
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get -o DPkg::Lock::Timeout=600 update -qq
    $sudo apt-get -o DPkg::Lock::Timeout=600 install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

cmake -S "$repo" -B "$repo/build" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$repo/build" -j"$(nproc)"
