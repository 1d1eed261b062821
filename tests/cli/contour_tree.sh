#!/usr/bin/env bash
# isotrack extract --method tree against --method all, isotrack tree --out
# .json/.svg, and the refusals (another table, an unknown --out extension).
# Usage: contour_tree.sh ISOTRACK WORK_DIR
set -euo pipefail
isotrack=$1
work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*"; exit 1; }
field() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])" "$1" "$2"; }

for spec in blobs:48 noise:24 gyroid:32; do
    "$isotrack" extract --field "$spec" --method all --json > all.json
    "$isotrack" extract --field "$spec" --method tree --json > tree.json
    [[ $(field all.json components) == $(field tree.json components) ]] || fail "$spec: tree and all differ in surfaces"
    [[ $(field all.json triangles) == $(field tree.json triangles) ]] || fail "$spec: tree and all differ in triangles"
    python3 -c "
import json; r = json.load(open('tree.json')); p = r['tree_phase_seconds']
assert sorted(p) == ['arcs', 'merge', 'sort', 'sweeps'] and all(v > 0 for v in p.values())
assert sum(p.values()) <= r['tree_seconds'] + 1e-6, (p, r['tree_seconds'])" || fail "$spec: tree_phase_seconds wrong"
    python3 -c "import json; s=json.load(open('tree.json'))['surfaces']; assert all('arc' in x and 'genus' in x for x in s)" \
        || fail "$spec: surfaces without arc or genus"
done

# Pruning by persistence keeps fewer surfaces, never more.
"$isotrack" extract --field noise:24 --iso 0.5 --method tree --min-persistence 0.1 --json > pruned.json
"$isotrack" extract --field noise:24 --iso 0.5 --method all --json > all.json
(( $(field pruned.json components) < $(field all.json components) )) || fail "--min-persistence pruned nothing"

# Pruning by size (samples swept) keeps as many surfaces as isotrack tree counts
# with the same --min-size, and fewer than all.
"$isotrack" extract --field noise:24 --iso 0.5 --method tree --min-size 4 --json > sized.json
sized=$(field sized.json components)
(( sized > 0 && sized < $(field all.json components) )) || fail "--min-size 4 kept $sized surfaces"
"$isotrack" tree --field noise:24 --at 0.5 --min-size 4 | grep -q "; $sized surfaces at iso 0.5" \
    || fail "extract --min-size and tree --min-size disagree"

"$isotrack" tree --field noise:24 --at 0.5 --out tree.json > tree.txt
grep -q "surfaces at iso 0.5" tree.txt || fail "no summary line"
# The build's four phases, each timed, adding up to no more than the build
# (each printed to 0.1 ms: their sum may pass the build's by 0.05 ms each).
python3 - tree.txt <<'PY' || fail "no phase times, or more than the build: $(cat tree.txt)"
import re, sys
text = open(sys.argv[1]).read()
build = float(re.search(r" in ([0-9.]+) ms \(simplified", text).group(1))
phases = [float(x) for x in re.search(
    r"build phases: sort ([0-9.]+) ms, sweeps ([0-9.]+) ms, merge ([0-9.]+) ms, arcs ([0-9.]+) ms", text).groups()]
assert all(p > 0 for p in phases) and sum(phases) <= build + 0.2, (phases, build)
PY
python3 -c "
import json; t=json.load(open('tree.json'))
assert len(t['arcs']) + 1 == len(t['nodes'])
assert len(t['arcs_at']) == $(field all.json components)
" || fail "tree.json does not hold the tree"
"$isotrack" tree --field blobs:32 --min-persistence 0.05 --out tree.svg > /dev/null
grep -q "<svg" tree.svg || fail "tree.svg is not an SVG"

# The SVG: well-formed, its branches' lines drawing every kept arc, the surfaces' arcs in the
# viewer's palette (surface k of extract --method tree in render/palette.cpp's
# colour k), a mark per surface.
"$isotrack" tree --field blobs:40 --at 0.3 --out plot.json > /dev/null
"$isotrack" tree --field blobs:40 --at 0.3 --out plot.svg > /dev/null
"$isotrack" extract --field blobs:40 --iso 0.3 --method tree --json > plot_surfaces.json
python3 - plot.svg plot.json plot_surfaces.json <<'PY' || fail "plot.svg does not draw the tree in the surfaces' colours"
import colorsys, json, math, sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
tree = json.load(open(sys.argv[2]))
surfaces = json.load(open(sys.argv[3]))["surfaces"]
ns = "{http://www.w3.org/2000/svg}"
branches = [e for e in root.iter(ns + "line") if e.get("class") == "branch"]
arcs = [e for e in root.iter(ns + "line") if e.get("class") == "arc"]
kept = sum(1 for a in tree["arcs"] if not a["pruned"])
assert sum(int(e.get("data-arcs")) for e in branches) == kept, kept
assert all(e.get("stroke") == "#999" for e in branches)
assert len(arcs) == len(surfaces), (len(arcs), len(surfaces))
def palette(rank):
    r = rank % 65536
    h = math.fmod(0.09 + r * 0.3819660112501051, 1.0)
    s = 0.40 + 0.35 * math.fmod(0.5 + r * 0.6710436067037893, 1.0)
    v = 0.68 + 0.27 * math.fmod(0.5 + r * 0.5497004779019703, 1.0)
    return [round(c * 255) for c in colorsys.hsv_to_rgb(h, s, v)]
coloured = {int(e.get("data-surface")): e for e in arcs if e.get("data-surface") is not None}
assert sorted(coloured) == list(range(len(surfaces))), (len(coloured), len(surfaces))
for k, e in coloured.items():
    assert int(e.get("data-arc")) == surfaces[k]["arc"], k
    rgb = [int(e.get("stroke")[i:i + 2], 16) for i in (1, 3, 5)]
    assert all(abs(a - b) <= 1 for a, b in zip(rgb, palette(k))), (k, rgb, palette(k))
marks = [e for e in root.iter(ns + "circle") if e.get("class") == "surface"]
assert len(marks) == len(surfaces)
PY
"$isotrack" tree --field noise:24 --max-branches 10 --out few.svg > /dev/null
grep -q "arcs hidden</text>" few.svg || fail "--max-branches 10: no count of the arcs hidden"

# Flexible isosurfaces: surface 0 at its own isovalue, the others untouched.
"$isotrack" extract --field blobs:48 --method tree --json > base.json
"$isotrack" extract --field blobs:48 --method tree --arc-iso 0:0.3 --json > flex.json
python3 -c "
import json; a=json.load(open('base.json'))['surfaces']; b=json.load(open('flex.json'))['surfaces']
assert len(a) == len(b)
assert b[0]['isovalue'] == 0.3 and b[1]['isovalue'] == a[1].get('isovalue', b[1]['isovalue'])
assert b[0]['triangles'] != a[0]['triangles']
assert [s['triangles'] for s in a[1:]] == [s['triangles'] for s in b[1:]]
assert [s['bounds'] for s in a[1:]] == [s['bounds'] for s in b[1:]]
" || fail "--arc-iso changed other surfaces or not its own"
set +e
"$isotrack" extract --field blobs:48 --method tree --arc-iso 0:100 2> err.txt
status=$?
set -e
[[ $status == 1 ]] && grep -q "^isotrack: --arc-iso 0:100: the surface vanishes" err.txt || fail "--arc-iso past the maximum: $status"

set +e
"$isotrack" extract --field blobs:32 --method tree --table classic 2> err.txt
status=$?
set -e
[[ $status == 1 ]] || fail "--method tree --table classic exited $status"
[[ $(wc -l < err.txt) == 1 ]] && grep -q "^isotrack: .*consistent table" err.txt || fail "unclear refusal: $(cat err.txt)"
set +e
"$isotrack" tree --field blobs:32 --out tree.txt 2> err.txt
status=$?
set -e
[[ $status == 1 ]] && grep -q "^isotrack: .*tree.txt" err.txt || fail "--out tree.txt: status $status, $(cat err.txt)"

# Progress on a terminal (script(1) gives the command one): the phases and a
# percentage on one line redrawn in place, cleared before the result; none in a pipe.
if command -v script > /dev/null; then
    script -qec "'$isotrack' tree --field gyroid:48" /dev/null | tr '\r' '\n' > tty.txt
    grep -Eq "^isotrack: contour tree: (sorting the samples|sweeping the join and split trees|merging them|building arcs|done) +[0-9]+%" tty.txt || fail "no progress on a terminal: $(cat tty.txt)"
    grep -q "gyroid:48: contour tree of" tty.txt || fail "no result after the progress: $(cat tty.txt)"
    grep -q $'^\033\[Kgyroid:48: contour tree of' tty.txt || fail "the progress line was not cleared"
fi
"$isotrack" tree --field gyroid:48 2> piped.txt > /dev/null
[[ ! -s piped.txt ]] || fail "progress in a pipe: $(cat piped.txt)"
"$isotrack" extract --field gyroid:48 --method tree 2> piped.txt > /dev/null
[[ ! -s piped.txt ]] || fail "extract --method tree: progress in a pipe: $(cat piped.txt)"
echo "contour tree CLI: ok"
