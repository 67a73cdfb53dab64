#include "skin/surface_index_groups.h"

#include <algorithm>
#include <array>

#include "skin/spectral_weights.h"

namespace hylios::skin {

SurfaceIndexGroups::SurfaceIndexGroups(const std::vector<double>& indexPerMember)
    : memberIndex_(indexPerMember) {
  for (const double n : indexPerMember) {
    memberInverseIndex_.push_back(1.0 / n);
    const auto found = std::find(index_.begin(), index_.end(), n);
    groupOfMember_.push_back(static_cast<std::uint32_t>(found - index_.begin()));
    if (found == index_.end()) {
      index_.push_back(n);
      inverseIndex_.push_back(1.0 / n);
    }
  }
}

// Each grouped form runs the kernel on zeroed group values, then adds (or copies) them to the
// members. The kernels add one term per member (x + term, or −∞ where the term does not exist), and
// 0 + term = term exactly, so members get the bits of the kernel run on them.

void SurfaceIndexGroups::reflectances(double cosI, bool fromInside, double* out) const {
  if (!grouped()) {
    spectral_weights::reflectances(memberCount(), cosI, memberIndex_.data(), fromInside, out);
    return;
  }
  std::array<double, kMaxGroups> perGroup;
  spectral_weights::reflectances(groupCount(), cosI, index_.data(), fromInside, perGroup.data());
  for (std::size_t i = 0; i < memberCount(); ++i) out[i] = perGroup[groupOfMember_[i]];
}

void SurfaceIndexGroups::addLogReflectances(double cosI, bool fromInside,
                                            double* logDensity) const {
  if (!grouped()) {
    spectral_weights::addLogReflectances(memberCount(), cosI, memberIndex_.data(), fromInside,
                                         logDensity);
    return;
  }
  std::array<double, kMaxGroups> perGroup{};
  spectral_weights::addLogReflectances(groupCount(), cosI, index_.data(), fromInside,
                                       perGroup.data());
  for (std::size_t i = 0; i < memberCount(); ++i) logDensity[i] += perGroup[groupOfMember_[i]];
}

void SurfaceIndexGroups::addRefractionDensities(const Vec3& d, const Vec3& t, const Vec3& macro,
                                                bool fromInside, double aspectSquared, bool forced,
                                                double* logDensity, double* proposalOffset) const {
  if (!grouped()) {
    spectral_weights::addRefractionDensities(memberCount(), d, t, macro, memberIndex_.data(),
                                             memberInverseIndex_.data(), fromInside, aspectSquared,
                                             forced, logDensity, proposalOffset);
    return;
  }
  std::array<double, kMaxGroups> logPerGroup{}, offsetPerGroup{};
  spectral_weights::addRefractionDensities(groupCount(), d, t, macro, index_.data(),
                                           inverseIndex_.data(), fromInside, aspectSquared, forced,
                                           logPerGroup.data(), offsetPerGroup.data());
  // A missing facet is −∞ in the group, and x + (−∞) = −∞ as the kernel assigns it.
  for (std::size_t i = 0; i < memberCount(); ++i) logDensity[i] += logPerGroup[groupOfMember_[i]];
  if (forced)  // the kernel subtracts log(1 − F): y + (0 − l) = y − l
    for (std::size_t i = 0; i < memberCount(); ++i)
      proposalOffset[i] += offsetPerGroup[groupOfMember_[i]];
}

}  // namespace hylios::skin
