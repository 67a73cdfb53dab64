// The eight-lane closed forms (skin/core/float_lanes.h): laneLog to 2 ulp over the normal floats
// and at hand values, laneSinCosTwoPi to 5e−7 over [0, 1] and at the quarter turns, and the
// lane helpers (select, copySign, permute, gather) against hand values.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "skin/core/constants.h"
#include "skin/core/float_lanes.h"

namespace hylios::skin::lanes {
namespace {

// ulps between a float result and the exact value (the spacing of floats at the exact value).
double ulpsFromExact(float result, double exact) {
  const float nearest = static_cast<float>(exact);
  const double spacing =
      std::nextafter(std::fabs(nearest), std::numeric_limits<float>::infinity()) -
      std::fabs(nearest);
  return std::fabs(static_cast<double>(result) - exact) / spacing;
}

Floats lanesOf(const float* eight) { return load(eight); }

TEST(FloatLanes, LogAtHandValues) {
  const float x[kLanes] = {1.0f, 2.0f, 0.5f, 0x1.0p-24f, 10.0f, 0.1f, 1.5f, 0.75f};
  // log 2 = 0.69314718, log 2^-24 = -16.635532, log 10 = 2.3025851, log 0.1 = -2.3025851,
  // log 1.5 = 0.40546511, log 0.75 = -0.28768207.
  const double expected[kLanes] = {0.0,       0.69314718, -0.69314718, -16.635532,
                                   2.3025851, -2.3025851, 0.40546511,  -0.28768207};
  const Floats result = laneLog(lanesOf(x));
  EXPECT_EQ(result[0], 0.0f);
  for (int l = 1; l < kLanes; ++l)
    EXPECT_NEAR(result[l], expected[l], 2e-7 * std::fabs(expected[l])) << "x = " << x[l];
}

TEST(FloatLanes, LogWithinTwoUlpOverTheNormalFloats) {
  // Every 97th float from the smallest normal to the largest finite one (about 22 million).
  std::uint32_t bits = 0x00800000u;
  double worst = 0;
  float worstX = 0;
  while (bits < 0x7f800000u) {
    float x[kLanes];
    for (float& v : x) {
      const std::uint32_t b = bits < 0x7f800000u ? bits : 0x7f7fffffu;
      __builtin_memcpy(&v, &b, sizeof v);
      bits += 97;
    }
    const Floats result = laneLog(lanesOf(x));
    for (int l = 0; l < kLanes; ++l) {
      if (x[l] == 1.0f) continue;  // log 1 = 0 exactly (tested above); no ulp scale there
      const double error = ulpsFromExact(result[l], std::log(static_cast<double>(x[l])));
      if (error > worst) worst = error, worstX = x[l];
    }
  }
  EXPECT_LE(worst, 2.0) << "worst at x = " << worstX;
}

TEST(FloatLanes, SinCosAtQuarterTurns) {
  // u = 0: angle -π; 1/4: -π/2; 1/2: 0; 3/4: π/2; 1: π.
  const float u[kLanes] = {0.0f, 0.25f, 0.5f, 0.75f, 1.0f, 0.5f, 0.5f, 0.5f};
  const double sinExpected[5] = {0, -1, 0, 1, 0}, cosExpected[5] = {-1, 0, 1, 0, -1};
  Floats s, c;
  laneSinCosTwoPi(lanesOf(u), s, c);
  for (int l = 0; l < 5; ++l) {
    EXPECT_NEAR(s[l], sinExpected[l], 4e-7) << "u = " << u[l];
    EXPECT_NEAR(c[l], cosExpected[l], 4e-7) << "u = " << u[l];
  }
}

TEST(FloatLanes, SinCosWithin5e7OverTheUnitInterval) {
  double worst = 0;
  for (int i = 0; i <= (1 << 20); i += kLanes) {
    float u[kLanes];
    for (int l = 0; l < kLanes; ++l)
      u[l] = static_cast<float>(std::min(i + l, 1 << 20)) * 0x1.0p-20f;
    Floats s, c;
    laneSinCosTwoPi(lanesOf(u), s, c);
    for (int l = 0; l < kLanes; ++l) {
      const double angle = 2 * kPi * (static_cast<double>(u[l]) - 0.5);
      worst =
          std::max({worst, std::fabs(s[l] - std::sin(angle)), std::fabs(c[l] - std::cos(angle))});
    }
  }
  EXPECT_LE(worst, 5e-7);  // measured 4.1e-7: pi and the angle rounded to float
}

TEST(FloatLanes, HelpersAtHandValues) {
  const float a[kLanes] = {1, -2, 3, -4, 5, -6, 7, -8};
  const float b[kLanes] = {-1, 2, -3, 4, 0, 0, -0.0f, 1};
  const Floats x = lanesOf(a), y = lanesOf(b);
  const Floats signed_ = copySign(x, y);
  const Floats chosen = select(x > 0.0f, x, y);
  const Floats magnitude = abs(x);
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(signed_[l], std::copysign(a[l], b[l])) << l;
    EXPECT_EQ(chosen[l], a[l] > 0 ? a[l] : b[l]) << l;
    EXPECT_EQ(magnitude[l], std::fabs(a[l])) << l;
  }
  const Ints index = {7, 0, 3, 3, 1, 6, 2, 5};
  const Floats permuted = permute(a, index), gathered = gather(a, index);
  const std::int32_t table[kLanes] = {10, 11, 12, 13, 14, 15, 16, 17};
  const Ints permutedInt = permuteInt(table, index), gatheredInt = gatherInt(table, index);
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(permuted[l], a[index[l]]);
    EXPECT_EQ(gathered[l], a[index[l]]);
    EXPECT_EQ(permutedInt[l], 10 + index[l]);
    EXPECT_EQ(gatheredInt[l], 10 + index[l]);
  }
  EXPECT_TRUE(any(x > 6.0f));
  EXPECT_FALSE(any(x > 7.0f));
}

}  // namespace
}  // namespace hylios::skin::lanes
