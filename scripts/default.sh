#!/usr/bin/env bash
# Builds hylios (installing dependencies as needed) and renders the default scene into ./out:
# the paper's Figure 1 — a lightly pigmented head with freckles at 365 nm (pseudo-colour), in the
# visible (sRGB) and at 1100 nm (pseudo-colour) — as spectral EXRs, PNG previews and a contact
# sheet, at a modest resolution: each band renders until its estimated median per-pixel noise on
# the head is 12 % (at most 256 spp; pass e.g. --resolution 512x512 --noise-target 0.05 --spp 4096
# for the full one).
set -euo pipefail
cd "$(dirname "$0")/.."
HYLIOS_TARGET=hylios bash scripts/build.sh  # only what the render needs (no tests, benchmarks)
./build/hylios figure scenes/figure01_uv365.toml scenes/figure01_visible.toml scenes/figure01_ir1100.toml \
  --out out/figure01 --resolution 256x256 --noise-target 0.12 --spp 256 "$@"
echo "open out/figure01/contact_sheet.png"
