// Image regression: small scenes (scenes/test/) rendered with a different seed than their committed
// references (tests/data/regression/<scene>.exr, see README.md there) and compared with a
// statistical tolerance, so that Monte Carlo noise passes and a real change fails.
//
// Comparison of a test image T and reference R (same channels), per pixel Δ = T − R, whose noise
// is independent between pixels (different seeds):
//   1. whole image: z = mean(Δ) / (sd(Δ)/√n) must satisfy |z| < 4;
//   2. the pixels that vary (value ≠ the image's most common value, i.e. not empty sky): same test;
//   3. 16 × 16-pixel blocks with at least 64 varying pixels: |z_block| < 5 (a local change).
// Each scene's test renders at the spp that makes a 5 % change of the varying pixels' mean at
// least ~5.5 standard errors; the test checks that a reference scaled by 1.05 or 0.95 (all
// pixels, and the varying pixels only) fails.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "renderer/image/film_output.h"
#include "renderer/scene/scene_file.h"
#include "renderer/tracing/integrator.h"

using namespace hylios;

namespace {

struct Image {
  int width = 0, height = 0;
  std::vector<double> values;  ///< all channels of a pixel, pixel-major
  int channels = 0;
};

Image readReference(const std::string& path, const Film& film) {
  auto input = OIIO::ImageInput::open(path);
  if (!input) throw std::runtime_error("cannot open reference " + path + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = input->spec();
  std::vector<float> pixels(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
  if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
    throw std::runtime_error("cannot read reference " + path);
  Image image{spec.width, spec.height, {}, static_cast<int>(film.channels().size())};
  std::vector<int> column;
  for (const FilmChannel& c : film.channels()) {
    const std::string name = spectralChannelName(c.wavelengthNm);
    const auto it = std::find(spec.channelnames.begin(), spec.channelnames.end(), name);
    if (it == spec.channelnames.end()) throw std::runtime_error(path + " has no channel " + name);
    column.push_back(static_cast<int>(it - spec.channelnames.begin()));
  }
  for (int p = 0; p < spec.width * spec.height; ++p)
    for (int c : column)
      image.values.push_back(pixels[static_cast<std::size_t>(p) * spec.nchannels + c]);
  return image;
}

Image fromFilm(const Film& film) {
  Image image{film.width(), film.height(), {}, static_cast<int>(film.channels().size())};
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x)
      for (std::size_t c = 0; c < film.channels().size(); ++c)
        image.values.push_back(film.value(x, y, c));
  return image;
}

/// z of the mean of Δ over the selected entries; 0 when Δ is identically 0 there.
double meanZ(const std::vector<double>& deltas) {
  if (deltas.size() < 2) return 0;
  double sum = 0, sum2 = 0;
  for (double d : deltas) {
    sum += d;
    sum2 += d * d;
  }
  const double n = static_cast<double>(deltas.size()), mean = sum / n;
  const double variance = std::max(0.0, (sum2 - n * mean * mean) / (n - 1));
  if (variance == 0) return mean == 0 ? 0 : std::copysign(1e300, mean);
  return mean / std::sqrt(variance / n);
}

struct Comparison {
  double wholeZ = 0, varyingZ = 0, worstBlockZ = 0;
  bool pass() const {
    return std::fabs(wholeZ) < 4 && std::fabs(varyingZ) < 4 && std::fabs(worstBlockZ) < 5;
  }
};

std::vector<bool> varyingPixels(const Image& reference) {
  std::map<double, int> counts;
  for (double v : reference.values) ++counts[v];
  const double mode = std::max_element(counts.begin(), counts.end(), [](auto& a, auto& b) {
                        return a.second < b.second;
                      })->first;
  std::vector<bool> varying(reference.values.size());
  for (std::size_t i = 0; i < varying.size(); ++i) varying[i] = reference.values[i] != mode;
  return varying;
}

Comparison compare(const Image& test, const Image& reference, const std::vector<bool>& varying) {
  Comparison result;
  std::vector<double> all, someVarying;
  for (std::size_t i = 0; i < test.values.size(); ++i) {
    const double d = test.values[i] - reference.values[i];
    all.push_back(d);
    if (varying[i]) someVarying.push_back(d);
  }
  result.wholeZ = meanZ(all);
  result.varyingZ = meanZ(someVarying);
  const int block = 16;
  for (int by = 0; by < test.height; by += block)
    for (int bx = 0; bx < test.width; bx += block) {
      std::vector<double> deltas;
      for (int y = by; y < std::min(by + block, test.height); ++y)
        for (int x = bx; x < std::min(bx + block, test.width); ++x)
          for (int c = 0; c < test.channels; ++c) {
            const std::size_t i =
                (static_cast<std::size_t>(y) * test.width + x) * test.channels + c;
            if (varying[i]) deltas.push_back(test.values[i] - reference.values[i]);
          }
      if (deltas.size() < 64) continue;
      const double z = meanZ(deltas);
      if (std::fabs(z) > std::fabs(result.worstBlockZ)) result.worstBlockZ = z;
    }
  return result;
}

Image scaled(Image image, double factor, const std::vector<bool>* only) {
  for (std::size_t i = 0; i < image.values.size(); ++i)
    if (!only || (*only)[i]) image.values[i] *= factor;
  return image;
}

struct RegressionCase {
  const char* scene;
  int testSpp;
};

class RenderRegression : public ::testing::TestWithParam<RegressionCase> {};

std::string caseName(const ::testing::TestParamInfo<RegressionCase>& caseInfo) {
  return caseInfo.param.scene;
}

}  // namespace

TEST_P(RenderRegression, MatchesTheReferenceWithinNoiseAndDetectsAFivePercentChange) {
  const RegressionCase param = GetParam();
  const std::string root = HYLIOS_SOURCE_DIR;
  SceneDesc scene = loadSceneFile(root + "/scenes/test/" + param.scene + ".toml");
  scene.film.samplesPerPixel = param.testSpp;
  scene.integrator.seed += 1000;  // the references use the scene's own seed
  Film film(scene.film);
  std::vector<double> wavelengths;
  for (const FilmChannel& c : film.channels()) wavelengths.push_back(c.wavelengthNm);
  const Integrator integrator(scene, wavelengths);
  integrator.render(film, quietRenderOptions(param.scene));
  const Image test = fromFilm(film);
  const Image reference =
      readReference(root + "/tests/data/regression/" + param.scene + ".exr", film);
  ASSERT_EQ(reference.width, test.width);
  ASSERT_EQ(reference.height, test.height);
  const std::vector<bool> varying = varyingPixels(reference);

  const Comparison same = compare(test, reference, varying);
  EXPECT_TRUE(same.pass()) << "z whole " << same.wholeZ << ", varying " << same.varyingZ
                           << ", worst block " << same.worstBlockZ;
  for (const double factor : {1.05, 0.95}) {
    const Comparison all = compare(test, scaled(reference, factor, nullptr), varying);
    const Comparison skinOnly = compare(test, scaled(reference, factor, &varying), varying);
    EXPECT_FALSE(all.pass()) << "reference × " << factor << " passed: z " << all.wholeZ << ", "
                             << all.varyingZ;
    EXPECT_FALSE(skinOnly.pass()) << "varying pixels × " << factor << " passed: z "
                                  << skinOnly.wholeZ << ", " << skinOnly.varyingZ << ", block "
                                  << skinOnly.worstBlockZ;
    std::cout << param.scene << ": same z " << same.wholeZ << " / " << same.varyingZ << " / block "
              << same.worstBlockZ << "; varying × " << factor << " z " << skinOnly.varyingZ << "\n";
    EXPECT_GT(std::fabs(skinOnly.varyingZ), 5)
        << "a 5 % change is too close to the noise at " << param.testSpp << " spp";
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, RenderRegression,
                         ::testing::Values(RegressionCase{"skin_sphere_365", 64},
                                           RegressionCase{"skin_sphere_550", 32},
                                           RegressionCase{"skin_sphere_1100", 16},
                                           RegressionCase{"head_1650", 256}),
                         caseName);
