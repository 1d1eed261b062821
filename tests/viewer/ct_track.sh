#!/usr/bin/env bash
# Acceptance on the CT sample: tests/viewer/ct_track.isotrack loads it, sets iso
# 400.5 and the track method, clicks the middle of the view and runs 90 frames.
# It must end with exactly one surface, the one under the click: the same
# triangles as `isotrack extract --method track` seeded at the clicked point;
# its profile must hold at least 90 frames, and the skull must have grown in
# place in the GPU arena: no slot moved to a bigger range, in no frame (the
# moves are what made growth frames hitch). Exits 77 (skipped) without the CT.
#   ct_track.sh ISOTRACK VIEWER_CHECK OUT_DIR
set -euo pipefail
isotrack=$1 check=$2 out=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ct="$here/../../assets/ct/cranium.nrrd"
if [[ ! -f $ct ]]; then
    echo "skipped: no $ct (make it with scripts/get_ct.sh)"
    exit 77
fi
mkdir -p "$out"
cd "$out"
rm -f ct_track.png ct_track.json ct_track_profile.json
"$isotrack" --script "$here/ct_track.isotrack" --size 960x600 --json > ct_track.json
"$check" summary ct_track.json --surfaces 1
"$check" profile ct_track_profile.json --min-frames 90
[[ -s ct_track.png ]] || { echo "no screenshot ct_track.png"; exit 1; }
moves=$("$check" field ct_track.json gpu_surface_arena.moves)
echo "GPU arena: $moves slots moved while the skull grew"
[[ $moves == 0 ]]

point=$("$check" field ct_track.json picks.0.point | tr -d '[] ')
"$isotrack" extract --volume "$ct" --iso 400.5 --method track --seed "$point" --json > ct_track_extract.json
viewer=$("$check" field ct_track.json surfaces.0.triangles)
extract=$("$check" field ct_track_extract.json triangles)
echo "clicked at $point: the viewer grew $viewer triangles, extract --method track gives $extract"
[[ $viewer == "$extract" ]]
echo "screenshot: $out/ct_track.png, profile: $out/ct_track_profile.json, summary: $out/ct_track.json"
