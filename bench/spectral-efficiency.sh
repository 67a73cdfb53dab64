#!/usr/bin/env bash
# Issue 11's benchmark: the full S1 curve (45°, 250–2500 nm at 5 nm, RAYS rays per wavelength) with
# the spectral estimator (cold: a fresh process, no cache involved), against the per-wavelength
# analog walk at every STEP nm (each wavelength its own process, the full model: --epsilon 0).
# Efficiency gain per wavelength = (t_pw · σ²_pw) / (t_sp · σ²_sp), σ the CSV's standard error, t in
# CPU seconds per wavelength: for a per-wavelength run its CPU time less that of a one-ray run (the
# process's fixed cost); for the spectral walk two ways:
#   curve  the full curve's CPU time shared equally by its 451 wavelengths (σ from the full curve);
#   range  the CPU time of the wavelength's range run alone, shared by the range's wavelengths (σ
#          from that run). The ranges are those of Algorithm 2's θo: 250–780 nm (θo = 5°; 780 nm
#          is the ramp's first point and still 5°, so it joins the plateau's last bundle),
#          785–1395 nm (the ramp) and 1400–2500 nm (θo = 0). No bundle crosses them, so the three
#          runs give the full curve's numbers to the last digit and together cost what it costs;
#          each wavelength pays for the bundles that serve it instead of an equal share of all.
# The per-wavelength walks run PW_RAYS rays (default 4 × RAYS): t·σ² does not depend on the number
# of rays, and a longer run times it more precisely (a 10⁵-ray run at 1400 nm takes 0.3 CPU-s,
# near the 10 ms resolution of the timer and the noise of the process's fixed cost); the CSV's
# pw_cpu_s is scaled to RAYS rays, pw_r and pw_stderr are those of the PW_RAYS run.
# Writes OUT/spectral-efficiency.csv, OUT/spectral-efficiency.png and OUT/spectral-efficiency.md.
# usage: bench/spectral-efficiency.sh [BUILD_DIR] [OUT_DIR] [RAYS] [STEP] [PW_RAYS]
set -euo pipefail
source "$(dirname "$0")/common.sh"
out="${2:-$root/docs/benchmarks}"
rays="${3:-100000}"
step="${4:-50}"
pw_rays="${5:-$((4 * rays))}"
mkdir -p "$out"
cpu() {  # CPU seconds (user + system) and wall seconds of a command, as "cpu wall"
  /usr/bin/time -f "%U %S %e" -o "$work/t" "$@" >/dev/null
  awk '{printf "%.3f %.3f\n", $1 + $2, $3}' "$work/t"
}
spectral() {  # CPU and wall seconds of the spectral estimator over wavelengths $1, CSV to $2
  cpu "$build/hylios" spectrum --specimen S1 --angle 45 --wavelengths "$1" --rays "$rays" --threads 2 --out "$2"
}
# The spectral runs (the full curve and the three range runs) are timed three times, before, in
# the middle of and after the per-wavelength runs, and each takes its median: this machine's speed
# drifts by up to 30 % over a minute, and a single timing at the start set every gain by it.
ranges=(250:780:5 785:1395:5 1400:2500:5)
spectral_block() {  # appends "cpu wall" of the full curve and of each range run to their files
  spectral 250:2500:5 "$work/spectral.csv" >> "$work/full_times.txt"
  for r in "${ranges[@]}"; do
    spectral "$r" "$work/range_${r//:/_}.csv" >> "$work/range_times_${r//:/_}.txt"
  done
}
median_of() {  # the median "cpu wall" line of a file of three, by CPU
  sort -g "$1" | sed -n 2p
}
: > "$work/full_times.txt"
for r in "${ranges[@]}"; do : > "$work/range_times_${r//:/_}.txt"; done
spectral_block
# The fixed cost of a process (loading the spectral data, specimen, optics): subtracted from each
# per-wavelength run, which the real per-wavelength curve pays once, not 451 times.
read -r startup_cpu startup_wall < <(cpu "$build/hylios" spectrum --specimen S1 --angle 45 --wavelengths 550 \
  --rays 1 --threads 2 --epsilon 0 --estimator per-wavelength --out "$work/startup.csv")
: > "$work/pw_times.txt"
middle=$(( (250 + 2500) / 2 ))
for ((w = 250; w <= 2500; w += step)); do
  read -r pw_cpu pw_wall < <(cpu "$build/hylios" spectrum --specimen S1 --angle 45 --wavelengths "$w" \
    --rays "$pw_rays" --threads 2 --epsilon 0 --estimator per-wavelength --out "$work/pw_$w.csv")
  pw_cpu=$(python3 -c "print(max($pw_cpu - $startup_cpu, 0.001) * $rays / $pw_rays)")  # at RAYS rays
  echo "$w $pw_cpu" >> "$work/pw_times.txt"
  if (( w < middle && w + step >= middle )); then spectral_block; fi
done
spectral_block
read -r sp_cpu sp_wall < <(median_of "$work/full_times.txt")
: > "$work/ranges.txt"
for r in "${ranges[@]}"; do
  read -r r_cpu r_wall < <(median_of "$work/range_times_${r//:/_}.txt")
  echo "$r $r_cpu $r_wall $work/range_${r//:/_}.csv" >> "$work/ranges.txt"
done
echo "wavelength_nm,pw_cpu_s,pw_r,pw_stderr,sp_r,sp_stderr,z,gain,range_cpu_per_wavelength_s,range_r,range_stderr,range_z,range_gain" > "$work/eff.csv"
while read -r w pw_cpu; do
  python3 - "$w" "$pw_cpu" "$sp_cpu" "$work/pw_$w.csv" "$work/spectral.csv" "$work/ranges.txt" "$rays" "$pw_rays" >> "$work/eff.csv" <<'PY'
import csv, math, sys
w, pw_cpu, sp_cpu = (float(x) for x in sys.argv[1:4])
pw_path, sp_path, ranges_path = sys.argv[4:7]
rays, pw_rays = (float(x) for x in sys.argv[7:9])
def row_at(rows):
    return next(r for r in rows if abs(float(r["wavelength_nm"]) - w) < 1e-9)
def gain(t_sp, rows):
    sp = row_at(rows)
    b, sb = float(sp["reflectance"]), float(sp["reflectance_stderr"])
    z = (b - a) / math.hypot(sa, sb)
    # t·σ² of the per-wavelength walk at RAYS rays: its time scaled to RAYS, its variance to RAYS.
    pw_product = pw_cpu * sa * sa * pw_rays / rays
    return b, sb, z, pw_product / (t_sp * sb * sb) if sb > 0 else float("inf")
pw = next(csv.DictReader(open(pw_path)))
a, sa = float(pw["reflectance"]), float(pw["reflectance_stderr"])
curve = list(csv.DictReader(open(sp_path)))
b, sb, z, g = gain(sp_cpu / len(curve), curve)
for line in open(ranges_path):
    spec, r_cpu, _, r_path = line.split()
    start, stop, _ = (float(x) for x in spec.split(":"))
    if start <= w <= stop:
        rows = list(csv.DictReader(open(r_path)))
        t_range = float(r_cpu) / len(rows)
        rb, rsb, rz, rg = gain(t_range, rows)
print(f"{w:g},{pw_cpu:.3f},{a:.6g},{sa:.6g},{b:.6g},{sb:.6g},{z:.3f},{g:.4g},"
      f"{t_range:.5f},{rb:.6g},{rsb:.6g},{rz:.3f},{rg:.4g}")
PY
done < "$work/pw_times.txt"
cp "$work/eff.csv" "$out/spectral-efficiency.csv"
cp "$work/spectral.csv" "$out/spectral-curve.csv"
gnuplot <<GP
set terminal pngcairo size 1000,560 font "DejaVu Sans,11"
set output "$out/spectral-efficiency.png"
set datafile separator ","
set logscale y
set grid
set xlabel "wavelength (nm)"
set ylabel "efficiency gain (t·σ²) per-wavelength / spectral"
set title "S1, 45°, $rays rays per wavelength: spectral walk against the per-wavelength walk"
plot "$out/spectral-efficiency.csv" every ::1 using 1:8 with linespoints lw 2 pt 7 title "gain, time shared equally by the curve", \\
  "" every ::1 using 1:13 with linespoints lw 2 pt 5 title "gain, time of the wavelength's θo range", \\
  20 with lines dt 2 lc rgb "black" title "20×"
GP
python3 - "$out" "$sp_cpu" "$sp_wall" "$rays" "$work/ranges.txt" "$pw_rays" <<'PY'
import csv, sys
out, sp_cpu, sp_wall, rays, ranges_path = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4], sys.argv[5]
pw_rays = sys.argv[6]
rows = list(csv.DictReader(open(out + "/spectral-efficiency.csv")))
curve = list(csv.DictReader(open(out + "/spectral-curve.csv")))
worst = max(curve, key=lambda r: float(r["reflectance_stderr"]))
def spread(key):
    g = sorted(float(r[key]) for r in rows)
    return f"min {g[0]:.3g}×, median {g[len(g) // 2]:.3g}×, max {g[-1]:.3g}×"
zs = [abs(float(r["z"])) for r in rows]
pw_total = sum(float(r["pw_cpu_s"]) for r in rows) / len(rows) * len(curve)
ranges = [line.split()[:3] for line in open(ranges_path)]
range_cpu = sum(float(r[1]) for r in ranges)
with open(out + "/spectral-efficiency.md", "w") as f:
    f.write(f"Full S1 curve (451 wavelengths, {rays} rays each, 45°), spectral estimator, cold: "
            f"{sp_wall:.2f} s wall, {sp_cpu:.2f} CPU-s (the median of three runs, as each range's below); largest standard error {float(worst['reflectance_stderr']):.4g} "
            f"at {worst['wavelength_nm']} nm. The per-wavelength walk at {len(rows)} of the wavelengths ({pw_rays} rays "
            f"each, its R ± σ below; its time at {rays} rays), scaled to 451: {pw_total:.0f} CPU-s. Efficiency gain per wavelength, the curve's time shared equally: {spread('gain')}; "
            f"each wavelength charged its θo range's time ("
            + ", ".join(f"{r[0]} {float(r[1]):.2f} CPU-s" for r in ranges)
            + f"; {range_cpu:.2f} CPU-s together): {spread('range_gain')}. Largest |z| between the two "
            f"estimators {max(zs):.2f}.\n\n")
    f.write("| λ (nm) | per-wavelength R ± σ | spectral R ± σ | z | gain, equal share | gain, θo range |\n"
            "|---|---|---|---|---|---|\n")
    for r in rows:
        f.write(f"| {r['wavelength_nm']} | {float(r['pw_r']):.4f} ± {float(r['pw_stderr']):.4f} | "
                f"{float(r['sp_r']):.4f} ± {float(r['sp_stderr']):.4f} | {float(r['z']):+.2f} | "
                f"{float(r['gain']):.3g} | {float(r['range_gain']):.3g} |\n")
print(open(out + "/spectral-efficiency.md").read().split("\n\n")[0])
PY
