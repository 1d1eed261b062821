#!/usr/bin/env bash
# The snap (3-state) table's acceptance on the CT skull (iso 400, tracked from
# 122,122,160): no zero-area triangles and no non-manifold edges after welding,
# by isotrack's own figures and independently (weld_check.py, numpy welding by
# position); fewer triangles than the consistent table; under 3% of the
# triangles with a smallest angle below 10 degrees. Surface counts of `all`
# within 1% of the consistent table's at 400.5 and on the noise field; track,
# all and mc agree on the skull. Skipped (77) without the CT.
# Usage: snap_table.sh ISOTRACK WORK_DIR
set -euo pipefail
isotrack=$1
work=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ct=$here/../../assets/ct/cranium.nrrd
if [[ ! -f $ct ]]; then
    echo "skipped: no assets/ct/cranium.nrrd (make it with scripts/get_ct.sh)"
    exit 77
fi
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*"; exit 1; }
py=/usr/bin/python3
skull=(extract --volume "$ct" --iso 400 --method track --seed 122,122,160 --json)
surface() { $py -c "import json,sys; s=json.load(open(sys.argv[1]))['surfaces'][0]; print(eval(sys.argv[2], {}, s))" "$1" "$2"; }
field() { $py -c "import json,sys; print(eval(sys.argv[2], {}, json.load(open(sys.argv[1]))))" "$1" "$2"; }

"$isotrack" "${skull[@]}" --table consistent > consistent.json
"$isotrack" "${skull[@]}" --table snap --out snap.ply > snap.json
$py "$here/weld_check.py" snap.ply > snap_check.json
echo "consistent: $(surface consistent.json '(triangles, quality)')"
echo "snap:       $(surface snap.json '(triangles, quality)')"
echo "numpy:      $(cat snap_check.json)"
[[ $(surface snap.json 'quality["degenerate_triangles"]') == 0 ]] || fail "zero-area triangles with the snap table"
[[ $(surface snap.json 'quality["non_manifold_edges"]') == 0 ]] || fail "non-manifold edges with the snap table"
[[ $(field snap_check.json 'zero_area') == 0 ]] || fail "numpy finds zero-area triangles"
[[ $(field snap_check.json 'non_manifold_edges') == 0 ]] || fail "numpy finds non-manifold edges after welding"
[[ $(field snap_check.json "triangles == $(surface snap.json triangles)") == True ]] || fail "PLY and JSON differ"
[[ $(surface snap.json "triangles < $(surface consistent.json triangles)") == True ]] ||
    fail "the snap table should make fewer triangles than the consistent one"
[[ $(surface snap.json 'quality["min_angle_below_10"] < 0.03') == True ]] || fail "3% or more below 10 degrees"
[[ $(field snap_check.json 'below_10 < 0.03') == True ]] || fail "numpy: 3% or more below 10 degrees"

# Surface counts: every surface of the consistent table survives snapping.
counts() {  # table, then extract's source arguments
    local table=$1
    shift
    "$isotrack" extract "$@" --method all --table "$table" --json | $py -c "import json,sys; print(len(json.load(sys.stdin)['surfaces']))"
}
for source in "--volume $ct --iso 400.5" "--field noise:48"; do
    read -r -a args <<<"$source"
    c=$(counts consistent "${args[@]}")
    s=$(counts snap "${args[@]}")
    echo "surfaces ($source): consistent $c, snap $s"
    [[ $($py -c "print(abs($s - $c) <= 0.01 * $c)") == True ]] || fail "surface counts differ by more than 1% ($source)"
done

# track is the surface of all that holds the seed, and mc the union of all.
"$isotrack" extract --volume "$ct" --iso 400 --method all --table snap --json > all.json
"$isotrack" extract --volume "$ct" --iso 400 --method mc --table snap --json > mc.json
[[ $(field all.json "$(surface snap.json triangles) in [s['triangles'] for s in surfaces]") == True ]] ||
    fail "the tracked skull is none of all's surfaces"
[[ $(field all.json "sum(s['triangles'] for s in surfaces) == $(field mc.json triangles)") == True ]] ||
    fail "all's surfaces do not add up to mc's triangles"
echo "ok"
