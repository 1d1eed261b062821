#!/usr/bin/env bash
# Seeds are remembered (tests/viewer/seeds.isotrack): a tracked surface that
# vanishes keeps its seed ("gone") and comes back with the same triangles; two
# tracked surfaces that merge show once ("merged"), and both come back when
# they split.
#   seeds.sh ISOTRACK VIEWER_CHECK OUT_DIR
set -euo pipefail
isotrack=$1 check=$2 out=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$out"
cd "$out"
"$isotrack" --script "$here/seeds.isotrack" --size 960x600 --json > seeds.json
field() { "$check" field seeds.json "$1"; }
expect() {  # CHECKPOINT_INDEX KEY VALUE
    local got
    got=$(field "checkpoints.$1.$2")
    echo "checkpoint $(field "checkpoints.$1.name"): $2 = $got"
    [[ $got == "$3" ]] || { echo "expected $3"; exit 1; }
}
expect 0 surfaces 1
expect 0 surfaces_gone 0
expect 1 surfaces 1
expect 1 surfaces_gone 1
expect 2 surfaces_gone 0
expect 2 triangles "$(field checkpoints.0.triangles)"
expect 3 surfaces 2
expect 3 surfaces_merged 0
expect 4 surfaces 2
expect 4 surfaces_merged 1
expect 5 surfaces 2
expect 5 surfaces_merged 0
"$check" surfaces seeds.json
[[ $(field surfaces.1.state) == shown && $(field surfaces.1.triangles) -gt 0 ]]
