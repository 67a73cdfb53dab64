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

namespace {
/// The figures of both measures: per pixel p and group g, the estimates are weighed by
/// share(p, g) = q (the second's), σ = scale·√(q(1 − q))·|a − b|; q ∉ (0, 1): no figure.
template <class Share>
std::vector<GroupNoise> groupNoise(const NoiseImage& a, const NoiseImage& b,
                                   const std::vector<bool>& mask, const Share& share,
                                   double scale) {
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
      const double q = share(p, g);
      if (!seen(mask, p) || !(q > 0 && q < 1)) continue;
      const double x = a.values[p * groups + g], y = b.values[p * groups + g];
      const double mean = (1 - q) * x + q * y;
      if (mean > 0) relative.push_back(scale * std::sqrt(q * (1 - q)) * std::fabs(x - y) / mean);
    }
    result.push_back({a.groups[g], median(relative), relative.size()});
  }
  const bool colour = a.rgb[0] >= 0 && a.rgb == b.rgb;
  if (colour) {
    relative.clear();
    for (std::size_t p = 0; p < pixels; ++p) {
      const double q = share(p, static_cast<std::size_t>(a.rgb[0]));
      if (!seen(mask, p) || !(q > 0 && q < 1)) continue;
      std::array<double, 3> ca{}, cb{};
      double sa = 0, sb = 0;
      for (int i = 0; i < 3; ++i) {
        ca[i] = a.values[p * groups + static_cast<std::size_t>(a.rgb[i])];
        cb[i] = b.values[p * groups + static_cast<std::size_t>(b.rgb[i])];
        sa += ca[i];
        sb += cb[i];
      }
      if (!(sa > 0) || !(sb > 0)) continue;
      double difference = 0, norm = 0;
      for (int i = 0; i < 3; ++i) {
        const double u = ca[i] / sa, v = cb[i] / sb, mean = (1 - q) * u + q * v;
        difference += (u - v) * (u - v);
        norm += mean * mean;
      }
      if (norm > 0)
        relative.push_back(scale * std::sqrt(q * (1 - q)) * std::sqrt(difference / norm));
    }
    result.push_back({"chromaticity", median(relative), relative.size()});
  }
  return result;
}
}  // namespace

std::vector<GroupNoise> measureNoise(const NoiseImage& a, const NoiseImage& b,
                                     const std::vector<bool>& mask) {
  // Two renders, equal weights: √(½·½)·|a − b|·√2 = |a − b|/√2, the noise of one render.
  return groupNoise(
      a, b, mask, [](std::size_t, std::size_t) { return 0.5; }, std::sqrt(2.0));
}

std::vector<GroupNoise> measureHalvesNoise(const NoiseImage& first, const NoiseImage& second,
                                           const std::vector<double>& secondShare,
                                           const std::vector<bool>& mask) {
  if (secondShare.size() != first.values.size())
    throw std::invalid_argument("noise: the halves' shares do not match the image");
  const std::size_t groups = first.groups.size();
  return groupNoise(
      first, second, mask,
      [&](std::size_t p, std::size_t g) { return secondShare[p * groups + g]; }, 1.0);
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
