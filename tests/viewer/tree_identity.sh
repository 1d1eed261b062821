#!/usr/bin/env bash
# Surfaces keep who they are by their contour-tree arcs (tests/viewer/tree_identity.isotrack).
#   tree_identity.sh ISOTRACK VIEWER_CHECK OUT_DIR
set -euo pipefail
isotrack=$1 check=$2 out=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$out"
cd "$out"
"$isotrack" --script "$here/tree_identity.isotrack" --size 960x600 --json > tree_identity.json
"$check" same-arcs tree_identity.json blobs_before blobs_after
field() { "$check" field tree_identity.json "$1"; }
expect() {
    local got
    got=$(field "$1")
    [[ $got == "$2" ]] || { echo "tree_identity.json: $1 is $got, expected $2"; exit 1; }
    echo "$1 = $got"
}
expect isovalue_shown 0.3
expect surfaces.2.id 2
expect surfaces.2.selected true
expect surfaces.3.id 3
expect surfaces.3.colour '[1.0,0.0,1.0]'
expect surfaces.5.id 5
expect surfaces.5.visible false
expect checkpoints.2.name flexible_gone
expect checkpoints.2.surfaces_gone 1
expect checkpoints.3.surfaces_gone 0
expect surfaces.0.id 0
expect surfaces.0.state shown
expect surfaces.0.isovalue 0.5
expect surfaces.1.isovalue 0.3
# The tree's build, as the summary reports it: each phase timed, together
# within the whole (which also lays out the plot).
/usr/bin/python3 - tree_identity.json <<'PY'
import json
import sys
build = json.load(open(sys.argv[1]))["contour_tree_build_ms"]
phases = [build[name] for name in ("sort", "sweeps", "merge", "arcs")]
if not all(p > 0 for p in phases) or sum(phases) > build["total"] + 0.01:
    sys.exit(f"tree_identity.json: contour_tree_build_ms {build}: a phase untimed, or the phases past the total")
print("contour_tree_build_ms", build)
PY
