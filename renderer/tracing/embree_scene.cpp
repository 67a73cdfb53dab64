#include "renderer/tracing/embree_scene.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "renderer/scene/toml_table_reader.h"
#include "skin/core/constants.h"

namespace hylios {
namespace {

void fatalEmbreeError(void*, RTCError code, const char* message) {
  std::fprintf(stderr, "hylios: fatal Embree error %d: %s\n", static_cast<int>(code),
               message ? message : "(no message)");
  std::fflush(stderr);
  std::abort();
}

/// Both roots of |o + t d − c|² = r² (t0 ≤ t1); false when the line misses the sphere.
bool sphereRoots(const glm::dvec3& o, const glm::dvec3& d, const EmbreeScene::Sphere& s, double& t0,
                 double& t1) {
  const glm::dvec3 oc = o - s.centre;
  const double a = glm::dot(d, d);
  const double b = glm::dot(oc, d);
  // Discriminant from the closest-approach distance (stable for rays far from the sphere).
  const glm::dvec3 closest = oc - d * (b / a);
  const double disc = a * (s.radius * s.radius - glm::dot(closest, closest));
  if (disc < 0) return false;
  const double q = -b - std::copysign(std::sqrt(disc), b);
  const double c = glm::dot(oc, oc) - s.radius * s.radius;
  t0 = q / a;
  t1 = q != 0 ? c / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

void sphereBounds(const RTCBoundsFunctionArguments* args) {
  const auto* s = static_cast<const EmbreeScene::Sphere*>(args->geometryUserPtr);
  RTCBounds* b = args->bounds_o;
  const double pad = s->radius * (1 + 1e-6);
  b->lower_x = static_cast<float>(s->centre.x - pad);
  b->lower_y = static_cast<float>(s->centre.y - pad);
  b->lower_z = static_cast<float>(s->centre.z - pad);
  b->upper_x = static_cast<float>(s->centre.x + pad);
  b->upper_y = static_cast<float>(s->centre.y + pad);
  b->upper_z = static_cast<float>(s->centre.z + pad);
}

/// The nearest root in (tnear, tfar) of ray i of a ray packet; < 0 when none.
template <typename RayN>
double nearestSphereRoot(const EmbreeScene::Sphere& s, RayN* ray, unsigned N, unsigned i) {
  const glm::dvec3 o(RTCRayN_org_x(ray, N, i), RTCRayN_org_y(ray, N, i), RTCRayN_org_z(ray, N, i));
  const glm::dvec3 d(RTCRayN_dir_x(ray, N, i), RTCRayN_dir_y(ray, N, i), RTCRayN_dir_z(ray, N, i));
  const double tnear = RTCRayN_tnear(ray, N, i), tfar = RTCRayN_tfar(ray, N, i);
  double t0, t1;
  if (!sphereRoots(o, d, s, t0, t1)) return -1;
  if (t0 > tnear && t0 < tfar) return t0;
  if (t1 > tnear && t1 < tfar) return t1;
  return -1;
}

void sphereIntersect(const RTCIntersectFunctionNArguments* args) {
  const auto* s = static_cast<const EmbreeScene::Sphere*>(args->geometryUserPtr);
  RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
  RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const double t = nearestSphereRoot(*s, ray, args->N, i);
    if (t < 0) continue;
    const glm::dvec3 o(RTCRayN_org_x(ray, args->N, i), RTCRayN_org_y(ray, args->N, i),
                       RTCRayN_org_z(ray, args->N, i));
    const glm::dvec3 d(RTCRayN_dir_x(ray, args->N, i), RTCRayN_dir_y(ray, args->N, i),
                       RTCRayN_dir_z(ray, args->N, i));
    const glm::dvec3 n = (o + d * t - s->centre) / s->radius;
    RTCRayN_tfar(ray, args->N, i) = static_cast<float>(t);
    RTCHitN_Ng_x(hit, args->N, i) = static_cast<float>(n.x);
    RTCHitN_Ng_y(hit, args->N, i) = static_cast<float>(n.y);
    RTCHitN_Ng_z(hit, args->N, i) = static_cast<float>(n.z);
    RTCHitN_u(hit, args->N, i) = 0;
    RTCHitN_v(hit, args->N, i) = 0;
    RTCHitN_primID(hit, args->N, i) = args->primID;
    RTCHitN_geomID(hit, args->N, i) = args->geomID;
    RTCHitN_instID(hit, args->N, i, 0) = args->context->instID[0];
  }
}

void sphereOccluded(const RTCOccludedFunctionNArguments* args) {
  const auto* s = static_cast<const EmbreeScene::Sphere*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    if (nearestSphereRoot(*s, args->ray, args->N, i) >= 0)
      RTCRayN_tfar(args->ray, args->N, i) = -std::numeric_limits<float>::infinity();
  }
}

/// The largest coordinate of a derived point (a transformed vertex, a sphere's extremes): ten
/// times the scene file's limit (renderer/scene/toml_table_reader.h), since a transform scales.
constexpr double kMaxDerivedCoordinate = 10 * kMaxSceneCoordinate;
/// Embree 3 asserts (and aborts) on a ray whose origin or direction is not inside ±1.844e18.
constexpr double kMaxRayCoordinate = 1e17;

bool rayInRange(const Ray& ray) {
  for (int k = 0; k < 3; ++k)
    if (!(std::fabs(ray.origin[k]) <= kMaxRayCoordinate) ||
        !(std::fabs(ray.direction[k]) <= kMaxRayCoordinate))
      return false;
  return !std::isnan(ray.tMax);
}

void setRay(RTCRay& r, const Ray& ray) {
  if (!rayInRange(ray))
    throw std::runtime_error(
        fmt::format("a ray left the range the tracer can represent (origin ({}, {}, {}), "
                    "direction ({}, {}, {})); keep the scene within the limits of "
                    "docs/scene-format.md",
                    ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y,
                    ray.direction.z));
  r.org_x = static_cast<float>(ray.origin.x);
  r.org_y = static_cast<float>(ray.origin.y);
  r.org_z = static_cast<float>(ray.origin.z);
  r.dir_x = static_cast<float>(ray.direction.x);
  r.dir_y = static_cast<float>(ray.direction.y);
  r.dir_z = static_cast<float>(ray.direction.z);
  r.tnear = 0;
  r.tfar = std::isfinite(ray.tMax) ? static_cast<float>(ray.tMax)
                                   : std::numeric_limits<float>::infinity();
  r.mask = 0xFFFFFFFFu;
  r.time = 0;
  r.flags = 0;
  r.id = 0;
}

}  // namespace

EmbreeDevice::EmbreeDevice() : device_(rtcNewDevice(nullptr)) {
  if (!device_) {
    std::fprintf(stderr, "hylios: fatal Embree error %d: cannot create a device\n",
                 static_cast<int>(rtcGetDeviceError(nullptr)));
    std::abort();
  }
  rtcSetDeviceErrorFunction(device_, fatalEmbreeError, nullptr);
}

EmbreeDevice::~EmbreeDevice() { rtcReleaseDevice(device_); }

EmbreeScene::Sphere transformedSphere(const ShapeDesc& desc) {
  const glm::dmat3 linear(desc.transform);
  const double sx = glm::length(linear[0]), sy = glm::length(linear[1]),
               sz = glm::length(linear[2]);
  const double tolerance = 1e-9 * std::max({sx, sy, sz});
  const bool orthogonal = std::fabs(glm::dot(linear[0], linear[1])) <= tolerance * sx &&
                          std::fabs(glm::dot(linear[1], linear[2])) <= tolerance * sy &&
                          std::fabs(glm::dot(linear[0], linear[2])) <= tolerance * sz;
  if (!(sx > 0) || std::fabs(sx - sy) > tolerance || std::fabs(sx - sz) > tolerance || !orthogonal)
    throw SceneError(desc.where,
                     "a sphere's transform may only rotate, translate and scale uniformly");
  if (!(desc.radius > 0) || !std::isfinite(desc.radius))
    throw SceneError(desc.where, "sphere radius must be a positive finite number");
  return {glm::dvec3(desc.transform * glm::dvec4(desc.centre, 1.0)), desc.radius * sx};
}

EmbreeScene::EmbreeScene(const SceneDesc& scene) {
  scene_ = rtcNewScene(device_.handle());
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  try {
    addShapes(scene);
  } catch (...) {
    rtcReleaseScene(scene_);
    throw;
  }
  rtcCommitScene(scene_);
}

void EmbreeScene::addShapes(const SceneDesc& scene) {
  for (std::size_t i = 0; i < scene.shapes.size(); ++i) {
    const ShapeDesc& desc = scene.shapes[i];
    auto shape = std::make_unique<Shape>();
    RTCGeometry geometry = nullptr;
    if (desc.kind == ShapeDesc::Kind::Sphere) {
      shape->isSphere = true;
      shape->sphere = transformedSphere(desc);
      shape->area = 4 * kPi * shape->sphere.radius * shape->sphere.radius;
      geometry = rtcNewGeometry(device_.handle(), RTC_GEOMETRY_TYPE_USER);
      rtcSetGeometryUserPrimitiveCount(geometry, 1);
      rtcSetGeometryUserData(geometry, &shape->sphere);
      rtcSetGeometryBoundsFunction(geometry, sphereBounds, nullptr);
      rtcSetGeometryIntersectFunction(geometry, sphereIntersect);
      rtcSetGeometryOccludedFunction(geometry, sphereOccluded);
      const glm::dvec3 c = glm::abs(shape->sphere.centre) + shape->sphere.radius;
      if (!(std::max({c.x, c.y, c.z}) <= kMaxDerivedCoordinate))
        throw SceneError(
            desc.where,
            fmt::format("the transformed sphere reaches {:g} scene units from the origin; "
                        "at most {:g}",
                        std::max({c.x, c.y, c.z}), kMaxDerivedCoordinate));
      extent_ = std::max({extent_, c.x, c.y, c.z});
    } else {
      if (desc.kind == ShapeDesc::Kind::Mesh) {
        shape->mesh = loadObjMesh(desc.meshPath, desc.where, desc.smoothNormals);
      } else {
        if (!(desc.planeSize > 0) || !(glm::length(desc.planeNormal) > 0))
          throw SceneError(desc.where, "a plane needs a positive size and a nonzero normal");
        shape->mesh = makePlaneMesh(desc.planePoint, desc.planeNormal, desc.planeSize);
      }
      transformMesh(shape->mesh, desc.transform, desc.where);
      const TriangleMesh& mesh = shape->mesh;
      for (const glm::dvec3& p : mesh.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
          throw SceneError(desc.where, "a transformed vertex is not finite");
        else if (!(std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}) <=
                   kMaxDerivedCoordinate))
          throw SceneError(
              desc.where,
              fmt::format("a transformed vertex ({:g}, {:g}, {:g}) lies beyond {:g} scene "
                          "units from the origin",
                          p.x, p.y, p.z, kMaxDerivedCoordinate));
      geometry = rtcNewGeometry(device_.handle(), RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* vertices = static_cast<float*>(
          rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                  3 * sizeof(float), mesh.positions.size()));
      for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::dvec3& p = mesh.positions[v];
        for (int k = 0; k < 3; ++k) vertices[3 * v + k] = static_cast<float>(p[k]);
        extent_ = std::max({extent_, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
      }
      auto* indices = static_cast<unsigned*>(
          rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                  3 * sizeof(unsigned), mesh.triangles.size()));
      double running = 0;
      for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) indices[3 * t + k] = mesh.triangles[t][k];
        const auto& tri = mesh.triangles[t];
        running += 0.5 * glm::length(glm::cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                                                mesh.positions[tri[2]] - mesh.positions[tri[0]]));
        shape->triangleAreaCdf.push_back(running);
      }
      shape->area = running;
      for (double& c : shape->triangleAreaCdf) c /= running;
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene_, geometry, static_cast<unsigned>(i));
    rtcReleaseGeometry(geometry);
    shapes_.push_back(std::move(shape));
  }
}

EmbreeScene::~EmbreeScene() {
  if (scene_) rtcReleaseScene(scene_);
}

double EmbreeScene::shapeArea(std::size_t shape) const { return shapes_.at(shape)->area; }

std::size_t EmbreeScene::skippedDegenerate(std::size_t shape) const {
  return shapes_.at(shape)->isSphere ? 0 : shapes_.at(shape)->mesh.skippedDegenerate;
}

SurfaceHit EmbreeScene::triangleHit(const Shape& shape, std::size_t shapeIndex,
                                    std::size_t primitive, double u, double v,
                                    const Ray& ray) const {
  const TriangleMesh& mesh = shape.mesh;
  const auto& tri = mesh.triangles[primitive];
  const double w = 1 - u - v;
  SurfaceHit hit;
  hit.shape = shapeIndex;
  hit.primitive = primitive;
  hit.position =
      w * mesh.positions[tri[0]] + u * mesh.positions[tri[1]] + v * mesh.positions[tri[2]];
  hit.t = glm::dot(hit.position - ray.origin, ray.direction);
  hit.geometricNormal = glm::normalize(glm::cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                                                  mesh.positions[tri[2]] - mesh.positions[tri[0]]));
  glm::dvec3 n = w * mesh.normals[tri[0]] + u * mesh.normals[tri[1]] + v * mesh.normals[tri[2]];
  const double len = glm::length(n);
  n = len > 0 ? n / len : hit.geometricNormal;
  hit.shadingNormal = glm::dot(n, hit.geometricNormal) < 0 ? -n : n;
  if (!mesh.uvs.empty()) {
    hit.uv = w * mesh.uvs[tri[0]] + u * mesh.uvs[tri[1]] + v * mesh.uvs[tri[2]];
    hit.hasUv = true;
  }
  return hit;
}

SurfaceHit EmbreeScene::sphereHit(const Shape& shape, std::size_t shapeIndex, const Ray& ray,
                                  double tFloat) const {
  double t0, t1;
  double t = tFloat;
  if (sphereRoots(ray.origin, ray.direction, shape.sphere, t0, t1))  // refine in double precision
    t = std::fabs(t0 - tFloat) <= std::fabs(t1 - tFloat) ? t0 : t1;
  SurfaceHit hit;
  hit.shape = shapeIndex;
  hit.t = t;
  const glm::dvec3 n = glm::normalize(ray.origin + ray.direction * t - shape.sphere.centre);
  hit.position = shape.sphere.centre + n * shape.sphere.radius;
  hit.geometricNormal = n;
  hit.shadingNormal = n;
  hit.uv = {0.5 + std::atan2(n.x, n.z) / (2 * kPi), std::acos(std::clamp(n.y, -1.0, 1.0)) / kPi};
  hit.hasUv = true;
  return hit;
}

std::optional<SurfaceHit> EmbreeScene::intersect(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayHit;
  setRay(rayHit.ray, ray);
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rayHit);
  if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  const std::size_t index = rayHit.hit.geomID;
  const Shape& shape = *shapes_[index];
  if (shape.isSphere) return sphereHit(shape, index, ray, rayHit.ray.tfar);
  return triangleHit(shape, index, rayHit.hit.primID, rayHit.hit.u, rayHit.hit.v, ray);
}

bool EmbreeScene::occluded(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r;
  setRay(r, ray);
  rtcOccluded1(scene_, &context, &r);
  return r.tfar < 0;
}

AreaSample EmbreeScene::sampleArea(std::size_t shapeIndex, double u0, double u1, double u2) const {
  const Shape& shape = *shapes_.at(shapeIndex);
  AreaSample sample;
  sample.pdfArea = 1.0 / shape.area;
  if (shape.isSphere) {  // uniform on the sphere: z uniform in [−1, 1], azimuth uniform
    const double z = 1 - 2 * u1, r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * kPi * u2;
    sample.normal = {r * std::cos(phi), r * std::sin(phi), z};
    sample.position = shape.sphere.centre + sample.normal * shape.sphere.radius;
    return sample;
  }
  const auto& cdf = shape.triangleAreaCdf;
  const std::size_t t = std::min<std::size_t>(
      static_cast<std::size_t>(std::upper_bound(cdf.begin(), cdf.end(), u0) - cdf.begin()),
      cdf.size() - 1);
  const auto& tri = shape.mesh.triangles[t];
  const double su = std::sqrt(u1);  // uniform on the triangle
  const double b0 = 1 - su, b1 = u2 * su;
  const glm::dvec3 &p0 = shape.mesh.positions[tri[0]], &p1 = shape.mesh.positions[tri[1]],
                   &p2 = shape.mesh.positions[tri[2]];
  sample.position = b0 * p0 + b1 * p1 + (1 - b0 - b1) * p2;
  sample.normal = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  return sample;
}

}  // namespace hylios
