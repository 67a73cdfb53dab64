// hylios._hylios: the compiled part of the Python module (python/hylios/__init__.py is the public
// face, with the keyword arguments and docstrings). Every function here does what the matching
// `hylios` command does (app/*_command.cpp) with the same libraries, options and random streams,
// so the numbers are the ones the command writes; results come back as dicts of numpy arrays.
//
// | concern     | how                                                                          |
// |-------------|------------------------------------------------------------------------------|
// | GIL         | released for the whole computation (it runs on a worker thread)              |
// | Ctrl-C      | the calling thread polls PyErr_CheckSignals every 50 ms; a pending signal    |
// |             | stops the work at its next safe point (between wavelengths, bundles, render  |
// |             | passes, or TBB tasks where nothing is cached) and the Python error is raised |
// | errors      | the messages of the command line (SpecimenError, SceneError: file:line:col)   |
// | data        | HYLIOS_DATA_DIR or the compiled-in source tree (renderer/scene/data_paths.h) |
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "app/measured_spectrum.h"
#include "app/progress_bar.h"
#include "app/render_options.h"
#include "app/specimen_options.h"
#include "app/wavelength_list.h"
#include "renderer/scene/data_paths.h"
#include "renderer/scene/scene.h"
#include "renderer/scene/scene_file.h"
#include "renderer/tracing/exit_table_cache.h"
#include "renderer/tracing/render_job.h"
#include "renderer/tracing/skin_table_cache.h"
#include "skin/core/constants.h"
#include "skin/core/thread_limit.h"
#include "skin/effect_plan.h"
#include "skin/exit_distribution.h"
#include "skin/skin_mode.h"
#include "skin/skin_optics.h"
#include "skin/skin_simulation.h"
#include "skin/specimen.h"
#include "skin/specimen_fit.h"
#include "skin/specimen_writer.h"
#include "skin/spectral_bundle.h"
#include "skin/spectral_database.h"
#include "skin/spectral_simulation.h"

namespace py = pybind11;

namespace hylios {
namespace {

// ---------------------------------------------------------------------------------------------
// Running a computation without the GIL, interruptibly.

/// What a computation may ask while it runs: whether Python has a pending interrupt.
struct StopFlag {
  std::atomic<bool> requested{false};
  bool operator()() const { return requested.load(std::memory_order_relaxed); }
};

/// Runs `work` on a worker thread with the GIL released, polling Python's signal handlers from the
/// calling thread. On a pending signal (Ctrl-C: KeyboardInterrupt) the stop flag is raised and,
/// when `cancelTasks`, the TBB tasks of the work that have not started are cancelled (only for work
/// whose partial results are thrown away and that fills no cache); the Python error is raised once
/// the worker has returned. An exception of the work is rethrown (pybind11 translates it).
void runInterruptible(const std::function<void(const StopFlag&)>& work, bool cancelTasks) {
  StopFlag stop;
  tbb::task_group_context context;
  std::exception_ptr failure;
  bool interrupted = false;
  {
    py::gil_scoped_release release;
    std::mutex mutex;
    std::condition_variable doneSignal;
    bool done = false;
    std::thread worker([&] {
      try {
        // One outer task with its own context: nested parallel algorithms bind to it, so
        // cancel_group_execution() skips their tasks that have not started.
        tbb::parallel_for(
            tbb::blocked_range<int>(0, 1), [&](const tbb::blocked_range<int>&) { work(stop); },
            context);
      } catch (...) {
        failure = std::current_exception();
      }
      const std::lock_guard<std::mutex> lock(mutex);
      done = true;
      doneSignal.notify_all();
    });
    std::unique_lock<std::mutex> lock(mutex);
    while (!done) {
      doneSignal.wait_for(lock, std::chrono::milliseconds(50));
      if (done || interrupted) continue;
      lock.unlock();
      {
        py::gil_scoped_acquire acquire;
        if (PyErr_CheckSignals() != 0) interrupted = true;  // the error stays set on this thread
      }
      if (interrupted) {
        stop.requested = true;
        if (cancelTasks) context.cancel_group_execution();
      }
      lock.lock();
    }
    lock.unlock();
    worker.join();
  }
  if (interrupted) throw py::error_already_set();
  if (failure) std::rethrow_exception(failure);
}

// ---------------------------------------------------------------------------------------------
// Conversions.

py::array_t<double> array(const std::vector<double>& values) {
  py::array_t<double> result(static_cast<py::ssize_t>(values.size()));
  auto out = result.mutable_unchecked<1>();
  for (std::size_t i = 0; i < values.size(); ++i) out(static_cast<py::ssize_t>(i)) = values[i];
  return result;
}

/// rows × columns, row-major.
py::array_t<double> array2(const std::vector<double>& values, std::size_t rows,
                           std::size_t columns) {
  py::array_t<double> result({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(columns)});
  auto out = result.mutable_unchecked<2>();
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < columns; ++c)
      out(static_cast<py::ssize_t>(r), static_cast<py::ssize_t>(c)) = values[r * columns + c];
  return result;
}

py::list layerNames() {
  py::list names;
  for (skin::Layer layer : skin::kAllLayers) names.append(std::string(skin::layerName(layer)));
  return names;
}

py::list absorberNames() {
  py::list names;
  for (skin::Absorber a : skin::kAllAbsorbers) names.append(std::string(skin::absorberName(a)));
  return names;
}

py::dict estimate(const skin::Estimate& e) {
  py::dict d;
  d["mean"] = e.mean;
  d["stderr"] = e.standardError;
  return d;
}

/// Means and standard errors of a list of estimates, as two arrays (optionally reshaped).
std::pair<std::vector<double>, std::vector<double>> split(
    const std::vector<skin::Estimate>& estimates) {
  std::pair<std::vector<double>, std::vector<double>> parts;
  for (const skin::Estimate& e : estimates) {
    parts.first.push_back(e.mean);
    parts.second.push_back(e.standardError);
  }
  return parts;
}

// ---------------------------------------------------------------------------------------------
// Specimens.

/// A loaded specimen (the Python Specimen wraps one).
struct PySpecimen {
  skin::Specimen specimen;
};

PySpecimen loadSpecimen(const std::string& nameOrPath, const std::vector<std::string>& overrides) {
  SpecimenOptions options;
  options.specimen = nameOrPath;
  options.overrides = overrides;
  return {loadSpecimenWithOverrides(options)};
}

/// The overrides of `overrides` ("key=value", as --set) applied in order to a copy; the parsing and
/// messages of app/specimen_options.cpp.
PySpecimen withOverrides(const PySpecimen& s, const std::vector<std::string>& overrides) {
  PySpecimen result = s;
  for (const std::string& text : overrides) {
    const std::string origin = "--set " + text;
    const auto equals = text.find('=');
    if (equals == std::string::npos || equals == 0) {
      std::string keys;
      for (const auto& key : skin::overrideKeys()) keys += (keys.empty() ? "" : ", ") + key;
      throw skin::SpecimenError(origin + ": expected KEY=VALUE with KEY one of " + keys);
    }
    const std::string valueText = text.substr(equals + 1);
    char* end = nullptr;
    const double value = std::strtod(valueText.c_str(), &end);
    if (valueText.empty() || *end != '\0' || !std::isfinite(value))
      throw skin::SpecimenError(origin + ": '" + valueText + "' is not a finite number");
    skin::applyOverride(result.specimen, {text.substr(0, equals), value, origin});
  }
  return result;
}

std::vector<skin::SkinOptics> opticsOf(const skin::Specimen& specimen,
                                       const std::vector<double>& wavelengths) {
  const auto spectra = skin::SpectralDatabase::load(spectraDir());
  std::vector<skin::SkinOptics> optics;  // first, so that a bad wavelength fails before any walk
  for (double w : wavelengths) optics.push_back(skin::computeSkinOptics(specimen, spectra, w));
  return optics;
}

/// The estimators of the commands' --estimator option (app/estimator_option.cpp).
void requireEstimator(const std::string& estimator) {
  if (estimator != "spectral" && estimator != "per-wavelength")
    throw std::invalid_argument("estimator '" + estimator +
                                "': expected 'spectral' or 'per-wavelength'");
}

/// One tally per optics, as the commands' simulateWithEstimator (app/estimator_option.cpp): the
/// analog walk per wavelength (per-wavelength), or the spectral walk with tabulated melanosome
/// paths (spectral). The spectral walk is run one bundle at a time: a bundle's members regroup into
/// that one bundle and its random stream depends only on its wavelengths, so the tallies are those
/// of one simulateSkinSpectral call over all wavelengths, and a stop request takes effect between
/// bundles. The per-wavelength walk stops between wavelengths.
std::vector<skin::SkinTally> simulateTallies(const std::string& estimator,
                                             const std::vector<skin::SkinOptics>& optics,
                                             const skin::WalkRunOptions& run, const StopFlag& stop,
                                             ProgressBar* bar = nullptr) {
  std::vector<skin::SkinTally> tallies(optics.size(), skin::SkinTally(run.tally));
  if (estimator == "spectral") {
    const skin::SpectralRunOptions spectral = skin::commandSpectralRun(run);
    const auto bundles = skin::groupIntoBundles(optics, spectral.walk, spectral.bundles);
    tbb::parallel_for(std::size_t{0}, bundles.size(), [&](std::size_t b) {
      if (stop()) return;
      std::vector<skin::SkinOptics> members;
      for (std::size_t i : bundles[b]) members.push_back(optics[i]);
      std::vector<skin::SkinTally> result = skin::simulateSkinSpectral(members, spectral);
      for (std::size_t k = 0; k < bundles[b].size(); ++k)
        tallies[bundles[b][k]] = std::move(result[k]);
      if (bar) bar->advance(bundles[b].size());
    });
  } else {
    tbb::parallel_for(std::size_t{0}, optics.size(), [&](std::size_t i) {
      if (stop()) return;
      tallies[i] = skin::simulateSkin(optics[i], run);
      if (bar) bar->advance();
    });
  }
  return tallies;
}

// ---------------------------------------------------------------------------------------------
// spectrum (app/spectrum_command.cpp).

struct SpectrumRequest {
  std::vector<double> wavelengths;
  double angleDeg = 45;
  std::uint64_t rays = 100000;
  std::uint64_t seed = 1;
  std::string estimator = "spectral";
  int threads = 0;
  double effectTolerance = skin::kDefaultEffectTolerance;
  std::string skinModel = "walk";
  bool progress = false;
};

constexpr std::uint64_t kSpectrumPilotRays = 2000;          // as app/spectrum_command.cpp
constexpr std::uint64_t kMaxRays = std::uint64_t{1} << 40;  // the commands' --rays bound

std::optional<skin::EffectPlan> planWavelength(const SpectrumRequest& r,
                                               const skin::SkinOptics& optics) {
  if (r.effectTolerance == 0) return std::nullopt;
  skin::PlanOptions options;
  options.incidenceDeg = {r.angleDeg};
  options.pilotRays = kSpectrumPilotRays;
  options.seed = r.seed;
  return skin::planEffects(optics, r.effectTolerance, options);
}

skin::SkinTally tableTally(const skin::SkinWalk& walk, const SpectrumRequest& r) {
  const auto table = ExitTableCache::shared().get(walk, SkinTableCache::renderSettings());
  const skin::Vec3 incident = skin::incidentDirection(r.angleDeg);
  const std::uint64_t stream = skin::wavelengthStream(walk.optics().wavelengthNm);
  skin::SkinTally tally;
  for (std::uint64_t i = 0; i < r.rays; ++i) {
    skin::Rng rng(r.seed, stream, i);
    tally.record(table->sample(incident, rng));
  }
  return tally;
}

py::dict spectrum(const PySpecimen& s, const std::string& wavelengthText, double angleDeg,
                  std::uint64_t rays, std::uint64_t seed, const std::string& estimator, int threads,
                  double epsilon, const std::string& skinModel, bool progress) {
  SpectrumRequest r;
  r.wavelengths = parseWavelengthList(wavelengthText);
  r.angleDeg = angleDeg;
  r.rays = rays;
  r.seed = seed;
  r.estimator = estimator;
  r.threads = threads;
  r.effectTolerance = epsilon;
  r.skinModel = skinModel;
  r.progress = progress;
  requireEstimator(estimator);
  if (skinModel != "walk" && skinModel != "table")
    throw std::invalid_argument("skin_model '" + skinModel + "': expected 'walk' or 'table'");
  if (!(angleDeg >= 0 && angleDeg < 90))
    throw std::invalid_argument("angle_deg must lie in [0, 90)");
  if (rays < 1 || rays > kMaxRays) throw std::invalid_argument("rays must lie in [1, 2^40]");
  if (!(epsilon >= 0 && epsilon <= 1)) throw std::invalid_argument("epsilon must lie in [0, 1]");
  if (threads < 0) throw std::invalid_argument("threads must be 0 (all cores) or positive");

  const std::vector<skin::SkinOptics> optics = opticsOf(s.specimen, r.wavelengths);
  const std::size_t n = r.wavelengths.size();
  std::vector<skin::SkinTally> tallies(n);
  std::vector<double> effectBound(n, 0.0);
  // As the command: the spectral walk (full model, no effect plan) unless table mode was asked
  // for; otherwise per wavelength, the effect plan's walk or the exit table.
  const bool spectral = r.estimator == "spectral" && r.skinModel == "walk";
  const bool cancellable = !spectral && skinModel == "walk";
  runInterruptible(
      [&](const StopFlag& stop) {
        const ThreadLimit threadLimit(r.threads);
        std::unique_ptr<ProgressBar> bar;
        if (r.progress) bar = std::make_unique<ProgressBar>("spectrum " + s.specimen.name, n);
        skin::WalkRunOptions run;
        run.incidenceDeg = r.angleDeg;
        run.rays = r.rays;
        run.seed = r.seed;
        if (spectral) {
          tallies = simulateTallies("spectral", optics, run, stop, bar.get());
        } else {
          tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
            if (stop()) return;
            const std::optional<skin::EffectPlan> plan = planWavelength(r, optics[i]);
            skin::WalkRunOptions planned = run;
            if (plan) planned.walk = plan->walk;
            const skin::SkinOptics& walked = plan ? plan->optics : optics[i];
            tallies[i] = r.skinModel == "table"
                             ? tableTally(skin::SkinWalk(walked, planned.walk), r)
                             : skin::simulateSkin(walked, planned);
            effectBound[i] = plan ? plan->droppedDepthBound : 0.0;
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
  d["wavelength_nm"] = array(r.wavelengths);
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

// ---------------------------------------------------------------------------------------------
// coefficients (app/coefficients_command.cpp).

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

// ---------------------------------------------------------------------------------------------
// brdf (app/brdf_command.cpp).

constexpr double kDegPerRad = 180.0 / kPi;

py::dict directions(const skin::ReflectedDirections& r, std::size_t polar, std::size_t azimuth) {
  py::dict d;
  const auto [surface, surfaceErr] = split(r.surface);
  const auto [subsurface, subsurfaceErr] = split(r.subsurface);
  const auto [total, totalErr] = split(r.total);
  d["surface"] = array2(surface, polar, azimuth);
  d["surface_stderr"] = array2(surfaceErr, polar, azimuth);
  d["subsurface"] = array2(subsurface, polar, azimuth);
  d["subsurface_stderr"] = array2(subsurfaceErr, polar, azimuth);
  d["total"] = array2(total, polar, azimuth);
  d["total_stderr"] = array2(totalErr, polar, azimuth);
  return d;
}

py::dict brdf(const PySpecimen& s, const std::string& wavelengthText, double angleDeg,
              std::uint64_t rays, std::uint64_t seed, std::size_t polarBins,
              std::size_t azimuthBins, const std::string& estimator, int threads) {
  requireEstimator(estimator);
  if (!(angleDeg >= 0 && angleDeg < 90))
    throw std::invalid_argument("angle_deg must lie in [0, 90)");
  if (rays < 1 || rays > kMaxRays) throw std::invalid_argument("rays must lie in [1, 2^40]");
  if (threads < 0) throw std::invalid_argument("threads must be 0 (all cores) or positive");
  const std::vector<double> wavelengths = parseWavelengthList(wavelengthText);
  const std::vector<skin::SkinOptics> optics = opticsOf(s.specimen, wavelengths);
  const skin::DirectionBins bins(polarBins, azimuthBins);
  skin::WalkRunOptions run;
  run.incidenceDeg = angleDeg;
  run.rays = rays;
  run.seed = seed;
  run.tally.polarBins = polarBins;
  run.tally.azimuthBins = azimuthBins;
  std::vector<skin::ReflectionDistribution> perWavelength(wavelengths.size());
  skin::ReflectionDistribution mean;
  runInterruptible(
      [&](const StopFlag& stop) {
        const ThreadLimit threadLimit(threads);
        const std::vector<skin::SkinTally> tallies = simulateTallies(estimator, optics, run, stop);
        if (stop()) return;
        for (std::size_t i = 0; i < tallies.size(); ++i)
          perWavelength[i] = skin::reflectionDistribution(tallies[i]);
        mean = skin::meanOverWavelengths(perWavelength);
      },
      estimator == "per-wavelength");
  std::vector<double> polarLower, polarUpper, azimuthLower, azimuthUpper, solidAngle;
  for (std::size_t i = 0; i < bins.polarBins(); ++i) {
    polarLower.push_back(bins.polarLowerRad(i) * kDegPerRad);
    polarUpper.push_back(bins.polarUpperRad(i) * kDegPerRad);
    solidAngle.push_back(bins.solidAngleSr(i));
  }
  for (std::size_t j = 0; j < bins.azimuthBins(); ++j) {
    azimuthLower.push_back(bins.azimuthLowerRad(j) * kDegPerRad);
    azimuthUpper.push_back((bins.azimuthLowerRad(j) + bins.azimuthWidthRad()) * kDegPerRad);
  }
  py::dict cut;
  cut["signed_polar_deg"] = array(mean.inPlanePerSteradian.signedPolarDeg);
  for (const auto& [name, values] : {std::pair<const char*, const std::vector<skin::Estimate>*>{
                                         "surface", &mean.inPlanePerSteradian.surface},
                                     {"subsurface", &mean.inPlanePerSteradian.subsurface},
                                     {"total", &mean.inPlanePerSteradian.total}}) {
    const auto [m, e] = split(*values);
    cut[name] = array(m);
    cut[(std::string(name) + "_stderr").c_str()] = array(e);
  }
  py::dict d;
  d["wavelength_nm"] = array(wavelengths);
  d["polar_lower_deg"] = array(polarLower);
  d["polar_upper_deg"] = array(polarUpper);
  d["azimuth_lower_deg"] = array(azimuthLower);
  d["azimuth_upper_deg"] = array(azimuthUpper);
  d["solid_angle_sr"] = array(solidAngle);
  d["per_sr"] = directions(mean.perSteradian, polarBins, azimuthBins);
  d["brdf"] = directions(mean.brdf, polarBins, azimuthBins);
  d["in_plane_per_sr"] = cut;
  d["surface_reflectance"] = estimate(mean.surfaceReflectance);
  d["subsurface_reflectance"] = estimate(mean.subsurfaceReflectance);
  d["total_reflectance"] = estimate(mean.totalReflectance);
  d["specimen"] = s.specimen.name;
  return d;
}

// ---------------------------------------------------------------------------------------------
// radial-profile (app/radial_profile_command.cpp).

py::dict radialProfile(const PySpecimen& s, double wavelengthNm, double angleDeg,
                       std::uint64_t rays, std::uint64_t seed, double maxRadiusCm, std::size_t bins,
                       const std::string& estimator, int threads) {
  requireEstimator(estimator);
  if (!(angleDeg >= 0 && angleDeg < 90))
    throw std::invalid_argument("angle_deg must lie in [0, 90)");
  if (rays < 1 || rays > kMaxRays) throw std::invalid_argument("rays must lie in [1, 2^40]");
  if (!(maxRadiusCm > 0)) throw std::invalid_argument("max_radius_cm must be positive");
  if (bins < 1) throw std::invalid_argument("bins must be positive");
  if (threads < 0) throw std::invalid_argument("threads must be 0 (all cores) or positive");
  const skin::SkinOptics optics =
      skin::computeSkinOptics(s.specimen, skin::SpectralDatabase::load(spectraDir()), wavelengthNm);
  skin::WalkRunOptions run;
  run.incidenceDeg = angleDeg;
  run.rays = rays;
  run.seed = seed;
  run.tally.radialBins = bins;
  run.tally.maxRadiusCm = maxRadiusCm;
  skin::RadialProfile p;
  runInterruptible(
      [&](const StopFlag& stop) {
        const ThreadLimit threadLimit(threads);
        const std::vector<skin::SkinTally> tallies =
            simulateTallies(estimator, {optics}, run, stop);
        if (!stop()) p = skin::radialProfile(tallies.front());
      },
      estimator == "per-wavelength");
  std::vector<double> area;
  for (std::size_t i = 0; i < p.perCm2.size(); ++i)
    area.push_back(skin::annulusAreaCm2(p.innerCm[i], p.outerCm[i]));
  const auto [fraction, fractionErr] = split(p.fraction);
  const auto [perCm2, perCm2Err] = split(p.perCm2);
  py::dict d;
  d["wavelength_nm"] = wavelengthNm;
  d["inner_radius_cm"] = array(p.innerCm);
  d["outer_radius_cm"] = array(p.outerCm);
  d["annulus_area_cm2"] = array(area);
  d["fraction"] = array(fraction);
  d["fraction_stderr"] = array(fractionErr);
  d["reflectance_per_cm2"] = array(perCm2);
  d["reflectance_per_cm2_stderr"] = array(perCm2Err);
  d["beyond_max_radius"] = estimate(p.beyondMaxRadius);
  d["subsurface_reflectance"] = estimate(p.subsurfaceReflectance);
  d["specimen"] = s.specimen.name;
  return d;
}

// ---------------------------------------------------------------------------------------------
// render (app/render_command.cpp, without files: the film comes back as an array).

/// Whether the renderer's settings have a noise target (issue 12) yet.
template <class T, class = void>
struct HasNoiseTarget : std::false_type {};
template <class T>
struct HasNoiseTarget<T, std::void_t<decltype(std::declval<T&>().noiseTarget)>> : std::true_type {};
constexpr bool kRenderHasNoiseTarget = HasNoiseTarget<RenderSettings>::value;

/// Whether the renderer's settings choose the skin estimator (issue 11) yet.
template <class T, class = void>
struct HasEstimator : std::false_type {};
template <class T>
struct HasEstimator<T, std::void_t<decltype(std::declval<T&>().estimator)>> : std::true_type {};
constexpr bool kRenderHasEstimator = HasEstimator<RenderSettings>::value;

template <class T>
void setEstimator(T& settings, const std::optional<std::string>& estimator) {
  if (!estimator) return;
  requireEstimator(*estimator);
  if constexpr (HasEstimator<T>::value) {
    using Estimator = typename std::decay_t<decltype(settings.estimator)>::value_type;
    settings.estimator = *estimator == "spectral" ? Estimator::Spectral : Estimator::PerWavelength;
  } else {
    throw std::invalid_argument(
        "estimator: this renderer has no choice of estimator (it walks per wavelength)");
  }
}

template <class T>
void setNoiseTarget(T& settings, std::optional<double> target) {
  if constexpr (HasNoiseTarget<T>::value) {
    settings.noiseTarget = target;
  } else if (target) {
    throw std::logic_error("no noise target in this renderer");
  }
}

py::tuple render(const std::string& scenePath, std::optional<int> spp, std::optional<int> width,
                 std::optional<int> height, std::optional<std::uint64_t> seed, int threads,
                 std::optional<std::string> skinMode, std::optional<double> epsilon,
                 std::optional<double> noiseTarget, std::optional<std::string> estimator,
                 bool progress, bool verbose) {
  if (threads < 0) throw std::invalid_argument("threads must be 0 (all cores) or positive");
  if (skinMode && *skinMode != "walk" && *skinMode != "table")
    throw std::invalid_argument("skin_model '" + *skinMode + "': expected 'walk' or 'table'");
  if (epsilon && !(*epsilon >= 0 && *epsilon <= 1))
    throw std::invalid_argument("epsilon must lie in [0, 1]");
  RenderSettings settings;
  settings.samplesPerPixel = spp;
  settings.width = width;
  settings.height = height;
  settings.seed = seed;
  settings.threads = threads;
  if (skinMode) settings.skinMode = parseEnum(*skinMode, skin::kSkinModeNames, "skin_model");
  settings.effectTolerance = epsilon;
  if (noiseTarget && !kRenderHasNoiseTarget)
    throw py::value_error(
        "noise_target: this renderer has no noise target");  // the Python layer says more
  if (noiseTarget && !(std::isfinite(*noiseTarget) && *noiseTarget > 0))
    throw std::invalid_argument("noise_target must be a positive relative noise");
  setNoiseTarget(settings, noiseTarget);
  setEstimator(settings, estimator);
  if (progress) settings.progress = progressBarFactory();
  SceneDesc scene;
  RenderResult result;
  runInterruptible(
      [&](const StopFlag& stop) {
        scene = applyRenderSettings(loadSceneFile(scenePath), settings);
        RenderSettings interruptible = settings;
        interruptible.stopRequested = [&stop] { return stop(); };
        result = renderScene(scene, interruptible, verbose ? &std::cout : nullptr);
      },
      false);
  const Film& film = *result.film;
  const std::size_t channels = film.channels().size();
  py::array_t<float> image({static_cast<py::ssize_t>(film.height()),
                            static_cast<py::ssize_t>(film.width()),
                            static_cast<py::ssize_t>(channels)});
  auto out = image.mutable_unchecked<3>();
  std::vector<double> wavelengths;
  for (const FilmChannel& c : film.channels()) wavelengths.push_back(c.wavelengthNm);
  {
    py::gil_scoped_release release;
    for (int y = 0; y < film.height(); ++y)
      for (int x = 0; x < film.width(); ++x)
        for (std::size_t c = 0; c < channels; ++c)
          out(y, x, static_cast<py::ssize_t>(c)) = static_cast<float>(film.value(x, y, c));
  }
  return py::make_tuple(image, array(wavelengths));
}

// ---------------------------------------------------------------------------------------------
// fit (app/fit_command.cpp, with the measured curve given as arrays).

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
  if (!(angleDeg >= 0 && angleDeg < 90))
    throw std::invalid_argument("angle_deg must lie in [0, 90)");
  if (rays < 100) throw std::invalid_argument("rays must be at least 100");
  if (maxIterations < 1) throw std::invalid_argument("max_iterations must be positive");
  if (threads < 0) throw std::invalid_argument("threads must be 0 (all cores) or positive");
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
}  // namespace hylios

PYBIND11_MODULE(_hylios, m) {
  using namespace hylios;
  m.doc() = "Compiled core of the hylios module; use the functions of the hylios package.";

  static py::exception<skin::SpecimenError> specimenError(m, "SpecimenError", PyExc_ValueError);
  static py::exception<SceneError> sceneError(m, "SceneError", PyExc_ValueError);
  static py::exception<skin::FitError> fitError(m, "FitError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const skin::SpecimenError& e) {
      specimenError(e.what());
    } catch (const SceneError& e) {
      sceneError(e.what());
    } catch (const skin::FitError& e) {
      fitError(e.what());
    }
  });

  py::class_<PySpecimen>(m, "_Specimen", "A loaded specimen (see hylios.Specimen)")
      .def_property_readonly("name", [](const PySpecimen& s) { return s.specimen.name; })
      .def_property_readonly("source_file",
                             [](const PySpecimen& s) { return s.specimen.sourceFile.string(); })
      .def(
          "to_toml",
          [](const PySpecimen& s, const std::string& header) {
            return skin::formatSpecimenToml(s.specimen, header);
          },
          py::arg("header") = "", "The specimen as specimen-file TOML text")
      .def(
          "values",
          [](const PySpecimen& s) {
            const skin::Specimen& x = s.specimen;
            py::dict d;
            d["surface_fold_aspect_ratio"] = x.surfaceFoldAspectRatio;
            d["thickness_cm"] = std::vector<double>(x.thicknessCm.begin(), x.thicknessCm.end());
            d["melanosome_fraction"] =
                std::vector<double>(x.melanosomeFraction.begin(), x.melanosomeFraction.end());
            d["colloidal_melanin_fraction"] = std::vector<double>(
                x.colloidalMelaninFraction.begin(), x.colloidalMelaninFraction.end());
            d["blood_fraction"] =
                std::vector<double>(x.bloodFraction.begin(), x.bloodFraction.end());
            d["melanosome_eumelanin_mg_per_ml"] = x.melanosomeEumelanin_mgPerMl;
            d["melanosome_pheomelanin_mg_per_ml"] = x.melanosomePheomelanin_mgPerMl;
            d["melanosome_major_axis_um"] = x.melanosomeMajorAxisUm;
            d["melanosome_minor_axis_um"] = x.melanosomeMinorAxisUm;
            d["oxygenated_blood_fraction"] = x.oxygenatedBloodFraction;
            d["water_reduction"] = x.waterReduction;
            return d;
          },
          "The main specimen quantities (fractions in [0, 1], per layer where a list)");

  m.def("load_specimen", &loadSpecimen, py::arg("name_or_path"), py::arg("overrides"),
        "Loads a specimen by name (S1..S4) or path and applies 'key=value' overrides in order");
  m.def(
      "specimen_from_toml",
      [](const std::string& text, const std::string& sourceName) {
        return PySpecimen{skin::parseSpecimen(text, sourceName)};
      },
      py::arg("text"), py::arg("source_name"), "Parses specimen-file TOML text");
  m.def("with_overrides", &withOverrides, py::arg("specimen"), py::arg("overrides"),
        "A copy of the specimen with 'key=value' overrides applied in order");
  m.def("override_keys", &skin::overrideKeys, "The keys of specimen overrides");
  m.def("layer_names", &layerNames, "The six layers, top to bottom");
  m.def("absorber_names", &absorberNames, "The absorbers, in the order of coefficient arrays");
  m.def(
      "data_root", [] { return dataRoot().string(); }, "The folder holding assets/ and scenes/");
  m.def("parse_resolution", &parseResolution, py::arg("text"), "'WxH' -> (W, H), as --resolution");
  m.def("parse_wavelengths", &parseWavelengthList, py::arg("text"),
        "start:stop:step or a comma list, nm");
  m.def("spectrum", &spectrum, py::arg("specimen"), py::arg("wavelengths"), py::arg("angle_deg"),
        py::arg("rays"), py::arg("seed"), py::arg("estimator"), py::arg("threads"),
        py::arg("epsilon"), py::arg("skin_model"), py::arg("progress"), "See hylios.spectrum");
  m.def("coefficients", &coefficients, py::arg("specimen"), py::arg("wavelengths"),
        "See hylios.coefficients");
  m.def("brdf", &brdf, py::arg("specimen"), py::arg("wavelengths"), py::arg("angle_deg"),
        py::arg("rays"), py::arg("seed"), py::arg("polar_bins"), py::arg("azimuth_bins"),
        py::arg("estimator"), py::arg("threads"), "See hylios.brdf");
  m.def("radial_profile", &radialProfile, py::arg("specimen"), py::arg("wavelength_nm"),
        py::arg("angle_deg"), py::arg("rays"), py::arg("seed"), py::arg("max_radius_cm"),
        py::arg("bins"), py::arg("estimator"), py::arg("threads"), "See hylios.radial_profile");
  m.def("render", &render, py::arg("scene_path"), py::arg("spp"), py::arg("width"),
        py::arg("height"), py::arg("seed"), py::arg("threads"), py::arg("skin_model"),
        py::arg("epsilon"), py::arg("noise_target"), py::arg("estimator"), py::arg("progress"),
        py::arg("verbose"), "See hylios.render");
  m.attr("render_has_estimator") = kRenderHasEstimator;
  m.attr("render_has_noise_target") = kRenderHasNoiseTarget;
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
