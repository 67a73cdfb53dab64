// A greyscale texture in UV space (e.g. a melanin map), read once through OpenImageIO into memory
// and looked up with bilinear filtering and wrap-around. Values are the stored pixel values scaled
// to [0, 1] (8-bit 255 → 1), with no colour-space conversion; colour images use the mean of their
// first three channels. Texture space: u to the right, v = 0 at the bottom row (OBJ convention).
#pragma once
#include <glm/glm.hpp>

#include <filesystem>
#include <vector>

#include "renderer/scene/scene.h"

namespace hylios {

class TextureMap {
 public:
  /// Throws SceneError at `where` when the file is missing or unreadable, or holds a value that
  /// is not finite.
  TextureMap(const std::filesystem::path& path, const SourceLocation& where);
  /// Builds a texture from rows of values (row 0 = top of the image), for tests.
  TextureMap(int width, int height, std::vector<float> valuesTopRowFirst);

  double lookup(const glm::dvec2& uv) const;
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  double texel(long x, long y) const;
  int width_ = 0, height_ = 0;
  std::vector<float> values_;
};

}  // namespace hylios
