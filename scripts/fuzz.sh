#!/usr/bin/env bash
# Builds the libFuzzer harnesses of fuzz/ (clang, ASan + UBSan, -DHYLIOS_FUZZ=ON) into
# ./build-fuzz and runs each for HYLIOS_FUZZ_SECONDS seconds (default 20) from its committed seed
# corpus: the CTest label "fuzz". A crash, sanitizer report, leak, hang (> 10 s per input) or
# a broken parser promise fails the test; the input is left in build-fuzz/fuzz/artifacts/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# clang and its libFuzzer runtime are needed only here, so they are installed only here.
fuzz_packages=(clang libclang-rt-14-dev)
for p in "${fuzz_packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    echo "fuzz: installing ${fuzz_packages[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${fuzz_packages[@]}"
    break
  fi
done
build=${HYLIOS_FUZZ_BUILD_DIR:-build-fuzz}
seconds=${HYLIOS_FUZZ_SECONDS:-20}
jobs=$(nproc 2>/dev/null || echo 2)
CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHYLIOS_FUZZ=ON \
  -DHYLIOS_BUILD_TESTS=OFF -DHYLIOS_BUILD_BENCHMARKS=OFF -DHYLIOS_FUZZ_SECONDS="$seconds" \
  "$@" >/dev/null
cmake --build "$build" -j"$jobs" --target hylios_fuzzers
ctest --test-dir "$build" -L fuzz -j"$jobs" --output-on-failure
