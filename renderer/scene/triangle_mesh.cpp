#include "renderer/scene/triangle_mesh.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <tiny_obj_loader.h>
#include <tuple>

namespace hylios {
namespace {

/// Materials come from the scene file, so mtllib files are not read.
struct IgnoreMaterials : tinyobj::MaterialReader {
  bool operator()(const std::string&, std::vector<tinyobj::material_t>*,
                  std::map<std::string, int>*, std::string*, std::string*) override {
    return true;
  }
};

[[noreturn]] void fail(const SourceLocation& where, const std::string& source,
                       const std::string& what) {
  throw SceneError(where, "mesh '" + source + "': " + what);
}

/// tinyobjloader reads "nan" or text as 0 without a word, so vertex lines are checked first.
void checkNumbers(const std::string& text, const std::string& source, const SourceLocation& where) {
  std::istringstream lines(text);
  std::string line;
  for (int lineNumber = 1; std::getline(lines, line); ++lineNumber) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword != "v" && keyword != "vn" && keyword != "vt") continue;
    const std::size_t needed = keyword == "vt" ? 2 : 3;
    std::size_t count = 0;
    for (std::string word; words >> word; ++count) {
      if (!word.empty() && word[0] == '#') break;
      char* end = nullptr;
      const double value = std::strtod(word.c_str(), &end);
      if (end == word.c_str() || *end != '\0' || !std::isfinite(value))
        fail(where, source,
             "line " + std::to_string(lineNumber) + ": '" + keyword + "' value '" + word +
                 "' is not a finite number");
    }
    if (count < needed)
      fail(where, source,
           "line " + std::to_string(lineNumber) + ": '" + keyword + "' needs " +
               std::to_string(needed) + " numbers, found " + std::to_string(count));
  }
}

/// tinyobjloader's warnings, minus the ones about the OBJ's own materials (ignored by design).
std::string relevantWarnings(const std::string& warnings) {
  std::istringstream lines(warnings);
  std::string line, kept;
  while (std::getline(lines, line)) {
    if (line.empty() || line.rfind("material [", 0) == 0) continue;
    kept += (kept.empty() ? "" : "; ") + line;
  }
  return kept;
}

bool isDegenerate(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 e1 = b - a, e2 = c - a;
  const double areaTwice = glm::length(glm::cross(e1, e2));
  return !(areaTwice > 1e-12 * glm::length(e1) * glm::length(e2));
}

void computeNormals(TriangleMesh& mesh) {
  mesh.normals.assign(mesh.positions.size(), glm::dvec3(0));
  for (const auto& t : mesh.triangles) {
    // The cross product's length is twice the area: an area-weighted sum.
    const glm::dvec3 n = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                    mesh.positions[t[2]] - mesh.positions[t[0]]);
    for (std::uint32_t v : t) mesh.normals[v] += n;
  }
  for (auto& n : mesh.normals) {
    const double len = glm::length(n);
    n = len > 0 ? n / len : glm::dvec3(0, 0, 1);  // unused vertices only
  }
}

}  // namespace

TriangleMesh parseObjMesh(const std::string& objText, const std::string& source,
                          const SourceLocation& where, bool smoothNormals) {
  checkNumbers(objText, source, where);
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warnings, errors;
  IgnoreMaterials ignore;
  std::istringstream in(objText);
  const bool ok =
      tinyobj::LoadObj(&attrib, &shapes, &materials, &warnings, &errors, &in, &ignore, true);
  if (!ok || !errors.empty()) fail(where, source, "cannot parse: " + errors);
  if (const std::string w = relevantWarnings(warnings); !w.empty()) fail(where, source, w);

  const long nv = static_cast<long>(attrib.vertices.size() / 3);
  const long nn = static_cast<long>(attrib.normals.size() / 3);
  const long nt = static_cast<long>(attrib.texcoords.size() / 2);
  bool allNormals = true, allUvs = true;
  std::size_t faceCount = 0;
  for (const auto& shape : shapes) {
    for (const auto& idx : shape.mesh.indices) {
      if (idx.vertex_index < 0 || idx.vertex_index >= nv)
        fail(where, source,
             "triangle " + std::to_string(faceCount / 3 + 1) + " refers to vertex " +
                 std::to_string(idx.vertex_index + 1) + " of " + std::to_string(nv));
      if (idx.normal_index >= nn || idx.normal_index < -1)
        fail(where, source,
             "triangle " + std::to_string(faceCount / 3 + 1) + " refers to normal " +
                 std::to_string(idx.normal_index + 1) + " of " + std::to_string(nn));
      if (idx.texcoord_index >= nt || idx.texcoord_index < -1)
        fail(where, source,
             "triangle " + std::to_string(faceCount / 3 + 1) + " refers to texture coordinate " +
                 std::to_string(idx.texcoord_index + 1) + " of " + std::to_string(nt));
      allNormals = allNormals && idx.normal_index >= 0;
      allUvs = allUvs && idx.texcoord_index >= 0;
      ++faceCount;
    }
  }
  const bool useObjNormals = allNormals && smoothNormals;

  TriangleMesh mesh;
  // One renderer vertex per distinct (position, normal, uv) corner; flat shading splits per face.
  std::map<std::tuple<int, int, int, std::size_t>, std::uint32_t> vertexOf;
  auto position = [&](int i) {
    return glm::dvec3(attrib.vertices[3 * i], attrib.vertices[3 * i + 1],
                      attrib.vertices[3 * i + 2]);
  };
  std::size_t triangleIndex = 0;
  for (const auto& shape : shapes) {
    const auto& indices = shape.mesh.indices;
    for (std::size_t f = 0; f + 2 < indices.size(); f += 3, ++triangleIndex) {
      const tinyobj::index_t c[3] = {indices[f], indices[f + 1], indices[f + 2]};
      if (c[0].vertex_index == c[1].vertex_index || c[1].vertex_index == c[2].vertex_index ||
          c[0].vertex_index == c[2].vertex_index ||
          isDegenerate(position(c[0].vertex_index), position(c[1].vertex_index),
                       position(c[2].vertex_index))) {
        ++mesh.skippedDegenerate;
        continue;
      }
      std::array<std::uint32_t, 3> tri{};
      for (int k = 0; k < 3; ++k) {
        const auto key = std::make_tuple(c[k].vertex_index, useObjNormals ? c[k].normal_index : -1,
                                         allUvs ? c[k].texcoord_index : -1,
                                         smoothNormals ? std::size_t{0} : triangleIndex + 1);
        auto [it, inserted] =
            vertexOf.try_emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
        if (inserted) {
          mesh.positions.push_back(position(c[k].vertex_index));
          if (useObjNormals) {
            const int n = c[k].normal_index;
            mesh.normals.emplace_back(attrib.normals[3 * n], attrib.normals[3 * n + 1],
                                      attrib.normals[3 * n + 2]);
          }
          if (allUvs) {
            const int t = c[k].texcoord_index;
            mesh.uvs.emplace_back(attrib.texcoords[2 * t], attrib.texcoords[2 * t + 1]);
          }
        }
        tri[k] = it->second;
      }
      mesh.triangles.push_back(tri);
    }
  }
  if (mesh.triangles.empty())
    fail(where, source,
         faceCount == 0 ? "has no triangles"
                        : "has no usable triangle (all " + std::to_string(mesh.skippedDegenerate) +
                              " are degenerate)");
  bool normalsUsable = useObjNormals;
  for (auto& n : mesh.normals) {
    const double len = glm::length(n);
    if (!(len > 0))
      normalsUsable = false;
    else
      n /= len;
  }
  if (!normalsUsable) computeNormals(mesh);
  return mesh;
}

TriangleMesh loadObjMesh(const std::filesystem::path& path, const SourceLocation& where,
                         bool smoothNormals) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(where, "cannot open mesh file '" + path.string() + "'");
  std::ostringstream text;
  text << in.rdbuf();
  return parseObjMesh(text.str(), path.string(), where, smoothNormals);
}

TriangleMesh makePlaneMesh(const glm::dvec3& point, const glm::dvec3& normal, double size) {
  const glm::dvec3 n = glm::normalize(normal);
  const glm::dvec3 helper = std::fabs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 t = glm::normalize(glm::cross(helper, n));
  const glm::dvec3 b = glm::cross(n, t);  // (t, b, n) right-handed: counter-clockwise seen from +n
  const double h = 0.5 * size;
  TriangleMesh mesh;
  mesh.positions = {point - t * h - b * h, point + t * h - b * h, point + t * h + b * h,
                    point - t * h + b * h};
  mesh.normals.assign(4, n);
  mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

void transformMesh(TriangleMesh& mesh, const glm::dmat4& objectToWorld,
                   const SourceLocation& where) {
  const glm::dmat3 linear(objectToWorld);
  const double det = glm::determinant(linear);
  if (!(std::fabs(det) > 1e-300) || !std::isfinite(det))
    throw SceneError(where, "the shape's transform is singular or not finite");
  const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(linear));
  for (auto& p : mesh.positions) p = glm::dvec3(objectToWorld * glm::dvec4(p, 1.0));
  for (auto& n : mesh.normals) n = glm::normalize(normalMatrix * n);
  if (det < 0)  // a mirroring transform flips the winding; keep front faces on the normals' side
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
}

}  // namespace hylios
