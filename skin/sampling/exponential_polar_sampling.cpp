#include "skin/sampling/exponential_polar_sampling.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "skin/core/constants.h"
#include "skin/sampling/bracketed_newton.h"
#include "skin/sampling/uniform_sample_check.h"

namespace hylios::skin {
namespace {

void requireMeanAngle(double meanAngleRad, bool allowZero, const char* where) {
  const bool zeroOk = allowZero && meanAngleRad == 0.0;
  const bool inRange =
      meanAngleRad >= kMinExponentialMeanAngleRad && meanAngleRad <= kMaxExponentialMeanAngleRad;
  if (!zeroOk && !inRange) {
    throw std::invalid_argument(std::string(where) +
                                ": mean angle θo = " + std::to_string(meanAngleRad) +
                                " rad must be " + (allowZero ? "0 or " : "") + "in [1e-300, 1e6]");
  }
}

/// 1 − e^{−x}(1 + x), the Gamma(2) CDF, accurate to relative rounding for all x >= 0.
double gamma2Cdf(double x) {
  if (x >= 1.0) return -std::expm1(-x) - x * std::exp(-x);
  // e^{−x}(e^x − 1 − x) = e^{−x} Σ_{k>=2} x^k/k!
  double term = 0.5 * x * x;
  double sum = 0.0;
  for (int k = 3; k < 40; ++k) {
    sum += term;
    term *= x / k;
    if (term <= 1e-17 * sum) break;
  }
  return std::exp(-x) * sum;
}

/// 1 − sinθ/θ, accurate to relative rounding for θ >= 0 (series below 0.5).
double oneMinusSinc(double theta) {
  if (theta >= 0.5) return 1.0 - std::sin(theta) / theta;
  const double t2 = theta * theta;
  double term = t2 / 6.0;  // θ²/3!
  double sum = 0.0;
  for (int k = 1; k < 20; ++k) {
    sum += term;
    term *= -t2 / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
    if (std::fabs(term) <= 1e-17 * sum) break;
  }
  return sum;
}

/// The CDF's pieces in the scaled variable x = θ/θo, all multiplied by Z = 1 + e^{−π/θo}.
struct ExponentialPolarCdf {
  double meanAngleRad;
  double normaliser;  // Z = 1 + e^{−π/θo}

  explicit ExponentialPolarCdf(double theta0)
      : meanAngleRad(theta0), normaliser(1.0 + std::exp(-kPi / theta0)) {}

  /// Z·F(θ) = 1 − e^{−x}(1+x) + e^{−x}[x(1 − sinθ/θ) + 2 sin²(θ/2)] (all terms >= 0).
  double cdfTimesNormaliser(double x) const {
    const double theta = meanAngleRad * x;
    const double halfSin = std::sin(0.5 * theta);
    return gamma2Cdf(x) + std::exp(-x) * (x * oneMinusSinc(theta) + 2.0 * halfSin * halfSin);
  }
  /// Z·(1 − F(θ)) = e^{−x}(sinθ/θo + cosθ) + e^{−π/θo}, with sinθ/θo = x·sinθ/θ.
  double complementTimesNormaliser(double x) const {
    const double theta = meanAngleRad * x;
    return std::exp(-x) * (x * (1.0 - oneMinusSinc(theta)) + std::cos(theta)) + (normaliser - 1.0);
  }
  /// d(Z·F)/dx = e^{−x}·(sinθ/θo)·(1 + θo²).
  double slope(double x) const {
    const double theta = meanAngleRad * x;
    return std::exp(-x) * x * (1.0 - oneMinusSinc(theta)) * (1.0 + meanAngleRad * meanAngleRad);
  }
};

/// A starting point for x = θ/θo: the Gamma(2) quantile (small θo) or the sinθ law's (large θo).
double initialScaledAngle(double meanAngleRad, double u) {
  if (meanAngleRad >= 0.3) return std::acos(1.0 - 2.0 * u) / meanAngleRad;
  if (u < 0.3) {
    const double s = std::sqrt(2.0 * u);  // x²/2 − x³/3 ≈ u  =>  x ≈ s + s²/3
    return s + s * s / 3.0;
  }
  const double l = -std::log1p(-u);  // x ≈ L + ln(1 + x), iterated twice
  return l + std::log1p(l + std::log1p(l));
}

}  // namespace

double sampleExponentialPolar(double meanAngleRad, double u) {
  requireMeanAngle(meanAngleRad, true, "sampleExponentialPolar");
  requireUniformSample(u, "sampleExponentialPolar");
  if (meanAngleRad == 0.0 || u == 0.0) return 0.0;
  const ExponentialPolarCdf cdf(meanAngleRad);
  // For θo < 0.05 the CDF is 1 to double precision beyond x = 60 (π/θo > 62.8 lies further out).
  const double xMax = meanAngleRad < 0.05 ? 60.0 : kPi / meanAngleRad;
  const double guess = initialScaledAngle(meanAngleRad, u);
  double x = 0;
  if (u <= 0.5) {
    const double target = u * cdf.normaliser;
    x = solveIncreasingBracketed(
        [&](double xi) {
          return ValueAndSlope{cdf.cdfTimesNormaliser(xi) - target, cdf.slope(xi)};
        },
        0.0, xMax, guess);
  } else {
    const double target = (1.0 - u) * cdf.normaliser;  // 1 − u is exact for u >= 1/2
    x = solveIncreasingBracketed(
        [&](double xi) {
          return ValueAndSlope{target - cdf.complementTimesNormaliser(xi), cdf.slope(xi)};
        },
        0.0, xMax, guess);
  }
  // θo·(π/θo) may round one ulp above π.
  return std::fmin(meanAngleRad * x, kPi);
}

double exponentialPolarDensity(double meanAngleRad, double thetaRad) {
  requireMeanAngle(meanAngleRad, false, "exponentialPolarDensity");
  if (!(thetaRad >= 0.0 && thetaRad <= kPi)) return 0.0;
  const ExponentialPolarCdf cdf(meanAngleRad);
  const double x = thetaRad / meanAngleRad;
  return cdf.slope(x) / (meanAngleRad * cdf.normaliser);  // dF/dθ = (dF/dx)/θo
}

double exponentialPolarCdf(double meanAngleRad, double thetaRad) {
  requireMeanAngle(meanAngleRad, false, "exponentialPolarCdf");
  if (!(thetaRad > 0.0)) return 0.0;
  if (thetaRad >= kPi) return 1.0;
  const ExponentialPolarCdf cdf(meanAngleRad);
  return cdf.cdfTimesNormaliser(thetaRad / meanAngleRad) / cdf.normaliser;
}

}  // namespace hylios::skin
