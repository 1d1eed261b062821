#!/usr/bin/env bash
# Volumes mapped from their files, at a scale CI affords: sparse float32 raw
# cubes with a few balls (bench/make_sparse_volume.py), holes elsewhere.
# - info reads a big mapped volume's header only, and says it is mapped;
# - track touches under 1% of the file; all finds every ball, each with the
#   triangles of the same ball extracted from an in-memory crop;
# - a file truncated while `all` streams over it: one line naming it, exit 1,
#   no core dump, and the mesh the command was to replace left as it was;
# - a gzip volume whose decoded samples exceed memory is refused at once;
# - the snap table and the contour tree refuse a volume whose working arrays
#   exceed the memory left (ulimit -v), naming the file.
# Usage: mapped_volumes.sh ISOTRACK SOURCE_DIR WORK_DIR   (exit 77: no numpy)
set -euo pipefail
isotrack=$1
source_dir=$2
work=$3
python=/usr/bin/python3
"$python" -c "import numpy" 2>/dev/null || { echo "skipped: $python has no numpy"; exit 77; }
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*"; exit 1; }
json() {  # FILE EXPRESSION: the expression over the JSON object j; a tuple printed space-separated
    "$python" -c "import json,sys; j=json.load(open(sys.argv[1])); v=eval(sys.argv[2]); print(*v) if isinstance(v, tuple) else print(v)" "$@"
}

"$python" "$source_dir/bench/make_sparse_volume.py" small.raw 384 4 > balls.txt
raw=(--dims 384,384,384 --type float32)

# info: mapped, values read (under 1 GiB); a 1 TiB sparse volume: header only, at once.
"$isotrack" info --volume small.raw "${raw[@]}" --json > info.json
[[ $(json info.json "j['mapped'], j['values_read'], j['range']") == "True True [0.0, 1.0]" ]] ||
    fail "info on small.raw: $(cat info.json)"
truncate -s 1T huge.raw
timeout 5 "$isotrack" info --volume huge.raw --dims 8192,8192,4096 --type float32 --json > huge.json ||
    fail "info on a 1 TiB sparse file did not finish within 5 s"
[[ $(json huge.json "j['mapped'], j['values_read'], j['range'], j['suggested_isovalue']") == "True False None None" ]] ||
    fail "info on huge.raw read values: $(cat huge.json)"

# track: one ball, under 1% of the file resident.
read -r centre radius < balls.txt
"$isotrack" extract --volume small.raw "${raw[@]}" --iso 0.5 --method track --seed "$centre" --json > track.json
share=$(json track.json "j['volume_resident_bytes'] / j['volume_bytes']")
"$python" -c "import sys; sys.exit(0 if $share < 0.01 else 1)" || fail "track kept $share of the file resident"
echo "track: $(json track.json "j['triangles']") triangles, $share of the file resident"

# all: every ball, each as extracted from an in-memory crop around it.
"$isotrack" extract --volume small.raw "${raw[@]}" --iso 0.5 --method all --json > all.json
[[ $(json all.json "len(j['surfaces'])") == "$(wc -l < balls.txt)" ]] || fail "all found $(json all.json "len(j['surfaces'])") surfaces"
n=0
while read -r centre radius; do
    "$python" - "$centre" "$radius" <<'EOF'
import sys
import numpy as np
x, y, z = (int(v) for v in sys.argv[1].split(","))
r = int(sys.argv[2]) + 3
volume = np.memmap("small.raw", dtype="<f4", mode="r", shape=(384, 384, 384))
np.ascontiguousarray(volume[z - r:z + r + 1, y - r:y + r + 1, x - r:x + r + 1]).tofile("crop.raw")
print(2 * r + 1, file=open("crop.size", "w"))
EOF
    s=$(cat crop.size)
    "$isotrack" extract --volume crop.raw --dims "$s,$s,$s" --type float32 --iso 0.5 --method all --json > crop.json
    want=$(json crop.json "j['triangles']")
    json all.json "sorted(s['triangles'] for s in j['surfaces'])" | grep -qw "$want" ||
        fail "the ball at $centre has $want triangles in its crop, none such in all"
    n=$((n + 1))
done < balls.txt
echo "all: $n balls, each equal to its crop"

# Truncated while all streams over it (a 12 GiB sparse cube, cut after 0.3 s).
truncate -s $((1536 * 1536 * 1536 * 4)) cut.raw
echo "old mesh" > cut.ply
"$isotrack" extract --volume cut.raw --dims 1536,1536,1536 --type float32 --iso 0.5 --method all \
    --out cut.ply > cut.out 2> cut.err &
pid=$!
sleep 0.3
truncate -s 1M cut.raw
status=0
wait $pid || status=$?
[[ $status -eq 1 ]] || fail "truncated file: exit status $status ($(cat cut.err))"
[[ $(wc -l < cut.err) -eq 1 ]] && grep -q "cut.raw: the file was truncated or removed while it was read" cut.err ||
    fail "truncated file: $(cat cut.err)"
[[ $(cat cut.ply) == "old mesh" ]] || fail "the failed run wrote over cut.ply"
echo "truncated: $(cat cut.err)"

# gzip samples decoded into memory: refused before anything is allocated.
printf 'NRRD0004\ntype: float\ndimension: 3\nsizes: 8192 8192 8192\nendian: little\nencoding: gzip\n\n' > huge.nrrd
head -c 4096 /dev/zero | gzip >> huge.nrrd
start=$(date +%s%N)
if "$isotrack" info --volume huge.nrrd 2> gzip.err; then fail "a 2 TiB gzip volume was accepted"; fi
elapsed_ms=$((($(date +%s%N) - start) / 1000000))
[[ $(wc -l < gzip.err) -eq 1 ]] && grep -q "huge.nrrd: .* need 2048.0 GiB of memory, more than the" gzip.err ||
    fail "gzip refusal: $(cat gzip.err)"
[[ $elapsed_ms -lt 1000 ]] || fail "gzip refusal took $elapsed_ms ms"
echo "gzip: $(cat gzip.err) ($elapsed_ms ms)"
# Work that keeps bytes per sample beside a mapped volume (the snap table's
# states, the contour tree's build) is refused before it allocates, naming the
# file, when they do not fit: here under an address-space limit (ulimit -v) that
# leaves under 1 GiB beside a 1 GiB sparse file.
truncate -s 1G zeros.raw
zeros=(--volume zeros.raw --dims 1024,1024,1024 --type uint8 --iso 0.5)
for run in "extract --table snap" "extract --method tree" "tree"; do
    # shellcheck disable=SC2086
    if (ulimit -v 2000000 && exec "$isotrack" $run "${zeros[@]}") > /dev/null 2> limit.err; then
        fail "$run: a volume whose working arrays exceed the limit was accepted"
    fi
    want="zeros.raw: the snap table's sample states, 3 bytes a sample: 1024 x 1024 x 1024 samples need 3.0 GiB, more"
    [[ $run == "extract --table snap" ]] ||
        want="zeros.raw: the contour tree's build, 24 bytes a sample: 1024 x 1024 x 1024 samples need 24.0 GiB, more"
    [[ $(wc -l < limit.err) -eq 1 ]] && grep -q "^isotrack: $want than the .* of memory available$" limit.err ||
        fail "$run: $(cat limit.err)"
    echo "$run under ulimit -v: $(cat limit.err)"
done
echo "mapped volumes: all checks passed"
