#!/usr/bin/env bash
# Issue 11's benchmark: the full S1 curve (45°, 250–2500 nm at 5 nm, RAYS rays per wavelength) with
# the spectral estimator (cold: a fresh process, no cache involved), against the per-wavelength
# analog walk at every STEP nm (each wavelength its own process, the full model: --epsilon 0).
# Efficiency gain per wavelength = (t_pw · σ²_pw) / (t_sp · σ²_sp), t in CPU seconds per wavelength
# (the spectral run's CPU time shared equally by its 451 wavelengths; a per-wavelength run less the
# CPU time of a one-ray run, the process's fixed cost), σ the CSV's standard error.
# Writes OUT/spectral-efficiency.csv, OUT/spectral-efficiency.png and OUT/spectral-efficiency.md.
# usage: bench/spectral-efficiency.sh [BUILD_DIR] [OUT_DIR] [RAYS] [STEP]
set -euo pipefail
source "$(dirname "$0")/common.sh"
out="${2:-$root/docs/benchmarks}"
rays="${3:-100000}"
step="${4:-50}"
mkdir -p "$out"
cpu() {  # CPU seconds (user + system) and wall seconds of a command, as "cpu wall"
  /usr/bin/time -f "%U %S %e" -o "$work/t" "$@" >/dev/null
  awk '{printf "%.3f %.3f\n", $1 + $2, $3}' "$work/t"
}
read -r sp_cpu sp_wall < <(cpu "$build/hylios" spectrum --specimen S1 --angle 45 --wavelengths 250:2500:5 \
  --rays "$rays" --threads 2 --out "$work/spectral.csv")
# The fixed cost of a process (loading the spectral data, specimen, optics): subtracted from each
# per-wavelength run, which the real per-wavelength curve pays once, not 451 times.
read -r startup_cpu startup_wall < <(cpu "$build/hylios" spectrum --specimen S1 --angle 45 --wavelengths 550 \
  --rays 1 --threads 2 --epsilon 0 --estimator per-wavelength --out "$work/startup.csv")
echo "wavelength_nm,pw_cpu_s,pw_r,pw_stderr,sp_r,sp_stderr,z,gain" > "$work/eff.csv"
for ((w = 250; w <= 2500; w += step)); do
  read -r pw_cpu pw_wall < <(cpu "$build/hylios" spectrum --specimen S1 --angle 45 --wavelengths "$w" \
    --rays "$rays" --threads 2 --epsilon 0 --estimator per-wavelength --out "$work/pw.csv")
  pw_cpu=$(python3 -c "print(max($pw_cpu - $startup_cpu, 0.001))")
  python3 - "$w" "$pw_cpu" "$sp_cpu" "$work/pw.csv" "$work/spectral.csv" >> "$work/eff.csv" <<'PY'
import csv, math, sys
w, pw_cpu, sp_cpu, pw_path, sp_path = float(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]), sys.argv[4], sys.argv[5]
pw = next(csv.DictReader(open(pw_path)))
rows = list(csv.DictReader(open(sp_path)))
sp = next(r for r in rows if abs(float(r["wavelength_nm"]) - w) < 1e-9)
a, sa = float(pw["reflectance"]), float(pw["reflectance_stderr"])
b, sb = float(sp["reflectance"]), float(sp["reflectance_stderr"])
t_sp = sp_cpu / len(rows)
z = (b - a) / math.hypot(sa, sb)
gain = (pw_cpu * sa * sa) / (t_sp * sb * sb) if sb > 0 else float("inf")
print(f"{w:g},{pw_cpu:.3f},{a:.6g},{sa:.6g},{b:.6g},{sb:.6g},{z:.3f},{gain:.4g}")
PY
done
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
plot "$out/spectral-efficiency.csv" every ::1 using 1:8 with linespoints lw 2 pt 7 title "gain", 20 with lines dt 2 lc rgb "black" title "20×"
GP
python3 - "$out" "$sp_cpu" "$sp_wall" "$rays" <<'PY'
import csv, sys
out, sp_cpu, sp_wall, rays = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
rows = list(csv.DictReader(open(out + "/spectral-efficiency.csv")))
curve = list(csv.DictReader(open(out + "/spectral-curve.csv")))
worst = max(curve, key=lambda r: float(r["reflectance_stderr"]))
gains = [float(r["gain"]) for r in rows]
zs = [abs(float(r["z"])) for r in rows]
pw_total = sum(float(r["pw_cpu_s"]) for r in rows) / len(rows) * len(curve)
with open(out + "/spectral-efficiency.md", "w") as f:
    f.write(f"Full S1 curve (451 wavelengths, {rays} rays each, 45°), spectral estimator, cold: "
            f"{sp_wall:.2f} s wall, {sp_cpu:.2f} CPU-s; largest standard error {float(worst['reflectance_stderr']):.4g} "
            f"at {worst['wavelength_nm']} nm. The per-wavelength walk at {len(rows)} of the wavelengths, scaled to 451: "
            f"{pw_total:.0f} CPU-s. Efficiency gain per wavelength: min {min(gains):.3g}×, median "
            f"{sorted(gains)[len(gains)//2]:.3g}×, max {max(gains):.3g}×; largest |z| between the two {max(zs):.2f}.\n\n")
    f.write("| λ (nm) | per-wavelength R ± σ | spectral R ± σ | z | gain |\n|---|---|---|---|---|\n")
    for r in rows:
        f.write(f"| {r['wavelength_nm']} | {float(r['pw_r']):.4f} ± {float(r['pw_stderr']):.4f} | "
                f"{float(r['sp_r']):.4f} ± {float(r['sp_stderr']):.4f} | {float(r['z']):+.2f} | {float(r['gain']):.3g} |\n")
print(open(out + "/spectral-efficiency.md").read().split("\n\n")[0])
PY
