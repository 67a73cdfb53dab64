// exp and log written so that a loop of calls vectorises (no libm call, no table, no branch): the
// spectral walk evaluates them once per wavelength for every stay in a layer and every surface
// crossing (skin/spectral_weights.cpp), hundreds per path, and glibc's scalar calls were half of
// its time. Compiled without -fno-trapping-math the selects stay branches and nothing vectorises.
//
// | function  | domain and result                                     | accuracy (vector_math_test) |
// |-----------|-------------------------------------------------------|-----------------------------|
// | vectorExp | exp(x) for x in [−708, 709]; 0 below −708 (and −∞),   | ≤ 3 ulp                     |
// |           | exp(709) above 709; NaN gives NaN                     |                             |
// | vectorLog | log(x) for x > 0 (subnormals too); −∞ at 0; +∞ at +∞; | ≤ 2 ulp                     |
// |           | NaN for x < 0 and NaN                                 |                             |
//
// vectorExp: x = k·ln2 + r, |r| ≤ ln2/2 (Cody–Waite, two-part ln2), exp(r) by its Taylor
// polynomial of degree 12 (truncation < 2e−16 relative), 2^k put into the exponent bits (k from the
// 1.5·2^52 rounding shift). vectorLog: x = 2^e·m, m in [√½, √2), log m = log(1+f) by fdlibm's
// polynomial in s = f/(2+f) (e_log.c), e·ln2 in two parts. Both need only double multiply, add,
// divide and 64-bit integer add, and, shift: SSE2, the x86-64 baseline, and wider units.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace hylios::skin {

inline double vectorExp(double x) {
  constexpr double kLog2e = 1.4426950408889634074;
  constexpr double kShift = 0x1.8p52;  // adding it rounds to an integer kept in the low bits
  constexpr double kLn2Hi = 0x1.62e42fefa3800p-1;  // ln 2 = kLn2Hi + kLn2Lo; k·kLn2Hi is exact
  constexpr double kLn2Lo = 0x1.ef35793c7673p-45;
  const double low = x < -708.0 ? -708.0 : x;  // NaN passes both tests unchanged
  const double clamped = low > 709.0 ? 709.0 : low;
  const double kd = clamped * kLog2e + kShift;
  std::uint64_t kBits;
  std::memcpy(&kBits, &kd, sizeof kBits);
  const double k = kd - kShift;
  const double r = (clamped - k * kLn2Hi) - k * kLn2Lo;
  double p = 1.0 / 479001600.0;  // 1/12!
  p = p * r + 1.0 / 39916800.0;
  p = p * r + 1.0 / 3628800.0;
  p = p * r + 1.0 / 362880.0;
  p = p * r + 1.0 / 40320.0;
  p = p * r + 1.0 / 5040.0;
  p = p * r + 1.0 / 720.0;
  p = p * r + 1.0 / 120.0;
  p = p * r + 1.0 / 24.0;
  p = p * r + 1.0 / 6.0;
  p = p * r + 0.5;
  p = p * r + 1.0;
  p = p * r + 1.0;
  // 2^k: k + 1023 in [1, 2046] into the exponent field (the shift's own bits leave to the left).
  const std::uint64_t scaleBits = (kBits + 1023) << 52;
  double scale;
  std::memcpy(&scale, &scaleBits, sizeof scale);
  const double result = p * scale;
  return x < -708.0 ? 0.0 : result;
}

inline double vectorLog(double x) {
  constexpr double kLn2Hi = 6.93147180369123816490e-01;  // fdlibm's split of ln 2
  constexpr double kLn2Lo = 1.90821492927058770002e-10;
  constexpr double kSqrt2 = 1.41421356237309504880;
  constexpr double kLg1 = 6.666666666666735130e-01, kLg2 = 3.999999999940941908e-01,
                   kLg3 = 2.857142874366239149e-01, kLg4 = 2.222219843214978396e-01,
                   kLg5 = 1.818357216161805012e-01, kLg6 = 1.531383769920937332e-01,
                   kLg7 = 1.479819860511658591e-01;
  const bool subnormal = x < 0x1p-1022;  // (and 0, negatives: replaced below)
  const double scaled = subnormal ? x * 0x1p54 : x;
  std::uint64_t bits;
  std::memcpy(&bits, &scaled, sizeof bits);
  // The biased exponent as a double (exact: OR into the mantissa of 2^52, subtract 2^52).
  const std::uint64_t exponentBits = ((bits >> 52) & 0x7ff) | 0x4330000000000000ULL;
  double exponent;
  std::memcpy(&exponent, &exponentBits, sizeof exponent);
  exponent = exponent - 0x1p52 - 1023.0 - (subnormal ? 54.0 : 0.0);
  const std::uint64_t mantissaBits = (bits & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL;
  double m;
  std::memcpy(&m, &mantissaBits, sizeof m);  // in [1, 2)
  const bool high = m > kSqrt2;
  m = high ? m * 0.5 : m;
  exponent = high ? exponent + 1.0 : exponent;
  const double f = m - 1.0;
  const double s = f / (2.0 + f);
  const double z = s * s, w = z * z;
  const double r =
      z * (kLg1 + w * (kLg3 + w * (kLg5 + w * kLg7))) + w * (kLg2 + w * (kLg4 + w * kLg6));
  const double halfF2 = 0.5 * f * f;
  const double result = exponent * kLn2Hi - ((halfF2 - (s * (halfF2 + r) + exponent * kLn2Lo)) - f);
  const double special =
      x == 0.0 ? -HUGE_VAL : (x > 0.0 ? x : std::numeric_limits<double>::quiet_NaN());
  return x > 0.0 && x < HUGE_VAL ? result : special;
}

}  // namespace hylios::skin
