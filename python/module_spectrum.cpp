// hylios.spectrum and hylios.coefficients: what `hylios spectrum` (app/spectrum_command.cpp) and
// `hylios coefficients` (app/coefficients_command.cpp) compute, as dicts of numpy arrays.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "app/progress_bar.h"
#include "app/spectral_table_spectrum.h"
#include "app/spectrum_wavelength.h"
#include "app/wavelength_list.h"
#include "python/argument_checks.h"
#include "python/interruptible.h"
#include "python/interruptible_tallies.h"
#include "python/module.h"
#include "python/module_specimen.h"
#include "python/numpy_conversions.h"
#include "skin/core/thread_limit.h"
#include "skin/skin_tally.h"

namespace hylios::python {

namespace py = pybind11;

namespace {

py::dict spectrum(const PySpecimen& s, const std::string& wavelengthText, double angleDeg,
                  std::uint64_t rays, std::uint64_t seed, const std::string& estimatorName,
                  int threads, double epsilon, const std::string& skinModelName, bool progress) {
  const std::vector<double> wavelengths = parseWavelengthList(wavelengthText);
  const skin::Estimator estimator = estimatorNamed(estimatorName);
  const skin::SkinMode skinMode = skinModeNamed(skinModelName);
  requireAngle(angleDeg);
  requireRays(rays);
  requireEpsilon(epsilon);
  requireThreads(threads);

  const std::vector<skin::SkinOptics> optics = opticsOf(s.specimen, wavelengths);
  const std::size_t n = wavelengths.size();
  std::vector<skin::SkinTally> tallies(n);
  std::vector<double> effectBound(n, 0.0);
  // As the command: the spectral walk (full model, no effect plan), or in table mode the bundles'
  // tables from spectral walks; with the per-wavelength estimator, per wavelength, the effect
  // plan's walk or its exit table.
  const bool spectral = estimator == skin::Estimator::Spectral && skinMode == skin::SkinMode::Walk;
  const bool cancellable = !spectral && skinMode == skin::SkinMode::Walk;
  const SpectrumWavelengthSettings settings{angleDeg, rays, seed, epsilon, false, skinMode};
  runInterruptible(
      [&](const StopFlag& stop) {
        const ThreadLimit threadLimit(threads);
        std::unique_ptr<ProgressBar> bar;
        if (progress) bar = std::make_unique<ProgressBar>("spectrum " + s.specimen.name, n);
        if (spectral) {
          skin::WalkRunOptions run{angleDeg, rays, seed, {}, {}};
          tallies = simulateTallies(skin::Estimator::Spectral, optics, run, stop, bar.get());
        } else if (estimator == skin::Estimator::Spectral) {
          tallies = spectralTableTallies(optics, angleDeg, rays, seed);
          if (bar) bar->advance(n);
        } else {
          tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
            if (stop()) return;
            SpectrumWavelengthResult result = simulateSpectrumWavelength(optics[i], settings);
            tallies[i] = std::move(result.tally);
            effectBound[i] = result.plan ? result.plan->droppedDepthBound : 0.0;
            if (bar) bar->advance();
          });
        }
        if (bar) stop() ? bar->stop() : bar->finish();
      },
      cancellable);

  std::vector<double> R, Rerr, surface, subsurface, T, A, Aerr, limited, perLayer;
  for (const skin::SkinTally& t : tallies) {
    R.push_back(t.reflectance().mean);
    Rerr.push_back(t.reflectance().standardError);
    surface.push_back(t.surfaceReflectance().mean);
    subsurface.push_back(t.subsurfaceReflectance().mean);
    T.push_back(t.transmittance().mean);
    A.push_back(t.absorptance().mean);
    Aerr.push_back(t.absorptance().standardError);
    limited.push_back(t.eventLimited().mean);
    for (skin::Layer layer : skin::kAllLayers) perLayer.push_back(t.absorptance(layer).mean);
  }
  py::dict d;
  d["wavelength_nm"] = array(wavelengths);
  d["reflectance"] = array(R);
  d["reflectance_stderr"] = array(Rerr);
  d["surface"] = array(surface);
  d["subsurface"] = array(subsurface);
  d["transmittance"] = array(T);
  d["absorptance"] = array(A);
  d["absorptance_stderr"] = array(Aerr);
  d["event_limited"] = array(limited);
  d["layer_absorptance"] = array2(perLayer, n, skin::kLayerCount);
  d["effect_bound"] = array(effectBound);
  d["layers"] = layerNames();
  d["specimen"] = s.specimen.name;
  return d;
}

void requireFinite(double value, double nm, skin::Layer layer, const char* what) {
  if (!std::isfinite(value))
    throw std::runtime_error(
        fmt::format("{} of {} at {} nm is {}", what, skin::layerName(layer), nm, value));
}

py::dict coefficients(const PySpecimen& s, const std::string& wavelengthText) {
  const std::vector<double> wavelengths = parseWavelengthList(wavelengthText);
  const std::vector<skin::SkinOptics> optics = opticsOf(s.specimen, wavelengths);
  const std::size_t n = wavelengths.size(), L = skin::kLayerCount, A = skin::kAbsorberCount;
  std::vector<double> muA(n * L), muR(n * L), muM(n * L), index(n * L);
  py::array_t<double> perAbsorber(
      {static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(L), static_cast<py::ssize_t>(A)});
  auto out = perAbsorber.mutable_unchecked<3>();
  for (std::size_t i = 0; i < n; ++i) {
    for (skin::Layer l : skin::kAllLayers) {
      const std::size_t j = skin::index(l);
      const skin::LayerOptics& o = optics[i][l];
      requireFinite(o.muATotal_perCm, wavelengths[i], l, "mu_a");
      requireFinite(o.muRayleigh_perCm, wavelengths[i], l, "mu_s_rayleigh");
      requireFinite(o.melanosome.mu_perCm, wavelengths[i], l, "mu_melanosome");
      requireFinite(o.refractiveIndex, wavelengths[i], l, "refractive index");
      muA[i * L + j] = o.muATotal_perCm;
      muR[i * L + j] = o.muRayleigh_perCm;
      muM[i * L + j] = o.melanosome.mu_perCm;
      index[i * L + j] = o.refractiveIndex;
      for (skin::Absorber a : skin::kAllAbsorbers) {
        const double v = o.muA_perCm[skin::index(a)];
        requireFinite(v, wavelengths[i], l, "mu_a of an absorber");
        out(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j),
            static_cast<py::ssize_t>(skin::index(a))) = v;
      }
    }
  }
  py::dict d;
  d["wavelength_nm"] = array(wavelengths);
  d["layers"] = layerNames();
  d["absorbers"] = absorberNames();
  d["mu_a_per_cm"] = array2(muA, n, L);
  d["mu_s_rayleigh_per_cm"] = array2(muR, n, L);
  d["mu_melanosome_per_cm"] = array2(muM, n, L);
  d["refractive_index"] = array2(index, n, L);
  d["mu_a_absorber_per_cm"] = perAbsorber;
  d["specimen"] = s.specimen.name;
  return d;
}

}  // namespace

void bindSpectrum(py::module_& m) {
  m.def("spectrum", &spectrum, py::arg("specimen"), py::arg("wavelengths"), py::arg("angle_deg"),
        py::arg("rays"), py::arg("seed"), py::arg("estimator"), py::arg("threads"),
        py::arg("epsilon"), py::arg("skin_model"), py::arg("progress"), "See hylios.spectrum");
  m.def("coefficients", &coefficients, py::arg("specimen"), py::arg("wavelengths"),
        "See hylios.coefficients");
}

}  // namespace hylios::python
