// Prolate spheroid geometry (Eq. 7): hand values, the sphere limit, and degenerate inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "skin/core/constants.h"
#include "skin/spheroid.h"

using hylios::kPi;

namespace hylios::skin {
namespace {

TEST(Spheroid, SurfaceToVolumeHandValueForLightMelanosome) {
  // a = 0.085 µm, c = 0.205 µm (half of Table 1's 0.17 × 0.41 µm).
  // b² = 1 − (0.085/0.205)² = 1 − 0.171921 = 0.828079, b = 0.909988
  // arcsin(b) = 1.143268 rad, arcsin(b)/b = 1.256341, a/c = 0.414634
  // S/V = 3/(2·0.085) · (0.414634 + 1.256341) = 17.647059 · 1.670975 = 29.4878 µm⁻¹
  const ProlateSpheroid s{0.085, 0.205};
  EXPECT_NEAR(eccentricity(s), 0.909988, 1e-6);
  EXPECT_NEAR(surfaceToVolumeRatio(s), 29.4878, 1e-4);
  // Cross-check against S and V computed separately: S = 0.182946 µm², V = 0.00620412 µm³.
  EXPECT_NEAR(surfaceArea(s), 0.182946, 1e-6);
  EXPECT_NEAR(volume(s), 0.00620412, 1e-8);
  EXPECT_NEAR(surfaceArea(s) / volume(s), surfaceToVolumeRatio(s), 1e-9);
}

TEST(Spheroid, SphereLimitIsThreeOverRadius) {
  EXPECT_DOUBLE_EQ(surfaceToVolumeRatio({0.2, 0.2}), 3.0 / 0.2);
  EXPECT_DOUBLE_EQ(surfaceArea({0.2, 0.2}), 4.0 * kPi * 0.04);
  // Approaching a = c from below: continuous, no 0/0, and within O(b²) of 3/a.
  for (double gap : {1e-3, 1e-6, 1e-9, 1e-12, 1e-15}) {
    const ProlateSpheroid s{1.0 - gap, 1.0};
    const double sv = surfaceToVolumeRatio(s);
    ASSERT_TRUE(std::isfinite(sv)) << "gap " << gap;
    EXPECT_NEAR(sv, 3.0 / (1.0 - gap), 3.0 * gap) << "gap " << gap;
  }
}

TEST(Spheroid, ArcsinOverArgumentSeriesJoinsClosedForm) {
  EXPECT_DOUBLE_EQ(arcsinOverArgument(0.0), 1.0);
  const double justBelow = 0.999e-3;  // series branch
  const double justAbove = 1.001e-3;  // closed form
  EXPECT_NEAR(arcsinOverArgument(justBelow), std::asin(justBelow) / justBelow, 1e-15);
  EXPECT_NEAR(arcsinOverArgument(justAbove), arcsinOverArgument(justBelow), 1e-9);
  EXPECT_DOUBLE_EQ(arcsinOverArgument(1.0), kPi / 2);
  EXPECT_THROW(arcsinOverArgument(1.5), std::invalid_argument);
}

TEST(Spheroid, CrossSectionsAndProjectedArea) {
  const ProlateSpheroid s{0.085, 0.205};
  EXPECT_DOUBLE_EQ(crossSectionNormalToMajorAxis(s), kPi * 0.085 * 0.085);
  EXPECT_DOUBLE_EQ(crossSectionContainingMajorAxis(s), kPi * 0.085 * 0.205);
  EXPECT_NEAR(projectedArea(s, 0.0), crossSectionNormalToMajorAxis(s), 1e-15);
  EXPECT_NEAR(projectedArea(s, kPi / 2), crossSectionContainingMajorAxis(s), 1e-15);
  // α = 60°: π·0.085·sqrt(0.085²·0.25 + 0.205²·0.75) = π·0.085·0.182551 = 0.0487477
  EXPECT_NEAR(projectedArea(s, kPi / 3), 0.0487477, 1e-7);
}

TEST(Spheroid, RejectsOblateZeroAndNonFinite) {
  EXPECT_THROW(surfaceToVolumeRatio({0.3, 0.2}), std::invalid_argument);
  EXPECT_THROW(surfaceToVolumeRatio({0.0, 0.2}), std::invalid_argument);
  EXPECT_THROW(surfaceToVolumeRatio({-0.1, 0.2}), std::invalid_argument);
  EXPECT_THROW(surfaceToVolumeRatio({0.1, std::nan("")}), std::invalid_argument);
  EXPECT_THROW(projectedArea({0.1, 0.2}, INFINITY), std::invalid_argument);
}

}  // namespace
}  // namespace hylios::skin
