#include "skin/core/controlled_means_array.h"

#include <stdexcept>
#include <string>

#include "skin/core/vector_clones.h"

namespace hylios::skin {
namespace {
/// The sums' places: the control's two, then three per quantity.
constexpr std::size_t kU = 0, kUU = 1, kFirstQuantity = 2;
}  // namespace

ControlledMeansArray::ControlledMeansArray(std::size_t members, std::size_t quantities)
    : members_(members),
      quantities_(quantities),
      sums_((kFirstQuantity + 3 * quantities) * 2 * members, 0.0) {}

HYLIOS_VECTOR_CLONES
void ControlledMeansArray::beginPath(const double* u, unsigned fold) {
  if (fold > 1)
    throw std::invalid_argument("ControlledMeansArray::beginPath: fold " + std::to_string(fold));
  ++count_[fold];
  u_ = u;
  fold_ = fold;
  double* __restrict su = sumsOf(kU, fold);
  double* __restrict suu = sumsOf(kUU, fold);
  for (std::size_t i = 0; i < members_; ++i) {
    su[i] += u[i];
    suu[i] += u[i] * u[i];
  }
}

HYLIOS_VECTOR_CLONES
void ControlledMeansArray::add(std::size_t k, const double* t) {
  if (!u_) throw std::logic_error("ControlledMeansArray::add before beginPath");
  if (k >= quantities_)
    throw std::invalid_argument("ControlledMeansArray::add: quantity " + std::to_string(k) +
                                " of " + std::to_string(quantities_));
  const std::size_t first = kFirstQuantity + 3 * k;
  double* __restrict st = sumsOf(first, fold_);
  double* __restrict stt = sumsOf(first + 1, fold_);
  double* __restrict stu = sumsOf(first + 2, fold_);
  const double* __restrict u = u_;
  for (std::size_t i = 0; i < members_; ++i) {
    st[i] += t[i];
    stt[i] += t[i] * t[i];
    stu[i] += t[i] * u[i];
  }
}

ControlledMeans ControlledMeansArray::member(std::size_t i) const {
  if (i >= members_)
    throw std::invalid_argument("ControlledMeansArray::member " + std::to_string(i) + " of " +
                                std::to_string(members_));
  ControlledMeans means(quantities_);
  for (unsigned f = 0; f < 2; ++f) {
    means.control_[f] = {count_[f], sumsOf(kU, f)[i], sumsOf(kUU, f)[i]};
    for (std::size_t k = 0; k < quantities_; ++k) {
      const std::size_t first = kFirstQuantity + 3 * k;
      means.sums_[2 * k + f] = {sumsOf(first, f)[i], sumsOf(first + 1, f)[i],
                                sumsOf(first + 2, f)[i]};
    }
  }
  return means;
}

}  // namespace hylios::skin
