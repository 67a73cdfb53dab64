// Colour tables: hand values from CIE 015:2018 (CMFs, D65), the D65 white point, the sRGB matrix of
// IEC 61966-2-1, the sRGB transfer function and the colour map's endpoints.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <thread>
#include <vector>

#include "renderer/image/colour_tables.h"

namespace {

using hylios::cie1931;
using hylios::d65;

TEST(ColourTables, Cie1931HandValues) {
  EXPECT_DOUBLE_EQ(cie1931(555)[1], 1.0);         // ȳ peaks at 555 nm
  EXPECT_NEAR(cie1931(600)[0], 1.0622, 1e-9);     // x̄(600)
  EXPECT_NEAR(cie1931(450)[2], 1.77211, 1e-9);    // z̄(450)
  EXPECT_NEAR(cie1931(380)[0], 0.001368, 1e-12);  // x̄(380)
  EXPECT_NEAR(cie1931(360)[2], 0.0006061, 1e-12);
  EXPECT_NEAR(cie1931(830)[1], 4.5181e-7, 1e-15);
}

TEST(ColourTables, Cie1931InterpolatesLinearlyAndVanishesOutside) {
  // Halfway between the 1 nm rows 555 (x̄ 0.5120501) and 556 (x̄ 0.5282959).
  EXPECT_NEAR(cie1931(555.5)[0], 0.5 * (0.5120501 + 0.5282959), 1e-12);
  EXPECT_EQ(cie1931(359.9)[0], 0.0);
  EXPECT_EQ(cie1931(830.1)[1], 0.0);
  EXPECT_EQ(cie1931(2000)[2], 0.0);
  EXPECT_THROW(cie1931(std::nan("")), std::invalid_argument);
}

TEST(ColourTables, D65HandValuesAndRange) {
  EXPECT_DOUBLE_EQ(d65(560), 100.0);
  EXPECT_NEAR(d65(300), 0.0341, 1e-12);
  EXPECT_NEAR(d65(830), 60.3125, 1e-12);
  EXPECT_NEAR(d65(302.5), 0.5 * (0.0341 + 1.6643), 1e-12);  // linear between 5 nm rows
  EXPECT_NEAR(d65(301), 0.36014, 1e-9);  // CIE's 1 nm table value, also linear in the 5 nm one
  EXPECT_THROW(d65(299.9), std::out_of_range);
  EXPECT_THROW(d65(830.1), std::out_of_range);
  EXPECT_THROW(d65(std::nan("")), std::out_of_range);
}

/// X, Y, Z of D65 with the 1 nm CMF table (Riemann sum, Δλ = 1 nm), relative units.
std::array<double, 3> d65Tristimulus() {
  std::array<double, 3> xyz{0, 0, 0};
  for (int nm = 360; nm <= 830; ++nm) {
    const auto cmf = cie1931(nm);
    for (int i = 0; i < 3; ++i) xyz[i] += d65(nm) * cmf[i];
  }
  return xyz;
}

TEST(ColourTables, D65WhitePointMatchesCie) {
  // CIE 015:2018 Table 11: D65 (2°) X = 95.047, Y = 100, Z = 108.883 (1 nm summation).
  const auto xyz = d65Tristimulus();
  EXPECT_NEAR(100.0 * xyz[0] / xyz[1], 95.047, 2e-3);
  EXPECT_NEAR(100.0 * xyz[2] / xyz[1], 108.883, 2e-3);
}

TEST(ColourTables, SrgbMatrixMatchesIec61966) {
  // IEC 61966-2-1 XYZ → linear sRGB, rounded to four decimals there.
  const auto r = hylios::xyzToLinearSrgb({1, 0, 0});
  const auto g = hylios::xyzToLinearSrgb({0, 1, 0});
  const auto b = hylios::xyzToLinearSrgb({0, 0, 1});
  EXPECT_NEAR(r[0], 3.2406, 1e-3);
  EXPECT_NEAR(g[0], -1.5372, 1e-3);
  EXPECT_NEAR(b[0], -0.4986, 1e-3);
  EXPECT_NEAR(r[1], -0.9689, 1e-3);
  EXPECT_NEAR(g[1], 1.8758, 1e-3);
  EXPECT_NEAR(b[1], 0.0415, 1e-3);
  EXPECT_NEAR(r[2], 0.0557, 1e-3);
  EXPECT_NEAR(g[2], -0.2040, 1e-3);
  EXPECT_NEAR(b[2], 1.0570, 1e-3);
}

TEST(ColourTables, NormalisedD65IsSrgbWhite) {
  // k = 1 / Σ D65·ȳ·Δλ makes Y = 1; the chromaticity of D65 then maps to R = G = B = 1.
  auto xyz = d65Tristimulus();
  const double k = 1.0 / xyz[1];
  for (double& v : xyz) v *= k;
  const auto rgb = hylios::xyzToLinearSrgb(xyz);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(rgb[i], 1.0, 1e-2) << "channel " << i;
}

TEST(ColourTables, SrgbTransferFunction) {
  EXPECT_DOUBLE_EQ(hylios::srgbEncode(0.0), 0.0);
  EXPECT_NEAR(hylios::srgbEncode(1.0), 1.0, 1e-12);
  EXPECT_NEAR(hylios::srgbEncode(0.002), 12.92 * 0.002, 1e-12);  // linear toe
  EXPECT_NEAR(hylios::srgbEncode(0.5), 0.735357, 1e-6);          // 1.055·0.5^(1/2.4) − 0.055
  EXPECT_DOUBLE_EQ(hylios::srgbEncode(3.0), 1.0);                // clamped for display
  EXPECT_DOUBLE_EQ(hylios::srgbEncode(-0.2), 0.0);
  EXPECT_THROW(hylios::srgbEncode(std::nan("")), std::invalid_argument);
}

TEST(ColourTables, ColourMapEndpointsAndMiddle) {
  const auto low = hylios::colourMap(0.0), high = hylios::colourMap(1.0);
  EXPECT_NEAR(low[0], 0.001462, 1e-12);  // magma entry 0
  EXPECT_NEAR(low[1], 0.000466, 1e-12);
  EXPECT_NEAR(low[2], 0.013866, 1e-12);
  EXPECT_NEAR(high[0], 0.987053, 1e-12);  // magma entry 255
  EXPECT_NEAR(high[1], 0.991438, 1e-12);
  EXPECT_NEAR(high[2], 0.749504, 1e-12);
  const auto middle = hylios::colourMap(0.5);  // halfway between entries 127 and 128
  EXPECT_NEAR(middle[0], 0.5 * (0.709962 + 0.716387), 1e-12);
  EXPECT_NEAR(middle[1], 0.5 * (0.212797 + 0.214982), 1e-12);
  EXPECT_NEAR(middle[2], 0.5 * (0.477201 + 0.475290), 1e-12);
  EXPECT_EQ(hylios::colourMap(-3.0), low);
  EXPECT_EQ(hylios::colourMap(7.0), high);
  EXPECT_THROW(hylios::colourMap(std::nan("")), std::invalid_argument);
}

TEST(ColourTables, ColourMapLightnessIncreases) {
  // A perceptual sequential map: relative luminance rises monotonically from 0 to 1.
  double previous = -1;
  for (int i = 0; i <= 255; ++i) {
    const auto c = hylios::colourMap(i / 255.0);
    const double luminance = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    EXPECT_GT(luminance, previous) << "entry " << i;
    previous = luminance;
  }
}

TEST(ColourTables, ConcurrentFirstUseSeesOneTable) {
  // Run alone (ctest runs each test in its own process) this is the tables' first use.
  std::vector<double> seen(8, 0.0);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < seen.size(); ++t)
    threads.emplace_back(
        [&seen, t] { seen[t] = cie1931(555)[1] + d65(560) + hylios::colourMap(1)[0]; });
  for (auto& thread : threads) thread.join();
  for (const double v : seen) EXPECT_DOUBLE_EQ(v, 1.0 + 100.0 + 0.987053);
}

}  // namespace
