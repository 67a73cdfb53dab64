// The spectral film: per pixel and per channel (one channel per band wavelength), the sum of
// radiance samples and their count. Each camera path carries one wavelength, drawn by
// sampleChannel(): a band uniformly, then a channel of that band uniformly; a channel's
// estimate is its sample mean (sum / count), so every band converges independently. At fewer
// samples than a band has channels some channels of a pixel get none; their value is then
// interpolated linearly in wavelength between the nearest sampled channels of the same band
// (the nearest one at the band's ends), never left at 0, which would darken the band by the
// fraction of channels missed (docs/interpretations.md).
//
// Thread safety: addSample() for distinct pixels may run concurrently (tiles own pixels).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "renderer/scene/scene.h"

namespace hylios {

struct FilmChannel {
  double wavelengthNm = 0;
  std::size_t band = 0;      ///< index into FilmDesc::bands
};

class Film {
 public:
  explicit Film(const FilmDesc& desc);

  int width() const { return width_; }
  int height() const { return height_; }
  const FilmDesc& desc() const { return desc_; }
  const std::vector<FilmChannel>& channels() const { return channels_; }

  /// A channel for uniform u in [0, 1) (band uniformly, then channel within it) and its
  /// probability (not needed by the mean-per-channel estimator, but reported for MIS users).
  std::size_t sampleChannel(double u) const;

  void addSample(int x, int y, std::size_t channel, double radiance);
  /// Mean radiance of a pixel's channel; for a channel without samples, interpolated from the
  /// band's sampled channels (see above); 0 while the pixel's band has no sample at all.
  double value(int x, int y, std::size_t channel) const;
  std::uint32_t sampleCount(int x, int y, std::size_t channel) const;
  /// Samples per pixel accumulated so far (recorded in EXR headers).
  int samplesPerPixelDone() const { return samplesPerPixelDone_; }
  void setSamplesPerPixelDone(int spp) { samplesPerPixelDone_ = spp; }

  /// The raw accumulation state, one slot per (pixel, channel), pixel-major (slot =
  /// (y·width + x)·channels + channel): radiance sums and sample counts (render checkpoints).
  const std::vector<double>& sums() const { return sums_; }
  const std::vector<std::uint32_t>& counts() const { return counts_; }
  /// Replaces the accumulated state with a saved one (a render checkpoint's). Throws
  /// std::invalid_argument, saying what is wrong, unless the sizes fit this film, every sum is
  /// finite, and every pixel's counts add up to samplesPerPixelDone (each sample adds one count).
  void restoreState(std::vector<double> sums, std::vector<std::uint32_t> counts, int samplesPerPixelDone);

 private:
  double interpolatedValue(int x, int y, std::size_t channel) const;
  std::size_t slot(int x, int y, std::size_t channel) const {
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)) *
               channels_.size() + channel;
  }
  FilmDesc desc_;
  int width_, height_;
  std::vector<FilmChannel> channels_;
  std::vector<std::vector<std::size_t>> bandChannels_;
  std::vector<std::size_t> positionInBand_;  ///< channel → its index in bandChannels_[band]
  std::vector<double> sums_;
  std::vector<std::uint32_t> counts_;
  int samplesPerPixelDone_ = 0;
};

}  // namespace hylios
