// SpectralBundleTally (skin/spectral_bundle_tally.h): without histograms its tallies are bit for
// bit those of one SkinTally::record per wavelength (the record it replaces), for paths of every
// end, with and without a split entry and layer absorption; with histograms it keeps per-wavelength
// tallies; mismatched paths and SkinTally::fromControlledMeans' misuse are errors.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "skin/core/random.h"
#include "skin/spectral_bundle_tally.h"

namespace hylios::skin {
namespace {

std::string bytesOf(const SkinTally& t) {
  std::string bytes;
  t.appendBytes(bytes);
  return bytes;
}

/// A path of `n` wavelengths with random weights (some 0, absorbed = ratio − exits may be < 0).
SpectralPath randomPath(std::size_t n, PathEnd end, bool split, bool layers, Rng& rng) {
  SpectralPath path;
  path.end = end;
  path.events = 1 + static_cast<std::uint32_t>(40 * rng.uniform());
  path.exitDirection = Vec3{0.1, 0.2, -0.97};
  for (std::size_t i = 0; i < n; ++i) {
    const double ratio = 2 * rng.uniform();
    const double exit =
        end == PathEnd::Absorbed || rng.uniform() < 0.2 ? 0.0 : ratio * rng.uniform();
    path.exitWeight.push_back(exit);
    path.absorbedTotal.push_back(ratio - exit);
    if (split) path.surfaceWeight.push_back(0.05 * rng.uniform());
  }
  if (layers)
    for (std::size_t j = 0; j < kLayerCount * n; ++j) {  // layer by layer (SpectralPath)
      path.absorbed.push_back(rng.uniform() < 0.3 ? 0.0 : 0.1 * rng.uniform());
      path.absorbedInMelanosomes.push_back(rng.uniform() * path.absorbed.back());
    }
  return path;
}

/// What one SkinTally::record per wavelength makes of the path (the scores of PathScore's fields).
void recordEachWavelength(const SpectralPath& path, std::uint64_t ray,
                          std::vector<SkinTally>& tallies) {
  for (std::size_t i = 0; i < tallies.size(); ++i) {
    PathScore score = pathScoreOf(path);
    score.hasControlWeight = true;
    score.fold = static_cast<unsigned>(ray & 1);
    score.exitWeight = path.exitWeight[i];
    score.surfaceWeight = path.surfaceWeight.empty() ? 0.0 : path.surfaceWeight[i];
    score.absorbed = path.absorbedTotal[i];
    score.controlWeight = score.absorbed + score.exitWeight + score.surfaceWeight;
    if (!path.absorbed.empty())
      for (std::size_t l = 0; l < kLayerCount; ++l) {
        score.absorbedByLayer[l] = path.absorbed[l * tallies.size() + i];
        score.absorbedInMelanosomes += path.absorbedInMelanosomes[l * tallies.size() + i];
      }
    tallies[i].record(score);
  }
}

TEST(SpectralBundleTally, SumsAreThoseOfOneRecordPerWavelength) {
  constexpr std::size_t kWavelengths = 13;
  const PathEnd ends[] = {PathEnd::SurfaceReflection, PathEnd::SubsurfaceReflection,
                          PathEnd::Transmitted, PathEnd::Absorbed, PathEnd::EventLimit};
  for (bool split : {false, true})
    for (bool layers : {false, true}) {
      SpectralBundleTally bundle(kWavelengths, TallyOptions{});
      std::vector<SkinTally> each(kWavelengths, SkinTally(TallyOptions{}));
      Rng rng(3, split * 2 + layers, 0);
      for (std::uint64_t ray = 0; ray < 400; ++ray) {
        const SpectralPath path = randomPath(kWavelengths, ends[ray % 5], split, layers, rng);
        bundle.record(path, ray);
        recordEachWavelength(path, ray, each);
      }
      const std::vector<SkinTally> tallies = bundle.tallies();
      ASSERT_EQ(tallies.size(), kWavelengths);
      for (std::size_t i = 0; i < kWavelengths; ++i) {
        SCOPED_TRACE("split " + std::to_string(split) + ", layers " + std::to_string(layers) +
                     ", wavelength " + std::to_string(i));
        EXPECT_TRUE(tallies[i].controlled());
        EXPECT_EQ(tallies[i].rays(), 400u);
        EXPECT_EQ(tallies[i].meanEvents(), each[i].meanEvents());
        EXPECT_EQ(bytesOf(tallies[i]), bytesOf(each[i]));
        EXPECT_EQ(tallies[i].reflectance().mean, each[i].reflectance().mean);
        EXPECT_EQ(tallies[i].absorptance(Layer::StratumBasale).standardError,
                  each[i].absorptance(Layer::StratumBasale).standardError);
      }
    }
}

TEST(SpectralBundleTally, HistogramsKeepATallyPerWavelength) {
  TallyOptions options;
  options.polarBins = 3;
  options.azimuthBins = 2;
  SpectralBundleTally bundle(4, options);
  std::vector<SkinTally> each(4, SkinTally(options));
  Rng rng(8, 1, 0);
  for (std::uint64_t ray = 0; ray < 50; ++ray) {
    SpectralPath path = randomPath(4, PathEnd::SubsurfaceReflection, true, false, rng);
    path.surfaceDirection = Vec3{0, 0.6, -0.8};
    bundle.record(path, ray);
    for (std::size_t i = 0; i < 4; ++i) {
      PathScore score = pathScoreOf(path);
      score.hasControlWeight = true;
      score.fold = static_cast<unsigned>(ray & 1);
      score.exitWeight = path.exitWeight[i];
      score.surfaceWeight = path.surfaceWeight[i];
      score.surfaceDirection = path.surfaceDirection;
      score.absorbed = path.absorbedTotal[i];
      score.controlWeight = score.absorbed + score.exitWeight + score.surfaceWeight;
      each[i].record(score);
    }
  }
  const std::vector<SkinTally> tallies = bundle.tallies();
  for (std::size_t i = 0; i < 4; ++i) {
    ASSERT_TRUE(tallies[i].subsurfaceDirections().has_value());
    EXPECT_EQ(bytesOf(tallies[i]), bytesOf(each[i]));
  }
}

TEST(SpectralBundleTally, MismatchedPathsAndSumsAreErrors) {
  Rng rng(1, 1, 1);
  SpectralBundleTally bundle(3, TallyOptions{});
  EXPECT_THROW(bundle.record(randomPath(2, PathEnd::SurfaceReflection, false, false, rng), 0),
               std::invalid_argument);
  SpectralPath lopsided = randomPath(3, PathEnd::SurfaceReflection, true, true, rng);
  lopsided.absorbedInMelanosomes.pop_back();
  EXPECT_THROW(bundle.record(lopsided, 0), std::invalid_argument);
  TallyOptions radial;
  radial.radialBins = 4;
  EXPECT_THROW(SkinTally::fromControlledMeans(radial, ControlledMeans(SkinTally::kQuantities), 0),
               std::invalid_argument);
  EXPECT_THROW(SkinTally::fromControlledMeans(TallyOptions{}, ControlledMeans(2), 0),
               std::invalid_argument);
}

}  // namespace
}  // namespace hylios::skin
