#!/usr/bin/env bash
# Installs what is missing, builds, and opens the interactive viewer on the
# built-in metaballs (125 surfaces): click one to select it, ctrl-click to grow
# it from the click, drag the isovalue. Extra arguments go to isotrack, e.g.
#   scripts/demo.sh --volume assets/ct/cranium.nrrd --iso 400.5 --method track
# Without a display it runs a short scripted session in a virtual one
# (xvfb-run) instead and writes what the window showed to build/demo.png.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$repo/scripts/setup.sh"
isotrack="$repo/build/app/isotrack"
if [[ -n ${DISPLAY:-} || -n ${WAYLAND_DISPLAY:-} ]]; then
    exec "$isotrack" "$@"
fi

echo "demo: no display; running a scripted session under xvfb-run instead"
script=$(mktemp --suffix=.isotrack)
trap 'rm -f "$script"' EXIT
cat > "$script" <<SESSION
field blobs:128
wait
explode 0.4
select 0
colour 0 1 0.2 0.8
sweep 0.25 0.4 40
wait
frames 3
screenshot $repo/build/demo.png
quit
SESSION
xvfb-run -a -s "-screen 0 1600x1000x24" "$isotrack" --script "$script" --size 1280x800 --json "$@" \
    > "$repo/build/demo.json"
echo "demo: the window as it ended: $repo/build/demo.png; summary: $repo/build/demo.json"
