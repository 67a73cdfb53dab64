// Chi-square goodness-of-fit tests for samplers, in the manner of Mitsuba 3's chi2 tests.
//
// A sample is binned (1-D: fixed or equal-probability edges; 2-D: a grid); the expected count of
// every bin is n·∫ density over the bin by adaptive Simpson quadrature; bins expecting fewer than
// 5 samples are pooled (smallest first) so the chi-square law applies; the statistic's p-value is
// Q(dof/2, χ²/2), the regularized upper incomplete gamma function (series / continued fraction).
// Samples outside the binned range form one more bin whose expectation is n·(1 − ∫ over the range),
// so a density that is not normalised, or a sampler that leaves the support, is caught. A bin that
// expects essentially nothing (< 1e-6 samples) yet receives one fails the test outright.
//
// Header-only; used by the tests/*_sampling_test.cpp files.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace hylios::test {

// ---------------------------------------------------------------- quadrature

namespace detail {
template <class F>
double simpsonStep(F& f, double a, double b, double fa, double fm, double fb, double whole,
                   double tolerance, int depth) {
  const double m = 0.5 * (a + b);
  const double leftMid = 0.5 * (a + m), rightMid = 0.5 * (m + b);
  const double fLeftMid = f(leftMid), fRightMid = f(rightMid);
  const double left = (m - a) / 6.0 * (fa + 4.0 * fLeftMid + fm);
  const double right = (b - m) / 6.0 * (fm + 4.0 * fRightMid + fb);
  const double delta = left + right - whole;
  const double floor = 1e-15 * std::fabs(left + right);  // below rounding noise: stop
  if (depth <= 0 || std::fabs(delta) <= 15.0 * std::max(tolerance, floor)) {
    return left + right + delta / 15.0;  // Richardson extrapolation
  }
  return simpsonStep(f, a, m, fa, fLeftMid, fm, left, 0.5 * tolerance, depth - 1) +
         simpsonStep(f, m, b, fm, fRightMid, fb, right, 0.5 * tolerance, depth - 1);
}
}  // namespace detail

/// ∫_a^b f by adaptive Simpson to absolute tolerance `tolerance`. The interval is first cut into
/// `initialPieces` so that a narrow peak between the first few nodes is not missed.
template <class F>
double integrate(F&& f, double a, double b, double tolerance = 1e-12, int initialPieces = 16) {
  double sum = 0.0;
  const double width = (b - a) / initialPieces;
  for (int i = 0; i < initialPieces; ++i) {
    const double lo = a + width * i;
    const double hi = i + 1 == initialPieces ? b : a + width * (i + 1);
    const double flo = f(lo), fmid = f(0.5 * (lo + hi)), fhi = f(hi);
    const double whole = (hi - lo) / 6.0 * (flo + 4.0 * fmid + fhi);
    sum += detail::simpsonStep(f, lo, hi, flo, fmid, fhi, whole, tolerance / initialPieces, 40);
  }
  return sum;
}

// ---------------------------------------------------------------- chi-square law

/// Q(a, x) = Γ(a, x)/Γ(a), the regularized upper incomplete gamma function, a > 0, x >= 0:
/// the power series of P = 1 − Q for x < a + 1, Legendre's continued fraction (modified Lentz)
/// otherwise.
inline double regularizedGammaQ(double a, double x) {
  if (x <= 0.0) return 1.0;
  const double logPrefactor = -x + a * std::log(x) - std::lgamma(a);
  if (x < a + 1.0) {
    // P(a, x) = e^{−x} x^a / Γ(a + 1) · Σ_n x^n / ((a + 1)…(a + n))
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 10000; ++n) {
      term *= x / (a + n);
      sum += term;
      if (term < 1e-17 * sum) break;
    }
    return 1.0 - sum * std::exp(logPrefactor);
  }
  // Q(a, x) = e^{−x} x^a / Γ(a) · 1/(x + 1 − a − 1(1 − a)/(x + 3 − a − 2(2 − a)/(x + 5 − a − …)))
  constexpr double kTiny = 1e-300;
  double b = x + 1.0 - a;
  double c = 1.0 / kTiny;
  double d = 1.0 / b;
  double fraction = d;
  for (int i = 1; i < 10000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double factor = d * c;
    fraction *= factor;
    if (std::fabs(factor - 1.0) < 1e-16) break;
  }
  return std::exp(logPrefactor) * fraction;
}

/// P(X >= statistic) for X chi-square distributed with `degreesOfFreedom` degrees of freedom.
inline double chi2SurvivalProbability(double statistic, int degreesOfFreedom) {
  return regularizedGammaQ(0.5 * degreesOfFreedom, 0.5 * statistic);
}

// ---------------------------------------------------------------- the test

struct Chi2Result {
  double statistic = 0;
  int degreesOfFreedom = 0;
  double pValue = 0;
  std::size_t samples = 0;
  std::string problem;  ///< non-empty: the test fails whatever the p-value (impossible sample…)
  std::string worstCells;
};

/// Chi-square statistic of observed against expected counts (same length), pooling the bins that
/// expect fewer than `minExpected` samples, smallest first, until each pool expects at least that.
inline Chi2Result chi2FromCounts(const std::vector<double>& observed,
                                 const std::vector<double>& expected, double minExpected = 5.0) {
  Chi2Result result;
  result.samples = static_cast<std::size_t>(std::accumulate(observed.begin(), observed.end(), 0.0));
  std::ostringstream problem;
  for (std::size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] < 1e-6 && observed[i] > 0) {
      problem << "bin " << i << " received " << observed[i] << " samples but expects "
              << expected[i] << "; ";
    }
  }
  const double totalExpected = std::accumulate(expected.begin(), expected.end(), 0.0);
  const double totalObserved = static_cast<double>(result.samples);
  if (std::fabs(totalExpected - totalObserved) > 1e-6 * totalObserved + 1e-3) {
    problem << "expected counts sum to " << totalExpected << " for " << totalObserved
            << " samples (density not normalised?); ";
  }
  std::vector<std::size_t> order(observed.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return expected[i] < expected[j]; });
  std::vector<std::pair<double, double>> cells;  // (observed, expected)
  double poolObserved = 0, poolExpected = 0;
  for (const std::size_t i : order) {
    poolObserved += observed[i];
    poolExpected += expected[i];
    if (poolExpected >= minExpected) {
      cells.emplace_back(poolObserved, poolExpected);
      poolObserved = poolExpected = 0;
    }
  }
  if (poolExpected > 0 || poolObserved > 0) {
    if (cells.empty()) {
      cells.emplace_back(poolObserved, poolExpected);
    } else {
      cells.back().first += poolObserved;
      cells.back().second += poolExpected;
    }
  }
  std::vector<std::pair<double, std::size_t>> contributions;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const double diff = cells[k].first - cells[k].second;
    const double term = cells[k].second > 0 ? diff * diff / cells[k].second : 0.0;
    result.statistic += term;
    contributions.emplace_back(term, k);
  }
  result.degreesOfFreedom = static_cast<int>(cells.size()) - 1;
  if (result.degreesOfFreedom < 1) problem << "fewer than two cells after pooling; ";
  result.pValue = result.degreesOfFreedom >= 1
                      ? chi2SurvivalProbability(result.statistic, result.degreesOfFreedom)
                      : 0.0;
  std::sort(contributions.rbegin(), contributions.rend());
  std::ostringstream worst;
  for (std::size_t k = 0; k < std::min<std::size_t>(3, contributions.size()); ++k) {
    const auto& cell = cells[contributions[k].second];
    worst << "(observed " << cell.first << ", expected " << cell.second << ") ";
  }
  result.worstCells = worst.str();
  result.problem = problem.str();
  return result;
}

/// `bins` + 1 edges on [lo, hi] whose bins each hold about the same probability under `density`
/// (found from a fine cumulative table; the expected counts are integrated afresh per bin later,
/// so the edges need not be exact). Coinciding edges (where the density vanishes) are dropped.
/// `n` values of `draw()`, drawn in order.
template <class Draw>
std::vector<double> drawSamples(std::size_t n, Draw&& draw) {
  std::vector<double> samples(n);
  for (double& x : samples) x = draw();
  return samples;
}

/// The arithmetic mean (summed in order).
inline double mean(const std::vector<double>& values) {
  double sum = 0;
  for (double x : values) sum += x;
  return sum / static_cast<double>(values.size());
}

template <class Density>
std::vector<double> equalProbabilityEdges(Density&& density, double lo, double hi, int bins) {
  const int pieces = 64 * bins;
  std::vector<double> cumulative(static_cast<std::size_t>(pieces) + 1, 0.0);
  const double width = (hi - lo) / pieces;
  for (int i = 0; i < pieces; ++i) {
    const double a = lo + width * i;
    cumulative[static_cast<std::size_t>(i) + 1] =
        cumulative[static_cast<std::size_t>(i)] + integrate(density, a, a + width, 1e-14, 1);
  }
  const double total = cumulative.back();
  std::vector<double> edges{lo};
  std::size_t piece = 0;
  for (int k = 1; k < bins; ++k) {
    const double target = total * k / bins;
    while (piece + 1 < cumulative.size() - 1 && cumulative[piece + 1] < target) ++piece;
    const double inPiece = cumulative[piece + 1] - cumulative[piece];
    const double fraction = inPiece > 0 ? (target - cumulative[piece]) / inPiece : 0.0;
    const double edge = lo + width * (static_cast<double>(piece) + std::clamp(fraction, 0.0, 1.0));
    if (edge > edges.back() && edge < hi) edges.push_back(edge);
  }
  edges.push_back(hi);
  return edges;
}

/// `bins` + 1 equally spaced edges on [lo, hi].
inline std::vector<double> uniformEdges(double lo, double hi, int bins) {
  std::vector<double> edges;
  for (int i = 0; i <= bins; ++i) edges.push_back(i == bins ? hi : lo + (hi - lo) * i / bins);
  return edges;
}

namespace detail {
/// Index of the bin of `x` among `edges` (sorted), or edges.size() − 1 when outside.
inline std::size_t binIndex(const std::vector<double>& edges, double x) {
  if (!(x >= edges.front() && x <= edges.back())) return edges.size() - 1;
  const auto it = std::upper_bound(edges.begin(), edges.end(), x);
  const std::size_t index = static_cast<std::size_t>(it - edges.begin());
  return index == 0 ? 0 : std::min(index - 1, edges.size() - 2);
}
}  // namespace detail

/// 1-D test of `samples` against the normalised `density` on the bins `edges`.
template <class Density>
Chi2Result chi2Test1D(const std::vector<double>& samples, Density&& density,
                      const std::vector<double>& edges) {
  const std::size_t bins = edges.size() - 1;
  std::vector<double> observed(bins + 1, 0.0), expected(bins + 1, 0.0);  // last: outside
  for (const double x : samples) observed[detail::binIndex(edges, x)] += 1.0;
  const double n = static_cast<double>(samples.size());
  double inside = 0.0;
  for (std::size_t i = 0; i < bins; ++i) {
    const double probability = integrate(density, edges[i], edges[i + 1], 1e-13, 4);
    expected[i] = n * probability;
    inside += probability;
  }
  expected[bins] = n * std::max(0.0, 1.0 - inside);
  return chi2FromCounts(observed, expected);
}

/// 2-D test of the pairs (xs[i], ys[i]) against the normalised joint `density`(x, y) on the grid
/// xEdges × yEdges.
template <class Density>
Chi2Result chi2Test2D(const std::vector<double>& xs, const std::vector<double>& ys,
                      Density&& density, const std::vector<double>& xEdges,
                      const std::vector<double>& yEdges) {
  const std::size_t nx = xEdges.size() - 1, ny = yEdges.size() - 1;
  std::vector<double> observed(nx * ny + 1, 0.0), expected(nx * ny + 1, 0.0);
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const std::size_t i = detail::binIndex(xEdges, xs[k]), j = detail::binIndex(yEdges, ys[k]);
    observed[(i < nx && j < ny) ? i * ny + j : nx * ny] += 1.0;
  }
  const double n = static_cast<double>(xs.size());
  double inside = 0.0;
  for (std::size_t i = 0; i < nx; ++i) {
    for (std::size_t j = 0; j < ny; ++j) {
      const auto overY = [&](double x) {
        return integrate([&](double y) { return density(x, y); }, yEdges[j], yEdges[j + 1], 1e-11,
                         2);
      };
      const double probability = integrate(overY, xEdges[i], xEdges[i + 1], 1e-10, 2);
      expected[i * ny + j] = n * probability;
      inside += probability;
    }
  }
  expected[nx * ny] = n * std::max(0.0, 1.0 - inside);
  return chi2FromCounts(observed, expected);
}

/// Success when the test found no impossible sample and p > significance (default 1 %).
inline ::testing::AssertionResult chi2Accepts(const Chi2Result& r, double significance = 0.01) {
  std::ostringstream text;
  text << "chi2 = " << r.statistic << ", dof = " << r.degreesOfFreedom << ", p = " << r.pValue
       << ", n = " << r.samples << "; largest contributions " << r.worstCells;
  if (!r.problem.empty()) return ::testing::AssertionFailure() << r.problem << text.str();
  if (!(r.pValue > significance)) {
    return ::testing::AssertionFailure() << "p <= " << significance << ": " << text.str();
  }
  return ::testing::AssertionSuccess() << text.str();
}

}  // namespace hylios::test
