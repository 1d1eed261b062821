#!/usr/bin/env bash
# Arguments are checked before any volume is read or generated: every refusal
# below names a field (sphere:1024, 4 GiB of float32, many seconds to build)
# and must come back within `timeout 5` with its exit status (1 for a run-time
# check, 2 for a parse error) and exactly one line on stderr. A check made
# after the field was built would run past the timeout (status 124) or take
# the memory.
# Usage: early_validation.sh ISOTRACK WORK_DIR
set -euo pipefail
isotrack=$1
work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
failures=0
big=sphere:1024

# refused NAME STATUS EXPECTED_TEXT isotrack-arguments...
refused() {
    local name=$1 want=$2 expected=$3
    shift 3
    local status=0 start end
    start=$(date +%s.%N)
    timeout 5 "$isotrack" "$@" > "$name.out" 2> "$name.err" || status=$?
    end=$(date +%s.%N)
    local lines seconds
    lines=$(wc -l < "$name.err")
    seconds=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')
    if [[ $status -ne $want || $lines -ne 1 ]] || ! grep -qF -- "$expected" "$name.err"; then
        echo "FAIL $name: exit $status (want $want) in $seconds s, $lines stderr lines, expected one line with: $expected"
        cat "$name.err"
        failures=$((failures + 1))
    else
        echo "ok   $name ($seconds s): $(cat "$name.err")"
    fi
}

# The acceptance case: track without a seed, at once.
refused track_without_seed 1 "isotrack: --method track needs --seed X,Y,Z" extract --field $big --method track
refused seed_without_track 1 "--seed is used by --method track only, not all" \
    extract --field $big --method all --seed 1,2,3
refused tree_with_classic 1 "--method tree works with the consistent table only, not classic" \
    extract --field $big --method tree --table classic
refused tree_option_without_tree 1 "need --method tree, not mc" extract --field $big --min-persistence 2
refused arc_iso_syntax 1 "--arc-iso 0:x: expected SURFACE:ISOVALUE" extract --field $big --method tree --arc-iso 0:x
refused out_extension 1 '".off"' extract --field $big --out mesh.off
refused out_dir_without_all 1 "--out-dir writes one file per surface" extract --field $big --out-dir surfaces
refused iso_not_finite 1 "--iso: must be a finite number" extract --field $big --iso nan
refused unknown_field 1 'unknown field "nosuch"' extract --field nosuch:1024
refused field_too_large 1 "is outside" extract --field sphere:99999

# Names: core's words and core's message, while the command line is parsed.
refused unknown_method 2 'unknown method "flying-edges" (expected mc, track, all or tree)' \
    extract --field $big --method flying-edges
refused unknown_table 2 'unknown table "mc33" (expected consistent, classic, trilinear or snap)' \
    extract --field $big --table mc33
refused unknown_frame 2 'unknown frame "xyz" (expected lps, ras or voxel)' extract --field $big --frame xyz
refused zero_threads 2 "--threads" extract --field $big --threads 0

refused render_track_without_seed 1 "--method track needs --seed" render --field $big --method track --out a.png
refused render_not_png 1 "--out a.jpg: render writes a .png file" render --field $big --out a.jpg
refused render_bad_size 1 "--size" render --field $big --size 10x0 --out a.png
refused render_method_tree 2 'method "tree" is not one of mc, track or all' \
    render --field $big --method tree --out a.png
refused bench_track_without_seed 1 "--methods track needs --seed" bench --field $big --methods mc,track
refused bench_unknown_method 2 'method "tree" is not one of mc, track, all or stream' \
    bench --field $big --methods mc,tree
refused tree_out_extension 1 "--out tree.txt: the tree is written as .json or .svg" tree --field $big --out tree.txt
refused tree_at_not_finite 1 "--at: must be a finite number" tree --field $big --at inf
refused info_bins 2 "--bins" info --volume missing.nrrd --bins 0

# The viewer checks its options before it opens a window or builds the field
# (so these need no display).
refused viewer_unknown_method 2 'unknown method "exhaustive"' --field $big --method exhaustive
refused viewer_iso_not_finite 1 "--iso: must be a finite number" --field $big --iso nan
refused viewer_unknown_field 1 'unknown field "nosuch"' --field nosuch:64
refused viewer_bad_size 1 "--size" --field $big --size 10x10

if [[ $failures -ne 0 ]]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "every refusal came before the volume"
