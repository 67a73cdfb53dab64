#include "renderer/image/render_noise.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace hylios {
namespace {

double median(std::vector<double>& values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  const std::size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle),
                   values.end());
  const double upper = values[middle];
  if (values.size() % 2 == 1) return upper;
  const double lower =
      *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle));
  return 0.5 * (lower + upper);
}

bool seen(const std::vector<bool>& mask, std::size_t pixel) { return mask.empty() || mask[pixel]; }

}  // namespace

std::vector<GroupNoise> measureNoise(const NoiseImage& a, const NoiseImage& b,
                                     const std::vector<bool>& mask) {
  if (a.width != b.width || a.height != b.height || a.groups != b.groups ||
      a.values.size() != b.values.size())
    throw std::invalid_argument("noise: the two images differ in size or channels");
  const std::size_t pixels = static_cast<std::size_t>(a.width) * static_cast<std::size_t>(a.height);
  const std::size_t groups = a.groups.size();
  if (a.values.size() != pixels * groups)
    throw std::invalid_argument("noise: image values do not match its size");
  if (!mask.empty() && mask.size() != pixels)
    throw std::invalid_argument("noise: the mask does not match the image");
  std::vector<GroupNoise> result;
  std::vector<double> relative;
  for (std::size_t g = 0; g < groups; ++g) {
    relative.clear();
    for (std::size_t p = 0; p < pixels; ++p) {
      const double x = a.values[p * groups + g], y = b.values[p * groups + g];
      const double mean = 0.5 * (x + y);
      if (seen(mask, p) && mean > 0) relative.push_back(std::fabs(x - y) / std::sqrt(2.0) / mean);
    }
    result.push_back({a.groups[g], median(relative), relative.size()});
  }
  const bool colour = a.rgb[0] >= 0 && a.rgb == b.rgb;
  if (colour) {
    relative.clear();
    for (std::size_t p = 0; p < pixels; ++p) {
      std::array<double, 3> ca{}, cb{};
      double sa = 0, sb = 0;
      for (int i = 0; i < 3; ++i) {
        ca[i] = a.values[p * groups + static_cast<std::size_t>(a.rgb[i])];
        cb[i] = b.values[p * groups + static_cast<std::size_t>(b.rgb[i])];
        sa += ca[i];
        sb += cb[i];
      }
      if (!seen(mask, p) || !(sa > 0) || !(sb > 0)) continue;
      double difference = 0, norm = 0;
      for (int i = 0; i < 3; ++i) {
        const double u = ca[i] / sa, v = cb[i] / sb;
        difference += (u - v) * (u - v);
        norm += 0.25 * (u + v) * (u + v);
      }
      if (norm > 0) relative.push_back(std::sqrt(difference) / std::sqrt(2.0) / std::sqrt(norm));
    }
    result.push_back({"chromaticity", median(relative), relative.size()});
  }
  return result;
}

double worstNoise(const std::vector<GroupNoise>& noise) {
  double worst = 0;
  for (const GroupNoise& g : noise)
    if (std::isfinite(g.medianRelative)) worst = std::max(worst, g.medianRelative);
  return worst;
}

std::string formatNoise(const std::vector<GroupNoise>& noise) {
  std::ostringstream text;
  text.setf(std::ios::fixed);
  text.precision(2);
  for (const GroupNoise& g : noise) {
    text << g.group << ": ";
    if (std::isfinite(g.medianRelative))
      text << 100 * g.medianRelative << " %";
    else
      text << "n/a";
    text << " (" << g.pixels << " pixels)\n";
  }
  return text.str();
}

}  // namespace hylios
