#!/usr/bin/env bash
# extract --cap, --smooth and --decimate on the CT skull (iso 400, tracked from
# 122,122,160). --cap against a copy padded independently (pad_nrrd.py, numpy)
# for track, all and mc; smoothing's volume, Hausdorff distance (mesh_distance)
# and mean dihedral angle (computed here with numpy from the written PLY), with
# both tables; decimation's ratio, closure and sampled Hausdorff distance
# (mesh_distance). Skipped (77) without the CT.
# Usage: mesh_processing.sh ISOTRACK MESH_DISTANCE WORK_DIR
set -euo pipefail
isotrack=$1
distance=$2
work=$3
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
# The padded copy's samples sit one spacing further along each axis.
padded_seed=122.9570312,122.9570312,161.5
surface() { $py -c "import json,sys; s=json.load(open(sys.argv[1]))['surfaces'][0]; print(eval(sys.argv[2], {}, s))" "$1" "$2"; }

"$isotrack" "${skull[@]}" --out raw.ply > raw.json
"$isotrack" "${skull[@]}" --cap --out cap.ply > cap.json
echo "raw: $(surface raw.json '(triangles, closed, border_loops, genus, quality["degenerate_triangles"])')"
echo "cap: $(surface cap.json '(triangles, closed, border_loops, genus, quality["boundary_edges"])')"
[[ $(surface raw.json 'border_loops') -gt 0 ]] || fail "the raw skull should be open"
[[ $(surface cap.json 'closed and border_loops == 0 and quality["boundary_edges"] == 0') == True ]] ||
    fail "--cap leaves the skull open"
[[ $(surface cap.json 'genus is not None') == True ]] || fail "--cap reports no genus"

# --cap equals extracting from an independently padded copy, for track, all and mc.
$py "$here/pad_nrrd.py" "$ct" 400 padded.nrrd
"$isotrack" extract --volume padded.nrrd --iso 400 --method track --seed $padded_seed --json > padded_track.json
# Triangle counts equal; volumes and areas within 1e-6 relative, plus 1e-4 for
# small surfaces: the copies' float positions differ by their origins' rounding.
same_surfaces() {  # capped.json padded.json
    $py - "$1" "$2" <<'PY' || fail "--cap differs from the padded copy: $1 vs $2"
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
sa, sb = a.get("surfaces", [a]), b.get("surfaces", [b])
assert len(sa) == len(sb), (len(sa), len(sb))
for x, y in zip(sa, sb):
    assert x["triangles"] == y["triangles"], (x["triangles"], y["triangles"])
    for key in ("enclosed_volume", "area"):
        if x.get(key) is not None or y.get(key) is not None:
            assert abs(x[key] - y[key]) <= 1e-6 * abs(y[key]) + 1e-4, (key, x[key], y[key])
print(f"  {len(sa)} surface(s), {sum(s['triangles'] for s in sa)} triangles: same as the padded copy")
PY
}
same_surfaces cap.json padded_track.json
"$isotrack" extract --volume "$ct" --iso 400 --method all --cap --json > cap_all.json
"$isotrack" extract --volume padded.nrrd --iso 400 --method all --json > padded_all.json
same_surfaces cap_all.json padded_all.json
[[ $($py -c "import json; print(all(s['closed'] for s in json.load(open('cap_all.json'))['surfaces']))") == True ]] ||
    fail "--method all --cap leaves a surface open"
"$isotrack" extract --volume "$ct" --iso 400 --cap --json > cap_mc.json
"$isotrack" extract --volume padded.nrrd --iso 400 --json > padded_mc.json
same_surfaces cap_mc.json padded_mc.json
[[ $($py -c "import json; print(json.load(open('cap_mc.json'))['quality']['boundary_edges'])") == 0 ]] ||
    fail "--method mc --cap leaves boundary edges"

# Smoothing, with both tables: the enclosed volume within 1%; every point
# within the tolerance --json reports (half the smallest spacing) of the
# unsmoothed skull both ways (mesh_distance; 1e-4 mm for the float rounding of
# the frame); still closed and manifold with the genus kept; the mean dihedral
# angle down. The goal is half: not met on the CT (docs/meshes.md:
# 70% of what stays is within 4 mm of an opposite sheet, thin bone and small
# tunnels), so the figures measured (-22% consistent, -41% snap) are asserted
# with a margin, and the halving where it is met (a segmented ball, core tests).
dihedral() {
    $py - "$1" <<'PY'
import sys
import numpy as np
data = open(sys.argv[1], "rb").read()
start = data.index(b"end_header\n") + len(b"end_header\n")
head = data[:start].decode()
nv = int(head.split("element vertex ")[1].split()[0])
nf = int(head.split("element face ")[1].split()[0])
v = np.frombuffer(data, "<f4", nv * 6, start).reshape(nv, 6)[:, :3].astype(float)
f = np.frombuffer(data, np.dtype([("n", "u1"), ("i", "<i4", 3)]), nf, start + nv * 24)["i"]
n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
length = np.linalg.norm(n, axis=1)
ok = length > 0
n[ok] /= length[ok, None]
edges = np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1)
faces = np.tile(np.arange(nf), 3)
order = np.lexsort((edges[:, 1], edges[:, 0]))
edges, faces = edges[order], faces[order]
pair = (edges[1:] == edges[:-1]).all(axis=1)
a, b = faces[:-1][pair], faces[1:][pair]
keep = ok[a] & ok[b]
print(np.arccos(np.clip((n[a[keep]] * n[b[keep]]).sum(axis=1), -1, 1)).mean())
PY
}
"$isotrack" "${skull[@]}" --table snap --cap --out snap_cap.ply > snap_cap.json
for table in consistent snap; do
    unsmoothed=cap
    [[ $table == snap ]] && unsmoothed=snap_cap
    "$isotrack" "${skull[@]}" --table $table --cap --smooth 20 --out ${table}_smooth.ply > ${table}_smooth.json
    tolerance=$($py -c "import json; print(json.load(open('${table}_smooth.json'))['smooth_tolerance'])")
    before=$(dihedral $unsmoothed.ply)
    after=$(dihedral ${table}_smooth.ply)
    hausdorff=$("$distance" $unsmoothed.ply ${table}_smooth.ply)
    echo "smooth 20 ($table): volume $(surface $unsmoothed.json enclosed_volume) -> $(surface ${table}_smooth.json enclosed_volume)," \
         "mean dihedral angle $before -> $after rad, Hausdorff $hausdorff mm (tolerance $tolerance)"
    $py -c "import sys; a, b = float(sys.argv[1]), float(sys.argv[2]); sys.exit(abs(b / a - 1) > 0.01)" \
        "$(surface $unsmoothed.json enclosed_volume)" "$(surface ${table}_smooth.json enclosed_volume)" ||
        fail "smoothing ($table) changed the volume by over 1%"
    $py -c "import sys; sys.exit(not 0 < float(sys.argv[2]) <= float(sys.argv[1]) + 1e-4 < 0.9570312)" "$tolerance" "$hausdorff" ||
        fail "smoothing ($table) moved the skull $hausdorff mm, over its tolerance $tolerance"
    [[ $(surface ${table}_smooth.json 'closed and quality["boundary_edges"] == 0 and quality["non_manifold_edges"] == 0') == True ]] ||
        fail "smoothing ($table) left the skull open or non-manifold"
    [[ $(surface ${table}_smooth.json genus) == $(surface $unsmoothed.json genus) ]] || fail "smoothing ($table) changed the genus"
    least=0.8  # consistent: -22% measured
    [[ $table == snap ]] && least=0.65  # -41% measured
    $py -c "import sys; sys.exit(not float(sys.argv[2]) < float(sys.argv[3]) * float(sys.argv[1]))" "$before" "$after" "$least" ||
        fail "smoothing ($table) left the mean dihedral angle at $after (from $before)"
done

# Decimation to a tenth, with both tables: at most 11% of the triangles,
# closed if the input was, within a voxel (the smallest spacing, 0.957 mm) of
# the original both ways. The consistent skull keeps its border loops; on the
# snapped one, whose sheets meet at grid points, splitting the pinched edges
# adds loops (9 -> 14 measured), so only its closure is asserted.
"$isotrack" "${skull[@]}" --table snap --out snap.ply > snap.json
for table in consistent snap; do
    for input in raw cap; do
        flag="" base=$input
        [[ $input == cap ]] && flag=--cap
        [[ $table == snap ]] && base=snap && [[ $input == cap ]] && base=snap_cap
        out=${table}_${input}_decimated
        # One thread: decimation follows the input's order, which a track on
        # several threads varies from run to run (docs/meshes.md, Decimation).
        "$isotrack" "${skull[@]}" --table $table $flag --threads 1 --decimate 0.1 --out "$out.ply" > "$out.json"
        ratio=$($py -c "import sys; print(int(sys.argv[2]) / int(sys.argv[1]))" "$(surface $base.json triangles)" \
                    "$(surface $out.json triangles)")
        hausdorff=$("$distance" "$base.ply" "$out.ply")
        echo "decimate 0.1 ($table, $input): ratio $ratio, Hausdorff $hausdorff mm," \
             "closed $(surface $out.json closed), border loops $(surface $out.json border_loops)"
        $py -c "import sys; sys.exit(not float(sys.argv[1]) <= 0.11)" "$ratio" || fail "--decimate 0.1 ($table) kept $ratio"
        $py -c "import sys; sys.exit(not float(sys.argv[1]) < 0.9570312)" "$hausdorff" ||
            fail "--decimate 0.1 ($table): Hausdorff $hausdorff mm"
        if [[ $table == consistent ]]; then
            [[ $(surface $out.json border_loops) == $(surface $base.json border_loops) ]] ||
                fail "decimation changed the border loops"
        fi
        if [[ $input == cap ]]; then
            [[ $(surface $out.json closed) == True ]] || fail "decimating the capped skull ($table) opened it"
        fi
    done
done
echo "ok"
