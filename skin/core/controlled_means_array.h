// The sums of ControlledMeans (skin/core/controlled_means.h) for many members at once, e.g. every
// wavelength of a spectral bundle, laid out member by member in one array per sum, so that
// recording a path is a few loops over contiguous values that the compiler vectorises.
//
// | call                  | adds, for every member i                                          |
// |-----------------------|-------------------------------------------------------------------|
// | beginPath(u, fold)    | one path to `fold`: n, ΣU_i, ΣU_i² (U_i = u[i], the control)      |
// | add(k, t)             | quantity k of that path: ΣT_i, ΣT_i², ΣT_i·U_i (T_i = t[i])       |
//
// A quantity not added for a path scores 0 there, as ControlledMeans::add skips zeros. member(i)
// is exactly the ControlledMeans that adding member i's paths one by one would have made: every
// sum takes the same values in the same order (adding a score of 0 changes no sum's bits).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "skin/core/controlled_means.h"

namespace hylios::skin {

class ControlledMeansArray {
 public:
  ControlledMeansArray(std::size_t members, std::size_t quantities);

  std::size_t members() const { return members_; }
  std::size_t quantities() const { return quantities_; }
  /// Starts a path in fold 0 or 1 (std::invalid_argument otherwise) with control weights
  /// u[0 .. members()); `u` must stay valid until the next beginPath.
  void beginPath(const double* u, unsigned fold);
  /// Quantity k's scores t[0 .. members()) of the path begun last (std::logic_error before any).
  void add(std::size_t k, const double* t);
  /// Member i's sums as one ControlledMeans.
  ControlledMeans member(std::size_t i) const;

 private:
  /// One sum per member: sums_[(sum · 2 + fold) · members_ + i] (sum: see the k* offsets).
  double* sumsOf(std::size_t sum, unsigned fold) { return &sums_[(sum * 2 + fold) * members_]; }
  const double* sumsOf(std::size_t sum, unsigned fold) const {
    return &sums_[(sum * 2 + fold) * members_];
  }
  std::size_t members_, quantities_;
  std::uint64_t count_[2] = {0, 0};
  std::vector<double> sums_;  ///< ΣU, ΣU², then per quantity ΣT, ΣT², ΣT·U
  const double* u_ = nullptr;
  unsigned fold_ = 0;
};

}  // namespace hylios::skin
