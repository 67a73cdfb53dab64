// The skin material's parts: the melanin-level cache with stochastic rounding, freckles, the
// melanin texture, the surface-lobe model g, the split entry's surface-branch density, and the
// projection of walk exits onto the surface.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "renderer/scene/data_paths.h"
#include "renderer/scene/texture_map.h"
#include "renderer/tracing/freckle_field.h"
#include "renderer/tracing/skin_material.h"
#include "renderer/tracing/skin_walk_cache.h"
#include "skin/core/constants.h"
#include "skin/core/random.h"
#include "skin/sampling/surface_normal_sampling.h"
#include "tests/support/chi2.h"
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

/// A scene of one skin sphere, radius 1 cm at the origin.
SceneDesc unitSkinSphere() {
  SceneDesc scene;
  ShapeDesc sphere;
  sphere.kind = ShapeDesc::Kind::Sphere;
  sphere.material = "skin";
  scene.shapes = {sphere};
  return scene;
}

}  // namespace

TEST(SkinWalkCache, StochasticRoundingIsUnbiasedInTheMultiplier) {
  const skin::Specimen specimen = skin::loadSpecimen("S1", specimenDir());
  const SkinWalkCache cache(specimen, 1, 5, {550}, spectra(), {});
  ASSERT_EQ(cache.levels(), SkinWalkCache::kMelaninLevels);
  EXPECT_DOUBLE_EQ(cache.levelMultiplier(0), 1);
  EXPECT_DOUBLE_EQ(cache.levelMultiplier(32), 5);
  // Levels equally spaced in √m: m_k = (1 + k(√5 − 1)/32)², m_16 = ((1 + √5)/2)² = 2.618034.
  EXPECT_NEAR(cache.levelMultiplier(16), 2.618034, 1e-6);
  EXPECT_NEAR(cache.levelMultiplier(13), 2.256462, 1e-6);
  EXPECT_NEAR(cache.levelMultiplier(14), 2.374002, 1e-6);
  // m = 2.3 lies between levels 13 and 14: level 14 with probability (2.3 − m_13)/(m_14 − m_13)
  // = 0.3704. N = 100000 draws: σ(mean multiplier) = 0.11754·sqrt(0.3704·0.6296/N) ≈ 1.8e-4.
  skin::Rng rng(4);
  double mean = 0, upper = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const int level = cache.level(2.3, rng.uniform());
    ASSERT_TRUE(level == 13 || level == 14) << level;
    mean += cache.levelMultiplier(level) / n;
    upper += level == 14 ? 1.0 / n : 0.0;
  }
  EXPECT_NEAR(mean, 2.3, 4 * 1.8e-4);
  EXPECT_NEAR(upper, 0.3704, 4 * 0.0015);  // binomial σ = sqrt(0.3704·0.6296/N) ≈ 0.0015
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
  const EmbreeScene geometry(unitSkinSphere());
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

// The split entry's surface branch (the walk's first facing facet mirrors the ray out) against its
// density SkinMaterial::surfaceBranchDensity, which the integrator's next-event estimation and MIS
// use: branch directions binned by their half vector h (equal-probability cells of the facet law
// in θ_h × 6 cells of φ_h over [0, π], folded by the y → −y symmetry, plus "no branch") by
// chi-square, the expected count of a cell N·∫ p(ω(h))·4|ω·h| dΩ_h (midpoint rule); and each
// channel's mean surface weight against ∫ F_λ(h)·p dω within 4 standard errors.
TEST(SkinMaterial, SurfaceBranchDensityIsTheSplitEntrysLaw) {
  const EmbreeScene geometry(unitSkinSphere());
  const skin::Specimen specimen = skin::loadSpecimen("S1", specimenDir());
  const std::vector<double> channels{450, 550, 650};
  const SkinMaterial material(skinDesc(), specimen, 0, 1.0, channels, spectra(),
                              skin::SkinMode::Walk, 0.0, {{0, 1, 2}});
  SurfaceHit hit;
  hit.position = {0, 0, 1};
  hit.geometricNormal = hit.shadingNormal = {0, 0, 1};
  const glm::dvec3 normal(0, 0, 1);
  const double s = specimen.surfaceFoldAspectRatio;
  constexpr int kThetaCells = 8, kPhiCells = 6, kPaths = 60000;
  std::vector<double> thetaEdges{0};
  for (int k = 1; k < kThetaCells; ++k)
    thetaEdges.push_back(skin::sampleSurfaceNormalPolar(s, static_cast<double>(k) / kThetaCells));
  thetaEdges.push_back(kPi / 2);
  for (const double incidenceDeg : {0.0, 45.0, 75.0}) {
    const double a = incidenceDeg * kPi / 180;
    const glm::dvec3 incident(std::sin(a), 0, -std::cos(a));
    auto cellOf = [&](const glm::dvec3& h) {
      const double theta = std::acos(std::clamp(h.z, -1.0, 1.0));
      const double phi = std::fabs(std::atan2(h.y, h.x));
      int t = 0;
      while (t + 1 < kThetaCells && theta >= thetaEdges[static_cast<std::size_t>(t) + 1]) ++t;
      return t * kPhiCells + std::min(kPhiCells - 1, static_cast<int>(phi / kPi * kPhiCells));
    };
    std::vector<double> observed(kThetaCells * kPhiCells + 1, 0.0), weight(channels.size(), 0.0),
        weightSquares(channels.size(), 0.0);
    std::vector<double> weights(channels.size()), surface(channels.size());
    for (int i = 0; i < kPaths; ++i) {
      skin::Rng rng(5, static_cast<std::uint64_t>(incidenceDeg), static_cast<std::uint64_t>(i));
      std::fill(surface.begin(), surface.end(), 0.0);
      const SkinScatter out = material.scatterSpectral(hit, incident, 0, geometry, {0}, rng,
                                                       weights.data(), surface.data());
      if (!out.surfaceBranch) {
        observed.back() += 1;
        continue;
      }
      observed[static_cast<std::size_t>(cellOf(glm::normalize(out.surfaceDirection - incident)))] +=
          1;
      for (std::size_t c = 0; c < channels.size(); ++c) {
        weight[c] += surface[c];
        weightSquares[c] += surface[c] * surface[c];
      }
    }
    // Expected cell probabilities and Fresnel-weighted integrals over the half-vector sphere.
    std::vector<double> expected(observed.size(), 0.0), fresnelIntegral(channels.size(), 0.0);
    constexpr int kSub = 24;
    double branch = 0;
    for (int t = 0; t < kThetaCells; ++t)
      for (int p = 0; p < kPhiCells; ++p)
        for (int i = 0; i < kSub; ++i)
          for (int j = 0; j < kSub; ++j) {
            const double lo = thetaEdges[static_cast<std::size_t>(t)];
            const double dTheta = (thetaEdges[static_cast<std::size_t>(t) + 1] - lo) / kSub;
            const double theta = lo + (i + 0.5) * dTheta;
            const double dPhi = kPi / kPhiCells / kSub;
            const double phi = p * kPi / kPhiCells + (j + 0.5) * dPhi;
            const glm::dvec3 h(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                               std::cos(theta));
            const double cosFacet = -glm::dot(incident, h);
            if (!(cosFacet > 0)) continue;
            const glm::dvec3 out = incident + h * (2 * cosFacet);
            // Both φ signs (the fold): twice the measure of this half.
            const double measure = 2 * material.surfaceBranchDensity(incident, normal, out) * 4 *
                                   cosFacet * std::sin(theta) * dTheta * dPhi;
            expected[static_cast<std::size_t>(t * kPhiCells + p)] += measure * kPaths;
            branch += measure;
            for (std::size_t c = 0; c < channels.size(); ++c)
              fresnelIntegral[c] += measure * material.surfaceFresnel(c, cosFacet);
          }
    expected.back() = kPaths * (1 - branch);
    EXPECT_TRUE(test::chi2Accepts(test::chi2FromCounts(observed, expected), 1e-3))
        << incidenceDeg << "°";
    for (std::size_t c = 0; c < channels.size(); ++c) {
      const double mean = weight[c] / kPaths;
      const double sigma = std::sqrt((weightSquares[c] / kPaths - mean * mean) / (kPaths - 1));
      EXPECT_NEAR(mean, fresnelIntegral[c], 4 * sigma + 1e-6)
          << incidenceDeg << "°, " << channels[c] << " nm";
    }
  }
}
