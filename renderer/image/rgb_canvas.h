// An RGB float image in memory for the PNG previews and contact sheets: row 0 at the top,
// channels interleaved, values in display space ([0, 1] is black to white).
#pragma once
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace hylios {

struct RgbCanvas {
  int width = 0, height = 0;
  std::vector<float> rgb;  ///< rgb[(y·width + x)·3 + c]

  RgbCanvas() = default;  ///< empty (0 × 0)
  /// A black canvas; throws std::invalid_argument unless both sizes are positive.
  RgbCanvas(int widthPx, int heightPx) : width(widthPx), height(heightPx) {
    if (widthPx <= 0 || heightPx <= 0)
      throw std::invalid_argument("preview canvas must have a positive size, got " +
                                  std::to_string(widthPx) + "x" + std::to_string(heightPx));
    rgb.assign(static_cast<std::size_t>(widthPx) * static_cast<std::size_t>(heightPx) * 3, 0.0f);
  }
  float* pixel(int x, int y) {
    return rgb.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                         static_cast<std::size_t>(x)) *
                            3;
  }
  const float* pixel(int x, int y) const {
    return rgb.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                         static_cast<std::size_t>(x)) *
                            3;
  }
  void set(int x, int y, const std::array<double, 3>& value) {
    float* p = pixel(x, y);
    for (int c = 0; c < 3; ++c) p[c] = static_cast<float>(value[static_cast<std::size_t>(c)]);
  }
};

}  // namespace hylios
