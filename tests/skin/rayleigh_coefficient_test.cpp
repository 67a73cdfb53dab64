// Rayleigh coefficient of the papillary dermis (Eq. 4–5): hand values and the λ⁻⁴ law.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "skin/rayleigh_coefficient.h"

namespace hylios::skin {
namespace {

// Hand computation at λ = 500 nm with r = 100 nm = 1e-5 cm, η = 1.55/1.33, 0.22 of Eq. 5:
//   D = 0.22 / (4/3 π (1e-5)³) = 5.25211e13 cm⁻³
//   Eq. 4 with D substituted: μs = 32 π⁴ · 0.22 · r³ / λ⁴ · K²
//        = 32 · 97.40909 · 0.22 · 1e-15 / (5e-5)⁴ · K² = 1.097216e5 · K²
//   η² = 1.358189; paper K = 0.358189/2.358189 = 0.151891, K² = 0.0230711 -> μs = 2531.4 cm⁻¹
//   textbook K = 0.358189/3.358189 = 0.106661, K² = 0.0113766 -> μs = 1248.3 cm⁻¹
TEST(RayleighCoefficient, PaperFormAt500nmMatchesHandValue) {
  EXPECT_NEAR(rayleighNumberDensity_perCm3({}), 5.25211e13, 1e8);
  EXPECT_NEAR(rayleighPolarizabilityFactor({}), 0.151891, 1e-6);
  EXPECT_NEAR(rayleighScatteringCoefficient_perCm(500.0), 2531.4, 0.1);
}

TEST(RayleighCoefficient, TextbookFormAt500nmMatchesHandValue) {
  RayleighParameters textbook;
  textbook.form = RayleighPolarizabilityForm::Textbook;
  EXPECT_NEAR(rayleighPolarizabilityFactor(textbook), 0.106661, 1e-6);
  EXPECT_NEAR(rayleighScatteringCoefficient_perCm(500.0, textbook), 1248.3, 0.1);
}

TEST(RayleighCoefficient, FallsAsInverseFourthPowerOfWavelength) {
  const double at500 = rayleighScatteringCoefficient_perCm(500.0);
  EXPECT_NEAR(rayleighScatteringCoefficient_perCm(1000.0), at500 / 16.0, 1e-9 * at500);
  EXPECT_NEAR(rayleighScatteringCoefficient_perCm(250.0), at500 * 16.0, 1e-9 * at500 * 16);
  // Finite and positive over the whole 250–2500 nm range.
  for (double nm = 250; nm <= 2500; nm += 50) {
    const double mu = rayleighScatteringCoefficient_perCm(nm);
    EXPECT_TRUE(std::isfinite(mu) && mu > 0) << nm;
  }
}

TEST(RayleighCoefficient, ScalesWithRadiusCubedAtFixedVolumeFraction) {
  RayleighParameters doubled;
  doubled.radiusNm = 200.0;
  EXPECT_NEAR(rayleighScatteringCoefficient_perCm(500.0, doubled),
              8.0 * rayleighScatteringCoefficient_perCm(500.0), 1e-6);
}

TEST(RayleighCoefficient, RejectsBadInput) {
  EXPECT_THROW(rayleighScatteringCoefficient_perCm(0.0), std::invalid_argument);
  EXPECT_THROW(rayleighScatteringCoefficient_perCm(-500.0), std::invalid_argument);
  EXPECT_THROW(rayleighScatteringCoefficient_perCm(NAN), std::invalid_argument);
  RayleighParameters bad;
  bad.radiusNm = 0;
  EXPECT_THROW(rayleighScatteringCoefficient_perCm(500.0, bad), std::invalid_argument);
}

}  // namespace
}  // namespace hylios::skin
