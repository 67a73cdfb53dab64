// θo(λ) of Algorithm 2 (Sec. 4.2.2): 5° to 780 nm, linear to 0 at 1400 nm, 0 beyond.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "skin/core/constants.h"
#include "skin/melanosome_scattering_angle.h"

using hylios::kPi;

namespace hylios::skin {
namespace {

constexpr double kDeg = kPi / 180.0;

TEST(MelanosomeScatteringAngle, FiveDegreesThroughTheVisible) {
  EXPECT_DOUBLE_EQ(melanosomeMeanScatteringAngleRad(250.0), 5.0 * kDeg);
  EXPECT_DOUBLE_EQ(melanosomeMeanScatteringAngleRad(700.0), 5.0 * kDeg);
  EXPECT_DOUBLE_EQ(melanosomeMeanScatteringAngleRad(780.0), 5.0 * kDeg);
}

TEST(MelanosomeScatteringAngle, LinearFalloffAcrossTheNearInfrared) {
  // 1090 nm is halfway from 780 to 1400 nm: (1400 − 1090)/(1400 − 780) = 310/620 = 0.5 -> 2.5°.
  EXPECT_NEAR(melanosomeMeanScatteringAngleRad(1090.0), 2.5 * kDeg, 1e-15);
  // 1245 nm: 155/620 = 0.25 -> 1.25°.
  EXPECT_NEAR(melanosomeMeanScatteringAngleRad(1245.0), 1.25 * kDeg, 1e-15);
  EXPECT_DOUBLE_EQ(melanosomeMeanScatteringAngleRad(1400.0), 0.0);
}

TEST(MelanosomeScatteringAngle, ZeroBeyond1400nm) {
  EXPECT_EQ(melanosomeMeanScatteringAngleRad(2000.0), 0.0);
  EXPECT_EQ(melanosomeMeanScatteringAngleRad(2500.0), 0.0);
}

TEST(MelanosomeScatteringAngle, RejectsBadWavelengths) {
  EXPECT_THROW(melanosomeMeanScatteringAngleRad(0.0), std::invalid_argument);
  EXPECT_THROW(melanosomeMeanScatteringAngleRad(NAN), std::invalid_argument);
}

}  // namespace
}  // namespace hylios::skin
