// The spectral film: channel layout, sampleChannel's distribution (band uniformly, then channel
// uniformly — chi-square), per-channel means, and its errors.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <thread>
#include <vector>

#include "renderer/image/film.h"
#include "skin/core/random.h"
#include "tests/support/chi2.h"

namespace {

using hylios::BandDesc;
using hylios::Film;
using hylios::FilmDesc;

BandDesc singleBand(const std::string& name, double nm) {
  BandDesc band;
  band.name = name;
  band.minNm = band.maxNm = nm;
  return band;
}

BandDesc rangeBand(const std::string& name, double minNm, double maxNm, double stepNm) {
  BandDesc band;
  band.name = name;
  band.minNm = minNm;
  band.maxNm = maxNm;
  band.stepNm = stepNm;
  return band;
}

/// Bands: uv365 (1 channel), vis 400–700 step 100 (4 channels), ir1100 (1 channel).
FilmDesc threeBandDesc(int width = 3, int height = 2) {
  FilmDesc desc;
  desc.width = width;
  desc.height = height;
  desc.bands = {singleBand("uv365", 365), rangeBand("vis", 400, 700, 100),
                singleBand("ir1100", 1100)};
  return desc;
}

TEST(Film, ChannelsFollowBandsInOrder) {
  const Film film(threeBandDesc());
  const std::vector<double> wavelengths{365, 400, 500, 600, 700, 1100};
  const std::vector<std::size_t> bands{0, 1, 1, 1, 1, 2};
  ASSERT_EQ(film.channels().size(), wavelengths.size());
  for (std::size_t c = 0; c < wavelengths.size(); ++c) {
    EXPECT_EQ(film.channels()[c].wavelengthNm, wavelengths[c]);
    EXPECT_EQ(film.channels()[c].band, bands[c]);
  }
  EXPECT_EQ(film.width(), 3);
  EXPECT_EQ(film.height(), 2);
}

TEST(Film, SampleChannelBoundaries) {
  const Film film(threeBandDesc());
  EXPECT_EQ(film.sampleChannel(0.0), 0u);
  EXPECT_EQ(film.sampleChannel(std::nextafter(1.0 / 3.0, 0.0)), 0u);
  EXPECT_EQ(film.sampleChannel(1.0 / 3.0 + 1e-12), 1u);  // first channel of the range band
  EXPECT_EQ(film.sampleChannel(0.5), 3u);  // band ⌊1.5⌋ = 1, channel ⌊0.5·4⌋ = 2 of it → 600 nm
  EXPECT_EQ(film.sampleChannel(2.0 / 3.0 - 1e-12), 4u);  // last channel of the range band
  EXPECT_EQ(film.sampleChannel(hylios::skin::kOneMinusEpsilon), 5u);
  EXPECT_THROW(film.sampleChannel(1.0), std::invalid_argument);
  EXPECT_THROW(film.sampleChannel(-0.1), std::invalid_argument);
  EXPECT_THROW(film.sampleChannel(std::nan("")), std::invalid_argument);
}

TEST(Film, SampleChannelIsBandUniformThenChannelUniform) {
  // Expected probabilities: 1/3 for each single band, 1/3 · 1/4 for each of the range's channels.
  const Film film(threeBandDesc());
  const std::vector<double> probability{1.0 / 3, 1.0 / 12, 1.0 / 12, 1.0 / 12, 1.0 / 12, 1.0 / 3};
  const int n = 120000;
  std::vector<double> observed(probability.size(), 0.0), expected(probability.size());
  hylios::skin::Rng rng(42, 7);
  for (int i = 0; i < n; ++i) observed[film.sampleChannel(rng.uniform())] += 1.0;
  for (std::size_t c = 0; c < probability.size(); ++c) expected[c] = n * probability[c];
  EXPECT_TRUE(hylios::test::chi2Accepts(hylios::test::chi2FromCounts(observed, expected)));
}

TEST(Film, ChiSquareRejectsAChannelUniformSampler) {
  // The same test must fail for the wrong law (every channel 1/6), so it has power here.
  const Film film(threeBandDesc());
  const int n = 120000;
  std::vector<double> observed(6, 0.0), expected(6, n / 6.0);
  hylios::skin::Rng rng(42, 7);
  for (int i = 0; i < n; ++i) observed[film.sampleChannel(rng.uniform())] += 1.0;
  EXPECT_FALSE(hylios::test::chi2Accepts(hylios::test::chi2FromCounts(observed, expected)));
}

TEST(Film, ValueIsTheMeanOfAChannelsSamples) {
  Film film(threeBandDesc());
  EXPECT_EQ(film.value(1, 1, 3), 0.0);  // no sample yet
  film.addSample(1, 1, 3, 1.0);
  film.addSample(1, 1, 3, 2.0);
  film.addSample(1, 1, 3, 6.0);
  EXPECT_DOUBLE_EQ(film.value(1, 1, 3), 3.0);
  EXPECT_EQ(film.sampleCount(1, 1, 3), 3u);
  EXPECT_EQ(film.sampleCount(1, 1, 2), 0u);  // neighbours untouched
  EXPECT_EQ(film.value(0, 1, 3), 0.0);
  EXPECT_EQ(film.value(1, 1, 0), 0.0);  // band "uv365" of that pixel has no sample yet
  film.setSamplesPerPixelDone(16);
  EXPECT_EQ(film.samplesPerPixelDone(), 16);
}

// Channels a pixel's samples missed take the linear interpolation in wavelength between the
// nearest sampled channels of their band, or the nearest one at the band's ends.
TEST(Film, UnsampledChannelsAreInterpolatedWithinTheirBand) {
  Film film(threeBandDesc());                  // band "vis": channels 1..4 at 400, 500, 600, 700 nm
  film.addSample(0, 0, 2, 2.0);                // 500 nm
  EXPECT_DOUBLE_EQ(film.value(0, 0, 1), 2.0);  // 400 nm: below the first sampled channel
  EXPECT_DOUBLE_EQ(film.value(0, 0, 4), 2.0);  // 700 nm: beyond the last
  film.addSample(0, 0, 4, 8.0);                // 700 nm
  EXPECT_DOUBLE_EQ(film.value(0, 0, 3), 5.0);  // 600 nm: halfway between 2 and 8
  EXPECT_DOUBLE_EQ(film.value(0, 0, 1), 2.0);
  EXPECT_EQ(film.value(0, 0, 0), 0.0);  // other bands do not lend values
  EXPECT_EQ(film.value(0, 0, 5), 0.0);
}

// Fewer samples than channels must not darken the band (each unsampled channel used to read 0):
// with constant radiance 1 and 2 samples per pixel into a 4-channel band, every channel reads 1.
TEST(Film, FewerSamplesThanChannelsDoNotDarkenTheBand) {
  FilmDesc desc;
  desc.width = 50;
  desc.height = 20;
  desc.bands = {rangeBand("vis", 400, 700, 100)};
  Film film(desc);
  hylios::skin::Rng rng(11, 2);
  for (int y = 0; y < desc.height; ++y)
    for (int x = 0; x < desc.width; ++x)
      for (int s = 0; s < 2; ++s) film.addSample(x, y, film.sampleChannel(rng.uniform()), 1.0);
  for (int y = 0; y < desc.height; ++y)
    for (int x = 0; x < desc.width; ++x)
      for (std::size_t c = 0; c < 4; ++c)
        ASSERT_DOUBLE_EQ(film.value(x, y, c), 1.0) << x << "," << y << " channel " << c;
}

TEST(Film, MonteCarloMeanPerChannelConverges) {
  // Radiance f(λ) + U(−½, ½) noise, channels drawn by sampleChannel: each channel's mean estimates
  // f(λ) with standard error sqrt(1/12 / n_c); accept within 4 σ.
  Film film(threeBandDesc(1, 1));
  const auto truth = [](double nm) { return nm / 100.0; };
  hylios::skin::Rng rng(3, 1);
  for (int i = 0; i < 60000; ++i) {
    const std::size_t c = film.sampleChannel(rng.uniform());
    film.addSample(0, 0, c, truth(film.channels()[c].wavelengthNm) + rng.uniform() - 0.5);
  }
  for (std::size_t c = 0; c < film.channels().size(); ++c) {
    const double n = film.sampleCount(0, 0, c);
    ASSERT_GT(n, 1000);
    const double standardError = std::sqrt(1.0 / 12.0 / n);
    EXPECT_NEAR(film.value(0, 0, c), truth(film.channels()[c].wavelengthNm), 4 * standardError)
        << "channel " << c << " (σ = " << standardError << ")";
  }
}

TEST(Film, ConcurrentSamplesOnDistinctPixels) {
  Film film(threeBandDesc(8, 4));
  std::vector<std::thread> threads;
  for (int y = 0; y < 4; ++y) {
    threads.emplace_back([&film, y] {
      for (int x = 0; x < 8; ++x)
        for (int k = 0; k < 1000; ++k) film.addSample(x, y, 0, 0.5);
    });
  }
  for (auto& thread : threads) thread.join();
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 8; ++x) {
      EXPECT_EQ(film.sampleCount(x, y, 0), 1000u);
      EXPECT_DOUBLE_EQ(film.value(x, y, 0), 0.5);
    }
  }
}

TEST(Film, RejectsBadSamplesAndBadDescriptions) {
  Film film(threeBandDesc());
  EXPECT_THROW(film.addSample(3, 0, 0, 1.0), std::out_of_range);
  EXPECT_THROW(film.addSample(0, -1, 0, 1.0), std::out_of_range);
  EXPECT_THROW(film.addSample(0, 0, 6, 1.0), std::out_of_range);
  EXPECT_THROW(film.addSample(0, 0, 0, std::nan("")), std::invalid_argument);
  EXPECT_THROW(film.addSample(0, 0, 0, INFINITY), std::invalid_argument);
  EXPECT_THROW(film.value(0, 2, 0), std::out_of_range);

  FilmDesc noBands = threeBandDesc();
  noBands.bands.clear();
  EXPECT_THROW(Film{noBands}, std::invalid_argument);
  FilmDesc empty = threeBandDesc(0, 4);
  EXPECT_THROW(Film{empty}, std::invalid_argument);
  FilmDesc zeroStep = threeBandDesc();
  zeroStep.bands[1].stepNm = 0;
  EXPECT_THROW(Film{zeroStep}, std::invalid_argument);
}

}  // namespace
