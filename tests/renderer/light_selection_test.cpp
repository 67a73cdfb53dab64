// Next-event estimation's choice of light (renderer/tracing/light_selection.h): the mixture with
// its defensive share against hand values, an area light's solid angle against a sphere's closed
// form, receiver points in proportion to area, and LightSet's choice frequencies. Monte Carlo
// assertions state their standard error σ and allow 4σ.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "renderer/tracing/embree_scene.h"
#include "renderer/tracing/light_selection.h"
#include "renderer/tracing/lights.h"
#include "skin/core/constants.h"
#include "tests/support/test_scenes.h"

using hylios::kPi;

using namespace hylios;

namespace {

ShapeDesc sphereShape(const std::string& name, glm::dvec3 centre, double radius) {
  ShapeDesc s;
  s.kind = ShapeDesc::Kind::Sphere;
  s.name = name;
  s.centre = centre;
  s.radius = radius;
  s.material = "m";
  return s;
}

SceneDesc sceneOf(std::vector<ShapeDesc> shapes) {
  SceneDesc scene;
  MaterialDesc m;
  m.kind = MaterialDesc::Kind::Diffuse;
  m.name = "m";
  m.reflectance = test::constantSpectrum(0.5);
  scene.materials = {m};
  scene.shapes = std::move(shapes);
  return scene;
}

}  // namespace

TEST(LightSelection, ProbabilitiesMixTheContributionsWithADefensiveShare) {
  // p_i = 0.9·e_i/Σe + 0.1/N.
  const std::vector<double> two = lightSelectionProbabilities({3, 1});
  EXPECT_DOUBLE_EQ(two[0], 0.9 * 0.75 + 0.05);
  EXPECT_DOUBLE_EQ(two[1], 0.9 * 0.25 + 0.05);
  const std::vector<double> three = lightSelectionProbabilities({2, 0, 0});
  EXPECT_DOUBLE_EQ(three[0], 0.9 + 0.1 / 3);
  EXPECT_DOUBLE_EQ(three[1], 0.1 / 3);  // a light estimated dark keeps δ/N
  EXPECT_EQ(lightSelectionProbabilities({0, 0}), (std::vector<double>{0.5, 0.5}));
  EXPECT_EQ(lightSelectionProbabilities({7}), (std::vector<double>{1.0}));
  EXPECT_TRUE(lightSelectionProbabilities({}).empty());
}

TEST(LightSelection, AreaLightSolidAngleMatchesASphereSeenFromOutside) {
  // A sphere of radius R at distance D subtends 2π(1 − cos α), sin α = R/D. Each call estimates
  // it from kLightPoints points (its own stream per receiver index): the mean over 4000 calls.
  const double R = 1, D = 4;
  const EmbreeScene geometry(sceneOf({sphereShape("lamp", {0, 0, D}, R)}));
  const int calls = 4000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < calls; ++i) {
    const double omega = areaLightSolidAngle(geometry, 0, {0, 0, 0}, static_cast<std::size_t>(i));
    sum += omega;
    sum2 += omega * omega;
  }
  const double mean = sum / calls, sigma = std::sqrt((sum2 / calls - mean * mean) / (calls - 1));
  const double cosAlpha = std::sqrt(1 - (R / D) * (R / D));
  EXPECT_NEAR(mean, 2 * kPi * (1 - cosAlpha), 4 * sigma) << "σ " << sigma;
  EXPECT_LT(sigma, 0.004);  // ≈ 0.0023 (the exact value is 0.199)
  // Only the front side counts: a square lamp facing the receiver gives its solid angle, turned
  // away it gives 0.
  ShapeDesc square;
  square.kind = ShapeDesc::Kind::Plane;
  square.name = "square";
  square.planePoint = {0, 0, 2};
  square.planeSize = 0.2;
  square.material = "m";
  square.planeNormal = {0, 0, -1};
  const EmbreeScene facing(sceneOf({square}));
  EXPECT_NEAR(areaLightSolidAngle(facing, 0, {0, 0, 0}, 0), 0.04 / 4, 0.04 / 4 * 0.02);
  square.planeNormal = {0, 0, 1};
  const EmbreeScene away(sceneOf({square}));
  EXPECT_EQ(areaLightSolidAngle(away, 0, {0, 0, 0}, 0), 0.0);
}

TEST(LightSelection, ReceiverPointsLieOnTheShapesInProportionToTheirArea) {
  // Spheres of radius 1 and 2: areas 1 : 4. The area coordinate is stratified over the 256
  // points, so the split is 256/5 and 4·256/5 within one point.
  const EmbreeScene geometry(
      sceneOf({sphereShape("a", {0, 0, 0}, 1), sphereShape("b", {10, 0, 0}, 2)}));
  const std::vector<glm::dvec3> points = receiverPoints(geometry, {0, 1});
  ASSERT_EQ(points.size(), static_cast<std::size_t>(kReceiverPoints));
  int onSmall = 0;
  for (const glm::dvec3& p : points) {
    const double small = glm::length(p), large = glm::length(p - glm::dvec3{10, 0, 0});
    ASSERT_TRUE(std::fabs(small - 1) < 1e-9 || std::fabs(large - 2) < 1e-9);
    if (std::fabs(small - 1) < 1e-9) ++onSmall;
  }
  EXPECT_NEAR(onSmall, kReceiverPoints / 5.0, 1.0);
  EXPECT_TRUE(receiverPoints(geometry, {}).empty());
}

TEST(LightSet, PicksLightsByTheIrradianceTheyGiveTheReceivers) {
  // A receiver sphere of radius 0.01 at the origin; a point light I = 3 at distance 2 gives it
  // I/d² = 0.75 (within 1 %: d varies by ±0.01), an environment L = 0.5 gives πL.
  SceneDesc scene = sceneOf({sphereShape("receiver", {0, 0, 0}, 0.01)});
  LightDesc point;
  point.kind = LightDesc::Kind::Point;
  point.position = {0, 0, 2};
  point.emission = test::constantSpectrum(3);
  LightDesc environment;
  environment.kind = LightDesc::Kind::Environment;
  environment.emission = test::constantSpectrum(0.5);
  scene.lights = {point, environment};
  const EmbreeScene geometry(scene);
  const LightSet lights(scene, geometry, {550});
  const double ePoint = 0.75, eEnvironment = 0.5 * kPi;
  const double pPoint = 0.9 * ePoint / (ePoint + eEnvironment) + 0.05;
  EXPECT_NEAR(lights.selectionProbability(0), pPoint, 0.01 * pPoint);
  EXPECT_DOUBLE_EQ(lights.selectionProbability(0) + lights.selectionProbability(1), 1.0);
  // sampleGeometry picks light 0 for uSelect below its probability: on a grid of 1000 values
  // of uSelect, p·1000 of them within one.
  int chosePoint = 0;
  for (int k = 0; k < 1000; ++k) {
    const auto s = lights.sampleGeometry({0, 0, 0.01}, (k + 0.5) / 1000, 0.3, 0.6, 0.2);
    ASSERT_TRUE(s.has_value());
    if (s->light == 0) {
      ++chosePoint;
      EXPECT_DOUBLE_EQ(s->pdf, lights.selectionProbability(0));
    } else {
      EXPECT_DOUBLE_EQ(s->pdf, lights.selectionProbability(1) / (4 * kPi));
    }
  }
  EXPECT_NEAR(chosePoint, 1000 * lights.selectionProbability(0), 1.0);
  EXPECT_DOUBLE_EQ(lights.environmentPdf(), lights.selectionProbability(1) / (4 * kPi));
  EXPECT_NE(lights.selectionReport(scene).find("point 0."), std::string::npos);
}
