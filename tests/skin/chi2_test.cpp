// The chi-square helper itself: p-values against tabulated quantiles, pooling, and that it
// rejects a sample drawn from a different density (so the sampler tests cannot pass vacuously).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "skin/core/constants.h"
#include "skin/core/random.h"
#include "skin/sampling/rayleigh_sampling.h"
#include "tests/support/chi2.h"

using hylios::kPi;

namespace hylios::test {
namespace {

TEST(Chi2Helper, PValuesMatchTabulatedQuantiles) {
  // Upper 5 % and 1 % points of the chi-square law (any statistics table):
  // dof 1: 3.841, 6.635; dof 2: 5.991; dof 10: 18.307, 23.209; dof 100: 124.342.
  EXPECT_NEAR(chi2SurvivalProbability(3.841459, 1), 0.05, 1e-6);
  EXPECT_NEAR(chi2SurvivalProbability(6.634897, 1), 0.01, 1e-6);
  EXPECT_NEAR(chi2SurvivalProbability(5.991465, 2), 0.05, 1e-6);
  EXPECT_NEAR(chi2SurvivalProbability(18.307038, 10), 0.05, 1e-6);
  EXPECT_NEAR(chi2SurvivalProbability(23.209251, 10), 0.01, 1e-6);
  EXPECT_NEAR(chi2SurvivalProbability(124.342113, 100), 0.05, 1e-6);
  // dof 2 has Q = exp(−x/2) exactly.
  EXPECT_NEAR(chi2SurvivalProbability(3.0, 2), std::exp(-1.5), 1e-14);
  EXPECT_DOUBLE_EQ(chi2SurvivalProbability(0.0, 7), 1.0);
}

TEST(Chi2Helper, IntegratesClosedForms) {
  EXPECT_NEAR(integrate([](double x) { return std::sin(x); }, 0.0, kPi), 2.0, 1e-11);
  // A peak of width 1e-4 between the first nodes is still found: ∫ of a normalised Lorentzian.
  const double w = 1e-4;
  const auto lorentz = [w](double x) { return w / (kPi * (x * x + w * w)); };
  EXPECT_NEAR(integrate(lorentz, -0.3, 0.7), (std::atan(0.7 / w) + std::atan(0.3 / w)) / kPi, 1e-9);
}

TEST(Chi2Helper, PoolsSmallBinsAndFlagsImpossibleSamples) {
  // Expected 2, 2, 2, 94: the three small bins pool into one cell of 6 -> 2 cells, dof 1.
  const Chi2Result pooled = chi2FromCounts({2, 1, 3, 94}, {2, 2, 2, 94});
  EXPECT_EQ(pooled.degreesOfFreedom, 1);
  EXPECT_TRUE(pooled.problem.empty());
  EXPECT_NEAR(pooled.statistic, 0.0, 1e-12);
  // A sample where the density is zero fails regardless of the statistic.
  const Chi2Result impossible = chi2FromCounts({1, 49, 50}, {0, 50, 50});
  EXPECT_FALSE(impossible.problem.empty());
  EXPECT_FALSE(chi2Accepts(impossible));
  // Expected counts that do not add up to the sample size (an unnormalised density) fail.
  const Chi2Result unnormalised = chi2FromCounts({50, 50}, {60, 60});
  EXPECT_FALSE(chi2Accepts(unnormalised));
}

TEST(Chi2Helper, RejectsRayleighSamplesAgainstUniformCosine) {
  // 1e5 Rayleigh cosines tested against the isotropic density 1/2 on [−1, 1]. The two differ by
  // (3/8)(1 + μ²) − 1/2, up to ±1/8; with 20 bins and 5000 expected per bin the statistic is
  // of order 1e3, so p is astronomically small. The same samples pass against their own density.
  skin::Rng rng(7);
  std::vector<double> mus(100000);
  for (double& mu : mus) mu = skin::sampleRayleighCos(rng.uniform());
  const auto edges = uniformEdges(-1.0, 1.0, 20);
  const Chi2Result wrong = chi2Test1D(
      mus, [](double) { return 0.5; }, edges);
  EXPECT_FALSE(chi2Accepts(wrong));
  EXPECT_LT(wrong.pValue, 1e-10);
  EXPECT_TRUE(chi2Accepts(chi2Test1D(mus, skin::rayleighCosDensity, edges)));
}

TEST(Chi2Helper, RejectsASlightlyWrongDensity) {
  // Uniform samples on [0, 1) against the density 0.95 + 0.1x (5 % tilt): with 1e6 samples and
  // 20 bins each bin's relative bias (up to 5 %) is ~50 standard errors (1/sqrt(5e4) = 0.45 %).
  skin::Rng rng(11);
  std::vector<double> xs(1000000);
  for (double& x : xs) x = rng.uniform();
  const auto edges = uniformEdges(0.0, 1.0, 20);
  EXPECT_FALSE(chi2Accepts(chi2Test1D(
      xs, [](double x) { return 0.95 + 0.1 * x; }, edges)));
  EXPECT_TRUE(chi2Accepts(chi2Test1D(
      xs, [](double) { return 1.0; }, edges)));
}

TEST(Chi2Helper, TwoDimensionalTestAcceptsAndRejects) {
  skin::Rng rng(3);
  std::vector<double> xs(200000), ys(200000);
  for (std::size_t i = 0; i < xs.size(); ++i) {
    xs[i] = std::sqrt(rng.uniform());  // density 2x on [0, 1)
    ys[i] = rng.uniform();
  }
  const auto edges = uniformEdges(0.0, 1.0, 10);
  EXPECT_TRUE(chi2Accepts(chi2Test2D(
      xs, ys, [](double x, double) { return 2.0 * x; }, edges, edges)));
  EXPECT_FALSE(chi2Accepts(chi2Test2D(
      xs, ys, [](double, double y) { return 2.0 * y; }, edges, edges)));
}

}  // namespace
}  // namespace hylios::test
