// Standard exponential variates by the ziggurat method (G. Marsaglia and W. W. Tsang, "The
// ziggurat method for generating random variables", J. Stat. Softw. 5(8), 2000), for both walks'
// free paths and Algorithm 2's Gamma(2) proposal: a log per draw was a tenth of the spectral
// walk's time in the θo ramp (docs/benchmarks.md, session 26).
//
// The area under e^{−x} is cut into 256 layers of equal area v: layer 0 is the rectangle
// [0, r) × [0, e^{−r}) with the tail beyond r, layer i ≥ 1 the rectangle [0, x_i) × [e^{−x_i},
// e^{−x_{i+1}}), with x_1 = r > x_2 > … > x_256 = 0. A draw picks a layer and a uniform x in
// [0, x_i) from one 64-bit number (low 8 bits, top 53 bits) and accepts it at once when x < x_{i+1}
// (the rectangle lies under the curve there: 98.9 % of draws). Otherwise layer 0 returns r plus a
// fresh exponential (memorylessness), and a wedge of layer i ≥ 1 is accepted when a uniform height
// lies under e^{−x}. The law is exactly e^{−x} up to the 2^−53 grid of the uniforms.
//
// | constant | value                                   |
// |----------|-----------------------------------------|
// | r        | 7.69711747013104972 (Marsaglia–Tsang)   |
// | v        | 3.949659822581572e−3 = r e^{−r} + e^{−r} |
#pragma once
#include <array>
#include <cmath>
#include <cstdint>

#include "skin/core/random.h"

namespace hylios::skin {

struct ExponentialZiggurat {
  static constexpr int kLayers = 256;
  static constexpr double kTailStart = 7.69711747013104972;       ///< r
  static constexpr double kLayerArea = 3.9496598225815571993e-3;  ///< v
  std::array<double, kLayers + 1> width{};   ///< x_i: x_0 = v/e^{−r} (layer 0's span), x_256 = 0
  std::array<double, kLayers + 1> height{};  ///< e^{−x_i}
  ExponentialZiggurat();
};
extern const ExponentialZiggurat kExponentialZiggurat;

/// A variate of density e^{−x} on [0, ∞) (finite; mean 1).
inline double sampleStandardExponential(Rng& rng) {
  const ExponentialZiggurat& z = kExponentialZiggurat;
  for (;;) {
    const std::uint64_t bits = rng.nextU64();
    const unsigned layer = static_cast<unsigned>(bits & 0xff);
    const double x = static_cast<double>(bits >> 11) * 0x1.0p-53 * z.width[layer];
    if (x < z.width[layer + 1]) return x;
    if (layer == 0) return ExponentialZiggurat::kTailStart - std::log(1.0 - rng.uniform());
    const double y = z.height[layer] + rng.uniform() * (z.height[layer + 1] - z.height[layer]);
    if (y < std::exp(-x)) return x;
  }
}

}  // namespace hylios::skin
