#!/usr/bin/env bash
# Issue 12's render measurements: for each band of Figure 1 (scenes/figure01_*.toml), the median
# per-pixel noise of two renders that differ only in the seed (hylios image-diff --noise) and the
# CPU time, for the skin with each estimator and for a Lambertian stand-in of equal reflectance
# (the floor set by the light transport alone). Time to a noise target N is extrapolated from the
# measured noise n at SPP samples as t · (n / N)² (noise ∝ 1/√spp), using the worst group of the band
# (for the visible: the worst of the band, R, G, B and chromaticity).
# usage: bench/render-noise.sh [BUILD_DIR] [OUT_DIR] [RESOLUTION] [SPP] [TARGET]
set -euo pipefail
source "$(dirname "$0")/common.sh"
out="${2:-$root/docs/benchmarks}"
resolution="${3:-256x256}"
spp="${4:-32}"
target="${5:-0.05}"
mkdir -p "$out"
echo "band,variant,cpu_s,worst_noise,time_to_target_s" > "$work/noise.csv"
for band in uv365:0.05 visible:0.4 ir1100:0.6; do
  name=${band%%:*}; rho=${band#*:}
  for variant in spectral per-wavelength lambertian; do
    figure01_variant "$name" "$rho" "$variant"
    total=0
    for seed in 1 2; do
      /usr/bin/time -f "%U %S" -o "$work/t" "$build/hylios" render "$file" --out "$work/${name}_${variant}_$seed.exr" \
        --resolution "$resolution" --spp "$spp" --seed "$seed" "${extra[@]}" > /dev/null
      total=$(awk -v t="$total" '{print t + $1 + $2}' "$work/t")
    done
    noise=$("$build/hylios" image-diff --noise "$work/${name}_${variant}_1.exr" "$work/${name}_${variant}_2.exr" | worst)
    python3 -c "t=$total/2; n=$noise/100; print(f'$name,$variant,{t:.2f},{n:.4f},{t*(n/$target)**2:.1f}')" >> "$work/noise.csv"
    "$build/hylios" image-diff --noise "$work/${name}_${variant}_1.exr" "$work/${name}_${variant}_2.exr" > "$work/${name}_${variant}_noise.txt"
  done
done
cp "$work/noise.csv" "$out/render-noise.csv"
cat "$work"/*_noise.txt > "$out/render-noise-groups.txt"
cp "$work/visible_spectral_1_visible.png" "$out/render-noise-visible-spectral.png"
cp "$work/visible_per-wavelength_1_visible.png" "$out/render-noise-visible-per-wavelength.png"
cp "$work/uv365_spectral_1_uv365.png" "$out/render-noise-uv365-spectral.png"
cp "$work/uv365_per-wavelength_1_uv365.png" "$out/render-noise-uv365-per-wavelength.png"
cat "$out/render-noise.csv"
