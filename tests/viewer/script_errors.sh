#!/usr/bin/env bash
# Script errors and a missing display: exit status 1 and exactly one line on
# stderr, naming the script and the line (or suggesting xvfb-run).
#   script_errors.sh ISOTRACK OUT_DIR
set -euo pipefail
isotrack=$1 out=$2
mkdir -p "$out"
cd "$out"
failures=0

# expect_error NAME EXPECTED_TEXT [isotrack arguments...]
expect_error() {
    local name=$1 expected=$2
    shift 2
    local status=0
    "$@" > "$name.out" 2> "$name.err" || status=$?
    local lines
    lines=$(wc -l < "$name.err")
    if [[ $status -ne 1 || $lines -ne 1 ]] || ! grep -qF -- "$expected" "$name.err"; then
        echo "FAIL $name: exit $status, $lines stderr lines, expected one line with: $expected"
        cat "$name.err"
        failures=$((failures + 1))
    else
        echo "ok   $name: $(cat "$name.err")"
    fi
}

script() {  # script NAME LINES...
    local name=$1
    shift
    printf '%s\n' "$@" > "$name.isotrack"
}

script unknown "field sphere:16" "frobnicate 3"
expect_error unknown "unknown.isotrack:2: unknown command \"frobnicate\"" "$isotrack" --script unknown.isotrack
script bad_number "# a comment" "field sphere:16" "iso zero"
expect_error bad_number "bad_number.isotrack:3: iso: \"zero\" is not a number" "$isotrack" --script bad_number.isotrack
script missing_file "load no/such/volume.nrrd"
expect_error missing_file "missing_file.isotrack:1: load: no such file or folder no/such/volume.nrrd" "$isotrack" --script missing_file.isotrack
script bad_click "field sphere:16" "click 1.5 0.5"
expect_error bad_click "bad_click.isotrack:2: click: 1.5 is outside 0..1" "$isotrack" --script bad_click.isotrack
script bad_field "field teapot:16"
expect_error bad_field "bad_field.isotrack:1:" "$isotrack" --script bad_field.isotrack
# Found while running, in the window: there is no surface 3 in an empty scene.
script no_surface "field sphere:16" "method track" "wait" "hide 3" "quit"
expect_error no_surface "no_surface.isotrack:4: hide: there is no surface 3 (0 surfaces)" "$isotrack" --script no_surface.isotrack
# An isovalue of its own needs the contour tree: with `all` the surface is on no arc.
script not_tree "field sphere:16" "method all" "wait" "surface-iso 0 0.5" "quit"
expect_error not_tree "not_tree.isotrack:4: surface 0 is on no contour-tree arc" "$isotrack" --script not_tree.isotrack
expect_error no_script "no/such.isotrack: cannot read the script" "$isotrack" --script no/such.isotrack
expect_error no_volume "--volume no/such.nrrd: cannot open the file" "$isotrack" --volume no/such.nrrd
expect_error no_display "xvfb-run" env -u DISPLAY -u WAYLAND_DISPLAY "$isotrack"

exit $((failures > 0))
