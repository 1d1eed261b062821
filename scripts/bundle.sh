#!/usr/bin/env bash
# Copies the built `isotrack` executable and the shared libraries it loads
# from this machine's packages (GDCM, GLFW, meshoptimizer, ...) into DIR, with
# a launcher DIR/isotrack that finds them, so that the command line runs on
# another x86-64 Linux machine that lacks those packages (the C library and
# the loader are the other machine's own: it needs glibc 2.36 or newer).
# Benchmarks on a borrowed many-core machine use it (bench/thread_scaling.sh).
#
# Usage: scripts/bundle.sh DIR [ISOTRACK]   (default: build/app/isotrack)
set -euo pipefail
out=${1:?usage: scripts/bundle.sh DIR [ISOTRACK]}
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=${2:-$repo/build/app/isotrack}
[[ -x $exe ]] || { echo "bundle.sh: $exe: no such executable (build it first: scripts/test.sh)" >&2; exit 1; }
rm -rf "$out"
mkdir -p "$out/bin" "$out/lib"
cp "$exe" "$out/bin/isotrack"
# Every library ldd resolves, but the C library's own parts and the loader.
ldd "$exe" | awk '$2 == "=>" && $3 ~ /^\// { print $3 }' | while read -r lib; do
    case $(basename "$lib") in
        libc.so.* | libm.so.* | libdl.so.* | libpthread.so.* | librt.so.* | ld-linux*) ;;
        *) cp -L "$lib" "$out/lib/" ;;
    esac
done
cat > "$out/isotrack" <<'EOF'
#!/usr/bin/env bash
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" exec "$here/bin/isotrack" "$@"
EOF
chmod +x "$out/isotrack"
# The bundle must not lean on what it was copied from.
missing=$(LD_LIBRARY_PATH="$out/lib" ldd "$out/bin/isotrack" | awk '/not found/ { print $1 }')
[[ -z $missing ]] || { echo "bundle.sh: not found: $missing" >&2; exit 1; }
echo "$out: isotrack and $(find "$out/lib" -type f | wc -l) libraries, $(du -sh "$out" | cut -f1)"
