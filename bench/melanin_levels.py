#!/usr/bin/env python3
"""Largest relative error of linear interpolation in m between melanin levels.

Reads DIR/m_0.csv … m_30.csv (`hylios spectrum` at multipliers m = 1.0 … 4.0, written by
bench/melanin-levels.sh), fits each wavelength's R(m) by a degree-6 polynomial in ln m (the fit's
rms residual in standard errors is printed: near 0.5 with common random numbers), and prints, for
each level set over [1, 4], the largest |interpolated − fitted| / fitted over m per wavelength.

usage: melanin_levels.py DIR
"""
import csv
import sys

import numpy as np


def main():
    folder = sys.argv[1]
    ms = np.array([1 + 0.1 * i for i in range(31)])
    data = {}
    for i in range(31):
        with open(f"{folder}/m_{i}.csv") as f:
            for row in csv.DictReader(f):
                data.setdefault(float(row["wavelength_nm"]), []).append(
                    (float(row["reflectance"]), float(row["reflectance_stderr"])))
    fits = {}
    print("wavelength_nm, R(m=1), R(m=4), fit rms residual (standard errors)")
    for wl, values in sorted(data.items()):
        r = np.array([v[0] for v in values])
        se = np.array([v[1] for v in values])
        fits[wl] = np.polyfit(np.log(ms), r, 6)
        residual = (r - np.polyval(fits[wl], np.log(ms))) / se
        print(f"{wl:.0f}, {r[0]:.4f}, {r[-1]:.4f}, {np.sqrt(np.mean(residual ** 2)):.2f}")
    fine = np.linspace(1, 4, 3001)
    sets = {f"{k} levels linear in m": np.linspace(1, 4, k) for k in (6, 7, 8, 9)}
    sets.update({f"{k} levels linear in ln m": np.geomspace(1, 4, k) for k in (7, 8, 9)})
    sets.update({f"{k} levels linear in sqrt m" + (" (the renderer's)" if k == 7 else ""):
                 np.linspace(1, 2, k) ** 2 for k in (6, 7, 8)})
    print("level set: largest relative interpolation error per wavelength (%), and overall")
    for name, levels in sets.items():
        errors = []
        for wl, c in sorted(fits.items()):
            f = np.polyval(c, np.log(fine))
            interpolated = np.interp(fine, levels, np.polyval(c, np.log(levels)))
            errors.append((wl, 100 * np.max(np.abs(interpolated - f) / f)))
        text = " ".join(f"{wl:.0f}:{e:.2f}" for wl, e in errors)
        print(f"{name}: {text}  max {max(e for _, e in errors):.2f}")


if __name__ == "__main__":
    main()
