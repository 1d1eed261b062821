#!/usr/bin/env bash
# isotrack extract on hostile volumes: exit status 1 (not 0, not a signal), and
# stderr exactly one line that starts with "isotrack: " and names the file.
# Usage: hostile_volumes.sh ISOTRACK WORK_DIR
set -uo pipefail
isotrack=$1
work=$2
corpus=$(cd "$(dirname "${BASH_SOURCE[0]}")/../fuzz/corpus" && pwd) || exit 2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 2

nrrd_head='NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3 2\nendian: little\nencoding: raw\n'
samples=$(printf '%048d' 0)
printf "$nrrd_head\n%s" "${samples:0:40}" > truncated.nrrd
printf "${nrrd_head/4 3 2/4 0 2}\n%s" "$samples" > zero_dims.nrrd
printf "${nrrd_head/4 3 2/100000 100000 100000}\n%s" "$samples" > absurd.nrrd
printf "${nrrd_head/short/complex}\n%s" "$samples" > unknown_type.nrrd
printf "${nrrd_head/raw/gzip}\n%s" "not gzip at all" > corrupt_gzip.nrrd
printf "${nrrd_head}data file: gone.raw\n" > missing_data.nhdr
head -c 3000 /dev/urandom > random.nii
head -c 3000 /dev/urandom > random.nii.gz
printf 'ObjectType = Image\nNDims = 3\nDimSize = 4 3 2\nElementType = MET_SHORT\nElementDataFile = LOCAL\n%s' \
    "${samples:0:30}" > short.mha
printf '# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 2 2 2\nPOINT_DATA 8\nSCALARS s float\nLOOKUP_TABLE default\n1 2 3\n' \
    > truncated_ascii.vtk
printf 'NRRD0004\ntype: float\ndimension: 3\nsizes: 2 2 2\nendian: little\nencoding: raw\n\n' > all_nan.nrrd
for _ in 1 2 3 4 5 6 7 8; do printf '\x00\x00\xc0\x7f' >> all_nan.nrrd; done
mkdir -p folder.nrrd
printf 'abc' > scan.dcm
# DICOM, from the fuzz corpus's 8 x 6 slice: cut in the pixel data, cut before it,
# a pixel data length past the end, 65535 x 65535 samples, and a folder holding a
# series whose second file is another size. And a file GDCM aborts on (a file meta
# group in implicit VR, with nothing after it): GDCM runs in a child process.
dicom=$corpus/dicom/explicit.dcm
head -c 600 "$dicom" > truncated.dcm
head -c 500 "$dicom" > no_pixels.dcm
cp "$corpus/dicom/implicit_meta_group.dcm" .
/usr/bin/python3 - "$dicom" <<'PY'
import struct, sys
good = open(sys.argv[1], "rb").read()
pixels = good.rindex(b"\xe0\x7f\x10\x00OW")  # (7FE0,0010) OW, then 2 reserved bytes and the length
open("lying_length.dcm", "wb").write(good[:pixels + 8] + struct.pack("<I", 0x7ffffff0) + good[pixels + 12:])
absurd = good
for tag in (b"\x28\x00\x10\x00US", b"\x28\x00\x11\x00US"):  # Rows, Columns
    at = absurd.index(tag) + 8
    absurd = absurd[:at] + b"\xff\xff" + absurd[at + 2:]
open("absurd.dcm", "wb").write(absurd)
rows = good.index(b"\x28\x00\x10\x00US") + 8
bigger = good[:rows] + struct.pack("<H", 7) + good[rows + 2:]
import os
os.makedirs("mixed_series", exist_ok=True)
open("mixed_series/a.dcm", "wb").write(good)
position = b"1\\2\\3"
open("mixed_series/b.dcm", "wb").write(bigger.replace(position, b"1\\2\\4"))
PY
# VTK XML ImageData: truncated raw data, bad base64, a zlib header whose sizes lie,
# a huge WholeExtent, a Piece file with elements nested without end, an array
# that is not there, and an unknown compressor.
/usr/bin/python3 - <<'PY'
import base64, struct, zlib
def vti(data_array, extent="0 3 0 2 0 1", appended=b"", compressor="", nest=""):
    head = ('<?xml version="1.0"?>\n<VTKFile type="ImageData" version="1.0" byte_order="LittleEndian" '
            'header_type="UInt32"' + (f' compressor="{compressor}"' if compressor else "") + '>\n'
            f'<ImageData WholeExtent="{extent}" Origin="0 0 0" Spacing="1 1 1">\n'
            f'<Piece Extent="{extent}">{nest}<PointData>{data_array}</PointData></Piece>\n</ImageData>\n')
    tail = (b'<AppendedData encoding="raw">\n_' + appended + b'\n</AppendedData>\n' if appended else b"")
    return head.encode() + tail + b"</VTKFile>\n"
samples = struct.pack("<24h", *range(24))
appended = '<DataArray type="Int16" Name="s" format="appended" offset="0"/>'
open("truncated.vti", "wb").write(vti(appended, appended=struct.pack("<I", 48) + samples[:30])[:-40])
open("bad_base64.vti", "wb").write(vti('<DataArray type="Int16" Name="s" format="binary">AAAA*!!!</DataArray>'))
block = zlib.compress(samples)
lying = struct.pack("<4I", 1, 1 << 30, 0, len(block)) + block
open("lying_zlib.vti", "wb").write(vti(appended, appended=lying, compressor="vtkZLibDataCompressor"))
short = struct.pack("<4I", 1, 32768, 48, len(block)) + block
open("cut_zlib.vti", "wb").write(vti(appended, appended=short, compressor="vtkZLibDataCompressor")[:-50])
open("huge_extent.vti", "wb").write(vti(appended, extent="0 999999 0 999999 0 999999",
                                        appended=struct.pack("<I", 48) + samples))
open("nested.vti", "wb").write(vti(appended, nest="<a>" * 100 + "</a>" * 100))
open("no_array.vti", "wb").write(vti('<DataArray type="Float32" Name="v" NumberOfComponents="3" format="ascii">'
                                      '</DataArray>'))
open("lz4.vti", "wb").write(vti(appended, appended=lying, compressor="vtkLZ4DataCompressor"))
# ParaView collections: a missing step file, a .pvd naming a .pvd (itself), a bad
# timestep, no DataSet, and elements nested without end.
def pvd(body):
    return f'<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1"><Collection>{body}</Collection></VTKFile>\n'
open("missing_step.pvd", "w").write(pvd('<DataSet timestep="0" file="gone.vti"/>'))
open("self.pvd", "w").write(pvd('<DataSet timestep="0" file="self.pvd"/>'))
open("bad_time.pvd", "w").write(pvd('<DataSet timestep="soon" file="truncated.vti"/>'))
open("empty.pvd", "w").write(pvd(""))
open("nested.pvd", "w").write(pvd("<a>" * 100 + "</a>" * 100))
PY

failures=0
check() {  # check FILE [extra isotrack args...]
    local file=$1
    shift
    "$isotrack" extract --volume "$file" "$@" >stdout.txt 2>stderr.txt
    local status=$?
    local lines
    lines=$(wc -l <stderr.txt)
    local first
    first=$(head -n1 stderr.txt)
    if [[ $status -ne 1 ]]; then
        echo "FAIL $file: exit status $status, expected 1 ($( ((status > 128)) && echo "signal $((status - 128))"))"
    elif [[ $lines -ne 1 ]]; then
        echo "FAIL $file: stderr has $lines lines, expected 1:"; cat stderr.txt
    elif [[ $first != "isotrack: "* ]]; then
        echo "FAIL $file: stderr does not start with \"isotrack: \": $first"
    elif [[ $first != *"$file"* ]]; then
        echo "FAIL $file: stderr does not name the file: $first"
    else
        echo "ok   $first"
        return
    fi
    failures=$((failures + 1))
}

for f in truncated.nrrd zero_dims.nrrd absurd.nrrd unknown_type.nrrd corrupt_gzip.nrrd missing_data.nhdr \
         random.nii random.nii.gz short.mha truncated_ascii.vtk all_nan.nrrd folder.nrrd scan.dcm absent.vtk \
         absent.vti; do
    check "$f"
done
# The DICOM cases also say what is wrong.
for case in "truncated.dcm|declares 96 bytes, 34 remain" "no_pixels.dcm|no pixel data" \
            "lying_length.dcm|declares 2147483632 bytes" "absurd.dcm|65535 x 65535 x 1 samples need" \
            "mixed_series|mixed sizes in one series" \
            "implicit_meta_group.dcm|the DICOM library failed on it (it crashed: Aborted)"; do
    expect=${case#*|}
    check "${case%%|*}"
    if ! grep -q "$expect" stderr.txt; then
        echo "FAIL ${case%%|*}: stderr lacks \"$expect\": $(cat stderr.txt)"
        failures=$((failures + 1))
    fi
done
for case in "truncated.vti|truncated" "bad_base64.vti|not valid base64" \
            "lying_zlib.vti|compression header says 1 blocks of 1073741824 bytes" \
            "cut_zlib.vti|truncated" "huge_extent.vti|WholeExtent" "nested.vti|nested deeper than 8" \
            "no_array.vti|no one-component PointData array" "lz4.vti|vtkLZ4DataCompressor" \
            "missing_step.pvd|cannot read" "self.pvd|is another .pvd" "bad_time.pvd|not a finite number" \
            "empty.pvd|no DataSet" "nested.pvd|nested deeper than 8"; do
    expect=${case#*|}
    check "${case%%|*}"
    if ! grep -q "$expect" stderr.txt; then
        echo "FAIL ${case%%|*}: stderr lacks \"$expect\": $(cat stderr.txt)"
        failures=$((failures + 1))
    fi
done
check short.mha --method all
check all_nan.nrrd --method all
printf '%048d' 0 > layout.raw
check layout.raw --dims 4,3,3 --type int16

if ((failures)); then
    echo "$failures hostile volume(s) not refused as expected"
    exit 1
fi
