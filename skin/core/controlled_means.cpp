#include "skin/core/controlled_means.h"

#include <cmath>

#include "skin/core/state_bytes.h"

namespace hylios::skin {
namespace {

/// Below this sample variance of U (per path) the control weight is taken as constant: its
/// rounding (U = (1 − F) + F) is ~1e-16 and must not become a β.
constexpr double kConstantControlVariance = 1e-24;

constexpr const char* kReader = "ControlledMeans::fromBytes";

struct Moments {
  double varT, varU, cov;
};

template <class Control, class Sums>
Moments momentsOf(const Control& c, const Sums& s) {
  const double n = static_cast<double>(c.n);
  const double mt = s.t / n, mu = c.u / n;
  return {std::fmax(0.0, s.tt / n - mt * mt), std::fmax(0.0, c.uu / n - mu * mu),
          s.tu / n - mt * mu};
}

}  // namespace

void ControlledMeans::merge(const ControlledMeans& other) {
  if (other.quantities() != quantities())
    throw std::invalid_argument("ControlledMeans::merge: " + std::to_string(other.quantities()) +
                                " quantities into " + std::to_string(quantities()));
  for (unsigned f = 0; f < 2; ++f) {
    control_[f].n += other.control_[f].n;
    control_[f].u += other.control_[f].u;
    control_[f].uu += other.control_[f].uu;
  }
  for (std::size_t i = 0; i < sums_.size(); ++i) {
    sums_[i].t += other.sums_[i].t;
    sums_[i].tt += other.sums_[i].tt;
    sums_[i].tu += other.sums_[i].tu;
  }
}

double ControlledMeans::beta(std::size_t k, unsigned fold) const {
  const Control& c = control_[fold];
  if (c.n < 2) return 0.0;
  const Moments m = momentsOf(c, sums_.at(2 * k + fold));
  return m.varU > kConstantControlVariance ? m.cov / m.varU : 0.0;
}

Estimate ControlledMeans::estimate(std::size_t k) const {
  const std::uint64_t total = count();
  if (total == 0) return {};
  const bool bothFolds = control_[0].n >= 2 && control_[1].n >= 2;
  double sum = 0, variance = 0;  // the corrected sums, and Σ over folds of n·Var per path
  for (unsigned f = 0; f < 2; ++f) {
    const Control& c = control_[f];
    if (c.n == 0) continue;
    const Sums& s = sums_.at(2 * k + f);
    const double b = bothFolds ? beta(k, 1 - f) : 0.0;  // the other fold's β
    sum += s.t - b * (c.u - static_cast<double>(c.n));
    const Moments m = momentsOf(c, s);
    variance += static_cast<double>(c.n) * (m.varT - 2 * b * m.cov + b * b * m.varU);
  }
  const double n = static_cast<double>(total);
  const double error = total < 2 ? 0.0 : std::sqrt(std::fmax(0.0, variance) / (n * (n - 1.0)));
  return {sum / n, error};
}

void ControlledMeans::appendBytes(std::string& bytes) const {
  for (const Control& c : control_) {
    putBytes(bytes, c.n);
    putBytes(bytes, c.u);
    putBytes(bytes, c.uu);
  }
  for (const Sums& s : sums_) {
    putBytes(bytes, s.t);
    putBytes(bytes, s.tt);
    putBytes(bytes, s.tu);
  }
}

ControlledMeans ControlledMeans::fromBytes(std::size_t quantities, const std::string& bytes,
                                           std::size_t& offset) {
  ControlledMeans c(quantities);
  for (Control& control : c.control_) {
    control.n = takeBytes<std::uint64_t>(bytes, offset, kReader);
    control.u = takeBytes<double>(bytes, offset, kReader);
    control.uu = takeBytes<double>(bytes, offset, kReader);
  }
  for (Sums& s : c.sums_) {
    s.t = takeBytes<double>(bytes, offset, kReader);
    s.tt = takeBytes<double>(bytes, offset, kReader);
    s.tu = takeBytes<double>(bytes, offset, kReader);
  }
  return c;
}

}  // namespace hylios::skin
