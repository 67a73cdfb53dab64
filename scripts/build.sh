#!/usr/bin/env bash
# Installs dependencies (Debian 12 packages) and builds hylios in Release into ./build: every
# target, or only $HYLIOS_TARGET when set (scripts/default.sh builds only the hylios executable).
# Arguments go to the CMake configure step.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
target=()
if [[ -n ${HYLIOS_TARGET:-} ]]; then target=(--target "$HYLIOS_TARGET"); fi
cmake --build build -j"$jobs" "${target[@]}"
