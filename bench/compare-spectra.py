#!/usr/bin/env python3
"""Statistical agreement of two `hylios spectrum` CSVs (same wavelengths, independent runs).

For every wavelength and every fraction column, z = (a - b) / sqrt(se_a^2 + se_b^2), with the
binomial standard error sqrt(p (1 - p) / (N - 1)) of an analog 0/1 tally of N rays (equal to the
CSV's *_stderr columns). Prints the largest |z| per column and overall; exits 1 if any |z| > limit.

usage: compare-spectra.py A.csv B.csv RAYS [--limit 3]
"""
import csv
import math
import sys


def main():
    args = sys.argv[1:]
    limit = 3.0
    if "--limit" in args:
        i = args.index("--limit")
        limit = float(args[i + 1])
        del args[i:i + 2]
    if len(args) != 3:
        sys.exit(__doc__)
    a_rows = list(csv.DictReader(open(args[0])))
    b_rows = list(csv.DictReader(open(args[1])))
    rays = float(args[2])
    if [r["wavelength_nm"] for r in a_rows] != [r["wavelength_nm"] for r in b_rows]:
        sys.exit("the two files have different wavelengths")
    columns = [c for c in a_rows[0] if c != "wavelength_nm" and not c.endswith("_stderr")]
    se = lambda p: math.sqrt(max(p * (1 - p), 0.0) / (rays - 1))
    worst_all = (0.0, "", "")
    for column in columns:
        worst = (0.0, "")
        for ra, rb in zip(a_rows, b_rows):
            pa, pb = float(ra[column]), float(rb[column])
            sigma = math.hypot(se(pa), se(pb))
            if sigma == 0:
                if pa != pb:
                    worst = (math.inf, ra["wavelength_nm"])
                continue
            z = (pa - pb) / sigma
            if abs(z) > abs(worst[0]):
                worst = (z, ra["wavelength_nm"])
        print(f"{column:32s} max |z| = {abs(worst[0]):5.2f} at {worst[1] or '-'} nm")
        if abs(worst[0]) > abs(worst_all[0]):
            worst_all = (worst[0], column, worst[1])
    print(f"overall max |z| = {abs(worst_all[0]):.2f} ({worst_all[1]} at {worst_all[2]} nm), "
          f"{len(a_rows)} wavelengths x {len(columns)} columns")
    sys.exit(1 if abs(worst_all[0]) > limit else 0)


if __name__ == "__main__":
    main()
