"""hylios: the HyLIoS hyperspectral skin model and renderer from Python.

Every function runs what the matching ``hylios`` command runs (same libraries, options and random
streams), so the numbers are the ones the command writes for the same seed, and returns numpy
arrays instead of CSV or EXR files::

    import hylios
    s1 = hylios.Specimen.load("S1", melanosome_percent=3)
    curve = hylios.spectrum(s1, "250:2500:5", rays=100000)
    curve.wavelength_nm, curve.reflectance, curve.reflectance_stderr

Data (absorber spectra, specimens S1-S4) come from ``$HYLIOS_DATA_DIR`` or else the source tree
the module was built from. Errors raise exceptions with the command line's messages
(``SpecimenError``, ``SceneError`` with file:line:col, ``ValueError``, ``RuntimeError``). The GIL
is released while a call computes, and Ctrl-C interrupts it (KeyboardInterrupt) at the next safe
point: between wavelengths, spectral bundles or render passes.

Functions: ``Specimen.load``, ``spectrum``, ``coefficients``, ``brdf``, ``radial_profile``,
``fit``, ``render``, ``fit_quantities``, ``override_keys``, ``layer_names``, ``absorber_names``,
``data_root``.
"""
import numbers
import os

import numpy as np

from . import _hylios
from ._hylios import FitError, SceneError, SpecimenError

__all__ = [
    "Specimen", "SpecimenError", "SceneError", "FitError", "Result", "spectrum", "coefficients",
    "brdf", "radial_profile", "slab", "render", "fit", "fit_quantities", "override_keys", "layer_names", "absorber_names", "data_root",
]


def override_keys():
    """The specimen quantities that overrides may set (the keys of ``--set KEY=VALUE``)."""
    return list(_hylios.override_keys())


def layer_names():
    """The six skin layers, top to bottom: the column order of per-layer arrays."""
    return list(_hylios.layer_names())


def absorber_names():
    """The absorbers, in the order of the last axis of ``coefficients(...).mu_a_absorber_per_cm``."""
    return list(_hylios.absorber_names())


def data_root():
    """The folder holding assets/ and scenes/ ($HYLIOS_DATA_DIR, else the source tree built from)."""
    return _hylios.data_root()


def _override_texts(overrides, kwargs):
    """'key=value' texts (as given to --set) from a dict or list of pairs and keyword arguments."""
    items = []
    if overrides is not None:
        items.extend(overrides.items() if hasattr(overrides, "items") else overrides)
    items.extend(kwargs.items())
    texts = []
    for key, value in items:
        if isinstance(value, bool):
            pass
        elif isinstance(value, numbers.Integral):
            value = str(int(value))
        elif isinstance(value, numbers.Real):
            value = repr(float(value))
        texts.append("%s=%s" % (key, value))
    return texts


class Specimen:
    """A skin specimen (paper Tables 1-2) with any overrides applied.

    Make one with ``Specimen.load("S1")``, ``Specimen.load("path/to/file.toml")`` or
    ``Specimen.from_toml(text)``; ``with_overrides`` gives a modified copy.
    """

    def __init__(self, core, overrides=()):
        """Wraps a loaded specimen; use ``Specimen.load`` or ``Specimen.from_toml`` instead."""
        self._core = core
        self._overrides = tuple(overrides)

    @classmethod
    def load(cls, name_or_path, overrides=None, **kwargs):
        """Loads specimen ``S1``..``S4`` (scenes/specimens/) or a specimen file by path.

        Overrides come as a dict and/or keyword arguments with the keys of the command line's
        ``--set KEY=VALUE`` (``override_keys()``), applied in order, e.g.
        ``Specimen.load("S1", melanosome_percent=3, water_reduction_percent=20)``.
        Raises ``SpecimenError`` with the command's message for a bad file, key or value.
        """
        texts = _override_texts(overrides, kwargs)
        return cls(_hylios.load_specimen(os.fspath(name_or_path), texts), texts)

    @classmethod
    def from_toml(cls, text, source_name="<string>"):
        """Parses specimen-file TOML text (the format of ``to_toml``); errors name ``source_name``."""
        return cls(_hylios.specimen_from_toml(text, source_name))

    def with_overrides(self, overrides=None, **kwargs):
        """A copy with further overrides (a dict and/or keyword arguments, as in ``load``)."""
        texts = _override_texts(overrides, kwargs)
        return Specimen(_hylios.with_overrides(self._core, texts), self._overrides + tuple(texts))

    @property
    def name(self):
        """The specimen's name (e.g. "S1")."""
        return self._core.name

    @property
    def source_file(self):
        """The file it was loaded from ("" when parsed from text)."""
        return self._core.source_file

    @property
    def overrides(self):
        """The overrides applied, as 'key=value' texts in order."""
        return list(self._overrides)

    def to_toml(self, header=""):
        """The specimen (overrides included) as specimen-file TOML that ``load``/``from_toml`` read
        back; ``header`` is written first as comment lines."""
        return self._core.to_toml(header)

    def values(self):
        """The main quantities as a dict (fractions in [0, 1]; lists are per layer, top to bottom)."""
        return dict(self._core.values())

    def __repr__(self):
        """Specimen('S1', key=value, ...)."""
        extra = (", " + ", ".join(self._overrides)) if self._overrides else ""
        return "Specimen(%r%s)" % (self.name, extra)


class Result:
    """The arrays of one computation as attributes (``fields()`` lists them, ``as_dict()`` gives them)."""

    def __init__(self, kind, values):
        """Holds ``values`` (a dict) as attributes; made by the hylios functions."""
        self._kind = kind
        self._fields = list(values)
        for key, value in values.items():
            setattr(self, key, value)

    def fields(self):
        """The attribute names, in order."""
        return list(self._fields)

    def as_dict(self):
        """The attributes as a dict."""
        return {key: getattr(self, key) for key in self._fields}

    def __repr__(self):
        """Kind(field: array[shape], ...)."""
        parts = []
        for key in self._fields:
            value = getattr(self, key)
            if isinstance(value, np.ndarray):
                parts.append("%s: array%s" % (key, list(value.shape)))
            elif isinstance(value, Result):
                parts.append("%s: %r" % (key, value))
            else:
                parts.append("%s: %r" % (key, value))
        return "%s(%s)" % (self._kind, ", ".join(parts))


def _specimen(specimen):
    """The compiled specimen of a ``Specimen`` or of a name/path (loaded without overrides)."""
    if isinstance(specimen, Specimen):
        return specimen._core
    if isinstance(specimen, (str, os.PathLike)):
        return Specimen.load(specimen)._core
    raise TypeError("specimen: expected a hylios.Specimen or a specimen name/path, got %r" % (specimen,))


def _wavelength_text(wavelengths):
    """The command line's --wavelengths text: 'start:stop:step' or a comma list (exact values)."""
    if isinstance(wavelengths, str):
        return wavelengths
    values = np.asarray(wavelengths, dtype=float).ravel()
    return ",".join(repr(float(w)) for w in values)


def _count(name, value):
    """A non-negative integer argument (an integral float is accepted); TypeError/ValueError otherwise."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        if isinstance(value, float) and value.is_integer():
            value = int(value)
        else:
            raise TypeError("%s: expected an integer, got %r" % (name, value))
    if value < 0:
        raise ValueError("%s must not be negative" % name)
    return int(value)


def _seed(value):
    """A seed in [0, 2^63-1], the commands' range."""
    value = _count("seed", value)
    if value > 2**63 - 1:
        raise ValueError("seed must lie in [0, 2^63-1]")
    return value


def spectrum(specimen, wavelengths, angle_deg=45, rays=100000, seed=1, estimator="spectral",
             threads=0, epsilon=1e-3, skin_model="walk", progress=False):
    """Total hemispherical reflectance of a specimen over wavelengths (``hylios spectrum``).

    specimen: a ``Specimen`` (or a name/path); wavelengths: 'start:stop:step', a comma list, a
    number or a sequence/array (nm); angle_deg: incidence from the normal in [0, 90); rays: per
    wavelength; seed: the same seed gives the same numbers at any thread count; estimator:
    "spectral" (the default of the command: paths shared by bundles of wavelengths,
    skin/spectral_simulation.h, tabulated melanosome paths, the full model) or "per-wavelength"
    (the analog walk per wavelength, skin/skin_simulation.h, with the effect planner of tolerance
    ``epsilon``, 0 = full model); skin_model "table" samples the cached exit tables per wavelength
    (with the planner, whatever the estimator, as the command does); threads: 0 = all cores;
    progress: draw the command's progress bar on a terminal's stderr.

    Returns a ``Result`` with arrays over the wavelengths: ``wavelength_nm, reflectance,
    reflectance_stderr, surface, subsurface, transmittance, absorptance, absorptance_stderr,
    event_limited, effect_bound``; ``layer_absorptance`` [wavelength, layer] and
    ``absorptance_<layer>`` per layer; ``layers`` (names) and ``specimen`` (its name).
    """
    d = _hylios.spectrum(_specimen(specimen), _wavelength_text(wavelengths), float(angle_deg),
                         _count("rays", rays), _seed(seed), str(estimator),
                         _count("threads", threads), float(epsilon), str(skin_model), bool(progress))
    values = {k: d[k] for k in ("wavelength_nm", "reflectance", "reflectance_stderr", "surface",
                                "subsurface", "transmittance", "absorptance", "absorptance_stderr",
                                "event_limited", "effect_bound", "layer_absorptance")}
    for i, layer in enumerate(d["layers"]):
        values["absorptance_" + layer] = d["layer_absorptance"][:, i]
    values["layers"] = list(d["layers"])
    values["specimen"] = d["specimen"]
    values["estimator"] = str(estimator)
    return Result("Spectrum", values)


def coefficients(specimen, wavelengths):
    """Every layer's optical coefficients over wavelengths (``hylios coefficients``, Eqs. 2-7).

    Returns a ``Result`` with ``wavelength_nm`` [N], ``layers`` and ``absorbers`` (names), arrays
    [N, layer]: ``mu_a_per_cm`` (total absorption, Eq. 3), ``mu_s_rayleigh_per_cm`` (Eq. 4),
    ``mu_melanosome_per_cm`` (Eq. 6), ``refractive_index``; and ``mu_a_absorber_per_cm``
    [N, layer, absorber] (the CSV's mu_a_<absorber>_per_cm columns).
    """
    d = _hylios.coefficients(_specimen(specimen), _wavelength_text(wavelengths))
    return Result("Coefficients", {k: d[k] for k in (
        "wavelength_nm", "layers", "absorbers", "mu_a_per_cm", "mu_s_rayleigh_per_cm",
        "mu_melanosome_per_cm", "refractive_index", "mu_a_absorber_per_cm", "specimen")})


def brdf(specimen, wavelengths="380:780:10", angle_deg=45, rays=200000, seed=1, polar_bins=18,
         azimuth_bins=36, estimator="spectral", threads=0):
    """Angular distribution of reflected light (``hylios brdf``, paper Figs. 10-11).

    Several wavelengths are averaged with equal weight (the default is the command's --visible
    band, 380-780 nm every 10 nm). estimator: "spectral" or "per-wavelength" as in ``spectrum``
    (no effect planner here, as in the command). Returns a ``Result`` with the bin edges ``polar_lower_deg,
    polar_upper_deg`` [polar], ``azimuth_lower_deg, azimuth_upper_deg`` [azimuth] (0 = specular
    side), ``solid_angle_sr`` [polar]; ``per_sr`` (fraction of incident rays per sr = BRDF*cos)
    and ``brdf``, each a ``Result`` of ``surface, subsurface, total`` and their ``*_stderr``
    arrays [polar, azimuth]; ``in_plane_per_sr`` (``signed_polar_deg`` and the same parts along
    the plane of incidence); ``surface_reflectance, subsurface_reflectance, total_reflectance``
    as (mean, stderr).
    """
    d = _hylios.brdf(_specimen(specimen), _wavelength_text(wavelengths), float(angle_deg),
                     _count("rays", rays), _seed(seed), _count("polar_bins", polar_bins),
                     _count("azimuth_bins", azimuth_bins), str(estimator), _count("threads", threads))
    values = dict(d)
    values["per_sr"] = Result("Directions", dict(d["per_sr"]))
    values["brdf"] = Result("Directions", dict(d["brdf"]))
    values["in_plane_per_sr"] = Result("InPlaneCut", dict(d["in_plane_per_sr"]))
    for key in ("surface_reflectance", "subsurface_reflectance", "total_reflectance"):
        values[key] = (d[key]["mean"], d[key]["stderr"])
    return Result("Brdf", values)


def radial_profile(specimen, wavelength_nm=550, angle_deg=0, rays=1000000, seed=1,
                   max_radius_cm=0.5, bins=100, estimator="spectral", threads=0):
    """Subsurface reflectance per unit area vs distance from the entry point, R(r) in cm^-2
    (``hylios radial-profile``, the radial part of the BSSRDF); estimator as in ``brdf``.

    Returns a ``Result`` with arrays over annuli ``inner_radius_cm, outer_radius_cm,
    annulus_area_cm2, fraction, fraction_stderr, reflectance_per_cm2,
    reflectance_per_cm2_stderr``, and ``beyond_max_radius``, ``subsurface_reflectance`` as
    (mean, stderr).
    """
    d = _hylios.radial_profile(_specimen(specimen), float(wavelength_nm), float(angle_deg),
                               _count("rays", rays), _seed(seed), float(max_radius_cm),
                               _count("bins", bins), str(estimator), _count("threads", threads))
    values = dict(d)
    for key in ("beyond_max_radius", "subsurface_reflectance"):
        values[key] = (d[key]["mean"], d[key]["stderr"])
    return Result("RadialProfile", values)


def _slab_layer(index, layer):
    """(n, mua, mus, g, d) from a dict with those keys or a 5-sequence, as ``--layer`` takes it."""
    keys = ("n", "mua", "mus", "g", "d")
    if isinstance(layer, dict):
        unknown = sorted(set(layer) - set(keys))
        missing = [k for k in keys if k not in layer]
        if unknown or missing:
            raise ValueError("layers[%d]: expected the keys n, mua, mus, g, d%s%s" % (
                index, "; unknown: " + ", ".join(map(str, unknown)) if unknown else "",
                "; missing: " + ", ".join(missing) if missing else ""))
        values = [layer[k] for k in keys]
    else:
        values = list(layer)
        if len(values) != 5:
            raise ValueError("layers[%d]: expected (n, mua, mus, g, d), got %d values" % (index, len(values)))
    return tuple(float(v) for v in values)


def slab(layers, above=1.0, below=1.0, angle_deg=0, diffuse=False, rays=1000000, seed=1,
         scheme="weighted", scalar=False, threads=0):
    """Monte Carlo of a layered slab, MCML's problem (``hylios slab``): diffuse reflectance,
    transmittance and absorptance per layer of plane-parallel Henyey-Greenstein layers between
    two ambient media, lit by a pencil beam (or diffuse light).

    layers: top first, each a dict ``{"n", "mua", "mus", "g", "d"}`` or a tuple in that order
    (refractive index, absorption and scattering coefficients in 1/cm, anisotropy in (-1, 1),
    thickness in cm; the last layer may be ``float("inf")``); above/below: ambient indices;
    angle_deg: beam incidence in [0, 90); diffuse: Lambertian light instead of the beam; rays:
    photon packets; seed: the same seed gives the same numbers at any thread count; scheme:
    "weighted" (absorption as weight with roulette, MCML's implicit capture) or "analog";
    scalar: the weighted walk one packet at a time in double precision instead of eight at once
    in single-precision lanes (the same laws; skin/layered_slab_lanes.h); threads: 0 = all cores.

    Returns a ``Result`` with ``specular_reflectance``, ``diffuse_reflectance``,
    ``transmittance``, ``unscattered_transmittance``, ``diffuse_transmittance``, ``absorptance``,
    ``event_limited`` (weight still travelling after 2^20 events per packet: 0 unless a thick
    layer scatters without absorbing; each with ``_stderr`` but the specular part), arrays
    ``layer_absorptance`` and ``layer_absorptance_stderr``, and ``photons``.
    """
    if isinstance(layers, dict) or not hasattr(layers, "__iter__"):
        raise TypeError("layers: expected a sequence of layers, got %r" % (layers,))
    tuples = [_slab_layer(i, layer) for i, layer in enumerate(layers)]
    d = _hylios.slab(tuples, float(above), float(below), float(angle_deg), bool(diffuse),
                     _count("rays", rays), _seed(seed), str(scheme), bool(scalar),
                     _count("threads", threads))
    return Result("Slab", dict(d))


def render(scene_path, spp=None, noise_target=None, resolution=None, seed=None, threads=0,
           skin_model=None, epsilon=None, estimator=None, sampler=None, progress=False,
           verbose=False):
    """Renders a scene file (``hylios render``) and returns ``(image, channel_wavelengths_nm)``.

    image: float32 array [height, width, channel] of the film's per-channel mean radiance (what
    the spectral EXR holds); channel_wavelengths_nm: float64 [channel]. spp, resolution ((W, H)
    or "WxH"), seed, skin_model ("walk"/"table") and epsilon override the scene's values when
    given (None: the scene's, like the command without the option); so does estimator
    ("spectral" or "per-wavelength") where the renderer has the choice
    (``hylios._hylios.render_has_estimator``), and sampler ("sobol" or "independent", the camera
    paths' numbers, ``--sampler``). threads: 0 = all cores;
    progress: the command's progress bar on a terminal; verbose: the command's report on stdout.
    noise_target: stop once the median relative per-pixel noise of every band is below it (spp
    then the most passes; renderer/image/render_noise.h), where the renderer has a noise target
    (``hylios._hylios.render_has_noise_target``), else NotImplementedError.
    Scene errors raise ``SceneError`` with file:line:col.
    """
    if noise_target is not None and not _hylios.render_has_noise_target:
        raise NotImplementedError(
            "render(noise_target=...): this build's renderer has no noise target (its "
            "RenderSettings take a fixed samples-per-pixel count); give spp instead")
    width = height = None
    if resolution is not None:
        if isinstance(resolution, str):
            width, height = _hylios.parse_resolution(resolution)
        else:
            width, height = (int(v) for v in resolution)
            if width <= 0 or height <= 0:
                raise ValueError("resolution: expected positive (width, height), got %r" % (resolution,))
    if spp is not None:
        spp = int(spp)
    if seed is not None:
        seed = _seed(seed)
    image, wavelengths = _hylios.render(os.fspath(scene_path), spp, width, height, seed,
                                        _count("threads", threads), skin_model,
                                        None if epsilon is None else float(epsilon),
                                        None if noise_target is None else float(noise_target),
                                        None if estimator is None else str(estimator),
                                        None if sampler is None else str(sampler),
                                        bool(progress), bool(verbose))
    return image, wavelengths


def fit_quantities():
    """The quantities ``fit`` may free: a list of dicts with name, unit, lower, upper, basis."""
    return [dict(q) for q in _hylios.fit_quantities()]


_DEFAULT_FREE = ("melanosome", "colloidal", "blood", "oxygenation", "water_reduction")


def fit(measured_wavelengths, measured_reflectance, specimen,
        free=_DEFAULT_FREE, angle_deg=45, wavelengths="400:700:10", rays=20000, seed=1,
        max_iterations=25, threads=0):
    """Fits freed specimen quantities to a measured reflectance curve (``hylios fit``): bounded
    Levenberg-Marquardt on the spectral walk with common random numbers (skin/specimen_fit.h).

    measured_wavelengths (nm, increasing) and measured_reflectance: the curve, interpolated
    linearly onto ``wavelengths`` ('start:stop:step', a list, or None for the measured
    wavelengths themselves; those outside the curve are left out, as the command does);
    specimen: the start (a ``Specimen`` or name); free: names of ``fit_quantities()``;
    rays: per wavelength and curve evaluation; seed: the same for every evaluation.

    Returns a ``Result`` with ``specimen`` (the fitted ``Specimen``), ``values``,
    ``uncertainties`` (1 sigma), ``start_values`` and ``at_bound`` (dicts by quantity name),
    ``units``, ``quantities`` (one dict per quantity), ``wavelength_nm``,
    ``target_reflectance``, ``model_reflectance``, ``model_reflectance_stderr``, ``rms``,
    ``start_rms``, ``evaluations``, ``iterations``, ``stop_reason``.
    Raises ``FitError`` for an unknown or repeated quantity and other bad requests.
    """
    if isinstance(free, str):
        free = [name for name in free.split(",") if name]
    w = np.asarray(measured_wavelengths, dtype=float).ravel()
    r = np.asarray(measured_reflectance, dtype=float).ravel()
    d = _hylios.fit(w.tolist(), r.tolist(), _specimen(specimen), [str(n) for n in free],
                    None if wavelengths is None else _wavelength_text(wavelengths), float(angle_deg),
                    _count("rays", rays), _seed(seed), _count("max_iterations", max_iterations),
                    _count("threads", threads))
    quantities = [dict(q) for q in d["quantities"]]
    values = {
        "specimen": Specimen(d["specimen"]),
        "values": {q["name"]: q["value"] for q in quantities},
        "uncertainties": {q["name"]: q["uncertainty"] for q in quantities},
        "start_values": {q["name"]: q["start"] for q in quantities},
        "at_bound": {q["name"]: q["at_bound"] for q in quantities},
        "units": {q["name"]: q["unit"] for q in quantities},
        "quantities": quantities,
    }
    for key in ("wavelength_nm", "target_reflectance", "model_reflectance",
                "model_reflectance_stderr", "rms", "start_rms", "evaluations", "iterations",
                "stop_reason"):
        values[key] = d[key]
    return Result("Fit", values)
