// The scene's geometry in Embree 3: every ShapeDesc becomes one Embree geometry whose geomID is
// the shape's index in SceneDesc::shapes. Meshes come from OBJ files
// (renderer/scene/triangle_mesh.h), planes are two triangles, spheres are analytic Embree user
// geometry (intersected in double precision, so their normals are exact). Hits are refined in
// double precision: triangle hits from the barycentrics, sphere hits from the quadratic.
//
// Embree's errors are fatal: the device's error callback prints "hylios: fatal Embree error ..."
// and aborts (as Embree's tutorials do), since an error inside Embree leaves no state to recover.
//
// Area sampling of shapes (for area lights): uniform in area over the shape.
#pragma once
#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "renderer/scene/scene.h"
#include "renderer/scene/triangle_mesh.h"

namespace hylios {

/// An Embree device with the fatal error callback registered; owns the RTCDevice.
class EmbreeDevice {
 public:
  EmbreeDevice();
  ~EmbreeDevice();
  EmbreeDevice(const EmbreeDevice&) = delete;
  EmbreeDevice& operator=(const EmbreeDevice&) = delete;
  RTCDevice handle() const { return device_; }

 private:
  RTCDevice device_;
};

struct Ray {
  glm::dvec3 origin;
  glm::dvec3 direction;  ///< unit
  double tMax = std::numeric_limits<double>::infinity();
};

struct SurfaceHit {
  double t = 0;
  glm::dvec3 position;
  glm::dvec3 geometricNormal;  ///< unit; front side by winding (meshes) or outward (spheres)
  glm::dvec3 shadingNormal;    ///< unit, on the geometric normal's side
  glm::dvec2 uv{0};
  bool hasUv = false;
  std::size_t shape = 0;      ///< index into SceneDesc::shapes
  std::size_t primitive = 0;  ///< triangle index (meshes)
};

/// A point drawn on a shape's surface, uniformly in area.
struct AreaSample {
  glm::dvec3 position;
  glm::dvec3 normal;   ///< geometric, front side
  double pdfArea = 0;  ///< 1 / shape area
};

class EmbreeScene {
 public:
  /// Loads and validates every shape (SceneError at the shape's position on failure) and commits.
  explicit EmbreeScene(const SceneDesc& scene);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  std::optional<SurfaceHit> intersect(const Ray& ray) const;
  /// True when something lies along the ray before tMax.
  bool occluded(const Ray& ray) const;

  std::size_t shapeCount() const { return shapes_.size(); }
  double shapeArea(std::size_t shape) const;
  AreaSample sampleArea(std::size_t shape, double u0, double u1, double u2) const;
  /// Degenerate triangles skipped while loading, per shape (0 for spheres).
  std::size_t skippedDegenerate(std::size_t shape) const;
  /// Largest absolute coordinate of the scene's bounds (for ray offsets).
  double sceneExtent() const { return extent_; }

  struct Sphere {
    glm::dvec3 centre;
    double radius;
  };

 private:
  struct Shape {
    bool isSphere = false;
    Sphere sphere{};
    TriangleMesh mesh;
    std::vector<double> triangleAreaCdf;  ///< normalised running sum (meshes)
    double area = 0;
  };
  void addShapes(const SceneDesc& scene);
  SurfaceHit triangleHit(const Shape& shape, std::size_t shapeIndex, std::size_t primitive,
                         double u, double v, const Ray& ray) const;
  SurfaceHit sphereHit(const Shape& shape, std::size_t shapeIndex, const Ray& ray,
                       double tFloat) const;

  EmbreeDevice device_;
  RTCScene scene_ = nullptr;
  std::vector<std::unique_ptr<Shape>> shapes_;
  double extent_ = 1;
};

/// The sphere of a ShapeDesc after its transform (rotation and uniform scale only; SceneError
/// otherwise).
EmbreeScene::Sphere transformedSphere(const ShapeDesc& shape);

}  // namespace hylios
