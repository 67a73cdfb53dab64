// Mathematical constants, defined once for every library (skin, renderer, app) and the tests.
#pragma once

namespace hylios {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2 * kPi;  // exact: doubling a double does not round

}  // namespace hylios
