// Vectors at a surface hit, shared by the integrator and the materials: conversions between the
// renderer's glm vectors and the skin model's skin::Vec3, and the hit's normals turned to face the
// arriving ray.
#pragma once
#include <glm/glm.hpp>

#include "skin/core/vector3.h"

namespace hylios {

inline skin::Vec3 toSkin(const glm::dvec3& v) { return {v.x, v.y, v.z}; }
inline glm::dvec3 toGlm(const skin::Vec3& v) { return {v.x, v.y, v.z}; }

/// A hit's geometric and shading normals on the side a ray travelling along `direction` arrives
/// from (a back-face hit flips both); the shading normal falls back to the geometric one when the
/// ray is not above its hemisphere.
struct FacingNormals {
  glm::dvec3 geometric;
  glm::dvec3 shading;
};
inline FacingNormals faceTheRay(const glm::dvec3& direction, glm::dvec3 geometric,
                                glm::dvec3 shading) {
  if (glm::dot(direction, geometric) > 0) {
    geometric = -geometric;
    shading = -shading;
  }
  if (!(glm::dot(direction, shading) < 0)) shading = geometric;
  return {geometric, shading};
}

}  // namespace hylios
