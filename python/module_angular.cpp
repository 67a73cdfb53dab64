// hylios.brdf and hylios.radial_profile: what `hylios brdf` (app/brdf_command.cpp) and `hylios
// radial-profile` (app/radial_profile_command.cpp) compute, as dicts of numpy arrays.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "app/wavelength_list.h"
#include "python/argument_checks.h"
#include "python/interruptible.h"
#include "python/interruptible_tallies.h"
#include "python/module.h"
#include "python/module_specimen.h"
#include "python/numpy_conversions.h"
#include "renderer/scene/data_paths.h"
#include "skin/core/constants.h"
#include "skin/core/thread_limit.h"
#include "skin/exit_distribution.h"
#include "skin/spectral_database.h"

namespace hylios::python {

namespace py = pybind11;

namespace {

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
              std::size_t azimuthBins, const std::string& estimatorName, int threads) {
  const skin::Estimator estimator = estimatorNamed(estimatorName);
  requireAngle(angleDeg);
  requireRays(rays);
  requireThreads(threads);
  const std::vector<double> wavelengths = parseWavelengthList(wavelengthText);
  const std::vector<skin::SkinOptics> optics = opticsOf(s.specimen, wavelengths);
  const skin::DirectionBins bins(polarBins, azimuthBins);
  skin::WalkRunOptions run{angleDeg, rays, seed, {}, {}};
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
      estimator == skin::Estimator::PerWavelength);
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

py::dict radialProfile(const PySpecimen& s, double wavelengthNm, double angleDeg,
                       std::uint64_t rays, std::uint64_t seed, double maxRadiusCm, std::size_t bins,
                       const std::string& estimatorName, int threads) {
  const skin::Estimator estimator = estimatorNamed(estimatorName);
  requireAngle(angleDeg);
  requireRays(rays);
  if (!(maxRadiusCm > 0)) throw std::invalid_argument("max_radius_cm must be positive");
  if (bins < 1) throw std::invalid_argument("bins must be positive");
  requireThreads(threads);
  const skin::SkinOptics optics =
      skin::computeSkinOptics(s.specimen, skin::SpectralDatabase::load(spectraDir()), wavelengthNm);
  skin::WalkRunOptions run{angleDeg, rays, seed, {}, {}};
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
      estimator == skin::Estimator::PerWavelength);
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

}  // namespace

void bindAngular(py::module_& m) {
  m.def("brdf", &brdf, py::arg("specimen"), py::arg("wavelengths"), py::arg("angle_deg"),
        py::arg("rays"), py::arg("seed"), py::arg("polar_bins"), py::arg("azimuth_bins"),
        py::arg("estimator"), py::arg("threads"), "See hylios.brdf");
  m.def("radial_profile", &radialProfile, py::arg("specimen"), py::arg("wavelength_nm"),
        py::arg("angle_deg"), py::arg("rays"), py::arg("seed"), py::arg("max_radius_cm"),
        py::arg("bins"), py::arg("estimator"), py::arg("threads"), "See hylios.radial_profile");
}

}  // namespace hylios::python
