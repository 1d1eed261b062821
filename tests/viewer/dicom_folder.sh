#!/usr/bin/env bash
# A script's `load DIR` in the real window on a DICOM folder as it comes: a CT
# series (a ball, written by scripts/ct_to_dicom.py), pydicom's radial MR
# series and a truncated file. The viewer opens the CT (the surfaces `isotrack
# extract` finds there, the first exported byte-equal to extract's), warns
# once about the truncated file, and a folder where no series forms a volume
# is a one-line script error listing them.
#   dicom_folder.sh ISOTRACK VIEWER_CHECK OUT_DIR   (exit 77 without pydicom and numpy)
set -euo pipefail
isotrack=$1 check=$2 out=$3
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
py=/usr/bin/python3
mr700=$("$py" -c 'import os, numpy, pydicom.data as d
print(os.path.join(os.path.dirname(d.__file__), "test_files", "dicomdirtests", "98892003", "MR700"))' 2>/dev/null) ||
    { echo "skipped: $py has no pydicom or numpy"; exit 77; }
[[ -d $mr700 ]] || { echo "skipped: pydicom's MR700 series is missing"; exit 77; }
rm -rf "$out" && mkdir -p "$out" && cd "$out"
"$py" - <<'PY'
import numpy as np
z, y, x = np.mgrid[0:20, 0:24, 0:24]
r = np.sqrt((x - 11.5) ** 2 + (y - 11.5) ** 2 + ((z - 9.5) * 1.5) ** 2)
(1000 - 60 * r).astype("<i2").tofile("ball.raw")
open("ball.nhdr", "w").write("NRRD0004\ntype: short\ndimension: 3\nsizes: 24 24 20\nspacings: 0.75 0.75 1.25\n"
                             "encoding: raw\nendian: little\ndata file: ball.raw\n")
PY
"$py" "$repo/scripts/ct_to_dicom.py" ball.nhdr scan/ct > /dev/null
cp -r "$mr700" scan/MR700
head -c 700 scan/ct/slice_0000.dcm > scan/broken.dcm
mkdir -p flat && cp -r "$mr700" flat/MR700

printf 'load scan\niso 500\nwait\nexport 0 viewer_surface.ply\nquit\n' > session.isotrack
# One thread each: the vertex order of --method all depends on the thread count.
"$isotrack" --script session.isotrack --threads 1 --size 960x600 --json > session.json 2> session.err
surfaces=$("$check" field session.json surfaces | grep -o '"id"' | wc -l)
"$isotrack" extract --volume scan --iso 500 --method all --threads 1 --out-dir extract > /dev/null 2>&1
expected=$(ls extract | wc -l)
echo "load scan: $surfaces surfaces (extract: $expected); stderr: $(cat session.err)"
(( surfaces == expected && surfaces > 0 ))
cmp viewer_surface.ply extract/surface_000.ply
[[ $(cat session.err) == "isotrack: scan/broken.dcm: skipped: truncated: "* && $(wc -l < session.err) -eq 1 ]]

printf 'load flat\nquit\n' > flat.isotrack
if "$isotrack" --script flat.isotrack --size 960x600 > /dev/null 2> flat.err; then
    echo "a folder of no volume loaded"; exit 1
fi
cat flat.err
(( $(wc -l < flat.err) == 1 ))
grep -q "flat: no series forms a volume: .*mixed ImageOrientationPatient in one series" flat.err
