#include "renderer/tracing/channel_buffer.h"

#include <algorithm>

namespace hylios {

ChannelBuffer::ChannelBuffer(std::size_t size, double value) : size_(size) {
  if (size > kInlineChannels) heap_.resize(size);
  data_ = size > kInlineChannels ? heap_.data() : inline_.data();
  std::fill(data_, data_ + size, value);
}

ChannelBuffer::ChannelBuffer(const double* first, const double* last)
    : ChannelBuffer(static_cast<std::size_t>(last - first)) {
  std::copy(first, last, data_);
}

}  // namespace hylios
