// The skin material's parts: the melanin-level cache with stochastic rounding, freckles, the
// melanin texture, the surface-lobe model g, and the projection of walk exits onto the surface.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/scene/data_paths.h"
#include "renderer/scene/texture_map.h"
#include "renderer/tracing/freckle_field.h"
#include "renderer/tracing/skin_material.h"
#include "renderer/tracing/skin_walk_cache.h"
#include "skin/core/constants.h"
#include "skin/core/random.h"
#include "tests/support/test_spectra.h"

using hylios::kPi;

using namespace hylios;

namespace {

MaterialDesc skinDesc() {
  MaterialDesc m;
  m.kind = MaterialDesc::Kind::Skin;
  m.name = "skin";
  m.skin.specimen = "S1";
  return m;
}

using hylios::test::spectra;

}  // namespace

TEST(SkinWalkCache, StochasticRoundingIsUnbiasedInTheMultiplier) {
  const skin::Specimen specimen = skin::loadSpecimen("S1", specimenDir());
  const SkinWalkCache cache(specimen, 1, 5, {550}, spectra(), {});
  ASSERT_EQ(cache.levels(), SkinWalkCache::kMelaninLevels);
  EXPECT_DOUBLE_EQ(cache.levelMultiplier(0), 1);
  EXPECT_DOUBLE_EQ(cache.levelMultiplier(32), 5);
  // m = 2.3 lies between levels 10 (2.25) and 11 (2.375): level 11 with probability 0.4.
  // N = 100000 draws: σ(mean multiplier) = 0.125·sqrt(0.24/N) ≈ 1.9e-4.
  skin::Rng rng(4);
  double mean = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const int level = cache.level(2.3, rng.uniform());
    ASSERT_TRUE(level == 10 || level == 11) << level;
    mean += cache.levelMultiplier(level) / n;
  }
  EXPECT_NEAR(mean, 2.3, 4 * 1.9e-4);
  EXPECT_EQ(cache.level(5, 0.999), 32);
  EXPECT_EQ(cache.level(1, 0.0), 0);
}

TEST(SkinWalkCache, ScaledMelaninAboveOneIsASceneError) {
  const skin::Specimen specimen = skin::loadSpecimen("S1", specimenDir());
  EXPECT_THROW(SkinWalkCache(specimen, 1, 1e4, {550}, spectra(), {}), SceneError);
  const skin::Specimen scaled = scaleMelanin(specimen, 2);
  EXPECT_DOUBLE_EQ(scaled.melanosomeFraction[2], 2 * specimen.melanosomeFraction[2]);
  EXPECT_DOUBLE_EQ(scaled.colloidalMelaninFraction[3], 2 * specimen.colloidalMelaninFraction[3]);
}

TEST(FreckleField, CoveredFractionMatchesDensityAndRadius) {
  // A plane through the 3-D field meets discs of radius sqrt(r² − h²), h uniform in [−r, r]:
  // mean disc area 2πr²/3, so the covered fraction is ≈ ρ·2πr²/3 = 0.0105 for ρ = 0.5 cm⁻²,
  // r = 0.1 cm (overlaps change it by < 1 %). Over 100 × 100 cm (≈ 5000 freckles) and 200000
  // points, σ ≈ 0.0105·sqrt(1/5000 + 1/2100) ≈ 2.7e-4 (freckle count + point sampling).
  SkinMaterialDesc::Freckles desc;
  desc.densityPerCm2 = 0.5;
  desc.radiusCm = 0.1;
  desc.melaninGain = 4;
  desc.seed = 9;
  const FreckleField field(desc, {});
  skin::Rng rng(1);
  int covered = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double m = field.multiplier({100 * rng.uniform(), 100 * rng.uniform(), 0.37});
    ASSERT_GE(m, 1.0);
    ASSERT_LE(m, 4.0);
    if (m > 1) ++covered;
  }
  EXPECT_NEAR(static_cast<double>(covered) / n, 0.5 * 2 * kPi * 0.01 / 3, 4 * 2.7e-4);
  EXPECT_EQ(field.multiplier({3.3, 4.4, 0.37}),
            FreckleField(desc, {}).multiplier({3.3, 4.4, 0.37}));
}

TEST(FreckleField, CentreOfAFreckleHasTheFullGain) {
  SkinMaterialDesc::Freckles desc;
  desc.densityPerCm2 = 3;
  desc.radiusCm = 0.2;
  desc.melaninGain = 2.5;
  const FreckleField field(desc, {});
  // Search a line for the strongest multiplier: a freckle crossing it near its centre reaches ≈
  // gain.
  double strongest = 1;
  for (int i = 0; i < 200000; ++i)
    strongest = std::max(strongest, field.multiplier({i * 1e-3, 0.1, 0.05}));
  EXPECT_GT(strongest, 2.4);
  EXPECT_LE(strongest, 2.5);
}

TEST(TextureMap, BilinearLookupWithBottomRowAtVZero) {
  const TextureMap map(2, 2,
                       {0.0f, 1.0f,                 // top row
                        2.0f, 3.0f});               // bottom row
  EXPECT_DOUBLE_EQ(map.lookup({0.25, 0.25}), 2.0);  // bottom-left texel centre
  EXPECT_DOUBLE_EQ(map.lookup({0.75, 0.75}), 1.0);  // top-right texel centre
  EXPECT_DOUBLE_EQ(map.lookup({0.5, 0.25}), 2.5);   // between the bottom texels
  EXPECT_DOUBLE_EQ(map.lookup({0.5, 0.5}), 1.5);    // the middle
  EXPECT_THROW(TextureMap("/nonexistent/melanin.png", {}), SceneError);
}

TEST(SkinMaterial, SurfaceLobeModelIsANormalisedDensity) {
  // ∫ g dω over the outgoing hemisphere = 1 for every incidence (midpoint rule in (cosθ, φ)).
  const skin::Specimen specimen = skin::loadSpecimen("S1", specimenDir());
  const SkinMaterial material(skinDesc(), specimen, 0, 1.0, {550}, spectra());
  const glm::dvec3 normal(0, 0, 1);
  for (const double incidenceDeg : {0.0, 30.0, 60.0, 80.0}) {
    const double a = incidenceDeg * kPi / 180;
    const glm::dvec3 incident(std::sin(a), 0, -std::cos(a));
    double integral = 0;
    const int nMu = 2000, nPhi = 720;
    for (int i = 0; i < nMu; ++i) {
      const double mu = (i + 0.5) / nMu, sinTheta = std::sqrt(1 - mu * mu);
      for (int j = 0; j < nPhi; ++j) {
        const double phi = 2 * kPi * (j + 0.5) / nPhi;
        integral += material.surfaceLobeDensity(
            incident, normal, {sinTheta * std::cos(phi), sinTheta * std::sin(phi), mu});
      }
    }
    integral *= 2 * kPi / (nMu * nPhi);
    // The lobe is narrow (s = 0.1); 1.4 M quadrature points resolve it to well under 1 %.
    EXPECT_NEAR(integral, 1.0, 0.01) << incidenceDeg << "°";
  }
}

TEST(SkinMaterial, SubsurfaceExitsLandOnTheSurface) {
  // A skin sphere (radius 1 cm) at 1100 nm, where exits lie ~5 mm from the entry on average: every
  // subsurface exit is projected back onto the sphere. Exits farther than ~1.4 radii (the probes'
  // reach on a sphere; about 3 % of them here) fall back to the entry point and are counted.
  SceneDesc scene;
  ShapeDesc sphere;
  sphere.kind = ShapeDesc::Kind::Sphere;
  sphere.material = "skin";
  scene.shapes = {sphere};
  const EmbreeScene geometry(scene);
  const skin::Specimen specimen = skin::loadSpecimen("S1", specimenDir());
  const SkinMaterial material(skinDesc(), specimen, 0, 1.0, {1100}, spectra());
  const auto hit = geometry.intersect({{0, 0, 5}, {0, 0, -1}});
  ASSERT_TRUE(hit.has_value());
  int subsurface = 0, fallbacks = 0;
  double meanDistance = 0;
  for (int i = 0; i < 3000; ++i) {
    skin::Rng rng(3, 0, static_cast<std::uint64_t>(i));
    const SkinScatter s = material.scatter(*hit, {0, 0, -1}, 0, geometry, {0}, rng);
    if (s.kind != SkinScatter::Kind::SubsurfaceReflection) continue;
    ++subsurface;
    fallbacks += s.exitFallback ? 1 : 0;
    EXPECT_NEAR(glm::length(s.point), 1.0, 1e-6);
    EXPECT_NEAR(glm::dot(s.geometricNormal, s.point), 1.0, 1e-6);  // outward normal
    meanDistance += glm::length(s.point - hit->position);
  }
  ASSERT_GT(subsurface, 1000);
  EXPECT_LT(fallbacks, subsurface / 20) << fallbacks << " of " << subsurface;
  meanDistance /= subsurface;
  EXPECT_GT(meanDistance, 0.005);  // at 1100 nm light travels millimetres in the dermis
  EXPECT_LT(meanDistance, 0.5);
}
