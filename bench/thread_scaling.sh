#!/usr/bin/env bash
# Thread scaling on one machine, as markdown: `isotrack bench` of track (the
# consistent and trilinear tables), all and mc on the CT at iso 400.5 (the
# skull's seed), and the contour tree's build (`isotrack tree`, as it reports
# it, median of RUNS) on sphere:256, gyroid:256, the CT and sphere:512, each
# at THREADS (default 1 2 4 8 16), with each figure's speed-up over one thread
# and the scaling goals checked: no thread count slower than the one before,
# track at 16 threads at least 6x one thread, the tree at 16 at least 4x at 2;
# then the tree's phases at each thread count (which of them scale).
# Wall clock: only as good as the machine is idle (the load is printed).
#
# Usage: bench/thread_scaling.sh ISOTRACK CT OUT.md [THREADS...]
#   ISOTRACK: an isotrack executable (or scripts/bundle.sh's launcher, for a
#   machine without isotrack's packages); CT: cranium.nrrd (scripts/get_ct.sh).
#   RUNS (environment, default 3): tree builds per figure (sphere:512: 1).
set -euo pipefail
isotrack=${1:?usage: bench/thread_scaling.sh ISOTRACK CT OUT.md [THREADS...]}
ct=${2:?usage: bench/thread_scaling.sh ISOTRACK CT OUT.md [THREADS...]}
out=${3:?usage: bench/thread_scaling.sh ISOTRACK CT OUT.md [THREADS...]}
shift 3
threads=("$@")
[[ ${#threads[@]} -gt 0 ]] || threads=(1 2 4 8 16)
runs=${RUNS:-3}
[[ -f $ct ]] || { echo "thread_scaling.sh: $ct: no such file (scripts/get_ct.sh makes it)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }

# rows.txt: NAME<TAB>UNIT<TAB>figure at each thread count (ms)
: > "$work/rows.txt"
: > "$work/phases.txt"
skull=(bench --volume "$ct" --iso 400.5 --seed 122,122,160 --repeat 11 --threads "${threads[@]}")
"$isotrack" "${skull[@]}" --methods track all mc > "$work/bench.txt"
"$isotrack" "${skull[@]}" --methods track --table trilinear > "$work/trilinear.txt"
for method in track all mc; do
    # "  track   2 threads      25.76 ms  ..." -> one figure per thread count, in order
    printf '%s (CT skull, iso 400.5)\tms\t%s\n' "$method" \
        "$(awk -v m="$method" '$1 == m { printf "%s ", $4 }' "$work/bench.txt")" >> "$work/rows.txt"
done
printf 'track, trilinear table\tms\t%s\n' "$(awk '$1 == "track" { printf "%s ", $4 }' "$work/trilinear.txt")" \
    >> "$work/rows.txt"

for volume in sphere:256 gyroid:256 "$ct" sphere:512; do
    source=(--field "$volume")
    name=$volume
    [[ -e $volume ]] && source=(--volume "$volume") && name="CT $(basename "$volume")"
    n=$runs
    [[ $volume == sphere:512 ]] && n=1
    figures=""
    phases=""
    for t in "${threads[@]}"; do
        : > "$work/runs.txt"
        for ((r = 0; r < n; ++r)); do
            # "sphere:256: contour tree of 16 nodes, 15 arcs (15 kept) in 827.133 ms ..."
            # "build phases: sort 206.1 ms, sweeps 171.9 ms, merge 91.0 ms, arcs 69.2 ms"
            "$isotrack" tree "${source[@]}" --threads "$t" > "$work/tree.txt"
            printf '%s %s\n' "$(sed -n 's/^[^(]*([^)]*) in \([0-9.]*\) ms.*/\1/p' "$work/tree.txt")" \
                "$(sed -n 's/^build phases: sort \([0-9.]*\) ms, sweeps \([0-9.]*\) ms, merge \([0-9.]*\) ms, arcs \([0-9.]*\) ms/\1 \2 \3 \4/p' \
                    "$work/tree.txt")" >> "$work/runs.txt"
        done
        figures+="$(cut -d' ' -f1 "$work/runs.txt" | median) "
        # each phase's median, as sort/sweeps/merge/arcs
        phases+="$(for f in 2 3 4 5; do cut -d' ' -f"$f" "$work/runs.txt" | median; done | xargs printf '%.0f/%.0f/%.0f/%.0f') "
    done
    printf 'tree, %s\tms\t%s\n' "$name" "$figures" >> "$work/rows.txt"
    printf '%s\t%s\n' "$name" "$phases" >> "$work/phases.txt"
done

{
    echo "Machine: $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')); load before the tree"
    echo "builds and after: $(uptime | sed 's/.*load average: //')."
    echo
    header="| work |"
    rule="|---|"
    for t in "${threads[@]}"; do header+=" $t |"; rule+="---|"; done
    echo "$header speed-up at ${threads[-1]} | no count slower than the one before |"
    echo "$rule---|---|"
    while IFS=$'\t' read -r name _ values; do
        read -r -a v <<< "$values"
        awk -v name="$name" -v values="${v[*]}" 'BEGIN {
            n = split(values, f, " ")
            row = "| " name " |"
            for (i = 1; i <= n; ++i) row = row sprintf(" %.1f ms |", f[i])
            monotone = "yes"
            for (i = 2; i <= n; ++i) if (f[i] > f[i - 1]) monotone = "no"
            printf "%s %.2fx |%s |\n", row, f[1] / f[n], " " monotone
        }'
    done < "$work/rows.txt"
    echo
    echo "The tree's phases, sort / sweeps / merge / arcs in ms (medians, as \`isotrack tree\` prints them):"
    echo
    echo "$header"
    echo "$rule"
    while IFS=$'\t' read -r name values; do
        row="| tree, $name |"
        for cell in $values; do row+=" $cell |"; done
        echo "$row"
    done < "$work/phases.txt"
    echo
    awk -F'\t' -v first="${threads[0]}" -v last="${threads[-1]}" -v list="${threads[*]}" '
        BEGIN { k = split(list, t, " "); for (i = 1; i <= k; ++i) if (t[i] == 2) two = i }
        {
            n = split($3, f, " ")
            if ($1 ~ /^track \(/ && first == 1)
                printf "- track at %s threads: %.2fx one thread (goal: at least 6x)\n", last, f[1] / f[n]
            if ($1 ~ /^tree/ && two)
                printf "- %s at %s threads: %.2fx two threads (goal: at least 4x)\n", $1, last, f[two] / f[n]
        }' "$work/rows.txt"
} > "$out"
cat "$out"
