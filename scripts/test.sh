#!/usr/bin/env bash
# Builds everything (installing dependencies as needed) and runs the whole test suite with CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh "$@"
jobs=$(nproc 2>/dev/null || echo 2)
ctest --test-dir build -j"$jobs" --output-on-failure --timeout 900
