#include "skin/sampling/rayleigh_sampling.h"

#include <algorithm>
#include <cmath>

#include "skin/core/constants.h"
#include "skin/sampling/uniform_sample_check.h"

namespace hylios::skin {
double sampleRayleighCos(double u) {
  requireUniformSample(u, "sampleRayleighCos");
  // F(μ) = (μ³ + 3μ + 4)/8 = u  <=>  μ³ + 3μ = 2w with w = 4u − 2 in [−2, 2).
  // Cardano: μ = A − 1/A with A³ = w + sqrt(w² + 1). Since A³ − A⁻³ = 2w exactly,
  // A − 1/A = 2w / (A² + 1 + A⁻²), which has no cancellation near w = 0. Taking A from |w| keeps
  // A >= 1 (no cancellation inside the cube root either); the root is odd in w.
  const double w = 4.0 * u - 2.0;
  const double a = std::cbrt(std::fabs(w) + std::sqrt(w * w + 1.0));
  const double mu = 2.0 * w / (a * a + 1.0 + 1.0 / (a * a));
  // |μ| <= 1 holds exactly; at u = 0 rounding may leave it one ulp outside, so bound it.
  return std::clamp(mu, -1.0, 1.0);
}

double sampleRayleighPolar(double u) { return std::acos(sampleRayleighCos(u)); }

double rayleighCosDensity(double mu) {
  if (!(mu >= -1.0 && mu <= 1.0)) return 0.0;
  return 0.375 * (1.0 + mu * mu);
}

double rayleighPolarDensity(double thetaRad) {
  if (!(thetaRad >= 0.0 && thetaRad <= kPi)) return 0.0;
  const double c = std::cos(thetaRad);
  return 0.375 * (1.0 + c * c) * std::sin(thetaRad);
}

}  // namespace hylios::skin
