// The HyLIoS walk on stacks whose answers are known in closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "skin/core/constants.h"
#include "skin/core/thread_limit.h"
#include "skin/fresnel.h"
#include "skin/melanosome_interaction.h"
#include "skin/sampling/cosine_sampling.h"
#include "skin/sampling/melanosome_orientation_sampling.h"
#include "skin/skin_simulation.h"
#include "skin/skin_walk.h"
#include "skin/spheroid_intersection.h"
#include "tests/support/clear_optics.h"

using hylios::kPi;

using namespace hylios::skin;

namespace {

using hylios::test::clearOptics;

SkinTally run(const SkinOptics& optics, WalkOptions walk, double angleDeg, std::uint64_t rays) {
  WalkRunOptions options;
  options.incidenceDeg = angleDeg;
  options.rays = rays;
  options.seed = 7;
  options.walk = walk;
  return simulateSkin(optics, options);
}

double fresnelNormal(double n1, double n2) { return std::pow((n1 - n2) / (n1 + n2), 2); }

}  // namespace

TEST(SkinWalk, ClearStackReturnsEveryRay) {
  // Nothing absorbs and the hypodermis junction reflects all: every ray must come back out.
  SkinOptics optics = clearOptics(1.55);
  WalkOptions walk;
  walk.roughSurface = false;
  const SkinTally t = run(optics, walk, 0, 20000);
  EXPECT_EQ(t.reflectance().mean, 1.0);
  EXPECT_EQ(t.eventLimited().mean, 0.0);
  // Smooth surface at normal incidence: surface part = Fresnel 1 -> 1.55 = 0.046489.
  const double expected = fresnelNormal(1.0, 1.55);
  const double sigma = std::sqrt(expected * (1 - expected) / 20000.0);  // ≈ 0.0015
  EXPECT_NEAR(t.surfaceReflectance().mean, expected, 4 * sigma);
}

TEST(SkinWalk, AbsorbingSlabOverMatchedMediumFollowsBeerLambert) {
  // Matched indices (n = 1 everywhere), one absorbing layer, transmitting bottom:
  // T = exp(-mu_a d) exactly in expectation, R = 0.
  SkinOptics optics = clearOptics(1.0, 0.0);
  optics.layers[index(Layer::StratumCorneum)].thicknessCm = 0.01;
  optics.layers[index(Layer::StratumCorneum)].muATotal_perCm = 100.0;  // optical depth 1
  WalkOptions walk;
  walk.roughSurface = false;
  walk.deepestLayer = Layer::StratumBasale;
  const std::uint64_t rays = 40000;
  const SkinTally t = run(optics, walk, 0, rays);
  const double expected = std::exp(-1.0);
  const double sigma =
      std::sqrt(expected * (1 - expected) / static_cast<double>(rays));  // ≈ 0.0024
  EXPECT_NEAR(t.transmittance().mean, expected, 4 * sigma);
  EXPECT_EQ(t.reflectance().mean, 0.0);
  EXPECT_DOUBLE_EQ(t.transmittance().mean + t.absorptance().mean, 1.0);
}

TEST(SkinWalk, ObliqueAbsorptionUsesThePathLength) {
  // 60° incidence into a matched absorbing slab: path = d / cos 60° = 2d, T = exp(-2).
  SkinOptics optics = clearOptics(1.0, 0.0);
  optics.layers[index(Layer::StratumCorneum)].thicknessCm = 0.01;
  optics.layers[index(Layer::StratumCorneum)].muATotal_perCm = 100.0;
  WalkOptions walk;
  walk.roughSurface = false;
  walk.deepestLayer = Layer::StratumCorneum;
  const SkinTally t = run(optics, walk, 60, 40000);
  const double expected = std::exp(-2.0);
  const double sigma = std::sqrt(expected * (1 - expected) / 40000.0);  // ≈ 0.0017
  EXPECT_NEAR(t.transmittance().mean, expected, 4 * sigma);
}

TEST(SkinWalk, EnergyIsAccountedForWithEveryProcess) {
  SkinOptics optics = clearOptics(1.4);
  for (auto& layer : optics.layers) layer.muATotal_perCm = 20;
  auto& basale = optics.layers[index(Layer::StratumBasale)];
  basale.melanosome = {0.085e-4, 0.205e-4, true, 0.41e-4, 4, 300.0};
  optics.melanosomeInteriorMuA_perCm = 2000;
  optics.meanScatteringAngleRad = 5.0 * kPi / 180.0;
  optics.layers[index(Layer::PapillaryDermis)].muRayleigh_perCm = 2500;
  const SkinTally t = run(optics, WalkOptions{}, 45, 20000);
  EXPECT_DOUBLE_EQ(
      t.reflectance().mean + t.transmittance().mean + t.absorptance().mean + t.eventLimited().mean,
      1.0);
  EXPECT_EQ(t.eventLimited().mean, 0.0);
  EXPECT_GT(t.melanosomeAbsorptance().mean, 0.0);
  double layers = 0;
  for (Layer l : kAllLayers) layers += t.absorptance(l).mean;
  EXPECT_NEAR(layers, t.absorptance().mean, 1e-12);
}

TEST(SkinWalk, SameSeedSameResultAtAnyThreadCount) {
  SkinOptics optics = clearOptics(1.4);
  for (auto& layer : optics.layers) layer.muATotal_perCm = 5;
  optics.layers[index(Layer::PapillaryDermis)].muRayleigh_perCm = 2500;
  SkinTally one, two;
  {
    const hylios::ThreadLimit limit(1);
    one = run(optics, WalkOptions{}, 30, 30000);
  }
  {
    const hylios::ThreadLimit limit(2);
    two = run(optics, WalkOptions{}, 30, 30000);
  }
  EXPECT_EQ(one.reflectance().mean, two.reflectance().mean);
  EXPECT_EQ(one.reflectance().standardError, two.reflectance().standardError);
  EXPECT_EQ(one.meanEvents(), two.meanEvents());
}

TEST(SkinWalk, RejectsAStackWithoutThickness) {
  SkinOptics optics = clearOptics(1.4, 0.0);
  EXPECT_THROW(SkinWalk{optics}, std::invalid_argument);
}

TEST(MelanosomeInteraction, MatchedSphereAbsorbsAsItsChordLengthsSay) {
  // a = c = R, matched indices: a uniform hit over the projected disc gives the chord 2√(R²−ρ²);
  // P(absorbed) = 1 − [1 − e^{−2μR}(1 + 2μR)] / (2μ²R²).
  const double radiusCm = 1e-5, muA = 1e5;  // μR = 1
  const double x = muA * radiusCm;
  const double expected = 1.0 - (1.0 - std::exp(-2 * x) * (1 + 2 * x)) / (2 * x * x);
  Rng rng(3);
  const int trials = 100000;
  int absorbed = 0;
  for (int i = 0; i < trials; ++i)
    absorbed += absorbedInMelanosome(Vec3{0, 0, 1}, radiusCm, radiusCm, muA, 1.4, 1.4, rng) ? 1 : 0;
  const double p = absorbed / static_cast<double>(trials);
  const double sigma = std::sqrt(expected * (1 - expected) / trials);  // ≈ 0.0015
  EXPECT_NEAR(p, expected, 4 * sigma);
}

TEST(MelanosomeInteraction, ClearMelanosomeNeverAbsorbsAndAlwaysLetsTheRayOut) {
  Rng rng(5);
  for (int i = 0; i < 20000; ++i)
    ASSERT_FALSE(
        absorbedInMelanosome(normalize(Vec3{0.3, 0.2, 1}), 0.2e-4, 4e-4, 0.0, 1.4, 1.7, rng));
}

namespace {
/// The melanosome interaction traced in the world frame, step by step as Sec. 4.2.2 describes it,
/// with the geometry samplers of skin/sampling/melanosome_orientation_sampling.h and
/// skin/spheroid_intersection.h: the reference for the body-frame shortcut of MelanosomeLayer.
bool absorbedInWorldFrame(const Vec3& direction, double a, double c, double muA, double n1,
                          double n2, Rng& rng) {
  const ProlateSpheroid spheroid{a, c};
  const double u1 = rng.uniform(), u2 = rng.uniform();
  const Vec3 axis = sampleMelanosomeAxis(spheroid, direction, u1, u2);  // Eq. 8
  const double u3 = rng.uniform(), u4 = rng.uniform();
  const SpheroidSurfacePoint entry = sampleSilhouetteEntry(spheroid, axis, direction, u3, u4);
  const FresnelResult in = fresnel(dot(direction, entry.outwardNormal), n1, n2);
  if (rng.uniform() < in.reflectance) return false;
  Vec3 d = refractDirection(direction, entry.outwardNormal, n1, n2, in.cosTransmitted);
  Vec3 p = entry.position;
  for (int bounce = 0; bounce < 1000; ++bounce) {
    const SpheroidExit exit = distanceToSpheroidExit(spheroid, axis, p, d);
    if (-std::log1p(-rng.uniform()) / muA < exit.distance) return true;
    p = exit.position;
    const FresnelResult out = fresnel(dot(d, exit.outwardNormal), n2, n1);
    if (rng.uniform() >= out.reflectance) return false;
    const double v1 = rng.uniform(), v2 = rng.uniform();
    d = Frame(-exit.outwardNormal).toWorld(sampleCosineHemisphere(v1, v2));
  }
  return false;
}
}  // namespace

TEST(MelanosomeInteraction, BodyFrameShortcutMatchesTheWorldFrameWalk) {
  // A basal-layer melanosome of S1 (a = 0.085 µm, c = 0.205 µm), n 1.4 -> 1.7, and interior
  // coefficients giving absorption probabilities from ~0.15 to ~0.9; an oblique incoming ray.
  const double a = 0.085e-4, c = 0.205e-4;
  const Vec3 direction = normalize(Vec3{0.6, -0.3, 0.74});
  const int trials = 100000;
  for (const double muA : {1e4, 1e5, 1e6}) {
    Rng fastRng(21), referenceRng(22);
    const MelanosomeLayer layer(a, c, muA, 1.4, 1.7);
    int fast = 0, reference = 0;
    for (int i = 0; i < trials; ++i) {
      fast += layer.absorbedInOne(fastRng) ? 1 : 0;
      reference += absorbedInWorldFrame(direction, a, c, muA, 1.4, 1.7, referenceRng) ? 1 : 0;
    }
    const double pFast = fast / double(trials), pReference = reference / double(trials);
    // Two independent binomial estimates: σ of the difference = sqrt(2 p (1 − p)/N) ≤ 0.0023.
    const double sigma = std::sqrt(2.0 * pReference * (1.0 - pReference) / trials);
    EXPECT_NEAR(pFast, pReference, 4.0 * sigma)
        << "muA = " << muA << ": " << pFast << " vs " << pReference;
    EXPECT_GT(pReference, 0.05) << "muA = " << muA;  // the case tests something
  }
}
