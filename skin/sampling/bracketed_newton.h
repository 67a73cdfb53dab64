// Inversion of a monotone function (a CDF) by Newton steps kept inside a shrinking bracket.
//
// Used by the samplers whose CDF has a closed form but no closed-form inverse (Algorithm 2's
// exponential polar density, the Sec. 4.3 surface-normal density). Every evaluation narrows the
// bracket [lo, hi]; a Newton step that leaves it, or that does not at least halve the previous
// step, is replaced by bisection. So the iteration always ends (bisection alone reaches adjacent
// doubles, or the smallest denormal above 0, in at most ~1100 halvings) and returns a finite value
// inside the bracket, while smooth CDFs converge quadratically in a handful of steps.
#pragma once
#include <cmath>

namespace hylios::skin {

struct ValueAndSlope {
  double value = 0;  ///< f(x)
  double slope = 0;  ///< f'(x) (>= 0 for an increasing f)
};

/// A root of the non-decreasing function `f` (callable double -> ValueAndSlope) in [lo, hi], where
/// f(lo) <= 0 <= f(hi) is the caller's promise. `guess` seeds the first Newton step.
template <class Function>
double solveIncreasingBracketed(Function&& f, double lo, double hi, double guess) {
  double x = (guess > lo && guess < hi) ? guess : 0.5 * (lo + hi);
  double previousStep = hi - lo;
  constexpr int kMaxIterations = 4000;  // > 1100 bisections, so never the binding limit
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const ValueAndSlope fx = f(x);
    if (fx.value == 0) return x;
    if (fx.value < 0) {
      lo = x;
    } else {
      hi = x;
    }
    double next = x - fx.value / fx.slope;
    // A Newton correction below ~2 ulp (often rounding to x itself): x is the root.
    if (std::fabs(next - x) <= 4e-16 * std::fabs(x)) return x;
    const bool newtonUsable = next > lo && next < hi && std::fabs(next - x) <= 0.5 * previousStep;
    if (!newtonUsable) next = 0.5 * (lo + hi);  // also catches slope 0 and NaN steps
    if (next == lo || next == hi) return next;  // the bracket is down to adjacent doubles
    previousStep = std::fabs(next - x);
    x = next;
  }
  return x;
}

}  // namespace hylios::skin
