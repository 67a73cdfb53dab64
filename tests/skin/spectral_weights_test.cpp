// The spectral walk's vectorised Fresnel kernels (skin/spectral_weights.h) against skin::fresnel,
// whose branches they replace with selects: the same reflectance, to the bit as the header says,
// from the air and from inside, at normal, oblique and grazing incidence, beyond the critical
// angle and for matched indices; the log kernel adds vectorLog of the same values (≤ 2 ulp).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "skin/fresnel.h"
#include "skin/spectral_weights.h"

using namespace hylios::skin;

TEST(SpectralWeights, ReflectancesAreFresnelsBits) {
  const std::vector<double> index{1.0, 1.33, 1.4, 1.55, 1.64, 2.5};
  std::vector<double> out(index.size()), logs(index.size());
  for (const bool fromInside : {false, true})
    for (const double cosI : {1.0, 0.9, 0.5, 0.2, 0.05, 1e-6, 0.0, -0.7}) {
      spectral_weights::reflectances(index.size(), cosI, index.data(), fromInside, out.data());
      std::fill(logs.begin(), logs.end(), 1.0);
      spectral_weights::addLogReflectances(index.size(), cosI, index.data(), fromInside,
                                           logs.data());
      for (std::size_t i = 0; i < index.size(); ++i) {
        const double n1 = fromInside ? index[i] : 1.0, n2 = fromInside ? 1.0 : index[i];
        const double expected = fresnel(cosI, n1, n2).reflectance;
        EXPECT_EQ(out[i], expected) << "cos " << cosI << ", n " << n1 << " → " << n2;
        if (expected > 0)
          EXPECT_NEAR(logs[i], 1.0 + std::log(expected),
                      4e-16 * std::fabs(std::log(expected)) + 1e-15)
              << "cos " << cosI << ", n " << n1 << " → " << n2;
        else
          EXPECT_EQ(logs[i], -INFINITY);
      }
    }
}
