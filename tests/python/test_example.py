"""examples/plot_spectrum.py runs (matplotlib's Agg backend) and writes its PNG."""
import os
import subprocess
import sys

from conftest import SOURCE_DIR


def test_plot_spectrum_example(tmp_path):
    out = tmp_path / "s1-s4.png"
    env = dict(os.environ, MPLBACKEND="Agg", MPLCONFIGDIR=str(tmp_path / "mpl"))
    result = subprocess.run([sys.executable, str(SOURCE_DIR / "examples" / "plot_spectrum.py"),
                             "--rays", "500", "--wavelengths", "400:700:50", "--out", str(out)],
                            capture_output=True, text=True, env=env, timeout=600)
    assert result.returncode == 0, result.stderr
    assert "S1 vs NCSU obj117: RMS" in result.stdout and "S2 vs NCSU obj113: RMS" in result.stdout
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert out.stat().st_size > 10000
