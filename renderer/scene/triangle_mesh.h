// Triangle meshes for the renderer: loading Wavefront OBJ files (through tinyobjloader) with strict
// validation, building the two-triangle plane, and applying a shape's object-to-world transform.
//
// Loading rejects, with SceneError at the shape's scene-file position and the OBJ line where known:
// a missing or unreadable file, tinyobjloader errors and warnings, vertex/normal/texture numbers
// that are not finite numbers ("nan", "inf", "1e999", text), indices out of range, and a mesh
// without a single usable triangle. Degenerate triangles (zero area, or repeated vertices) are
// skipped and counted in TriangleMesh::skippedDegenerate, never silently dropped. Materials named
// by the OBJ (mtllib/usemtl) are ignored: the scene file assigns materials.
//
// Normals: the OBJ's per-vertex normals when every corner has one and smoothNormals is on;
// otherwise area-weighted averages of the face normals (smoothNormals) or the face normal (flat).
// Texture coordinates are kept when every corner has one (for melanin maps).
#pragma once
#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <filesystem>
#include <vector>

#include "renderer/scene/scene.h"

namespace hylios {

struct TriangleMesh {
  std::vector<glm::dvec3> positions;  ///< per corner-vertex (scene units)
  std::vector<glm::dvec3> normals;    ///< per vertex, unit (shading normals)
  std::vector<glm::dvec2> uvs;        ///< per vertex; empty when the mesh has none
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::size_t skippedDegenerate = 0;  ///< degenerate triangles left out
};

/// Loads an OBJ file; `where` is the shape's position in the scene file (for errors).
TriangleMesh loadObjMesh(const std::filesystem::path& path, const SourceLocation& where,
                         bool smoothNormals);
/// Parses OBJ text (tests); `sourceName` appears in messages.
TriangleMesh parseObjMesh(const std::string& objText, const std::string& sourceName,
                          const SourceLocation& where, bool smoothNormals);

/// A square of side `size` centred on `point` with normal `normal` (two triangles, uvs in [0, 1]²).
TriangleMesh makePlaneMesh(const glm::dvec3& point, const glm::dvec3& normal, double size);

/// Positions by `objectToWorld`, normals by its inverse transpose (renormalised). Throws SceneError
/// at `where` for a singular transform.
void transformMesh(TriangleMesh& mesh, const glm::dmat4& objectToWorld,
                   const SourceLocation& where);

}  // namespace hylios
