#include "python/argument_checks.h"

#include <stdexcept>

namespace hylios::python {

void requireAngle(double angleDeg) {
  if (!(angleDeg >= 0 && angleDeg < 90))
    throw std::invalid_argument("angle_deg must lie in [0, 90)");
}

void requireRays(std::uint64_t rays) {
  if (rays < 1 || rays > kMaxRays) throw std::invalid_argument("rays must lie in [1, 2^40]");
}

void requireThreads(int threads) {
  if (threads < 0) throw std::invalid_argument("threads must be 0 (all cores) or positive");
}

void requireEpsilon(double epsilon) {
  if (!(epsilon >= 0 && epsilon <= 1)) throw std::invalid_argument("epsilon must lie in [0, 1]");
}

skin::Estimator estimatorNamed(const std::string& estimator) {
  return parseEnum(estimator, skin::kEstimatorNames, "estimator");
}

skin::SkinMode skinModeNamed(const std::string& skinModel) {
  return parseEnum(skinModel, skin::kSkinModeNames, "skin_model");
}

}  // namespace hylios::python
