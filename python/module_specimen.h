// Specimens in the Python module: the loaded specimen that hylios.Specimen wraps, loading with
// the command line's overrides and messages, and the bindings (_Specimen, load_specimen, ...).
#pragma once
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "skin/skin_optics.h"
#include "skin/specimen.h"

namespace hylios::python {

/// A loaded specimen (the Python Specimen wraps one).
struct PySpecimen {
  skin::Specimen specimen;
};

/// The specimen's optics at each wavelength, all computed before any walk (so that a bad
/// wavelength fails first).
std::vector<skin::SkinOptics> opticsOf(const skin::Specimen& specimen,
                                       const std::vector<double>& wavelengths);

/// _Specimen, load_specimen, specimen_from_toml, with_overrides, override_keys.
void bindSpecimen(pybind11::module_& m);

}  // namespace hylios::python
