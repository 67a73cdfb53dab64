// The distinct surface indices of a spectral bundle (skin/spectral_walk.h). The rough surface's
// per-wavelength terms (Fresnel reflectance, its log, the refraction density) depend on λ only
// through the top layer's index, and neighbouring wavelengths often share it: Hale & Querry's
// water index has three decimals, so Figure 1's 41 visible channels hold 28 indices. Each kernel
// of skin/spectral_weights.h runs once per distinct index and its values are spread to the members
// that share it, which gives every member the bits it would get alone (tested).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "skin/core/vector3.h"

namespace hylios::skin {

class SurfaceIndexGroups {
 public:
  /// Groups beyond which the kernels run per member instead (a stack scratch of this size).
  static constexpr std::size_t kMaxGroups = 64;

  SurfaceIndexGroups() = default;
  /// Groups equal values of indexPerMember (exact equality), in order of first appearance.
  explicit SurfaceIndexGroups(const std::vector<double>& indexPerMember);

  std::size_t memberCount() const { return groupOfMember_.size(); }
  std::size_t groupCount() const { return index_.size(); }
  std::size_t groupOf(std::size_t member) const { return groupOfMember_[member]; }

  /// out[i] = spectral_weights::reflectances' value for member i.
  void reflectances(double cosI, bool fromInside, double* out) const;
  /// logDensity[i] += log of member i's reflectance (spectral_weights::addLogReflectances).
  void addLogReflectances(double cosI, bool fromInside, double* logDensity) const;
  /// spectral_weights::addRefractionDensities for every member.
  void addRefractionDensities(const Vec3& d, const Vec3& t, const Vec3& macro, bool fromInside,
                              double aspectSquared, bool forced, double* logDensity,
                              double* proposalOffset) const;

 private:
  bool grouped() const { return groupCount() < memberCount() && groupCount() <= kMaxGroups; }

  std::vector<double> memberIndex_;         ///< per member (the kernels' input when not grouped)
  std::vector<double> memberInverseIndex_;  ///< per member: 1 / memberIndex_
  std::vector<double> index_;               ///< per group
  std::vector<double> inverseIndex_;        ///< per group: 1 / index_
  std::vector<std::uint32_t> groupOfMember_;
};

}  // namespace hylios::skin
