// A mean of per-path scores corrected by a control variate of known mean (issue 11): the spectral
// walk's MIS ratio (skin/spectral_walk.h) has expectation exactly 1 for every wavelength, and its
// fluctuation is most of a bundle member's extra variance, so each scalar tally subtracts it:
//
//   T̂ = mean(T) − β·(mean(U) − 1),   β = Cov(T, U) / Var(U).
//
// | quantity | meaning                                                                 |
// |----------|-------------------------------------------------------------------------|
// | T        | a path's score for one quantity (reflectance, absorptance in a layer, …) |
// | U        | the path's control weight, E[U] = 1 exactly                              |
// | fold     | 0 or 1 (the path's parity): β of one fold corrects the other fold's sums |
//
// β is estimated from the paths, and a β estimated from the same paths it corrects would make T̂
// biased by O(1/N). Cross-fitting keeps it exact: fold 0's sums are corrected with fold 1's β and
// vice versa, and since the folds' paths are independent, E[β₁·(ΣU₀ − n₀)] = E[β₁]·0. The
// standard error is that of the two corrected sums with their β held fixed. Without a recorded
// fluctuation of U (every U equal, e.g. one-member bundles) β = 0 and T̂ is the plain mean.
// Sums merge in a fixed order (byte-identical results at any thread count).
#pragma once
#include <array>
#include <cstdint>
#include <string>

#include "skin/core/statistics.h"

namespace hylios::skin {

class ControlledMean {
 public:
  /// Records one path's score `t` with control weight `u` into fold `fold` (0 or 1).
  void add(double t, double u, unsigned fold);
  void merge(const ControlledMean& other);
  std::uint64_t count() const { return folds_[0].n + folds_[1].n; }
  /// T̂ with its standard error (mean 0, error 0 without paths; plain mean of T when a fold is
  /// empty or U does not vary in it).
  Estimate estimate() const;
  /// β of `fold` (0 where U does not vary in it).
  double beta(unsigned fold) const;

  /// Appends the exact state (native byte order) for another process (app/mpi_session.h).
  void appendBytes(std::string& bytes) const;
  /// The state appendBytes wrote at `offset` (moved past it). Throws std::invalid_argument when
  /// the bytes end early.
  static ControlledMean fromBytes(const std::string& bytes, std::size_t& offset);

 private:
  struct Fold {
    std::uint64_t n = 0;
    double t = 0, tt = 0, u = 0, uu = 0, tu = 0;  ///< sums of T, T², U, U², T·U
  };
  std::array<Fold, 2> folds_{};
};

}  // namespace hylios::skin
