// The spectral estimator of the renderer (hero wavelengths: a path carries every channel of its
// band; skin runs the spectral walk) against the per-wavelength estimator it replaces: the same
// image in expectation. Scene: the skin sphere of scenes/test under a uniform environment and a
// small area light, a 3-channel band; per channel the mean per-pixel difference over the sphere
// must be within 4 standard errors (σ from the spread of the pixel differences, pixels being
// independent estimates).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "renderer/image/film.h"
#include "renderer/image/film_output.h"
#include "renderer/scene/scene_file.h"
#include "renderer/tracing/integrator.h"
#include "skin/core/thread_limit.h"
#include "tests/support/test_scenes.h"

using namespace hylios;

namespace {

SceneDesc testScene(skin::Estimator estimator) {
  SceneDesc scene = test::skinSphereScene(32, 96);
  scene.film.bands = {test::rangeBand("green", 500, 600, 50)};
  scene.integrator.estimator = estimator;
  scene.integrator.seed = estimator == skin::Estimator::Spectral ? 5 : 6;
  return scene;
}

Film render(const SceneDesc& scene) {
  Film film(scene.film);
  std::vector<double> wavelengths;
  for (const FilmChannel& c : film.channels()) wavelengths.push_back(c.wavelengthNm);
  const Integrator integrator(scene, wavelengths);
  integrator.render(film, quietRenderOptions("test"));
  return film;
}

}  // namespace

namespace {
/// The whole film as a noise image: each half weighed by its share of the samples.
NoiseImage wholeFilmNoiseImage(const Film& film) {
  NoiseImage whole = filmHalfNoiseImage(film, false);
  const NoiseImage second = filmHalfNoiseImage(film, true);
  const std::vector<double> share = filmSecondHalfShare(film);
  for (std::size_t i = 0; i < whole.values.size(); ++i)
    whole.values[i] = (1 - share[i]) * whole.values[i] + share[i] * second.values[i];
  return whole;
}
}  // namespace

TEST(SpectralRender, HeroWavelengthRenderEqualsPerWavelengthRender) {
  const Film spectral = render(testScene(skin::Estimator::Spectral));
  const Film perWavelength = render(testScene(skin::Estimator::PerWavelength));
  ASSERT_TRUE(spectral.wholeBandSamples());
  ASSERT_FALSE(perWavelength.wholeBandSamples());
  ASSERT_EQ(spectral.coverage(), perWavelength.coverage());
  for (std::size_t c = 0; c < spectral.channels().size(); ++c) {
    double sum = 0, sumSquares = 0, reference = 0;
    int pixels = 0;
    for (int y = 0; y < spectral.height(); ++y)
      for (int x = 0; x < spectral.width(); ++x) {
        if (!spectral.coverage()[static_cast<std::size_t>(y * spectral.width() + x)]) continue;
        const double d = spectral.value(x, y, c) - perWavelength.value(x, y, c);
        sum += d;
        sumSquares += d * d;
        reference += perWavelength.value(x, y, c);
        ++pixels;
      }
    ASSERT_GT(pixels, 100);
    const double mean = sum / pixels;
    const double standardError = std::sqrt((sumSquares / pixels - mean * mean) / (pixels - 1));
    EXPECT_LE(std::fabs(mean), 4 * standardError)
        << spectral.channels()[c].wavelengthNm << " nm: mean difference " << mean << " ± "
        << standardError << " (mean radiance " << reference / pixels << ")";
    EXPECT_LT(standardError, 0.02 * reference / pixels);  // the test sees an 8 % bias
  }
}

TEST(SpectralRender, SameSeedSameImageAtOneAndTwoThreads) {
  const SceneDesc scene = testScene(skin::Estimator::Spectral);
  Film one(scene.film), two(scene.film);
  {
    const ThreadLimit limit(1);
    one = render(scene);
  }
  {
    const ThreadLimit limit(2);
    two = render(scene);
  }
  EXPECT_TRUE(one.sums() == two.sums());
  EXPECT_TRUE(one.secondHalfSums() == two.secondHalfSums());
}

TEST(SpectralRender, NoiseTargetStopsWhenTheEstimateIsReached) {
  SceneDesc scene = testScene(skin::Estimator::Spectral);
  scene.film.width = scene.film.height = 24;
  scene.film.samplesPerPixel = 4096;  // the cap
  Film film(scene.film);
  std::vector<double> wavelengths;
  for (const FilmChannel& c : film.channels()) wavelengths.push_back(c.wavelengthNm);
  const Integrator integrator(scene, wavelengths);
  RenderOptions options = quietRenderOptions("test");
  options.noiseTarget = 0.08;
  const RenderStats stats = integrator.render(film, options);
  EXPECT_TRUE(stats.noiseTargetReached);
  EXPECT_LT(film.samplesPerPixelDone(), 4096);
  EXPECT_GE(film.samplesPerPixelDone(), kMinNoiseSamples);
  EXPECT_EQ(film.samplesPerPixelDone() % kNoiseCheckGranule, 0);  // the checks' sample counts
  EXPECT_LE(worstNoise(stats.noise), 0.08);
  // Where it stops depends on the film only, not on timing: other pass sizes, one thread, same spp
  // and the same sums.
  {
    const ThreadLimit limit(1);
    Film again(scene.film);
    RenderOptions fixedPasses = options;
    fixedPasses.samplesPerPass = 3;
    integrator.render(again, fixedPasses);
    EXPECT_EQ(again.samplesPerPixelDone(), film.samplesPerPixelDone());
    EXPECT_TRUE(again.sums() == film.sums());
  }
  // The film's own estimate (its halves weighed by their shares: at a count that is not a
  // multiple of 8 the halves are unequal) agrees with the two-seed measure of the whole films,
  // within a factor 1.5 (both are medians over the sphere's pixels of noisy per-pixel figures).
  SceneDesc again = scene;
  again.film.samplesPerPixel = film.samplesPerPixelDone();
  again.integrator.seed = 99;
  const Film other = render(again);
  const auto twoSeeds =
      measureNoise(wholeFilmNoiseImage(film), wholeFilmNoiseImage(other), film.coverage());
  const double own = worstNoise(stats.noise), measured = worstNoise(twoSeeds);
  EXPECT_GT(own / measured, 1 / 1.5) << own << " vs " << measured;
  EXPECT_LT(own / measured, 1.5) << own << " vs " << measured;
}
