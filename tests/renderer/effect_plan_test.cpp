// The effect planner (skin/effect_plan.h): optical depths against closed forms, ε = 0 changes
// nothing, the default ε keeps the reflectance of S1–S4 within its stated bound, explain() and
// argument checks.
//
// Monte Carlo errors: R from N rays has σ = sqrt(R(1−R)/N) (the tally's standard error); the
// planned and the full walk draw their numbers differently, so their difference has
// σ_diff = sqrt(σ1² + σ2²).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "renderer/tracing/skin_walk_cache.h"
#include "skin/core/constants.h"
#include "skin/effect_plan.h"
#include "skin/melanosome_interaction.h"
#include "skin/skin_simulation.h"
#include "skin/specimen.h"
#include "skin/spectral_database.h"
#include "tests/support/test_spectra.h"

using hylios::kPi;

using namespace hylios::skin;

namespace {

const std::string kRoot = HYLIOS_SOURCE_DIR;

using hylios::test::spectra;

SkinOptics specimenOptics(const std::string& name, double wavelengthNm) {
  return computeSkinOptics(loadSpecimen(name, kRoot + "/scenes/specimens"), spectra(),
                           wavelengthNm);
}

SkinTally run(const SkinOptics& optics, const WalkOptions& walk, std::uint64_t rays,
              std::uint64_t seed) {
  WalkRunOptions options;
  options.rays = rays;
  options.seed = seed;
  options.walk = walk;
  return simulateSkin(optics, options);
}

/// One matched (n = 1), smooth, transmitting layer of `thicknessCm` absorbing by water only.
SkinOptics singleAbsorbingLayer(double muA_perCm, double thicknessCm) {
  SkinOptics optics;
  optics.wavelengthNm = 500;
  optics.surfaceAspectRatio = 0.1;
  optics.melaninRefractiveIndex = 1.7;
  for (auto& layer : optics.layers) layer.refractiveIndex = 1.0;
  LayerOptics& top = optics.layers[index(Layer::StratumCorneum)];
  top.thicknessCm = thicknessCm;
  top.muA_perCm[index(Absorber::Water)] = muA_perCm;
  top.muATotal_perCm = muA_perCm;
  return optics;
}

WalkOptions smoothSingleLayer() {
  WalkOptions walk;
  walk.roughSurface = false;
  walk.deepestLayer = Layer::StratumCorneum;
  return walk;
}

const PlannedEffect* find(const EffectPlan& plan, Process process, Layer layer,
                          Absorber absorber = Absorber::Water) {
  for (const PlannedEffect& e : plan.effects)
    if (e.process == process &&
        (process == Process::SurfaceRoughness ||
         (e.layer == layer && (process != Process::Absorption || e.absorber == absorber))))
      return &e;
  return nullptr;
}

/// Processes with a nonzero coefficient, counted from the optics as the walk would see them.
std::size_t nonzeroProcesses(const SkinOptics& optics, const WalkOptions& walk) {
  std::size_t n = walk.roughSurface ? 1 : 0;
  for (Layer layer : kAllLayers) {
    const LayerOptics& lo = optics[layer];
    if (!(lo.thicknessCm > 0) || index(layer) > index(walk.deepestLayer)) continue;
    for (double mu : lo.muA_perCm) n += mu > 0 ? 1 : 0;
    n += (walk.melanosomes && lo.melanosome.mu_perCm > 0) ? 1 : 0;
    n += (walk.rayleigh && lo.muRayleigh_perCm > 0) ? 1 : 0;
  }
  return n;
}

bool sameOptics(const SkinOptics& a, const SkinOptics& b) {
  for (std::size_t k = 0; k < kLayerCount; ++k) {
    const LayerOptics &x = a.layers[k], &y = b.layers[k];
    if (x.muA_perCm != y.muA_perCm || x.muATotal_perCm != y.muATotal_perCm ||
        x.muRayleigh_perCm != y.muRayleigh_perCm ||
        x.melanosome.mu_perCm != y.melanosome.mu_perCm || x.thicknessCm != y.thicknessCm ||
        x.refractiveIndex != y.refractiveIndex)
      return false;
  }
  return true;
}

}  // namespace

TEST(EffectPlan, OpticalDepthOfOneAbsorberMatchesBeerLambert) {
  // Normal incidence through a matched slab: ℓ = min(d, free path), so E[ℓ] = (1 − e^{−μd})/μ and
  // τ = μE[ℓ] = 1 − e^{−μd} (= the absorbed fraction). At 60° the path is d / cos 60° = 2d.
  const double mu = 50, d = 0.01;  // μd = 0.5
  for (double angle : {0.0, 60.0}) {
    PlanOptions options;
    options.incidenceDeg = {angle};
    options.pilotRays = 4000;
    options.walk = smoothSingleLayer();
    const EffectPlan plan = planEffects(singleAbsorbingLayer(mu, d), 0.3, options);
    ASSERT_EQ(plan.effects.size(), 1u);  // no roughness, nothing else nonzero
    const PlannedEffect& e = plan.effects.front();
    const double expected = 1 - std::exp(-mu * d / std::cos(angle * kPi / 180));
    // μℓ is in [0, μd/cos]; its standard deviation is < 0.45 for these laws, so σ(τ) < 0.45/√4000 ≈
    // 0.0071.
    EXPECT_NEAR(e.opticalDepth, expected, 4 * 0.0071) << angle;
    // τ⁺ is τ + 3 s.e., capped by the bound on entering the layer (every ray enters: ≤ 1).
    EXPECT_GT(e.opticalDepthUpper, e.opticalDepth);
    EXPECT_LT(e.opticalDepthUpper, e.opticalDepth + 4 * 0.0071);
    EXPECT_TRUE(e.kept);  // τ⁺ ≈ 0.4 or 0.63 > ε = 0.3
  }
}

TEST(EffectPlan, DropsWhatFitsAndZeroesItsCoefficient) {
  PlanOptions options;
  options.walk = smoothSingleLayer();
  const SkinOptics optics = singleAbsorbingLayer(0.05, 0.01);  // τ = 1 − e^{−5e-4} ≈ 5.0e-4
  const EffectPlan plan = planEffects(optics, 1e-3, options);
  ASSERT_EQ(plan.effects.size(), 1u);
  // All but ~5e-4 of the rays cross the whole d, so the estimate's s.e. is ≈ 5e-4·sqrt(5e-4/2000)
  // ≈ 2.5e-7.
  EXPECT_NEAR(plan.effects[0].opticalDepth, 1 - std::exp(-5e-4), 4 * 2.5e-7);
  EXPECT_FALSE(plan.effects[0].kept);
  EXPECT_EQ(plan.droppedDepthBound, plan.effects[0].opticalDepthUpper);
  EXPECT_EQ(plan.optics[Layer::StratumCorneum].muA_perCm[index(Absorber::Water)], 0.0);
  EXPECT_EQ(plan.optics[Layer::StratumCorneum].muATotal_perCm, 0.0);
  // Too large for ε: kept, optics untouched.
  const EffectPlan tight = planEffects(optics, 4e-4, options);
  EXPECT_TRUE(tight.effects[0].kept);
  EXPECT_TRUE(sameOptics(tight.optics, optics));
}

TEST(EffectPlan, SurfaceRoughnessIsAlwaysKept) {
  const SkinOptics optics = specimenOptics("S1", 550);
  const EffectPlan plan = planEffects(optics, 1.0);
  const PlannedEffect* rough = find(plan, Process::SurfaceRoughness, Layer::StratumCorneum);
  ASSERT_NE(rough, nullptr);
  EXPECT_TRUE(rough->kept);
  EXPECT_GE(rough->opticalDepth, 1.0);  // every ray meets the surface at least once
  EXPECT_TRUE(std::isinf(rough->opticalDepthUpper));
  EXPECT_TRUE(plan.walk.roughSurface);
  EXPECT_LE(plan.droppedDepthBound, 1.0);
}

TEST(EffectPlan, EpsilonZeroKeepsEveryProcessAndIsBitIdentical) {
  // σ: none needed — with nothing dropped the planned walk is the full walk, so the tallies are
  // identical ray for ray (same seed).
  for (double w : {550.0, 1650.0}) {
    const SkinOptics optics = specimenOptics("S1", w);
    PlanOptions options;
    options.pilotRays = 500;
    const EffectPlan plan = planEffects(optics, 0.0, options);
    EXPECT_EQ(plan.effects.size(), nonzeroProcesses(optics, WalkOptions{})) << w;
    EXPECT_EQ(plan.droppedCount(), 0u);
    EXPECT_EQ(plan.droppedDepthBound, 0.0);
    EXPECT_TRUE(sameOptics(plan.optics, optics));
    const SkinTally full = run(optics, WalkOptions{}, 4000, 11),
                    planned = run(plan.optics, plan.walk, 4000, 11);
    EXPECT_EQ(full.reflectance().mean, planned.reflectance().mean) << w;
    EXPECT_EQ(full.absorptance().mean, planned.absorptance().mean) << w;
    EXPECT_EQ(full.meanEvents(), planned.meanEvents()) << w;
  }
}

TEST(EffectPlan, DefaultEpsilonKeepsReflectanceWithinTheBound) {
  // S1–S4 at five wavelengths, 20,000 rays each way: σ_R ≤ sqrt(0.25/20000) = 0.0035, σ_diff ≤
  // 0.005; the test is |ΔR| ≤ bound + 4 σ_diff (the bound itself, ≤ 1e-3, is far below the noise:
  // this catches a planner that drops something that matters, not errors of order ε).
  std::size_t droppedSomewhere = 0;
  for (const std::string name : {"S1", "S2", "S3", "S4"})
    for (double w : {300.0, 550.0, 1100.0, 1650.0, 2200.0}) {
      const SkinOptics optics = specimenOptics(name, w);
      PlanOptions options;
      options.pilotRays = 1000;
      const EffectPlan plan = planEffects(optics, kDefaultEffectTolerance, options);
      EXPECT_LE(plan.droppedDepthBound, kDefaultEffectTolerance);
      droppedSomewhere += plan.droppedCount();
      const Estimate full = run(optics, WalkOptions{}, 20000, 21).reflectance();
      const Estimate planned = run(plan.optics, plan.walk, 20000, 22).reflectance();
      const double sigma = std::hypot(full.standardError, planned.standardError);
      EXPECT_LE(std::fabs(planned.mean - full.mean), plan.droppedDepthBound + 4 * sigma)
          << name << " " << w << " nm";
    }
  EXPECT_GT(droppedSomewhere, 0u);  // the default does skip the negligible absorbers
}

TEST(EffectPlan, DroppingAProcessOfLargeDepthChangesReflectance) {
  // The converse check: the bound is not vacuous. S1 at 550 nm without the papillary-dermis
  // Rayleigh term (τ ≫ 1) changes R by far more than 4 σ_diff (σ_diff ≈ 0.0065 at 6,000 rays).
  const SkinOptics optics = specimenOptics("S1", 550);
  WalkOptions noRayleigh;
  noRayleigh.rayleigh = false;
  const Estimate full = run(optics, WalkOptions{}, 6000, 21).reflectance();
  const Estimate without = run(optics, noRayleigh, 6000, 22).reflectance();
  const EffectPlan plan = planEffects(optics, 1e-3);
  const PlannedEffect* rayleigh = find(plan, Process::Rayleigh, Layer::PapillaryDermis);
  ASSERT_NE(rayleigh, nullptr);
  EXPECT_TRUE(rayleigh->kept);
  EXPECT_GT(rayleigh->opticalDepth, 1.0);
  EXPECT_GT(std::fabs(full.mean - without.mean),
            4 * std::hypot(full.standardError, without.standardError));
}

TEST(EffectPlan, MelanosomesWithoutScatteringAngleCountOnlyAbsorbingInteractions) {
  // At 1650 nm θo = 0: τ_mel = μ_mel·E[ℓ_k]·p_abs and τ_water = μ_water·E[ℓ_k] share E[ℓ_k], so
  // p̂ = (τ_mel/μ_mel)/(τ_water/μ_water), the planner's p_abs from the path-length table. Checked
  // against 100,000 traced interactions: σ = sqrt(p(1−p)/n) ≈ 1.4e-4 at p ≈ 0.002 (the table's own
  // s.e., from 65,536 path samples, is about ten times smaller).
  const SkinOptics optics = specimenOptics("S1", 1650);
  ASSERT_EQ(optics.meanScatteringAngleRad, 0.0);
  const EffectPlan plan = planEffects(optics, 0.0);
  const Layer layer = Layer::StratumBasale;
  const PlannedEffect* mel = find(plan, Process::Melanosomes, layer);
  const PlannedEffect* water = find(plan, Process::Absorption, layer, Absorber::Water);
  ASSERT_NE(mel, nullptr);
  ASSERT_NE(water, nullptr);
  const double pPlanned = (mel->opticalDepth / optics[layer].melanosome.mu_perCm) /
                          (water->opticalDepth / optics[layer].muA_perCm[index(Absorber::Water)]);
  const MelanosomeLayer melanosomes(optics, layer);
  int absorbed = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    Rng rng(99, 5, static_cast<std::uint64_t>(i));
    absorbed += melanosomes.interact(Vec3{0, 0, 1}, rng).absorbed ? 1 : 0;
  }
  const double p = static_cast<double>(absorbed) / n;
  EXPECT_GT(p, 0.0);
  EXPECT_LT(p, 0.05);
  const double sigma = std::sqrt(p * (1 - p) / n);
  EXPECT_NEAR(pPlanned, p, 4 * sigma);
  EXPECT_GE(mel->opticalDepthUpper, mel->opticalDepth);
}

TEST(EffectPlan, SharedPlanTakesTheLargestDepthOverOptics) {
  // Same pilot streams for each optics, so the shared plan's τ is exactly the larger single τ.
  PlanOptions options;
  options.walk = smoothSingleLayer();
  options.pilotRays = 500;
  const SkinOptics weak = singleAbsorbingLayer(1, 0.01), strong = singleAbsorbingLayer(30, 0.01);
  const EffectPlan a = planEffects(weak, 0.1, options), b = planEffects(strong, 0.1, options);
  const EffectPlan both = planEffects(std::vector<SkinOptics>{weak, strong}, 0.1, options);
  ASSERT_EQ(both.effects.size(), 1u);
  EXPECT_EQ(both.effects[0].opticalDepth,
            std::max(a.effects[0].opticalDepth, b.effects[0].opticalDepth));
  EXPECT_EQ(both.effects[0].opticalDepthUpper,
            std::max(a.effects[0].opticalDepthUpper, b.effects[0].opticalDepthUpper));
  EXPECT_FALSE(a.effects[0].kept);    // τ ≈ 0.01 fits in 0.1
  EXPECT_TRUE(both.effects[0].kept);  // τ ≈ 0.26 does not
  EXPECT_EQ(both.pilotRaysTraced, 1000u);
  // Applying a plan to other optics zeroes what it dropped and copies the rest bit for bit.
  SkinOptics expected = strong;
  expected.layers[index(Layer::StratumCorneum)].muA_perCm[index(Absorber::Water)] = 0;
  expected.layers[index(Layer::StratumCorneum)].muATotal_perCm = 0;
  EXPECT_TRUE(sameOptics(a.apply(strong), expected));
}

TEST(EffectPlan, IsDeterministicForASeed) {
  const SkinOptics optics = specimenOptics("S2", 1100);
  PlanOptions options;
  options.pilotRays = 300;
  const EffectPlan a = planEffects(optics, 1e-3, options), b = planEffects(optics, 1e-3, options);
  ASSERT_EQ(a.effects.size(), b.effects.size());
  for (std::size_t i = 0; i < a.effects.size(); ++i) {
    EXPECT_EQ(a.effects[i].opticalDepth, b.effects[i].opticalDepth);
    EXPECT_EQ(a.effects[i].kept, b.effects[i].kept);
  }
  EXPECT_EQ(a.explain(), b.explain());
}

TEST(EffectPlan, ExplainListsEveryProcessWithItsDecision) {
  PlanOptions options;
  options.walk = smoothSingleLayer();
  const EffectPlan plan = planEffects(singleAbsorbingLayer(0.05, 0.01), 1e-3, options);
  const std::string text = plan.explain();
  EXPECT_NE(text.find("effect plan at 500 nm, epsilon = 0.001"), std::string::npos) << text;
  EXPECT_NE(text.find("process"), std::string::npos);
  EXPECT_NE(text.find("bound"), std::string::npos);
  EXPECT_NE(text.find("absorption: water"), std::string::npos);
  EXPECT_NE(text.find("stratum_corneum"), std::string::npos);
  EXPECT_NE(text.find("skipped\n"), std::string::npos);
  EXPECT_NE(text.find("skipped 1 of 1 processes"), std::string::npos);
  EXPECT_NE(plan.summary().find("500 nm: kept 0 of 1"), std::string::npos) << plan.summary();
  const EffectPlan s1 = planEffects(specimenOptics("S1", 550), 1e-3);
  const std::string full = s1.explain();
  for (const char* row :
       {"melanosomes", "Rayleigh", "surface roughness", "absorption: oxyhemoglobin", "kept"})
    EXPECT_NE(full.find(row), std::string::npos) << row;
}

TEST(EffectPlan, InvalidArgumentsThrow) {
  const SkinOptics optics = singleAbsorbingLayer(1, 0.01);
  EXPECT_THROW(planEffects(optics, -0.1), std::invalid_argument);
  EXPECT_THROW(planEffects(optics, 1.5), std::invalid_argument);
  EXPECT_THROW(planEffects(optics, std::nan("")), std::invalid_argument);
  PlanOptions badAngle;
  badAngle.incidenceDeg = {90};
  EXPECT_THROW(planEffects(optics, 1e-3, badAngle), std::invalid_argument);
  PlanOptions noRays;
  noRays.pilotRays = 0;
  EXPECT_THROW(planEffects(optics, 1e-3, noRays), std::invalid_argument);
  SkinOptics other = optics;
  other.wavelengthNm = 600;
  EXPECT_THROW(planEffects(std::vector<SkinOptics>{optics, other}, 1e-3), std::invalid_argument);
  try {
    planEffects(optics, 2);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("[0, 1]"), std::string::npos) << e.what();
  }
}

TEST(EffectPlan, RenderCacheAppliesOneChannelPlanToEveryMelaninLevel) {
  // Melanin × [1, 3] at 550 and 2200 nm, with 550 nm given twice (overlapping bands): one plan per
  // distinct wavelength from 2 end levels × 2 incidences × kRenderPilotRays, applied at every
  // level.
  const Specimen specimen = loadSpecimen("S1", kRoot + "/scenes/specimens");
  const std::vector<double> channels{550, 2200, 550};
  const hylios::SkinWalkCache cache(specimen, 1, 3, channels, spectra(), {}, 5,
                                    kDefaultEffectTolerance);
  ASSERT_EQ(cache.effectPlans().size(), 2u);
  for (std::size_t c = 0; c < channels.size(); ++c) {
    const EffectPlan& plan = cache.effectPlans()[c == 1 ? 1 : 0];
    EXPECT_EQ(plan.wavelengthNm, channels[c]);
    EXPECT_EQ(plan.pilotRaysTraced, 4 * hylios::SkinWalkCache::kRenderPilotRays);
    EXPECT_LE(plan.droppedDepthBound, kDefaultEffectTolerance);
    for (int k = 0; k < cache.levels(); ++k) {
      const SkinOptics full = computeSkinOptics(
          hylios::scaleMelanin(specimen, cache.levelMultiplier(k)), spectra(), channels[c]);
      EXPECT_TRUE(sameOptics(cache.walk(c, k).optics(), plan.apply(full))) << c << " " << k;
    }
  }
  EXPECT_EQ(&cache.walk(0, 2), &cache.walk(2, 2));  // the repeated wavelength shares its walks
  EXPECT_GT(cache.effectPlans()[0].droppedCount(), 0u);
  const std::string text = cache.explainEffectPlans();
  EXPECT_NE(text.find("effect plan at 2200 nm"), std::string::npos) << text;
  // ε = 0: no plan, the full optics at every level.
  const hylios::SkinWalkCache full(specimen, 1, 3, {550}, spectra(), {}, 3, 0.0);
  EXPECT_TRUE(full.effectPlans().empty());
  EXPECT_TRUE(sameOptics(full.walk(0, 2).optics(),
                         computeSkinOptics(hylios::scaleMelanin(specimen, 3), spectra(), 550)));
  EXPECT_NE(full.explainEffectPlans().find("off"), std::string::npos);
  EXPECT_THROW(hylios::SkinWalkCache(specimen, 1, 3, {550}, spectra(), {}, 3, 1.5),
               hylios::SceneError);
}
