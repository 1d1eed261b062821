#!/usr/bin/env bash
# track_threads.sh -- tracking the CT skull on 1 to 16 threads, two isotrack builds side by side.
#
# Usage: bench/track_threads.sh BEFORE AFTER [ROUNDS]
#   BEFORE, AFTER: isotrack executables (e.g. a copy of an earlier build, build/app/isotrack)
#   ROUNDS: rounds of `isotrack bench` per build, alternating which goes first (default 2)
#
# Prints the load, then for each build: `isotrack bench --methods track` medians of 11 at
# 1, 2, 4, 8 and 16 threads (wall clock: only as good as the machine is idle), and counts that
# depend less on the load: context switches, migrations and CPU time (perf stat), and futex
# and sched_yield calls (strace -f -c), over the same 11 runs per thread count. On a machine
# with fewer cores than threads the counts exaggerate what threads waiting on one another cost.
# Needs assets/ct/cranium.nrrd (scripts/get_ct.sh), perf and strace.
set -euo pipefail
before=$1 after=$2 rounds=${3:-2}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ct=$here/../assets/ct/cranium.nrrd
[[ -f $ct ]] || { echo "no $ct: make it with scripts/get_ct.sh" >&2; exit 1; }
args=(bench --volume "$ct" --iso 400.5 --seed 122,122,160 --methods track --repeat 11)

echo "load: $(uptime)"
echo "cores: $(nproc)"
for ((round = 0; round < rounds; ++round)); do
    order=("$before" "$after")
    ((round % 2 == 1)) && order=("$after" "$before")
    for exe in "${order[@]}"; do
        echo "== round $round: $exe"
        "$exe" "${args[@]}" --threads 1 2 4 8 16 | grep ' track '
    done
done
for threads in 1 2 4 8 16; do
    for exe in "$before" "$after"; do
        perf=$(perf stat -x, -e context-switches,cpu-migrations,task-clock "$exe" "${args[@]}" \
                   --threads "$threads" 2>&1 >/dev/null | awk -F, '{ printf "%s %s  ", $3, $1 }')
        calls=$(strace -f -c -e trace=futex,sched_yield "$exe" "${args[@]}" --threads "$threads" 2>&1 \
                    >/dev/null | awk '$NF == "futex" || $NF == "sched_yield" { printf "%s %s  ", $NF, $4 }')
        echo "threads $threads  $exe  $perf $calls"
    done
done
echo "load: $(uptime)"
