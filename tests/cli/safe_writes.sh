#!/usr/bin/env bash
# Overwriting an export when the disk cannot take the new one: the old file stays
# byte-identical, no temporary is left, and the message names the file and the cause.
# The full disk is the file-size limit (ulimit -f, with SIGXFSZ ignored so that
# write() fails with EFBIG instead of killing the process), which needs no root.
# Usage: safe_writes.sh ISOTRACK WORK_DIR
set -euo pipefail
isotrack=$1
work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*"; exit 1; }

"$isotrack" field blobs:32 --out blobs.nrrd >/dev/null
"$isotrack" field sphere:32 --out sphere.nrrd >/dev/null
limited() { (ulimit -f 4; trap '' XFSZ; "$@"); }  # at most 4 KiB per file
for target in mesh.ply mesh.obj mesh.stl field.nrrd; do
    "$isotrack" extract --volume sphere.nrrd --out old.ply >/dev/null
    cp old.ply "$target"
    case $target in
        field.nrrd) cmd=("$isotrack" field blobs:32 --out "$target") ;;
        *) cmd=("$isotrack" extract --volume blobs.nrrd --out "$target") ;;
    esac
    if limited "${cmd[@]}" >/dev/null 2>err.txt; then fail "$target: writing past the limit succeeded"; fi
    cmp -s old.ply "$target" || fail "$target was changed by the failed write"
    [[ $(wc -l < err.txt) -eq 1 ]] || fail "$target: expected one line, got: $(cat err.txt)"
    grep -q "$target: cannot write: File too large" err.txt || fail "$target: unhelpful message: $(cat err.txt)"
    leftovers=$(ls -A | grep -c '\.tmp\.' || true)
    [[ $leftovers -eq 0 ]] || fail "$target: temporary files left: $(ls -A)"
    # Without the limit the same command replaces the file.
    "${cmd[@]}" >/dev/null
    cmp -s old.ply "$target" && fail "$target was not replaced"
done

# Per-surface exports: a surface file that cannot be written keeps its old contents.
mkdir -p surfaces
"$isotrack" extract --volume blobs.nrrd --out surfaces/surface_000.ply >/dev/null
cp surfaces/surface_000.ply old_surface.ply
if limited "$isotrack" extract --volume sphere.nrrd --method all --out-dir surfaces >/dev/null 2>err.txt; then
    fail "--out-dir past the limit succeeded"
fi
cmp -s old_surface.ply surfaces/surface_000.ply || fail "surface_000.ply was changed by the failed write"
grep -q "surface_000.ply: cannot write: File too large" err.txt || fail "unhelpful message: $(cat err.txt)"
echo ok
