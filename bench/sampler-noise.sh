#!/usr/bin/env bash
# Issue 12, item 3: what the sobol pixel sampler buys over the independent one at equal spp. For
# each band of Figure 1 (scenes/figure01_*.toml) and each variant — the skin with the spectral and
# the per-wavelength estimator, and a Lambertian stand-in of equal reflectance (as in
# bench/render-noise.sh) — and each sampler and spp: the median per-pixel noise of two renders that
# differ only in the seed (hylios image-diff --noise; the worst group of the band, and every group
# in the groups file), the film's own half-split estimate of seed 1 (what --noise-target uses), and
# the CPU time (user + sys, mean of the two seeds).
# usage: bench/sampler-noise.sh [BUILD_DIR] [OUT_DIR] [RESOLUTION] [SPP_LIST]
set -euo pipefail
source "$(dirname "$0")/common.sh"
out="${2:-$root/docs/benchmarks}"
resolution="${3:-128x128}"
spps="${4:-16 64}"
mkdir -p "$out"
echo "band,variant,sampler,spp,cpu_s,two_seed_noise,film_estimate" > "$work/noise.csv"
: > "$work/groups.txt"
for band in uv365:0.05 visible:0.4 ir1100:0.6; do
  name=${band%%:*}; rho=${band#*:}
  for variant in spectral per-wavelength lambertian; do
    figure01_variant "$name" "$rho" "$variant"
    for spp in $spps; do
      for sampler in independent sobol; do
        total=0
        tag="${name}_${variant}_${sampler}_$spp"
        for seed in 1 2; do
          # --noise-target far below reach: the film's own estimate is logged at the spp cap.
          /usr/bin/time -f "%U %S" -o "$work/t" "$build/hylios" render "$file" --out "$work/${tag}_$seed.exr" \
            --resolution "$resolution" --spp "$spp" --seed "$seed" --sampler "$sampler" \
            --noise-target 1e-6 "${extra[@]}" > "$work/${tag}_$seed.log" 2>&1
          total=$(awk -v t="$total" '{print t + $1 + $2}' "$work/t")
        done
        "$build/hylios" image-diff --noise "$work/${tag}_1.exr" "$work/${tag}_2.exr" > "$work/${tag}_noise.txt"
        noise=$(worst < "$work/${tag}_noise.txt")
        estimate=$(sed -n '/estimated noise/,$p' "$work/${tag}_1.log" | worst)
        echo "$name,$variant,$sampler,$spp,$(awk -v t="$total" 'BEGIN{printf "%.2f", t / 2}'),$noise,$estimate" >> "$work/noise.csv"
        { echo "== $tag (two seeds)"; tail -n +2 "$work/${tag}_noise.txt"; } >> "$work/groups.txt"
      done
    done
  done
done
cp "$work/noise.csv" "$out/sampler-noise.csv"
cp "$work/groups.txt" "$out/sampler-noise-groups.txt"
cat "$out/sampler-noise.csv"
