#include "skin/sampling/polar_rejection_sampling.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "skin/core/constants.h"
#include "skin/sampling/exponential_polar_sampling.h"
#include "skin/sampling/surface_normal_sampling.h"

namespace hylios::skin {
namespace {
/// Above this θo the Gamma(2) proposal's acceptance falls below 0.8: use the inversion sampler.
constexpr double kLargestRejectionMeanAngleRad = 0.5;
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
    // Gamma(2, θo): the sum of two exponentials; 1 − u lies in (0, 1], so the log is finite.
    const double u1 = rng.uniform(), u2 = rng.uniform();
    const double theta = -meanAngleRad * std::log((1.0 - u1) * (1.0 - u2));
    if (!(theta <= kPi)) continue;
    const double sinTheta = std::sin(theta), cosTheta = std::cos(theta);
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

PolarCosSin SurfaceNormalPolarSampler::sample(Rng& rng) const {
  double c = 0, h2 = 0;
  for (;;) {
    const double u1 = rng.uniform(), u2 = rng.uniform();
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
