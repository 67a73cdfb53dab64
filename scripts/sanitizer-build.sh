#!/usr/bin/env bash
# Configures and builds hylios with clang, AddressSanitizer + UndefinedBehaviorSanitizer and
# libFuzzer's coverage instrumentation on every target (-DHYLIOS_FUZZ=ON, cmake/Fuzzing.cmake)
# into ./build-sanitize (or $HYLIOS_SANITIZE_BUILD_DIR): one build serves both the whole test
# suite under the sanitizers (scripts/sanitize.sh) and the fuzz harnesses (scripts/fuzz.sh), so
# CI compiles the libraries twice (this and Release), not three times. Installs dependencies and
# clang as needed. Arguments go to `cmake --build` (e.g. --target hylios_fuzzers).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# clang and its libFuzzer runtime are needed only here, so they are installed only here.
clang_packages=(clang libclang-rt-14-dev)
for p in "${clang_packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    echo "sanitizer-build: installing ${clang_packages[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${clang_packages[@]}"
    break
  fi
done
build=${HYLIOS_SANITIZE_BUILD_DIR:-build-sanitize}
jobs=$(nproc 2>/dev/null || echo 2)
# -O2 with line tables only (-gline-tables-only): sanitizer reports keep file:line, the objects
# and links stay small. MPI is off: Open MPI's own allocations trip LeakSanitizer (cmake/Mpi.cmake).
CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
  -DHYLIOS_FUZZ=ON -DHYLIOS_BUILD_BENCHMARKS=OFF -DHYLIOS_MPI=OFF \
  -DHYLIOS_FUZZ_SECONDS="${HYLIOS_FUZZ_SECONDS:-20}" >/dev/null
cmake --build "$build" -j"$jobs" "$@"
