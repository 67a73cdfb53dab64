#!/usr/bin/env bash
# Builds hylios (installing dependencies as needed) and runs the default job into ./out:
# the per-layer optical coefficients of specimen S1 over 250–2500 nm, as CSV and plot.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out
./build/hylios coefficients --specimen S1 --wavelengths 250:2500:5 \
  --out out/s1_coefficients.csv --plot out/s1_coefficients.png
echo "wrote out/s1_coefficients.csv and out/s1_coefficients.png"
