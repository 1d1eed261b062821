#!/usr/bin/env bash
# Mesh quality of the CT skull (iso 400, tracked from 122,122,160) raw, capped,
# smoothed and decimated, with the consistent and the snap table: one row per
# table and processing, from `isotrack extract --json`
# (each surface's quality block) and the seconds processing took. docs/meshes.md
# holds the table. Needs assets/ct (scripts/get_ct.sh) and /usr/bin/python3.
#   bench/mesh_quality.sh [ISOTRACK]
set -euo pipefail
isotrack=$(realpath "${1:-build/app/isotrack}")
ct=$(realpath assets/ct/cranium.nrrd)
rows=("raw|" "--cap|--cap" "--smooth 20|--smooth 20" "--cap --smooth 20|--cap --smooth 20"
      "--decimate 0.1|--decimate 0.1" "--cap --decimate 0.1|--cap --decimate 0.1"
      "--cap --smooth 20 --decimate 0.1|--cap --smooth 20 --decimate 0.1")
tables=(consistent snap)
echo "| table | processing | triangles | closed | border loops | genus | enclosed volume (mm³) | area (mm²) | zero-area | boundary edges | non-manifold edges | min angle < 1° | < 10° | < 20° | processing (s) |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
for table in "${tables[@]}"; do
for row in "${rows[@]}"; do
    name=${row%%|*}
    read -r -a flags <<<"${row#*|}"
    "$isotrack" extract --volume "$ct" --iso 400 --method track --seed 122,122,160 --json --table "$table" "${flags[@]}" |
        /usr/bin/python3 -c '
import json, sys
r = json.load(sys.stdin)
s = r["surfaces"][0]
q = s["quality"]
cells = [sys.argv[2], sys.argv[1], s["triangles"], "yes" if s["closed"] else "no", s["border_loops"], s["genus"],
         "-" if s["enclosed_volume"] is None else "%.0f" % s["enclosed_volume"], "%.0f" % s["area"],
         q["degenerate_triangles"], q["boundary_edges"], q["non_manifold_edges"],
         "%.2f%%" % (100 * q["min_angle_below_1"]), "%.2f%%" % (100 * q["min_angle_below_10"]),
         "%.2f%%" % (100 * q["min_angle_below_20"]), "%.2f" % r["process_seconds"]]
print("| " + " | ".join(str(c) for c in cells) + " |")' "$name" "$table"
done
done
