// The path tracer against answers known in closed form: white furnace, direct light from point
// and spherical area lights (alone and with the environment), the skin material's total
// reflectance, determinism across thread counts. Monte Carlo assertions state their standard error
// σ and allow 4σ.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/scene/data_paths.h"
#include "renderer/tracing/integrator.h"
#include "skin/core/constants.h"
#include "skin/core/thread_limit.h"
#include "skin/sampling/cosine_sampling.h"
#include "skin/skin_optics.h"
#include "skin/skin_walk.h"
#include "tests/support/test_scenes.h"

using hylios::kPi;

using namespace hylios;

namespace {

using test::constantSpectrum;
using test::singleWavelengthBand;

/// A sphere of `material` (radius 1 at the origin) seen from +z, in a uniform environment L.
SceneDesc sphereScene(const MaterialDesc& material, double environment, int maxDepth = 8) {
  SceneDesc scene;
  scene.camera.position = {0, 0, 6};
  scene.camera.verticalFovDeg = 25;
  scene.film.width = scene.film.height = 24;
  scene.film.samplesPerPixel = 4;
  scene.film.bands = {singleWavelengthBand(550)};
  scene.materials = {material};
  ShapeDesc sphere;
  sphere.kind = ShapeDesc::Kind::Sphere;
  sphere.material = material.name;
  scene.shapes = {sphere};
  if (environment > 0) {
    LightDesc env;
    env.kind = LightDesc::Kind::Environment;
    env.emission = constantSpectrum(environment);
    scene.lights = {env};
  }
  scene.integrator.maxDepth = maxDepth;
  return scene;
}

MaterialDesc diffuse(double rho) {
  MaterialDesc m;
  m.kind = MaterialDesc::Kind::Diffuse;
  m.name = "d";
  m.reflectance = constantSpectrum(rho);
  return m;
}

MaterialDesc skinMaterial(const std::string& specimen) {
  MaterialDesc m;
  m.kind = MaterialDesc::Kind::Skin;
  m.name = "skin";
  m.skin.specimen = specimen;
  return m;
}

struct MeanAndError {
  double mean, standardError;
};

/// Paths along −z aimed uniformly over the sphere's projected disk (radius 1): the incidence
/// angle is then cosine-distributed (projected area ∝ cosθ·dA), as for diffuse illumination.
MeanAndError diskAverage(const Integrator& integrator, int paths, std::uint64_t seed) {
  double sum = 0, sum2 = 0;
  RenderStats stats;
  for (int i = 0; i < paths; ++i) {
    hylios::skin::Rng rng(seed, 0, static_cast<std::uint64_t>(i));
    const double r = std::sqrt(rng.uniform()), phi = 2 * kPi * rng.uniform();
    const Ray ray{{r * std::cos(phi), r * std::sin(phi), 10}, {0, 0, -1}};
    const double L = integrator.radiance(ray, 0, rng, stats);
    sum += L;
    sum2 += L * L;
  }
  const double mean = sum / paths;
  return {mean, std::sqrt(std::max(0.0, sum2 / paths - mean * mean) / (paths - 1))};
}

}  // namespace

TEST(Integrator, WhiteFurnaceDiffuseSphereReflectsTheEnvironment) {
  // A convex Lambertian sphere in a uniform environment L: one bounce reaches the sky, so the
  // radiance is ρ·L for every sphere point (NEE + BSDF sampling, MIS): exactly ρL in expectation.
  for (const double rho : {1.0, 0.5}) {
    const Integrator integrator(sphereScene(diffuse(rho), 2.0), {550});
    const MeanAndError m = diskAverage(integrator, 20000, 5);
    EXPECT_NEAR(m.mean, rho * 2.0, 4 * m.standardError + 1e-12)
        << "rho " << rho << ", σ " << m.standardError;
    EXPECT_LT(m.standardError, 0.01);  // σ ≈ 0.004: MIS keeps the furnace nearly noise-free
  }
}

TEST(Integrator, WhiteFurnaceImageBackgroundIsExactAndDepthZeroIsBlack) {
  SceneDesc scene = sphereScene(diffuse(1.0), 1.5, 0);
  Film film(scene.film);
  const Integrator integrator(scene, {550});
  integrator.render(film, quietRenderOptions("test"));
  EXPECT_DOUBLE_EQ(film.value(0, 0, 0), 1.5);    // sky
  EXPECT_DOUBLE_EQ(film.value(12, 12, 0), 0.0);  // sphere, no bounce allowed
}

TEST(Integrator, AHiddenEnvironmentIsBlackBehindTheSubjectAndStillLightsIt) {
  // camera_visible = false: camera rays that miss see 0, but the sphere still reflects ρL in
  // expectation (next-event estimation and bounces that reach the sky count as before).
  SceneDesc scene = sphereScene(diffuse(0.5), 2.0);
  scene.lights[0].cameraVisible = false;
  Film film(scene.film);
  const Integrator integrator(scene, {550});
  integrator.render(film, quietRenderOptions("test"));
  EXPECT_EQ(film.value(0, 0, 0), 0.0);  // the sky, hidden
  EXPECT_GT(film.value(12, 12, 0), 0.0);
  const MeanAndError m = diskAverage(integrator, 20000, 5);
  EXPECT_NEAR(m.mean, 1.0, 4 * m.standardError + 1e-12) << "σ " << m.standardError;
  EXPECT_LT(m.standardError, 0.01);  // σ ≈ 0.002, as for the visible sky
}

TEST(Integrator, PointLightOnADiffusePlaneIsExact) {
  // L = ρ/π · I·cosθ/d² with no noise: one delta light, NEE only.
  SceneDesc scene = sphereScene(diffuse(0.6), 0, 1);
  scene.shapes[0].kind = ShapeDesc::Kind::Plane;
  scene.shapes[0].planeNormal = {0, 0, 1};
  scene.shapes[0].planeSize = 100;
  LightDesc point;
  point.kind = LightDesc::Kind::Point;
  point.position = {1, 0, 2};
  point.emission = constantSpectrum(3);
  scene.lights = {point};
  const Integrator integrator(scene, {550});
  hylios::skin::Rng rng(1);
  RenderStats stats;
  const double L = integrator.radiance({{0, 0, 5}, {0, 0, -1}}, 0, rng, stats);
  const double d2 = 5, cosTheta = 2 / std::sqrt(5.0);
  EXPECT_NEAR(L, 0.6 / kPi * 3 * cosTheta / d2, 1e-9);
}

TEST(Integrator, SphericalAreaLightOnADiffusePlaneMatchesItsSolidAngle) {
  // Emitting sphere (radius R = 0.5, radiance Le = 2) centred at height D = 2 over a diffuse plane
  // (ρ = 0.8), seen at the foot point: L = ρ·Le·(R/D)² = 0.1 (the sphere subtends sin²α = (R/D)²).
  SceneDesc scene = sphereScene(diffuse(0.8), 0, 1);
  scene.shapes[0].kind = ShapeDesc::Kind::Plane;
  scene.shapes[0].planeNormal = {0, 0, 1};
  scene.shapes[0].planeSize = 100;
  MaterialDesc black = diffuse(0);
  black.name = "black";
  scene.materials.push_back(black);
  ShapeDesc lamp;
  lamp.kind = ShapeDesc::Kind::Sphere;
  lamp.name = "lamp";
  lamp.centre = {0, 0, 2};
  lamp.radius = 0.5;
  lamp.material = "black";
  scene.shapes.push_back(lamp);
  LightDesc area;
  area.kind = LightDesc::Kind::Area;
  area.shape = "lamp";
  area.emission = constantSpectrum(2);
  scene.lights = {area};
  const Integrator integrator(scene, {550});
  double sum = 0, sum2 = 0;
  const int n = 40000;
  RenderStats stats;
  for (int i = 0; i < n; ++i) {
    hylios::skin::Rng rng(9, 0, static_cast<std::uint64_t>(i));
    const double L =
        integrator.radiance({{0.0, 0.0, 1.0}, {0, 0, -1}}, 0, rng, stats);  // under the lamp
    sum += L;
    sum2 += L * L;
  }
  const double mean = sum / n, sigma = std::sqrt((sum2 / n - mean * mean) / (n - 1));
  EXPECT_NEAR(mean, 0.8 * 2 * 0.0625, 4 * sigma) << "σ " << sigma;
  EXPECT_LT(sigma, 0.002);
}

TEST(Integrator, AnAreaLightAndTheEnvironmentSumOverTheirProjectedSolidAngles) {
  // The spherical lamp (R = 0.8, Le = 2, centre at height D = 2) over a diffuse plane (ρ = 0.8,
  // side 4) in an environment L = 0.5: at the foot point the lamp covers a cap of projected solid
  // angle π sin²α (sin α = R/D) and hides that much of the sky, so L_out = ρ(L + (Le − L) sin²α)
  // = 0.592. The two lights are chosen with unequal probabilities (light_selection.h), which
  // next-event estimation and the MIS weights of the rays that hit the lamp or escape must share.
  SceneDesc scene = sphereScene(diffuse(0.8), 0, 1);
  scene.shapes[0].kind = ShapeDesc::Kind::Plane;
  scene.shapes[0].planeNormal = {0, 0, 1};
  scene.shapes[0].planeSize = 4;
  MaterialDesc black = diffuse(0);
  black.name = "black";
  scene.materials.push_back(black);
  ShapeDesc lamp;
  lamp.kind = ShapeDesc::Kind::Sphere;
  lamp.name = "lamp";
  lamp.centre = {0, 0, 2};
  lamp.radius = 0.8;
  lamp.material = "black";
  scene.shapes.push_back(lamp);
  LightDesc area, environment;
  area.kind = LightDesc::Kind::Area;
  area.shape = "lamp";
  area.emission = constantSpectrum(2);
  environment.kind = LightDesc::Kind::Environment;
  environment.emission = constantSpectrum(0.5);
  scene.lights = {area, environment};
  const Integrator integrator(scene, {550});
  ASSERT_GT(std::fabs(integrator.lights().selectionProbability(0) - 0.5), 0.1);
  double sum = 0, sum2 = 0;
  const int n = 40000;
  RenderStats stats;
  for (int i = 0; i < n; ++i) {
    hylios::skin::Rng rng(10, 0, static_cast<std::uint64_t>(i));
    const double L = integrator.radiance({{0.0, 0.0, 0.5}, {0, 0, -1}}, 0, rng, stats);
    sum += L;
    sum2 += L * L;
  }
  const double mean = sum / n, sigma = std::sqrt((sum2 / n - mean * mean) / (n - 1));
  EXPECT_NEAR(mean, 0.8 * (0.5 + 1.5 * 0.16), 4 * sigma) << "σ " << sigma;
  EXPECT_LT(sigma, 0.004);
}

TEST(Integrator, SkinSphereInAUniformEnvironmentReflectsTheWalksDiffuseAlbedo) {
  // Paths over the projected disk hit the skin sphere at cosine-distributed incidence; under a
  // uniform environment L every reflected path reaches the sky, so the mean radiance / L is the
  // walk's total reflectance for diffuse incidence. Reference: the same walk (S1, 550 nm) traced
  // directly with cosine-distributed incidence. Both estimates are Bernoulli-like with
  // R ≈ 0.3: σ ≈ sqrt(R(1 − R)/N) ≈ 0.0046 each for N = 10000; the test allows 4σ of the
  // difference.
  const int n = 10000;
  const Integrator integrator(sphereScene(skinMaterial("S1"), 1.0), {550});
  const MeanAndError rendered = diskAverage(integrator, n, 11);

  const auto spectra = hylios::skin::SpectralDatabase::load(spectraDir());
  const auto specimen = hylios::skin::loadSpecimen("S1", specimenDir());
  const hylios::skin::SkinWalk walk(hylios::skin::computeSkinOptics(specimen, spectra, 550));
  double reflected = 0;
  for (int i = 0; i < n; ++i) {
    hylios::skin::Rng rng(12, 0, static_cast<std::uint64_t>(i));
    const hylios::skin::Vec3 d = hylios::skin::sampleCosineHemisphere(rng.uniform(), rng.uniform());
    const auto path = walk.trace(d, rng);
    if (path.end == hylios::skin::PathEnd::SurfaceReflection ||
        path.end == hylios::skin::PathEnd::SubsurfaceReflection)
      reflected += 1;
  }
  const double reference = reflected / n;
  const double sigma =
      std::hypot(rendered.standardError, std::sqrt(reference * (1 - reference) / n));
  EXPECT_NEAR(rendered.mean, reference, 4 * sigma)
      << "rendered " << rendered.mean << " reference " << reference << " σ " << sigma;
  EXPECT_GT(reference, 0.1);
}

TEST(Integrator, SameSeedSameImageAtOneAndTwoThreads) {
  SceneDesc scene = sphereScene(skinMaterial("S2"), 1.0);
  LightDesc point;
  point.kind = LightDesc::Kind::Point;
  point.position = {2, 2, 3};
  point.emission = constantSpectrum(5);
  scene.lights.push_back(point);
  scene.film.bands = {singleWavelengthBand(365), singleWavelengthBand(550)};
  scene.film.width = scene.film.height = 16;
  const Integrator integrator(scene, {365, 550});
  Film one(scene.film), two(scene.film);
  {
    const hylios::ThreadLimit limit(1);
    integrator.render(one, quietRenderOptions("1"));
  }
  {
    const hylios::ThreadLimit limit(2);
    integrator.render(two, quietRenderOptions("2"));
  }
  double total = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      for (std::size_t c = 0; c < 2; ++c) {
        ASSERT_EQ(one.value(x, y, c), two.value(x, y, c)) << x << "," << y << "," << c;
        total += one.value(x, y, c);
      }
  EXPECT_GT(total, 0);
}

TEST(Integrator, UnknownMaterialAndBadReflectanceAreSceneErrors) {
  SceneDesc scene = sphereScene(diffuse(1.2), 1);
  EXPECT_THROW(Integrator(scene, {550}), SceneError);
  scene = sphereScene(diffuse(0.5), 1);
  scene.shapes[0].material = "nothing";
  EXPECT_THROW(Integrator(scene, {550}), SceneError);
}
