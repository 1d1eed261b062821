#!/usr/bin/env bash
# Frame time drawing many surfaces: one call per GPU arena page (what isotrack
# draws with) against one call per surface, through `isotrack render --frames`
# (each frame timed to the end of the GPU's work with glFinish, and the part
# spent issuing its GL calls; medians). docs/performance.md "Drawing many surfaces" holds the table.
#   bench/draw_frames.sh [ISOTRACK] [FRAMES] [--gl osmesa|egl|auto]
set -euo pipefail
isotrack=${1:-build/app/isotrack}
frames=${2:-9}
gl=${3:-osmesa}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

field() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])" "$1" "$2"; }

printf '| scene | surfaces | triangles | path | draw calls | frame (ms) | issuing the calls (ms) |\n|---|---:|---:|---|---:|---:|---:|\n'
for scene in "noise:128 all" "gyroid:256 mc"; do
    read -r spec method <<<"$scene"
    for path in batched per-surface; do
        extra=()
        [[ $path == per-surface ]] && extra=(--one-call-per-surface)
        "$isotrack" render --gl "$gl" --field "$spec" --method "$method" --size 960x600 --frames "$frames" \
            "${extra[@]}" --json --out "$out/$path.png" >"$out/$path.json"
        printf '| `%s %s` | %s | %s | %s | %s | %.1f | %.2f |\n' "$spec" "$method" \
            "$(field "$out/$path.json" surfaces)" "$(field "$out/$path.json" triangles)" "$path" \
            "$(field "$out/$path.json" draw_calls)" "$(field "$out/$path.json" frame_ms)" \
            "$(field "$out/$path.json" submit_ms)"
    done
    cmp -s "$out/batched.png" "$out/per-surface.png" || echo "note: $spec: the two pictures differ"
done
echo "renderer: $(field "$out/batched.json" renderer)"
