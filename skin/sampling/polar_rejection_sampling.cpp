#include "skin/sampling/polar_rejection_sampling.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "skin/core/constants.h"
#include "skin/sampling/exponential_polar_sampling.h"
#include "skin/sampling/exponential_ziggurat.h"
#include "skin/sampling/surface_normal_sampling.h"

namespace hylios::skin {
namespace {
/// Above this θo the Gamma(2) proposal's acceptance falls below 0.8: use the inversion sampler.
constexpr double kLargestRejectionMeanAngleRad = 0.5;

/// Below this angle sinθ and cosθ come from their Taylor polynomials (truncation < 5e−17
/// relative, as exact as libm's); the model's θo ≤ 5° puts ≈ 98 % of Algorithm 2's angles there,
/// where sincos was 5 % of the spectral walk's time.
constexpr double kLargestSeriesAngleRad = 0.5;

struct CosSin {
  double cosTheta, sinTheta;
};
CosSin cosSinOf(double theta) {
  if (!(theta <= kLargestSeriesAngleRad)) return {std::cos(theta), std::sin(theta)};
  // sinθ = θ(1 − θ²/3! + θ⁴/5! − … − θ¹⁴/15!), cosθ = 1 − θ²/2! + … − θ¹⁴/14!, as polynomials in
  // u = θ² by Estrin's scheme (pairs, then u², u⁴): a third of Horner's chain of dependent steps.
  const double u = theta * theta, u2 = u * u, u4 = u2 * u2;
  const double s01 = -1.0 / 6.0 + u * (1.0 / 120.0);                // −1/3!, 1/5!
  const double s23 = -1.0 / 5040.0 + u * (1.0 / 362880.0);          // −1/7!, 1/9!
  const double s45 = -1.0 / 39916800.0 + u * (1.0 / 6227020800.0);  // −1/11!, 1/13!
  const double s6 = -1.0 / 1307674368000.0;                         // −1/15!
  const double sinSeries = (s01 + u2 * s23) + u4 * (s45 + u2 * s6);
  const double c01 = -0.5 + u * (1.0 / 24.0);                     // −1/2!, 1/4!
  const double c23 = -1.0 / 720.0 + u * (1.0 / 40320.0);          // −1/6!, 1/8!
  const double c45 = -1.0 / 3628800.0 + u * (1.0 / 479001600.0);  // −1/10!, 1/12!
  const double c6 = -1.0 / 87178291200.0;                         // −1/14!
  const double cosSeries = (c01 + u2 * c23) + u4 * (c45 + u2 * c6);
  return {1.0 + u * cosSeries, theta + theta * (u * sinSeries)};
}
}  // namespace

PolarCosSin sampleExponentialPolarCosSin(double meanAngleRad, Rng& rng) {
  if (meanAngleRad == 0.0) return {1.0, 0.0};
  if (!(meanAngleRad >= kMinExponentialMeanAngleRad && meanAngleRad <= kMaxExponentialMeanAngleRad))
    throw std::invalid_argument(
        "sampleExponentialPolarCosSin: mean angle θo = " + std::to_string(meanAngleRad) +
        " rad must be 0 or in [1e-300, 1e6]");
  if (meanAngleRad > kLargestRejectionMeanAngleRad) {
    const double theta = sampleExponentialPolar(meanAngleRad, rng.uniform());
    return {std::cos(theta), std::sin(theta), theta};
  }
  for (;;) {
    // Gamma(2, θo): θo times the sum of two standard exponentials.
    const double theta =
        meanAngleRad * (sampleStandardExponential(rng) + sampleStandardExponential(rng));
    if (!(theta <= kPi)) continue;
    const auto [cosTheta, sinTheta] = cosSinOf(theta);
    const double u3 = rng.uniform();
    if (u3 * theta <= sinTheta)
      return {cosTheta, sinTheta, theta};  // accept with probability sinθ/θ
  }
}

SurfaceNormalPolarSampler::SurfaceNormalPolarSampler(double aspectRatio)
    : s_(aspectRatio),
      s2_(aspectRatio * aspectRatio),
      slope_(0),
      k2_((1.0 - aspectRatio) * (1.0 + aspectRatio)),
      envelopeArea_(0) {
  if (!(aspectRatio >= kMinSurfaceAspectRatio && aspectRatio <= kMaxSurfaceAspectRatio))
    throw std::invalid_argument("SurfaceNormalPolarSampler: surface aspect ratio s = " +
                                std::to_string(aspectRatio) + " must be in [1e-100, 1e10]");
  if (s_ < 1.0) {
    slope_ = std::sqrt(k2_);
    envelopeArea_ = s_ + 0.5 * slope_;
  }
}

PolarCosSin SurfaceNormalPolarSampler::sample(Rng& rng,
                                              const std::array<double, 2>* firstTrial) const {
  double c = 0, h2 = 0;
  for (;;) {
    double u1 = 0, u2 = 0;
    if (firstTrial) {
      u1 = (*firstTrial)[0];
      u2 = (*firstTrial)[1];
      firstTrial = nullptr;
    } else {
      u1 = rng.uniform();
      u2 = rng.uniform();
    }
    double envelope = s_;
    if (s_ < 1.0) {
      // c from the density ∝ s + k·c: s·c + k·c²/2 = w, root 2w/(s + sqrt(s² + 2kw)).
      const double w = u1 * envelopeArea_;
      c = 2.0 * w / (s_ + std::sqrt(s2_ + 2.0 * slope_ * w));
      if (c > 1.0) c = 1.0;  // rounding at w = envelope area only
      envelope = s_ + slope_ * c;
    } else {
      c = u1;
    }
    h2 = s2_ + k2_ * c * c;  // h(c)² = s² + (1 − s²)c²
    const double scaled = u2 * envelope;
    if (scaled * scaled <= h2) break;
  }
  const double inverseH = 1.0 / std::sqrt(h2);
  return {c * inverseH, s_ * std::sqrt((1.0 - c) * (1.0 + c)) * inverseH};
}

}  // namespace hylios::skin
