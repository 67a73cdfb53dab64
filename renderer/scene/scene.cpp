#include "renderer/scene/scene.h"

#include <cmath>

namespace hylios {

std::vector<double> BandDesc::channelWavelengths() const {
  if (!isRange()) return {minNm};
  std::vector<double> wavelengths;
  const auto count = static_cast<long>(std::floor((maxNm - minNm) / stepNm + 1e-9)) + 1;
  for (long i = 0; i < count; ++i) wavelengths.push_back(minNm + static_cast<double>(i) * stepNm);
  return wavelengths;
}

}  // namespace hylios
