#!/usr/bin/env bash
# The project's own C++ sources are formatted as .clang-format says: clang-format
# 14 --dry-run --Werror over core/, app/, ui/, tests/, bench/ and python/
# (third_party/ keeps its own style). Lists every file it would change.
#   format_check.sh CLANG_FORMAT SOURCE_DIR
# Exit 77 (skipped) when CLANG_FORMAT is not version 14: other versions format
# differently. `clang-format-14 -i FILE...` fixes what it reports.
set -euo pipefail
clang_format=$1 root=$2
version=$("$clang_format" --version)
if [[ $version != *"version 14."* ]]; then
    echo "skipped: $clang_format is not clang-format 14 ($version)"
    exit 77
fi
cd "$root"
mapfile -d '' files < <(find core app ui tests bench python -type f \( -name '*.cpp' -o -name '*.h' \) -print0 | sort -z)
unformatted=()
for f in "${files[@]}"; do
    "$clang_format" --style=file --dry-run --Werror "$f" > /dev/null 2>&1 || unformatted+=("$f")
done
if ((${#unformatted[@]})); then
    printf 'not formatted as .clang-format says (clang-format-14 -i FILE fixes it):\n'
    printf '  %s\n' "${unformatted[@]}"
    echo "${#unformatted[@]} of ${#files[@]} files"
    exit 1
fi
echo "all ${#files[@]} files are formatted"
