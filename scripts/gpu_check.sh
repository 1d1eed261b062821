#!/usr/bin/env bash
# Headless rendering on a GPU machine with no display: runs the already-built
# isotrack (builds nothing) through `render --gl egl` and `--gl auto` on a few
# fields and sizes, and prints what drew each image and how long it took.
# Images (and each run's JSON) go to $OUT when it is set.
#
#   scripts/gpu_check.sh [path/to/isotrack]     (default: build/app/isotrack)
#   OUT=/tmp/gpu scripts/gpu_check.sh
#
# It keeps going when something is missing and says what: libEGL.so.1 (glvnd),
# the NVIDIA EGL vendor file, libraries the binary was linked against. Exit
# status: 0 when every run drew through EGL on hardware, 1 otherwise.
set -uo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
isotrack=${1:-$repo/build/app/isotrack}
out=${OUT:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[[ -n $out ]] && mkdir -p "$out"

section() { printf '\n== %s\n' "$*"; }

section "machine"
echo "isotrack: $isotrack"
[[ -x $isotrack ]] || { echo "not found or not executable: build it first (scripts/setup.sh)"; exit 1; }
echo "DISPLAY='${DISPLAY:-}' WAYLAND_DISPLAY='${WAYLAND_DISPLAY:-}' (neither is needed)"
if command -v nvidia-smi >/dev/null; then
    nvidia-smi --query-gpu=index,name,driver_version,memory.total --format=csv,noheader | sed 's/^/gpu: /'
else
    echo "nvidia-smi: not found"
fi
ls /dev/dri 2>/dev/null | tr '\n' ' ' | sed 's/^/\/dev\/dri: /;s/$/\n/' || true
ls /dev/nvidia* 2>/dev/null | tr '\n' ' ' | sed 's/^/nvidia devices: /;s/$/\n/' || true
egl_lib=${ISOTRACK_EGL_LIBRARY:-libEGL.so.1}
if ldconfig -p 2>/dev/null | grep -q "libEGL.so.1 "; then
    echo "libEGL.so.1: $(ldconfig -p | grep -m1 'libEGL.so.1 ' | sed 's/.*=> //')"
elif [[ -n ${ISOTRACK_EGL_LIBRARY:-} ]]; then
    echo "libEGL: ISOTRACK_EGL_LIBRARY=$egl_lib"
else
    echo "libEGL.so.1: not in the loader cache (glvnd's libegl1; isotrack finds it only through LD_LIBRARY_PATH" \
         "or ISOTRACK_EGL_LIBRARY=/path/libEGL.so.1)"
fi
for dir in /usr/share/glvnd/egl_vendor.d /etc/glvnd/egl_vendor.d ${__EGL_VENDOR_LIBRARY_DIRS:-}; do
    [[ -d $dir ]] && for f in "$dir"/*.json; do
        [[ -e $f ]] && echo "EGL vendor: $f -> $(grep -o '"library_path"[^,}]*' "$f" | sed 's/.*: *//')"
    done
done
missing=$(ldd "$isotrack" 2>/dev/null | grep 'not found' || true)
if [[ -n $missing ]]; then
    echo "isotrack cannot start, libraries not found:"
    echo "$missing"
    echo "copy them (and glvnd's libEGL.so.1 + libGLdispatch.so.0 if missing) from the build machine into a folder"
    echo "and rerun with LD_LIBRARY_PATH=that-folder (libOSMesa is optional: it is opened at run time)"
    exit 1
fi

failures=0
# run NAME GL FIELD SIZE [render options...]: one render, its summary and timings.
run() {
    local name=$1 gl=$2 field=$3 size=$4
    shift 4
    local png="$work/$name.png" json="$work/$name.json" err="$work/$name.err"
    [[ -n $out ]] && png="$out/$name.png"
    if "$isotrack" render --field "$field" --size "$size" --gl "$gl" --json --out "$png" "$@" >"$json" 2>"$err"; then
        [[ -n $out ]] && cp "$json" "$out/$name.json"
        local get
        get() { sed -nE "s/^  \"$1\": (\"([^\"]*)\"|([^\",]*)),?\$/\2\3/p" "$json"; }
        printf '%-28s %-6s %-9s %8s tris  extract %7.1f ms  context %7.1f ms  draw %7.1f ms  %s\n' \
            "$name" "$(get backend)" "$size" "$(get triangles)" "$(get extract_ms)" "$(get context_ms)" \
            "$(get draw_ms)" "$(get renderer)"
        [[ -s $err ]] && sed 's/^/    /' "$err"
        if [[ $gl != osmesa ]] && { [[ $(get backend) != egl ]] || [[ $(get renderer) =~ llvmpipe|softpipe|swrast ]]; }; then
            failures=$((failures + 1))
        fi
    else
        echo "$name: FAILED (--gl $gl): $(cat "$err")"
        [[ $gl == osmesa ]] || failures=$((failures + 1))
    fi
}

section "renderer"
if "$isotrack" render --field sphere:16 --size 64x48 --gl egl --out "$work/probe.png" >"$work/probe.txt" 2>&1; then
    grep '^gl:' "$work/probe.txt"
else
    echo "--gl egl failed: $(cat "$work/probe.txt")"
    echo "(for EGL debugging: EGL_LOG_LEVEL=debug for Mesa, __EGL_VENDOR_LIBRARY_FILENAMES=/usr/share/glvnd/egl_vendor.d/10_nvidia.json for glvnd)"
fi

section "renders (first run of each includes shader compilation; draw = upload + draw + read back)"
for size in 1024x768 320x240; do
    for gl in egl auto; do
        run "gyroid128_all_${size}_$gl" "$gl" gyroid:128 "$size" --method all
        run "blobs128_all_${size}_$gl" "$gl" blobs:128 "$size" --method all
        run "blobs128_wire_${size}_$gl" "$gl" blobs:128 "$size" --wireframe
    done
done
# The CPU reference, for scale (fails harmlessly where libOSMesa is missing).
run "gyroid128_all_1024x768_osmesa" osmesa gyroid:128 1024x768 --method all

# The golden tests through EGL, with each comparison's numbers, when they are built.
gl_tests=$(dirname "$(dirname "$isotrack")")/tests/gl_tests
if [[ -x $gl_tests ]]; then
    section "golden images through EGL against the OSMesa baselines ($gl_tests)"
    ISOTRACK_TEST_GL=egl ISOTRACK_GOLDEN_REPORT=1 "$gl_tests" "[golden]" >"$work/golden.txt" 2>&1
    status=$?
    grep -E "^(gl_tests:|golden |All tests|test cases)|FAILED|differ by more" "$work/golden.txt"
    [[ -n $out ]] && cp "$work/golden.txt" "$out/golden.txt"
    echo "gl_tests exit status $status (77: skipped, EGL unavailable)"
fi

section "summary"
[[ -n $out ]] && echo "images and JSON: $out"
if ((failures)); then
    echo "$failures EGL/auto run(s) did not draw through EGL on hardware"
    exit 1
fi
echo "every run drew through EGL on hardware"
