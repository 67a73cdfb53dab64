// Eight independent random streams in lanes: xoshiro128+ (Blackman & Vigna 2019, the variant its
// authors give for single-precision floats, whose upper 24 bits are used) with one 128-bit state
// per lane. A lane's state is seeded from the packet's own skin::Rng(seed, stream, index), so a
// packet's numbers depend on its identity only, never on the lane or the thread that runs it.
#pragma once
#include <cstdint>

#include "skin/core/float_lanes.h"
#include "skin/core/random.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"  // force-inlined: no vector crosses a call

namespace hylios::skin::lanes {

struct LaneRng {
  Bits s0{}, s1{}, s2{}, s3{};

  /// Lane `lane` takes its state from two 64-bit numbers of `rng` (never the all-zero state).
  void seedLane(int lane, Rng& rng) {
    const std::uint64_t a = rng.nextU64(), b = rng.nextU64();
    s0[lane] = static_cast<std::uint32_t>(a);
    s1[lane] = static_cast<std::uint32_t>(a >> 32);
    s2[lane] = static_cast<std::uint32_t>(b);
    s3[lane] = static_cast<std::uint32_t>(b >> 32);
    if ((a | b) == 0) s0[lane] = 1;
  }

  /// The next 32-bit output of every lane.
  HYLIOS_LANES_INLINE Bits next() {
    const Bits result = s0 + s3;
    const Bits t = s1 << 9;
    s2 ^= s0;
    s3 ^= s1;
    s1 ^= s2;
    s0 ^= s3;
    s2 ^= t;
    s3 = (s3 << 11) | (s3 >> 21);
    return result;
  }

  /// Uniform in [0, 1) on the grid k·2⁻²⁴ (the upper 24 bits); never 1.
  HYLIOS_LANES_INLINE Floats uniform() {
    const Ints top = reinterpret_cast<Ints>(next() >> 8);
    return __builtin_convertvector(top, Floats) * 0x1.0p-24f;
  }
};

}  // namespace hylios::skin::lanes

#pragma GCC diagnostic pop
