// Mean polar scattering angle θo of melanosomes and melanosome complexes (paper Sec. 4.2.2,
// Algorithm 2): 5° [Lat84] up to 780 nm, reduced linearly to 0 over the near IR, reaching 0 at
// 1400 nm (the paper: "from 780 nm to 1400 nm ... we linearly reduce θo to 0 over this region"),
// and 0 beyond. θo = 0 means the melanosome leaves the direction unchanged.
#pragma once

namespace hylios::skin {

inline constexpr double kMelanosomeMeanScatteringAngleDeg = 5.0;
inline constexpr double kMelanosomeAngleFalloffStartNm = 780.0;
inline constexpr double kMelanosomeAngleFalloffEndNm = 1400.0;

/// θo(λ) in radians for a wavelength in nm; throws std::invalid_argument if λ is not finite
/// and positive.
double melanosomeMeanScatteringAngleRad(double wavelengthNm);

}  // namespace hylios::skin
