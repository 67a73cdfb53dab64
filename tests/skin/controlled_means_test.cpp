// ControlledMeans (skin/core/controlled_means.h): hand values of β, the cross-fitted mean and its
// standard error; exact in expectation at a handful of paths (where a β taken from the paths it
// corrects is biased); the variance it removes; constant control weights; merging and bytes.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "skin/core/controlled_means.h"
#include "skin/core/random.h"
#include "skin/core/statistics.h"

namespace hylios::skin {
namespace {

/// One path of a single quantity.
void addOne(ControlledMeans& c, double t, double u, unsigned fold) { c.add(&t, u, fold); }

TEST(ControlledMeans, HandValues) {
  // Fold 0: (t, u) = (1, 2), (3, 0): mean t 2, mean u 1, Var t 1, Var u 1, Cov −1: β0 = −1.
  // Fold 1: (2, 2), (0, 0.5): mean t 1, mean u 1.25, Var t 1, Var u 0.5625, Cov 0.75: β1 = 4/3.
  // T̂ = [4 − β1·(2 − 2) + 2 − β0·(2.5 − 2)] / 4 = 6.5 / 4 = 1.625.
  // Variance: fold 0 with β1: 1 + 2·(4/3) + (16/9)·1 = 49/9; fold 1 with β0: 1 + 1.5 + 0.5625 =
  // 3.0625; σ = sqrt((2·49/9 + 2·3.0625) / (4·3)) = 1.1907242.
  ControlledMeans c;
  addOne(c, 1, 2, 0);
  addOne(c, 3, 0, 0);
  addOne(c, 2, 2, 1);
  addOne(c, 0, 0.5, 1);
  EXPECT_EQ(c.count(), 4u);
  EXPECT_DOUBLE_EQ(c.beta(0, 0), -1.0);
  EXPECT_DOUBLE_EQ(c.beta(0, 1), 4.0 / 3.0);
  EXPECT_DOUBLE_EQ(c.estimate(0).mean, 1.625);
  EXPECT_NEAR(c.estimate(0).standardError, 1.1907242, 1e-7);
}

TEST(ControlledMeans, EmptyConstantAndOneFoldAreThePlainMean) {
  EXPECT_EQ(ControlledMeans().estimate(0).mean, 0.0);
  EXPECT_EQ(ControlledMeans().estimate(0).standardError, 0.0);
  ControlledMeans constant;  // U = 1 always: β = 0, the plain mean
  RunningStatistic plain;
  for (double t : {0.2, 0.5, 0.1, 0.9, 0.4}) {
    addOne(constant, t, 1.0, static_cast<unsigned>(plain.count() % 2));
    plain.add(t);
  }
  EXPECT_EQ(constant.beta(0, 0), 0.0);
  EXPECT_EQ(constant.beta(0, 1), 0.0);
  EXPECT_DOUBLE_EQ(constant.estimate(0).mean, plain.mean());
  ControlledMeans oneFold;  // no other fold to take β from: the plain mean
  addOne(oneFold, 1, 2, 0);
  addOne(oneFold, 3, 0, 0);
  EXPECT_DOUBLE_EQ(oneFold.estimate(0).mean, 2.0);
  EXPECT_THROW(addOne(oneFold, 1, 1, 2), std::invalid_argument);
}

double standardNormal(Rng& rng) {
  return std::sqrt(-2 * std::log(1 - rng.uniform())) * std::cos(6.283185307179586 * rng.uniform());
}

/// U lognormal with mean 1 (skewed, like an MIS ratio), T = 0.5·U + 0.1·noise: E[T] = 0.5.
void addPath(ControlledMeans& c, Rng& rng, unsigned fold) {
  const double u = std::exp(standardNormal(rng) - 0.5);
  addOne(c, 0.5 * u + 0.1 * standardNormal(rng), u, fold);
}

TEST(ControlledMeans, ExactInExpectationWithAHandfulOfPaths) {
  // 200 000 estimates of 6 paths each (3 per fold), T not linear in U: U lognormal (σ 0.5, mean 1),
  // T = 0.5·U²/e^0.25 + 0.05·noise, E[T] = 0.5. The mean of the estimates is 0.5 within 4 σ (σ
  // from their spread, ≈ 0.00036). A β fitted on the paths it corrects gives 0.452 here (−300 σ,
  // measured with the same model): the cross-fitting is what makes the estimate exact.
  Rng rng(7, 1);
  RunningStatistic estimates;
  for (int replicate = 0; replicate < 200000; ++replicate) {
    ControlledMeans c;
    for (unsigned i = 0; i < 6; ++i) {
      const double u = std::exp(0.5 * standardNormal(rng) - 0.125);
      addOne(c, 0.5 * u * u / std::exp(0.25) + 0.05 * standardNormal(rng), u, i % 2);
    }
    estimates.add(c.estimate(0).mean);
  }
  EXPECT_NEAR(estimates.mean(), 0.5, 4 * estimates.standardError())
      << "σ of the mean " << estimates.standardError();
}

TEST(ControlledMeans, RemovesTheControlWeightsVarianceAndStatesItsError) {
  // 100 000 paths: Var(T) = 0.25·(e − 1) + 0.01 = 0.4396 per path, Var(T − 0.5·U) = 0.01, so the
  // standard error drops about 6.6×; the estimate is within 4 σ of 0.5 and σ is the stated one.
  Rng rng(11, 2);
  ControlledMeans c;
  RunningStatistic plainT;
  for (unsigned i = 0; i < 100000; ++i) addPath(c, rng, i % 2);
  const Estimate e = c.estimate(0);
  EXPECT_NEAR(e.mean, 0.5, 4 * e.standardError);
  EXPECT_NEAR(e.standardError, std::sqrt(0.01 / 100000), 0.05 * std::sqrt(0.01 / 100000));
  EXPECT_NEAR(c.beta(0, 0), 0.5, 0.01);
  EXPECT_NEAR(c.beta(0, 1), 0.5, 0.01);
}

TEST(ControlledMeans, MergesAndTravelsExactly) {
  Rng rng(3, 4);
  ControlledMeans whole, first, second;
  for (unsigned i = 0; i < 1000; ++i) {
    ControlledMeans& part = i < 400 ? first : second;
    Rng copy = rng;
    addPath(whole, copy, i % 2);
    addPath(part, rng, i % 2);
  }
  first.merge(second);
  EXPECT_EQ(first.count(), whole.count());
  EXPECT_NEAR(first.estimate(0).mean, whole.estimate(0).mean, 1e-12);
  std::string bytes;
  whole.appendBytes(bytes);
  std::size_t offset = 0;
  const ControlledMeans back = ControlledMeans::fromBytes(1, bytes, offset);
  EXPECT_EQ(offset, bytes.size());
  EXPECT_EQ(back.estimate(0).mean, whole.estimate(0).mean);
  EXPECT_EQ(back.estimate(0).standardError, whole.estimate(0).standardError);
  bytes.pop_back();
  offset = 0;
  EXPECT_THROW(ControlledMeans::fromBytes(1, bytes, offset), std::invalid_argument);
  EXPECT_THROW(whole.merge(ControlledMeans(2)), std::invalid_argument);
}

TEST(ControlledMeans, QuantitiesShareTheControlWeightAndAdd) {
  // Three quantities of one path: T0, T1 = 1 − T0 scaled by U, and one that is always 0. The
  // estimates are linear in the scores (β too), so T̂0 + T̂1 is the estimate of their sum, U's
  // own (1 exactly); the zero quantity is 0 ± 0.
  Rng rng(9, 5);
  ControlledMeans c(3);
  for (unsigned i = 0; i < 5000; ++i) {
    const double u = std::exp(0.5 * standardNormal(rng) - 0.125);
    const double share = rng.uniform();
    const double t[3] = {share * u, (1 - share) * u, 0.0};
    c.add(t, u, i % 2);
  }
  EXPECT_NEAR(c.estimate(0).mean + c.estimate(1).mean, 1.0, 1e-12);
  EXPECT_NEAR(c.estimate(0).mean, 0.5, 4 * c.estimate(0).standardError);
  EXPECT_EQ(c.estimate(2).mean, 0.0);
  EXPECT_EQ(c.estimate(2).standardError, 0.0);
}

}  // namespace
}  // namespace hylios::skin
