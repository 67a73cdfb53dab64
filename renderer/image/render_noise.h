// Render noise from two independent estimates of the same image (issue 12; the project's
// measure): two renders that differ only in the seed, or the two halves of one render. For a
// per-pixel quantity with estimates a and b,
//   two renders:      σ = |a − b| / √2 (the standard deviation of one render), mean (a + b)/2;
//   a film's halves:  the film's value is m = (1 − q)·a + q·b, q = n_b / (n_a + n_b) the second
//                     half's share of the pixel's samples, and σ(m) = √(q(1 − q))·|a − b|
//                     (E(a − b)² = σ²/n_a + σ²/n_b for per-sample variance σ²; |a − b|/2 when
//                     the halves are equal);
//   relative noise = σ / mean,
// and a group's figure is the median of the relative noise over the pixels that see an object
// (the coverage mask: the pixel's centre ray meets a shape that does not emit) whose mean is > 0;
// a film pixel with an empty half has no figure. Groups: "band <name>" — the mean radiance over
// the band's channels; for a colour band also "R", "G", "B" (linear sRGB) and "chromaticity":
// with c = (R, G, B)/(R + G + B), the same with ‖c_a − c_b‖ and ‖mean of c‖.
#pragma once
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace hylios {

/// One estimate of an image reduced to what noise is measured on: per pixel, each group's value.
struct NoiseImage {
  int width = 0, height = 0;
  std::vector<std::string> groups;  ///< names, e.g. "band visible", "R", "G", "B"
  std::vector<double> values;       ///< [(y·width + x)·groups + g]
  /// The indices of R, G, B in `groups` when the image has a colour band (chromaticity), else -1.
  std::array<int, 3> rgb{-1, -1, -1};
};

struct GroupNoise {
  std::string group;
  double medianRelative = 0;  ///< median over the masked pixels (NaN when no pixel qualifies)
  std::size_t pixels = 0;     ///< pixels that entered the median
};

/// The figures of every group, then "chromaticity" when both images have R, G, B. `mask` has one
/// entry per pixel (true: the pixel sees an object); empty means every pixel. Throws
/// std::invalid_argument when the two images differ in size or groups.
std::vector<GroupNoise> measureNoise(const NoiseImage& a, const NoiseImage& b,
                                     const std::vector<bool>& mask);

/// The noise of a film from its two halves (see above): `secondShare` holds q per pixel and group
/// ([(y·width + x)·groups + g], the colour band's R for chromaticity). Throws as measureNoise, and
/// for a share vector of another size.
std::vector<GroupNoise> measureHalvesNoise(const NoiseImage& first, const NoiseImage& second,
                                           const std::vector<double>& secondShare,
                                           const std::vector<bool>& mask);

/// The largest of the figures (the noise target is met when it is ≤ the target); NaN groups are
/// skipped; 0 when there is none.
double worstNoise(const std::vector<GroupNoise>& noise);

/// One line per group: "band uv365: 4.21 % (61234 pixels)".
std::string formatNoise(const std::vector<GroupNoise>& noise);

}  // namespace hylios
