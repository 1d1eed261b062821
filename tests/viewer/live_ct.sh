#!/usr/bin/env bash
# Acceptance for progressive updates on the CT sample (skipped, 77, without it):
# - every surface, 350 -> 450 in 60 steps: at least 10 extractions applied;
# - the tracked skull, 380 -> 420 in 40 steps: at least 8 re-tracked results
#   shown during the sweep, and at the end the selected surface is still the
#   skull (more than 300,000 triangles).
#   live_ct.sh ISOTRACK VIEWER_CHECK OUT_DIR
set -euo pipefail
isotrack=$1 check=$2 out=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
if [[ ! -f $here/../../assets/ct/cranium.nrrd ]]; then
    echo "skipped: no assets/ct/cranium.nrrd (make it with scripts/get_ct.sh)"
    exit 77
fi
mkdir -p "$out"
cd "$out"
"$isotrack" --script "$here/live_ct_all.isotrack" --size 960x600 --json > live_ct_all.json
"$check" sweep live_ct_all.json live_ct_all_profile.json before still swept done --min-applied 10

"$isotrack" --script "$here/live_ct_track.isotrack" --size 960x600 --json > live_ct_track.json
"$check" sweep live_ct_track.json live_ct_track_profile.json before still swept done --min-applied 8
during=$(( $("$check" field live_ct_track.json checkpoints.2.extractions_applied) -
           $("$check" field live_ct_track.json checkpoints.1.extractions_applied) ))
echo "re-tracked results shown during the sweep: $during"
(( during >= 8 )) || { echo "expected at least 8 during the sweep"; exit 1; }
"$check" surfaces live_ct_track.json
selected=$("$check" surfaces live_ct_track.json | awk '$5 == 1 { print $3 }')
echo "selected surface at the end: ${selected:-none} triangles"
[[ -n $selected ]] && (( selected > 300000 ))
