#include "skin/sampling/exponential_ziggurat.h"

namespace hylios::skin {

ExponentialZiggurat::ExponentialZiggurat() {
  // x_{i+1} from layer i's area: x_i·(e^{−x_{i+1}} − e^{−x_i}) = v.
  width[0] = kLayerArea / std::exp(-kTailStart);
  width[1] = kTailStart;
  for (int i = 1; i < kLayers - 1; ++i)
    width[i + 1] = -std::log(kLayerArea / width[i] + std::exp(-width[i]));
  width[kLayers] = 0;  // the recursion ends at 0 to rounding (the top layer's area v to 1e−13)
  for (int i = 0; i <= kLayers; ++i) height[i] = std::exp(-width[i]);
}

const ExponentialZiggurat kExponentialZiggurat;

}  // namespace hylios::skin
