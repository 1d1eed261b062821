#!/usr/bin/env bash
# A scripted viewer session compared against a golden screenshot.
#   session_golden.sh ISOTRACK VIEWER_CHECK OUT_DIR NAME
# Runs tests/viewer/NAME.isotrack with --deterministic in a 960x600 window (run
# it under xvfb-run), then checks NAME.png against tests/golden/viewer_NAME.png
# (metric: tests/viewer/viewer_check.cpp) and the --json summary. When
# tests/viewer/NAME.expect exists, each of its lines "KEY VALUE" (a summary
# field as viewer_check field prints it) must hold too; when NAME.check exists,
# each of its lines is a viewer_check command run with the summary's path after
# its first word.
set -euo pipefail
isotrack=$1 check=$2 out=$3 name=$4
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$out"
cd "$out"
rm -f "$name.png" "$name.json"
"$isotrack" --script "$here/$name.isotrack" --deterministic --size 960x600 --json > "$name.json"
"$check" summary "$name.json"
"$check" golden "$out/$name.png" "viewer_$name"
expect="$here/$name.expect"
if [[ -f $expect ]]; then
    while read -r key value; do
        [[ -z $key || $key == \#* ]] && continue
        got=$("$check" field "$name.json" "$key")
        if [[ $got != "$value" ]]; then
            echo "$name.json: $key is $got, expected $value"
            exit 1
        fi
        echo "$key = $got"
    done < "$expect"
fi
checks="$here/$name.check"
if [[ -f $checks ]]; then
    while read -r command args; do
        [[ -z $command || $command == \#* ]] && continue
        # shellcheck disable=SC2086
        "$check" "$command" "$name.json" $args
    done < "$checks"
fi
