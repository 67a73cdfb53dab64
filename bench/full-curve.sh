#!/usr/bin/env bash
# Wall time and peak memory of the full S1 reflectance curve: 250–2500 nm at 5 nm (451
# wavelengths), 1e5 rays each, 45° incidence, 2 threads. Prints one "key: value" per line.
# usage: bench/full-curve.sh [BUILD_DIR] [RAYS] [THREADS]
set -euo pipefail
source "$(dirname "$0")/common.sh"
rays="${2:-100000}"
threads="${3:-2}"
/usr/bin/time -v -o "$work/time.txt" "$build/hylios" spectrum --specimen S1 \
  --angle 45 --wavelengths 250:2500:5 --rays "$rays" --threads "$threads" --out "$work/S1.csv" >/dev/null
wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$work/time.txt")
user=$(sed -n 's/.*User time (seconds): //p' "$work/time.txt")
system=$(sed -n 's/.*System time (seconds): //p' "$work/time.txt")
peak=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/time.txt")
wavelengths=$(($(wc -l < "$work/S1.csv") - 1))
echo "command: hylios spectrum --specimen S1 --angle 45 --wavelengths 250:2500:5 --rays $rays --threads $threads"
echo "wavelengths: $wavelengths"
echo "wall_time: $wall"
echo "cpu_time_s: $(python3 -c "print(round($user + $system, 2))")"
echo "rays_per_cpu_second: $(python3 -c "print(round($wavelengths * $rays / ($user + $system)))")"
echo "peak_memory_kb: $peak"
