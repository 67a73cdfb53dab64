#include "renderer/scene/texture_map.h"

#include <cmath>

#include "renderer/image/image_file.h"

namespace hylios {

TextureMap::TextureMap(const std::filesystem::path& path, const SourceLocation& where) {
  StoredImage image;
  std::string error;
  if (!tryReadImageFile(path, image, error))
    throw SceneError(where, "cannot read texture '" + path.string() + "': " + error);
  width_ = image.width;
  height_ = image.height;
  const int channels = static_cast<int>(image.channelNames.size());
  const std::vector<float>& pixels = image.pixels;
  const int used = channels >= 3 ? 3 : 1;
  values_.resize(static_cast<std::size_t>(width_) * height_);
  for (std::size_t i = 0; i < values_.size(); ++i) {
    float sum = 0;
    for (int c = 0; c < used; ++c) sum += pixels[i * channels + c];
    values_[i] = sum / static_cast<float>(used);
    if (!std::isfinite(values_[i]))
      throw SceneError(where, "texture '" + path.string() + "' holds a non-finite value");
  }
}

TextureMap::TextureMap(int width, int height, std::vector<float> values)
    : width_(width), height_(height), values_(std::move(values)) {}

double TextureMap::texel(long x, long y) const {
  const long w = width_, h = height_;
  x = ((x % w) + w) % w;
  y = ((y % h) + h) % h;
  return values_[static_cast<std::size_t>(y * w + x)];
}

double TextureMap::lookup(const glm::dvec2& uv) const {
  // Texel centres at (i + 0.5)/width; v = 0 is the bottom row, image row 0 the top.
  const double x = uv.x * width_ - 0.5;
  const double y = (1 - uv.y) * height_ - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double tx = x - fx, ty = y - fy;
  const long ix = static_cast<long>(fx), iy = static_cast<long>(fy);
  return (1 - tx) * (1 - ty) * texel(ix, iy) + tx * (1 - ty) * texel(ix + 1, iy) +
         (1 - tx) * ty * texel(ix, iy + 1) + tx * ty * texel(ix + 1, iy + 1);
}

}  // namespace hylios
