#!/usr/bin/env bash
# Flexible isosurfaces in the viewer on the CT: the worker's time for every
# surface at a new common isovalue against one surface moved to its own
# isovalue (surface-iso: only it is tracked again), from the session's profile.
# docs/performance.md "Contour tree" holds the table. Needs assets/ct
# (scripts/get_ct.sh) and a display (run it under xvfb-run).
#   bench/flexible_ct.sh [ISOTRACK]
set -euo pipefail
isotrack=$(realpath "${1:-build/app/isotrack}")
ct=$(realpath assets/ct/cranium.nrrd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cd "$out"
cat >session.isotrack <<SESSION
load $ct
iso 400.5
method tree
wait
profile trace.json
iso 420
wait
surface-iso 3 430
wait
surface-iso 3 440
wait
surface-iso 0 430
wait
iso 430
wait
quit
SESSION
"$isotrack" --script session.isotrack --size 960x600 --json >summary.json
python3 - <<'REPORT'
import json
trace = json.load(open("trace.json"))
spans = [e["dur"] / 1000 for e in trace["traceEvents"] if e.get("ph") == "X" and "contour tree" in e.get("name", "")]
summary = json.load(open("summary.json"))
own = {s["id"]: s for s in summary["surfaces"] if s["own_isovalue"]}
small = [s for s in own.values() if s["id"] != 0][0]
steps = ["every surface, 400.5 -> 420", "surface 3 alone, own 430 (%d triangles at 440)" % small["triangles"],
         "surface 3 alone, own 440", "surface 0, the skull, alone, own 430 (%d triangles)" % own[0]["triangles"],
         "every other surface, 420 -> 430 (%d surfaces)" % len(summary["surfaces"])]
for step, ms in zip(steps, spans):
    print("| %s | %.1f |" % (step, ms))
REPORT
