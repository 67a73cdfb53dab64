// RunningStatistic and Histogram: hand-computed means and standard errors, merging, errors.
#include <gtest/gtest.h>

#include <cmath>

#include "skin/core/random.h"
#include "skin/core/statistics.h"

namespace hylios::skin {
namespace {

TEST(StatisticsTest, MeanAndStandardErrorByHand) {
  // Scores 1, 0, 1, 1: mean 0.75, E[x^2] = 0.75, variance 0.75 - 0.5625 = 0.1875,
  // stderr = sqrt(0.1875 / 3) = 0.25.
  RunningStatistic s;
  for (double x : {1.0, 0.0, 1.0, 1.0}) s.add(x);
  EXPECT_EQ(s.count(), 4u);
  EXPECT_DOUBLE_EQ(s.mean(), 0.75);
  EXPECT_DOUBLE_EQ(s.standardError(), 0.25);
  // Real weights 0.5, 1.5: mean 1, E[x^2] = 1.25, variance 0.25, stderr sqrt(0.25 / 1) = 0.5.
  RunningStatistic w;
  w.add(0.5);
  w.add(1.5);
  EXPECT_DOUBLE_EQ(w.mean(), 1.0);
  EXPECT_DOUBLE_EQ(w.standardError(), 0.5);
}

TEST(StatisticsTest, EmptyAndSingleAreFinite) {
  RunningStatistic s;
  EXPECT_EQ(s.mean(), 0.0);
  EXPECT_EQ(s.standardError(), 0.0);
  s.add(0.3);
  EXPECT_DOUBLE_EQ(s.mean(), 0.3);
  EXPECT_EQ(s.standardError(), 0.0);
  RunningStatistic constant;
  for (int i = 0; i < 10; ++i) constant.add(0.1);
  EXPECT_FALSE(std::isnan(constant.standardError()));
  EXPECT_NEAR(constant.standardError(), 0.0, 1e-9);
}

TEST(StatisticsTest, AddZerosAndMergeEqualSequentialAdds) {
  RunningStatistic all, first, second;
  Rng rng(1);
  for (int i = 0; i < 1000; ++i) {
    const double x = rng.uniform() < 0.3 ? rng.uniform() : 0.0;
    all.add(x);
    (i < 400 ? first : second).add(x);
  }
  RunningStatistic merged = first;
  merged.merge(second);
  EXPECT_EQ(merged.count(), all.count());
  EXPECT_NEAR(merged.mean(), all.mean(), 1e-15);
  EXPECT_NEAR(merged.standardError(), all.standardError(), 1e-15);
  RunningStatistic zeros;
  zeros.add(1.0);
  zeros.addZeros(3);
  EXPECT_DOUBLE_EQ(zeros.mean(), 0.25);
  EXPECT_DOUBLE_EQ(zeros.standardError(), 0.25);  // scores 1, 0, 0, 0 mirror the first test
}

TEST(StatisticsTest, StandardErrorMatchesBinomialTheory) {
  // Bernoulli(0.2) scores, N = 10000: stderr ~ sqrt(0.2 * 0.8 / N) = 0.004 (within 5 %).
  RunningStatistic s;
  Rng rng(42);
  for (int i = 0; i < 10000; ++i) s.add(rng.uniform() < 0.2 ? 1.0 : 0.0);
  EXPECT_NEAR(s.standardError(), 0.004, 0.0002);
  EXPECT_NEAR(s.mean(), 0.2, 4 * 0.004);
}

TEST(HistogramTest, BinsUnderflowOverflowAndEstimates) {
  Histogram h(0.0, 1.0, 4);
  EXPECT_EQ(h.binCount(), 4u);
  EXPECT_DOUBLE_EQ(h.binWidth(), 0.25);
  EXPECT_DOUBLE_EQ(h.binCentre(1), 0.375);
  EXPECT_EQ(h.binOf(0.0), 0u);
  EXPECT_EQ(h.binOf(0.26), 1u);
  EXPECT_EQ(h.binOf(std::nextafter(1.0, 0.0)), 3u);
  EXPECT_EQ(h.binOf(-0.1), h.underflowIndex());
  EXPECT_EQ(h.binOf(1.0), h.overflowIndex());
  EXPECT_EQ(h.binOf(std::nan("")), h.overflowIndex());
  // Four packets: two score 1 in bin 0, one scores 0.5 in overflow, one scores nothing.
  h.add(0.1, 1.0);
  h.add(0.2, 1.0);
  h.add(3.0, 0.5);
  h.countPacket(4);
  const Estimate bin0 = h.estimate(0);
  EXPECT_DOUBLE_EQ(bin0.mean, 0.5);  // scores 1, 1, 0, 0: variance 0.25, stderr sqrt(0.25 / 3)
  EXPECT_DOUBLE_EQ(bin0.standardError, std::sqrt(0.25 / 3.0));
  EXPECT_DOUBLE_EQ(h.estimate(h.overflowIndex()).mean, 0.125);
  EXPECT_EQ(h.estimate(2).mean, 0.0);
}

TEST(HistogramTest, MergeAddsAndRejectsDifferentBins) {
  Histogram a(0.0, 2.0, 8), b(0.0, 2.0, 8);
  a.add(0.5, 1.0);
  a.countPacket();
  b.add(0.5, 1.0);
  b.add(1.5, 2.0);
  b.countPacket(2);
  a.merge(b);
  EXPECT_EQ(a.packets(), 3u);
  EXPECT_DOUBLE_EQ(a.estimate(a.binOf(0.5)).mean, 2.0 / 3.0);
  Histogram other(0.0, 1.0, 8);
  EXPECT_THROW(a.merge(other), std::invalid_argument);
  EXPECT_THROW(Histogram(1.0, 1.0, 3), std::invalid_argument);
  EXPECT_THROW(Histogram(0.0, 1.0, 0), std::invalid_argument);
}

}  // namespace
}  // namespace hylios::skin
