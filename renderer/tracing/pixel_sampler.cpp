#include "renderer/tracing/pixel_sampler.h"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hylios {
namespace sobol {
namespace {

std::uint32_t reverseBits(std::uint32_t v) {
  v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
  v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
  v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
  v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
  return (v >> 16) | (v << 16);
}

constexpr std::uint32_t reverseBitsConstexpr(std::uint32_t v) {
  std::uint32_t r = 0;
  for (int k = 0; k < 32; ++k) r |= ((v >> k) & 1u) << (31 - k);
  return r;
}

/// Dimension 1 per byte of the index: table[b][x] is the value of index x << 8b, bit-reversed when
/// `reversed` (the scrambles work on reversed digits). Direction numbers as 32-bit fractions:
/// v_0 = 2^31, v_k = v_(k−1) ⊕ (v_(k−1) >> 1).
using ByteTables = std::array<std::array<std::uint32_t, 256>, 4>;
constexpr ByteTables dimension1Tables(bool reversed) {
  std::array<std::uint32_t, 32> v{};
  v[0] = 1u << 31;
  for (std::size_t k = 1; k < v.size(); ++k) v[k] = v[k - 1] ^ (v[k - 1] >> 1);
  ByteTables tables{};
  for (std::size_t b = 0; b < 4; ++b)
    for (std::uint32_t x = 0; x < 256; ++x) {
      std::uint32_t value = 0;
      for (std::size_t k = 0; k < 8; ++k)
        if ((x >> k) & 1u) value ^= v[8 * b + k];
      tables[b][x] = reversed ? reverseBitsConstexpr(value) : value;
    }
  return tables;
}
constexpr ByteTables kDimension1 = dimension1Tables(false);
constexpr ByteTables kDimension1Reversed = dimension1Tables(true);

std::uint32_t lookup(const ByteTables& tables, std::uint32_t index) {
  return tables[0][index & 0xffu] ^ tables[1][(index >> 8) & 0xffu] ^
         tables[2][(index >> 16) & 0xffu] ^ tables[3][index >> 24];
}

/// owenScramble in the reversed domain: owenScramble(v, s) = reverseBits(nestedHash(
/// reverseBits(v), s)). With the digits reversed, digit k of the value is bit k, and a step that
/// changes bit k only by a function of the bits below it (adding the seed, multiplying by an odd
/// number, x ⊕= x·c with c even) changes digit k only by a function of the digits above it: a
/// nested scramble. The steps and constants are the hash of Vegdahl's "Building a better LK hash"
/// (2021), the one pbrt-v4's FastOwenScrambler uses; the tests check the net property it keeps.
std::uint32_t nestedHash(std::uint32_t x, std::uint32_t seed) {
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}

}  // namespace

std::uint32_t dimension0(std::uint32_t index) { return reverseBits(index); }

std::uint32_t dimension1(std::uint32_t index) { return lookup(kDimension1, index); }

std::uint32_t owenScramble(std::uint32_t value, std::uint32_t seed) {
  return reverseBits(nestedHash(reverseBits(value), seed));
}

// The padded requests with the reversals that cancel left out: for the shuffled index
// j = owenScramble(i, s1), dimension0(j) = reverseBits(j) = nestedHash(reverseBits(i), s1) = t, so
//   1-D:  owenScramble(t, s2) = reverseBits(nestedHash(reverseBits(t), s2)),
//   2-D:  x = owenScramble(t, s2) = reverseBits(nestedHash(j, s2)),
//         y = owenScramble(dimension1(j), s3) = reverseBits(nestedHash(reversed dimension1(j),
//         s3)).
std::uint32_t scrambledRadicalInverse(std::uint32_t reversedIndex, std::uint32_t shuffleSeed,
                                      std::uint32_t seed) {
  return reverseBits(nestedHash(reverseBits(nestedHash(reversedIndex, shuffleSeed)), seed));
}

std::array<std::uint32_t, 2> scrambledSobol2D(std::uint32_t reversedIndex,
                                              std::uint32_t shuffleSeed, std::uint32_t seedX,
                                              std::uint32_t seedY) {
  const std::uint32_t j = reverseBits(nestedHash(reversedIndex, shuffleSeed));
  return {reverseBits(nestedHash(j, seedX)),
          reverseBits(nestedHash(lookup(kDimension1Reversed, j), seedY))};
}

}  // namespace sobol

namespace {

constexpr double kFixedPointScale = 0x1.0p-32;
constexpr std::uint64_t kGolden = 0x9e3779b97f4a7c15ULL;
constexpr std::uint64_t kBranchSalt = 0x5ab1e5b7a9c3d2e1ULL;
constexpr std::uint64_t kSobolSalt = 0x2545f4914f6cdd1dULL;
/// The independent sampler's band rotations: stream kChannelRotationStream − block of the pixel.
constexpr std::uint64_t kChannelRotationStream = ~std::uint64_t{0};

double unit(std::uint32_t fixedPoint) { return static_cast<double>(fixedPoint) * kFixedPointScale; }

}  // namespace

double SampleStream::get1D() {
  if (!sobol_ || dimension_ + 1 > kLowDiscrepancyDimensions) {
    ++dimension_;
    return rng_->uniform();
  }
  const std::uint64_t h = skin::mix64(scrambleSeed_ + (dimension_ + 1) * kGolden);
  ++dimension_;
  return unit(sobol::scrambledRadicalInverse(reversedIndex_, static_cast<std::uint32_t>(h),
                                             static_cast<std::uint32_t>(h >> 32)));
}

std::array<double, 2> SampleStream::get2D() {
  if (!sobol_ || dimension_ + 2 > kLowDiscrepancyDimensions) {
    dimension_ += 2;
    const double first = rng_->uniform();
    return {first, rng_->uniform()};
  }
  const std::uint64_t h = skin::mix64(scrambleSeed_ + (dimension_ + 1) * kGolden);
  const std::uint64_t g = skin::mix64(h);
  dimension_ += 2;
  const std::array<std::uint32_t, 2> point =
      sobol::scrambledSobol2D(reversedIndex_, static_cast<std::uint32_t>(h),
                              static_cast<std::uint32_t>(h >> 32), static_cast<std::uint32_t>(g));
  return {unit(point[0]), unit(point[1])};
}

SampleStream SampleStream::branch() const {
  if (!sobol_) return SampleStream(*rng_);
  return SampleStream(*rng_, skin::mix64(scrambleSeed_ ^ kBranchSalt), index());
}

PixelSampler::PixelSampler(SamplerKind kind, std::uint64_t seed, std::uint64_t strata)
    : kind_(kind), seed_(seed), strata_(strata) {
  if (strata == 0) throw std::invalid_argument("PixelSampler: strata must be at least 1");
}

SampleStream PixelSampler::stream(std::uint64_t pixel, std::uint64_t sample, skin::Rng& rng) const {
  if (kind_ == SamplerKind::Independent) return SampleStream(rng);
  if (sample >> 33 != 0)
    throw std::invalid_argument("PixelSampler: sample index " + std::to_string(sample) +
                                " is beyond the sobol sampler's 2^33 per pixel");
  // The film's halves: two independently scrambled sequences, in alternating blocks (header).
  const std::uint64_t half = inSecondFilmHalf(sample) ? 1 : 0;
  const std::uint64_t scrambleSeed =
      skin::mix64(skin::mix64(seed_ ^ kSobolSalt) ^ skin::mix64(2 * pixel + half));
  return SampleStream(rng, scrambleSeed, static_cast<std::uint32_t>(filmHalfPoint(sample)));
}

CameraSample PixelSampler::cameraSample(std::uint64_t pixel, std::uint64_t sample,
                                        SampleStream& stream) const {
  CameraSample c;
  if (kind_ == SamplerKind::Independent) {
    // Sample s takes slice s mod strata of [0, 1), jittered, rotated per block of strata samples:
    // every complete block meets every band or channel once, whenever the render stops.
    const std::uint64_t block = sample / strata_;
    const double rotation = skin::Rng(seed_, pixel, kChannelRotationStream - block).uniform();
    double u =
        (static_cast<double>(sample % strata_) + stream.get1D()) / static_cast<double>(strata_) +
        rotation;
    u -= std::floor(u);
    c.band = u < 1.0 ? u : skin::kOneMinusEpsilon;
    c.filmX = stream.get1D();
    c.filmY = stream.get1D();
    c.lensU = stream.get1D();
    c.lensV = stream.get1D();
    return c;
  }
  c.band = stream.get1D();
  const std::array<double, 2> film = stream.get2D(), lens = stream.get2D();
  c.filmX = film[0];
  c.filmY = film[1];
  c.lensU = lens[0];
  c.lensV = lens[1];
  return c;
}

}  // namespace hylios
