#!/usr/bin/env bash
# The snap table grown live (tests/viewer/snap_track.isotrack): the
# surface under a click and the one a track command names, each exported once
# grown, are byte for byte the file `isotrack extract --method track --table
# snap --threads 1` writes from the same seed point (on more threads the same
# triangles come in another order), and the growth took several frames.
#   snap_track.sh ISOTRACK VIEWER_CHECK OUT_DIR
set -euo pipefail
isotrack=$1 check=$2 out=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$out"
cd "$out"
rm -f snap_click.ply snap_track.ply snap_extract_*.ply
"$isotrack" --script "$here/snap_track.isotrack" --size 960x600 --json > snap_track.json
"$check" summary snap_track.json --surfaces 2
# The clicked surface has 38,575 pieces: grown 300 a frame, it takes over 100 frames.
frames=$("$check" field snap_track.json frames)
echo "grown over $frames frames"
(( frames > 100 ))
click=$("$check" field snap_track.json picks.0.point | tr -d '[] ')
for run in "click:$click" "track:17,0.6,28"; do
    name=${run%%:*} point=${run#*:}
    "$isotrack" extract --field noise:32 --iso 0.5 --table snap --method track --threads 1 --seed "$point" \
        --out "snap_extract_$name.ply" > /dev/null
    cmp "snap_$name.ply" "snap_extract_$name.ply"
    echo "$name at $point: the viewer's surface equals extract's ($(stat -c %s "snap_$name.ply") bytes)"
done
