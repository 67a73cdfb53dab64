// Henyey–Greenstein scattering in eight single-precision lanes (skin/core/float_lanes.h), for the
// lane walk of the layered slab (skin/layered_slab_lanes.cpp). The same inversion as
// skin/sampling/henyey_greenstein.h, factorised so that nothing cancels:
//   D = 1 − g + 2gu,  1 − μ = 2(1 − g)²(1 − u)(1 + gu)/D²,  1 + μ = 2(1 + g)²u(1 − g + gu)/D²,
// the smaller of the two taken, and sin²θ = (1 − μ)(1 + μ) from the same factor. The new direction
// is built about the old one with the branchless orthonormal basis of skin/core/vector3.h (Frame).
#pragma once
#include "skin/core/float_lanes.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"  // force-inlined: no vector crosses a call

namespace hylios::skin::lanes {

/// Per-lane constants of one asymmetry g in (−1, 1) (gathered per lane from the layers).
struct HenyeyGreensteinLanes {
  Floats g, oneMinusG, twoTimesG, twoOneMinusGSquared, twoOnePlusGSquared;
};

/// cosθ and sinθ ≥ 0 of a Henyey–Greenstein deflection for uniform u in [0, 1).
HYLIOS_LANES_INLINE void sampleHenyeyGreensteinLanes(const HenyeyGreensteinLanes& p, Floats u,
                                                     Floats& cosTheta, Floats& sinTheta) {
  const Floats d = p.oneMinusG + p.twoTimesG * u;
  const Floats inverseDSquared = 1.0f / (d * d);
  const Floats oneMinusMu = p.twoOneMinusGSquared * (1.0f - u) * (1.0f + p.g * u) * inverseDSquared;
  const Floats onePlusMu = p.twoOnePlusGSquared * u * (p.oneMinusG + p.g * u) * inverseDSquared;
  const Ints forward = oneMinusMu <= 1.0f;
  const Floats smaller = select(forward, oneMinusMu, onePlusMu);
  cosTheta = select(forward, 1.0f - oneMinusMu, onePlusMu - 1.0f);
  sinTheta = sqrt(max(splat(0.0f), smaller * (2.0f - smaller)));
}

/// The unit direction at (cosθ, sinθ) from unit axis (x, y, z) and azimuth φ = 2π(uAzimuth − ½),
/// renormalised by one Newton step (keeps |d| = 1 to float rounding over thousands of bounces).
HYLIOS_LANES_INLINE void turnLanes(Floats& x, Floats& y, Floats& z, Floats cosTheta,
                                   Floats sinTheta, Floats uAzimuth) {
  Floats sinPhi, cosPhi;
  laneSinCosTwoPi(uAzimuth, sinPhi, cosPhi);
  const Floats sign = copySign(splat(1.0f), z);
  const Floats a = -1.0f / (sign + z);
  const Floats b = x * y * a;
  const Floats tx = 1.0f + sign * x * x * a, ty = sign * b, tz = -sign * x;
  const Floats bx = b, by = sign + y * y * a, bz = -y;
  const Floats lx = sinTheta * cosPhi, ly = sinTheta * sinPhi;
  Floats nx = tx * lx + bx * ly + x * cosTheta;
  Floats ny = ty * lx + by * ly + y * cosTheta;
  Floats nz = tz * lx + bz * ly + z * cosTheta;
  const Floats scale = 1.5f - 0.5f * (nx * nx + ny * ny + nz * nz);
  x = nx * scale;
  y = ny * scale;
  z = nz * scale;
}

}  // namespace hylios::skin::lanes

#pragma GCC diagnostic pop
