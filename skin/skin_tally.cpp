#include "skin/skin_tally.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "skin/core/constants.h"
#include "skin/core/state_bytes.h"

namespace hylios::skin {
namespace {

template <class T>
T take(const std::string& bytes, std::size_t& offset) {
  return takeBytes<T>(bytes, offset, "SkinTally::fromBytes");
}

void putStatistic(std::string& bytes, const RunningStatistic& s) {
  putBytes(bytes, s.count());
  putBytes(bytes, s.sum());
  putBytes(bytes, s.sumSquares());
}

RunningStatistic takeStatistic(const std::string& bytes, std::size_t& offset) {
  const auto count = take<std::uint64_t>(bytes, offset);
  const auto sum = take<double>(bytes, offset);
  const auto sumSquares = take<double>(bytes, offset);
  return RunningStatistic::restored(count, sum, sumSquares);
}

void putHistogram(std::string& bytes, const std::optional<Histogram>& h) {
  if (!h) return;
  putBytes(bytes, h->packets());
  for (std::size_t i = 0; i < h->sums().size(); ++i) {
    putBytes(bytes, h->sums()[i]);
    putBytes(bytes, h->sumSquares()[i]);
  }
}

void takeHistogram(const std::string& bytes, std::size_t& offset, std::optional<Histogram>& h) {
  if (!h) return;
  const auto packets = take<std::uint64_t>(bytes, offset);
  std::vector<double> sums(h->sums().size()), sumSquares(h->sums().size());
  for (std::size_t i = 0; i < sums.size(); ++i) {
    sums[i] = take<double>(bytes, offset);
    sumSquares[i] = take<double>(bytes, offset);
  }
  h->restore(std::move(sums), std::move(sumSquares), packets);
}

}  // namespace

SkinTally::SkinTally(const TallyOptions& options) : options_(options) {
  if (options.polarBins > 0) {
    const double bins = static_cast<double>(options.polarBins * options.azimuthBins);
    surfaceDirections_.emplace(0.0, bins, options.polarBins * options.azimuthBins);
    subsurfaceDirections_.emplace(0.0, bins, options.polarBins * options.azimuthBins);
    transmittedDirections_.emplace(0.0, bins, options.polarBins * options.azimuthBins);
  }
  if (options.radialBins > 0) radialExits_.emplace(0.0, options.maxRadiusCm, options.radialBins);
}

SkinTally SkinTally::fromControlledMeans(const TallyOptions& options, ControlledMeans means,
                                         std::uint64_t events) {
  if (options.polarBins > 0 || options.radialBins > 0)
    throw std::invalid_argument(
        "SkinTally::fromControlledMeans: the options ask for histograms, which the sums lack");
  if (means.quantities() != kQuantities)
    throw std::invalid_argument(
        "SkinTally::fromControlledMeans: " + std::to_string(means.quantities()) +
        " quantities, not " + std::to_string(kQuantities));
  SkinTally tally(options);
  tally.controlled_ = std::move(means);
  tally.events_ = events;
  return tally;
}

std::size_t SkinTally::directionBin(const Vec3& exitDirection) const {
  const double polar = std::acos(std::clamp(std::fabs(exitDirection.z), 0.0, 1.0));  // [0, π/2]
  const double azimuth = std::atan2(exitDirection.y, exitDirection.x);               // [-π, π]
  auto bin = [](double value, double lower, double upper, std::size_t count) {
    const auto b =
        static_cast<std::size_t>((value - lower) / (upper - lower) * static_cast<double>(count));
    return std::min(b, count - 1);
  };
  return bin(polar, 0.0, kPi / 2, options_.polarBins) * options_.azimuthBins +
         bin(azimuth, -kPi, kPi, options_.azimuthBins);
}

void SkinTally::record(const SkinPath& path) {
  PathScore score = pathScoreOf(path);
  const bool absorbed = path.end == PathEnd::Absorbed;
  score.exitWeight = absorbed ? 0.0 : 1.0;
  if (absorbed) {
    score.absorbed = 1.0;
    score.absorbedByLayer[index(path.layer)] = 1.0;
    score.absorbedInMelanosomes = path.absorbedInMelanosome ? 1.0 : 0.0;
  }
  record(score);
}

void SkinTally::record(const PathScore& score) {
  const double w = score.exitWeight;
  const bool surface = score.end == PathEnd::SurfaceReflection;
  const bool subsurface = score.end == PathEnd::SubsurfaceReflection;
  const bool transmitted = score.end == PathEnd::Transmitted;
  const double sw = score.surfaceWeight;
  if (score.hasControlWeight != controlled() && rays() > 0)
    throw std::logic_error(std::string("SkinTally::record: a path ") +
                           (score.hasControlWeight ? "with" : "without") +
                           " a control weight in a tally of paths " +
                           (score.hasControlWeight ? "without" : "with") + " one");
  std::array<double, kQuantities> scores{};  // in the order of the k* indices (skin_tally.h)
  scores[kTotal] = (surface || subsurface ? w : 0.0) + sw;
  scores[kSurface] = (surface ? w : 0.0) + sw;
  scores[kSubsurface] = subsurface ? w : 0.0;
  scores[kTransmitted] = transmitted ? w : 0.0;
  scores[kAbsorbed] = score.absorbed;
  scores[kMelanosome] = score.absorbedInMelanosomes;
  scores[kEventLimited] = score.end == PathEnd::EventLimit ? w : 0.0;
  for (std::size_t i = 0; i < kLayerCount; ++i) scores[kFirstLayer + i] = score.absorbedByLayer[i];
  if (score.hasControlWeight) {
    if (!controlled_) controlled_.emplace(kQuantities);
    controlled_->add(scores.data(), score.controlWeight, score.fold);
  } else {
    for (std::size_t k = 0; k < kQuantities; ++k) plain_[k].add(scores[k]);
  }
  events_ += score.events;
  if (surfaceDirections_) {
    surfaceDirections_->countPacket();
    subsurfaceDirections_->countPacket();
    transmittedDirections_->countPacket();
    if (surface) surfaceDirections_->addToBin(directionBin(score.exitDirection), w);
    if (sw != 0) surfaceDirections_->addToBin(directionBin(score.surfaceDirection), sw);
    if (subsurface) subsurfaceDirections_->addToBin(directionBin(score.exitDirection), w);
    if (transmitted) transmittedDirections_->addToBin(directionBin(score.exitDirection), w);
  }
  if (radialExits_) {
    radialExits_->countPacket();
    if (subsurface) radialExits_->add(std::hypot(score.exitOffsetXCm, score.exitOffsetYCm), w);
  }
}

void SkinTally::merge(const SkinTally& other) {
  if (other.rays() > 0 && rays() > 0 && controlled() != other.controlled())
    throw std::logic_error("SkinTally::merge: tallies with and without control weights");
  if (other.controlled_) {
    if (!controlled_) controlled_.emplace(kQuantities);
    controlled_->merge(*other.controlled_);
  }
  for (std::size_t k = 0; k < kQuantities; ++k) plain_[k].merge(other.plain_[k]);
  events_ += other.events_;
  if (surfaceDirections_) {
    surfaceDirections_->merge(*other.surfaceDirections_);
    subsurfaceDirections_->merge(*other.subsurfaceDirections_);
    transmittedDirections_->merge(*other.transmittedDirections_);
  }
  if (radialExits_) radialExits_->merge(*other.radialExits_);
}

void SkinTally::appendBytes(std::string& bytes) const {
  // Either the control-variate sums or the plain statistics: a tally holds one kind of path.
  putBytes(bytes, static_cast<std::uint8_t>(controlled() ? 1 : 0));
  if (controlled_)
    controlled_->appendBytes(bytes);
  else
    for (const RunningStatistic& s : plain_) putStatistic(bytes, s);
  putBytes(bytes, events_);
  putHistogram(bytes, surfaceDirections_);
  putHistogram(bytes, subsurfaceDirections_);
  putHistogram(bytes, transmittedDirections_);
  putHistogram(bytes, radialExits_);
}

SkinTally SkinTally::fromBytes(const TallyOptions& options, const std::string& bytes,
                               std::size_t& offset) {
  SkinTally t(options);
  if (take<std::uint8_t>(bytes, offset) != 0)
    t.controlled_ = ControlledMeans::fromBytes(kQuantities, bytes, offset);
  else
    for (RunningStatistic& s : t.plain_) s = takeStatistic(bytes, offset);
  t.events_ = take<std::uint64_t>(bytes, offset);
  takeHistogram(bytes, offset, t.surfaceDirections_);
  takeHistogram(bytes, offset, t.subsurfaceDirections_);
  takeHistogram(bytes, offset, t.transmittedDirections_);
  takeHistogram(bytes, offset, t.radialExits_);
  return t;
}

}  // namespace hylios::skin
