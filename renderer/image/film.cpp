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
    throw std::out_of_range(
        std::string(what) + ": pixel (" + std::to_string(x) + ", " + std::to_string(y) +
        ") channel " + std::to_string(channel) + " is outside the " + std::to_string(width) + "x" +
        std::to_string(height) + " film with " + std::to_string(channels) + " channels");
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
  secondHalfSums_.assign(slots, 0.0);
  secondHalfCounts_.assign(slots, 0);
}

std::size_t Film::sampleBand(double u) const {
  if (!(u >= 0.0 && u < 1.0))
    throw std::invalid_argument("Film::sampleBand: u = " + std::to_string(u) +
                                " is outside [0, 1)");
  return std::min(static_cast<std::size_t>(u * static_cast<double>(bandChannels_.size())),
                  bandChannels_.size() - 1);
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

void Film::addSample(int x, int y, std::size_t channel, double radiance, bool secondHalf) {
  requireInside("Film::addSample", x, y, channel, width_, height_, channels_.size());
  accumulate(x, y, channel, radiance, secondHalf);
}

void Film::accumulate(int x, int y, std::size_t channel, double radiance, bool secondHalf) {
  if (!std::isfinite(radiance)) {
    throw std::invalid_argument("Film::addSample: non-finite radiance " + std::to_string(radiance) +
                                " at pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                "), " + std::to_string(channels_[channel].wavelengthNm) + " nm");
  }
  const std::size_t s = slot(x, y, channel);
  sums_[s] += radiance;
  counts_[s] += 1;
  if (secondHalf) {
    secondHalfSums_[s] += radiance;
    secondHalfCounts_[s] += 1;
  }
}

void Film::addBandSample(int x, int y, std::size_t band, const double* radiance, bool secondHalf) {
  if (!wholeBandSamples_)
    throw std::logic_error("Film::addBandSample on a film filled one channel per sample");
  const std::vector<std::size_t>& channels = bandChannels_.at(band);
  if (channels.empty()) return;
  // The band's channels exist: the pixel is checked once, not once per channel.
  requireInside("Film::addBandSample", x, y, channels.front(), width_, height_, channels_.size());
  for (std::size_t i = 0; i < channels.size(); ++i)
    accumulate(x, y, channels[i], radiance[i], secondHalf);
}

double Film::value(int x, int y, std::size_t channel) const {
  requireInside("Film::value", x, y, channel, width_, height_, channels_.size());
  return meanOrInterpolated(
      x, y, channel, [this](std::size_t s) { return sums_[s]; },
      [this](std::size_t s) { return counts_[s]; });
}

double Film::halfValue(int x, int y, std::size_t channel, bool secondHalf) const {
  requireInside("Film::halfValue", x, y, channel, width_, height_, channels_.size());
  if (secondHalf)
    return meanOrInterpolated(
        x, y, channel, [this](std::size_t s) { return secondHalfSums_[s]; },
        [this](std::size_t s) { return secondHalfCounts_[s]; });
  return meanOrInterpolated(
      x, y, channel, [this](std::size_t s) { return sums_[s] - secondHalfSums_[s]; },
      [this](std::size_t s) { return counts_[s] - secondHalfCounts_[s]; });
}

void Film::setCoverage(std::vector<bool> coverage) {
  if (!coverage.empty() &&
      coverage.size() != static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_))
    throw std::invalid_argument("Film::setCoverage: the mask does not match the film");
  coverage_ = std::move(coverage);
}

template <class Sum, class Count>
double Film::meanOrInterpolated(int x, int y, std::size_t channel, const Sum& sum,
                                const Count& count) const {
  if (count(slot(x, y, channel)) > 0)
    return sum(slot(x, y, channel)) / static_cast<double>(count(slot(x, y, channel)));
  const std::vector<std::size_t>& band = bandChannels_[channels_[channel].band];
  const std::size_t at = positionInBand_[channel];
  auto sampled = [&](std::size_t c) { return count(slot(x, y, c)) > 0; };
  auto mean = [&](std::size_t c) {
    return sum(slot(x, y, c)) / static_cast<double>(count(slot(x, y, c)));
  };
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

void Film::restoreState(std::vector<double> sums, std::vector<std::uint32_t> counts,
                        std::vector<double> secondHalfSums,
                        std::vector<std::uint32_t> secondHalfCounts, int samplesPerPixelDone) {
  if (sums.size() != sums_.size() || counts.size() != counts_.size() ||
      secondHalfSums.size() != sums_.size() || secondHalfCounts.size() != counts_.size()) {
    throw std::invalid_argument("film state has " + std::to_string(sums.size()) + " sums and " +
                                std::to_string(counts.size()) + " counts; this " +
                                std::to_string(width_) + "x" + std::to_string(height_) +
                                " film with " + std::to_string(channels_.size()) +
                                " channels needs " + std::to_string(sums_.size()) +
                                " of each (and as many for the second half)");
  }
  if (samplesPerPixelDone < 0)
    throw std::invalid_argument("film state has a negative sample count");
  const std::size_t channels = channels_.size();
  for (std::size_t pixel = 0; pixel * channels < sums.size(); ++pixel) {
    std::uint64_t total = 0;
    for (const std::vector<std::size_t>& band : bandChannels_) {
      const std::uint32_t first = counts[pixel * channels + band.front()];
      for (std::size_t c : band) {
        const std::size_t s = pixel * channels + c;
        if (!std::isfinite(sums[s]) || !std::isfinite(secondHalfSums[s]) ||
            secondHalfCounts[s] > counts[s])
          throw std::invalid_argument(
              "film state has a non-finite sum or a second-half count above the count at pixel " +
              std::to_string(pixel) + ", channel " + std::to_string(c));
        if (wholeBandSamples_ && counts[s] != first)
          throw std::invalid_argument(
              "film state: pixel " + std::to_string(pixel) +
              " has unequal counts within a band filled a whole band per sample");
        if (!wholeBandSamples_) total += counts[s];
      }
      if (wholeBandSamples_) total += first;
    }
    if (total != static_cast<std::uint64_t>(samplesPerPixelDone))
      throw std::invalid_argument("film state: pixel " + std::to_string(pixel) + " has " +
                                  std::to_string(total) + " samples, not the " +
                                  std::to_string(samplesPerPixelDone) + " it claims");
  }
  sums_ = std::move(sums);
  counts_ = std::move(counts);
  secondHalfSums_ = std::move(secondHalfSums);
  secondHalfCounts_ = std::move(secondHalfCounts);
  samplesPerPixelDone_ = samplesPerPixelDone;
}

std::uint32_t Film::sampleCount(int x, int y, std::size_t channel) const {
  requireInside("Film::sampleCount", x, y, channel, width_, height_, channels_.size());
  return counts_[slot(x, y, channel)];
}

std::uint32_t Film::secondHalfSampleCount(int x, int y, std::size_t channel) const {
  requireInside("Film::secondHalfSampleCount", x, y, channel, width_, height_, channels_.size());
  return secondHalfCounts_[slot(x, y, channel)];
}

}  // namespace hylios
