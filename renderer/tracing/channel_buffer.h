// Per-channel values of one camera path (throughput, branch weights, albedo), kept on the stack for
// bands of up to ChannelBuffer::kInlineChannels channels (Figure 1's visible band has 41) and on
// the heap beyond: a path that meets skin needs five such arrays, and allocating each of them per
// path cost a few per cent of a render (malloc, free and their page faults in perf).
#pragma once
#include <array>
#include <cstddef>
#include <vector>

namespace hylios {

class ChannelBuffer {
 public:
  static constexpr std::size_t kInlineChannels = 64;

  /// `size` channels, each `value`.
  explicit ChannelBuffer(std::size_t size, double value = 0.0);
  /// A copy of [first, last).
  ChannelBuffer(const double* first, const double* last);
  ChannelBuffer(const ChannelBuffer&) = delete;
  ChannelBuffer& operator=(const ChannelBuffer&) = delete;

  double* data() { return data_; }
  const double* data() const { return data_; }
  std::size_t size() const { return size_; }
  double& operator[](std::size_t i) { return data_[i]; }
  double operator[](std::size_t i) const { return data_[i]; }
  double* begin() { return data_; }
  double* end() { return data_ + size_; }
  /// True when the values live on the heap (more than kInlineChannels channels).
  bool onHeap() const { return !heap_.empty(); }

 private:
  std::array<double, kInlineChannels> inline_;  // not initialised beyond size_
  std::vector<double> heap_;
  double* data_;
  std::size_t size_;
};

}  // namespace hylios
