// The noise measure of renderer/image/render_noise.h on hand-made images with known answers.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/image/render_noise.h"

using namespace hylios;

namespace {
NoiseImage image(int width, int height, std::vector<std::string> groups,
                 std::vector<double> values) {
  NoiseImage n;
  n.width = width;
  n.height = height;
  n.groups = std::move(groups);
  n.values = std::move(values);
  return n;
}
}  // namespace

TEST(RenderNoise, RelativeNoiseIsTheMedianOfHalfDifferencesOverTheMean) {
  // Pixel values (a, b): (1, 3) → |a − b|/√2/2 = 0.7071; (2, 2) → 0; (4, 5) → 0.7071/4.5 = 0.1571.
  const NoiseImage a = image(3, 1, {"band x"}, {1, 2, 4});
  const NoiseImage b = image(3, 1, {"band x"}, {3, 2, 5});
  const auto noise = measureNoise(a, b, {});
  ASSERT_EQ(noise.size(), 1u);
  EXPECT_EQ(noise[0].pixels, 3u);
  EXPECT_NEAR(noise[0].medianRelative, 1.0 / std::sqrt(2.0) / 4.5, 1e-15);
  // The mask keeps pixels 0 and 2 only: the median of 0.7071 and 0.1571 is their mean.
  const auto masked = measureNoise(a, b, {true, false, true});
  EXPECT_EQ(masked[0].pixels, 2u);
  EXPECT_NEAR(masked[0].medianRelative, 0.5 * (1.0 / std::sqrt(2.0) + 1.0 / std::sqrt(2.0) / 4.5),
              1e-15);
  EXPECT_NEAR(worstNoise(noise), noise[0].medianRelative, 0);
}

TEST(RenderNoise, UnequalHalvesAreWeighedByTheirShares) {
  // A film's halves a = 1, b = 4 with the second holding q = 1/3 of the samples: the film's value
  // is (2/3)·1 + (1/3)·4 = 2 and σ = √(q(1 − q))·|a − b| = √(2/9)·3 = √2, relative 0.7071. Equal
  // halves (q = 1/2) give |a − b|/2 over the mean: 1.5 / 2.5 = 0.6, measureNoise's figure / √2.
  // A pixel with an empty half (q = 0) has no figure.
  const NoiseImage a = image(3, 1, {"band x"}, {1, 1, 1});
  const NoiseImage b = image(3, 1, {"band x"}, {4, 4, 4});
  const auto unequal = measureHalvesNoise(a, b, {1.0 / 3, 1.0 / 3, 0.0}, {});
  EXPECT_EQ(unequal[0].pixels, 2u);
  EXPECT_NEAR(unequal[0].medianRelative, std::sqrt(2.0) / 2, 1e-15);
  const auto equal = measureHalvesNoise(a, b, {0.5, 0.5, 0.5}, {});
  EXPECT_NEAR(equal[0].medianRelative, 0.6, 1e-15);
  EXPECT_NEAR(equal[0].medianRelative * std::sqrt(2.0), measureNoise(a, b, {})[0].medianRelative,
              1e-15);
  EXPECT_THROW(measureHalvesNoise(a, b, {0.5}, {}), std::invalid_argument);
}

TEST(RenderNoise, ChromaticityNoiseIgnoresBrightnessAndSeesHue) {
  // Same hue at twice the brightness: no chromaticity noise; a hue shift (1,1,1) vs (2,1,1):
  // c = (1/3, 1/3, 1/3) and (1/2, 1/4, 1/4), ‖Δc‖ = 0.2041, ‖mean c‖ = 0.5951 → 0.2425.
  NoiseImage a = image(2, 1, {"R", "G", "B"}, {1, 1, 1, 1, 1, 1});
  NoiseImage b = image(2, 1, {"R", "G", "B"}, {2, 2, 2, 2, 1, 1});
  a.rgb = b.rgb = {0, 1, 2};
  const auto noise = measureNoise(a, b, {true, false});
  ASSERT_EQ(noise.size(), 4u);
  EXPECT_EQ(noise[3].group, "chromaticity");
  EXPECT_NEAR(noise[3].medianRelative, 0.0, 1e-15);
  const auto hue = measureNoise(a, b, {false, true});
  const double dc = std::sqrt(1.0 / 36 + 2.0 / 144),
               mean = std::sqrt(std::pow(5.0 / 12, 2) + 2 * std::pow(7.0 / 24, 2));
  EXPECT_NEAR(hue[3].medianRelative, dc / std::sqrt(2.0) / mean, 1e-12);
}

TEST(RenderNoise, RefusesImagesThatDoNotMatch) {
  const NoiseImage a = image(2, 1, {"band x"}, {1, 2});
  const NoiseImage b = image(1, 2, {"band x"}, {1, 2});
  EXPECT_THROW(measureNoise(a, b, {}), std::invalid_argument);
  EXPECT_THROW(measureNoise(a, a, {true}), std::invalid_argument);
  EXPECT_TRUE(std::isnan(measureNoise(a, a, {false, false})[0].medianRelative));
}
