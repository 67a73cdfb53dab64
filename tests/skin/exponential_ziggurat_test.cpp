// The ziggurat's standard exponential against e^{−x} (chi-square over the body, and the tail
// beyond r on its own: its excess over r is again exponential), and its table: every layer's area
// is v, the widths fall from r to 0.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "skin/sampling/exponential_ziggurat.h"
#include "tests/support/chi2.h"

namespace hylios::skin {
namespace {

const auto kExponentialDensity = [](double x) { return x >= 0 ? std::exp(-x) : 0.0; };

TEST(ExponentialZiggurat, EveryLayerHasTheSameArea) {
  const ExponentialZiggurat& z = kExponentialZiggurat;
  const double v = ExponentialZiggurat::kLayerArea, r = ExponentialZiggurat::kTailStart;
  // Layer 0: the rectangle under e^{−r} up to r plus the tail, and its span x_0·e^{−r}.
  EXPECT_NEAR(r * std::exp(-r) + std::exp(-r), v, 1e-15);
  EXPECT_NEAR(z.width[0] * std::exp(-r), v, 1e-15);
  EXPECT_EQ(z.width[1], r);
  EXPECT_EQ(z.width[ExponentialZiggurat::kLayers], 0.0);
  for (int i = 1; i < ExponentialZiggurat::kLayers; ++i) {
    EXPECT_GT(z.width[i], z.width[i + 1]) << i;
    EXPECT_NEAR(z.width[i] * (z.height[i + 1] - z.height[i]), v, 1e-13 * v) << i;
  }
}

TEST(ExponentialZiggurat, MatchesTheExponentialDensity) {
  Rng rng(26, 1);
  std::vector<double> samples(1000000);
  for (double& x : samples) {
    x = sampleStandardExponential(rng);
    ASSERT_TRUE(std::isfinite(x));
    ASSERT_GE(x, 0.0);
  }
  // 60 bins of equal probability over [0, 12] (mass beyond: 6e−6, the outside bin).
  const auto edges = test::equalProbabilityEdges(kExponentialDensity, 0.0, 12.0, 60);
  EXPECT_TRUE(test::chi2Accepts(test::chi2Test1D(samples, kExponentialDensity, edges)));
  // Finer bins over the layers' wedges near 0, where x_256 = 0 closes the table.
  const auto nearZero = test::equalProbabilityEdges(kExponentialDensity, 0.0, 0.2, 40);
  EXPECT_TRUE(test::chi2Accepts(test::chi2Test1D(samples, kExponentialDensity, nearZero)));
}

TEST(ExponentialZiggurat, TailBeyondRIsAnExponentialShiftedByR) {
  // The tail (mass e^{−r} ≈ 4.5e−4) drawn by memorylessness: x − r given x > r is e^{−x} again.
  Rng rng(26, 2);
  const double r = ExponentialZiggurat::kTailStart;
  std::vector<double> excess;
  for (int i = 0; i < 40000000 && excess.size() < 10000; ++i) {
    const double x = sampleStandardExponential(rng);
    if (x > r) excess.push_back(x - r);
  }
  ASSERT_EQ(excess.size(), 10000u);
  const auto edges = test::equalProbabilityEdges(kExponentialDensity, 0.0, 8.0, 20);
  EXPECT_TRUE(test::chi2Accepts(test::chi2Test1D(excess, kExponentialDensity, edges)));
}

}  // namespace
}  // namespace hylios::skin
