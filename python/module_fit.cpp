// hylios.fit and hylios._hylios.fit_quantities: what `hylios fit` (app/fit_command.cpp) does,
// with the measured curve given as arrays and the fitted specimen returned, not written.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/measured_spectrum.h"
#include "app/wavelength_list.h"
#include "python/argument_checks.h"
#include "python/interruptible.h"
#include "python/module.h"
#include "python/module_specimen.h"
#include "python/numpy_conversions.h"
#include "renderer/scene/data_paths.h"
#include "skin/core/thread_limit.h"
#include "skin/specimen_fit.h"
#include "skin/spectral_database.h"

namespace hylios::python {

namespace py = pybind11;

namespace {

/// Thrown out of the fit's progress hook to stop it on an interrupt.
struct FitStopped {};

py::dict fit(const std::vector<double>& measuredWavelengths,
             const std::vector<double>& measuredReflectance, const PySpecimen& s,
             const std::vector<std::string>& free, std::optional<std::string> wavelengthText,
             double angleDeg, std::uint64_t rays, std::uint64_t seed, int maxIterations,
             int threads) {
  if (measuredWavelengths.size() != measuredReflectance.size())
    throw std::invalid_argument(
        "fit: measured_wavelengths and measured_reflectance differ in length");
  if (measuredWavelengths.empty()) throw std::invalid_argument("fit: the measured curve is empty");
  for (std::size_t i = 0; i < measuredWavelengths.size(); ++i) {
    if (!std::isfinite(measuredWavelengths[i]) || !std::isfinite(measuredReflectance[i]))
      throw std::invalid_argument("fit: the measured curve holds a non-finite value");
    if (i > 0 && !(measuredWavelengths[i] > measuredWavelengths[i - 1]))
      throw std::invalid_argument("fit: measured_wavelengths must increase");
  }
  requireAngle(angleDeg);
  if (rays < 100) throw std::invalid_argument("rays must be at least 100");
  if (maxIterations < 1) throw std::invalid_argument("max_iterations must be positive");
  requireThreads(threads);
  MeasuredSpectrum measured;
  measured.label = "measured";
  measured.wavelengthNm = measuredWavelengths;
  measured.value = measuredReflectance;
  skin::FitOptions options;
  options.free = free;
  for (const auto& name : options.free)
    skin::fitQuantity(name);  // unknown names fail before any walk
  options.incidenceDeg = angleDeg;
  options.rays = rays;
  options.seed = seed;
  options.maxIterations = maxIterations;
  skin::FitTarget target;
  if (wavelengthText) {
    for (double w : parseWavelengthList(*wavelengthText))
      if (measured.covers(w)) {
        target.wavelengthNm.push_back(w);
        target.reflectance.push_back(measured.at(w));
      }
    if (target.wavelengthNm.empty())
      throw skin::FitError(
          fmt::format("the measured curve ({}–{} nm) covers none of wavelengths {}",
                      measuredWavelengths.front(), measuredWavelengths.back(), *wavelengthText));
  } else {
    target.wavelengthNm = measuredWavelengths;
    target.reflectance = measuredReflectance;
  }
  const auto spectra = skin::SpectralDatabase::load(spectraDir());
  std::optional<skin::FitResult> result;
  runInterruptible(
      [&](const StopFlag& stop) {
        const ThreadLimit threadLimit(threads);
        options.progress = [&stop](std::size_t, double) {
          if (stop()) throw FitStopped{};
        };
        result = skin::fitSpecimen(s.specimen, spectra, target, options);
      },
      false);
  const skin::FitResult& r = *result;
  py::list quantities;
  for (const skin::FittedQuantity& q : r.quantities) {
    py::dict d;
    d["name"] = q.quantity.name;
    d["unit"] = q.quantity.unit;
    d["lower"] = q.quantity.lower;
    d["upper"] = q.quantity.upper;
    d["start"] = q.start;
    d["value"] = q.value;
    d["uncertainty"] = q.uncertainty;
    d["at_bound"] = q.atBound;
    quantities.append(d);
  }
  const auto [model, modelErr] = split(r.model);
  py::dict d;
  d["specimen"] = PySpecimen{r.specimen};
  d["quantities"] = quantities;
  d["wavelength_nm"] = array(target.wavelengthNm);
  d["target_reflectance"] = array(target.reflectance);
  d["model_reflectance"] = array(model);
  d["model_reflectance_stderr"] = array(modelErr);
  d["start_rms"] = r.startRms;
  d["rms"] = r.rms;
  d["evaluations"] = r.evaluations;
  d["iterations"] = r.iterations;
  d["stop_reason"] = r.stopReason;
  return d;
}

}  // namespace

void bindFit(py::module_& m) {
  m.def(
      "fit_quantities",
      [] {
        py::list list;
        for (const skin::FitQuantity& q : skin::fitQuantities()) {
          py::dict d;
          d["name"] = q.name;
          d["unit"] = q.unit;
          d["lower"] = q.lower;
          d["upper"] = q.upper;
          d["basis"] = q.basis;
          list.append(d);
        }
        return list;
      },
      "The quantities a fit may free, with units and bounds");
  m.def("fit", &fit, py::arg("measured_wavelengths"), py::arg("measured_reflectance"),
        py::arg("specimen"), py::arg("free"), py::arg("wavelengths"), py::arg("angle_deg"),
        py::arg("rays"), py::arg("seed"), py::arg("max_iterations"), py::arg("threads"),
        "See hylios.fit");
}

}  // namespace hylios::python
