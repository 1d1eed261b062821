#!/usr/bin/env bash
# Volumes bigger than memory: a sparse N^3 float32 raw file (default 2048: 32 GiB
# of address space, five balls written into it, holes elsewhere), the same
# samples behind a detached NRRD header, and a sparse uncompressed NIfTI of
# (N/2)^3. For each: info (header only), track on the smallest ball, all; then
# isotrack.open + track from Python. Prints wall time, peak RSS and the share of
# the file resident after track, and checks all's surfaces against in-memory
# crops around each ball.
# Usage: bench/big_volume.sh [N] [WORK_DIR]   (needs /usr/bin/python3 with numpy, nibabel)
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
isotrack=$repo/build/app/isotrack
n=${1:-2048}
work=${2:-/tmp/isotrack_big}
python=/usr/bin/python3
mkdir -p "$work" && cd "$work"
half=$((n / 2))

timed() {  # LABEL COMMAND...: one table row from /usr/bin/time
    local label=$1
    shift
    /usr/bin/time -f "%e %M" -o time.txt "$@" > out.json
    read -r seconds kib < time.txt
    printf '| %-34s | %8.2f s | %9.1f MiB |' "$label" "$seconds" "$(echo "$kib / 1024" | bc -l)"
}

echo "making big.raw ($n^3 float32, sparse) and nifti.nii (${half}^3)"
"$python" "$repo/bench/make_sparse_volume.py" big.raw "$n" 5 > balls.txt
"$python" - "$half" <<'EOF'
import sys
import nibabel, numpy as np
n = int(sys.argv[1])
header = nibabel.Nifti1Header()
header.set_data_shape((n, n, n)); header.set_data_dtype(np.float32); header.set_zooms((1.0, 1.0, 1.0))
header.set_sform(np.diag([-1.0, -1.0, 1.0, 1.0]), code=1)
header["vox_offset"] = 352
with open("nifti.nii", "wb") as f:
    f.write(header.binaryblock + b"\0" * 4)
    f.truncate(352 + n ** 3 * 4)
volume = np.memmap("nifti.nii", dtype="<f4", mode="r+", offset=352, shape=(n, n, n))  # (z, y, x) on disk
c, r = n // 3, 9
z, y, x = np.mgrid[c - r - 2:c + r + 3, c - r - 2:c + r + 3, c - r - 2:c + r + 3]
volume[c - r - 2:c + r + 3, c - r - 2:c + r + 3, c - r - 2:c + r + 3] = np.clip(
    r + 0.5 - np.sqrt((x - c) ** 2 + (y - c) ** 2 + (z - c) ** 2), 0, 1)
volume.flush()
EOF
printf 'NRRD0004\ntype: float\ndimension: 3\nsizes: %d %d %d\nendian: little\nencoding: raw\ndata file: big.raw\n' \
    "$n" "$n" "$n" > big.nhdr
smallest=$(sort -k2 -n balls.txt | head -1 | cut -d' ' -f1)
c=$((half / 3))
# The NIfTI's sform is diag(-1,-1,1): LPS x = i, y = j.
declare -A source=([raw]="--volume big.raw --dims $n,$n,$n --type float32" [nhdr]="--volume big.nhdr"
                   [nifti]="--volume nifti.nii")
declare -A seed=([raw]=$smallest [nhdr]=$smallest [nifti]="$c,$c,$c")

echo
echo "| step | wall | peak RSS | notes |"
echo "|---|---|---|---|"
for kind in raw nhdr nifti; do
    read -ra args <<< "${source[$kind]}"
    timed "$kind: info" "$isotrack" info "${args[@]}" --json
    echo " values read: $("$python" -c "import json; print(json.load(open('out.json'))['values_read'])") |"
    timed "$kind: track --seed ${seed[$kind]}" "$isotrack" extract "${args[@]}" --iso 0.5 --method track \
        --seed "${seed[$kind]}" --json
    "$python" -c "
import json; j = json.load(open('out.json'))
print(f\" {j['triangles']} triangles, {j['volume_resident_bytes'] / 2**20:.1f} MiB of the file resident \
({100 * j['volume_resident_bytes'] / j['volume_bytes']:.4f}%) |\")"
    timed "$kind: all" "$isotrack" extract "${args[@]}" --iso 0.5 --method all --json
    "$python" -c "
import json; j = json.load(open('out.json'))
print(f\" {len(j['surfaces'])} surfaces, triangles {sorted(s['triangles'] for s in j['surfaces'])} |\")"
done

echo
echo "Crops: each ball's triangles extracted from an in-memory copy of the region around it"
while read -r centre radius; do
    "$python" - "$centre" "$radius" "$n" <<'EOF'
import sys
import numpy as np
x, y, z = (int(v) for v in sys.argv[1].split(","))
r, n = int(sys.argv[2]) + 3, int(sys.argv[3])
volume = np.memmap("big.raw", dtype="<f4", mode="r", shape=(n, n, n))
np.ascontiguousarray(volume[z - r:z + r + 1, y - r:y + r + 1, x - r:x + r + 1]).tofile("crop.raw")
open("crop.size", "w").write(str(2 * r + 1))
EOF
    s=$(cat crop.size)
    "$isotrack" extract --volume crop.raw --dims "$s,$s,$s" --type float32 --iso 0.5 --method all --json > crop.json
    echo "  ball at $centre: $("$python" -c "import json; print(json.load(open('crop.json'))['triangles'])") triangles"
done < balls.txt

echo
cat > open_track.py <<EOF
import resource, sys, time
sys.path.insert(0, "$repo/build/python")
import isotrack
start = time.perf_counter()
volume = isotrack.open("big.nhdr")
surface = isotrack.track(volume, 0.5, seed=tuple(float(v) for v in "$smallest".split(",")))
print(f"python: isotrack.open('big.nhdr') + track: {time.perf_counter() - start:.2f} s, "
      f"{surface.triangle_count} triangles, peak RSS "
      f"{resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024:.1f} MiB")
EOF
"$python" open_track.py
