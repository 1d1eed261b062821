#!/usr/bin/env bash
# The viewer opens the CT at the isovalue the command line does: its --json
# summary's default_isovalue (and the isovalue it shows) equal `isotrack info`'s
# suggested_isovalue and `isotrack extract`'s isovalue without --iso. Skipped
# (77) without the CT sample.
#   default_isovalue.sh ISOTRACK VIEWER_CHECK OUT_DIR
set -euo pipefail
isotrack=$1 check=$2 out=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ct=$here/../../assets/ct/cranium.nrrd
if [[ ! -f $ct ]]; then
    echo "skipped: no assets/ct/cranium.nrrd (make it with scripts/get_ct.sh)"
    exit 77
fi
mkdir -p "$out"
cd "$out"
printf '%s\n' "wait" "quit" > default_isovalue.isotrack
"$isotrack" --volume "$ct" --method mc --script default_isovalue.isotrack --size 960x600 --json > viewer.json
"$isotrack" info --volume "$ct" --json > info.json
"$isotrack" extract --volume "$ct" --json > extract.json
viewer=$("$check" field viewer.json default_isovalue)
shown=$("$check" field viewer.json isovalue)
info=$("$check" field info.json suggested_isovalue)
extract=$("$check" field extract.json isovalue)
echo "viewer $viewer (showing $shown), info $info, extract $extract"
[[ $viewer == "$info" && $shown == "$info" && $extract == "$info" ]]
