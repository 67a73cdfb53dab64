// Emission spectra: Planck (Wien peak, a hand-computed value), LED Gaussian (half maximum at
// centre ± FWHM/2), D65 (1 at 560 nm), tables (linear, refusing wavelengths outside).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "renderer/scene/emission_spectrum.h"

namespace hylios {
namespace {

EmissionDesc spectrum(EmissionDesc::Kind kind, double scale = 1) {
  EmissionDesc e;
  e.kind = kind;
  e.scale = scale;
  e.where = {"lights.toml", 7, 12};
  return e;
}

std::string errorOf(const EmissionDesc& e, double wavelengthNm) {
  try {
    evaluateEmission(e, wavelengthNm);
  } catch (const SceneError& error) {
    return error.what();
  }
  return "";
}

TEST(EmissionSpectrum, WienPeakOfTheSun) {
  // b / T = 2.897771955e6 nm·K / 5772 K = 502.0395 nm.
  EXPECT_NEAR(blackbodyPeakNm(5772), 502.0395, 1e-4);
}

TEST(EmissionSpectrum, BlackbodyIsOneAtItsPeakAndLowerAround) {
  for (double t : {1500.0, 2856.0, 6504.0}) {
    const double peak = blackbodyPeakNm(t);
    EXPECT_NEAR(normalisedBlackbody(t, peak), 1.0, 1e-12) << t;
    EXPECT_LT(normalisedBlackbody(t, peak * 0.99), 1.0) << t;
    EXPECT_LT(normalisedBlackbody(t, peak * 1.01), 1.0) << t;
  }
}

TEST(EmissionSpectrum, BlackbodyHandValue) {
  // 6000 K at 1000 nm: (482.962/1000)^5 · (e^4.965114 − 1)/(e^2.397961 − 1) = 0.3739505
  // (also from the full Planck law with h, c, k of CODATA 2018).
  EmissionDesc e = spectrum(EmissionDesc::Kind::Blackbody, 2.0);
  e.temperatureK = 6000;
  EXPECT_NEAR(evaluateEmission(e, 1000), 2.0 * 0.3739505, 2e-7);
}

TEST(EmissionSpectrum, BlackbodyFarBelowItsPeakIsZeroNotNaN) {
  // 100 K at 250 nm: the exponent c2/(λT) = 575 overflows exp; the value must be 0.
  const double v = normalisedBlackbody(100, 250);
  EXPECT_TRUE(std::isfinite(v));
  EXPECT_GE(v, 0.0);
  EXPECT_LT(v, 1e-200);
}

TEST(EmissionSpectrum, BlackbodyRefusesNonPositiveTemperature) {
  EmissionDesc e = spectrum(EmissionDesc::Kind::Blackbody);
  e.temperatureK = 0;
  EXPECT_EQ(errorOf(e, 500), "lights.toml:7:12: blackbody temperature 0 K must be > 0");
}

TEST(EmissionSpectrum, LedHalfMaximumAtCentrePlusMinusHalfWidth) {
  EmissionDesc e = spectrum(EmissionDesc::Kind::Led, 3.0);
  e.centreNm = 365;
  e.fwhmNm = 10;
  EXPECT_DOUBLE_EQ(evaluateEmission(e, 365), 3.0);
  EXPECT_NEAR(evaluateEmission(e, 360), 1.5, 1e-12);
  EXPECT_NEAR(evaluateEmission(e, 370), 1.5, 1e-12);
  // At centre ± FWHM: exp(−4 ln 2) = 1/16.
  EXPECT_NEAR(evaluateEmission(e, 375), 3.0 / 16, 1e-12);
}

TEST(EmissionSpectrum, ConstantIsItsScale) {
  const EmissionDesc e = spectrum(EmissionDesc::Kind::Constant, 0.25);
  EXPECT_EQ(evaluateEmission(e, 250), 0.25);
  EXPECT_EQ(evaluateEmission(e, 2500), 0.25);
}

TEST(EmissionSpectrum, D65IsOneAt560AndUndefinedInTheInfrared) {
  const EmissionDesc e = spectrum(EmissionDesc::Kind::D65, 2.0);
  EXPECT_NEAR(evaluateEmission(e, 560), 2.0, 1e-12);  // D65 is 100 at 560 nm by definition
  const std::string message = errorOf(e, 1650);
  EXPECT_EQ(message.rfind("lights.toml:7:12: D65 is not defined at 1650 nm", 0), 0u) << message;
}

TEST(EmissionSpectrum, TabulatedInterpolatesLinearly) {
  EmissionDesc e = spectrum(EmissionDesc::Kind::Tabulated, 2.0);
  e.tableWavelengthNm = {400, 500, 700};
  e.tableValue = {1.0, 3.0, 0.0};
  EXPECT_DOUBLE_EQ(evaluateEmission(e, 400), 2.0);
  EXPECT_DOUBLE_EQ(evaluateEmission(e, 450), 4.0);
  EXPECT_DOUBLE_EQ(evaluateEmission(e, 500), 6.0);
  EXPECT_DOUBLE_EQ(evaluateEmission(e, 650), 1.5);
  EXPECT_DOUBLE_EQ(evaluateEmission(e, 700), 0.0);
}

TEST(EmissionSpectrum, TabulatedRefusesWavelengthsOutsideTheTable) {
  EmissionDesc e = spectrum(EmissionDesc::Kind::Tabulated);
  e.tableWavelengthNm = {400, 700};
  e.tableValue = {1.0, 1.0};
  EXPECT_EQ(errorOf(e, 399.5),
            "lights.toml:7:12: tabulated spectrum covers 400–700 nm; 399.5 nm is outside it "
            "(no extrapolation)");
  EXPECT_NE(errorOf(e, 700.5), "");
}

TEST(EmissionSpectrum, RefusesNonFiniteWavelength) {
  const EmissionDesc e = spectrum(EmissionDesc::Kind::Constant);
  EXPECT_NE(errorOf(e, std::nan("")), "");
  EXPECT_NE(errorOf(e, -1), "");
}

}  // namespace
}  // namespace hylios
