#include "skin/exit_table_rays.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "skin/core/constants.h"

namespace hylios::skin {
namespace {

// Random streams of the use estimate, apart from the bins' (stream k < 4096) of the build.
constexpr std::uint64_t kUseStreamBase = 0x7573650000000000ULL;

}  // namespace

std::vector<double> worstCaseBinUse(const SkinWalk& walk, int cosineBins, std::uint64_t seed) {
  const auto bins = static_cast<std::size_t>(cosineBins);
  std::vector<std::vector<double>> useAtAngle(kUseAngles, std::vector<double>(bins, 0.0));
  tbb::parallel_for(0, kUseAngles, [&](int g) {
    const double theta = 0.5 * kPi * (g + 0.5) / kUseAngles;
    const Vec3 incident{std::sin(theta), 0, std::cos(theta)};
    std::vector<double>& use = useAtAngle[static_cast<std::size_t>(g)];
    int entered = 0;
    for (int i = 0; i < kUseEntriesPerAngle; ++i) {
      Rng rng(seed, kUseStreamBase + static_cast<std::uint64_t>(g), static_cast<std::uint64_t>(i));
      const InterfaceCrossing entry = walk.enterFromAir(incident, rng);
      if (!entry.transmitted) continue;
      ++entered;
      // ExitTable::chooseBin's linear interpolation between the centres (k + 1)/K, as weights.
      const double x = std::clamp(entry.direction.z, 0.0, 1.0) * cosineBins - 1;
      if (x >= cosineBins - 1) {
        use[bins - 1] += 1;
      } else if (!(x > 0)) {
        use[0] += 1;
      } else {
        const auto k = static_cast<std::size_t>(x);
        const double upper = x - static_cast<double>(k);
        use[k] += 1 - upper;
        use[k + 1] += upper;
      }
    }
    for (double& u : use) u = entered > 0 ? u / entered : 0.0;
  });
  std::vector<double> worst(bins, 0.0);
  for (const std::vector<double>& use : useAtAngle)
    for (std::size_t k = 0; k < bins; ++k) worst[k] = std::max(worst[k], use[k]);
  return worst;
}

std::vector<std::uint64_t> raysByUse(const std::vector<double>& worstUse,
                                     std::uint64_t raysPerBin) {
  std::vector<std::uint64_t> rays;
  for (double use : worstUse) {
    const double ratio = use / kFullUse;
    const double fraction = std::clamp(ratio * ratio, kLeastRaysFraction, 1.0);
    const double wanted = std::ceil(fraction * static_cast<double>(raysPerBin));
    rays.push_back(std::clamp(static_cast<std::uint64_t>(wanted), std::uint64_t{2}, raysPerBin));
  }
  return rays;
}

}  // namespace hylios::skin
