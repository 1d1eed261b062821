#!/usr/bin/env bash
# DICOM folders as they come (docs/formats.md#dicom-folders): a folder holding a
# good CT series, pydicom's radial MR series (MR700: seven projections through
# one axis, the orientation turning per slice) and a truncated file. `info`
# lists both series and the skipped file; `extract` reads the CT (the same
# triangles as the CT alone); a folder of series that form no volume fails
# with exit status 1 and one error listing them.
# Usage: dicom_folders.sh ISOTRACK WORK_DIR   (exit 77 without pydicom and numpy)
set -uo pipefail
isotrack=$1
work=$2
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd) || exit 2
py=/usr/bin/python3
mr700=$("$py" -c 'import os, numpy, pydicom.data as d
print(os.path.join(os.path.dirname(d.__file__), "test_files", "dicomdirtests", "98892003", "MR700"))' 2>/dev/null) ||
    { echo "skipped: $py has no pydicom or numpy"; exit 77; }
[[ -d $mr700 ]] || { echo "skipped: pydicom's MR700 series is missing ($mr700)"; exit 77; }
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 2

# A 24 x 24 x 20 int16 ball as a detached NRRD, written as a CT series by the
# project's own writer (CT Image Storage, rescaled, SliceThickness not the spacing).
"$py" - <<'PY' || exit 2
import numpy as np
z, y, x = np.mgrid[0:20, 0:24, 0:24]
r = np.sqrt((x - 11.5) ** 2 + (y - 11.5) ** 2 + ((z - 9.5) * 1.5) ** 2)
(1000 - 60 * r).astype("<i2").tofile("ball.raw")
open("ball.nhdr", "w").write("NRRD0004\ntype: short\ndimension: 3\nsizes: 24 24 20\nspacings: 0.75 0.75 1.25\n"
                             "encoding: raw\nendian: little\ndata file: ball.raw\n")
PY
"$py" "$repo/scripts/ct_to_dicom.py" ball.nhdr ct >/dev/null || exit 2
mkdir -p mixed mixed_none
cp -r ct mixed/ct
cp -r "$mr700" mixed/MR700
head -c 700 ct/slice_0000.dcm > mixed/broken.dcm
cp -r "$mr700" mixed_none/MR700
cp ct/slice_0007.dcm mixed_none/localizer.dcm
# What pydicom says the files hold, to check isotrack's listing against.
read -r ct_uid mr_uid < <("$py" -c 'import pydicom, sys
print(pydicom.dcmread(sys.argv[1]).SeriesInstanceUID, pydicom.dcmread(sys.argv[2] + "/4467").SeriesInstanceUID)' \
    ct/slice_0000.dcm "$mr700")

failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
json() { "$py" -c "import json, sys; j = json.load(open(sys.argv[1])); print($2)" "$1"; }

# info: both series, the CT read, the radial MR not a volume and why; the
# truncated file skipped with one warning line.
"$isotrack" info --volume mixed >info.txt 2>info.err || fail "info mixed: exit status $?"
grep -q "1: CT \"cranium\", 20 slices of 24 x 24, a volume (read)" info.txt || fail "info mixed: no CT line"
grep -q "2: MR \"ANGIO Projected from   C\", 7 slices of 16 x 16, not a volume: orientation differs per slice" \
    info.txt || fail "info mixed: no MR line"
grep -q "uid $ct_uid" info.txt && grep -q "uid $mr_uid" info.txt || fail "info mixed: UIDs not listed"
grep -q "skipped   1 file" info.txt || fail "info mixed: the skipped count is missing"
[[ $(wc -l <info.err) -eq 1 ]] && grep -q "^isotrack: mixed/broken.dcm: skipped: truncated: " info.err ||
    fail "info mixed: stderr is not one warning for broken.dcm: $(cat info.err)"
"$isotrack" info --volume mixed --json >info.json 2>/dev/null || fail "info --json mixed: exit status $?"
[[ $(json info.json 'len(j["series"]), j["dicom_skipped"], j["dicom_skipped_files"][0]["file"]') == \
   "2 1 mixed/broken.dcm" ]] || fail "info --json: series and skipped: $(cat info.json)"
[[ $(json info.json '[(s["uid"], s["volume"], s["problem"], s["read"]) for s in j["series"]]') == \
   "[('$ct_uid', True, None, True), ('$mr_uid', False, 'orientation differs per slice', False)]" ]] ||
    fail "info --json: series: $(json info.json 'j["series"]')"
[[ $(json info.json 'j["dims"]') == "[24, 24, 20]" ]] || fail "info --json: dims $(json info.json 'j["dims"]')"

# extract reads the CT: the same triangles as the CT folder alone, at the same
# (default) isovalue; --json says which series and what was skipped.
"$isotrack" extract --volume ct --json >alone.json || fail "extract ct: exit status $?"
"$isotrack" extract --volume mixed --json >mixed.json 2>extract.err || fail "extract mixed: exit status $?"
alone=$(json alone.json 'j["triangles"], j["isovalue"]')
[[ $(json mixed.json 'j["triangles"], j["isovalue"]') == "$alone" && ${alone%% *} != 0 ]] ||
    fail "extract mixed: $(json mixed.json 'j["triangles"], j["isovalue"]'), the CT alone: $alone"
[[ $(json mixed.json 'j["dicom_series"]["uid"], j["dicom_skipped"]') == "$ct_uid 1" ]] ||
    fail "extract --json: dicom_series and dicom_skipped: $(cat mixed.json)"
grep -q "^isotrack: mixed/broken.dcm: skipped: " extract.err || fail "extract mixed: no warning: $(cat extract.err)"
# Naming the radial series: its own error, naming a file.
"$isotrack" extract --volume mixed --series 2 >/dev/null 2>series.err
status=$?
[[ $status -eq 1 ]] && grep -q "mixed ImageOrientationPatient in one series" series.err ||
    fail "extract --series 2: exit status $status: $(cat series.err)"

# No series forms a volume: exit status 1 and one error listing them (info:
# the series on the following lines).
"$isotrack" extract --volume mixed_none >/dev/null 2>none.err
status=$?
expected="isotrack: mixed_none: no series forms a volume (1: MR 7 slices of 16 x 16, orientation differs per slice;"
expected+=" 2: CT 1 slice of 24 x 24, single slice)"
[[ $status -eq 1 && $(cat none.err) == "$expected" ]] ||
    fail "extract mixed_none: exit status $status, stderr: $(cat none.err)"
"$isotrack" info --volume mixed_none >/dev/null 2>none_info.err
status=$?
[[ $status -eq 1 && $(head -n1 none_info.err) == "isotrack: mixed_none: no series forms a volume:" ]] &&
    grep -q "^  1: MR .*orientation differs per slice (uid $mr_uid)" none_info.err &&
    grep -q "^  2: CT .*single slice (uid $ct_uid)" none_info.err ||
    fail "info mixed_none: exit status $status, stderr: $(cat none_info.err)"

# A DICOMDIR of the CT and a smaller second series: both listed, the CT read.
"$py" "$repo/scripts/ct_to_dicom.py" ball.nhdr dicomdir --dicomdir --second-series >/dev/null || exit 2
"$isotrack" info --volume dicomdir/DICOMDIR --json >dir.json || fail "info DICOMDIR: exit status $?"
[[ $(json dir.json 'len(j["series"]), j["dims"], j["dicom_skipped"]') == \
   "2 [24, 24, 20] 0" ]] || fail "info DICOMDIR: $(cat dir.json)"

if ((failures)); then
    echo "$failures check(s) failed"
    exit 1
fi
echo "ok: DICOM folders"
