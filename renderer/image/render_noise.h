// Render noise from two independent estimates of the same image (issue 12; the project's
// measure): two renders that differ only in the seed, or the two halves (even and odd samples) of
// one render. For a per-pixel quantity q with estimates a and b,
//   σ_pixel = |a − b| / √2   (the standard deviation of one estimate),
//   relative noise = σ_pixel / ((a + b)/2),
// and a group's figure is the median of the relative noise over the pixels that see an object
// (the coverage mask: the pixel's centre ray meets a shape that does not emit) whose mean is > 0.
// Groups: "band <name>" — the mean radiance over the band's channels; for a colour band also "R",
// "G", "B" (linear sRGB) and "chromaticity": with c = (R, G, B)/(R + G + B),
//   chromaticity noise = ‖c_a − c_b‖ / √2 / ‖(c_a + c_b)/2‖.
// The noise of the mean of the two halves is the half-image figure / √2 (independent halves).
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

/// The largest of the figures (the noise target is met when it is ≤ the target); NaN groups are
/// skipped; 0 when there is none.
double worstNoise(const std::vector<GroupNoise>& noise);

/// One line per group: "band uv365: 4.21 % (61234 pixels)".
std::string formatNoise(const std::vector<GroupNoise>& noise);

}  // namespace hylios
