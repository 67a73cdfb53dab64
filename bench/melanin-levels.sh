#!/usr/bin/env bash
# Interpolation error of the renderer's melanin levels (renderer/tracing/skin_walk_cache.h):
# S1's reflectance at normal incidence for melanin multipliers m = 1.0, 1.1, …, 4.0 (both melanin
# contents × m; Figure 1's freckles span [1, 4]), one seed for all (common random numbers), then
# bench/melanin_levels.py fits R(m) per wavelength and prints the largest relative error of linear
# interpolation between levels for several level sets, the renderer's among them.
# usage: bench/melanin-levels.sh [BUILD_DIR] [RAYS]
set -euo pipefail
source "$(dirname "$0")/common.sh"
rays="${2:-200000}"
for i in $(seq 0 30); do
  m=$(python3 -c "print(1 + 0.1 * $i)")
  "$build/hylios" spectrum --specimen S1 --angle 0 --rays "$rays" --seed 5 \
    --set "melanosome_percent=$(python3 -c "print(1.0 * $m)")" \
    --set "colloidal_melanin_percent=$(python3 -c "print(0.8 * $m)")" \
    --wavelengths 365,420,450,500,550,600,650,780,1100 --out "$work/m_$i.csv" >/dev/null
done
python3 "$root/bench/melanin_levels.py" "$work"
