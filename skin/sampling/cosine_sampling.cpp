#include "skin/sampling/cosine_sampling.h"

#include <cmath>

#include "skin/core/constants.h"
#include "skin/sampling/uniform_sample_check.h"

namespace hylios::skin {
namespace {
constexpr double kHalfPi = 1.57079632679489661923;
}  // namespace

double sampleCosinePolar(double u) {
  requireUniformSample(u, "sampleCosinePolar");
  return std::asin(std::sqrt(u));
}

double cosinePolarDensity(double thetaRad) {
  if (!(thetaRad >= 0.0 && thetaRad < kHalfPi)) return 0.0;
  return std::sin(2.0 * thetaRad);  // 2 cosθ sinθ
}

Vec3 sampleCosineHemisphere(double u1, double u2) {
  requireUniformSample(u1, "sampleCosineHemisphere (u1)");
  requireUniformSample(u2, "sampleCosineHemisphere (u2)");
  const double sinTheta = std::sqrt(u1);
  const double cosTheta = std::sqrt(1.0 - u1);
  const double phi = kTwoPi * u2;
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

}  // namespace hylios::skin
