#!/usr/bin/env bash
# The viewer on a raw file, and its exports by extension (raw_export.isotrack):
# blobs:32 written as NRRD, its samples cut out as a headerless file, opened
# with --dims 32,32,32 --type float32: the same surfaces as `isotrack extract`
# gives for the field; the
# first surface exported as PLY, OBJ and STL, each in its own format with the
# surface's triangle count; an unknown extension is a one-line error. Then the
# same samples as an oblique, x-flipped NRRD (det -1): the viewer's export is
# byte-equal to `extract --out-dir`'s surface_000.ply, both in the LPS world.
#   raw_export.sh ISOTRACK VIEWER_CHECK OUT_DIR
set -euo pipefail
isotrack=$1 check=$2 out=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$out"
cd "$out"
rm -rf raw_surface.* oblique_surface.ply oblique_extract
"$isotrack" field blobs:32 --out blobs32.nrrd > /dev/null
tail -c $((32 * 32 * 32 * 4)) blobs32.nrrd > blobs32.raw
"$isotrack" --volume blobs32.raw --dims 32,32,32 --type float32 --iso 0.25 --script "$here/raw_export.isotrack" \
    --size 960x600 --json > raw_export.json
surfaces=$("$check" field raw_export.json surfaces | grep -o '"id"' | wc -l)
triangles=$("$check" field raw_export.json surfaces.0.triangles)
expected=$("$isotrack" extract --field blobs:32 --iso 0.25 --method all | grep -o '[0-9]* surfaces' | cut -d' ' -f1)
echo "raw file: $surfaces surfaces (extract on the field: $expected), the first has $triangles triangles"
(( surfaces == expected ))
head -c 3 raw_surface.ply | grep -q ply
(( $(grep -c '^f ' raw_surface.obj) == triangles ))
(( $(stat -c %s raw_surface.stl) == 84 + 50 * triangles ))
printf 'wait\nexport 0 surface.xyz\nquit\n' > bad_export.isotrack
if "$isotrack" --volume blobs32.raw --dims 32,32,32 --type float32 --script bad_export.isotrack 2> bad_export.err; then
    echo "an export to .xyz succeeded"; exit 1
fi
cat bad_export.err
grep -q 'unsupported mesh file extension' bad_export.err
(( $(wc -l < bad_export.err) == 1 ))
# Oblique and mirrored: the export leaves the grid for the world frame as extract's does.
{
    printf 'NRRD0004\ntype: float\ndimension: 3\nsizes: 32 32 32\nspace: left-posterior-superior\n'
    printf 'space directions: (-0.8,0.6,0) (0.6,0.8,0) (0,0,1.5)\nspace origin: (10,-20,5)\n'
    printf 'endian: little\nencoding: raw\n\n'
    cat blobs32.raw
} > oblique.nrrd
printf 'wait\nexport 0 oblique_surface.ply\nquit\n' > oblique_export.isotrack
# One thread each: the vertex order of --method all depends on the thread count.
"$isotrack" --volume oblique.nrrd --iso 0.25 --threads 1 --script oblique_export.isotrack --size 960x600 > /dev/null
"$isotrack" extract --volume oblique.nrrd --iso 0.25 --method all --threads 1 --out-dir oblique_extract > /dev/null
cmp oblique_surface.ply oblique_extract/surface_000.ply
echo "oblique, x-flipped NRRD: the viewer's export equals extract's surface_000.ply ($(stat -c %s oblique_surface.ply) bytes)"
# And not the grid-frame mesh: the transform was applied.
"$isotrack" --volume oblique.nrrd --iso 0.25 --threads 1 --frame voxel --script oblique_export.isotrack --size 960x600 > /dev/null
if cmp -s oblique_surface.ply oblique_extract/surface_000.ply; then echo "--frame voxel changed nothing"; exit 1; fi
