// Deterministic random numbers for the walk and the renderer.
//
// Every random stream is identified by (seed, stream, index): e.g. (user seed, wavelength index,
// ray index) or (user seed, pixel, sample). The generator state is derived from those three numbers
// alone, so results never depend on which thread ran which ray, nor on how many threads there were.
#pragma once
#include <cstdint>

namespace hylios::skin {

/// SplitMix64 finaliser: a bijective 64-bit mix (Steele, Lea & Flood 2014).
constexpr std::uint64_t mix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// xoshiro256++ (Blackman & Vigna 2019), seeded through SplitMix64 from (seed, stream, index).
class Rng {
 public:
  explicit Rng(std::uint64_t seed, std::uint64_t stream = 0, std::uint64_t index = 0) {
    std::uint64_t z =
        mix64(seed) ^ mix64(stream + 0x632be59bd9b4e019ULL) ^ mix64(index * 0x85157af5ULL + 0x1ULL);
    for (auto& word : state_) {
      z = mix64(z);
      word = z;
    }
  }

  std::uint64_t nextU64() {
    const std::uint64_t result = rotl(state_[0] + state_[3], 23) + state_[0];
    const std::uint64_t t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = rotl(state_[3], 45);
    return result;
  }

  /// Uniform double in [0, 1): 53 random bits. Never returns 1.
  double uniform() { return static_cast<double>(nextU64() >> 11) * 0x1.0p-53; }

 private:
  static constexpr std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t state_[4];
};

/// The largest double below 1; samplers must accept it (and 0) without NaN or Inf.
inline constexpr double kOneMinusEpsilon = 0x1.fffffffffffffp-1;

}  // namespace hylios::skin
