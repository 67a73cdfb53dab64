// Running Monte Carlo estimators: a mean and its standard error from per-packet scores, and a
// histogram of per-packet scores. Both are mergeable, so parallel workers can each fill one and
// the results are summed in a fixed order (byte-identical at any thread count).
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace hylios::skin {

/// A mean with its standard error.
struct Estimate {
  double mean = 0;
  double standardError = 0;
};

/// Sum and sum of squares of one score per packet (0/1 for analog tallies, real weights
/// otherwise). standardError = sqrt((E[x^2] - E[x]^2) / (N - 1)).
class RunningStatistic {
 public:
  /// Records one packet's total score for this quantity (call once per packet, zeros included).
  void add(double score) {
    ++count_;
    sum_ += score;
    sumSquares_ += score * score;
  }
  /// Records `packets` packets that scored 0 (cheaper than add(0) in a loop).
  void addZeros(std::uint64_t packets) { count_ += packets; }
  /// Adds another accumulator's packets (sums are added: merge in a fixed order for determinism).
  void merge(const RunningStatistic& other) {
    count_ += other.count_;
    sum_ += other.sum_;
    sumSquares_ += other.sumSquares_;
  }
  std::uint64_t count() const { return count_; }
  double sum() const { return sum_; }
  double sumSquares() const { return sumSquares_; }
  double mean() const { return count_ == 0 ? 0.0 : sum_ / static_cast<double>(count_); }
  /// 0 for fewer than two packets.
  double standardError() const {
    if (count_ < 2) return 0.0;
    const double n = static_cast<double>(count_);
    const double m = sum_ / n;
    // E[x^2] - E[x]^2 >= 0 mathematically; a negative value is rounding only.
    const double variance = std::fmax(0.0, sumSquares_ / n - m * m);
    return std::sqrt(variance / (n - 1.0));
  }
  Estimate estimate() const { return {mean(), standardError()}; }
  /// An accumulator holding exactly these sums (the state of one sent between processes).
  static RunningStatistic restored(std::uint64_t count, double sum, double sumSquares) {
    RunningStatistic s;
    s.count_ = count;
    s.sum_ = sum;
    s.sumSquares_ = sumSquares;
    return s;
  }

 private:
  std::uint64_t count_ = 0;
  double sum_ = 0;
  double sumSquares_ = 0;
};

/// Uniform bins over [lower, upper) of per-packet scores, plus underflow/overflow bins. Each
/// packet adds at most one score per bin (sum it first if it scores several times in one bin);
/// countPacket() once per packet. Bin estimates are per packet: mean = sum / packets.
class Histogram {
 public:
  Histogram(double lower, double upper, std::size_t binCount)
      : lower_(lower), upper_(upper), sums_(binCount + 2, 0.0), sumSquares_(binCount + 2, 0.0) {
    if (!(upper > lower) || binCount == 0 || !std::isfinite(lower) || !std::isfinite(upper))
      throw std::invalid_argument(
          "Histogram: need finite lower < upper and at least one bin, got [" +
          std::to_string(lower) + ", " + std::to_string(upper) + ") with " +
          std::to_string(binCount) + " bins");
  }
  std::size_t binCount() const { return sums_.size() - 2; }
  double binWidth() const { return (upper_ - lower_) / static_cast<double>(binCount()); }
  double binCentre(std::size_t bin) const {
    return lower_ + (static_cast<double>(bin) + 0.5) * binWidth();
  }
  /// Bin index of x: 0..binCount()-1 inside, kUnderflow below, kOverflow at or above `upper` (and
  /// NaN).
  std::size_t binOf(double x) const {
    if (x < lower_) return underflowIndex();
    if (!(x < upper_)) return overflowIndex();
    const auto bin = static_cast<std::size_t>((x - lower_) / binWidth());
    return bin < binCount() ? bin : binCount() - 1;  // x just below upper may round up
  }
  std::size_t underflowIndex() const { return binCount(); }
  std::size_t overflowIndex() const { return binCount() + 1; }
  /// Adds one packet's score `weight` at coordinate x.
  void add(double x, double weight) { addToBin(binOf(x), weight); }
  void addToBin(std::size_t bin, double weight) {
    sums_.at(bin) += weight;
    sumSquares_[bin] += weight * weight;
  }
  void countPacket(std::uint64_t packets = 1) { packets_ += packets; }
  void merge(const Histogram& other) {
    if (other.sums_.size() != sums_.size() || other.lower_ != lower_ || other.upper_ != upper_)
      throw std::invalid_argument("Histogram::merge: the two histograms have different bins");
    for (std::size_t i = 0; i < sums_.size(); ++i) {
      sums_[i] += other.sums_[i];
      sumSquares_[i] += other.sumSquares_[i];
    }
    packets_ += other.packets_;
  }
  std::uint64_t packets() const { return packets_; }
  /// The raw state, bins then underflow and overflow (for sending between processes).
  const std::vector<double>& sums() const { return sums_; }
  const std::vector<double>& sumSquares() const { return sumSquares_; }
  /// Replaces the state with one taken from sums()/sumSquares()/packets() of a histogram with
  /// the same bins; throws std::invalid_argument when the sizes differ.
  void restore(std::vector<double> sums, std::vector<double> sumSquares, std::uint64_t packets) {
    if (sums.size() != sums_.size() || sumSquares.size() != sumSquares_.size())
      throw std::invalid_argument("Histogram::restore: the state has " +
                                  std::to_string(sums.size()) + " bins, this histogram " +
                                  std::to_string(sums_.size()));
    sums_ = std::move(sums);
    sumSquares_ = std::move(sumSquares);
    packets_ = packets;
  }
  /// Per-packet mean score in `bin` (including underflowIndex()/overflowIndex()) and its error.
  Estimate estimate(std::size_t bin) const {
    if (packets_ < 2) return {packets_ == 0 ? 0.0 : sums_.at(bin), 0.0};
    const double n = static_cast<double>(packets_);
    const double m = sums_.at(bin) / n;
    const double variance = std::fmax(0.0, sumSquares_[bin] / n - m * m);  // rounding only
    return {m, std::sqrt(variance / (n - 1.0))};
  }

 private:
  double lower_, upper_;
  std::vector<double> sums_, sumSquares_;
  std::uint64_t packets_ = 0;
};

}  // namespace hylios::skin
