#!/usr/bin/env bash
# isotrack render --gl egl|auto|osmesa with no display: EGL gives a GL 3.3+
# context (a GPU device, or Mesa's surfaceless platform), --json names the
# backend and renderer, two EGL renders are identical, EGL on llvmpipe draws
# OSMesa's pixels, and auto falls back to OSMesa with a one-line notice where
# there is no EGL hardware device or no libEGL at all. Exit 77 (skipped) where
# EGL offers nothing to try.
# Usage: render_egl_test.sh ISOTRACK WORK_DIR
set -euo pipefail
isotrack=$1
work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*"; exit 1; }
unset DISPLAY WAYLAND_DISPLAY
render=(render --field blobs:32 --method all --size 160x120 --wireframe)

# A string or number from the --json object (one key per line).
field() { sed -nE "s/^  \"$2\": (\"([^\"]*)\"|([^\",]*)),?\$/\2\3/p" "$1"; }

if ! "$isotrack" "${render[@]}" --gl egl --json --out egl.png >egl.json 2>egl.err; then
    if grep -q "EGL is unavailable\|EGL offers neither" egl.err; then
        echo "SKIP: $(cat egl.err)"
        exit 77
    fi
    fail "render --gl egl: $(cat egl.err)"
fi
renderer=$(field egl.json renderer)
version=$(field egl.json version)
echo "egl: $(field egl.json platform): $renderer, OpenGL $version"
[[ $(field egl.json backend) == egl ]] || fail "--gl egl drew with '$(field egl.json backend)'"
[[ -n $renderer ]] || fail "no renderer in egl.json"
[[ $version =~ ^([0-9]+)\.([0-9]+) ]] || fail "GL_VERSION '$version'"
((BASH_REMATCH[1] > 3 || (BASH_REMATCH[1] == 3 && BASH_REMATCH[2] >= 3))) || fail "OpenGL $version < 3.3"
[[ $(field egl.json width)x$(field egl.json height) == 160x120 ]] || fail "size in egl.json"
[[ $(od -An -tx1 -j12 -N12 egl.png | tr -d ' \n') == 49484452000000a000000078 ]] || fail "egl.png is not a 160x120 PNG"

"$isotrack" "${render[@]}" --gl egl --out egl_again.png >plain.txt
cmp -s egl.png egl_again.png || fail "two EGL renders differ: $work/egl.png $work/egl_again.png"
grep -q "^gl: egl, .*: .*, OpenGL " plain.txt || fail "no 'gl: egl, ...' line: $(cat plain.txt)"

"$isotrack" "${render[@]}" --gl osmesa --json --out osmesa.png >osmesa.json
[[ $(field osmesa.json backend) == osmesa ]] || fail "--gl osmesa drew with '$(field osmesa.json backend)'"
if [[ $renderer == *llvmpipe* ]]; then
    # The same rasteriser behind both: the same pixels, and so the same PNG bytes.
    cmp -s egl.png osmesa.png || fail "EGL on llvmpipe differs from OSMesa: $work/egl.png $work/osmesa.png"
fi

"$isotrack" "${render[@]}" --gl auto --json --out auto.png >auto.json 2>auto.err
if [[ $renderer == *llvmpipe* ]]; then
    [[ $(field auto.json backend) == osmesa ]] || fail "--gl auto without a GPU drew with '$(field auto.json backend)'"
    [[ $(wc -l <auto.err) -eq 1 ]] && grep -q "^isotrack: --gl auto: .*; drawing with OSMesa$" auto.err ||
        fail "auto fallback notice: $(cat auto.err)"
else
    [[ $(field auto.json backend) == egl ]] || fail "--gl auto on a GPU drew with '$(field auto.json backend)'"
fi

# Without libEGL, auto still draws (OSMesa, one notice line) and egl says why it cannot.
export ISOTRACK_EGL_LIBRARY=$work/no-such-libEGL.so.1
"$isotrack" "${render[@]}" --gl auto --json --out nolib.png >nolib.json 2>nolib.err || fail "auto without libEGL: $(cat nolib.err)"
[[ $(field nolib.json backend) == osmesa ]] || fail "auto without libEGL drew with '$(field nolib.json backend)'"
[[ $(wc -l <nolib.err) -eq 1 ]] && grep -q "^isotrack: --gl auto: EGL is unavailable (.*no-such-libEGL" nolib.err ||
    fail "auto without libEGL: $(cat nolib.err)"
cmp -s nolib.png osmesa.png || fail "auto's OSMesa fallback differs from --gl osmesa"
if "$isotrack" "${render[@]}" --gl egl --out never.png >/dev/null 2>egl_nolib.err; then fail "--gl egl without libEGL succeeded"; fi
grep -q "^isotrack: EGL is unavailable" egl_nolib.err || fail "--gl egl without libEGL: $(cat egl_nolib.err)"
echo "isotrack render --gl egl|auto|osmesa: ok"
