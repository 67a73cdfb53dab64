#include "skin/rayleigh_coefficient.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "skin/core/constants.h"

namespace hylios::skin {
namespace {
constexpr double kCmPerNm = 1e-7;

void requirePositive(double value, const char* what) {
  if (!std::isfinite(value) || !(value > 0))
    throw std::invalid_argument(std::string("Rayleigh coefficient: ") + what +
                                " must be positive and finite, got " + std::to_string(value));
}

void checkParameters(const RayleighParameters& p) {
  requirePositive(p.radiusNm, "radius");
  requirePositive(p.relativeIndex, "relative index");
  requirePositive(p.volumeFraction, "volume fraction");
}
}  // namespace

double rayleighNumberDensity_perCm3(const RayleighParameters& p) {
  checkParameters(p);
  const double r = p.radiusNm * kCmPerNm;
  return p.volumeFraction / (4.0 / 3.0 * kPi * r * r * r);  // Eq. 5
}

double rayleighPolarizabilityFactor(const RayleighParameters& p) {
  checkParameters(p);
  const double eta2 = p.relativeIndex * p.relativeIndex;
  const double denominatorOffset = p.form == RayleighPolarizabilityForm::Paper ? 1.0 : 2.0;
  return (eta2 - 1.0) / (eta2 + denominatorOffset);
}

double rayleighScatteringCoefficient_perCm(double wavelengthNm, const RayleighParameters& p) {
  requirePositive(wavelengthNm, "wavelength");
  const double r = p.radiusNm * kCmPerNm;
  const double lambda = wavelengthNm * kCmPerNm;
  const double density = rayleighNumberDensity_perCm3(p);
  const double k = rayleighPolarizabilityFactor(p);
  const double r3 = r * r * r;
  const double lambda2 = lambda * lambda;
  // Eq. 4
  return 128.0 * std::pow(kPi, 5) * r3 * r3 * density / (3.0 * lambda2 * lambda2) * k * k;
}

}  // namespace hylios::skin
