#!/usr/bin/env bash
# Smoothing, decimation and undo of one surface in the viewer (script commands
# smooth, decimate, undo; the panel's buttons send the same actions): each
# export is byte-equal to `isotrack extract --method all --out-dir`'s
# surface_000.ply with the same --smooth or --decimate, and after undo to the
# unprocessed one. blobs:32, one thread (the vertex order of all depends on it).
#   mesh_processing.sh ISOTRACK OUT_DIR
set -euo pipefail
isotrack=$1 out=$2
rm -rf "$out" && mkdir -p "$out" && cd "$out"
cat > session.isotrack <<'SESSION'
wait
smooth 0 20
export 0 smoothed.ply
undo 0
export 0 undone.ply
decimate 0 0.1
export 0 decimated.ply
smooth 0 10
undo 0
export 0 decimated_again.ply
quit
SESSION
"$isotrack" --field blobs:32 --threads 1 --script session.isotrack --size 960x600 > /dev/null
extract() { "$isotrack" extract --field blobs:32 --method all --threads 1 --out-dir "$1" "${@:2}" > /dev/null; }
extract plain
extract smooth --smooth 20
extract decimate --decimate 0.1
cmp smoothed.ply smooth/surface_000.ply
cmp undone.ply plain/surface_000.ply
cmp decimated.ply decimate/surface_000.ply
cmp decimated_again.ply decimate/surface_000.ply
if cmp -s smoothed.ply plain/surface_000.ply; then echo "smoothing changed nothing"; exit 1; fi
echo "viewer: smooth, undo, decimate, smooth + undo: exports equal extract's ($(stat -c %s decimated.ply) bytes decimated)"
