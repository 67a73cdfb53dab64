// SkinTally with control weights (skin/skin_tally.h): spectral tallies are control-variate means
// whose outcomes sum to 1 exactly, they travel between processes unchanged, analog tallies keep
// the plain means, and paths with and without control weights never mix.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "skin/skin_simulation.h"
#include "skin/skin_tally.h"
#include "skin/skin_walk.h"
#include "skin/spectral_simulation.h"
#include "tests/support/test_spectra.h"

namespace hylios::skin {
namespace {

std::vector<SkinTally> rampTallies() {
  // Three wavelengths of Algorithm 2's θo ramp share one bundle: their MIS ratios vary.
  std::vector<SkinOptics> optics;
  for (double nm : {1100.0, 1110.0, 1120.0}) optics.push_back(test::s1Optics(nm));
  WalkRunOptions run;
  run.incidenceDeg = 45;
  run.rays = 4000;
  return simulateSkinSpectral(optics, commandSpectralRun(run));
}

TEST(SkinTally, SpectralOutcomesSumToOneExactly) {
  // Each path's scores R + T + A equal its control weight U, and the control variate of U against
  // itself (β = 1) is 1: so the three estimates sum to 1 up to rounding, where the plain means
  // sum to mean(U), 1 only within its error.
  for (const SkinTally& t : rampTallies()) {
    ASSERT_TRUE(t.controlled());
    const double sum = t.reflectance().mean + t.transmittance().mean + t.absorptance().mean;
    EXPECT_NEAR(sum, 1.0, 1e-12);
    EXPECT_NEAR(t.surfaceReflectance().mean + t.subsurfaceReflectance().mean, t.reflectance().mean,
                1e-12);
    EXPECT_GT(t.reflectance().standardError, 0.0);
  }
}

TEST(SkinTally, ControlledTalliesTravelUnchanged) {
  const SkinTally t = rampTallies()[1];
  std::string bytes;
  t.appendBytes(bytes);
  std::size_t offset = 0;
  const SkinTally back = SkinTally::fromBytes({}, bytes, offset);
  EXPECT_EQ(offset, bytes.size());
  EXPECT_TRUE(back.controlled());
  EXPECT_EQ(back.reflectance().mean, t.reflectance().mean);
  EXPECT_EQ(back.reflectance().standardError, t.reflectance().standardError);
  EXPECT_EQ(back.absorptance(Layer::StratumBasale).mean, t.absorptance(Layer::StratumBasale).mean);
}

TEST(SkinTally, AnalogTalliesKeepThePlainMeans) {
  const SkinWalk walk(test::s1Optics(550));
  SkinTally tally;
  RunningStatistic reflected;
  for (std::uint64_t ray = 0; ray < 2000; ++ray) {
    Rng rng(5, 0, ray);
    const SkinPath path = walk.trace(incidentDirection(0), rng);
    tally.record(path);
    reflected.add(
        path.end == PathEnd::SurfaceReflection || path.end == PathEnd::SubsurfaceReflection ? 1.0
                                                                                            : 0.0);
  }
  EXPECT_FALSE(tally.controlled());
  EXPECT_EQ(tally.reflectance().mean, reflected.mean());
  EXPECT_EQ(tally.reflectance().standardError, reflected.standardError());
}

TEST(SkinTally, PathsWithAndWithoutControlWeightsDoNotMix) {
  PathScore analog;
  analog.end = PathEnd::SubsurfaceReflection;
  analog.exitWeight = 1;
  PathScore spectral = analog;
  spectral.hasControlWeight = true;
  spectral.controlWeight = 1.2;
  SkinTally a;
  a.record(analog);
  EXPECT_THROW(a.record(spectral), std::logic_error);
  SkinTally s;
  s.record(spectral);
  EXPECT_THROW(s.record(analog), std::logic_error);
  EXPECT_THROW(s.merge(a), std::logic_error);
  SkinTally empty;
  empty.merge(s);  // an empty tally takes the other's kind
  EXPECT_TRUE(empty.controlled());
}

}  // namespace
}  // namespace hylios::skin
