#!/usr/bin/env bash
# Issue 12's time goals: each band of Figure 1 (scenes/figure01_*.toml) rendered at RESOLUTION
# until the film's own estimate of the median per-pixel noise on the head is TARGET in every group
# (band; for the visible also R, G, B and chromaticity), at most 1024 spp, from a cold exit-table
# cache: the skin as the scenes have it (table mode, the spectral estimator), and a Lambertian
# stand-in of reflectance 0.05 / 0.4 / 0.6 (the floor set by the light transport alone). Then the
# paper's Figures 12–14 with `hylios figure … --noise-target TARGET` at the scenes' resolution, cold.
# Records CPU seconds (user + sys), wall seconds, the spp reached and the noise, with the load.
# usage: bench/time-to-noise.sh [BUILD_DIR] [OUT_DIR] [RESOLUTION] [TARGET]
set -euo pipefail
source "$(dirname "$0")/common.sh"
out="${2:-$root/docs/benchmarks}"
resolution="${3:-512x512}"
target="${4:-0.05}"
mkdir -p "$out"
csv="$work/time-to-noise.csv"
echo "what,variant,cpu_s,wall_s,spp,worst_noise,load_before" > "$csv"
timed() {  # timed WHAT VARIANT LOG -- command…: runs it with a cold cache, appends a CSV row
  local what=$1 variant=$2 log=$3
  shift 4
  local load
  load=$(cut -d' ' -f1 /proc/loadavg)
  export HYLIOS_CACHE_DIR="$work/cache_${what}_$variant"
  /usr/bin/time -f "%U %S %e" -o "$work/t" "$@" > "$log" 2>&1
  local spp noise
  spp=$(sed -n 's/.* after \([0-9]*\) spp.*/\1/p' "$log" | sort -g | tail -1)
  noise=$(worst < "$log")
  awk -v w="$what" -v v="$variant" -v s="$spp" -v n="$noise" -v l="$load" \
    '{printf "%s,%s,%.1f,%.1f,%s,%s,%s\n", w, v, $1 + $2, $3, s, n, l}' "$work/t" >> "$csv"
}
for band in uv365:0.05 visible:0.4 ir1100:0.6; do
  name=${band%%:*}; rho=${band#*:}
  common=(--resolution "$resolution" --noise-target "$target" --spp 1024 --seed 1)
  timed "$name" skin "$work/${name}_skin.log" -- "$build/hylios" render \
    "$root/scenes/figure01_$name.toml" --out "$work/${name}_skin.exr" "${common[@]}"
  lambertian "$root/scenes/figure01_$name.toml" "$rho" > "$work/lambertian_$name.toml"
  timed "$name" lambertian "$work/${name}_lambertian.log" -- "$build/hylios" render \
    "$work/lambertian_$name.toml" --out "$work/${name}_lambertian.exr" "${common[@]}"
done
for figure in 12 13 14; do
  timed "figure$figure" skin "$work/figure$figure.log" -- "$build/hylios" figure \
    "$root"/scenes/figure"$figure"_*.toml --out "$work/figure$figure" --noise-target "$target" \
    --spp 1024
done
cp "$csv" "$out/time-to-noise.csv"
cp "$work/visible_skin_visible.png" "$out/time-to-noise-visible.png"
cat "$out/time-to-noise.csv"
