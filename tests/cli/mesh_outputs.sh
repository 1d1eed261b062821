#!/usr/bin/env bash
# isotrack extract --out FILE.{ply,obj,stl} and --out-dir, isotrack info --json,
# on a built-in field exported as each volume format's raw twin.
# Usage: mesh_outputs.sh ISOTRACK WORK_DIR
set -euo pipefail
isotrack=$1
work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*"; exit 1; }

"$isotrack" field blobs:32 --out blobs.nrrd >/dev/null
for ext in ply obj stl PLY; do
    "$isotrack" extract --volume blobs.nrrd --out "blobs.$ext" --json > "out_$ext.json"
    [[ -s blobs.$ext ]] || fail "blobs.$ext was not written"
done
grep -q '"triangles"' out_ply.json || fail "no JSON summary"

# An unknown extension is refused before any work, naming it and the supported ones.
if "$isotrack" extract --volume blobs.nrrd --out blobs.off 2>err.txt; then fail "--out blobs.off accepted"; fi
grep -q '".off"' err.txt && grep -q '.ply, .obj, .stl' err.txt || fail "unhelpful message: $(cat err.txt)"

# One file per surface; their triangles add up to the whole.
"$isotrack" extract --volume blobs.nrrd --method all --out-dir surfaces --out-format stl --json > all.json
count=$(ls surfaces/surface_*.stl | wc -l)
[[ $count -ge 2 ]] || fail "expected several surfaces, got $count"
[[ -f surfaces/surface_000.stl ]] || fail "no surface_000.stl"
total=0
for f in surfaces/surface_*.stl; do
    n=$(od -An -tu4 -j80 -N4 "$f" | tr -d ' ')
    total=$((total + n))
done
grep -q "\"triangles\":$total," all.json || fail "surface files hold $total triangles, summary says otherwise"
"$isotrack" extract --volume blobs.nrrd --method all --out blobs_all.obj --out-dir objs >/dev/null
[[ -f objs/surface_000.obj ]] || fail "--out-dir did not follow --out's format"
if "$isotrack" extract --volume blobs.nrrd --out-dir x 2>err.txt; then fail "--out-dir without --method all accepted"; fi

# bench: every method and thread count in one process, the same meshes as extract.
"$isotrack" bench --volume blobs.nrrd --methods mc,all --threads 1,2 --repeat 2 --json > bench.json
python3 - bench.json out_ply.json all.json <<'PY' || fail "bench report: $(cat bench.json)"
import json, sys
bench, mc, every = (json.load(open(f)) for f in sys.argv[1:])
runs = {(r["method"], r["threads"]): r for r in bench["runs"]}
assert sorted(runs) == [("all", 1), ("all", 2), ("mc", 1), ("mc", 2)], sorted(runs)
for (method, threads), r in runs.items():
    assert len(r["seconds_all"]) == 2 and r["seconds"] > 0, r
    want = mc if method == "mc" else every
    assert (r["triangles"], r["vertices"]) == (want["triangles"], want["vertices"]), (r, want["triangles"])
    assert r["components"] == (None if method == "mc" else every["components"]), r
PY
if "$isotrack" bench --volume blobs.nrrd --methods track 2>err.txt; then fail "bench track without --seed accepted"; fi
grep -q "needs --seed" err.txt || fail "unhelpful message: $(cat err.txt)"

# info: raw twin of the NRRD (header stripped) reports the same dims, range and histogram.
"$isotrack" info --volume blobs.nrrd --json > info_nrrd.json
tail -c $((32 * 32 * 32 * 4)) blobs.nrrd > blobs.raw
"$isotrack" info --volume blobs.raw --dims 32,32,32 --type float32 --json > info_raw.json
strip() { sed -e 's/"file":"[^"]*",//' -e 's/"format":"[^"]*",//' "$1"; }
[[ $(strip info_nrrd.json) == "$(strip info_raw.json)" ]] || fail "info differs: $(cat info_nrrd.json) vs $(cat info_raw.json)"
"$isotrack" info --volume blobs.nrrd | grep -q "histogram 16 bins" || fail "no text histogram"

# bench's stream: every sample read once, those at or above the isovalue counted.
"$isotrack" bench --volume blobs.raw --dims 32,32,32 --type float32 --iso 0.25 --methods stream --threads 1,2 --repeat 2 --json > stream.json
python3 - stream.json blobs.raw <<'PY' || fail "bench stream: $(cat stream.json)"
import array, json, sys
report = json.load(open(sys.argv[1]))
samples = array.array("f", open(sys.argv[2], "rb").read())
expected = sum(1 for v in samples if v >= 0.25)
assert 0 < expected < len(samples), expected
for run in report["runs"]:
    assert run["method"] == "stream" and run["samples_above"] == expected, (run, expected)
    assert "triangles" not in run, run
PY
echo "ok ($total triangles in $count surface files)"
