// Cosine-weighted sampling (Sec. 4.2.2 internal bounces, Sec. 4.3 dermis/hypodermis reflection):
// chi-square of the polar angle and of the hemisphere direction, hand values, end points.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "skin/core/constants.h"
#include "skin/core/random.h"
#include "skin/sampling/cosine_sampling.h"
#include "tests/support/chi2.h"

using hylios::kPi;

namespace hylios::skin {
namespace {

TEST(CosineSampling, InversionByHand) {
  // F(θ) = sin²θ: u = 1/4 -> θ = π/6, u = 1/2 -> θ = π/4, u = 0 -> θ = 0.
  EXPECT_NEAR(sampleCosinePolar(0.25), kPi / 6, 1e-15);
  EXPECT_NEAR(sampleCosinePolar(0.5), kPi / 4, 1e-15);
  EXPECT_EQ(sampleCosinePolar(0.0), 0.0);
  const Vec3 d = sampleCosineHemisphere(0.25, 0.25);  // sinθ = 1/2, φ = π/2
  EXPECT_NEAR(d.x, 0.0, 1e-16);
  EXPECT_NEAR(d.y, 0.5, 1e-15);
  EXPECT_NEAR(d.z, std::sqrt(0.75), 1e-15);
}

TEST(CosineSampling, DensityIsNormalised) {
  EXPECT_NEAR(test::integrate(cosinePolarDensity, 0.0, kPi / 2), 1.0, 1e-12);
}

TEST(CosineSampling, ChiSquareOfPolarAngle) {
  Rng rng(99);
  std::vector<double> thetas(1000000);
  for (double& t : thetas) t = sampleCosinePolar(rng.uniform());
  const auto edges = test::uniformEdges(0.0, kPi / 2, 50);
  EXPECT_TRUE(test::chi2Accepts(test::chi2Test1D(thetas, cosinePolarDensity, edges)));
}

TEST(CosineSampling, ChiSquareOfHemisphereDirection) {
  // Joint density of (cosθ, φ): 2cosθ · 1/(2π) on [0, 1] × [0, 2π).
  Rng rng(100);
  const std::size_t n = 500000;
  std::vector<double> cosines(n), azimuths(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 d = sampleCosineHemisphere(rng.uniform(), rng.uniform());
    ASSERT_NEAR(length(d), 1.0, 1e-14);
    cosines[i] = d.z;
    azimuths[i] = std::atan2(d.y, d.x) + (d.y < 0 ? 2 * kPi : 0.0);
  }
  const auto density = [](double mu, double) { return mu / kPi; };
  EXPECT_TRUE(test::chi2Accepts(test::chi2Test2D(cosines, azimuths, density,
                                                 test::uniformEdges(0.0, 1.0, 20),
                                                 test::uniformEdges(0.0, 2 * kPi, 20))));
}

TEST(CosineSampling, EndPointsAreFiniteAndInRange) {
  for (const double u : {0.0, kOneMinusEpsilon}) {
    const double theta = sampleCosinePolar(u);
    EXPECT_TRUE(std::isfinite(theta));
    EXPECT_GE(theta, 0.0);
    EXPECT_LT(theta, kPi / 2);
    for (const double v : {0.0, kOneMinusEpsilon}) {
      const Vec3 d = sampleCosineHemisphere(u, v);
      EXPECT_TRUE(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z));
      EXPECT_GT(d.z, 0.0) << "direction must stay strictly above the surface";
      EXPECT_NEAR(length(d), 1.0, 1e-15);
    }
  }
  EXPECT_THROW(sampleCosinePolar(1.0), std::invalid_argument);
  EXPECT_THROW(sampleCosineHemisphere(0.5, -0.1), std::invalid_argument);
}

}  // namespace
}  // namespace hylios::skin
