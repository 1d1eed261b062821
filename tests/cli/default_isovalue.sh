#!/usr/bin/env bash
# One default isovalue: without --iso, extract, bench and render open the CT at
# the value info suggests (core's suggestIsovalue), and info prints it with
# the step of the rule that chose it. Skipped (77) without the CT sample.
# Usage: default_isovalue.sh ISOTRACK WORK_DIR
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
field() { /usr/bin/python3 -c "import json,sys; print(repr(json.load(open(sys.argv[1]))[sys.argv[2]]))" "$1" "$2"; }

"$isotrack" info --volume "$ct" --json > info.json
"$isotrack" info --volume "$ct" > info.txt
"$isotrack" extract --volume "$ct" --json > extract.json
"$isotrack" bench --volume "$ct" --methods stream --threads 1 --repeat 1 --json > bench.json
suggested=$(field info.json suggested_isovalue)
rule=$(field info.json suggested_isovalue_rule)
echo "info suggests $suggested ($rule)"
[[ $rule == "'histogram valley'" ]] || fail "the CT's isovalue should come from its histogram valley, not $rule"
[[ $(field extract.json isovalue) == "$suggested" ]] || fail "extract opens at $(field extract.json isovalue)"
[[ $(field bench.json isovalue) == "$suggested" ]] || fail "bench opens at $(field bench.json isovalue)"
grep -qxF "  suggested isovalue: $suggested (histogram valley)" info.txt ||
    fail "info's text does not say it: $(grep suggested info.txt || echo nothing)"

# Between soft tissue and bone, as the rule means it to be; and the field's own for a field.
/usr/bin/python3 -c "import sys; v=float(sys.argv[1]); assert 250 < v < 600, v" "$suggested" ||
    fail "$suggested is not between soft tissue and bone"
"$isotrack" extract --field blobs:16 --json > blobs.json
"$isotrack" field blobs:16 --out blobs.nrrd | grep -q "default iso $(field blobs.json isovalue)" ||
    fail "a field opens at another value than its own"
echo "extract, bench and info agree on $suggested"
