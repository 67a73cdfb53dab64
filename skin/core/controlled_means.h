// Means of per-path scores corrected by a control variate of known mean (issue 11): the spectral
// walk's MIS ratio (skin/spectral_walk.h) has expectation exactly 1 for every wavelength, and its
// fluctuation is most of a bundle member's extra variance, so each scalar tally subtracts it:
//
//   T̂_k = mean(T_k) − β_k·(mean(U) − 1),   β_k = Cov(T_k, U) / Var(U).
//
// | quantity | meaning                                                                   |
// |----------|---------------------------------------------------------------------------|
// | T_k      | a path's score for quantity k (reflectance, absorptance in a layer, …)     |
// | U        | the path's control weight, E[U] = 1 exactly, shared by its quantities      |
// | fold     | 0 or 1 (the path's parity): β of one fold corrects the other fold's sums   |
//
// β is estimated from the paths, and a β estimated from the same paths it corrects would make T̂
// biased by O(1/N). Cross-fitting keeps it exact: fold 0's sums are corrected with fold 1's β and
// vice versa, and since the folds' paths are independent, E[β₁·(ΣU₀ − n₀)] = E[β₁]·0. The
// standard error is that of the two corrected sums with their β held fixed. Where U does not vary
// (e.g. one-member bundles) β = 0 and T̂ is the plain mean. Sums merge in a fixed order
// (byte-identical results at any thread count).
#pragma once
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "skin/core/statistics.h"

namespace hylios::skin {

class ControlledMeans {
 public:
  explicit ControlledMeans(std::size_t quantities = 1) : sums_(2 * quantities) {}

  std::size_t quantities() const { return sums_.size() / 2; }
  /// Records one path: its scores t[0 .. quantities()) with control weight `u`, in fold 0 or 1.
  void add(const double* t, double u, unsigned fold) {
    if (fold > 1) throw std::invalid_argument("ControlledMeans::add: fold " + std::to_string(fold));
    Control& c = control_[fold];
    ++c.n;
    c.u += u;
    c.uu += u * u;
    for (std::size_t k = 0; k < quantities(); ++k) {
      if (t[k] == 0) continue;  // adds nothing to the sums
      Sums& s = sums_[2 * k + fold];
      s.t += t[k];
      s.tt += t[k] * t[k];
      s.tu += t[k] * u;
    }
  }
  /// The same quantities of other paths (std::invalid_argument for another quantity count).
  void merge(const ControlledMeans& other);
  std::uint64_t count() const { return control_[0].n + control_[1].n; }
  /// T̂_k with its standard error (0 ± 0 without paths).
  Estimate estimate(std::size_t k) const;
  /// β_k of `fold` (0 where U does not vary in it or it holds fewer than two paths).
  double beta(std::size_t k, unsigned fold) const;

  /// Appends the exact state (native byte order) for another process (app/mpi_session.h).
  void appendBytes(std::string& bytes) const;
  /// The state appendBytes wrote at `offset` (moved past it) for `quantities` quantities. Throws
  /// std::invalid_argument when the bytes end early.
  static ControlledMeans fromBytes(std::size_t quantities, const std::string& bytes,
                                   std::size_t& offset);

 private:
  friend class ControlledMeansArray;  // fills the sums of many members at once
  struct Control {
    std::uint64_t n = 0;
    double u = 0, uu = 0;  ///< sums of U, U²
  };
  struct Sums {
    double t = 0, tt = 0, tu = 0;  ///< sums of T, T², T·U
  };
  Control control_[2];
  std::vector<Sums> sums_;  ///< quantity k, fold f at 2k + f
};

}  // namespace hylios::skin
