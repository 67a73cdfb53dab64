#!/usr/bin/env python3
"""Errors, noise floors, tables, plots and the report of bench/accuracy-cost (standard library only).

usage: accuracy_cost_report.py OUT --hylios PATH --root REPO [--docs DOCS_DIR]

Reads OUT/runs/manifest.csv and OUT/runs/study.env written by bench/accuracy-cost, and
  * spectra: error = RMS over wavelengths of (R − R_ref); expected Monte Carlo error of a run =
    sqrt(mean over wavelengths of (se² + se_ref²)) from the CSVs' reflectance_stderr; noise floor =
    RMS over wavelengths of the reference's se_ref; bias = mean over wavelengths of (R − R_ref);
  * renders: `hylios image-diff RUN refA` (relative RMSE over pixels, and over BxB block means,
    pooled over the spectral channels); noise floor of reference A = relRMSE(refB, refA) / √2 (two
    independent references at the same spp: their difference has twice one reference's variance);
    expected error of a walk render at N spp = floor · sqrt(N_ref / N + 1) (1/√spp extrapolation of
    the floor, plus the reference's own noise);
writes OUT/results/*.csv, OUT/plots/*.png (gnuplot, log–log) and OUT/accuracy-cost.md; with --docs,
also DOCS/accuracy-cost.md and DOCS/accuracy-cost/ (the CSVs and the plots).
"""
import argparse
import csv
import math
import os
import platform
import shutil
import subprocess
import sys


def read_env(path):
    env = {}
    with open(path) as f:
        for line in f:
            if "=" in line:
                key, value = line.rstrip("\n").split("=", 1)
                env[key] = value
    return env


def read_spectrum(path):
    """wavelength -> (reflectance, stderr)."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"accuracy-cost: '{path}' has no rows")
    return {float(r["wavelength_nm"]): (float(r["reflectance"]), float(r["reflectance_stderr"])) for r in rows}


def spectrum_error(run, reference, tolerance=0.0):
    """Errors of `run` against `reference`; `beyond_bound` counts the wavelengths where
    |R − R_ref| > tolerance + 4·sqrt(se² + se_ref²) (the planner promises |ΔR| ≤ ε)."""
    if sorted(run) != sorted(reference):
        sys.exit("accuracy-cost: a spectrum and its reference have different wavelengths")
    diffs = [run[w][0] - reference[w][0] for w in reference]
    n = len(diffs)
    beyond = sum(1 for w in reference if abs(run[w][0] - reference[w][0]) >
                 tolerance + 4 * math.sqrt(run[w][1] ** 2 + reference[w][1] ** 2))
    return {
        "beyond_bound": beyond,
        "error": math.sqrt(sum(d * d for d in diffs) / n),
        "bias": sum(diffs) / n,
        "max_abs_difference": max(abs(d) for d in diffs),
        "expected": math.sqrt(sum(run[w][1] ** 2 + reference[w][1] ** 2 for w in reference) / n),
    }


def image_diff(hylios, test, reference, block, csv_path):
    """The overall row of `hylios image-diff`: (relative RMSE, mean relative difference)."""
    subprocess.run([hylios, "image-diff", test, reference, "--block", str(block), "--csv", csv_path],
                   check=True, stdout=subprocess.DEVNULL)
    with open(csv_path, newline="") as f:
        for row in csv.DictReader(f):
            if row["channel"] == "overall":
                return float(row["relative_rmse"]), float(row["mean_relative_difference"])
    sys.exit(f"accuracy-cost: no overall row in '{csv_path}'")


def spectral_channel_count(csv_path):
    """How many spectral channels (rows with a wavelength) an image-diff CSV has."""
    with open(csv_path, newline="") as f:
        return sum(1 for row in csv.DictReader(f) if row["channel"] != "overall" and row["wavelength_nm"])


def fit_slope(xs, ys):
    """Least-squares slope of log y against log x (None with fewer than two usable points)."""
    points = [(math.log(x), math.log(y)) for x, y in zip(xs, ys) if x > 0 and y > 0]
    if len(points) < 2:
        return None
    mx = sum(p[0] for p in points) / len(points)
    my = sum(p[1] for p in points) / len(points)
    sxx = sum((p[0] - mx) ** 2 for p in points)
    return sum((p[0] - mx) * (p[1] - my) for p in points) / sxx if sxx > 0 else None


def above_floor(error, floor):
    """The error with the reference's own noise taken out: sqrt(error² − floor²), or 0."""
    return math.sqrt(max(error * error - floor * floor, 0.0))


def write_csv(path, header, rows):
    with open(path, "w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(header)
        writer.writerows(rows)


def g(value, digits=3):
    """A number for tables: 3 significant digits."""
    if value is None:
        return "–"
    if isinstance(value, str):
        return value
    if value == 0:
        return "0"
    return f"{value:.{digits}g}"


def markdown_table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(g(v) for v in row) + " |" for row in rows]
    return "\n".join(lines)


class Study:
    def __init__(self, out, hylios):
        self.out = out
        self.hylios = hylios
        self.env = read_env(os.path.join(out, "runs", "study.env"))
        with open(os.path.join(out, "runs", "manifest.csv"), newline="") as f:
            self.runs = list(csv.DictReader(f))
        for run in self.runs:
            run["wall_s"] = float(run["wall_s"])
            run["cpu_s"] = float(run["cpu_s"])
        self.block = int(self.env["block"])

    def select(self, study, band=None, variant=None):
        return [r for r in self.runs if r["study"] == study and (band is None or r["band"] == band)
                and (variant is None or r["variant"] == variant)]

    def spectrum_path(self, run):
        return os.path.join(self.out, "runs", "spectra", run["file"])

    def render_path(self, run):
        return os.path.join(self.out, "runs", "renders", run["file"])


def analyse_spectra(study, results):
    reference_run = study.select("reference", "S1")[0]
    reference = read_spectrum(study.spectrum_path(reference_run))
    floor = math.sqrt(sum(se * se for _, se in reference.values()) / len(reference))
    spectra = {"reference": reference_run, "floor": floor, "wavelengths": len(reference), "rays": []}
    for run in study.select("rays", "S1"):
        e = spectrum_error(read_spectrum(study.spectrum_path(run)), reference)
        spectra["rays"].append(dict(run, rays=int(run["setting"]), **e))
    spectra["rays"].sort(key=lambda r: r["rays"])
    rows = [[r["rays"], r["wall_s"], r["cpu_s"], r["error"], r["expected"], r["error"] / r["expected"], r["bias"],
             floor, floor * math.sqrt(int(reference_run["setting"]) / r["rays"])] for r in spectra["rays"]]
    write_csv(os.path.join(results, "spectra_rays.csv"),
              ["rays_per_wavelength", "wall_s", "cpu_s", "rms_error", "expected_noise", "error_over_expected",
               "mean_difference", "reference_noise_floor", "one_over_sqrt_n_line"], rows)
    spectra["slope"] = fit_slope([r["rays"] for r in spectra["rays"]],
                                 [above_floor(r["error"], floor) for r in spectra["rays"]])

    spectra["table"] = []
    for run in study.select("table", "S1"):
        e = spectrum_error(read_spectrum(study.spectrum_path(run)), reference)
        spectra["table"].append(dict(run, rays=int(run["setting"]), **e))
    spectra["epsilon"] = []
    for run in study.select("epsilon", "S1"):
        e = spectrum_error(read_spectrum(study.spectrum_path(run)), reference, float(run["setting"]))
        spectra["epsilon"].append(dict(run, epsilon=float(run["setting"]), **e))
    spectra["epsilon"].sort(key=lambda r: r["epsilon"])
    if spectra["epsilon"]:
        base = spectra["epsilon"][0]
        write_csv(os.path.join(results, "epsilon.csv"),
                  ["epsilon", "rays_per_wavelength", "wall_s", "cpu_s", "rms_error_vs_exact_reference",
                   "expected_noise", "error_over_expected", "mean_difference", "max_abs_difference",
                   "wavelengths_beyond_epsilon_plus_4sigma", "cpu_speedup_vs_epsilon0"],
                  [[r["setting"], study.env["epsilon_rays"], r["wall_s"], r["cpu_s"], r["error"], r["expected"],
                    r["error"] / r["expected"], r["bias"], r["max_abs_difference"], r["beyond_bound"],
                    base["cpu_s"] / r["cpu_s"]]
                   for r in spectra["epsilon"]])
    return spectra


def analyse_renders(study, results):
    renders = {}
    diffs = os.path.join(results, "image-diff")
    os.makedirs(diffs, exist_ok=True)
    bands = []
    for run in study.select("reference"):
        if run["band"] != "S1" and run["band"] not in bands:
            bands.append(run["band"])
    rows = []
    width, height = (int(v) for v in study.env["resolution"].split("x"))
    pixels = width * height  # the mean relative difference of an unbiased render ≈ N(0, (error / √pixels)²)
    for band in bands:
        refs = sorted(study.select("reference", band), key=lambda r: r["seed"])
        ref_a, ref_b = refs[0], refs[1]
        reference_spp = int(ref_a["setting"])
        path_a = study.render_path(ref_a)

        def compare(run, block):
            name = f"{os.path.splitext(run['file'])[0]}_block{block}.csv"
            return image_diff(study.hylios, study.render_path(run), path_a, block, os.path.join(diffs, name))

        floor = compare(ref_b, 1)[0] / math.sqrt(2)
        floor_block = compare(ref_b, study.block)[0] / math.sqrt(2)
        channels = spectral_channel_count(os.path.join(diffs, f"{os.path.splitext(ref_b['file'])[0]}_block1.csv"))
        entry = {"reference": ref_a, "reference_b": ref_b, "reference_spp": reference_spp, "floor": floor,
                 "floor_block": floor_block, "channels": channels, "spp": [], "table": []}
        for run in study.select("spp", band):
            spp = int(run["setting"])
            error, bias = compare(run, 1)
            error_block, bias_block = compare(run, study.block)
            expected = floor * math.sqrt(reference_spp / spp + 1)
            entry["spp"].append(dict(run, spp=spp, error=error, bias=bias, error_block=error_block,
                                     expected=expected, biased=abs(bias) > 4 * expected / math.sqrt(pixels)))
        entry["spp"].sort(key=lambda r: r["spp"])
        for r in entry["spp"]:
            rows.append([band, r["spp"], r["wall_s"], r["cpu_s"], r["error"], r["expected"], r["error_block"],
                         r["bias"], floor, floor_block])
        unbiased = [r for r in entry["spp"] if not r["biased"]]
        entry["slope"] = fit_slope([r["spp"] for r in unbiased], [above_floor(r["error"], floor) for r in unbiased])
        for run in study.select("table", band):
            error, bias = compare(run, 1)
            error_block, _ = compare(run, study.block)
            spp = int(run["setting"])
            entry["table"].append(dict(run, spp=spp, error=error, bias=bias, error_block=error_block,
                                       expected=floor * math.sqrt(reference_spp / spp + 1)))
        renders[band] = entry
    if rows:
        write_csv(os.path.join(results, "renders_spp.csv"),
                  ["band", "spp", "wall_s", "cpu_s", "relative_rmse", "expected_noise",
                   f"relative_rmse_block{study.block}", "mean_relative_difference", "reference_noise_floor",
                   f"reference_noise_floor_block{study.block}"], rows)
    return renders


def walk_vs_table_rows(study, spectra, renders):
    """Rows of walk_vs_table.csv: the walk at the same setting, then table cold and warm."""
    rows = []
    walk_by_rays = {r["rays"]: r for r in spectra["rays"]}
    for t in sorted(spectra["table"], key=lambda r: r["variant"]):
        walk = walk_by_rays.get(t["rays"])
        if walk and not any(r[0] == "spectrum" and r[3] == "walk" for r in rows):
            rows.append(["spectrum", "S1 45°", f"{t['rays']} rays", "walk", walk["wall_s"], walk["cpu_s"],
                         walk["error"], walk["expected"], walk["bias"]])
        rows.append(["spectrum", "S1 45°", f"{t['rays']} rays", t["variant"], t["wall_s"], t["cpu_s"], t["error"],
                     t["expected"], t["bias"]])
    for band, entry in renders.items():
        walk_by_spp = {r["spp"]: r for r in entry["spp"]}
        for t in sorted(entry["table"], key=lambda r: (r["spp"], r["variant"])):
            walk = walk_by_spp.get(t["spp"])
            if walk and not any(r[1] == band and r[2] == f"{t['spp']} spp" and r[3] == "walk" for r in rows):
                rows.append(["render", band, f"{t['spp']} spp", "walk", walk["wall_s"], walk["cpu_s"], walk["error"],
                             walk["expected"], walk["bias"]])
            if t["spp"] == entry["reference_spp"] and not any(r[1] == band and r[3] == "walk (reference B)"
                                                             for r in rows):
                ref_b = entry["reference_b"]
                rows.append(["render", band, f"{t['spp']} spp", "walk (reference B)", ref_b["wall_s"], ref_b["cpu_s"],
                             entry["floor"] * math.sqrt(2), entry["floor"] * math.sqrt(2), None])
            rows.append(["render", band, f"{t['spp']} spp", t["variant"], t["wall_s"], t["cpu_s"], t["error"],
                         t["expected"], t["bias"]])
    return rows


# ---- plots ------------------------------------------------------------------------------------------

def gnuplot(script, path):
    with open(path, "w") as f:
        f.write(script)
    subprocess.run(["gnuplot", path], check=True)


def write_dat(path, rows):
    with open(path, "w") as f:
        for row in rows:
            f.write(" ".join(f'"{v}"' if isinstance(v, str) else repr(float(v)) for v in row) + "\n")


GNUPLOT_HEAD = """set terminal pngcairo size {w},{h} font 'DejaVu Sans,11'
set output '{png}'
set logscale xy
set grid xtics ytics mxtics mytics lc rgb '#dddddd'
set key below maxrows 3 font ',10'
set format y '%g'
"""


def plot_spectra(study, spectra, plots):
    d = os.path.join(plots, "spectra")
    write_dat(d + "_rays.dat", [[r["wall_s"], r["error"], r["expected"], f"{r['rays']:g}"] for r in spectra["rays"]])
    series = [f"'{d}_rays.dat' u 1:2 w lp pt 7 lw 2 lc rgb '#1f77b4' t 'walk, ε = 0: rays per wavelength'",
              f"'{d}_rays.dat' u 1:2:4 w labels offset 0,1 font ',9' notitle",
              f"'{d}_rays.dat' u 1:3 w l dt 2 lw 2 lc rgb '#1f77b4' t 'expected Monte Carlo error (1/√N)'",
              f"{spectra['floor']!r} w l lw 1 lc rgb 'black' t 'noise floor: reference ({int(spectra['reference']['setting']):g} rays)'"]
    if spectra["table"]:
        write_dat(d + "_table.dat", [[r["wall_s"], r["error"], r["variant"]] for r in spectra["table"]])
        series += [f"'{d}_table.dat' u 1:2 w p pt 5 ps 1.5 lc rgb '#d62728' t 'table ({int(study.env['table_rays']):g} rays)'",
                   f"'{d}_table.dat' u 1:2:3 w labels offset 0,-1 font ',9' notitle"]
    if spectra["epsilon"]:
        write_dat(d + "_epsilon.dat", [[r["wall_s"], r["error"], f"ε={r['setting']}"] for r in spectra["epsilon"]])
        series += [f"'{d}_epsilon.dat' u 1:2 w p pt 9 ps 1.5 lc rgb '#2ca02c' t 'planner ε ({int(study.env['epsilon_rays']):g} rays)'",
                   f"'{d}_epsilon.dat' u 1:2:3 w labels offset 0,-1 rotate by -30 font ',8' tc rgb '#2ca02c' notitle"]
    script = GNUPLOT_HEAD.format(w=1100, h=650, png=os.path.join(plots, "spectra.png"))
    script += (f"set title 'S1 at 45°, {spectra['wavelengths']} wavelengths: RMS error of R against the reference'\n"
               f"set xlabel 'wall time per spectrum (s, {study.env['threads']} threads)'\n"
               "set ylabel 'RMS over wavelengths of R − R_{ref}'\n")
    script += "plot " + ", \\\n     ".join(series) + "\n"
    gnuplot(script, d + ".gp")
    return "spectra.png"


def plot_renders(study, renders, plots):
    if not renders:
        return None
    d = os.path.join(plots, "renders")
    width = 620 * len(renders)
    script = GNUPLOT_HEAD.format(w=width, h=700, png=os.path.join(plots, "renders.png"))
    script += ("set key below maxrows 3 font ',9'\n"
               f"set multiplot layout 1,{len(renders)} title 'Figure 1 scenes at {study.env['resolution']}: "
               "relative RMSE over pixels against reference A'\n")
    for band, entry in renders.items():
        dat = f"{d}_{band}"
        write_dat(dat + "_spp.dat", [[r["wall_s"], r["error"], r["error_block"], r["expected"], f"{r['spp']}"]
                                     for r in entry["spp"]])
        series = [f"'{dat}_spp.dat' u 1:2 w lp pt 7 lw 2 lc rgb '#1f77b4' t 'walk: spp (pixels)'",
                  f"'{dat}_spp.dat' u 1:2:5 w labels offset 0,1 font ',9' notitle",
                  f"'{dat}_spp.dat' u 1:3 w lp pt 6 lw 2 dt 3 lc rgb '#9467bd' t 'walk: {study.block}×{study.block} blocks'",
                  f"'{dat}_spp.dat' u 1:4 w l dt 2 lw 2 lc rgb '#1f77b4' t 'expected (1/√spp from the floor)'",
                  f"{entry['floor']!r} w l lw 1 lc rgb 'black' t 'floor: reference A ({entry['reference_spp']} spp)'",
                  f"{entry['floor_block']!r} w l lw 1 dt 3 lc rgb 'black' t 'floor, blocks'"]
        if entry["table"]:
            write_dat(dat + "_table.dat", [[r["wall_s"], r["error"], f"{r['variant']} {r['spp']}"]
                                           for r in entry["table"]])
            series += [f"'{dat}_table.dat' u 1:2 w p pt 5 ps 1.5 lc rgb '#d62728' t 'table (pixels)'",
                       f"'{dat}_table.dat' u 1:2:3 w labels offset 0,-1 font ',8' tc rgb '#d62728' notitle"]
        script += (f"set title '{band}'\nset xlabel 'wall time per render (s, {study.env['threads']} threads)'\n"
                   "set ylabel 'relative RMSE'\n")
        script += "plot " + ", \\\n     ".join(series) + "\n"
    script += "unset multiplot\n"
    gnuplot(script, d + ".gp")
    return "renders.png"


# ---- report -----------------------------------------------------------------------------------------

def git_commit(root):
    try:
        commit = subprocess.run(["git", "-C", root, "rev-parse", "--short=12", "HEAD"], check=True,
                                capture_output=True, text=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", root, "status", "--porcelain", "--untracked-files=no"], check=True,
                               capture_output=True, text=True).stdout.strip()
        return commit + (" (with uncommitted changes)" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown (no git)"


def machine_rows(env, root):
    cpu = "unknown"
    memory = "unknown"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
        with open("/proc/meminfo") as f:
            for line in f:
                if line.startswith("MemTotal"):
                    memory = f"{int(line.split()[1]) / 1024 / 1024:.1f} GiB"
                    break
    except OSError:
        pass
    wall = float(env["end_epoch"]) - float(env["start_epoch"])
    return [["date (start, end)", f"{env['started']} – {env['finished']}"],
            ["git commit", git_commit(root)],
            ["nproc / threads per run", f"{os.cpu_count()} / {env['threads']}"],
            ["CPU", cpu], ["memory", memory], ["OS", f"{platform.system()} {platform.release()}"],
            ["load average at start (1, 5, 15 min)", env["load_start"]],
            ["load average at end", env["load_end"]],
            ["study wall time (runs only)", f"{wall / 60:.1f} min"]]


def noise_band(count):
    """Half-width of the 3σ band of measured/expected RMS error when the error is pure noise: with
    `count` independent normal differences, (RMS/σ)² ~ χ²_count / count, so RMS/σ has a standard
    deviation of about 1/sqrt(2·count)."""
    return 3.0 / math.sqrt(2.0 * count)


def reading(study, spectra, renders):
    lines = []
    env = study.env
    s = spectra
    halfwidth = noise_band(s["wavelengths"])
    if s["rays"]:
        last = s["rays"][-1]
        ratios = [r["error"] / r["expected"] for r in s["rays"]]
        slope = f"{s['slope']:.2f}" if s["slope"] is not None else "–"
        lines.append(f"* **Spectra, rays per wavelength.** With the reference's noise taken out, the RMS error falls as "
                     f"N^{slope} (1/√N is N^-0.5). At {last['rays']:g} rays it is {last['error']:.2g} for "
                     f"{last['cpu_s']:.1f} CPU s; the reference's own noise floor is {s['floor']:.2g}. Measured over "
                     f"expected Monte Carlo error stays within {min(ratios):.2f}–{max(ratios):.2f} "
                     f"(pure noise over {s['wavelengths']} wavelengths: 1 ± {halfwidth:.2f} at 3σ): "
                     + ("the error is the standard errors' noise, nothing else."
                        if 1 - halfwidth < min(ratios) and max(ratios) < 1 + halfwidth else "beyond noise alone: look for a bias."))
    for band, e in renders.items():
        slope = f"{e['slope']:.2f}" if e["slope"] is not None else "–"
        last = e["spp"][-1]
        biased = [r for r in e["spp"] if r["biased"]]
        text = (f"* **Render {band}** ({e['channels']} spectral channel{'s' if e['channels'] != 1 else ''}). Relative "
                f"RMSE over pixels falls as spp^{slope} (reference noise taken out"
                + (", biased runs left out" if biased else "") + f"); {last['spp']} spp: {last['error']:.3g} per pixel "
                f"({last['error'] / last['expected']:.2f}× expected), {last['error_block']:.3g} over "
                f"{study.block}×{study.block} blocks, in {last['wall_s']:.1f} s wall. Reference A's own noise "
                f"(two references at {e['reference_spp']} spp) is {e['floor']:.3g} per pixel, "
                f"{e['floor_block']:.3g} over blocks.")
        if biased:
            text += (" **Biased at " + ", ".join(f"{r['spp']} spp (mean relative difference {r['bias']:+.2f})"
                                                 for r in biased) + "**")
            short = [r for r in biased if r["spp"] < e["channels"]]
            if short:
                text += (f": below {e['channels']} spp a pixel's samples cannot cover all {e['channels']} channels "
                         "(one channel per sample, stratified), and the film reports a channel without a sample as 0 "
                         "(renderer/image/film.h, Film::value), so the image comes out dark by about 1 − spp/channels "
                         f"(e.g. {1 - short[0]['spp'] / e['channels']:.2f} at {short[0]['spp']} spp)")
            text += "."
        lines.append(text)
    walk_rays = {r["rays"]: r for r in s["rays"]}
    cold = [t for t in s["table"] if t["variant"] == "table-cold"]
    warm = [t for t in s["table"] if t["variant"] == "table-warm"]
    if cold and warm and warm[0]["rays"] in walk_rays:
        w, c, h = walk_rays[warm[0]["rays"]], cold[0], warm[0]
        lines.append(f"* **Spectra, walk versus table** ({h['rays']:g} rays): table error {h['error']:.2g} "
                     f"({h['error'] / h['expected']:.1f}× its expected noise, mean difference {h['bias']:+.2g}) against "
                     f"the walk's {w['error']:.2g}; CPU time {c['cpu_s']:.1f} s cold (tables built), {h['cpu_s']:.2f} s "
                     f"warm, walk {w['cpu_s']:.1f} s.")
    for band, e in renders.items():
        walk = {r["spp"]: r for r in e["spp"]}
        for t in e["table"]:
            if t["variant"] == "table-warm" and t["spp"] in walk:
                c = [x for x in e["table"] if x["variant"] == "table-cold" and x["spp"] == t["spp"]]
                w = walk[t["spp"]]
                lines.append(f"* **Render {band}, walk versus table** ({t['spp']} spp): relative RMSE {t['error']:.3g} "
                             f"(table) against {w['error']:.3g} (walk), mean relative difference {t['bias']:+.3g}; wall "
                             f"{t['wall_s']:.1f} s warm" + (f", {c[0]['wall_s']:.1f} s cold" if c else "")
                             + f", walk {w['wall_s']:.1f} s.")
            if t["spp"] == e["reference_spp"]:
                lines.append(f"* **Render {band}, table at {t['spp']} spp** against walk reference A: relative RMSE "
                             f"{t['error']:.3g} where an unbiased render would give about {e['floor'] * math.sqrt(2):.3g}"
                             f" (reference B's); mean relative difference {t['bias']:+.3g}, "
                             f"{t['error_block']:.3g} over blocks (floor {e['floor_block']:.3g}).")
    if s["epsilon"]:
        base = s["epsilon"][0]
        largest = None
        for r in s["epsilon"]:  # ascending ε: the largest ε up to which every error is noise
            if r["error"] > (1 + halfwidth) * r["expected"]:
                break
            largest = r
        text = (f"* **Planner ε** ({int(env['epsilon_rays']):g} rays): "
                + (f"up to ε = {largest['setting']} the error against the exact reference stays within the noise "
                   f"band (≤ {1 + halfwidth:.2f}× the expected noise; {largest['error']:.2g} vs {largest['expected']:.2g}), at "
                   f"{base['cpu_s'] / largest['cpu_s']:.2f}× the speed of ε = 0. " if largest else "")
                + "Per ε: " + "; ".join(f"{r['setting']}: error {r['error']:.2g}, mean difference {r['bias']:+.2g}, "
                                        f"{base['cpu_s'] / r['cpu_s']:.2f}× speed" for r in s["epsilon"]) + ". ")
        beyond = [r for r in s["epsilon"] if r["beyond_bound"]]
        text += ("The planner's promise |ΔR| ≤ ε holds at every wavelength and ε (|R − R_ref| ≤ ε + 4σ, σ the "
                 "combined standard error)." if not beyond else
                 "|R − R_ref| exceeds ε + 4σ (σ the combined standard error) at " + "; ".join(
                     f"ε = {r['setting']}: {r['beyond_bound']} wavelength(s)" for r in beyond) + ".")
        lines.append(text)
    return "\n".join(lines)


def report(study, spectra, renders, plots, root, title_note):
    env = study.env
    md = ["# Accuracy versus cost", "",
          f"Written by `bench/accuracy-cost{' --quick' if env['quick'] == '1' else ''}`; rerun it to refresh "
          f"(5–15 minutes on a shared 2-core machine; `--quick` for a smoke run of 1–2 minutes). {title_note}", "",
          "## Machine", "", markdown_table(["", ""], machine_rows(env, root)), "",
          "Wall times depend on how busy the machine was (the load averages above, and each run's in "
          "`accuracy-cost/runs.csv`); CPU times (user + system, all threads) are the steadier measure of cost. "
          "Errors do not depend on the machine: every run has a fixed seed.", "",
          "## Definitions", "",
          "* **Spectra** (`hylios spectrum --specimen S1 --angle 45 --wavelengths "
          f"{env['wavelengths']}`, {spectra['wavelengths']} wavelengths): error = RMS over wavelengths of "
          f"R(λ) − R_ref(λ), the reference a run at {int(env['reference_rays']):g} rays with another seed and ε = 0 "
          "(nothing skipped). Expected Monte Carlo error of a run = sqrt(mean over λ of se² + se_ref²) from the "
          "`reflectance_stderr` columns. Noise floor = RMS over λ of the reference's se_ref. Mean difference = "
          "mean over λ of R − R_ref (a bias shows here).",
          "* **Renders** (`hylios render scenes/figure01_<band>.toml --resolution "
          f"{env['resolution']}`, ε = 0): error = relative RMSE over pixels from `hylios image-diff RUN refA` = "
          "sqrt(mean over pixels and spectral channels of (a − b)²) / mean(|b|), b = reference A; also over "
          f"{study.block}×{study.block} pixel-block means. Noise floor = reference A's own noise, estimated from a "
          "second, independent reference B at the same spp: relRMSE(B, A) / √2. Expected error at N spp = "
          "floor · sqrt(N_ref / N + 1) — the floor extrapolated as 1/√spp plus the reference's own noise. "
          "Mean relative difference = mean(a − b) / mean(|b|).",
          "* **Slopes** are least-squares fits of log(sqrt(error² − floor²)) against log N.", ""]
    md += ["## Results", "", "### Spectra", "", f"![spectra](accuracy-cost/{plots['spectra']})", ""]
    md += [markdown_table(["rays per λ", "wall s", "CPU s", "RMS error", "expected", "error / expected",
                           "mean difference"],
                          [[r["rays"], r["wall_s"], r["cpu_s"], r["error"], r["expected"], r["error"] / r["expected"],
                            r["bias"]] for r in spectra["rays"]]),
           "", f"Reference: {int(env['reference_rays']):g} rays, {spectra['reference']['wall_s']:.1f} s wall, "
           f"{spectra['reference']['cpu_s']:.1f} s CPU; noise floor {spectra['floor']:.3g}.", ""]
    if renders:
        md += ["### Renders", "", f"![renders](accuracy-cost/{plots['renders']})", ""]
        rows = []
        for band, e in renders.items():
            for r in e["spp"]:
                rows.append([band, r["spp"], r["wall_s"], r["cpu_s"], r["error"], r["expected"], r["error_block"],
                             r["bias"]])
            rows.append([band, f"ref ×2: {e['reference_spp']}", e["reference"]["wall_s"], e["reference"]["cpu_s"],
                         f"floor {g(e['floor'])}", "", f"floor {g(e['floor_block'])}", ""])
        md += [markdown_table(["band", "spp", "wall s", "CPU s", "relative RMSE", "expected",
                               f"rel. RMSE {study.block}×{study.block} blocks", "mean rel. difference"], rows), ""]
    table_rows = walk_vs_table_rows(study, spectra, renders)
    md += ["### Walk versus table", ""]
    if table_rows:
        md += ["Cold: the table cache (`HYLIOS_CACHE_DIR`, a folder in the study's output) emptied before the run, so "
               "the tables are built; warm: the same run again, tables read from disk. Errors against the walk "
               "references above (spectra: RMS error and mean difference; renders: relative RMSE over pixels and "
               "mean relative difference).", "",
               markdown_table(["kind", "subject", "setting", "model", "wall s", "CPU s", "error", "expected noise",
                               "mean (rel.) difference"], table_rows), ""]
    else:
        md += ["Not measured: this hylios has no `--skin-model` option yet.", ""]
    md += ["### Planner tolerance ε", ""]
    if spectra["epsilon"]:
        base = spectra["epsilon"][0]
        md += [f"Spectra at {int(env['epsilon_rays']):g} rays per wavelength, same seed for every ε, errors against the "
               "ε = 0 reference above.", "",
               markdown_table(["ε", "wall s", "CPU s", "RMS error", "expected", "error / expected", "mean difference",
                               "max \\|R − R_ref\\|", "λ beyond ε + 4σ", "CPU speed-up"],
                              [[r["setting"], r["wall_s"], r["cpu_s"], r["error"], r["expected"],
                                r["error"] / r["expected"], r["bias"], r["max_abs_difference"], str(r["beyond_bound"]),
                                base["cpu_s"] / r["cpu_s"]] for r in spectra["epsilon"]]), ""]
    else:
        md += ["Not measured: this hylios has no `--epsilon` option yet.", ""]
    md += ["## Reading", "", reading(study, spectra, renders), "",
           "## Files", "",
           "CSVs beside this report in `accuracy-cost/`: `spectra_rays.csv`, `renders_spp.csv`, "
           "`walk_vs_table.csv`, `epsilon.csv`, and `runs.csv` (every run: study, subject, setting, model, seed, "
           "wall and CPU seconds, 1-minute load average before it). The study's full output (spectra, EXRs, "
           "per-channel image-diff CSVs, log) stays in its output folder.", ""]
    return "\n".join(md)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out")
    parser.add_argument("--hylios", required=True)
    parser.add_argument("--root", required=True)
    parser.add_argument("--docs")
    args = parser.parse_args()
    study = Study(args.out, args.hylios)
    results = os.path.join(args.out, "results")
    plots_dir = os.path.join(args.out, "plots")
    os.makedirs(results, exist_ok=True)
    os.makedirs(plots_dir, exist_ok=True)
    spectra = analyse_spectra(study, results)
    renders = analyse_renders(study, results)
    table_rows = walk_vs_table_rows(study, spectra, renders)
    if table_rows:
        write_csv(os.path.join(results, "walk_vs_table.csv"),
                  ["kind", "subject", "setting", "model", "wall_s", "cpu_s", "error", "expected_noise",
                   "mean_difference"], table_rows)
    shutil.copy(os.path.join(args.out, "runs", "manifest.csv"), os.path.join(results, "runs.csv"))
    plots = {"spectra": plot_spectra(study, spectra, plots_dir), "renders": plot_renders(study, renders, plots_dir)}
    pending = []
    if study.env["has_table"] != "1" or study.env["has_render_table"] != "1":
        pending.append("(c) walk versus table")
    if study.env["has_epsilon"] != "1":
        pending.append("(d) the planner's ε")
    note = ("Pending, because this hylios lacks the options: " + ", ".join(pending) + "." if pending else "")
    text = report(study, spectra, renders, plots, args.root, note)
    # The report in the output folder links to its own copies, laid out like docs/.
    local = os.path.join(args.out, "accuracy-cost")
    targets = [(args.out, local)]
    if args.docs:
        targets.append((args.docs, os.path.join(args.docs, "accuracy-cost")))
    for folder, assets in targets:
        os.makedirs(assets, exist_ok=True)
        for name in sorted(os.listdir(results)):
            if name.endswith(".csv"):
                shutil.copy(os.path.join(results, name), assets)
        for name in plots.values():
            if name:
                shutil.copy(os.path.join(plots_dir, name), assets)
        with open(os.path.join(folder, "accuracy-cost.md"), "w") as f:
            f.write(text)
        print(f"accuracy-cost: wrote {os.path.join(folder, 'accuracy-cost.md')}")


if __name__ == "__main__":
    main()
