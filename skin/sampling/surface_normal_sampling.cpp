#include "skin/sampling/surface_normal_sampling.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "skin/sampling/bracketed_newton.h"
#include "skin/sampling/uniform_sample_check.h"

namespace hylios::skin {
namespace {

constexpr double kHalfPi = 1.57079632679489661923;
constexpr double kExactLimitAspectRatio = 1e-20;

void requireAspectRatio(double s, const char* where) {
  if (!(s >= kMinSurfaceAspectRatio && s <= kMaxSurfaceAspectRatio)) {
    throw std::invalid_argument(std::string(where) + ": surface aspect ratio s = " +
                                std::to_string(s) + " must be in [1e-100, 1e10]");
  }
}

/// atan(y)/y for y >= 0 (series below 1e-3, where the next term is < 1e-24).
double atanOverArgument(double y) {
  if (y < 1e-3) {
    const double y2 = y * y;
    return 1.0 - y2 * (1.0 / 3.0 - y2 * (1.0 / 5.0 - y2 / 7.0));
  }
  return std::atan(y) / y;
}

/// atanh(y)/y for 0 <= y < 1, given 1 − y computed without cancellation by the caller.
double atanhOverArgument(double y, double oneMinusY) {
  if (y < 1e-3) {
    const double y2 = y * y;
    return 1.0 + y2 * (1.0 / 3.0 + y2 * (1.0 / 5.0 + y2 / 7.0));
  }
  return 0.5 * (std::log1p(y) - std::log(oneMinusY)) / y;
}

/// The density's constants and its CDF pieces (each times 2/s⁴, see the header).
class SurfaceNormalLaw {
 public:
  explicit SurfaceNormalLaw(double s)
      : s2_(s * s),
        b_((s - 1.0) * (s + 1.0)),
        root_(std::sqrt(std::fabs(b_))),
        oneMinusRoot_(b_ < 0 ? s2_ / (1.0 + root_) : 1.0 - root_),
        phiOfB_(phiTimes(1.0, 0.0)),
        normaliser_(1.0 / s2_ + phiOfB_) {}

  double normaliser() const { return normaliser_; }

  /// The normalised density 2 sinθ/((s²cos²θ + sin²θ)²·(1/s² + Φ(B))), written with r = sinθ/s
  /// as 2r/(s(μ² + r²)) / (μ² + r²) / (1 + s²Φ(B)) so that no power of s under- or overflows.
  double density(double theta, double s) const {
    const double mu = std::cos(theta), r = std::sin(theta) / s;
    const double q = mu * mu + r * r;
    return 2.0 * r / (s * q) / q / (1.0 + s2_ * phiOfB_);
  }

  /// C(θ): the integral from 0 to θ.
  double head(double theta) const {
    const double mu = std::cos(theta), sinTheta = std::sin(theta);
    const double halfSin = std::sin(0.5 * theta);
    const double oneMinusMu = 2.0 * halfSin * halfSin;
    const double rational =
        oneMinusMu * (1.0 - b_ * mu) / (s2_ * (s2_ * mu * mu + sinTheta * sinTheta));
    // w·Φ(B w²) with y = √|B|·w; for B < 0, 1 − y = ((1 − μ)(1 − √−B) + s²μ)/((1 − μ) + s²μ).
    const double denominator = oneMinusMu + s2_ * mu;
    const double w = oneMinusMu / denominator;
    const double oneMinusY = (oneMinusMu * oneMinusRoot_ + s2_ * mu) / denominator;
    return rational + w * phiOf(root_ * w, oneMinusY);
  }

  /// T(θ): the integral from θ to π/2.
  double tail(double theta) const {
    const double mu = std::cos(theta), sinTheta = std::sin(theta);
    return mu / (s2_ * mu * mu + sinTheta * sinTheta) + phiTimes(mu, theta);
  }

  /// dF/dθ times the normaliser: 2 sinθ / (s²cos²θ + sin²θ)².
  double slope(double theta) const {
    const double mu = std::cos(theta), sinTheta = std::sin(theta);
    const double q = s2_ * mu * mu + sinTheta * sinTheta;
    return theta > 0 ? 2.0 * sinTheta / (q * q) : 0.0;
  }

 private:
  /// Φ(B y²/|B|)-type value: atan(y)/y for B > 0, atanh(y)/y for B < 0, 1 for B = 0.
  double phiOf(double y, double oneMinusY) const {
    if (b_ > 0) return atanOverArgument(y);
    if (b_ < 0) return atanhOverArgument(y, oneMinusY);
    return 1.0;
  }
  /// μ·Φ(Bμ²); θ is passed so 1 − μ can be formed as 2 sin²(θ/2).
  double phiTimes(double mu, double theta) const {
    const double halfSin = std::sin(0.5 * theta);
    const double oneMinusMu = 2.0 * halfSin * halfSin;
    return mu * phiOf(root_ * mu, oneMinusMu + mu * oneMinusRoot_);
  }

  double s2_;            // s²
  double b_;             // B = s² − 1
  double root_;          // √|B|
  double oneMinusRoot_;  // 1 − √|B| (as s²/(1 + √−B) when B < 0)
  double phiOfB_;        // Φ(B)
  double normaliser_;    // 1/s² + Φ(B)
};

}  // namespace

double sampleSurfaceNormalPolar(double aspectRatio, double u) {
  requireAspectRatio(aspectRatio, "sampleSurfaceNormalPolar");
  requireUniformSample(u, "sampleSurfaceNormalPolar");
  const double guess = std::atan(aspectRatio * std::sqrt(u / (1.0 - u)));
  if (aspectRatio < kExactLimitAspectRatio || u == 0.0) return guess;
  const SurfaceNormalLaw law(aspectRatio);
  if (u <= 0.5) {
    const double target = u * law.normaliser();
    return solveIncreasingBracketed(
        [&](double t) {
          return ValueAndSlope{law.head(t) - target, law.slope(t)};
        },
        0.0, kHalfPi, guess);
  }
  const double target = (1.0 - u) * law.normaliser();  // exact for u >= 1/2
  return solveIncreasingBracketed(
      [&](double t) {
        return ValueAndSlope{target - law.tail(t), law.slope(t)};
      },
      0.0, kHalfPi, guess);
}

double surfaceNormalPolarDensity(double aspectRatio, double thetaRad) {
  requireAspectRatio(aspectRatio, "surfaceNormalPolarDensity");
  if (!(thetaRad > 0.0 && thetaRad < kHalfPi)) return 0.0;
  const SurfaceNormalLaw law(aspectRatio);
  return law.density(thetaRad, aspectRatio);
}

double surfaceNormalPolarCdf(double aspectRatio, double thetaRad) {
  requireAspectRatio(aspectRatio, "surfaceNormalPolarCdf");
  if (!(thetaRad > 0.0)) return 0.0;
  if (thetaRad >= kHalfPi) return 1.0;
  const SurfaceNormalLaw law(aspectRatio);
  return law.head(thetaRad) / law.normaliser();
}

}  // namespace hylios::skin
