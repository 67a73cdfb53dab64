// OBJ loading and validation, the Embree scene (meshes, planes, analytic spheres), area sampling,
// the camera, and Embree's fatal error callback.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "renderer/scene/triangle_mesh.h"
#include "renderer/tracing/camera.h"
#include "renderer/tracing/embree_scene.h"
#include "skin/core/constants.h"
#include "skin/core/random.h"

using hylios::kPi;

using namespace hylios;

namespace {

const SourceLocation kWhere{"scene.toml", 12, 3};

std::string sceneErrorOf(const std::string& obj) {
  try {
    parseObjMesh(obj, "test.obj", kWhere, true);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

ShapeDesc sphereShape(glm::dvec3 centre, double radius) {
  ShapeDesc s;
  s.kind = ShapeDesc::Kind::Sphere;
  s.centre = centre;
  s.radius = radius;
  s.material = "m";
  s.where = kWhere;
  return s;
}

}  // namespace

TEST(ObjMesh, EmptyFileIsRejectedAtTheShapesPosition) {
  const std::string message = sceneErrorOf("# nothing here\n");
  EXPECT_NE(message.find("scene.toml:12:3"), std::string::npos) << message;
  EXPECT_NE(message.find("has no triangles"), std::string::npos) << message;
}

TEST(ObjMesh, NanAndInfiniteAndTextVerticesAreRejectedWithTheirLine) {
  for (const std::string bad : {"nan", "inf", "1e999", "abc"}) {
    const std::string message = sceneErrorOf("v 0 0 0\nv 1 0 0\nv 0 " + bad + " 0\nf 1 2 3\n");
    EXPECT_NE(message.find("line 3"), std::string::npos) << message;
    EXPECT_NE(message.find("'" + bad + "' is not a finite number"), std::string::npos) << message;
  }
  EXPECT_NE(sceneErrorOf("v 0 0\nf 1 1 1\n").find("needs 3 numbers"), std::string::npos);
}

TEST(ObjMesh, IndicesOutOfRangeAreRejected) {
  EXPECT_NE(sceneErrorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n").find("out of bounds"),
            std::string::npos);
  const std::string negative = sceneErrorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9\n");
  EXPECT_NE(negative.find("refers to vertex"), std::string::npos) << negative;
}

TEST(ObjMesh, DegenerateTrianglesAreSkippedAndCounted) {
  // Triangle 2 is collinear, triangle 3 repeats a vertex.
  const TriangleMesh mesh = parseObjMesh(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\nf 1 1 3\n", "t.obj", kWhere, true);
  EXPECT_EQ(mesh.triangles.size(), 1u);
  EXPECT_EQ(mesh.skippedDegenerate, 2u);
  const std::string allBad = sceneErrorOf("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  EXPECT_NE(allBad.find("no usable triangle"), std::string::npos) << allBad;
}

TEST(ObjMesh, ComputedNormalsAreAreaWeighted) {
  // Two faces share vertex 1: one in the z = 0 plane (area 2), one in the x = 0 plane (area 0.5).
  const TriangleMesh mesh = parseObjMesh(
      "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 0 0 1\nv 0 1 0\nf 1 2 3\nf 1 5 4\n", "t.obj", kWhere, true);
  ASSERT_EQ(mesh.triangles.size(), 2u);
  const glm::dvec3 n = mesh.normals[mesh.triangles[0][0]];
  // Σ cross products: (0, 0, 4) + (0.5·2·(1, 0, 0)) = (1, 0, 4) → normalised.
  EXPECT_NEAR(n.x, 1 / std::sqrt(17.0), 1e-12);
  EXPECT_NEAR(n.z, 4 / std::sqrt(17.0), 1e-12);
}

TEST(ObjMesh, ObjNormalsAndUvsAreKept) {
  const TriangleMesh mesh = parseObjMesh(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nvt 0.25 0.5\nvt 1 0\nvt 0 1\nf 1/1/1 2/2/1 3/3/1\n",
      "t.obj", kWhere, true);
  ASSERT_EQ(mesh.uvs.size(), 3u);
  EXPECT_EQ(mesh.uvs[0], glm::dvec2(0.25, 0.5));
  EXPECT_EQ(mesh.normals[1], glm::dvec3(0, 0, 1));
}

TEST(ObjMesh, TransformUsesTheInverseTransposeForNormals) {
  TriangleMesh mesh = makePlaneMesh({0, 0, 0}, glm::normalize(glm::dvec3(1, 1, 0)), 1);
  const glm::dmat4 stretch = glm::dmat4(glm::dvec4(2, 0, 0, 0), glm::dvec4(0, 1, 0, 0),
                                        glm::dvec4(0, 0, 1, 0), glm::dvec4(0, 0, 0, 1));
  transformMesh(mesh, stretch, kWhere);
  // The plane x + y = 0 becomes x/2 + y = 0, normal ∝ (1/2, 1, 0).
  const glm::dvec3 expected = glm::normalize(glm::dvec3(0.5, 1, 0));
  EXPECT_NEAR(glm::length(mesh.normals[0] - expected), 0, 1e-12);
  EXPECT_THROW(transformMesh(mesh, glm::dmat4(0.0), kWhere), SceneError);
}

TEST(EmbreeScene, MissingMeshFileNamesTheShape) {
  SceneDesc scene;
  ShapeDesc shape;
  shape.kind = ShapeDesc::Kind::Mesh;
  shape.meshPath = "/nonexistent/folder/head.obj";
  shape.where = kWhere;
  scene.shapes.push_back(shape);
  try {
    EmbreeScene geometry(scene);
    FAIL() << "no error";
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("scene.toml:12:3"), std::string::npos) << message;
    EXPECT_NE(message.find("cannot open mesh file '/nonexistent/folder/head.obj'"),
              std::string::npos)
        << message;
  }
}

TEST(EmbreeScene, MeshFromFileIsIntersectedWithInterpolatedAttributes) {
  const auto path = std::filesystem::temp_directory_path() / "hylios_embree_scene_test.obj";
  std::ofstream(path) << "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0.5 1\nf 1/1 2/2 3/3\n";
  SceneDesc scene;
  ShapeDesc shape;
  shape.kind = ShapeDesc::Kind::Mesh;
  shape.meshPath = path;
  shape.transform = glm::dmat4(1.0);
  shape.transform[3] = glm::dvec4(0, 0, -2, 1);  // moved to z = -2
  scene.shapes.push_back(shape);
  const EmbreeScene geometry(scene);
  const auto hit = geometry.intersect({{0, 0, 5}, {0, 0, -1}});
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->t, 7, 1e-12);
  EXPECT_NEAR(hit->uv.x, 0.5, 1e-6);
  EXPECT_NEAR(hit->uv.y, 0.5, 1e-6);
  EXPECT_NEAR(hit->geometricNormal.z, 1, 1e-12);
  EXPECT_FALSE(geometry.intersect({{2, 0, 5}, {0, 0, -1}}).has_value());
  EXPECT_NEAR(geometry.shapeArea(0), 2, 1e-12);
  std::filesystem::remove(path);
}

TEST(EmbreeScene, AnalyticSphereHitsInDoublePrecisionFromOutsideAndInside) {
  SceneDesc scene;
  scene.shapes.push_back(sphereShape({1, 2, 3}, 0.5));
  const EmbreeScene geometry(scene);
  const auto outside = geometry.intersect({{1, 2, 10}, {0, 0, -1}});
  ASSERT_TRUE(outside.has_value());
  EXPECT_NEAR(outside->t, 6.5, 1e-12);
  EXPECT_NEAR(outside->geometricNormal.z, 1, 1e-12);
  const auto inside = geometry.intersect({{1, 2, 3}, {1, 0, 0}});
  ASSERT_TRUE(inside.has_value());
  EXPECT_NEAR(inside->t, 0.5, 1e-12);
  EXPECT_NEAR(inside->geometricNormal.x, 1, 1e-12);  // outward even from inside
  EXPECT_TRUE(geometry.occluded({{1, 2, 10}, {0, 0, -1}, 7}));
  EXPECT_FALSE(geometry.occluded({{1, 2, 10}, {0, 0, -1}, 6}));
  EXPECT_NEAR(geometry.shapeArea(0), kPi * 1.0, 1e-12);
}

TEST(EmbreeScene, SphereTransformMustBeSimilarity) {
  ShapeDesc s = sphereShape({0, 0, 0}, 1);
  s.transform = glm::dmat4(1.0);
  s.transform[0][0] = 2;  // non-uniform scale
  EXPECT_THROW(transformedSphere(s), SceneError);
  s.transform[1][1] = 2;
  s.transform[2][2] = 2;
  s.transform[3] = glm::dvec4(1, 0, 0, 1);
  const auto sphere = transformedSphere(s);
  EXPECT_DOUBLE_EQ(sphere.radius, 2);
  EXPECT_DOUBLE_EQ(sphere.centre.x, 1);
}

TEST(EmbreeScene, AreaSamplingIsUniformOverTriangles) {
  // Plane of side 2: the mean sample position is the centre, the mean of x² is 1/3 (uniform on
  // [−1, 1]); N = 40000 samples, σ(mean x) = sqrt(1/3/N) ≈ 0.0029, σ(mean x²) = sqrt(4/45/N) ≈
  // 0.0015.
  SceneDesc scene;
  ShapeDesc plane;
  plane.kind = ShapeDesc::Kind::Plane;
  plane.planeNormal = {0, 0, 1};
  plane.planeSize = 2;
  scene.shapes.push_back(plane);
  const EmbreeScene geometry(scene);
  hylios::skin::Rng rng(3);
  const int n = 40000;
  double meanX = 0, meanX2 = 0, meanY = 0;
  for (int i = 0; i < n; ++i) {
    const AreaSample s = geometry.sampleArea(0, rng.uniform(), rng.uniform(), rng.uniform());
    ASSERT_NEAR(s.normal.z, 1, 1e-12);
    ASSERT_DOUBLE_EQ(s.pdfArea, 0.25);
    meanX += s.position.x / n;
    meanY += s.position.y / n;
    meanX2 += s.position.x * s.position.x / n;
  }
  EXPECT_NEAR(meanX, 0, 4 * 0.0029);
  EXPECT_NEAR(meanY, 0, 4 * 0.0029);
  EXPECT_NEAR(meanX2, 1.0 / 3, 4 * 0.0015);
}

TEST(Camera, CentreRayLooksAtTheTargetAndEdgesSpanTheFieldOfView) {
  CameraDesc desc;
  desc.position = {0, 0, 5};
  desc.lookAt = {0, 0, 0};
  desc.up = {0, 1, 0};
  desc.verticalFovDeg = 60;
  const Camera camera(desc, 200, 100);
  const Ray centre = camera.generateRay(100, 50, 0.5, 0.5);
  EXPECT_NEAR(centre.direction.z, -1, 1e-12);
  const Ray top = camera.generateRay(100, 0, 0.5, 0.5);  // image row 0 is the top
  EXPECT_NEAR(std::atan2(top.direction.y, -top.direction.z), 30 * kPi / 180, 1e-12);
  const Ray right = camera.generateRay(200, 50, 0.5, 0.5);
  EXPECT_NEAR(right.direction.x / -right.direction.z, 2 * std::tan(30 * kPi / 180), 1e-12);
  desc.lookAt = desc.position;
  EXPECT_THROW(Camera(desc, 10, 10), SceneError);
}

TEST(Camera, ThinLensRaysMeetOnThePlaneOfFocus) {
  CameraDesc desc;
  desc.position = {0, 0, 5};
  desc.apertureRadius = 0.2;
  desc.focusDistance = 4;
  const Camera camera(desc, 64, 64);
  const Ray a = camera.generateRay(10, 20, 0.1, 0.9), b = camera.generateRay(10, 20, 0.8, 0.3);
  const glm::dvec3 pa = a.origin + a.direction * ((1 - a.origin.z) / a.direction.z);
  const glm::dvec3 pb = b.origin + b.direction * ((1 - b.origin.z) / b.direction.z);
  EXPECT_NEAR(glm::length(pa - pb), 0, 1e-12);
}

TEST(EmbreeDeathTest, DeviceErrorsAreFatalWithAClearMessage) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH(
      {
        EmbreeDevice device;
        RTCGeometry triangles = rtcNewGeometry(device.handle(), RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetGeometryUserPrimitiveCount(triangles, 1);  // only user geometries have one
      },
      "hylios: fatal Embree error");
}
