#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "renderer/tracing/channel_buffer.h"

namespace hylios {
namespace {

TEST(ChannelBuffer, HoldsABandOnTheStackAndALargerOneOnTheHeap) {
  for (const std::size_t n :
       {std::size_t{0}, std::size_t{1}, std::size_t{41}, ChannelBuffer::kInlineChannels,
        ChannelBuffer::kInlineChannels + 1, std::size_t{451}}) {
    ChannelBuffer b(n, 0.25);
    EXPECT_EQ(b.size(), n);
    EXPECT_EQ(b.onHeap(), n > ChannelBuffer::kInlineChannels) << n;
    for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(b[i], 0.25) << i << " of " << n;
    for (std::size_t i = 0; i < n; ++i) b[i] = static_cast<double>(i);
    const double count = static_cast<double>(n);
    EXPECT_EQ(std::accumulate(b.begin(), b.end(), 0.0), count * (count > 0 ? count - 1 : 0) / 2);
  }
}

TEST(ChannelBuffer, CopiesARange) {
  for (const std::size_t n : {std::size_t{3}, std::size_t{200}}) {
    std::vector<double> values(n);
    for (std::size_t i = 0; i < n; ++i) values[i] = 1.5 * static_cast<double>(i) - 7.0;
    const ChannelBuffer b(values.data(), values.data() + n);
    ASSERT_EQ(b.size(), n);
    EXPECT_NE(b.data(), values.data());
    for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(b[i], values[i]) << i;
  }
}

}  // namespace
}  // namespace hylios
