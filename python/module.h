// The parts of the compiled module hylios._hylios (python/module.cpp), each adding its functions
// to the module; every function does what the matching `hylios` command does (app/*_command.cpp).
#pragma once
#include <pybind11/pybind11.h>

namespace hylios::python {

/// python/module_specimen.cpp: _Specimen, load_specimen, specimen_from_toml, with_overrides,
/// override_keys.
void bindSpecimen(pybind11::module_& m);
/// python/module_spectrum.cpp: spectrum, coefficients.
void bindSpectrum(pybind11::module_& m);
/// python/module_angular.cpp: brdf, radial_profile.
void bindAngular(pybind11::module_& m);
/// python/module_render.cpp: render, render_has_estimator, render_has_noise_target.
void bindRender(pybind11::module_& m);
/// python/module_fit.cpp: fit_quantities, fit.
void bindFit(pybind11::module_& m);
/// python/module_slab.cpp: slab.
void bindSlab(pybind11::module_& m);

}  // namespace hylios::python
