#include "renderer/image/film.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace hylios {
namespace {

void requireInside(const char* what, int x, int y, std::size_t channel, int width, int height,
                   std::size_t channels) {
  if (x < 0 || y < 0 || x >= width || y >= height || channel >= channels) {
    throw std::out_of_range(std::string(what) + ": pixel (" + std::to_string(x) + ", " +
                            std::to_string(y) + ") channel " + std::to_string(channel) +
                            " is outside the " + std::to_string(width) + "x" +
                            std::to_string(height) + " film with " + std::to_string(channels) +
                            " channels");
  }
}

}  // namespace

Film::Film(const FilmDesc& desc) : desc_(desc), width_(desc.width), height_(desc.height) {
  if (width_ <= 0 || height_ <= 0) {
    throw std::invalid_argument(desc.where.str() + ": film resolution must be positive, got " +
                                std::to_string(width_) + "x" + std::to_string(height_));
  }
  if (desc.bands.empty()) throw std::invalid_argument(desc.where.str() + ": film has no band");
  for (std::size_t b = 0; b < desc.bands.size(); ++b) {
    const BandDesc& band = desc.bands[b];
    if (band.isRange() && !(band.stepNm > 0)) {
      throw std::invalid_argument(band.where.str() + ": band '" + band.name +
                                  "' is a range but its step is not positive");
    }
    if (!(band.minNm > 0) || band.maxNm < band.minNm) {
      throw std::invalid_argument(band.where.str() + ": band '" + band.name +
                                  "' has an invalid wavelength range");
    }
    std::vector<std::size_t> indices;
    for (const double wavelength : band.channelWavelengths()) {
      positionInBand_.push_back(indices.size());
      indices.push_back(channels_.size());
      channels_.push_back({wavelength, b});
    }
    bandChannels_.push_back(std::move(indices));
  }
  const std::size_t slots =
      static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * channels_.size();
  sums_.assign(slots, 0.0);
  counts_.assign(slots, 0);
}

std::size_t Film::sampleChannel(double u) const {
  if (!(u >= 0.0 && u < 1.0)) {
    throw std::invalid_argument("Film::sampleChannel: u = " + std::to_string(u) +
                                " is outside [0, 1)");
  }
  const std::size_t bands = bandChannels_.size();
  const double scaledBand = u * static_cast<double>(bands);
  const std::size_t band = std::min(static_cast<std::size_t>(scaledBand), bands - 1);
  // The fractional part is again uniform on [0, 1): reuse it to pick the channel in the band.
  const double v = scaledBand - static_cast<double>(band);
  const auto& inBand = bandChannels_[band];
  const std::size_t channel =
      std::min(static_cast<std::size_t>(v * static_cast<double>(inBand.size())), inBand.size() - 1);
  return inBand[channel];
}

void Film::addSample(int x, int y, std::size_t channel, double radiance) {
  requireInside("Film::addSample", x, y, channel, width_, height_, channels_.size());
  if (!std::isfinite(radiance)) {
    throw std::invalid_argument("Film::addSample: non-finite radiance " + std::to_string(radiance) +
                                " at pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                "), " + std::to_string(channels_[channel].wavelengthNm) + " nm");
  }
  const std::size_t s = slot(x, y, channel);
  sums_[s] += radiance;
  counts_[s] += 1;
}

double Film::value(int x, int y, std::size_t channel) const {
  requireInside("Film::value", x, y, channel, width_, height_, channels_.size());
  const std::size_t s = slot(x, y, channel);
  return counts_[s] == 0 ? interpolatedValue(x, y, channel) : sums_[s] / static_cast<double>(counts_[s]);
}

double Film::interpolatedValue(int x, int y, std::size_t channel) const {
  const std::vector<std::size_t>& band = bandChannels_[channels_[channel].band];
  const std::size_t at = positionInBand_[channel];
  auto sampled = [&](std::size_t c) { return counts_[slot(x, y, c)] > 0; };
  auto mean = [&](std::size_t c) { return sums_[slot(x, y, c)] / static_cast<double>(counts_[slot(x, y, c)]); };
  std::size_t below = at, above = at;
  while (below > 0 && !sampled(band[below])) --below;
  while (above + 1 < band.size() && !sampled(band[above])) ++above;
  const bool hasBelow = sampled(band[below]), hasAbove = sampled(band[above]);
  if (!hasBelow && !hasAbove) return 0.0;
  if (!hasAbove) return mean(band[below]);
  if (!hasBelow) return mean(band[above]);
  const double lo = channels_[band[below]].wavelengthNm, hi = channels_[band[above]].wavelengthNm;
  const double t = (channels_[channel].wavelengthNm - lo) / (hi - lo);
  return (1 - t) * mean(band[below]) + t * mean(band[above]);
}

void Film::restoreState(std::vector<double> sums, std::vector<std::uint32_t> counts, int samplesPerPixelDone) {
  if (sums.size() != sums_.size() || counts.size() != counts_.size()) {
    throw std::invalid_argument("film state has " + std::to_string(sums.size()) + " sums and " +
                                std::to_string(counts.size()) + " counts; this " + std::to_string(width_) + "x" +
                                std::to_string(height_) + " film with " + std::to_string(channels_.size()) +
                                " channels needs " + std::to_string(sums_.size()) + " of each");
  }
  if (samplesPerPixelDone < 0) throw std::invalid_argument("film state has a negative sample count");
  const std::size_t channels = channels_.size();
  for (std::size_t pixel = 0; pixel * channels < sums.size(); ++pixel) {
    std::uint64_t total = 0;
    for (std::size_t c = 0; c < channels; ++c) {
      const std::size_t s = pixel * channels + c;
      if (!std::isfinite(sums[s]))
        throw std::invalid_argument("film state has a non-finite sum at pixel " + std::to_string(pixel) +
                                    ", channel " + std::to_string(c));
      total += counts[s];
    }
    if (total != static_cast<std::uint64_t>(samplesPerPixelDone))
      throw std::invalid_argument("film state: pixel " + std::to_string(pixel) + " has " + std::to_string(total) +
                                  " samples, not the " + std::to_string(samplesPerPixelDone) + " it claims");
  }
  sums_ = std::move(sums);
  counts_ = std::move(counts);
  samplesPerPixelDone_ = samplesPerPixelDone;
}

std::uint32_t Film::sampleCount(int x, int y, std::size_t channel) const {
  requireInside("Film::sampleCount", x, y, channel, width_, height_, channels_.size());
  return counts_[slot(x, y, channel)];
}

}  // namespace hylios
