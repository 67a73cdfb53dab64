// The `table` skin mode in the renderer: a small skin scene rendered with exit tables agrees with
// the exact walk within the renders' noise; a bad skin_mode is a positioned scene error.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <stdlib.h>
#include <string>
#include <utility>
#include <vector>

#include "renderer/image/film.h"
#include "renderer/scene/scene_file.h"
#include "renderer/tracing/exit_table_cache.h"
#include "renderer/tracing/integrator.h"

using namespace hylios;

namespace {

/// Per-pixel values of channel 0 after rendering `scene` in `mode` with `seed`; with `channels`
/// also every channel's, one vector per channel.
std::vector<double> render(SceneDesc scene, skin::SkinMode mode, std::uint64_t seed,
                           std::vector<std::vector<double>>* channels = nullptr) {
  scene.integrator.skinMode = mode;
  scene.integrator.seed = seed;
  Film film(scene.film);
  std::vector<double> wavelengths;
  for (const FilmChannel& c : film.channels()) wavelengths.push_back(c.wavelengthNm);
  const Integrator integrator(scene, wavelengths);
  RenderOptions options;
  options.label = std::string(enumName(mode, skin::kSkinModeNames));
  integrator.render(film, options);
  std::vector<std::vector<double>> values(film.channels().size());
  for (std::size_t c = 0; c < values.size(); ++c)
    for (int y = 0; y < film.height(); ++y)
      for (int x = 0; x < film.width(); ++x) values[c].push_back(film.value(x, y, c));
  if (channels) *channels = values;
  return values[0];
}

/// z of the mean difference over the pixels where either image is nonzero (the sphere), from the
/// per-pixel differences' spread (pixels are independent: different seeds).
double meanDifferenceZ(const std::vector<double>& a, const std::vector<double>& b,
                       std::size_t first, std::size_t stride, std::size_t rows, int width,
                       double* relative, double* relativeSigma = nullptr) {
  double sum = 0, sum2 = 0, reference = 0;
  double n = 0;
  for (std::size_t row = first; row < first + rows; ++row)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = row * stride + static_cast<std::size_t>(x);
      if (a[i] == 0 && b[i] == 0) continue;
      const double d = a[i] - b[i];
      sum += d;
      sum2 += d * d;
      reference += b[i];
      ++n;
    }
  const double mean = sum / n, sd = std::sqrt((sum2 / n - mean * mean) / (n - 1));
  if (relative) *relative = sum / reference;
  if (relativeSigma) *relativeSigma = sd * n / reference;
  return mean / sd;
}

/// skin_sphere_550 with a band of five channels, 420–700 nm, at 32 spp (tables cached in the
/// build folder).
SceneDesc fiveChannelSphere() {
  setenv("HYLIOS_CACHE_DIR",
         (std::string(HYLIOS_BINARY_DIR) + "/skin_table_render_test_cache").c_str(), 1);
  SceneDesc scene =
      loadSceneFile(std::string(HYLIOS_SOURCE_DIR) + "/scenes/test/skin_sphere_550.toml");
  scene.film.bands[0].minNm = 420;
  scene.film.bands[0].maxNm = 700;
  scene.film.bands[0].stepNm = 70;
  scene.film.samplesPerPixel = 32;
  return scene;
}

}  // namespace

// skin_sphere_550 (S1, uniform environment): the mean over the sphere and over its upper and lower
// halves agree within 4 standard errors of the difference of two independent renders. With 64×64
// pixels at 16 spp the standard error of the sphere's mean is ≈ 0.2 % of it, so a 1 % table error
// would show as z ≈ 5.
TEST(SkinTableRender, TableModeAgreesWithWalkMode) {
  setenv("HYLIOS_CACHE_DIR",
         (std::string(HYLIOS_BINARY_DIR) + "/skin_table_render_test_cache").c_str(), 1);
  SceneDesc scene =
      loadSceneFile(std::string(HYLIOS_SOURCE_DIR) + "/scenes/test/skin_sphere_550.toml");
  scene.film.samplesPerPixel = 16;
  const std::vector<double> walk = render(scene, skin::SkinMode::Walk, 11),
                            table = render(scene, skin::SkinMode::Table, 12);
  const int w = scene.film.width, h = scene.film.height;
  double relative = 0;
  const double whole = meanDifferenceZ(table, walk, 0, static_cast<std::size_t>(w),
                                       static_cast<std::size_t>(h), w, &relative);
  std::cout << "table − walk over the sphere: " << 100 * relative << " %, z " << whole << "\n";
  EXPECT_LT(std::fabs(whole), 4);
  for (std::size_t half = 0; half < 2; ++half)
    EXPECT_LT(std::fabs(meanDifferenceZ(table, walk, half * static_cast<std::size_t>(h / 2),
                                        static_cast<std::size_t>(w),
                                        static_cast<std::size_t>(h / 2), w, nullptr)),
              4)
        << "half " << half;
  EXPECT_GT(ExitTableCache::shared().built() + ExitTableCache::shared().loaded(), 0u);
}

// A band of five channels: the spectral estimator samples the band's tables at once
// (skin/exit_table_bundle.h) and the band's spectral walk, one camera path for all channels. Each
// channel's mean over the sphere agrees within 4 standard errors of the two renders' difference
// and of the tables' own sampling error (10⁴ rays per bin: σ_table ≈ 0.4 % of the mean, the
// relative standard error of P(subsurface) averaged over the bins the sphere's rays use).
TEST(SkinTableRender, BandTablesSampledAtOnceAgreeWithTheBandsWalk) {
  SceneDesc scene = fiveChannelSphere();
  ASSERT_EQ(scene.integrator.estimator, skin::Estimator::Spectral);
  std::vector<std::vector<double>> walk, table;
  render(scene, skin::SkinMode::Walk, 21, &walk);
  render(scene, skin::SkinMode::Table, 22, &table);
  const int w = scene.film.width, h = scene.film.height;
  for (std::size_t c = 0; c < walk.size(); ++c) {
    double relative = 0, renderSigma = 0;  // the difference and its standard error, relative
    meanDifferenceZ(table[c], walk[c], 0, static_cast<std::size_t>(w), static_cast<std::size_t>(h),
                    w, &relative, &renderSigma);
    const double sigma = std::hypot(renderSigma, 0.004);
    std::cout << "channel " << c << ": table − walk " << 100 * relative << " %, render σ "
              << 100 * renderSigma << " %\n";
    EXPECT_LT(std::fabs(relative), 4 * sigma) << "channel " << c;
  }
}

// The exit control variate (renderer/tracing/integrator.h) under a spot light whose hard edge
// crosses the sphere, where the light at a skin entry and at its exit point differ most. With the
// same seed the renders with and without it draw the same numbers, so their per-pixel difference is
// the variate's term alone: its mean over the sphere must be 0 within 4 standard errors (pixels are
// independent), per channel, and it must lower the per-pixel spread of a colour channel between
// two seeds (the blue end, where the band's exit weights spread most).
TEST(SkinTableRender, ExitControlVariateAddsNothingInExpectation) {
  SceneDesc scene = fiveChannelSphere();
  LightDesc spot = scene.lights.front();
  spot.kind = LightDesc::Kind::Spot;
  spot.position = {0, 0, 3};
  spot.direction = {0, 0, -1};
  spot.spotInnerDeg = spot.spotOuterDeg = 12;  // edge ≈ 0.4 cm from the sphere's pole
  scene.lights = {spot};
  std::vector<std::vector<double>> with, without, withOtherSeed, withoutOtherSeed;
  render(scene, skin::SkinMode::Table, 41, &with);
  render(scene, skin::SkinMode::Table, 42, &withOtherSeed);
  scene.integrator.exitControlVariate = false;
  render(scene, skin::SkinMode::Table, 41, &without);
  render(scene, skin::SkinMode::Table, 42, &withoutOtherSeed);
  const int w = scene.film.width, h = scene.film.height;
  const auto spread = [&](const std::vector<double>& a, const std::vector<double>& b) {
    double relative = 0, sigma = 0;
    meanDifferenceZ(a, b, 0, static_cast<std::size_t>(w), static_cast<std::size_t>(h), w, &relative,
                    &sigma);
    return sigma;  // σ of the mean difference: the per-pixel spread / √pixels
  };
  for (std::size_t c = 0; c < with.size(); ++c) {
    double relative = 0;
    const double z = meanDifferenceZ(with[c], without[c], 0, static_cast<std::size_t>(w),
                                     static_cast<std::size_t>(h), w, &relative);
    std::cout << "channel " << c << ": with − without " << 100 * relative << " %, z " << z
              << "; two seeds' spread with " << 100 * spread(with[c], withOtherSeed[c])
              << " %, without " << 100 * spread(without[c], withoutOtherSeed[c]) << " %\n";
    EXPECT_LT(std::fabs(z), 4) << "channel " << c;
    EXPECT_GT(std::fabs(relative), 0) << "channel " << c << ": the variate changed nothing";
  }
  EXPECT_LT(spread(with[0], withOtherSeed[0]), spread(without[0], withoutOtherSeed[0]));
}

TEST(SkinTableRender, BadSkinModeIsAPositionedError) {
  const std::string text =
      "[camera]\nposition = [0.0, 0.0, 4.0]\nlook_at = [0.0, 0.0, 0.0]\nfov_deg = 40.0\n"
      "[film]\nresolution = [8, 8]\nspp = 1\n[[film.band]]\nname = \"a\"\nwavelength_nm = 550\n"
      "[[light]]\ntype = \"environment\"\nemission = { type = \"constant\", scale = 1.0 }\n"
      "[integrator]\nskin_mode = \"tables\"\n";
  try {
    parseSceneText(text, "bad.toml", ".");
    FAIL() << "no error";
  } catch (const std::exception& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("bad.toml:15:"), std::string::npos) << message;
    EXPECT_NE(message.find("table"), std::string::npos) << message;
  }
}
