#!/usr/bin/env bash
# Builds the loader fuzzers (tests/fuzz/) with clang, libFuzzer, ASan and UBSan into
# build-fuzz/ and runs each for a fixed time from its seed corpus.
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET]   (default 20; one target per loader)
# New corpus entries stay in build-fuzz/corpus/; a crash leaves its input in
# build-fuzz/artifacts/ and makes the script fail. The DICOM loader runs GDCM in
# a child process: an input GDCM crashes on there is a handled error (not a
# finding) and is kept for triage in build-fuzz/library-failures/.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds=${1:-20}
build=$repo/build-fuzz

command -v clang++ >/dev/null || { echo "fuzz: clang++ not found (scripts/setup.sh installs it)" >&2; exit 1; }
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g"
cmake -S "$repo" -B "$build" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" -DISOTRACK_FUZZ=ON -DISOTRACK_BUILD_BENCH=OFF \
      -DISOTRACK_WERROR=OFF >/dev/null
cmake --build "$build" --target isotrack_fuzzers -j"$(nproc)" >/dev/null
# The targets tests/fuzz/CMakeLists.txt defines, one per loader.
targets=()
for f in "$build"/tests/fuzz/fuzz_*; do
    [[ -f $f && -x $f ]] && targets+=("${f##*/fuzz_}")
done

mkdir -p "$build/artifacts"
# The targets write each input to a file here (on tmpfs when there is one).
work=$(mktemp -d "$( [[ -d /dev/shm ]] && echo /dev/shm || echo "${TMPDIR:-/tmp}")/isotrack-fuzz.XXXXXX")
trap 'rm -rf "$work"' EXIT
export ISOTRACK_FUZZ_DIR=$work
status=0
export ISOTRACK_FUZZ_LIBRARY_FAILURES=$build/library-failures
mkdir -p "$ISOTRACK_FUZZ_LIBRARY_FAILURES"
failures_before=$(ls "$ISOTRACK_FUZZ_LIBRARY_FAILURES" | wc -l)
for t in "${targets[@]}"; do
    corpus=$build/corpus/$t
    mkdir -p "$corpus"
    log=$build/fuzz_$t.log
    # -rss_limit_mb and -malloc_limit_mb make a giant allocation a finding, -timeout a hang.
    if UBSAN_OPTIONS=print_stacktrace=1 "$build/tests/fuzz/fuzz_$t" "$corpus" "$repo/tests/fuzz/corpus/$t" \
           -max_total_time="$seconds" -timeout=5 -rss_limit_mb=2048 -malloc_limit_mb=1024 \
           -artifact_prefix="$build/artifacts/${t}-" -print_final_stats=1 >"$log" 2>&1; then
        execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
        cov=$(grep -o 'cov: [0-9]*' "$log" | tail -n1)
        echo "fuzz $t: ok, ${execs:-?} runs in ${seconds}s, $cov, corpus $(ls "$corpus" | wc -l) files"
    else
        echo "fuzz $t: FAILED (see $log; input in $build/artifacts/)"
        grep -E "ERROR|SUMMARY|==[0-9]+==" "$log" | head -n 5 || true
        status=1
    fi
done
failures=$(ls "$ISOTRACK_FUZZ_LIBRARY_FAILURES" | wc -l)
echo "fuzz: $((failures - failures_before)) new inputs GDCM failed on in its child process (handled), $failures in all in $ISOTRACK_FUZZ_LIBRARY_FAILURES"
exit $status
