#!/usr/bin/env python3
"""Plots the HyLIoS reflectance of specimens S1-S4 (45 deg incidence) against the NCSU skin curves
(Vrhel et al. 1994, tests/data/validation/ncsu_vrhel1994_skin.csv): the range of all 30 NCSU
samples as a band in every panel, and the sample the paper's Fig. 7 pairs with S1 (object 117)
and S2 (object 113) as a line. Prints the RMS difference for those pairs.

    PYTHONPATH=build/python python3 examples/plot_spectrum.py --out s1-s4.png
    PYTHONPATH=build/python python3 examples/plot_spectrum.py --rays 100000 --wavelengths 250:2500:5

Without a display, set MPLBACKEND=Agg (the test does).
"""
import argparse
import csv
import pathlib

import matplotlib.pyplot as plt
import numpy as np

import hylios

NCSU = pathlib.Path(hylios.data_root()) / "tests" / "data" / "validation" / "ncsu_vrhel1994_skin.csv"
PAIRS = {"S1": "obj117", "S2": "obj113"}  # the pairing of the paper's Fig. 7 caption


def load_ncsu(path=NCSU):
    """(wavelengths, {column header: reflectances}) of the NCSU file."""
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r]
    wavelengths = np.array([float(r[0]) for r in rows[1:]])
    columns = {name: np.array([float(r[i]) for r in rows[1:]]) for i, name in enumerate(rows[0]) if i}
    return wavelengths, columns


def column(columns, prefix):
    """The NCSU column whose header starts with `prefix` (e.g. "obj117")."""
    return next(values for name, values in columns.items() if name.startswith(prefix))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--wavelengths", default="380:780:10", help="start:stop:step or a comma list, nm")
    parser.add_argument("--rays", type=int, default=20000, help="rays per wavelength")
    parser.add_argument("--estimator", default="spectral", choices=["spectral", "per-wavelength"])
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", default="s1-s4_vs_ncsu.png", help="PNG to write")
    args = parser.parse_args()

    ncsu_nm, ncsu = load_ncsu()
    stack = np.vstack(list(ncsu.values()))
    figure, axes = plt.subplots(2, 2, figsize=(11, 8), sharex=True, sharey=True)
    for ax, name in zip(axes.flat, ["S1", "S2", "S3", "S4"]):
        curve = hylios.spectrum(hylios.Specimen.load(name), args.wavelengths, angle_deg=45,
                                rays=args.rays, seed=args.seed, estimator=args.estimator)
        ax.fill_between(ncsu_nm, stack.min(axis=0), stack.max(axis=0), color="0.85",
                        label="NCSU, all 30 samples")
        ax.errorbar(curve.wavelength_nm, curve.reflectance, yerr=2 * curve.reflectance_stderr,
                    label="HyLIoS %s (± 2 s.e.)" % name, lw=1.8)
        ax.plot(curve.wavelength_nm, curve.surface, ":", lw=1, label="surface")
        if name in PAIRS:
            measured = column(ncsu, PAIRS[name])
            ax.plot(ncsu_nm, measured, "k-", lw=1.5, label="NCSU %s" % PAIRS[name])
            inside = (curve.wavelength_nm >= ncsu_nm[0]) & (curve.wavelength_nm <= ncsu_nm[-1])
            if inside.any():
                model = curve.reflectance[inside]
                rms = np.sqrt(np.mean((model - np.interp(curve.wavelength_nm[inside], ncsu_nm, measured)) ** 2))
                print("%s vs NCSU %s: RMS %.4f over %d wavelengths" % (name, PAIRS[name], rms, inside.sum()))
        ax.set_title("%s, 45°, %d rays per wavelength" % (name, args.rays))
        ax.set_xlabel("wavelength (nm)")
        ax.set_ylabel("reflectance")
        ax.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(args.out, dpi=100)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
