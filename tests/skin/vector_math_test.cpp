// vectorExp and vectorLog (skin/core/vector_math.h) against the C library: ulp error over their
// domains, the special values, and a loop of calls (the form the spectral walk vectorises).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "skin/core/random.h"
#include "skin/core/vector_math.h"

using namespace hylios::skin;

namespace {

/// |a − b| in units of the last place of b (long double reference).
double ulps(double a, long double reference) {
  const double b = static_cast<double>(reference);
  const double ulp = std::fabs(std::nextafter(b, INFINITY) - b);
  return static_cast<double>(std::fabs(static_cast<long double>(a) - reference)) / ulp;
}

TEST(VectorMath, ExpWithinThreeUlpOverItsRange) {
  Rng rng(7);
  double worst = 0;
  for (int i = 0; i < 2000000; ++i) {
    const double u = rng.uniform();
    const double x = i % 2 ? -708.0 + 1417.0 * u : (u - 0.5) * 2.0;
    worst = std::fmax(worst, ulps(vectorExp(x), std::exp(static_cast<long double>(x))));
  }
  EXPECT_LE(worst, 3.0);
}

TEST(VectorMath, ExpSpecialValues) {
  EXPECT_EQ(vectorExp(0.0), 1.0);
  EXPECT_EQ(vectorExp(-708.5), 0.0);
  EXPECT_EQ(vectorExp(-INFINITY), 0.0);
  EXPECT_TRUE(std::isfinite(vectorExp(1e6)));
  EXPECT_TRUE(std::isnan(vectorExp(std::numeric_limits<double>::quiet_NaN())));
}

TEST(VectorMath, LogWithinTwoUlpOverAllPositiveDoubles) {
  Rng rng(8);
  double worst = 0;
  for (int i = 0; i < 2000000; ++i) {
    // Random bit patterns (every exponent, subnormals included) and values near 1.
    std::uint64_t bits = rng.nextU64() & 0x7fefffffffffffffULL;
    double x;
    std::memcpy(&x, &bits, sizeof x);
    if (i % 3 == 0) x = 1.0 + (rng.uniform() - 0.5) * 1e-3;
    if (!(x > 0)) continue;
    const long double reference = std::log(static_cast<long double>(x));
    if (reference == 0) {
      EXPECT_EQ(vectorLog(x), 0.0);
      continue;
    }
    worst = std::fmax(worst, ulps(vectorLog(x), reference));
  }
  EXPECT_LE(worst, 2.0);
}

TEST(VectorMath, LogSpecialValues) {
  EXPECT_EQ(vectorLog(1.0), 0.0);
  EXPECT_EQ(vectorLog(0.0), -INFINITY);
  EXPECT_EQ(vectorLog(INFINITY), INFINITY);
  EXPECT_TRUE(std::isnan(vectorLog(-1.0)));
  EXPECT_TRUE(std::isnan(vectorLog(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_NEAR(vectorLog(4.9406564584124654e-324), -744.44007192138126, 1e-12);
}

TEST(VectorMath, LoopsGiveTheScalarValues) {
  std::vector<double> x(37), e(37), l(37);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = -20.0 + 1.3 * static_cast<double>(i);
  for (std::size_t i = 0; i < x.size(); ++i) e[i] = vectorExp(x[i]);
  for (std::size_t i = 0; i < x.size(); ++i) l[i] = vectorLog(e[i]);
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_NEAR(e[i], std::exp(x[i]), 4e-16 * std::exp(x[i]));
    EXPECT_NEAR(l[i], x[i], 1e-14 * std::fmax(1.0, std::fabs(x[i])));
  }
}

}  // namespace
