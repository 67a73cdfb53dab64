"""A module call and the matching command give identical numbers for the same seed (compared at the
CSV's printed precision, %.6g)."""
import pytest

import hylios
from conftest import command_has_option, printed, read_csv, run_hylios

SPECTRUM_COLUMNS = {
    "reflectance": "reflectance", "reflectance_stderr": "reflectance_stderr",
    "surface_reflectance": "surface", "subsurface_reflectance": "subsurface",
    "transmittance": "transmittance", "absorptance": "absorptance",
    "absorptance_stderr": "absorptance_stderr", "event_limited": "event_limited",
    "effect_bound": "effect_bound",
}


def compare_spectrum(rows, curve):
    assert len(rows) == len(curve.wavelength_nm)
    for i, row in enumerate(rows):
        assert float(row["wavelength_nm"]) == pytest.approx(curve.wavelength_nm[i], rel=1e-12)
        for column, field in SPECTRUM_COLUMNS.items():
            if column in row:
                assert row[column] == printed(getattr(curve, field)[i]), (column, row["wavelength_nm"])
        for layer in curve.layers:
            assert row["absorptance_" + layer] == printed(getattr(curve, "absorptance_" + layer)[i])


@pytest.mark.parametrize("specimen,overrides,angle", [
    ("S1", {}, 45), ("S4", {"melanosome_percent": 3, "water_reduction_percent": 20}, 20)])
def test_spectrum_per_wavelength_matches_command(tmp_path, specimen, overrides, angle):
    out = tmp_path / "s.csv"
    args = ["spectrum", "--specimen", specimen, "--wavelengths", "365,550,1100,2200", "--rays", "3000",
            "--seed", "7", "--angle", angle, "--out", out]
    for key, value in overrides.items():
        args += ["--set", "%s=%s" % (key, value)]
    run_hylios(*args, *estimator_args("spectrum", "per-wavelength"))
    curve = hylios.spectrum(hylios.Specimen.load(specimen, overrides), [365, 550, 1100, 2200],
                            angle_deg=angle, rays=3000, seed=7, estimator="per-wavelength")
    compare_spectrum(read_csv(out), curve)


def test_spectrum_range_and_epsilon_zero_match_command(tmp_path):
    out = tmp_path / "s.csv"
    args = ["spectrum", "--specimen", "S2", "--wavelengths", "400:700:100", "--rays", "2000",
            "--epsilon", "0", "--out", out]
    run_hylios(*args, *estimator_args("spectrum", "per-wavelength"))
    curve = hylios.spectrum("S2", "400:700:100", rays=2000, epsilon=0, estimator="per-wavelength")
    compare_spectrum(read_csv(out), curve)


def test_spectrum_spectral_matches_command(tmp_path):
    out = tmp_path / "s.csv"
    # 24 wavelengths across the bundle rule's bounds (several bundles)
    run_hylios("spectrum", "--specimen", "S3", "--wavelengths", "350:1500:50", "--rays", "2000",
               "--seed", "3", "--out", out, *estimator_args("spectrum", "spectral"))
    curve = hylios.spectrum("S3", "350:1500:50", rays=2000, seed=3, estimator="spectral")
    compare_spectrum(read_csv(out), curve)


def test_spectrum_table_mode_matches_command(tmp_path, monkeypatch):
    # Table mode with the spectral estimator: the bundle's tables are built once from spectral walks
    # (by the command, into this cache) and then read by the module (its cache is made on first use).
    monkeypatch.setenv("HYLIOS_CACHE_DIR", str(tmp_path / "cache"))
    out = tmp_path / "s.csv"
    run_hylios("spectrum", "--specimen", "S1", "--wavelengths", "300,320,340", "--rays", "2000",
               "--seed", "5", "--skin-model", "table", "--out", out)
    curve = hylios.spectrum("S1", [300, 320, 340], rays=2000, seed=5, skin_model="table")
    compare_spectrum(read_csv(out), curve)
    assert len(list((tmp_path / "cache").glob("exit-*.hxt"))) == 3


def test_spectral_same_at_any_thread_count():
    one = hylios.spectrum("S1", "400:700:20", rays=1500, threads=1)
    two = hylios.spectrum("S1", "400:700:20", rays=1500, threads=2)
    assert (one.reflectance == two.reflectance).all()
    assert (one.layer_absorptance == two.layer_absorptance).all()


def test_coefficients_match_command(tmp_path):
    out = tmp_path / "c.csv"
    run_hylios("coefficients", "--specimen", "S2", "--wavelengths", "250:2500:250",
               "--set", "blood_percent=4", "--out", out)
    c = hylios.coefficients(hylios.Specimen.load("S2", blood_percent=4), "250:2500:250")
    rows = read_csv(out)
    assert len(rows) == len(c.wavelength_nm) * len(c.layers)
    for k, row in enumerate(rows):
        i, j = divmod(k, len(c.layers))
        assert row["layer"] == c.layers[j]
        assert row["mu_a_per_cm"] == printed(c.mu_a_per_cm[i, j])
        assert row["mu_s_rayleigh_per_cm"] == printed(c.mu_s_rayleigh_per_cm[i, j])
        assert row["mu_melanosome_per_cm"] == printed(c.mu_melanosome_per_cm[i, j])
        assert row["refractive_index"] == printed(c.refractive_index[i, j])
        for a, absorber in enumerate(c.absorbers):
            assert row["mu_a_%s_per_cm" % absorber] == printed(c.mu_a_absorber_per_cm[i, j, a])


def estimator_args(command, estimator):
    """--estimator ESTIMATOR where the command has it (else it walks per wavelength)."""
    if command_has_option(command, "--estimator"):
        return ["--estimator", estimator]
    if estimator != "per-wavelength":
        pytest.skip("hylios %s has no --estimator option in this build" % command)
    return []


@pytest.mark.parametrize("estimator", ["spectral", "per-wavelength"])
def test_radial_profile_matches_command(tmp_path, estimator):
    out = tmp_path / "r.csv"
    run_hylios("radial-profile", "--specimen", "S1", "--wavelength", "650", "--rays", "4000",
               "--bins", "12", "--max-radius-cm", "0.3", "--out", out, *estimator_args("radial-profile", estimator))
    p = hylios.radial_profile("S1", 650, rays=4000, bins=12, max_radius_cm=0.3, estimator=estimator)
    rows = read_csv(out)
    assert len(rows) == 12
    for i, row in enumerate(rows):
        for column in ("inner_radius_cm", "outer_radius_cm", "annulus_area_cm2", "fraction",
                       "fraction_stderr", "reflectance_per_cm2", "reflectance_per_cm2_stderr"):
            assert row[column] == printed(getattr(p, column)[i]), column


@pytest.mark.parametrize("estimator", ["spectral", "per-wavelength"])
def test_brdf_matches_command(tmp_path, estimator):
    out = tmp_path / "b.csv"
    run_hylios("brdf", "--specimen", "S1", "--wavelengths", "450,600,1200", "--rays", "3000",
               "--polar-bins", "6", "--azimuth-bins", "4", "--angle", "30", "--out", out,
               *estimator_args("brdf", estimator))
    b = hylios.brdf("S1", [450, 600, 1200], rays=3000, polar_bins=6, azimuth_bins=4, angle_deg=30,
                    estimator=estimator)
    rows = read_csv(out)
    assert len(rows) == 24
    for k, row in enumerate(rows):
        i, j = divmod(k, 4)
        assert row["polar_lower_deg"] == printed(b.polar_lower_deg[i])
        assert row["azimuth_upper_deg"] == printed(b.azimuth_upper_deg[j])
        assert row["solid_angle_sr"] == printed(b.solid_angle_sr[i])
        for quantity, parts in (("per_sr", b.per_sr), ("brdf", b.brdf)):
            for part in ("surface", "subsurface", "total"):
                assert row["%s_%s" % (part, quantity)] == printed(getattr(parts, part)[i, j])
                assert row["%s_%s_stderr" % (part, quantity)] == printed(getattr(parts, part + "_stderr")[i, j])


SLAB_LAYERS = [{"n": 1.37, "mua": 1, "mus": 100, "g": 0.9, "d": 0.1},
               {"n": 1.37, "mua": 1, "mus": 10, "g": 0, "d": 0.1},
               (1.37, 2, 10, 0.7, 0.2)]


@pytest.mark.parametrize("extra,kwargs", [
    ([], {}),                                    # the weighted walk in lanes (the default)
    (["--scalar"], {"scalar": True}),            # one packet at a time, double precision
    (["--scheme", "analog"], {"scheme": "analog"}),
    (["--diffuse", "--below", "1.4"], {"diffuse": True, "below": 1.4}),
])
def test_slab_matches_command(tmp_path, extra, kwargs):
    out = tmp_path / "slab.csv"
    layer_args = []
    for layer in SLAB_LAYERS:
        n, mua, mus, g, d = (layer[k] for k in ("n", "mua", "mus", "g", "d")) if isinstance(layer, dict) else layer
        layer_args += ["--layer", "n=%r,mua=%r,mus=%r,g=%r,d=%r" % (n, mua, mus, g, d)]
    run_hylios("slab", *layer_args, "--rays", "20000", "--seed", "5", "--out", out, *extra)
    result = hylios.slab(SLAB_LAYERS, rays=20000, seed=5, **kwargs)
    row = read_csv(out)[0]
    columns = ["specular_reflectance", "diffuse_reflectance", "diffuse_reflectance_stderr",
               "transmittance", "transmittance_stderr", "unscattered_transmittance", "absorptance",
               "absorptance_stderr", "event_limited"]
    for column in columns:  # the command prints 9 significant digits
        assert float(row[column]) == pytest.approx(getattr(result, column), rel=1e-8, abs=1e-300), column
    for i in range(3):
        assert float(row["absorptance_layer%d" % (i + 1)]) == pytest.approx(
            result.layer_absorptance[i], rel=1e-8, abs=1e-300)
        assert float(row["absorptance_layer%d_stderr" % (i + 1)]) == pytest.approx(
            result.layer_absorptance_stderr[i], rel=1e-8, abs=1e-300)
