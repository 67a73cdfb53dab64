// Henyey–Greenstein scattering in lanes (skin/sampling/henyey_greenstein_lanes.h): the cosine by
// chi-square against henyeyGreensteinDensity for g = 0, 0.5, 0.9, −0.7, 0.99; sinθ; and the turned
// direction: unit length, at angle θ from the old one, with a uniform azimuth (chi-square) about
// axes pointing up and down.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "skin/core/constants.h"
#include "skin/core/lane_random.h"
#include "skin/sampling/henyey_greenstein.h"
#include "skin/sampling/henyey_greenstein_lanes.h"
#include "tests/support/chi2.h"

namespace hylios::skin::lanes {
namespace {

HenyeyGreensteinLanes constantsFor(float g) {
  return {splat(g), splat(1 - g), splat(2 * g), splat(2 * (1 - g) * (1 - g)),
          splat(2 * (1 + g) * (1 + g))};
}

LaneRng seededLanes(std::uint64_t seed) {
  LaneRng rng;
  for (int l = 0; l < kLanes; ++l) {
    Rng packet(seed, 0, static_cast<std::uint64_t>(l));
    rng.seedLane(l, packet);
  }
  return rng;
}

class HenyeyGreensteinLanesChi2 : public ::testing::TestWithParam<double> {};

TEST_P(HenyeyGreensteinLanesChi2, CosineMatchesDensity) {
  const double g = GetParam();
  const HenyeyGreensteinLanes constants = constantsFor(static_cast<float>(g));
  LaneRng rng = seededLanes(21);
  std::vector<double> mus;
  for (int i = 0; i < 125000; ++i) {  // 10^6 samples
    Floats cosTheta, sinTheta;
    sampleHenyeyGreensteinLanes(constants, rng.uniform(), cosTheta, sinTheta);
    for (int l = 0; l < kLanes; ++l) {
      ASSERT_GE(cosTheta[l], -1.0f);
      ASSERT_LE(cosTheta[l], 1.0f);
      ASSERT_NEAR(cosTheta[l] * cosTheta[l] + sinTheta[l] * sinTheta[l], 1.0, 1e-6);
      ASSERT_GE(sinTheta[l], 0.0f);
      mus.push_back(cosTheta[l]);
    }
  }
  // The density of the float g the lanes use (0.9f is not 0.9).
  const double gUsed = static_cast<float>(g);
  const auto density = [gUsed](double mu) { return henyeyGreensteinDensity(gUsed, mu); };
  EXPECT_TRUE(test::chi2Accepts(
      test::chi2Test1D(mus, density, test::equalProbabilityEdges(density, -1.0, 1.0, 50))))
      << "g = " << g;
  // Mean cosine g: Var[μ] <= 1, so se <= 1e-3; 4σ.
  EXPECT_NEAR(test::mean(mus), gUsed, 4e-3) << "g = " << g;
}

INSTANTIATE_TEST_SUITE_P(AsymmetryValues, HenyeyGreensteinLanesChi2,
                         ::testing::Values(0.0, 0.5, 0.9, -0.7, 0.99));

TEST(HenyeyGreensteinLanes, TurnKeepsUnitLengthAndAngle) {
  LaneRng rng = seededLanes(5);
  Floats x = splat(0.6f), y = splat(0.0f), z = splat(-0.8f);
  for (int step = 0; step < 10000; ++step) {
    const Floats x0 = x, y0 = y, z0 = z;
    Floats cosTheta, sinTheta;
    sampleHenyeyGreensteinLanes(constantsFor(0.8f), rng.uniform(), cosTheta, sinTheta);
    turnLanes(x, y, z, cosTheta, sinTheta, rng.uniform());
    for (int l = 0; l < kLanes; ++l) {
      ASSERT_NEAR(x[l] * x[l] + y[l] * y[l] + z[l] * z[l], 1.0, 2e-6) << "step " << step;
      ASSERT_NEAR(x[l] * x0[l] + y[l] * y0[l] + z[l] * z0[l], cosTheta[l], 2e-6) << "step " << step;
    }
  }
}

// The azimuth about the axis ±z is atan2(y, x) up to a fixed rotation: uniform on (−π, π].
TEST(HenyeyGreensteinLanes, AzimuthIsUniformAboutUpAndDownAxes) {
  for (const float axisZ : {1.0f, -1.0f}) {
    LaneRng rng = seededLanes(axisZ > 0 ? 6 : 7);
    std::vector<double> azimuths;
    for (int i = 0; i < 50000; ++i) {
      Floats x = Floats{}, y = Floats{}, z = splat(axisZ);
      const Floats cosTheta = splat(0.3f), sinTheta = splat(std::sqrt(1 - 0.09f));
      turnLanes(x, y, z, cosTheta, sinTheta, rng.uniform());
      for (int l = 0; l < kLanes; ++l) azimuths.push_back(std::atan2(y[l], x[l]));
    }
    const auto density = [](double) { return 1.0 / (2 * kPi); };
    EXPECT_TRUE(
        test::chi2Accepts(test::chi2Test1D(azimuths, density, test::uniformEdges(-kPi, kPi, 64))))
        << "axis z = " << axisZ;
  }
}

}  // namespace
}  // namespace hylios::skin::lanes
