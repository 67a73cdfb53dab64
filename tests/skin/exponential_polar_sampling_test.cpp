// Algorithm 2 (Sec. 4.2.2), sampled exactly: chi-square against the density for θo = 5°, 1°,
// 0.01°, 1e-6 rad, 1 rad and 10 rad; the closed-form CDF against quadrature; the density against
// the paper's unnormalised target; the paper's own rejection loop against our density; the mean
// against quadrature (≈ 2θo for small θo); θo = 0 and the u end points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "skin/core/constants.h"
#include "skin/core/random.h"
#include "skin/sampling/exponential_polar_sampling.h"
#include "tests/support/chi2.h"

using hylios::kPi;

namespace hylios::skin {
namespace {

constexpr double kDeg = kPi / 180.0;

/// Where the density lives: beyond 80θo the mass is < 81·e^{−80} ≈ 1e-33.
double supportEnd(double meanAngleRad) { return std::min(kPi, 80.0 * meanAngleRad); }

TEST(ExponentialPolarSampling, DensityMatchesAlgorithmTwoTarget) {
  // Algorithm 2 accepts against e^{−θ/θo} sinθ (its 1/θo factor cancels). Normalise it by
  // quadrature here, independently of the library's closed form.
  for (const double t : {5 * kDeg, 1 * kDeg, 1.0, 10.0, 1e-6}) {
    const auto target = [t](double x) { return std::exp(-x / t) * std::sin(x); };
    const double z = test::integrate(target, 0.0, supportEnd(t), 1e-14 * t * t, 64);
    for (const double fraction : {0.1, 0.5, 1.0, 3.0, 7.0}) {
      const double theta = std::min(fraction * t, 3.0);
      EXPECT_NEAR(exponentialPolarDensity(t, theta) * z / target(theta), 1.0, 1e-9)
          << "θo = " << t << ", θ = " << theta;
    }
  }
}

TEST(ExponentialPolarSampling, ClosedFormCdfMatchesQuadrature) {
  for (const double t : {5 * kDeg, 0.01 * kDeg, 1.0, 10.0}) {
    const auto density = [t](double x) { return exponentialPolarDensity(t, x); };
    for (const double fraction : {0.01, 0.5, 2.0, 10.0}) {
      const double theta = std::min(fraction * t, 3.1);
      EXPECT_NEAR(exponentialPolarCdf(t, theta), test::integrate(density, 0.0, theta, 1e-14, 64),
                  1e-11)
          << "θo = " << t << ", θ = " << theta;
    }
    EXPECT_EQ(exponentialPolarCdf(t, kPi), 1.0);
  }
  // Hand value, small θo: F -> 1 − e^{−x}(1 + x) at x = θ/θo = 2: 1 − 3e^{−2} = 0.593994150.
  EXPECT_NEAR(exponentialPolarCdf(1e-8, 2e-8), 1.0 - 3.0 * std::exp(-2.0), 1e-12);
  // Hand value, θo = 1 rad at θ = π/2: [1 − e^{−π/2}(1 + 0)]/(1 + e^{−π}) = 0.758205/1.043214.
  EXPECT_NEAR(exponentialPolarCdf(1.0, kPi / 2),
              (1.0 - std::exp(-kPi / 2)) / (1.0 + std::exp(-kPi)), 1e-15);
}

class ExponentialPolarChi2 : public ::testing::TestWithParam<double> {};

TEST_P(ExponentialPolarChi2, SamplesMatchDensityAndMean) {
  const double t = GetParam();
  // A stream per θo; through int64 so that θo > 1 rad (a negative value) converts modulo 2⁶⁴.
  Rng rng(31, static_cast<std::uint64_t>(static_cast<std::int64_t>(-std::log(t) * 1000)));
  const std::size_t n = 500000;
  const std::vector<double> thetas =
      test::drawSamples(n, [&] { return sampleExponentialPolar(t, rng.uniform()); });
  const double sampleMean = test::mean(thetas);
  const auto density = [t](double x) { return exponentialPolarDensity(t, x); };
  const double end = supportEnd(t);
  const auto edges = test::equalProbabilityEdges(density, 0.0, end, 50);
  EXPECT_TRUE(test::chi2Accepts(test::chi2Test1D(thetas, density, edges))) << "θo = " << t;
  // Mean and its standard error from quadrature of the density.
  const double mean =
      test::integrate([&](double x) { return x * density(x); }, 0.0, end, 1e-15, 64);
  const double second =
      test::integrate([&](double x) { return x * x * density(x); }, 0.0, end, 1e-15, 64);
  const double standardError = std::sqrt((second - mean * mean) / static_cast<double>(n));
  EXPECT_NEAR(sampleMean, mean, 4 * standardError) << "θo = " << t;
  if (t <= 0.01 * kDeg) {
    // As θo -> 0, θ/θo tends to Gamma(2): mean 2θo (the correction is −2θo³, negligible here).
    EXPECT_NEAR(mean / (2 * t), 1.0, 1e-6);
    EXPECT_NEAR(sampleMean / (2 * t), 1.0, 4 * standardError / (2 * t));
  }
}

INSTANTIATE_TEST_SUITE_P(MeanAngles, ExponentialPolarChi2,
                         ::testing::Values(5 * kDeg, 1 * kDeg, 0.01 * kDeg, 1e-6, 1.0, 10.0));

TEST(ExponentialPolarSampling, PaperRejectionLoopAgreesWithOurDensity) {
  // Algorithm 2 verbatim at θo = 5° (acceptance ≈ 6 %), chi-square against our density: confirms
  // that the exact sampler targets the paper's law.
  const double t = 5 * kDeg;
  const double phi = std::atan(t);
  const double maxTarget = 1.0 / t * std::exp(-phi / t) * std::sin(phi);
  Rng rng(8);
  std::vector<double> thetas(100000);
  for (double& theta : thetas) {
    do {
      theta = kPi * rng.uniform();
    } while (!(maxTarget * rng.uniform() <= 1.0 / t * std::exp(-theta / t) * std::sin(theta)));
  }
  const auto density = [t](double x) { return exponentialPolarDensity(t, x); };
  const auto edges = test::equalProbabilityEdges(density, 0.0, supportEnd(t), 40);
  EXPECT_TRUE(test::chi2Accepts(test::chi2Test1D(thetas, density, edges)));
}

TEST(ExponentialPolarSampling, ZeroMeanAngleMeansNoDeflection) {
  EXPECT_EQ(sampleExponentialPolar(0.0, 0.3), 0.0);
  EXPECT_EQ(sampleExponentialPolar(0.0, kOneMinusEpsilon), 0.0);
  EXPECT_THROW(exponentialPolarDensity(0.0, 0.1), std::invalid_argument);
}

TEST(ExponentialPolarSampling, EndPointsAreFiniteAndInRange) {
  for (const double t : {1e-300, 1e-6, 0.01 * kDeg, 5 * kDeg, 0.3, 1.0, 10.0, 1e6}) {
    for (const double u : {0.0, 1e-16, 0.5, kOneMinusEpsilon}) {
      const double theta = sampleExponentialPolar(t, u);
      EXPECT_TRUE(std::isfinite(theta)) << "θo = " << t << ", u = " << u;
      EXPECT_GE(theta, 0.0);
      EXPECT_LE(theta, kPi);
    }
    // Monotone in u, as an inversion must be.
    double previous = 0;
    for (int k = 1; k < 200; ++k) {
      const double theta = sampleExponentialPolar(t, k / 200.0);
      EXPECT_GE(theta, previous) << "θo = " << t << ", u = " << k / 200.0;
      previous = theta;
    }
  }
  EXPECT_EQ(sampleExponentialPolar(1.0, 0.0), 0.0);
}

TEST(ExponentialPolarSampling, RejectsBadArguments) {
  EXPECT_THROW(sampleExponentialPolar(-1e-3, 0.5), std::invalid_argument);
  EXPECT_THROW(sampleExponentialPolar(1e-320, 0.5), std::invalid_argument);
  EXPECT_THROW(sampleExponentialPolar(2e6, 0.5), std::invalid_argument);
  EXPECT_THROW(sampleExponentialPolar(std::nan(""), 0.5), std::invalid_argument);
  EXPECT_THROW(sampleExponentialPolar(0.1, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace hylios::skin
