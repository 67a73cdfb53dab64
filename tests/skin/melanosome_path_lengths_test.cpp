// The tabulated melanosome absorption (issue 5): the path-length table against the traced
// interaction, hand limits, the chord law of a sphere, whole walks, and the exact walk's stream.
//
// Monte Carlo errors: a traced absorption frequency from M trials has σ = sqrt(p(1 − p)/M); the
// table's p1 = mean of (1 − e^{−κL}) over its N samples has σ = sd(1 − e^{−κL})/√N; independent
// estimates are compared within 4 combined σ = 4·sqrt(σ1² + σ2²).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include "skin/fresnel.h"
#include "skin/fresnel_pair.h"
#include "skin/melanosome_interaction.h"
#include "skin/melanosome_path_lengths.h"
#include "skin/sampling/polar_rejection_sampling.h"
#include "skin/skin_simulation.h"
#include "skin/specimen.h"
#include "skin/spectral_database.h"
#include "tests/support/chi2.h"
#include "tests/support/test_spectra.h"

using namespace hylios::skin;

namespace {

// ------------------------------------------------ the pre-refactor absorbedInOne, copied verbatim

/// MelanosomeLayer's constants as the pre-refactor class held them (a, c in one unit).
struct OldMelanosome {
  OldMelanosome(double a, double c, double muA, double nLayer, double nMelanin)
      : aspect_(c / a),
        inverseAspect_(a / c),
        muA_perMinorAxis_(muA * a),
        entering_(nLayer, nMelanin),
        leaving_(nMelanin, nLayer) {}
  double aspect_, inverseAspect_, muA_perMinorAxis_;
  FresnelPair entering_, leaving_;
};

Vec3 oldNormalAtImage(const Vec3& p, double inverseAspect) {
  const Vec3 gradient{p.x, p.y, p.z * inverseAspect};
  return gradient * (1.0 / std::sqrt(dot(gradient, gradient)));
}

/// MelanosomeLayer::absorbedInOne as it was before the geometry moved to
/// skin/melanosome_internal_walk.h (commit 8942654): the reference for its use of uniforms.
bool oldAbsorbedInOne(const OldMelanosome& m, Rng& rng) {
  const double gamma = m.aspect_;
  const double v = rng.uniform();
  const double cosAlpha = v * (gamma + 1.0) / (gamma + std::sqrt(gamma * gamma * (1.0 - v) + v));
  const double sinAlpha = std::sqrt((1.0 - cosAlpha) * (1.0 + cosAlpha));
  const Vec3 incoming{sinAlpha, 0.0, cosAlpha};
  const double imageZ = cosAlpha * m.inverseAspect_;
  const double inverseLength = 1.0 / std::sqrt(sinAlpha * sinAlpha + imageZ * imageZ);
  const double nx = sinAlpha * inverseLength, nz = imageZ * inverseLength;
  const DiskPoint disk = sampleUnitDisk(rng);
  const double depth = std::sqrt(1.0 - disk.radiusSquared);
  Vec3 image{disk.x * nz - depth * nx, disk.y, -disk.x * nx - depth * nz};
  Vec3 normal = oldNormalAtImage(image, m.inverseAspect_);
  double cosTransmitted = 0;
  const double entryReflectance = m.entering_.reflectance(dot(incoming, normal), cosTransmitted);
  if (rng.uniform() < entryReflectance) return false;
  Vec3 d = m.entering_.refract(incoming, normal, cosTransmitted);
  for (int bounce = 0; bounce < 10000; ++bounce) {
    const Vec3 imageD{d.x, d.y, d.z * m.inverseAspect_};
    const double alpha = dot(imageD, imageD), beta = dot(image, imageD);
    const double offset = dot(image, image) - 1.0;
    const double discriminant = beta * beta - alpha * offset;
    const double root = discriminant > 0.0 ? std::sqrt(discriminant) : 0.0;
    double chord = beta <= 0.0 ? (root - beta) / alpha : -offset / (beta + root);
    if (!(chord > 0.0)) chord = 0.0;
    if (m.muA_perMinorAxis_ > 0 && -std::log(1.0 - rng.uniform()) < m.muA_perMinorAxis_ * chord)
      return true;
    image += imageD * chord;
    normal = oldNormalAtImage(image, m.inverseAspect_);
    double unused = 0;
    const double wallReflectance = m.leaving_.reflectance(dot(d, normal), unused);
    if (rng.uniform() >= wallReflectance) return false;
    d = Frame(-normal).toWorld(sampleCosineHemisphereByDisk(rng));
  }
  return false;
}

/// p1 = 1 − q from the table with its standard error sd(1 − e^{−κL})/√N.
Estimate tableAbsorption(const MelanosomePathLengths& table, double kappa) {
  RunningStatistic s;
  for (double length : table.pathLengths()) s.add(-std::expm1(-kappa * length));
  return {table.absorptionProbability(kappa), s.standardError()};
}

Estimate tracedAbsorption(double aspect, double indexRatio, double kappa, int trials,
                          std::uint64_t seed) {
  const MelanosomeLayer layer(1.0, aspect, kappa, 1.0, indexRatio);  // a = 1: κ = μa·a
  Rng rng(seed);
  int absorbed = 0;
  for (int i = 0; i < trials; ++i) absorbed += layer.absorbedInOne(rng) ? 1 : 0;
  const double p = absorbed / static_cast<double>(trials);
  return {p, std::sqrt(p * (1.0 - p) / trials)};
}

}  // namespace

TEST(MelanosomeInternalWalk, AbsorbedInOneDrawsTheSameUniformsAsBeforeTheRefactor) {
  struct Case {
    double a, c, muA, nLayer, nMelanin;
  };
  // S1's basal melanosome (cm) at a weak and a strong coefficient, a clear one, a sphere,
  // a needle with a high index ratio, matched indices.
  const Case cases[] = {{0.085e-4, 0.205e-4, 1e4, 1.4, 1.7}, {0.085e-4, 0.205e-4, 1e6, 1.4, 1.7},
                        {0.085e-4, 0.205e-4, 0.0, 1.4, 1.7}, {1.0, 1.0, 0.7, 1.3, 1.9},
                        {1.0, 20.0, 0.05, 1.0, 1.5},         {1.0, 2.4, 0.3, 1.4, 1.4}};
  for (const Case& k : cases) {
    const MelanosomeLayer layer(k.a, k.c, k.muA, k.nLayer, k.nMelanin);
    const OldMelanosome old(k.a, k.c, k.muA, k.nLayer, k.nMelanin);
    Rng now(99), before(99);
    int absorbed = 0;
    for (int i = 0; i < 20000; ++i) {
      const bool outcome = layer.absorbedInOne(now);
      ASSERT_EQ(outcome, oldAbsorbedInOne(old, before)) << "call " << i << ", c/a = " << k.c / k.a;
      absorbed += outcome ? 1 : 0;
    }
    EXPECT_EQ(now.nextU64(), before.nextU64()) << "the streams drifted apart, c/a = " << k.c / k.a;
    if (k.muA > 0) {
      EXPECT_GT(absorbed, 0) << "the case tests absorption, c/a = " << k.c / k.a;
    }
  }
}

TEST(MelanosomePathLengths, TableAbsorptionMatchesTracedMelanosomes) {
  // 9 shapes × 4 coefficients; 1e5 traced trials each (σ ≤ 0.0016), the table N = 2^16.
  int comparison = 0;
  for (const double aspect : {1.0, 2.4, 20.0}) {
    for (const double ratio : {1.0, 1.214, 1.5}) {
      const auto table = MelanosomePathLengths::shared(aspect, ratio);
      for (const double kappa : {1e-4, 0.05, 1.0, 10.0}) {
        const Estimate fromTable = tableAbsorption(*table, kappa);
        const Estimate traced = tracedAbsorption(aspect, ratio, kappa, 100000, 1000 + comparison++);
        const double sigma = std::hypot(fromTable.standardError, traced.standardError);
        EXPECT_NEAR(fromTable.mean, traced.mean, 4.0 * sigma)
            << "γ = " << aspect << ", ρ = " << ratio << ", κ = " << kappa << ": table "
            << fromTable.mean << " ± " << fromTable.standardError << ", traced " << traced.mean
            << " ± " << traced.standardError;
        EXPECT_NEAR(table->survivalProbability(kappa), 1.0 - table->absorptionProbability(kappa),
                    1e-12);
      }
    }
  }
}

TEST(MelanosomePathLengths, MatchedSphereHasTheMeanChordOfASphere) {
  // ρ = 1, γ = 1: no Fresnel, one chord; a uniform point on the unit disk gives E[ℓ] = 4/3.
  const MelanosomePathLengths table(1.0, 1.0);
  const Estimate mean = table.meanPathLength();
  // sd(ℓ) = sqrt(E[ℓ²] − 16/9) = sqrt(2 − 16/9) ≈ 0.471, so s.e. ≈ 0.0018 at N = 2^16.
  EXPECT_NEAR(mean.standardError, std::sqrt(2.0 - 16.0 / 9.0) / std::sqrt(65536.0), 2e-4);
  EXPECT_NEAR(mean.mean, 4.0 / 3.0, 4.0 * mean.standardError)
      << mean.mean << " ± " << mean.standardError;
  EXPECT_EQ(table.reflectedAtEntryFraction(), 0.0);
}

TEST(MelanosomePathLengths, MatchedSphereChordsFollowTheirDensity) {
  // ℓ = 2·sqrt(1 − r²) with r² uniform: P(ℓ ≤ x) = P(1 − r² ≤ x²/4) = x²/4, density x/2 on [0, 2].
  const MelanosomePathLengths table(1.0, 1.0, 20000);
  const auto density = [](double x) { return x >= 0 && x <= 2 ? 0.5 * x : 0.0; };
  const auto result =
      hylios::test::chi2Test1D(table.pathLengths(), density, hylios::test::uniformEdges(0, 2, 40));
  EXPECT_TRUE(hylios::test::chi2Accepts(result));
}

TEST(MelanosomePathLengths, SmallCoefficientAbsorbsInProportionToTheMeanPath) {
  // 1 − e^{−κL} = κL − κ²L²/2 + …, so |p1/κ − mean(L)| ≤ κ·mean(L²)/2 on the same sample.
  const auto table = MelanosomePathLengths::shared(2.4, 1.214);
  double meanSquare = 0;
  for (double length : table->pathLengths()) meanSquare += length * length;
  meanSquare /= static_cast<double>(table->sampleCount());
  const double kappa = 1e-6;
  EXPECT_NEAR(table->absorptionProbability(kappa) / kappa, table->meanPathLength().mean,
              kappa * meanSquare);
  EXPECT_GT(table->meanPathLength().mean, 0.5);
}

TEST(MelanosomePathLengths, OpaqueSphereAbsorbsAllButTheEntryReflection) {
  // κ → ∞: p1 → 1 − P(reflected at entry). For a sphere hit uniformly over its disk, cos θ of the
  // entry has density 2cosθ, so P = ∫ R(c)·2c dc (Fresnel, 1 → 1.214).
  const double ratio = 1.214;
  const MelanosomePathLengths table(1.0, ratio);
  const double expected = hylios::test::integrate(
      [ratio](double c) { return 2.0 * c * fresnelReflectance(c, 1.0, ratio); }, 0.0, 1.0, 1e-12);
  const double sigma = std::sqrt(expected * (1.0 - expected) / 65536.0);  // ≈ 0.00055
  EXPECT_NEAR(table.reflectedAtEntryFraction(), expected, 4.0 * sigma) << "hand value " << expected;
  EXPECT_DOUBLE_EQ(table.absorptionProbability(1e9), 1.0 - table.reflectedAtEntryFraction());
  EXPECT_DOUBLE_EQ(table.survivalProbability(0.0), 1.0);
}

TEST(MelanosomePathLengths, CountsCombineAsIndependentMelanosomes) {
  const auto table = MelanosomePathLengths::shared(2.4, 1.214);
  const double q = table->survivalProbability(0.3);
  EXPECT_EQ(table->absorptionProbability(0.3, 0), 0.0);
  EXPECT_NEAR(table->absorptionProbability(0.3, 1), 1.0 - q, 1e-14);
  EXPECT_NEAR(table->absorptionProbability(0.3, 7), 1.0 - std::pow(q, 7), 1e-13);
  EXPECT_DOUBLE_EQ(MelanosomePathLengths::absorptionByCount(0.25, 2), 1.0 - 0.75 * 0.75);
  EXPECT_EQ(MelanosomePathLengths::absorptionByCount(1.0, 4), 1.0);
  EXPECT_EQ(MelanosomePathLengths::absorptionByCount(1.0, 0), 0.0);
  EXPECT_NEAR(MelanosomePathLengths::absorptionByCount(1e-12, 100), 1e-10,
              1e-20);  // no cancellation
  EXPECT_THROW(MelanosomePathLengths::absorptionByCount(1.5, 2), std::invalid_argument);
  EXPECT_NEAR(table->absorptionProbability(1e300, 3),
              1.0 - std::pow(table->reflectedAtEntryFraction(), 3), 1e-12);
}

TEST(MelanosomePathLengths, SharedTablesAreDeterministicAndThreadSafe) {
  const auto first = MelanosomePathLengths::shared(2.4, 1.3, 4096);
  EXPECT_EQ(first, MelanosomePathLengths::shared(2.4, 1.3, 4096));
  EXPECT_NE(first, MelanosomePathLengths::shared(2.4, 1.3, 4097));
  const MelanosomePathLengths fresh(2.4, 1.3, 4096);
  EXPECT_EQ(fresh.pathLengths(), first->pathLengths());  // the fixed stream: bit for bit
  std::vector<std::shared_ptr<const MelanosomePathLengths>> got(4);
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < got.size(); ++i)
    threads.emplace_back([&got, i] { got[i] = MelanosomePathLengths::shared(3.0, 1.25, 2048); });
  for (auto& t : threads) t.join();
  for (const auto& table : got) EXPECT_EQ(table, got[0]);
}

TEST(MelanosomePathLengths, RejectsBadInput) {
  EXPECT_THROW(MelanosomePathLengths(0.5, 1.2), std::invalid_argument);
  EXPECT_THROW(MelanosomePathLengths(2.0, 0.0), std::invalid_argument);
  EXPECT_THROW(MelanosomePathLengths(2.0, 1.2, 1), std::invalid_argument);
  EXPECT_THROW(MelanosomePathLengths::shared(std::nan(""), 1.2), std::invalid_argument);
  const auto table = MelanosomePathLengths::shared(2.4, 1.214);
  EXPECT_THROW(table->survivalProbability(-1.0), std::invalid_argument);
  EXPECT_THROW(table->absorptionProbability(INFINITY), std::invalid_argument);
}

namespace {
/// A basal layer of complexes holding 3 melanosomes each (S1-like melanosome).
SkinOptics complexOptics(double interiorMuA_perCm) {
  SkinOptics optics;
  optics.melaninRefractiveIndex = 1.7;
  optics.melanosomeInteriorMuA_perCm = interiorMuA_perCm;
  optics.meanScatteringAngleRad = 0.2;
  LayerOptics& basal = optics.layers[index(Layer::StratumBasale)];
  basal.thicknessCm = 0.001;
  basal.refractiveIndex = 1.4;
  basal.melanosome = {0.085e-4, 0.205e-4, true, 0.2e-4, 3, 100.0};
  return optics;
}
}  // namespace

TEST(MelanosomeLayerTabulated, InteractionsAbsorbLikeTracedOnes) {
  const SkinOptics optics = complexOptics(1e5);
  const MelanosomeLayer traced(optics, Layer::StratumBasale);
  const MelanosomeLayer tabulated(optics, Layer::StratumBasale, MelanosomeAbsorption::Tabulated);
  // The layer's table: γ = 0.205/0.085, ρ = 1.7/1.4 (its key is rounded to 12 digits, so the
  // lengths agree to ~1e-12), κ = 1e5 cm⁻¹ × 0.085e-4 cm; 3 melanosomes absorb with 1 − q³.
  const MelanosomePathLengths table(0.205 / 0.085, 1.7 / 1.4);
  const double q = table.survivalProbability(1e5 * 0.085e-4);
  const double expected = 1.0 - q * q * q;
  EXPECT_NEAR(tabulated.tabulatedAbsorption(), expected, 1e-9);
  EXPECT_THROW(traced.tabulatedAbsorption(), std::logic_error);
  EXPECT_EQ(tabulated.melanosomesPerInteraction(), 3u);
  EXPECT_EQ(traced.melanosomesPerInteraction(), 3u);
  Rng tracedRng(5), tabulatedRng(6);
  const int trials = 100000;
  int tracedAbsorbed = 0, tabulatedAbsorbed = 0;
  std::uint64_t tracedMet = 0;
  for (int i = 0; i < trials; ++i) {
    const MelanosomeEvent t = traced.interact(Vec3{0, 0, 1}, tracedRng);
    ASSERT_TRUE(t.melanosomesMet >= 1 && t.melanosomesMet <= 3) << t.melanosomesMet;
    ASSERT_TRUE(t.absorbed || t.melanosomesMet == 3);  // only absorption stops it early
    tracedMet += t.melanosomesMet;
    tracedAbsorbed += t.absorbed ? 1 : 0;
    const MelanosomeEvent event = tabulated.interact(Vec3{0, 0, 1}, tabulatedRng);
    ASSERT_EQ(event.melanosomesMet, 3u);
    tabulatedAbsorbed += event.absorbed ? 1 : 0;
    if (!event.absorbed) {
      ASSERT_NEAR(dot(event.direction, event.direction), 1.0, 1e-12);
    }
  }
  const double pTraced = tracedAbsorbed / double(trials),
               pTabulated = tabulatedAbsorbed / double(trials);
  const double sigma =
      std::sqrt(expected * (1 - expected) / trials);  // ≈ 0.0016; the table's own is smaller
  EXPECT_NEAR(pTabulated, expected, 4.0 * sigma);
  EXPECT_NEAR(pTraced, expected, 4.0 * std::sqrt(2.0) * sigma) << "table " << expected;
  EXPECT_GT(expected, 0.1);
  // The traced interaction meets 1 + q + q² melanosomes on average (each survived with q;
  // per trial at most 3, so σ of the mean ≤ 1/√trials ≈ 0.0032).
  EXPECT_NEAR(static_cast<double>(tracedMet) / trials, 1 + q + q * q, 0.01);
}

namespace {
using hylios::test::spectra;
}  // namespace

TEST(SkinWalkTabulated, WholeWalksAgreeWithTracedMelanosomes) {
  // 30000 rays per run (σ_R ≤ 0.0029), independent seeds: σ_diff = sqrt(σ1² + σ2²).
  double largestMelanosomeAbsorptance = 0;
  for (const std::string name : {"S1", "S4"}) {
    const Specimen specimen =
        loadSpecimen(name, std::string(HYLIOS_SOURCE_DIR) + "/scenes/specimens");
    for (const double nm : {365.0, 550.0, 1100.0, 1650.0}) {
      const SkinOptics optics = computeSkinOptics(specimen, spectra(), nm);
      WalkRunOptions run;
      run.incidenceDeg = 45;
      run.rays = 30000;
      run.seed = 31;
      const SkinTally traced = simulateSkin(optics, run);
      run.seed = 32;
      run.walk.tabulatedMelanosomes = true;
      const SkinTally tabulated = simulateSkin(optics, run);
      const auto compare = [&](Estimate a, Estimate b, const char* what) {
        const double sigma = std::hypot(a.standardError, b.standardError);
        EXPECT_NEAR(a.mean, b.mean, 4.0 * sigma)
            << name << " " << nm << " nm " << what << ": traced " << a.mean << ", tabulated "
            << b.mean << ", σ " << sigma;
      };
      compare(traced.reflectance(), tabulated.reflectance(), "reflectance");
      compare(traced.melanosomeAbsorptance(), tabulated.melanosomeAbsorptance(),
              "melanosome absorptance");
      largestMelanosomeAbsorptance =
          std::max(largestMelanosomeAbsorptance, traced.melanosomeAbsorptance().mean);
    }
  }
  EXPECT_GT(largestMelanosomeAbsorptance, 0.1);  // melanosomes matter in the cases compared
}
