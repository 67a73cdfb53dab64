// Argument check shared by the samplers: a uniform random number must lie in [0, 1).
#pragma once
#include <stdexcept>
#include <string>

namespace hylios::skin {

/// Throws std::invalid_argument naming `where` unless 0 <= u < 1 (NaN fails too).
inline void requireUniformSample(double u, const char* where) {
  if (!(u >= 0.0 && u < 1.0)) {
    throw std::invalid_argument(std::string(where) + ": uniform sample u = " + std::to_string(u) +
                                " is outside [0, 1)");
  }
}

}  // namespace hylios::skin
