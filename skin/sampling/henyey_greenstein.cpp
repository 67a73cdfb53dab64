#include "skin/sampling/henyey_greenstein.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "skin/sampling/uniform_sample_check.h"

namespace hylios::skin {
namespace {

void requireAsymmetry(double g, const char* where) {
  if (!(g > -1.0 && g < 1.0)) {
    throw std::invalid_argument(std::string(where) + ": asymmetry g = " + std::to_string(g) +
                                " must lie in (−1, 1)");
  }
}

}  // namespace

double sampleHenyeyGreensteinCos(double g, double u) {
  requireAsymmetry(g, "sampleHenyeyGreensteinCos");
  requireUniformSample(u, "sampleHenyeyGreensteinCos");
  const double d = (1.0 - g) + 2.0 * g * u;  // > 0: between 1 − g and 1 + g
  const double dSquared = d * d;
  const double oneMinusMu = 2.0 * (1.0 - g) * (1.0 - g) * (1.0 - u) * (1.0 + g * u) / dSquared;
  if (oneMinusMu <= 1.0) return 1.0 - oneMinusMu;
  const double onePlusMu = 2.0 * (1.0 + g) * (1.0 + g) * u * ((1.0 - g) + g * u) / dSquared;
  return onePlusMu - 1.0;
}

double henyeyGreensteinDensity(double g, double mu) {
  requireAsymmetry(g, "henyeyGreensteinDensity");
  if (!(mu >= -1.0 && mu <= 1.0)) return 0.0;
  // 1 + g² − 2gμ = (1 − g)² + 2g(1 − μ) = (1 + g)² − 2g(1 + μ): take the sum of non-negative
  // terms for the sign of g, so nothing cancels near the forward (backward) peak as |g| -> 1.
  const double q = g >= 0.0 ? (1.0 - g) * (1.0 - g) + 2.0 * g * (1.0 - mu)
                            : (1.0 + g) * (1.0 + g) - 2.0 * g * (1.0 + mu);
  return 0.5 * (1.0 - g) * (1.0 + g) / (q * std::sqrt(q));
}

}  // namespace hylios::skin
