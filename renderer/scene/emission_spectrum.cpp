#include "renderer/scene/emission_spectrum.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "renderer/image/colour_tables.h"

namespace hylios {
namespace {

constexpr double kWienB_nmK = 2.897771955e6;            // Wien displacement constant (CODATA 2018)
constexpr double kSecondRadiation_nmK = 1.438776877e7;  // c2 = hc/k (CODATA 2018)

double interpolateTable(const EmissionDesc& e, double wavelengthNm) {
  const auto& x = e.tableWavelengthNm;
  const auto& y = e.tableValue;
  if (x.empty() || x.size() != y.size())
    throw SceneError(e.where, fmt::format("tabulated spectrum has {} wavelengths and {} values",
                                          x.size(), y.size()));
  if (wavelengthNm < x.front() || wavelengthNm > x.back())
    throw SceneError(e.where, fmt::format("tabulated spectrum covers {}–{} nm; {} nm is outside "
                                          "it (no extrapolation)",
                                          x.front(), x.back(), wavelengthNm));
  const auto upper = std::lower_bound(x.begin(), x.end(), wavelengthNm);
  const auto i = static_cast<std::size_t>(upper - x.begin());
  if (x[i] == wavelengthNm) return y[i];
  const double t = (wavelengthNm - x[i - 1]) / (x[i] - x[i - 1]);
  return y[i - 1] + t * (y[i] - y[i - 1]);
}

double d65Relative(const EmissionDesc& e, double wavelengthNm) {
  try {
    return d65(wavelengthNm) / 100.0;
  } catch (const std::out_of_range& error) {
    throw SceneError(e.where,
                     fmt::format("D65 is not defined at {} nm ({})", wavelengthNm, error.what()));
  }
}

}  // namespace

double blackbodyPeakNm(double temperatureK) { return kWienB_nmK / temperatureK; }

double normalisedBlackbody(double temperatureK, double wavelengthNm) {
  // B_λ ∝ λ⁻⁵ / (exp(c2/(λT)) − 1); the ratio to the peak needs no other constant.
  const double peakNm = blackbodyPeakNm(temperatureK);
  const double ratio5 = std::pow(peakNm / wavelengthNm, 5.0);
  const double peakDenominator = std::expm1(kSecondRadiation_nmK / (peakNm * temperatureK));
  const double denominator = std::expm1(kSecondRadiation_nmK / (wavelengthNm * temperatureK));
  return ratio5 * peakDenominator / denominator;  // → 0 (not NaN) when the exponent overflows
}

double ledGaussian(double centreNm, double fwhmNm, double wavelengthNm) {
  const double d = (wavelengthNm - centreNm) / fwhmNm;
  return std::exp(-4.0 * std::log(2.0) * d * d);
}

double evaluateEmission(const EmissionDesc& e, double wavelengthNm) {
  if (!std::isfinite(wavelengthNm) || wavelengthNm <= 0)
    throw SceneError(e.where,
                     fmt::format("wavelength {} nm is not a positive finite number", wavelengthNm));
  double shape = 0;
  switch (e.kind) {
    case EmissionDesc::Kind::Constant:
      shape = 1;
      break;
    case EmissionDesc::Kind::D65:
      shape = d65Relative(e, wavelengthNm);
      break;
    case EmissionDesc::Kind::Blackbody:
      if (!(e.temperatureK > 0))
        throw SceneError(e.where,
                         fmt::format("blackbody temperature {} K must be > 0", e.temperatureK));
      shape = normalisedBlackbody(e.temperatureK, wavelengthNm);
      break;
    case EmissionDesc::Kind::Led:
      if (!(e.fwhmNm > 0))
        throw SceneError(e.where, fmt::format("LED FWHM {} nm must be > 0", e.fwhmNm));
      shape = ledGaussian(e.centreNm, e.fwhmNm, wavelengthNm);
      break;
    case EmissionDesc::Kind::Tabulated:
      shape = interpolateTable(e, wavelengthNm);
      break;
  }
  return e.scale * shape;
}

}  // namespace hylios
