// Exit distributions: bin geometry in closed form, the combination of estimates, and the
// per-steradian / per-area densities against walks and samples whose answers are known exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "skin/core/constants.h"
#include "skin/exit_distribution.h"
#include "skin/fresnel.h"
#include "skin/sampling/cosine_sampling.h"
#include "skin/skin_simulation.h"
#include "tests/support/chi2.h"
#include "tests/support/clear_optics.h"

using hylios::kPi;

using namespace hylios::skin;

namespace {

using hylios::test::clearOptics;

WalkRunOptions smoothRun(double angleDeg, std::uint64_t rays) {
  WalkRunOptions run;
  run.incidenceDeg = angleDeg;
  run.rays = rays;
  run.seed = 11;
  run.walk.roughSurface = false;
  return run;
}

}  // namespace

TEST(DirectionBins, SolidAnglesSumToTheHemisphere) {
  for (auto [polar, azimuth] :
       {std::pair<std::size_t, std::size_t>{1, 1}, {18, 36}, {7, 5}, {90, 1}}) {
    const DirectionBins bins(polar, azimuth);
    double solid = 0, projected = 0;
    for (std::size_t i = 0; i < polar; ++i) {
      solid += bins.solidAngleSr(i) * static_cast<double>(azimuth);
      projected += bins.projectedSolidAngleSr(i) * static_cast<double>(azimuth);
    }
    EXPECT_NEAR(solid, 2 * kPi, 1e-12) << polar << "×" << azimuth;
    EXPECT_NEAR(projected, kPi, 1e-12) << polar << "×" << azimuth;
  }
  // One hand value: the 0–5° ring in 36 azimuth bins: (1 − cos 5°)·2π/36 = 6.6415e-4 sr.
  EXPECT_NEAR(DirectionBins(18, 36).solidAngleSr(0), (1 - std::cos(5 * kPi / 180)) * 2 * kPi / 36,
              1e-15);
  EXPECT_NEAR(DirectionBins(18, 36).solidAngleSr(0), 6.6415e-4, 1e-8);
  EXPECT_THROW(DirectionBins(0, 4), std::invalid_argument);
  EXPECT_THROW(DirectionBins(4, 4).flatIndex(4, 0), std::out_of_range);
}

TEST(DirectionBins, InPlaneAzimuthBins) {
  // 36 bins: φ = 0 is the edge between bins 17 and 18, φ = ±180° the edge between 35 and 0.
  EXPECT_EQ(DirectionBins(1, 36).azimuthBinsNear(0.0), (std::vector<std::size_t>{17, 18}));
  EXPECT_EQ(DirectionBins(1, 36).azimuthBinsNear(kPi), (std::vector<std::size_t>{0, 35}));
  // 5 bins: bin 2 is centred on φ = 0; φ = 180° is the edge between bins 4 and 0.
  EXPECT_EQ(DirectionBins(1, 5).azimuthBinsNear(0.0), (std::vector<std::size_t>{2}));
  EXPECT_EQ(DirectionBins(1, 5).azimuthBinsNear(kPi), (std::vector<std::size_t>{0, 4}));
  EXPECT_EQ(DirectionBins(1, 1).azimuthBinsNear(0.0), (std::vector<std::size_t>{0}));
}

TEST(EstimateAlgebra, ExclusiveSumEqualsTheDirectTally) {
  // 10 packets: 3 score in bin A, 2 in bin B, none in both. A∪B: 5 of 10.
  Histogram h(0, 2, 2);
  RunningStatistic direct;
  for (int p = 0; p < 10; ++p) {
    h.countPacket();
    if (p < 3) h.addToBin(0, 1.0);
    if (p >= 3 && p < 5) h.addToBin(1, 1.0);
    direct.add(p < 5 ? 1.0 : 0.0);
  }
  const Estimate sum = sumOfExclusive({h.estimate(0), h.estimate(1)}, h.packets());
  EXPECT_NEAR(sum.mean, 0.5, 1e-15);
  // sqrt(0.5·0.5/9) = 0.1666…
  EXPECT_NEAR(sum.standardError, direct.standardError(), 1e-14);
  EXPECT_NEAR(sum.standardError, 1.0 / 6.0, 1e-14);
}

TEST(EstimateAlgebra, RatioAndMean) {
  // a = 0.2 ± 0.01, b = 0.4 ± 0.02 from 101 packets: r = 0.5,
  // σ² = (0.01² + 0.25·0.02² + 2·0.5·0.2·0.4/100) / 0.4² = (1e-4 + 1e-4 + 8e-4)/0.16 = 6.25e-3.
  const Estimate r = ratioOfExclusive({0.2, 0.01}, {0.4, 0.02}, 101);
  EXPECT_NEAR(r.mean, 0.5, 1e-15);
  EXPECT_NEAR(r.standardError, std::sqrt(6.25e-3), 1e-12);
  EXPECT_THROW(ratioOfExclusive({0.2, 0.01}, {0.0, 0.0}, 10), std::domain_error);
  // Independent: σ² = (1e-4 + 1e-4)/0.16 = 1.25e-3; a = 0 gives 0 ± σa/|b|.
  const Estimate independent = ratioOfIndependent({0.2, 0.01}, {0.4, 0.02});
  EXPECT_NEAR(independent.mean, 0.5, 1e-15);
  EXPECT_NEAR(independent.standardError, std::sqrt(1.25e-3), 1e-12);
  const Estimate zero = ratioOfIndependent({0.0, 0.01}, {0.4, 0.02});
  EXPECT_EQ(zero.mean, 0.0);
  EXPECT_NEAR(zero.standardError, 0.025, 1e-15);
  EXPECT_THROW(ratioOfIndependent({0.2, 0.01}, {0.0, 0.0}), std::domain_error);
  // Mean of 1 ± 0.3 and 3 ± 0.4: 2 ± 0.5/2.
  const Estimate m = meanOfIndependent({{1, 0.3}, {3, 0.4}});
  EXPECT_NEAR(m.mean, 2.0, 1e-15);
  EXPECT_NEAR(m.standardError, 0.25, 1e-15);
  EXPECT_THROW(meanOfIndependent({}), std::invalid_argument);
}

TEST(ReflectionDistribution, DiffuseJunctionUnderAClearMatchedStackIsLambertian) {
  // n = 1 everywhere, smooth surface, nothing absorbs or scatters: every ray reaches the
  // hypodermis junction and comes back with density cosθ/π per sr, so BRDF·cos = cosθ/π and the
  // BRDF is 1/π in every bin. Chi-square on the counts of all 18×36 bins (expected count of a bin
  // = N·Ω⊥/π, the smallest ≈ 21 for 100 000 rays).
  const std::uint64_t rays = 100000;
  WalkRunOptions run = smoothRun(30, rays);
  run.tally.polarBins = 18;
  run.tally.azimuthBins = 36;
  const SkinTally tally = simulateSkin(clearOptics(1.0), run);
  ASSERT_EQ(tally.subsurfaceReflectance().mean, 1.0);
  const ReflectionDistribution d = reflectionDistribution(tally);
  const DirectionBins bins(18, 36);
  std::vector<double> observed, expected;
  double worstZ = 0;
  for (std::size_t i = 0; i < bins.polarBins(); ++i) {
    for (std::size_t j = 0; j < bins.azimuthBins(); ++j) {
      const std::size_t b = bins.flatIndex(i, j);
      const double p = bins.projectedSolidAngleSr(i) / kPi;  // probability of the bin
      observed.push_back(tally.subsurfaceDirections()->estimate(b).mean *
                         static_cast<double>(rays));
      expected.push_back(p * static_cast<double>(rays));
      EXPECT_EQ(d.perSteradian.surface[b].mean, 0.0);
      EXPECT_EQ(d.perSteradian.total[b].mean, d.perSteradian.subsurface[b].mean);
      // z-test of the BRDF against 1/π with σ = √(p(1−p)/N)/Ω⊥ (≈ 22 % of 1/π in the rim bins,
      // 0.8 % near the normal): the largest of 648 |z| stays below 4.5 (false alarm ≈ 0.4 %).
      // The reported σ is the binomial one of the observed fraction p̂: √(p̂(1−p̂)/(N−1))/Ω⊥.
      const double sigma =
          std::sqrt(p * (1 - p) / static_cast<double>(rays)) / bins.projectedSolidAngleSr(i);
      const double observedP = tally.subsurfaceDirections()->estimate(b).mean;
      const double reportedSigma =
          std::sqrt(observedP * (1 - observedP) / static_cast<double>(rays - 1)) /
          bins.projectedSolidAngleSr(i);
      EXPECT_NEAR(d.brdf.subsurface[b].standardError, reportedSigma, 1e-9 * reportedSigma)
          << "bin " << b;
      worstZ = std::max(worstZ, std::fabs(d.brdf.subsurface[b].mean - 1 / kPi) / sigma);
    }
  }
  EXPECT_LT(worstZ, 4.5);
  EXPECT_TRUE(hylios::test::chi2Accepts(hylios::test::chi2FromCounts(observed, expected), 0.001));
  // The in-plane cut (2 azimuth bins each side) against cosθ/π at the bin-averaged cosine.
  const InPlaneCut& cut = d.inPlanePerSteradian;
  ASSERT_EQ(cut.signedPolarDeg.size(), 36u);
  EXPECT_NEAR(cut.signedPolarDeg.front(), -87.5, 1e-12);
  EXPECT_NEAR(cut.signedPolarDeg.back(), 87.5, 1e-12);
  for (std::size_t k = 0; k < cut.total.size(); ++k) {
    const std::size_t i = k < 18 ? 17 - k : k - 18;
    const double value = bins.projectedSolidAngleSr(i) / bins.solidAngleSr(i) / kPi;
    EXPECT_NEAR(cut.total[k].mean, value, 4.5 * cut.total[k].standardError)
        << cut.signedPolarDeg[k];
  }
}

TEST(ReflectionDistribution, SmoothSurfaceReflectsIntoTheSpecularBinOnThePositiveSide) {
  // n = 1.4 under a smooth surface at 32°: the surface part F(32°) all lands in polar bin 6
  // (30–35°) at φ = 0 (azimuth bin 18 of 36), i.e. +32.5° of the in-plane cut.
  const std::uint64_t rays = 40000;
  WalkRunOptions run = smoothRun(32, rays);
  run.tally.polarBins = 18;
  run.tally.azimuthBins = 36;
  const ReflectionDistribution d = reflectionDistribution(simulateSkin(clearOptics(1.4), run));
  const DirectionBins bins(18, 36);
  const double fresnel = fresnelReflectance(std::cos(32 * kPi / 180), 1.0, 1.4);        // ≈ 0.030
  const double sigma = std::sqrt(fresnel * (1 - fresnel) / static_cast<double>(rays));  // ≈ 8.5e-4
  EXPECT_NEAR(d.surfaceReflectance.mean, fresnel, 4 * sigma);
  const std::size_t specular = bins.flatIndex(6, 18);
  EXPECT_DOUBLE_EQ(d.perSteradian.surface[specular].mean * bins.solidAngleSr(6),
                   d.surfaceReflectance.mean);
  // In the cut: mean over the two bins either side of φ = 0 → half the bin's per-sr value.
  const InPlaneCut& cut = d.inPlanePerSteradian;
  EXPECT_NEAR(cut.signedPolarDeg[18 + 6], 32.5, 1e-12);
  EXPECT_DOUBLE_EQ(cut.surface[18 + 6].mean, 0.5 * d.perSteradian.surface[specular].mean);
  EXPECT_EQ(cut.surface[17 - 6].mean, 0.0);  // −32.5°: toward the source
  // Total = surface + subsurface, bin by bin.
  for (std::size_t b = 0; b < bins.count(); ++b)
    EXPECT_NEAR(d.perSteradian.total[b].mean,
                d.perSteradian.surface[b].mean + d.perSteradian.subsurface[b].mean, 1e-12);
}

TEST(ReflectionDistribution, MeanOverWavelengthsAveragesBinByBin) {
  TallyOptions options{2, 2, 0, 0.5};
  SkinTally a(options), b(options);
  SkinPath up;
  up.end = PathEnd::SubsurfaceReflection;
  up.exitDirection = {0, 0, -1};  // polar bin 0
  SkinPath lost;
  lost.end = PathEnd::Absorbed;
  for (int i = 0; i < 4; ++i) a.record(i < 2 ? up : lost);  // 1/2 in bin 0 at λ1
  for (int i = 0; i < 4; ++i) b.record(i < 1 ? up : lost);  // 1/4 at λ2
  const ReflectionDistribution mean =
      meanOverWavelengths({reflectionDistribution(a), reflectionDistribution(b)});
  const std::size_t bin = a.directionBin(up.exitDirection);  // polar bin 0
  const double omega = DirectionBins(2, 2).solidAngleSr(0);
  EXPECT_NEAR(mean.perSteradian.subsurface[bin].mean, 0.375 / omega, 1e-12);
  EXPECT_NEAR(mean.subsurfaceReflectance.mean, 0.375, 1e-15);
  EXPECT_THROW(meanOverWavelengths({}), std::invalid_argument);
  EXPECT_THROW(reflectionDistribution(SkinTally()), std::invalid_argument);
}

TEST(TransmissionProfile, CosineTransmissionGivesTheBinAveragedCosine) {
  // Directions drawn with density cosθ/π and recorded as transmitted: per sr = Ω⊥/(πΩ) per ring,
  // relative to the first ring = (Ω⊥ᵢ/Ωᵢ)/(Ω⊥₀/Ω₀) ≈ cos θᵢ. z-test each ring with its reported
  // σ (|z| < 4 for each of 18 rings: false alarm ≈ 0.1 %); transmittance 1/2 exactly.
  TallyOptions options{18, 1, 0, 0.5};
  SkinTally tally(options);
  Rng rng(3, 4, 5);
  const int packets = 200000;
  for (int p = 0; p < packets; ++p) {
    SkinPath path;
    path.end = p % 2 == 0 ? PathEnd::Transmitted : PathEnd::Absorbed;
    path.exitDirection = sampleCosineHemisphere(rng.uniform(), rng.uniform());
    tally.record(path);
  }
  const TransmissionProfile profile = transmissionProfile(tally);
  EXPECT_DOUBLE_EQ(profile.transmittance.mean, 0.5);
  const DirectionBins bins(18, 1);
  const double first = bins.projectedSolidAngleSr(0) / bins.solidAngleSr(0);
  double total = 0;
  for (std::size_t i = 0; i < 18; ++i) {
    const double perSr = 0.5 * bins.projectedSolidAngleSr(i) / bins.solidAngleSr(i) / kPi;
    EXPECT_NEAR(profile.perSteradian[i].mean, perSr, 4 * profile.perSteradian[i].standardError)
        << i;
    const double relative = bins.projectedSolidAngleSr(i) / bins.solidAngleSr(i) / first;
    if (i > 0) {
      EXPECT_NEAR(profile.relativeToNormal[i].mean, relative,
                  4 * profile.relativeToNormal[i].standardError)
          << i;
    }
    total += profile.perSteradian[i].mean * profile.solidAngleSr[i];
  }
  EXPECT_DOUBLE_EQ(profile.relativeToNormal[0].mean, 1.0);
  EXPECT_NEAR(total, 0.5, 1e-12);
}

TEST(TransmissionProfile, ClearMatchedEpidermisTransmitsEverything) {
  // n = 1 everywhere and below: nothing reflects or absorbs, T = 1 exactly, all along the normal.
  WalkRunOptions run = smoothRun(0, 5000);
  run.walk.deepestLayer = Layer::StratumBasale;
  run.walk.belowRefractiveIndex = 1.0;
  run.tally.polarBins = 18;
  const TransmissionProfile profile = transmissionProfile(simulateSkin(clearOptics(1.0), run));
  EXPECT_EQ(profile.transmittance.mean, 1.0);
  EXPECT_DOUBLE_EQ(profile.perSteradian[0].mean * profile.solidAngleSr[0], 1.0);
  // Index 1.4 matched below: only the top surface reflects, T = 1 − F(0°) = 1 − (0.4/2.4)².
  const std::uint64_t rays = 40000;
  run = smoothRun(0, rays);
  run.walk.deepestLayer = Layer::StratumBasale;
  run.walk.belowRefractiveIndex = 1.4;
  run.tally.polarBins = 18;
  const TransmissionProfile matched = transmissionProfile(simulateSkin(clearOptics(1.4), run));
  const double expected = 1 - std::pow(0.4 / 2.4, 2);  // 0.97222
  const double sigma =
      std::sqrt(expected * (1 - expected) / static_cast<double>(rays));  // ≈ 8.2e-4
  EXPECT_NEAR(matched.transmittance.mean, expected, 4 * sigma);
  // At 40° incidence nothing leaves near the normal: no normalisation, a clear error.
  run = smoothRun(40, 1000);
  run.walk.deepestLayer = Layer::StratumBasale;
  run.tally.polarBins = 18;
  EXPECT_THROW(transmissionProfile(simulateSkin(clearOptics(1.0), run)), std::domain_error);
}

TEST(RadialProfile, DiffuseJunctionUnderAClearStackFollowsTheClosedForm) {
  // Clear stack of total depth D = 0.06 cm, n = 1, normal incidence: a ray goes straight down and
  // comes back at θ (cosine law) to r = D tanθ, so P(r < R) = R²/(R² + D²) and
  // R(r) = D²/(π (r² + D²)²). Chi-square of the 50 annuli + the overflow against it.
  const double depthCm = 0.06, maxRadiusCm = 0.3;
  const std::uint64_t rays = 100000;
  WalkRunOptions run = smoothRun(0, rays);
  run.tally.radialBins = 50;
  run.tally.maxRadiusCm = maxRadiusCm;
  const SkinTally tally = simulateSkin(clearOptics(1.0), run);
  const RadialProfile profile = radialProfile(tally);
  auto cumulative = [&](double r) { return r * r / (r * r + depthCm * depthCm); };
  std::vector<double> observed, expected;
  double integral = 0;
  for (std::size_t i = 0; i < profile.perCm2.size(); ++i) {
    const double area = annulusAreaCm2(profile.innerCm[i], profile.outerCm[i]);
    integral += profile.perCm2[i].mean * area;
    observed.push_back(profile.fraction[i].mean * static_cast<double>(rays));
    expected.push_back((cumulative(profile.outerCm[i]) - cumulative(profile.innerCm[i])) *
                       static_cast<double>(rays));
  }
  observed.push_back(profile.beyondMaxRadius.mean * static_cast<double>(rays));
  expected.push_back((1 - cumulative(maxRadiusCm)) * static_cast<double>(rays));  // ≈ 3.8 %
  EXPECT_TRUE(hylios::test::chi2Accepts(hylios::test::chi2FromCounts(observed, expected), 0.001));
  // Σ R(r)·area + the exits beyond the last annulus = R_d (the same rays, so up to rounding).
  EXPECT_NEAR(integral + profile.beyondMaxRadius.mean, profile.subsurfaceReflectance.mean, 1e-12);
  EXPECT_EQ(profile.subsurfaceReflectance.mean, 1.0);
  EXPECT_DOUBLE_EQ(profile.outerCm.back(), maxRadiusCm);
  EXPECT_EQ(profile.innerCm.front(), 0.0);
  // Near the centre, R(0) → 1/(π D²) = 88.4 cm⁻²: the first annulus (r < 6 mm·0.01) within 4σ.
  const double firstExpected =
      (cumulative(profile.outerCm[0])) / annulusAreaCm2(0, profile.outerCm[0]);
  EXPECT_NEAR(profile.perCm2[0].mean, firstExpected, 4 * profile.perCm2[0].standardError);
  EXPECT_THROW(radialProfile(SkinTally()), std::invalid_argument);
}

TEST(RadialProfile, AnnulusArea) {
  EXPECT_NEAR(annulusAreaCm2(1, 2), 3 * kPi, 1e-15);
  EXPECT_EQ(annulusAreaCm2(0, 0), 0.0);
  EXPECT_THROW(annulusAreaCm2(2, 1), std::invalid_argument);
  EXPECT_THROW(annulusAreaCm2(-1, 1), std::invalid_argument);
}
