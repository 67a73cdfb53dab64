// Eight xoshiro128+ streams in lanes (skin/core/lane_random.h): the generator against hand values
// of its recurrence, each lane seeded from its own Rng, and the uniforms on the 2^-24 grid,
// uniform by chi-square.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "skin/core/lane_random.h"
#include "tests/support/chi2.h"

namespace hylios::skin::lanes {
namespace {

TEST(LaneRandom, RecurrenceAtHandValues) {
  // State (1, 2, 3, 4): outputs s0 + s3 = 5; then the state is (7, 0, 1026, rotl(6, 11) = 12288),
  // so 7 + 12288 = 12295; the third, 25178119, from the same recurrence by hand.
  LaneRng rng;
  rng.s0 = Bits{} + 1u;
  rng.s1 = Bits{} + 2u;
  rng.s2 = Bits{} + 3u;
  rng.s3 = Bits{} + 4u;
  const std::uint32_t expected[3] = {5u, 12295u, 25178119u};
  for (const std::uint32_t e : expected) {
    const Bits out = rng.next();
    for (int l = 0; l < kLanes; ++l) EXPECT_EQ(out[l], e) << "lane " << l;
  }
}

TEST(LaneRandom, EachLaneIsSeededFromItsOwnRng) {
  LaneRng rng;
  for (int l = 0; l < kLanes; ++l) {
    Rng packet(9, 0, static_cast<std::uint64_t>(100 + l));
    rng.seedLane(l, packet);
  }
  for (int l = 0; l < kLanes; ++l) {
    Rng packet(9, 0, static_cast<std::uint64_t>(100 + l));
    const std::uint64_t a = packet.nextU64(), b = packet.nextU64();
    EXPECT_EQ(rng.s0[l], static_cast<std::uint32_t>(a));
    EXPECT_EQ(rng.s1[l], static_cast<std::uint32_t>(a >> 32));
    EXPECT_EQ(rng.s2[l], static_cast<std::uint32_t>(b));
    EXPECT_EQ(rng.s3[l], static_cast<std::uint32_t>(b >> 32));
  }
  // Lanes seeded alike draw alike; differently, differently.
  LaneRng same;
  Rng first(9, 0, 100), again(9, 0, 100);
  same.seedLane(0, first);
  same.seedLane(1, again);
  const Floats u = same.uniform();
  EXPECT_EQ(u[0], u[1]);
  EXPECT_NE(rng.uniform()[0], rng.uniform()[1]);
}

TEST(LaneRandom, UniformsLieOnTheGridAndAreUniform) {
  LaneRng rng;
  for (int l = 0; l < kLanes; ++l) {
    Rng packet(3, 0, static_cast<std::uint64_t>(l));
    rng.seedLane(l, packet);
  }
  std::vector<double> samples;
  const int draws = 125000;  // per lane: 10^6 in all
  for (int i = 0; i < draws; ++i) {
    const Floats u = rng.uniform();
    for (int l = 0; l < kLanes; ++l) {
      ASSERT_GE(u[l], 0.0f);
      ASSERT_LT(u[l], 1.0f);
      const float scaled = u[l] * 0x1.0p24f;
      ASSERT_EQ(scaled, std::floor(scaled)) << "off the 2^-24 grid: " << u[l];
      samples.push_back(u[l]);
    }
  }
  const auto density = [](double) { return 1.0; };
  EXPECT_TRUE(test::chi2Accepts(test::chi2Test1D(samples, density, test::uniformEdges(0, 1, 100))));
  // Mean 1/2, standard error sqrt(1/12 / 10^6) = 2.9e-4; 4σ.
  EXPECT_NEAR(test::mean(samples), 0.5, 1.2e-3);
}

}  // namespace
}  // namespace hylios::skin::lanes
