#!/usr/bin/env bash
# get_ct.sh -- fetch the InVesalius "Cranium" CT volume as NRRD for isotrack.
#
# Usage: scripts/get_ct.sh [TARGET_DIR]
#   TARGET_DIR defaults to assets/ct under the repo root (a relative
#   TARGET_DIR is taken relative to the current directory).
#
# Source: Debian package invesalius-examples,
#   /usr/share/doc/invesalius-examples/examples/Cranium.inv3
# (a gzip'd tar holding main.plist + matrix.dat: raw int16, x fastest).
# Installs the package if it is missing and we are root; otherwise errors.
#
# Writes into TARGET_DIR:
#   cranium.raw   raw little-endian int16 samples (matrix.dat verbatim)
#   cranium.nhdr  detached NRRD header pointing at cranium.raw
#   cranium.nrrd  attached-header NRRD (header + raw bytes)
#   variants/     the same CT as gzip NRRD, MetaImage (.mhd, .mha), VTK
#                 legacy and big-endian NIfTI (.nii, .nii.gz), made by
#                 scripts/make_ct_variants.py
# Dimensions and spacing are read from main.plist inside the tar. The tar
# gives no origin, so no "space origin" is written (readers use 0,0,0).
#
# Idempotent: does nothing (but print the paths) when all outputs exist and
# are newer than Cranium.inv3. Uses only bash, tar, gzip, python3, coreutils.
set -euo pipefail

PKG=invesalius-examples
SRC=/usr/share/doc/invesalius-examples/examples/Cranium.inv3

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo_root=$(cd "$script_dir/.." && pwd)
target=${1:-$repo_root/assets/ct}

die() { echo "get_ct.sh: error: $*" >&2; exit 1; }

# Any python3 will do (stdlib only); prefer Debian's.
if [[ -x /usr/bin/python3 ]]; then PY=/usr/bin/python3
elif command -v python3 >/dev/null 2>&1; then PY=python3
else die "python3 not found"; fi

if [[ ! -f $SRC ]]; then
    if [[ $(id -u) -ne 0 ]]; then
        die "$SRC not found; install it first (as root):
    apt-get install -y --no-install-recommends $PKG"
    fi
    echo "get_ct.sh: installing $PKG ..." >&2
    export DEBIAN_FRONTEND=noninteractive
    apt_install() {
        apt-get install -y -o DPkg::Lock::Timeout=600 \
            --no-install-recommends "$PKG"
    }
    if ! apt_install; then
        apt-get -o DPkg::Lock::Timeout=600 update && apt_install \
            || die "apt-get install $PKG failed"
    fi
    [[ -f $SRC ]] || die "$PKG installed but $SRC is missing"
fi

mkdir -p "$target"
target=$(cd "$target" && pwd)
raw=$target/cranium.raw
nhdr=$target/cranium.nhdr
nrrd=$target/cranium.nrrd

up_to_date=1
for f in "$raw" "$nhdr" "$nrrd"; do
    if [[ ! -s $f || ! $f -nt $SRC ]]; then up_to_date=0; fi
done
make_variants() { "$PY" "$script_dir/make_ct_variants.py" "$target" || die "make_ct_variants.py failed"; }

if [[ $up_to_date -eq 1 ]]; then
    echo "get_ct.sh: up to date" >&2
    printf '%s\n' "$raw" "$nhdr" "$nrrd"
    make_variants
    exit 0
fi

tmp=$(mktemp -d "$target/.get_ct.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# Members live under a random temp-dir prefix (e.g. tmpocjcea/matrix.dat).
members=$(tar -tzf "$SRC")
mat_member=$(grep -E '(^|/)matrix\.dat$' <<<"$members" | head -n1) \
    || die "no matrix.dat in $SRC"
plist_member=$(grep -E '(^|/)main\.plist$' <<<"$members" | head -n1) || true
tar -xzmf "$SRC" -C "$tmp" "$mat_member" ${plist_member:+"$plist_member"}
mat=$tmp/$mat_member
plist=${plist_member:+$tmp/$plist_member}

# Geometry from main.plist (numpy shape is z,y,x); fall back to the known
# values if the plist is absent. Also checks the file size.
read -r nx ny nz sx sy sz < <("$PY" - "$mat" "$plist" <<'EOF'
import os, plistlib, sys
mat, plist = sys.argv[1], sys.argv[2]
shape, spacing, dtype = [108, 256, 256], [0.957, 0.957, 1.5], "int16"
if plist:
    with open(plist, "rb") as f:
        d = plistlib.load(f)
    m = d.get("matrix", {})
    shape = list(m.get("shape", shape))
    dtype = m.get("dtype", dtype)
    spacing = list(d.get("spacing", spacing))
if dtype != "int16":
    sys.exit("unexpected dtype %r" % dtype)
nz, ny, nx = shape
size = os.path.getsize(mat)
if size != nx * ny * nz * 2:
    sys.exit("matrix.dat is %d bytes, expected %d" % (size, nx * ny * nz * 2))
print(nx, ny, nz, *(repr(float(s)) for s in spacing))
EOF
) || die "could not read geometry"
[[ -n ${sz:-} ]] || die "could not read geometry"

header() {  # $1 = "data file: ..." line for a detached header, or empty
    cat <<EOF
NRRD0004
# InVesalius example "Cranium" CT (ProMED CT 0051), from
# $SRC (matrix.dat + main.plist); origin not given (0,0,0)
content: cranium
type: short
dimension: 3
sizes: $nx $ny $nz
spacings: $sx $sy $sz
kinds: domain domain domain
encoding: raw
endian: little
EOF
    if [[ -n $1 ]]; then
        echo "$1"
    else
        echo  # attached header ends at the first blank line; data follows
    fi
}

mv "$mat" "$tmp/cranium.raw"
chmod 644 "$tmp/cranium.raw"
header "data file: cranium.raw" > "$tmp/cranium.nhdr"
{ header ""; cat "$tmp/cranium.raw"; } > "$tmp/cranium.nrrd"

# Move into place (same filesystem, so each rename is atomic).
mv -f "$tmp/cranium.raw" "$raw"
mv -f "$tmp/cranium.nhdr" "$nhdr"
mv -f "$tmp/cranium.nrrd" "$nrrd"
printf '%s\n' "$raw" "$nhdr" "$nrrd"
make_variants
