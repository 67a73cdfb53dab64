"""Shared helpers of the Python module's tests: the hylios executable, running it, reading its CSV.

CTest runs these with PYTHONPATH at build/python, HYLIOS_DATA_DIR at the source tree and
HYLIOS_EXECUTABLE at build/hylios (python/CMakeLists.txt); run by hand, the same defaults apply.
"""
import csv
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[2]


def hylios_executable():
    """The hylios command to compare with: $HYLIOS_EXECUTABLE, else build/hylios."""
    return os.environ.get("HYLIOS_EXECUTABLE", str(SOURCE_DIR / "build" / "hylios"))


def run_hylios(*args, check=True):
    """Runs the hylios command; returns the CompletedProcess (text output)."""
    result = subprocess.run([hylios_executable(), *map(str, args)], capture_output=True, text=True,
                            timeout=600)
    if check and result.returncode != 0:
        raise AssertionError("hylios %s failed (%d): %s" % (" ".join(map(str, args)), result.returncode,
                                                            result.stderr))
    return result


def read_csv(path):
    """The rows of a CSV file as dicts of strings (the command's printed values)."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def printed(value):
    """A number as the command prints it (%.6g)."""
    return "%.6g" % value


def command_has_option(command, option):
    """Whether `hylios COMMAND --help` lists OPTION."""
    return option in run_hylios(command, "--help").stdout


@pytest.fixture
def ncsu():
    """The NCSU skin curves (Vrhel et al. 1994): (wavelengths, {column header: values})."""
    path = SOURCE_DIR / "tests" / "data" / "validation" / "ncsu_vrhel1994_skin.csv"
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], [r for r in rows[1:] if r]
    wavelengths = [float(r[0]) for r in body]
    columns = {name: [float(r[i]) for r in body] for i, name in enumerate(header) if i > 0}
    return wavelengths, columns
