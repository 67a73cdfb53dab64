// The spectral film: per pixel and per channel (one channel per band wavelength), the sum of
// radiance samples and their count (also split by the parity of the sample index, for the noise
// estimate). A camera path carries either one wavelength, drawn by sampleChannel() (a band
// uniformly, then a channel of that band uniformly; addSample), or every wavelength of a band drawn
// by sampleBand() (addBandSample); a channel's estimate is its sample mean (sum / count), so every
// band converges independently. At fewer
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
  std::size_t band = 0;  ///< index into FilmDesc::bands
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

  /// The bands' channels (indices into channels()).
  std::size_t bandCount() const { return bandChannels_.size(); }
  const std::vector<std::size_t>& bandChannels(std::size_t band) const {
    return bandChannels_.at(band);
  }
  /// A band for uniform u in [0, 1) (every band equally likely).
  std::size_t sampleBand(double u) const;

  /// One sample of one channel (per-wavelength paths). `secondHalf`: the sample belongs to the
  /// second of the film's two halves (inSecondFilmHalf, renderer/tracing/pixel_sampler.h; the two
  /// halves of the samples give the render's noise, renderer/image/render_noise.h).
  void addSample(int x, int y, std::size_t channel, double radiance, bool secondHalf = false);
  /// One sample of every channel of `band` at once (a path carrying the band's wavelengths):
  /// radiance[i] for bandChannels(band)[i].
  void addBandSample(int x, int y, std::size_t band, const double* radiance,
                     bool secondHalf = false);
  /// Mean radiance of a pixel's channel; for a channel without samples, interpolated from the
  /// band's sampled channels (see above); 0 while the pixel's band has no sample at all.
  double value(int x, int y, std::size_t channel) const;
  /// The same from the first (secondHalf = false) or the second half's samples alone.
  double halfValue(int x, int y, std::size_t channel, bool secondHalf) const;
  /// Pixels whose centre ray sees a shape that does not emit (set by the renderer; empty: unknown).
  const std::vector<bool>& coverage() const { return coverage_; }
  void setCoverage(std::vector<bool> coverage);
  std::uint32_t sampleCount(int x, int y, std::size_t channel) const;
  /// The part of sampleCount() from the second half's samples.
  std::uint32_t secondHalfSampleCount(int x, int y, std::size_t channel) const;
  /// Samples per pixel accumulated so far (recorded in EXR headers).
  int samplesPerPixelDone() const { return samplesPerPixelDone_; }
  void setSamplesPerPixelDone(int spp) { samplesPerPixelDone_ = spp; }

  /// The raw accumulation state, one slot per (pixel, channel), pixel-major (slot =
  /// (y·width + x)·channels + channel): radiance sums and sample counts (render checkpoints).
  const std::vector<double>& sums() const { return sums_; }
  const std::vector<std::uint32_t>& counts() const { return counts_; }
  /// The part of sums() and counts() from the second half's samples.
  const std::vector<double>& secondHalfSums() const { return secondHalfSums_; }
  const std::vector<std::uint32_t>& secondHalfCounts() const { return secondHalfCounts_; }
  /// Replaces the accumulated state with a saved one (a render checkpoint's). Throws
  /// std::invalid_argument, saying what is wrong, unless the sizes fit this film, every sum is
  /// finite, and every pixel's counts add up to samplesPerPixelDone (each sample adds one count).
  /// Whether samples fill a whole band at once (addBandSample) or one channel (addSample); set
  /// before the first sample. restoreState checks the counts accordingly.
  bool wholeBandSamples() const { return wholeBandSamples_; }
  void setWholeBandSamples(bool whole) { wholeBandSamples_ = whole; }
  void restoreState(std::vector<double> sums, std::vector<std::uint32_t> counts,
                    std::vector<double> secondHalfSums, std::vector<std::uint32_t> secondHalfCounts,
                    int samplesPerPixelDone);

 private:
  /// Mean of a slot from the given sums and counts, interpolated within the band when it has none.
  template <class Sum, class Count>
  double meanOrInterpolated(int x, int y, std::size_t channel, const Sum& sum,
                            const Count& count) const;
  /// Adds one sample to a checked pixel and channel; throws for a non-finite radiance.
  void accumulate(int x, int y, std::size_t channel, double radiance, bool secondHalf);
  std::size_t slot(int x, int y, std::size_t channel) const {
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
            static_cast<std::size_t>(x)) *
               channels_.size() +
           channel;
  }
  FilmDesc desc_;
  int width_, height_;
  std::vector<FilmChannel> channels_;
  std::vector<std::vector<std::size_t>> bandChannels_;
  std::vector<std::size_t> positionInBand_;  ///< channel → its index in bandChannels_[band]
  std::vector<double> sums_;
  std::vector<std::uint32_t> counts_;
  std::vector<double> secondHalfSums_;
  std::vector<std::uint32_t> secondHalfCounts_;
  std::vector<bool> coverage_;
  bool wholeBandSamples_ = false;
  int samplesPerPixelDone_ = 0;
};

}  // namespace hylios
