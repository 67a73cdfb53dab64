// The spectral walk (one path, many wavelengths) against the per-wavelength analog walk it
// replaces: same expectation for every wavelength, specimen and incidence. Each comparison's z is
// the difference over the combined standard error (each side's error from its own per-path
// scores); a test's scores are judged as one family, |z| ≤ 4.32 for 630 of them (1 % false
// alarms, Bonferroni: tests/support/score_family.h). Measured over 13 seed pairs (32,760 scores): z
// has mean 0.02 and standard deviation 0.99, with 85 beyond 3 (88 expected) and 3 beyond 4 (2.1
// expected).
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "skin/core/constants.h"
#include "skin/skin_simulation.h"
#include "skin/specimen.h"
#include "skin/spectral_bundle.h"
#include "skin/spectral_simulation.h"
#include "skin/spectral_walk.h"
#include "tests/support/chi2.h"
#include "tests/support/score_family.h"
#include "tests/support/test_spectra.h"

using namespace hylios::skin;

namespace {

/// Two-sample chi-square of two histograms' bins: each difference over the summed variance of the
/// two estimates. A bin is used only where the analog estimate `analog` rests on at least 25 rays
/// ((mean / standard error)², its effective count): below that its standard error is no estimate
/// of its spread (a bin with no ray has 0), and one such bin alone can pass the 0.1 % point.
/// Returns whether the statistic stays below the upper 0.1 % point for the bins used. Measured over
/// 300 seed pairs of each of the two tests below (2100 statistics): 1 below p = 0.001 (2.1
/// expected) and 20 below p = 0.01 (21 expected); per bin, the spread of the spectral estimates
/// over the seeds matches their mean standard error to within 0.8–1.3 in variance.
::testing::AssertionResult binsAgree(const Histogram& spectral, const Histogram& analog) {
  double statistic = 0;
  int bins = 0;
  for (std::size_t bin = 0; bin < analog.binCount(); ++bin) {
    const Estimate x = spectral.estimate(bin), y = analog.estimate(bin);
    if (y.standardError == 0 || (y.mean / y.standardError) * (y.mean / y.standardError) < 25)
      continue;
    const double variance = x.standardError * x.standardError + y.standardError * y.standardError;
    statistic += (x.mean - y.mean) * (x.mean - y.mean) / variance;
    ++bins;
  }
  const double p = bins > 0 ? hylios::test::chi2SurvivalProbability(statistic, bins) : 0;
  if (p >= 1e-3) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "chi2 = " << statistic << " over " << bins << " bins, p = " << p;
}

// 21 wavelengths over 250–2500 nm: UV, the hemoglobin bands, the θo ramp (780–1400 nm) and
// its end, the water bands at 1450 and 1940 nm.
const std::vector<double> kWavelengthsNm = {250,  300,  365,  420,  500,  550,  577,
                                            650,  700,  780,  900,  1000, 1100, 1200,
                                            1300, 1400, 1450, 1650, 1940, 2200, 2500};

std::vector<SkinOptics> opticsAt(const std::string& specimen,
                                 const std::vector<double>& wavelengths) {
  const Specimen s = loadSpecimen(specimen, hylios::test::specimenDir());
  std::vector<SkinOptics> optics;
  for (double w : wavelengths) optics.push_back(computeSkinOptics(s, hylios::test::spectra(), w));
  return optics;
}

double z(const Estimate& a, const Estimate& b) {
  return hylios::test::zScore(a.mean - b.mean, std::hypot(a.standardError, b.standardError));
}

/// z of a spectral estimate against a per-wavelength one made of `rays` 0/1 scores: the analog
/// side's error is the binomial sqrt(p(1 − p)/n) at the pooled mean, so a rare outcome that the
/// analog walk never saw (0 ± 0) is judged by what its count could have been.
double zAgainstAnalog(const Estimate& spectral, const Estimate& analog, std::uint64_t rays) {
  const double p = 0.5 * (spectral.mean + analog.mean);
  const double analogError = std::sqrt(std::fmax(p * (1 - p), 0.0) / static_cast<double>(rays));
  return z(spectral, {analog.mean, std::fmax(analog.standardError, analogError)});
}

/// Adds every quantity of the two tallies to the family of scores.
void compare(const SkinTally& spectral, const SkinTally& analog, const std::string& where,
             hylios::test::ScoreFamily& family) {
  auto check = [&](const std::string& what, const Estimate& a, const Estimate& b) {
    std::ostringstream text;
    text << where << " " << what << ": spectral " << a.mean << " ± " << a.standardError
         << ", per-wavelength " << b.mean << " ± " << b.standardError;
    family.add(text.str(), zAgainstAnalog(a, b, analog.rays()));
  };
  check("R", spectral.reflectance(), analog.reflectance());
  check("R surface", spectral.surfaceReflectance(), analog.surfaceReflectance());
  check("R subsurface", spectral.subsurfaceReflectance(), analog.subsurfaceReflectance());
  check("A", spectral.absorptance(), analog.absorptance());
  for (Layer layer : kAllLayers)
    check("A " + std::string(layerName(layer)), spectral.absorptance(layer),
          analog.absorptance(layer));
}

/// Spectral and per-wavelength walks of `specimen` at 0°, 45° and 80° over `wavelengths`.
void expectSameAsPerWavelength(const std::string& specimen, std::uint64_t rays,
                               const WalkOptions& walk = {}, const BundleRule& rule = {},
                               const std::vector<double>& wavelengths = kWavelengthsNm) {
  const std::vector<SkinOptics> optics = opticsAt(specimen, wavelengths);
  hylios::test::ScoreFamily family;
  for (double angle : {0.0, 45.0, 80.0}) {
    SpectralRunOptions spectral;
    spectral.incidenceDeg = angle;
    spectral.rays = rays;
    spectral.seed = 11;
    spectral.walk = walk;
    spectral.bundles = rule;
    const std::vector<SkinTally> s = simulateSkinSpectral(optics, spectral);
    for (std::size_t i = 0; i < optics.size(); ++i) {
      WalkRunOptions analog;
      analog.incidenceDeg = angle;
      analog.rays = rays;
      analog.seed = 12;
      std::ostringstream where;
      where << specimen << " " << wavelengths[i] << " nm " << angle << "°";
      compare(s[i], simulateSkin(optics[i], analog), where.str(), family);
      EXPECT_EQ(s[i].eventLimited().mean, 0.0) << where.str();
    }
  }
  EXPECT_EQ(family.size(), 30 * wavelengths.size());
  family.expectWithinFamilyWiseBound();
}

}  // namespace

// 21 wavelengths × 3 angles × 10 quantities per specimen; 6000 paths each side (σ(R) ≈ 0.005).
TEST(SpectralWalk, S1MatchesPerWavelengthWalk) { expectSameAsPerWavelength("S1", 6000); }
TEST(SpectralWalk, S2MatchesPerWavelengthWalk) { expectSameAsPerWavelength("S2", 6000); }
TEST(SpectralWalk, S3MatchesPerWavelengthWalk) { expectSameAsPerWavelength("S3", 6000); }
TEST(SpectralWalk, S4MatchesPerWavelengthWalk) { expectSameAsPerWavelength("S4", 6000); }

// The split at the first Rayleigh event (WalkOptions::splitFirstRayleigh) in every bundle, θo > 0
// included (the curves split only where θo = 0): the same 630 scores per specimen.
TEST(SpectralWalk, RayleighSplitMatchesPerWavelengthWalkS1) {
  WalkOptions walk;
  walk.splitFirstRayleigh = true;
  expectSameAsPerWavelength("S1", 6000, walk);
}
TEST(SpectralWalk, RayleighSplitMatchesPerWavelengthWalkS4) {
  WalkOptions walk;
  walk.splitFirstRayleigh = true;
  expectSameAsPerWavelength("S4", 6000, walk);
}

// Heroes in shares by law (WalkOptions::heroSharesByLaw) in the curves' wide bundles: 31
// wavelengths 75 nm apart over 250–2500 nm (250, 1450, 2500 among them; 785–1375 nm in the θo
// ramp), so that the bundles hold members of different θo and τ: 930 scores per specimen.
std::vector<double> everySeventyFiveNm() {
  std::vector<double> wavelengths;
  for (double w = 250; w <= 2500; w += 75) wavelengths.push_back(w);
  return wavelengths;
}
void expectHeroSharesSameAsPerWavelength(const std::string& specimen) {
  WalkOptions walk;
  walk.heroSharesByLaw = true;
  BundleRule rule;
  rule.maxLogAngleSpread = 0.6;
  rule.maxRayleighSpread = 1.2;
  const std::vector<double> wavelengths = everySeventyFiveNm();
  const std::vector<SkinOptics> optics = opticsAt(specimen, wavelengths);
  ASSERT_LT(groupIntoBundles(optics, walk, rule).size(), 12u);  // members share paths
  expectSameAsPerWavelength(specimen, 6000, walk, rule, wavelengths);
}
TEST(SpectralWalk, HeroSharesMatchPerWavelengthWalkS1) {
  expectHeroSharesSameAsPerWavelength("S1");
}
TEST(SpectralWalk, HeroSharesMatchPerWavelengthWalkS4) {
  expectHeroSharesSameAsPerWavelength("S4");
}

TEST(SpectralWalk, EveryMisRatioHasMeanOneWithUniformAndLawShares) {
  // The tallies' control variate corrects a ratio of the wrong scale almost exactly (each score
  // is about R·U), so the comparisons above would not see heroes drawn with shares the balance
  // heuristic does not use; the ratio's own mean must be 1 for every member. S1 at 45°, 30
  // members of the θo ramp (785–1075 nm, ln θo spread 0.64), 20 000 paths each way.
  std::vector<double> wavelengths;
  for (double w = 785; w <= 1075; w += 10) wavelengths.push_back(w);
  const std::vector<SkinOptics> optics = opticsAt("S1", wavelengths);
  hylios::test::ScoreFamily family;
  for (bool shares : {false, true}) {
    WalkOptions options;
    options.heroSharesByLaw = shares;
    options.tabulatedMelanosomes = true;
    const SpectralWalk walk(optics, options);
    std::vector<double> sum(optics.size(), 0.0), sumSquares(optics.size(), 0.0);
    SpectralPath path;
    constexpr int kPaths = 20000;
    const double angle = 45.0 * hylios::kPi / 180.0;
    for (int k = 0; k < kPaths; ++k) {
      Rng rng(21, shares ? 2 : 1, static_cast<std::uint64_t>(k));
      walk.trace(Vec3{std::sin(angle), 0.0, std::cos(angle)}, rng, path);
      for (std::size_t i = 0; i < optics.size(); ++i) {
        const double u = path.exitWeight[i] + path.absorbedTotal[i] +
                         (path.surfaceWeight.empty() ? 0.0 : path.surfaceWeight[i]);
        sum[i] += u;
        sumSquares[i] += u * u;
      }
    }
    for (std::size_t i = 0; i < optics.size(); ++i) {
      const double mean = sum[i] / kPaths;
      const double error = std::sqrt((sumSquares[i] / kPaths - mean * mean) / (kPaths - 1));
      std::ostringstream what;
      what << wavelengths[i] << " nm, " << (shares ? "law" : "uniform") << " shares: mean ratio "
           << mean << " ± " << error;
      family.add(what.str(), hylios::test::zScore(mean - 1.0, error));
    }
  }
  family.expectWithinFamilyWiseBound();
}

TEST(SpectralWalk, RayleighSplitHalvesTheWaterBandsVariance) {
  // S1 at 45°, 1400 nm in its curve bundle (1400–1715 nm): measured at 10⁵ rays, σ(R) 0.00078
  // unsplit and 0.00053 split (variance 2.2× lower). At 20 000 rays each σ is estimated to
  // about 1.5 % (the spread of its per-path scores), so a ratio below 0.8 is a margin of more
  // than 7 of those errors; R + T + A stays 1 exactly (the branches' control weights add up).
  std::vector<double> wavelengths;
  for (double w = 1400; w <= 1715; w += 5) wavelengths.push_back(w);
  const std::vector<SkinOptics> optics = opticsAt("S1", wavelengths);
  WalkRunOptions run;
  run.incidenceDeg = 45;
  run.rays = 20000;
  SpectralRunOptions split = commandSpectralRun(run), unsplit = split;
  ASSERT_TRUE(split.splitRayleighWithoutDeflection);
  unsplit.splitRayleighWithoutDeflection = false;
  const std::vector<SkinTally> a = simulateSkinSpectral(optics, split);
  const std::vector<SkinTally> b = simulateSkinSpectral(optics, unsplit);
  EXPECT_LT(a[0].reflectance().standardError, 0.8 * b[0].reflectance().standardError);
  EXPECT_LE(std::fabs(z(a[0].reflectance(), b[0].reflectance())), 4.0);
  for (const SkinTally& t : a)
    EXPECT_NEAR(t.reflectance().mean + t.transmittance().mean + t.absorptance().mean, 1.0, 1e-12);
}

TEST(SpectralWalk, RayleighSplitPathsCarryTwoHalves) {
  // At 1400 nm (τ_Rayleigh ≈ 0.8) many paths split; each branch's MIS ratio is halved, so for a
  // one-wavelength bundle the branches' absorbed + exit weights are ½ of the entered ratio each,
  // the entry's surface weight stays on the forward branch alone, and the branches share the
  // events before the split. Without the option no path splits.
  const std::vector<SkinOptics> optics = opticsAt("S1", {1400});
  WalkOptions walk;
  walk.tabulatedMelanosomes = true;
  walk.splitEntryReflection = true;
  walk.splitFirstRayleigh = true;
  const SpectralWalk splitting(optics, walk);
  walk.splitFirstRayleigh = false;
  const SpectralWalk plain(optics, walk);
  SpectralPath path;
  int splits = 0;
  for (std::uint64_t i = 0; i < 2000; ++i) {
    Rng rng(4, 4, i);
    plain.trace(incidentDirection(45), rng, path);
    EXPECT_FALSE(path.split);
    Rng again(4, 4, i);
    splitting.trace(incidentDirection(45), again, path);
    if (!path.split) continue;
    ++splits;
    const SpectralPath& back = path.backward.front();
    // A forced entry's ratio is 1 − F (F = the surface weight scored at the entry).
    const double entered = 1.0 - (path.surfaceWeight.empty() ? 0.0 : path.surfaceWeight[0]);
    EXPECT_NEAR(path.absorbedTotal[0] + path.exitWeight[0], 0.5 * entered, 1e-12);
    EXPECT_NEAR(back.absorbedTotal[0] + back.exitWeight[0], 0.5 * entered, 1e-12);
    EXPECT_TRUE(back.surfaceWeight.empty());
    EXPECT_GE(back.events, path.splitAtEvent);
    EXPECT_GE(path.events, path.splitAtEvent);
  }
  EXPECT_GT(splits, 500);  // P(a Rayleigh event on the first pass) ≈ 0.5 here
}

TEST(SpectralWalk, SplitEntryReflectionKeepsEveryExpectation) {
  // The renders' entry split: surface reflection scored as an expected value, transmission forced.
  WalkOptions walk;
  walk.splitEntryReflection = true;
  expectSameAsPerWavelength("S2", 6000, walk);
}

TEST(SpectralWalk, TabulatedMelanosomesMatchTheExactWalk) {
  // The fast default draws each melanosome's internal path from a 2¹⁸-path table.
  const std::vector<double> wavelengths = {365, 550, 1100};
  for (const char* specimen : {"S1", "S4"}) {
    const std::vector<SkinOptics> optics = opticsAt(specimen, wavelengths);
    SpectralRunOptions spectral;
    spectral.incidenceDeg = 45;
    spectral.rays = 20000;
    spectral.walk.tabulatedMelanosomes = true;
    const std::vector<SkinTally> s = simulateSkinSpectral(optics, spectral);
    for (std::size_t i = 0; i < optics.size(); ++i) {
      WalkRunOptions analog;
      analog.incidenceDeg = 45;
      analog.rays = 20000;
      const SkinTally a = simulateSkin(optics[i], analog);
      EXPECT_LE(std::fabs(z(s[i].reflectance(), a.reflectance())), 4.0)
          << specimen << " " << wavelengths[i];
      EXPECT_LE(
          std::fabs(z(s[i].absorptance(Layer::StratumBasale), a.absorptance(Layer::StratumBasale))),
          4.0)
          << specimen << " " << wavelengths[i];
    }
  }
}

TEST(SpectralWalk, TruncatedStackTransmittanceAndDirectionsMatch) {
  // Fig. 8's epidermis over air: the smooth bottom into a fixed index (λ-dependent Fresnel) and
  // the transmitted-direction histogram, compared bin by bin (two-sample chi-square, 20 bins).
  const std::vector<SkinOptics> optics = opticsAt("S2", {290, 302, 315, 330});
  WalkOptions walk;
  walk.deepestLayer = Layer::StratumBasale;
  walk.belowRefractiveIndex = 1.0;
  TallyOptions tally;
  tally.polarBins = 20;
  SpectralRunOptions spectral;
  spectral.rays = 30000;
  spectral.walk = walk;
  spectral.tally = tally;
  const std::vector<SkinTally> s = simulateSkinSpectral(optics, spectral);
  ASSERT_EQ(groupIntoBundles(optics, walk).size(), 1u);  // one bundle: the ratios are exercised
  for (std::size_t i = 0; i < optics.size(); ++i) {
    WalkRunOptions analog;
    analog.rays = 30000;
    analog.walk = walk;
    analog.tally = tally;
    const SkinTally a = simulateSkin(optics[i], analog);
    EXPECT_LE(std::fabs(z(s[i].transmittance(), a.transmittance())), 4.0) << optics[i].wavelengthNm;
    EXPECT_TRUE(binsAgree(*s[i].transmittedDirections(), *a.transmittedDirections()))
        << optics[i].wavelengthNm;
  }
}

TEST(SpectralWalk, ReflectionDirectionsAndRadialProfileMatch) {
  const std::vector<SkinOptics> optics = opticsAt("S1", {540, 550, 560});
  TallyOptions tally;
  tally.polarBins = 9;
  tally.azimuthBins = 4;
  tally.radialBins = 12;
  tally.maxRadiusCm = 0.3;
  SpectralRunOptions spectral;
  spectral.incidenceDeg = 45;
  spectral.rays = 30000;
  spectral.tally = tally;
  const std::vector<SkinTally> s = simulateSkinSpectral(optics, spectral);
  WalkRunOptions analog;
  analog.incidenceDeg = 45;
  analog.rays = 30000;
  analog.tally = tally;
  const SkinTally a = simulateSkin(optics[1], analog);
  EXPECT_TRUE(binsAgree(*s[1].surfaceDirections(), *a.surfaceDirections()));
  EXPECT_TRUE(binsAgree(*s[1].subsurfaceDirections(), *a.subsurfaceDirections()));
  EXPECT_TRUE(binsAgree(*s[1].radialExits(), *a.radialExits()));
}

TEST(SpectralWalk, SameSeedSameResultAtOneAndTwoThreads) {
  const std::vector<SkinOptics> optics = opticsAt("S3", {400, 405, 410, 1100, 1105, 2000});
  SpectralRunOptions spectral;
  spectral.incidenceDeg = 30;
  spectral.rays = 3000;
  spectral.splitRayleighWithoutDeflection = true;  // 2000 nm: split paths
  std::vector<SkinTally> one, two;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = simulateSkinSpectral(optics, spectral);
  }
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    two = simulateSkinSpectral(optics, spectral);
  }
  for (std::size_t i = 0; i < optics.size(); ++i) {
    EXPECT_EQ(one[i].reflectance().mean, two[i].reflectance().mean);
    EXPECT_EQ(one[i].reflectance().standardError, two[i].reflectance().standardError);
    EXPECT_EQ(one[i].absorptance(Layer::PapillaryDermis).mean,
              two[i].absorptance(Layer::PapillaryDermis).mean);
  }
}

TEST(SpectralWalk, MelanosomeAbsorptionOffLeavesEveryOtherOutcomeBitForBit) {
  // Without melanin's share booked the paths and every other outcome are the same bits; the
  // melanosome absorptance is then not scored (0), and booked it is positive and below the total.
  const std::vector<SkinOptics> optics = opticsAt("S2", {400, 405, 410, 1500, 1505});
  SpectralRunOptions booked;
  booked.incidenceDeg = 20;
  booked.rays = 2000;
  SpectralRunOptions unbooked = booked;
  unbooked.walk.melanosomeAbsorption = false;
  const std::vector<SkinTally> with = simulateSkinSpectral(optics, booked);
  const std::vector<SkinTally> without = simulateSkinSpectral(optics, unbooked);
  for (std::size_t i = 0; i < optics.size(); ++i) {
    EXPECT_EQ(with[i].reflectance().mean, without[i].reflectance().mean);
    EXPECT_EQ(with[i].reflectance().standardError, without[i].reflectance().standardError);
    for (Layer layer : kAllLayers)
      EXPECT_EQ(with[i].absorptance(layer).mean, without[i].absorptance(layer).mean);
    EXPECT_EQ(without[i].melanosomeAbsorptance().mean, 0.0);
    EXPECT_GT(with[i].melanosomeAbsorptance().mean, 0.0);
    EXPECT_LT(with[i].melanosomeAbsorptance().mean, with[i].absorptance().mean);
  }
  const std::vector<SkinOptics> visible(optics.begin(), optics.begin() + 3);  // θo > 0
  SpectralWalk walk(visible, unbooked.walk);
  SpectralPath path;
  Rng rng(5);
  walk.trace(incidentDirection(20), rng, path);
  EXPECT_TRUE(path.absorbedInMelanosomes.empty());
  EXPECT_EQ(path.absorbed.size(), kLayerCount * visible.size());
}

TEST(SpectralWalk, OneWavelengthAloneOrInABundleHasTheSameExpectation) {
  // A bundle of one carries no ratios; the same λ inside a bundle of 16 must agree within noise.
  const std::vector<SkinOptics> bundle = opticsAt(
      "S1", {500, 505, 510, 515, 520, 525, 530, 535, 540, 545, 550, 555, 560, 565, 570, 575});
  SpectralWalk together(bundle);
  SpectralWalk alone(std::vector<SkinOptics>{bundle[5]});
  RunningStatistic inBundle, single;
  SpectralPath path;
  for (std::uint64_t i = 0; i < 20000; ++i) {
    Rng a(3, 1, i), b(3, 2, i);
    together.trace(incidentDirection(45), a, path);
    inBundle.add(path.exitWeight[5] + (path.surfaceWeight.empty() ? 0.0 : path.surfaceWeight[5]));
    alone.trace(incidentDirection(45), b, path);
    single.add(path.exitWeight[0] + (path.surfaceWeight.empty() ? 0.0 : path.surfaceWeight[0]));
  }
  EXPECT_LE(std::fabs(z(inBundle.estimate(), single.estimate())), 4.0);
}

TEST(SpectralWalk, RefusesOpticsThatCannotShareAPath) {
  std::vector<SkinOptics> optics = opticsAt("S1", {550, 560});
  optics[1].layers[index(Layer::StratumSpinosum)].thicknessCm *= 2;
  EXPECT_THROW(SpectralWalk{optics}, std::invalid_argument);
  std::vector<SkinOptics> angles = opticsAt("S1", {1300, 1450});  // θo > 0 and θo = 0
  EXPECT_THROW(SpectralWalk{angles}, std::invalid_argument);
  WalkOptions smooth;
  smooth.roughSurface = false;
  // (Wavelengths whose water index differs: Hale & Querry's n is flat over 550–575 nm.)
  EXPECT_THROW((SpectralWalk{opticsAt("S1", {400, 450}), smooth}), std::invalid_argument);
  EXPECT_THROW(SpectralWalk{std::vector<SkinOptics>{}}, std::invalid_argument);
}

TEST(SpectralBundle, GroupsByAngleRayleighDepthAndSize) {
  std::vector<double> wavelengths;
  for (double w = 250; w <= 2500; w += 5) wavelengths.push_back(w);
  const std::vector<SkinOptics> optics = opticsAt("S1", wavelengths);
  const BundleRule rule;
  const auto bundles = groupIntoBundles(optics, {}, rule);
  std::size_t total = 0;
  for (const auto& bundle : bundles) {
    total += bundle.size();
    ASSERT_LE(bundle.size(), rule.maxWavelengths);
    double lowTheta = INFINITY, highTheta = 0;
    for (std::size_t i : bundle) {
      lowTheta = std::min(lowTheta, optics[i].meanScatteringAngleRad);
      highTheta = std::max(highTheta, optics[i].meanScatteringAngleRad);
    }
    EXPECT_EQ(lowTheta == 0, highTheta == 0);  // θo = 0 never shares with θo > 0
    if (lowTheta > 0) {
      EXPECT_LE(std::log(highTheta / lowTheta), rule.maxLogAngleSpread + 1e-12);
    }
    for (std::size_t k = 1; k < bundle.size(); ++k)
      EXPECT_LT(optics[bundle[k - 1]].wavelengthNm, optics[bundle[k]].wavelengthNm);
  }
  EXPECT_EQ(total, wavelengths.size());
  EXPECT_LT(bundles.size(), 40u);  // the whole curve shares paths (451 wavelengths)
  WalkOptions smooth;
  smooth.roughSurface = false;  // a smooth surface refracts every index elsewhere: one λ per bundle
  EXPECT_EQ(groupIntoBundles(opticsAt("S1", {400, 450, 500}), smooth).size(), 3u);
}

TEST(SpectralBundle, UndeflectedMembersAreGroupedByAbsorptionDepth) {
  // 1400–2500 nm (θo = 0): bundles of at most 16 take the members in increasing absorption depth,
  // so each bundle's depths lie below the next one's, while each bundle is in increasing λ.
  std::vector<double> wavelengths;
  for (double w = 1400; w <= 2500; w += 10) wavelengths.push_back(w);
  const std::vector<SkinOptics> optics = opticsAt("S1", wavelengths);
  const WalkOptions walk;
  BundleRule rule;
  rule.maxWavelengths = 16;
  const auto bundles = groupIntoBundles(optics, walk, rule);
  ASSERT_EQ(bundles.size(), (wavelengths.size() + 15) / 16);
  double previousDeepest = 0;
  for (const auto& bundle : bundles) {
    double shallowest = INFINITY, deepest = 0;
    for (std::size_t i : bundle) {
      ASSERT_EQ(optics[i].meanScatteringAngleRad, 0.0);
      shallowest = std::min(shallowest, absorptionDepth(optics[i], walk));
      deepest = std::max(deepest, absorptionDepth(optics[i], walk));
    }
    EXPECT_GE(shallowest, previousDeepest);
    previousDeepest = deepest;
    for (std::size_t k = 1; k < bundle.size(); ++k)
      EXPECT_LT(optics[bundle[k - 1]].wavelengthNm, optics[bundle[k]].wavelengthNm);
  }
  // Not contiguous in λ: the water bands' members (1450, 1940 nm) share the last bundles.
  const auto& last = bundles.back();
  EXPECT_GT(optics[last.back()].wavelengthNm - optics[last.front()].wavelengthNm, 16 * 10.0);
}

TEST(SpectralBundle, AbsorptionDepthSumsTheWalkedLayersAtNormalIncidence) {
  SkinOptics o = opticsAt("S1", {500}).front();
  double expected = 0;
  double muA_perCm = 1.0;  // hand values: 1, 2, … 6 per cm from the surface down
  for (Layer layer : kAllLayers) {
    o.layers[index(layer)].muATotal_perCm = muA_perCm;
    expected += muA_perCm * o.layers[index(layer)].thicknessCm;
    muA_perCm += 1.0;
  }
  EXPECT_NEAR(absorptionDepth(o, {}), expected, 1e-15 * expected);
  WalkOptions papillary;
  papillary.deepestLayer = Layer::PapillaryDermis;
  EXPECT_NEAR(absorptionDepth(o, papillary),
              expected - 6.0 * o.layers[index(Layer::ReticularDermis)].thicknessCm,
              1e-15 * expected);
}

TEST(SpectralBundle, RayleighDepthSumsTheWalkedLayersAtNormalIncidence) {
  SkinOptics o = opticsAt("S1", {500}).front();
  for (Layer layer : kAllLayers) o.layers[index(layer)].muRayleigh_perCm = 0;
  o.layers[index(Layer::StratumBasale)].muRayleigh_perCm = 2;  // 2/cm × its thickness
  o.layers[index(Layer::PapillaryDermis)].muRayleigh_perCm = 10;
  o.layers[index(Layer::ReticularDermis)].muRayleigh_perCm = 5;
  o.layers[index(Layer::StratumBasale)].thicknessCm = 0.01;
  o.layers[index(Layer::PapillaryDermis)].thicknessCm = 0.02;
  o.layers[index(Layer::ReticularDermis)].thicknessCm = 0.1;
  WalkOptions walk;
  EXPECT_NEAR(rayleighDepth(o, walk), 0.02 + 0.2 + 0.5, 1e-15);
  walk.deepestLayer = Layer::PapillaryDermis;  // the reticular dermis is not walked
  EXPECT_NEAR(rayleighDepth(o, walk), 0.02 + 0.2, 1e-15);
  walk.rayleigh = false;
  EXPECT_EQ(rayleighDepth(o, walk), 0.0);
}
