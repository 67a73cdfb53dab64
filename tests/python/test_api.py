"""The module's API: specimens and overrides, results, errors with the command line's messages,
the GIL released during a call, Ctrl-C, renders and fits."""
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

import hylios
from conftest import SOURCE_DIR, run_hylios


def command_error(*args):
    """The message the command prints for an error ("hylios: error: MESSAGE")."""
    result = run_hylios(*args, check=False)
    assert result.returncode != 0
    line = [l for l in result.stderr.splitlines() if l.startswith("hylios: error: ")][-1]
    return line[len("hylios: error: "):]


def test_goal_check_call():
    curve = hylios.spectrum(hylios.Specimen.load("S1"), [365, 550, 1100], rays=20000)
    assert curve.reflectance.shape == (3,)
    assert curve.reflectance.dtype == np.float64
    assert ((curve.reflectance > 0.05) & (curve.reflectance < 0.9)).all()
    assert curve.layer_absorptance.shape == (3, 6)
    # every ray ends somewhere: R + T + A = 1 up to the event-limited ones
    total = curve.reflectance + curve.transmittance + curve.absorptance + curve.event_limited
    assert np.allclose(total, 1, atol=1e-9)
    assert np.allclose(curve.surface + curve.subsurface, curve.reflectance, atol=1e-9)


def test_specimen_load_overrides_and_toml_round_trip(tmp_path):
    s1 = hylios.Specimen.load("S1")
    assert s1.name == "S1" and s1.source_file.endswith("S1.toml")
    by_kwargs = hylios.Specimen.load("S1", melanosome_percent=3, water_reduction_percent=20)
    by_dict = hylios.Specimen.load("S1", {"melanosome_percent": 3, "water_reduction_percent": 20})
    chained = s1.with_overrides(melanosome_percent=3).with_overrides(water_reduction_percent=20)
    assert by_kwargs.to_toml() == by_dict.to_toml() == chained.to_toml() != s1.to_toml()
    assert by_kwargs.values()["water_reduction"] == pytest.approx(0.2)
    assert "melanosome_percent" in hylios.override_keys()
    # to_toml reads back (from text and from a file) to the same model
    path = tmp_path / "mine.toml"
    path.write_text(by_kwargs.to_toml("written by a test"))
    again = hylios.Specimen.load(str(path))
    parsed = hylios.Specimen.from_toml(by_kwargs.to_toml())
    a = hylios.coefficients(by_kwargs, "300:2400:300").mu_a_per_cm
    assert np.allclose(hylios.coefficients(again, "300:2400:300").mu_a_per_cm, a, rtol=1e-12)
    assert np.allclose(hylios.coefficients(parsed, "300:2400:300").mu_a_per_cm, a, rtol=1e-12)


def test_errors_carry_the_command_line_messages(tmp_path):
    with pytest.raises(hylios.SpecimenError) as e:
        hylios.Specimen.load("S1", no_such_key=3)
    assert str(e.value) == command_error("spectrum", "--specimen", "S1", "--set", "no_such_key=3",
                                         "--out", tmp_path / "x.csv")
    with pytest.raises(hylios.SpecimenError) as e:
        hylios.Specimen.load("S1", melanosome_percent=-5)
    assert str(e.value) == command_error("spectrum", "--specimen", "S1", "--set", "melanosome_percent=-5",
                                         "--out", tmp_path / "x.csv")
    with pytest.raises(hylios.SpecimenError) as e:
        hylios.Specimen.load("S9")
    assert str(e.value) == command_error("spectrum", "--specimen", "S9", "--out", tmp_path / "x.csv")
    with pytest.raises(ValueError) as e:
        hylios.spectrum("S1", "700:400:5")
    assert str(e.value) == command_error("spectrum", "--wavelengths", "700:400:5", "--out", tmp_path / "x.csv")
    with pytest.raises(ValueError):
        hylios.spectrum("S1", [550], estimator="nonsense")
    with pytest.raises(TypeError):
        hylios.spectrum(42, [550])


def test_slab_errors_name_the_layer(tmp_path):
    good = {"n": 1.37, "mua": 1, "mus": 10, "g": 0.5, "d": 0.1}
    with pytest.raises(ValueError) as e:
        hylios.slab([good, dict(good, mus=-1)])
    assert str(e.value) == "layer 2: mus must be finite and >= 0, got -1"
    with pytest.raises(ValueError) as e:
        hylios.slab([dict(good, mu_a=1)])
    assert str(e.value) == "layers[0]: expected the keys n, mua, mus, g, d; unknown: mu_a"
    with pytest.raises(ValueError) as e:
        hylios.slab([(1.37, 1, 10, 0.5)])
    assert str(e.value) == "layers[0]: expected (n, mua, mus, g, d), got 4 values"
    with pytest.raises(ValueError) as e:
        hylios.slab([good], angle_deg=95)
    assert str(e.value) == "angle_deg must lie in [0, 90)"
    with pytest.raises(ValueError):
        hylios.slab([good], scheme="nonsense")
    with pytest.raises(ValueError) as e:
        hylios.slab([])
    assert str(e.value) == "slab: at least one layer is needed"
    with pytest.raises(TypeError):
        hylios.slab(good)


def test_scene_errors_name_file_line_column(tmp_path):
    scene = tmp_path / "broken.toml"
    scene.write_text((SOURCE_DIR / "scenes" / "test" / "skin_sphere_550.toml").read_text()
                     .replace("[film]", "[film]\nno_such_key = 1", 1))
    with pytest.raises(hylios.SceneError) as e:
        hylios.render(str(scene))
    message = str(e.value)
    assert message.startswith(str(scene) + ":")
    assert message == command_error("render", scene, "--out", tmp_path / "x.exr")


def test_render_returns_image_and_wavelengths():
    scene = SOURCE_DIR / "scenes" / "test" / "skin_sphere_550.toml"
    image, wavelengths = hylios.render(scene, spp=2, resolution=(20, 12), seed=3)
    assert image.shape == (12, 20, len(wavelengths)) and image.dtype == np.float32
    assert wavelengths.tolist() == [550.0]
    assert np.isfinite(image).all() and image.max() > 0
    again, _ = hylios.render(str(scene), spp=2, resolution="20x12", seed=3, threads=1)
    assert (again == image).all()  # deterministic at any thread count
    with pytest.raises(ValueError):
        hylios.render(scene, resolution="20by12")
    if hylios._hylios.render_has_noise_target:
        noisy, _ = hylios.render(scene, spp=4, resolution=(20, 12), noise_target=0.5)
        assert noisy.shape == image.shape and np.isfinite(noisy).all()
    else:
        with pytest.raises(NotImplementedError):
            hylios.render(scene, noise_target=0.05)
    for estimator in ("spectral", "per-wavelength"):
        if hylios._hylios.render_has_estimator:
            walked, _ = hylios.render(scene, spp=2, resolution=(20, 12), estimator=estimator)
            assert walked.shape == image.shape and walked.max() > 0
        else:
            with pytest.raises(ValueError):
                hylios.render(scene, spp=2, resolution=(20, 12), estimator=estimator)
    # The camera paths' numbers (--sampler): sobol by default, independent on request.
    independent, _ = hylios.render(scene, spp=2, resolution=(20, 12), seed=3, sampler="independent")
    sobol, _ = hylios.render(scene, spp=2, resolution=(20, 12), seed=3, sampler="sobol")
    assert (sobol == image).all() and not (independent == image).all()
    assert np.isfinite(independent).all() and independent.max() > 0
    with pytest.raises(ValueError, match="sampler"):
        hylios.render(scene, spp=2, resolution=(20, 12), sampler="halton")


def test_gil_is_released_during_a_call():
    ticks = []
    done = threading.Event()

    def compute():
        hylios.spectrum("S1", "400:700:10", rays=4000, estimator="per-wavelength")
        done.set()

    worker = threading.Thread(target=compute)
    worker.start()
    while not done.is_set():
        ticks.append(time.monotonic())
        time.sleep(0.005)
    worker.join()
    assert len(ticks) > 10  # the main thread ran while the spectrum was computed


# Each call would run for minutes. The spectral estimator stops between bundles of wavelengths
# (seconds each at 1e5 rays on 2 cores; a one-wavelength call is one bundle, so it is not
# interrupted before its end), the per-wavelength one between wavelengths or TBB tasks.
@pytest.mark.parametrize("call,latency_s", [
    ("hylios.spectrum('S1', '250:2500:5', rays=10**5)", 45),
    ("hylios.spectrum('S1', '250:2500:5', rays=10**6, estimator='per-wavelength')", 30),
    ("hylios.radial_profile('S1', rays=10**7, estimator='per-wavelength')", 30),
    ("hylios.brdf('S1', '380:780:10', rays=3 * 10**6, estimator='per-wavelength')", 30),
    ("hylios.slab([(1.37, 1, 100, 0.9, 0.1)], rays=10**10)", 30),
])
def test_ctrl_c_interrupts_a_long_call(call, latency_s):
    script = textwrap.dedent("""
        import sys, time, hylios
        print("started", flush=True)
        t = time.monotonic()
        try:
            %s
        except KeyboardInterrupt:
            print("interrupted after %%.2f s" %% (time.monotonic() - t), flush=True)
            sys.exit(3)
        sys.exit(0)
    """) % call
    process = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True,
                               env=os.environ.copy())
    assert process.stdout.readline().strip() == "started"
    time.sleep(1.5)
    sent = time.monotonic()
    process.send_signal(signal.SIGINT)
    out, _ = process.communicate(timeout=120)
    assert process.returncode == 3, out
    assert "interrupted" in out
    assert time.monotonic() - sent < latency_s


def test_fit_matches_command(tmp_path, ncsu):
    wavelengths, columns = ncsu
    name = next(k for k in columns if k.startswith("obj113"))
    fitted_file = tmp_path / "fit.toml"
    run_hylios("fit", "--specimen", "S2", "--measured",
               "%s:obj113" % (SOURCE_DIR / "tests" / "data" / "validation" / "ncsu_vrhel1994_skin.csv"),
               "--wavelengths", "400:700:50", "--free", "melanosome,blood", "--rays", "500",
               "--max-iterations", "3", "--out", fitted_file)
    fit = hylios.fit(wavelengths, columns[name], hylios.Specimen.load("S2"), free=["melanosome", "blood"],
                     wavelengths="400:700:50", rays=500, max_iterations=3)
    assert set(fit.values) == {"melanosome", "blood"}
    assert fit.rms <= fit.start_rms
    assert fit.model_reflectance.shape == fit.wavelength_nm.shape == (7,)
    assert all(u >= 0 for u in fit.uncertainties.values())
    body = "\n".join(l for l in fitted_file.read_text().splitlines() if not l.startswith("#")).strip()
    assert fit.specimen.to_toml().strip() == body
    with pytest.raises(hylios.FitError):
        hylios.fit(wavelengths, columns[name], "S2", free=["no_such_quantity"])
