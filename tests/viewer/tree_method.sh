#!/usr/bin/env bash
# The viewer's contour-tree method (tests/viewer/tree_method.isotrack): as many
# surfaces and triangles as `isotrack extract --method all` at each isovalue, and
# as `--method tree --min-persistence 0.1` with the panel's persistence.
#   tree_method.sh ISOTRACK VIEWER_CHECK OUT_DIR
set -euo pipefail
isotrack=$1 check=$2 out=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$out"
cd "$out"
"$isotrack" --script "$here/tree_method.isotrack" --size 960x600 --json > tree_method.json
field() { "$check" field tree_method.json "$1"; }
for k in 0 1; do
    iso=$([[ $k == 0 ]] && echo 0.6 || echo 0.45)
    "$isotrack" extract --field noise:32 --iso "$iso" --method all --json > all.json
    want=$("$check" field all.json components)
    triangles=$("$check" field all.json triangles)
    echo "checkpoint $(field "checkpoints.$k.name"): $(field "checkpoints.$k.surfaces") surfaces (all: $want)"
    [[ $(field "checkpoints.$k.surfaces") == "$want" ]] || exit 1
    [[ $(field "checkpoints.$k.triangles") == "$triangles" ]] || { echo "triangles differ from all's $triangles"; exit 1; }
done
[[ $(field checkpoints.2.surfaces) == $(field checkpoints.1.surfaces) ]]
"$isotrack" extract --field noise:32 --iso 0.45 --method tree --min-persistence 0.1 --json > simplified.json
want=$("$check" field simplified.json components)
echo "checkpoint $(field checkpoints.3.name): $(field checkpoints.3.surfaces) surfaces (tree simplified: $want)"
[[ $want -lt $(field checkpoints.1.surfaces) ]] || { echo "persistence 0.1 hides no surface"; exit 1; }
[[ $(field checkpoints.3.surfaces) == "$want" ]] || exit 1
[[ $(field checkpoints.3.triangles) == $("$check" field simplified.json triangles) ]] || exit 1
[[ $(field min_persistence) == 0.1 ]]
