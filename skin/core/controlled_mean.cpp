#include "skin/core/controlled_mean.h"

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace hylios::skin {
namespace {

/// Below this sample variance of U (per path) the control weight is taken as constant: its
/// rounding (U = (1 − F) + F) is ~1e-16 and must not become a β.
constexpr double kConstantControlVariance = 1e-24;

struct Moments {
  double meanT, meanU, varT, varU, cov;
};

template <class Fold>
Moments momentsOf(const Fold& f) {
  const double n = static_cast<double>(f.n);
  const double mt = f.t / n, mu = f.u / n;
  return {mt, mu, std::fmax(0.0, f.tt / n - mt * mt), std::fmax(0.0, f.uu / n - mu * mu),
          f.tu / n - mt * mu};
}

}  // namespace

void ControlledMean::add(double t, double u, unsigned fold) {
  if (fold > 1) throw std::invalid_argument("ControlledMean::add: fold " + std::to_string(fold));
  Fold& f = folds_[fold];
  ++f.n;
  f.t += t;
  f.tt += t * t;
  f.u += u;
  f.uu += u * u;
  f.tu += t * u;
}

void ControlledMean::merge(const ControlledMean& other) {
  for (unsigned k = 0; k < 2; ++k) {
    Fold& f = folds_[k];
    const Fold& o = other.folds_[k];
    f.n += o.n;
    f.t += o.t;
    f.tt += o.tt;
    f.u += o.u;
    f.uu += o.uu;
    f.tu += o.tu;
  }
}

double ControlledMean::beta(unsigned fold) const {
  const Fold& f = folds_.at(fold);
  if (f.n < 2) return 0.0;
  const Moments m = momentsOf(f);
  return m.varU > kConstantControlVariance ? m.cov / m.varU : 0.0;
}

Estimate ControlledMean::estimate() const {
  const std::uint64_t total = count();
  if (total == 0) return {};
  const bool bothFolds = folds_[0].n >= 2 && folds_[1].n >= 2;
  double sum = 0, variance = 0;  // Σ over folds of the corrected sums, and of n·Var per path
  for (unsigned k = 0; k < 2; ++k) {
    const Fold& f = folds_[k];
    if (f.n == 0) continue;
    const double b = bothFolds ? beta(1 - k) : 0.0;  // the other fold's β (Eq. above)
    sum += f.t - b * (f.u - static_cast<double>(f.n));
    const Moments m = momentsOf(f);
    variance += static_cast<double>(f.n) * (m.varT - 2 * b * m.cov + b * b * m.varU);
  }
  const double n = static_cast<double>(total);
  const double error = total < 2 ? 0.0 : std::sqrt(std::fmax(0.0, variance) / (n * (n - 1.0)));
  return {sum / n, error};
}

void ControlledMean::appendBytes(std::string& bytes) const {
  for (const Fold& f : folds_) {
    bytes.append(reinterpret_cast<const char*>(&f.n), sizeof f.n);
    for (double v : {f.t, f.tt, f.u, f.uu, f.tu})
      bytes.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
}

ControlledMean ControlledMean::fromBytes(const std::string& bytes, std::size_t& offset) {
  constexpr std::size_t kFoldBytes = sizeof(std::uint64_t) + 5 * sizeof(double);
  if (offset > bytes.size() || bytes.size() - offset < 2 * kFoldBytes)
    throw std::invalid_argument("ControlledMean::fromBytes: the state ends early (byte " +
                                std::to_string(offset) + " of " + std::to_string(bytes.size()) +
                                ")");
  ControlledMean c;
  for (Fold& f : c.folds_) {
    std::memcpy(&f.n, bytes.data() + offset, sizeof f.n);
    offset += sizeof f.n;
    for (double* v : {&f.t, &f.tt, &f.u, &f.uu, &f.tu}) {
      std::memcpy(v, bytes.data() + offset, sizeof *v);
      offset += sizeof *v;
    }
  }
  return c;
}

}  // namespace hylios::skin
