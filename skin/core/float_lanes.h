// Eight single-precision lanes (GCC vector extensions) and the closed forms a lane walk needs, so
// that a walk can follow eight packets at once in one AVX2 register (two SSE2 registers in the
// x86-64 baseline). Everything here is force-inlined, so a caller compiled as a target clone
// (skin/layered_slab_lanes.cpp) gets it in its own instruction set, and with -ffp-contract=off
// every clone computes the same bits.
//
// | function          | domain and result                                      | accuracy (test) |
// |-------------------|--------------------------------------------------------|-----------------|
// | laneLog(x)        | log(x) for normal x > 0 (the walk's 1 − u ≥ 2⁻²⁴)      | ≤ 2 ulp         |
// | laneSinCosTwoPi(u)| sin, cos of 2π(u − ½) for u in [0, 1]                  | ≤ 5e−7 absolute |
//
// laneLog: x = 2^e·m with m in [√½, √2), log m = log(1 + f) by fdlibm's single-precision
// polynomial in s = f/(2 + f) (e_logf.c), e·ln 2 in two parts. laneSinCosTwoPi: b = π(u − ½) in
// [−π/2, π/2], sin b and cos b by their Taylor polynomials to b¹¹ and b¹² (truncation ≤ 6e−8), then
// the double angle: sin 2b = 2 sin b cos b, cos 2b = (cos b − sin b)(cos b + sin b).
#pragma once
#include <cstdint>

// The lane functions are force-inlined, so no 32-byte vector ever crosses a call: GCC's note that
// such a return "changes the ABI" without AVX does not apply.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace hylios::skin::lanes {

inline constexpr int kLanes = 8;
using Floats = float __attribute__((vector_size(32)));
using Ints = std::int32_t __attribute__((vector_size(32)));  ///< also masks: −1 true, 0 false
using Bits = std::uint32_t __attribute__((vector_size(32)));

#define HYLIOS_LANES_INLINE inline __attribute__((always_inline))

HYLIOS_LANES_INLINE Floats splat(float x) { return Floats{} + x; }
HYLIOS_LANES_INLINE Ints splatInt(std::int32_t x) { return Ints{} + x; }
/// Per lane: mask ? a : b (mask lanes are −1 or 0, as comparisons give).
HYLIOS_LANES_INLINE Floats select(Ints mask, Floats a, Floats b) { return mask ? a : b; }
HYLIOS_LANES_INLINE Ints selectInt(Ints mask, Ints a, Ints b) { return mask ? a : b; }
HYLIOS_LANES_INLINE Floats abs(Floats x) {
  return reinterpret_cast<Floats>(reinterpret_cast<Bits>(x) & 0x7fffffffu);
}
HYLIOS_LANES_INLINE Floats min(Floats a, Floats b) { return a < b ? a : b; }
HYLIOS_LANES_INLINE Floats max(Floats a, Floats b) { return a > b ? a : b; }
/// |magnitude| with the sign of sign.
HYLIOS_LANES_INLINE Floats copySign(Floats magnitude, Floats sign) {
  const Bits m = reinterpret_cast<Bits>(magnitude) & 0x7fffffffu;
  const Bits s = reinterpret_cast<Bits>(sign) & 0x80000000u;
  return reinterpret_cast<Floats>(m | s);
}
HYLIOS_LANES_INLINE Floats sqrt(Floats x) {  // vectorised (sqrtps) without errno
  Floats r;
  for (int l = 0; l < kLanes; ++l) r[l] = __builtin_sqrtf(x[l]);
  return r;
}
/// Eight floats from / to memory of any alignment (heap blocks of plain floats need not be
/// 32-byte aligned).
HYLIOS_LANES_INLINE Floats load(const float* from) {
  Floats r;
  __builtin_memcpy(&r, from, sizeof r);
  return r;
}
HYLIOS_LANES_INLINE void store(float* to, Floats x) { __builtin_memcpy(to, &x, sizeof x); }
/// table[index] per lane (a gather).
HYLIOS_LANES_INLINE Floats gather(const float* table, Ints index) {
  Floats r;
  for (int l = 0; l < kLanes; ++l) r[l] = table[index[l]];
  return r;
}
/// The same for a table of at most eight entries, padded to eight: one permute, no gather (GCC;
/// Clang, which builds the fuzzers, has no shuffle with a variable mask and reads lane by lane).
HYLIOS_LANES_INLINE Floats permute(const float* table8, Ints index) {
#if defined(__clang__)
  return gather(table8, index);
#else
  return __builtin_shuffle(load(table8), index);
#endif
}
HYLIOS_LANES_INLINE Ints permuteInt(const std::int32_t* table8, Ints index) {
#if defined(__clang__)
  Ints r;
  for (int l = 0; l < kLanes; ++l) r[l] = table8[index[l]];
  return r;
#else
  Ints t;
  __builtin_memcpy(&t, table8, sizeof t);
  return __builtin_shuffle(t, index);
#endif
}
HYLIOS_LANES_INLINE Ints gatherInt(const std::int32_t* table, Ints index) {
  Ints r;
  for (int l = 0; l < kLanes; ++l) r[l] = table[index[l]];
  return r;
}
/// Whether any lane of the mask is set: the halves folded in 64-bit words (a lane-by-lane loop
/// compiles to eight extractions).
HYLIOS_LANES_INLINE bool any(Ints mask) {
  using Quads = std::uint64_t __attribute__((vector_size(32)));
  const Quads q = reinterpret_cast<Quads>(mask);
#if defined(__clang__)
  const Quads folded = q | __builtin_shufflevector(q, q, 2, 3, 0, 1);
#else
  const Quads folded = q | __builtin_shuffle(q, Quads{2, 3, 0, 1});
#endif
  return (folded[0] | folded[1]) != 0;
}

/// log(x) for normal x > 0 (see the table above).
HYLIOS_LANES_INLINE Floats laneLog(Floats x) {
  const Bits bits = reinterpret_cast<Bits>(x);
  Ints exponent = reinterpret_cast<Ints>(bits >> 23) - 127;
  // Mantissa in [1, 2); above √2 halve it (exponent + 1) so that m is in [√½, √2).
  const Bits mantissaBits = (bits & 0x007fffffu) | 0x3f800000u;
  const Floats m1 = reinterpret_cast<Floats>(mantissaBits);
  const Ints high = m1 > 1.41421356f;
  const Floats m = select(high, m1 * 0.5f, m1);
  exponent = exponent - high;  // high is −1 where true
  const Floats f = m - 1.0f;
  const Floats s = f / (2.0f + f);
  const Floats z = s * s, w = z * z;
  constexpr float kLg1 = 0xaaaaaa.0p-24f, kLg2 = 0xccce13.0p-25f;
  constexpr float kLg3 = 0x91e9ee.0p-25f, kLg4 = 0xf89e26.0p-26f;
  const Floats t1 = w * (kLg2 + w * kLg4);
  const Floats t2 = z * (kLg1 + w * kLg3);
  const Floats r = t2 + t1;
  const Floats halfFSquared = 0.5f * f * f;
  const Floats e = __builtin_convertvector(exponent, Floats);
  constexpr float kLn2Hi = 6.9313812256e-01f, kLn2Lo = 9.0580006145e-06f;
  return e * kLn2Hi - ((halfFSquared - (s * (halfFSquared + r) + e * kLn2Lo)) - f);
}

/// sin and cos of 2π(u − ½), an angle uniform on [−π, π) when u is uniform on [0, 1).
HYLIOS_LANES_INLINE void laneSinCosTwoPi(Floats u, Floats& sinAngle, Floats& cosAngle) {
  const Floats b = 3.14159265f * (u - 0.5f);
  const Floats b2 = b * b;
  Floats sinB = splat(-2.5052108e-08f);  // −1/11!
  sinB = sinB * b2 + 2.7557319e-06f;
  sinB = sinB * b2 - 1.9841270e-04f;
  sinB = sinB * b2 + 8.3333333e-03f;
  sinB = sinB * b2 - 1.6666667e-01f;
  sinB = (sinB * b2) * b + b;
  Floats cosB = splat(2.0876757e-09f);  // 1/12!
  cosB = cosB * b2 - 2.7557319e-07f;
  cosB = cosB * b2 + 2.4801587e-05f;
  cosB = cosB * b2 - 1.3888889e-03f;
  cosB = cosB * b2 + 4.1666667e-02f;
  cosB = cosB * b2 - 0.5f;
  cosB = cosB * b2 + 1.0f;
  sinAngle = 2.0f * sinB * cosB;
  cosAngle = (cosB - sinB) * (cosB + sinB);
}

}  // namespace hylios::skin::lanes

#pragma GCC diagnostic pop
