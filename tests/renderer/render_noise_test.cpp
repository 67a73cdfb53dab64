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
