#include "skin/sampling/melanosome_orientation_sampling.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "skin/core/constants.h"
#include "skin/sampling/uniform_sample_check.h"

namespace hylios::skin {
namespace {

void requireUnitDirection(const Vec3& d, const char* where) {
  const double lengthSquared = dot(d, d);
  if (!(std::fabs(lengthSquared - 1.0) <= 1e-6)) {
    throw std::invalid_argument(std::string(where) + ": ray direction has length² " +
                                std::to_string(lengthSquared) + ", expected a unit vector");
  }
}

/// |μ| in [0, 1] for v in [0, 1], density ∝ χ1 + (χ2 − χ1)m with χ1 ∝ c, χ2 ∝ a (π·a cancels).
/// The quadratic (χ2 − χ1)m²/2 + χ1 m = v(χ1 + χ2)/2 has the root
/// m = v(χ1 + χ2) / (χ1 + sqrt(χ1²(1 − v) + χ2² v)), stable for any sign of χ2 − χ1.
double invertLinearDensity(double chi1, double chi2, double v) {
  return v * (chi1 + chi2) / (chi1 + std::sqrt(chi1 * chi1 * (1.0 - v) + chi2 * chi2 * v));
}

}  // namespace

double melanosomeAxisCosDensity(const ProlateSpheroid& spheroid, double mu) {
  checkProlateSpheroid(spheroid);
  if (!(mu >= -1.0 && mu <= 1.0)) return 0.0;
  const double chi1 = crossSectionContainingMajorAxis(spheroid);  // π a c
  const double chi2 = crossSectionNormalToMajorAxis(spheroid);    // π a²
  const double m = std::fabs(mu);
  return (chi1 * (1.0 - m) + chi2 * m) / (chi1 + chi2);  // Eq. 8
}

double sampleMelanosomeAxisCos(const ProlateSpheroid& spheroid, double u) {
  checkProlateSpheroid(spheroid);
  requireUniformSample(u, "sampleMelanosomeAxisCos");
  // u in [0, 1/2) -> μ <= 0 with v = 1 − 2u; u in [1/2, 1) -> μ >= 0 with v = 2u − 1 (both exact).
  const bool negative = u < 0.5;
  const double v = negative ? 1.0 - 2.0 * u : 2.0 * u - 1.0;
  const double m = invertLinearDensity(spheroid.semiMajorAxis, spheroid.semiMinorAxis, v);
  return negative ? -m : m;
}

Vec3 sampleMelanosomeAxisInRayFrame(const ProlateSpheroid& spheroid, double u1, double u2) {
  requireUniformSample(u2, "sampleMelanosomeAxisInRayFrame (u2)");
  const double mu = sampleMelanosomeAxisCos(spheroid, u1);
  const double sinAlpha = std::sqrt((1.0 - mu) * (1.0 + mu));
  const double beta = kTwoPi * u2;
  return {sinAlpha * std::cos(beta), sinAlpha * std::sin(beta), mu};
}

Vec3 sampleMelanosomeAxis(const ProlateSpheroid& spheroid, const Vec3& rayDirection, double u1,
                          double u2) {
  requireUnitDirection(rayDirection, "sampleMelanosomeAxis");
  return Frame(rayDirection).toWorld(sampleMelanosomeAxisInRayFrame(spheroid, u1, u2));
}

}  // namespace hylios::skin
