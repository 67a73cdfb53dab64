#!/usr/bin/env bash
# Builds the libFuzzer harnesses of fuzz/ (scripts/sanitizer-build.sh: clang, ASan + UBSan,
# ./build-sanitize) and runs each for HYLIOS_FUZZ_SECONDS seconds (default 20) from its committed
# seed corpus: the CTest label "fuzz". A crash, sanitizer report, leak, hang (> 10 s per input) or
# a broken parser promise fails the test; the input is left in build-sanitize/fuzz/artifacts/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/sanitizer-build.sh --target hylios_fuzzers
build=${HYLIOS_SANITIZE_BUILD_DIR:-build-sanitize}
jobs=$(nproc 2>/dev/null || echo 2)
ctest --test-dir "$build" -L fuzz -j"$jobs" --output-on-failure
