// Comparing two multi-channel OpenEXR images (a test image and a reference), e.g. a render against
// a converged render of the same scene. For a channel c with P compared values a_p (test) and b_p
// (reference), p over pixels or over N×N block means:
//   RMSE_c                     = sqrt( (1/P) Σ_p (a_p − b_p)² )
//   reference scale S_c        = (1/P) Σ_p |b_p|
//   relative RMSE_c            = RMSE_c / S_c
//   mean relative difference_c = ((1/P) Σ_p (a_p − b_p)) / S_c     (signed: the relative bias)
// "overall" pools the spectral channels (names "S0.<λ>nm"; every channel when there are none) in
// the same formulas, with p running over every (pixel, channel) pair — so brighter channels weigh
// more, as the radiance does. With a block size N > 1 the values compared are the means over
// N×N pixel blocks (those blocks that fit whole; a remainder strip on the right or bottom is left
// out), which removes pixel-scale noise and keeps the structure. A reference channel that is zero
// everywhere has no relative error: that is an error, not a NaN.
#pragma once
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "renderer/image/image_file.h"
#include "renderer/image/render_noise.h"

namespace hylios {

/// An image file's float pixels and string attributes (StoredImage; hylios writes hylios:bands and
/// hylios:rgb) without its channel "A", which is kept apart.
struct ExrImage : StoredImage {
  /// The file's channel "A" (hylios: 1 where the pixel sees an object), kept apart from the
  /// compared channels; empty when the file has none.
  std::vector<bool> coverage;

  float value(int x, int y, std::size_t channel) const {
    return pixels[(static_cast<std::size_t>(y) * width + x) * channelNames.size() + channel];
  }
};

/// Reads every channel of subimage 0 of an image file (OpenEXR or any format OpenImageIO reads)
/// as float (channel "A" into ExrImage::coverage). Throws naming the file when it cannot be read.
ExrImage readExrImage(const std::filesystem::path& path);

/// The image reduced for renderer/image/render_noise.h: per band of hylios:bands the mean over its
/// spectral channels (one group "spectral mean" over every spectral channel without the
/// attribute), and R, G, B when they hold a colour band's linear sRGB. Throws when a band's
/// wavelength has no channel.
NoiseImage noiseImageOf(const ExrImage& image);

/// The differences in one channel (or pooled over channels, for "overall").
struct ChannelDifference {
  std::string channel;
  std::optional<double> wavelengthNm;  ///< for spectral channels
  std::size_t valuesCompared = 0;      ///< P: pixels or blocks (× channels for "overall")
  double rmse = 0;
  double referenceMeanAbs = 0;  ///< S
  double relativeRmse = 0;
  double meanRelativeDifference = 0;
};

struct ImageComparison {
  int blockSize = 1;
  int blocksX = 0, blocksY = 0;             ///< values per channel = blocksX·blocksY
  std::vector<ChannelDifference> channels;  ///< in the test image's channel order
  ChannelDifference overall;  ///< over the spectral channels (all when there are none)
  std::size_t overallChannelCount = 0;
};

/// Compares `test` with `reference` (the names are used in error messages). The images must have
/// the same size and the same channel names (in any order); blockSize ≥ 1 and no larger than
/// either side. Throws naming the image and what differs otherwise.
ImageComparison compareImages(const ExrImage& test, const std::string& testName,
                              const ExrImage& reference, const std::string& referenceName,
                              int blockSize);

/// Reads both files and compares them.
ImageComparison compareImageFiles(const std::filesystem::path& test,
                                  const std::filesystem::path& reference, int blockSize);

/// CSV: channel,wavelength_nm,values_compared,rmse,reference_mean_abs,relative_rmse,
/// mean_relative_difference — one row per channel, then "overall" (wavelength empty). Channel
/// names holding a comma (the spectral ones) are quoted: "S0.500,000000nm".
std::string formatComparisonCsv(const ImageComparison& comparison);

/// A short aligned table for a terminal, the overall row first.
std::string formatComparisonTable(const ImageComparison& comparison);

}  // namespace hylios
