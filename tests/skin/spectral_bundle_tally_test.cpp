// SpectralBundleTally (skin/spectral_bundle_tally.h): without histograms its tallies are bit for
// bit those of one SkinTally::record per wavelength (the record it replaces), for paths of every
// end, with and without a split entry and layer absorption; a path split at a Rayleigh event is
// one sample of its branches' sums; with histograms it keeps per-wavelength tallies; mismatched
// or split paths where they cannot go and SkinTally::fromControlledMeans' misuse are errors.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "skin/core/random.h"
#include "skin/spectral_bundle_tally.h"
#include "tests/support/state_bytes.h"

namespace hylios::skin {
namespace {

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
        EXPECT_EQ(hylios::test::stateBytes(tallies[i]), hylios::test::stateBytes(each[i]));
        EXPECT_EQ(tallies[i].reflectance().mean, each[i].reflectance().mean);
        EXPECT_EQ(tallies[i].absorptance(Layer::StratumBasale).standardError,
                  each[i].absorptance(Layer::StratumBasale).standardError);
      }
    }
}

TEST(SpectralBundleTally, ASplitPathIsOneSampleOfItsBranchesSum) {
  // A path split at a Rayleigh event: per quantity the forward and backward branches' scores
  // add up, and so do their control weights (the entry's surface weight counted once).
  constexpr std::size_t kWavelengths = 5;
  const PathEnd ends[] = {PathEnd::SubsurfaceReflection, PathEnd::Absorbed, PathEnd::EventLimit};
  SpectralBundleTally bundle(kWavelengths, TallyOptions{});
  std::vector<SkinTally> each(kWavelengths, SkinTally(TallyOptions{}));
  Rng rng(6, 2, 0);
  for (std::uint64_t ray = 0; ray < 300; ++ray) {
    SpectralPath path = randomPath(kWavelengths, ends[ray % 3], true, true, rng);
    if (ray % 2 == 0) {
      path.split = true;
      path.splitAtEvent = path.events / 2;
      path.backward.push_back(randomPath(kWavelengths, ends[(ray / 2) % 3], false, true, rng));
    }
    bundle.record(path, ray);
    for (std::size_t i = 0; i < kWavelengths; ++i) {
      const SpectralPath* branches[2] = {&path, path.split ? &path.backward.front() : nullptr};
      double scores[SkinTally::kQuantities] = {};
      double control = path.surfaceWeight[i];
      for (const SpectralPath* b : branches) {
        if (!b) continue;
        const double w = b->exitWeight[i], sw = b == &path ? path.surfaceWeight[i] : 0.0;
        const bool surface = b->end == PathEnd::SurfaceReflection;
        const bool subsurface = b->end == PathEnd::SubsurfaceReflection;
        scores[SkinTally::kTotal] += (surface || subsurface ? w : 0.0) + sw;
        scores[SkinTally::kSurface] += (surface ? w : 0.0) + sw;
        scores[SkinTally::kSubsurface] += subsurface ? w : 0.0;
        scores[SkinTally::kTransmitted] += b->end == PathEnd::Transmitted ? w : 0.0;
        scores[SkinTally::kEventLimited] += b->end == PathEnd::EventLimit ? w : 0.0;
        scores[SkinTally::kAbsorbed] += b->absorbedTotal[i];
        for (std::size_t l = 0; l < kLayerCount; ++l) {
          scores[SkinTally::kFirstLayer + l] += b->absorbed[l * kWavelengths + i];
          scores[SkinTally::kMelanosome] += b->absorbedInMelanosomes[l * kWavelengths + i];
        }
        control += b->absorbedTotal[i] + w;
      }
      ControlledMeans one(SkinTally::kQuantities);  // the path as one sample of its sums
      one.add(scores, control, static_cast<unsigned>(ray & 1));
      each[i].merge(SkinTally::fromControlledMeans(TallyOptions{}, one, 0));
    }
  }
  const std::vector<SkinTally> tallies = bundle.tallies();
  for (std::size_t i = 0; i < kWavelengths; ++i) {
    EXPECT_EQ(tallies[i].rays(), 300u);
    for (auto estimate : {&SkinTally::reflectance, &SkinTally::subsurfaceReflectance,
                          &SkinTally::absorptance, &SkinTally::eventLimited}) {
      EXPECT_NEAR(((tallies[i]).*estimate)().mean, ((each[i]).*estimate)().mean, 1e-12) << i;
      EXPECT_NEAR(((tallies[i]).*estimate)().standardError, ((each[i]).*estimate)().standardError,
                  1e-12)
          << i;
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
    EXPECT_EQ(hylios::test::stateBytes(tallies[i]), hylios::test::stateBytes(each[i]));
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
  SpectralPath split = randomPath(3, PathEnd::SubsurfaceReflection, true, true, rng);
  split.split = true;  // without its branch
  EXPECT_THROW(bundle.record(split, 0), std::invalid_argument);
  TallyOptions radial;
  radial.radialBins = 4;
  SpectralBundleTally withHistograms(3, radial);
  split.backward.push_back(randomPath(3, PathEnd::Absorbed, false, true, rng));
  EXPECT_THROW(withHistograms.record(split, 0), std::logic_error);
  EXPECT_THROW(SkinTally::fromControlledMeans(radial, ControlledMeans(SkinTally::kQuantities), 0),
               std::invalid_argument);
  EXPECT_THROW(SkinTally::fromControlledMeans(TallyOptions{}, ControlledMeans(2), 0),
               std::invalid_argument);
}

}  // namespace
}  // namespace hylios::skin
