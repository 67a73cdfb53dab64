#include "skin/layer_refractive_index.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace hylios::skin {

double dispersedRefractiveIndex(double indexAtReference, double waterIndexAtWavelength,
                                double waterIndexAtReference) {
  for (double v : {indexAtReference, waterIndexAtWavelength, waterIndexAtReference})
    if (!std::isfinite(v) || !(v > 0))
      throw std::invalid_argument("dispersedRefractiveIndex: index " + std::to_string(v) +
                                  " is not positive and finite");
  return indexAtReference * waterIndexAtWavelength / waterIndexAtReference;
}

}  // namespace hylios::skin
