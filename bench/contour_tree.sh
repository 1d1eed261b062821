#!/usr/bin/env bash
# The contour tree's build time and memory: `isotrack tree` on each volume,
# RUNS times (median), one markdown row per volume and binary. With several
# binaries (ISOTRACK="old new"), their runs are interleaved, so that a load
# that comes and goes weighs on them alike. The load average is printed
# before and after; the table means little above 1.
#
# Columns: the build as the tree reports it ("in X ms"), per sample; its
# phases' medians (the "build phases:" line; – for a binary without it); the whole
# process's wall and CPU (user + system, both threads), field or file reading
# included; the peak RSS, and what it holds beyond the volume per sample.
#
# Usage: bench/contour_tree.sh [RUNS] [THREADS] [VOLUME...]
#   VOLUME is a built-in field (sphere:256) or a file; default: sphere:128,
#   sphere:256, gyroid:128, gyroid:256, the CT (scripts/get_ct.sh), sphere:512.
#   ISOTRACK: the binaries to compare (default build/app/isotrack).
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
runs=${1:-3}
threads=${2:-2}
shift $(($# < 2 ? $# : 2))
volumes=("$@")
if [ ${#volumes[@]} -eq 0 ]; then
    volumes=(sphere:128 sphere:256 gyroid:128 gyroid:256 "$repo/assets/ct/cranium.nhdr" sphere:512)
fi
read -r -a binaries <<< "${ISOTRACK:-$repo/build/app/isotrack}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

source_of() {  # VOLUME -> the isotrack arguments naming it
    if [ -e "$1" ]; then echo "--volume $1"; else echo "--field $1"; fi
}
median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }

echo "load before: $(uptime | sed 's/.*load average: //')"
echo
echo "| binary | volume | samples | nodes / arcs | build (median of $runs) | ns/sample | sort / sweeps / merge / arcs, ms | process wall, CPU | peak RSS | beyond the volume |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for volume in "${volumes[@]}"; do
    if [ -e "$volume" ]; then
        read -r samples bytes < <("${binaries[0]}" info --volume "$volume" --json | /usr/bin/python3 -c '
import json, sys
info = json.load(sys.stdin)
size = {"int8": 1, "uint8": 1, "int16": 2, "uint16": 2, "int32": 4, "uint32": 4, "float32": 4, "float64": 8}
print(info["samples"], info["samples"] * size[info["scalar_type"]])')
    else  # the built-in fields are N^3 float32
        n=${volume#*:}
        samples=$((n * n * n)) bytes=$((4 * n * n * n))
    fi
    for run in $(seq "$runs"); do
        for b in "${!binaries[@]}"; do
            # shellcheck disable=SC2046
            /usr/bin/time -f "%e %U %S %M" -o "$work/time" "${binaries[$b]}" tree $(source_of "$volume") \
                --threads "$threads" > "$work/out"
            sed -n 's/.* contour tree of \([0-9]*\) nodes, \([0-9]*\) arcs .* in \([0-9.]*\) ms (simplified.*/\1 \2 \3/p' \
                "$work/out" > "$work/tree"
            read -r nodes arcs ms < "$work/tree"
            # the build's phases (binaries that print them), a file each
            sed -n 's/^build phases: sort \([0-9.]*\) ms, sweeps \([0-9.]*\) ms, merge \([0-9.]*\) ms, arcs \([0-9.]*\) ms/\1 \2 \3 \4/p' \
                "$work/out" | while read -r sort sweeps merge arcs; do
                echo "$sort" >> "$work/sort.$b"; echo "$sweeps" >> "$work/sweeps.$b"
                echo "$merge" >> "$work/merge.$b"; echo "$arcs" >> "$work/arcs.$b"
            done
            read -r wall user sys kib < "$work/time"
            echo "$ms" >> "$work/ms.$b"
            echo "$wall" >> "$work/wall.$b"
            echo "$user $sys" | awk '{print $1 + $2}' >> "$work/cpu.$b"
            echo "$kib" >> "$work/kib.$b"
            echo "$nodes / $arcs" > "$work/shape.$b"
        done
    done
    for b in "${!binaries[@]}"; do
        ms=$(median < "$work/ms.$b")
        kib=$(median < "$work/kib.$b")
        phases="–"
        if [ -s "$work/sort.$b" ]; then
            phases=$(for p in sort sweeps merge arcs; do median < "$work/$p.$b"; done | xargs printf '%.0f / %.0f / %.0f / %.0f')
        fi
        printf '| %s | %s | %s | %s | %.2f s | %.0f | %s | %.2f s, %.2f s | %.0f MB | %.1f B/sample |\n' \
            "${binaries[$b]#"$repo"/}" \
            "$(basename "$volume")" "$samples" "$(cat "$work/shape.$b")" "$(echo "$ms / 1000" | bc -l)" \
            "$(echo "$ms * 1000000 / $samples" | bc -l)" "$phases" "$(median < "$work/wall.$b")" "$(median < "$work/cpu.$b")" \
            "$(echo "$kib / 1000" | bc -l)" "$(echo "($kib * 1024 - $bytes) / $samples" | bc -l)"
        rm -f "$work/ms.$b" "$work/wall.$b" "$work/cpu.$b" "$work/kib.$b" "$work/"{sort,sweeps,merge,arcs}".$b"
    done
done
echo
echo "load after: $(uptime | sed 's/.*load average: //')"
