#!/usr/bin/env bash
# Builds hylios (installing dependencies as needed) and renders the default scene into ./out:
# the paper's Figure 1 — a lightly pigmented head with freckles at 365 nm (pseudo-colour), in the
# visible (sRGB) and at 1100 nm (pseudo-colour) — as spectral EXRs, PNG previews and a contact
# sheet, at 512×512: each band renders until its estimated median per-pixel noise on the head is
# 5 % (every band, and R, G, B of the visible; at most 1024 spp). The scenes use exit tables
# (skin_mode = "table"), built on the first run (about a tenth of its 35–70 CPU-s, by machine) and
# cached in ~/.cache/hylios.
set -euo pipefail
cd "$(dirname "$0")/.."
HYLIOS_TARGET=hylios bash scripts/build.sh  # only what the render needs (no tests, benchmarks)
./build/hylios figure scenes/figure01_uv365.toml scenes/figure01_visible.toml scenes/figure01_ir1100.toml \
  --out out/figure01 --resolution 512x512 --noise-target 0.05 --spp 1024 "$@"
echo "open out/figure01/contact_sheet.png"
