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

// ---- stayLosses and pathDepths against the products and sums they stand for ----

namespace {
struct ReferenceLosses {
  std::vector<double> transmitted, absorbed, inMelanin;  // absorbed and inMelanin: layer · n + i
};

// The definition stayLosses vectorises: stay by stay, T ← T·e^{−d}, the stay's loss
// roulette·T·(1 − e^{−d}) (as −expm1) booked in its layer, melanin's share by optical depth, every
// loss times the path's MIS ratio.
ReferenceLosses referenceLosses(std::size_t n, const std::vector<SpectralPath::Stay>& stays,
                                const std::vector<spectral_weights::SlabAbsorption>& slabs,
                                const std::vector<double>& melaninMuA,
                                const std::vector<double>& ratio) {
  ReferenceLosses r{std::vector<double>(n, 1.0), std::vector<double>(kLayerCount * n, 0.0),
                    std::vector<double>(kLayerCount * n, 0.0)};
  for (const SpectralPath::Stay& stay : stays) {
    const spectral_weights::SlabAbsorption& slab = slabs[stay.slab];
    for (std::size_t i = 0; i < n; ++i) {
      const double melaninDepth = melaninMuA[i] * stay.melaninCm;
      const double d = slab.muA_perCm[i] * stay.cm + melaninDepth;
      const double lost = stay.roulette * r.transmitted[i] * -std::expm1(-d) * ratio[i];
      r.absorbed[slab.layer * n + i] += lost;
      if (d > 0) r.inMelanin[slab.layer * n + i] += lost * melaninDepth / d;
      r.transmitted[i] *= std::exp(-d);
    }
  }
  return r;
}

void expectRelativelyNear(double actual, double expected, double relative, const char* what,
                          std::size_t j) {
  EXPECT_NEAR(actual, expected, relative * std::fabs(expected) + 1e-300)
      << what << " [" << j << "]";
}
}  // namespace

TEST(SpectralWeights, OneStayLosesOneMinusItsTransmittance) {
  // Hand values: μa = 2 /cm over 0.5 cm is a depth of 1, so T = e^{−1} and the loss 1 − e^{−1}.
  const std::vector<double> muA{2.0}, melaninMuA{0.0}, ratio{1.0};
  const spectral_weights::SlabAbsorption slab{muA.data(), 3, 2.0};
  const SpectralPath::Stay stay{0, 0.5, 0.0, 1.0};
  double transmitted = 0;
  std::vector<double> absorbed(kLayerCount, -1.0), inMelanin(kLayerCount, -1.0);
  spectral_weights::stayLosses(1, &stay, 1, &slab, melaninMuA.data(), 0.0, ratio.data(),
                               &transmitted, absorbed.data(), inMelanin.data());
  EXPECT_NEAR(transmitted, 0.36787944117144233, 1e-16);
  for (std::size_t layer = 0; layer < kLayerCount; ++layer) {
    EXPECT_NEAR(absorbed[layer], layer == 3 ? 0.63212055882855767 : 0.0, 1e-16) << layer;
    EXPECT_EQ(inMelanin[layer], 0.0) << layer;
  }
}

TEST(SpectralWeights, StayLossesMatchTheStayByStayProductInEveryBranch) {
  // Three wavelengths; four stays whose largest depth falls in each of the kernel's four forms of
  // 1 − e^{−d} (the series to 7, 11 and 15 terms, and the exponential), with and without melanin,
  // roulette factors and MIS ratios other than 1.
  const std::size_t n = 3;
  const std::vector<double> sc{0.01, 2.0, 40.0}, papillary{0.5, 0.0, 3.0};
  const std::vector<double> melaninMuA{100.0, 50.0, 0.0}, ratio{1.0, 0.5, 2.0};
  const std::vector<spectral_weights::SlabAbsorption> slabs{{sc.data(), 0, 40.0},
                                                            {papillary.data(), 4, 3.0}};
  const std::vector<SpectralPath::Stay> stays{{0, 1e-4, 0.0, 1.0},    // largest 0.004
                                              {1, 0.03, 1e-4, 2.0},   // 0.09 + 0.01
                                              {0, 0.01, 0.0, 1.0},    // 0.4
                                              {1, 0.5, 0.002, 4.0}};  // 1.5 + 0.2
  std::vector<double> transmitted(n), absorbed(kLayerCount * n), inMelanin(kLayerCount * n);
  spectral_weights::stayLosses(n, stays.data(), stays.size(), slabs.data(), melaninMuA.data(),
                               100.0, ratio.data(), transmitted.data(), absorbed.data(),
                               inMelanin.data());
  const ReferenceLosses expected = referenceLosses(n, stays, slabs, melaninMuA, ratio);
  // The series' truncation is below 2e-17 relative and vectorExp within 3 ulp; a few roundings per
  // stay: 1e-14 relative.
  for (std::size_t i = 0; i < n; ++i)
    expectRelativelyNear(transmitted[i], expected.transmitted[i], 1e-14, "transmitted", i);
  for (std::size_t j = 0; j < kLayerCount * n; ++j) {
    expectRelativelyNear(absorbed[j], expected.absorbed[j], 1e-14, "absorbed", j);
    expectRelativelyNear(inMelanin[j], expected.inMelanin[j], 1e-14, "in melanin", j);
  }
  EXPECT_GT(inMelanin[4 * n + 0], 0.0);  // the papillary stays' melanin was booked
  EXPECT_EQ(inMelanin[4 * n + 2], 0.0);  // no melanin absorption at the third wavelength
  // Without melanin's share (null): the transmittances and losses are the same bits.
  std::vector<double> transmittedAlone(n), absorbedAlone(kLayerCount * n);
  spectral_weights::stayLosses(n, stays.data(), stays.size(), slabs.data(), melaninMuA.data(),
                               100.0, ratio.data(), transmittedAlone.data(), absorbedAlone.data(),
                               nullptr);
  EXPECT_EQ(transmittedAlone, transmitted);
  EXPECT_EQ(absorbedAlone, absorbed);
}

TEST(SpectralWeights, PathDepthsSumEachSlabsAndMelaninsDepth) {
  const std::vector<double> first{1.0, 2.0}, second{3.0, 4.0}, melaninMuA{10.0, 20.0};
  const std::vector<spectral_weights::SlabAbsorption> slabs{{first.data(), 0, 2.0},
                                                            {second.data(), 1, 4.0}};
  const std::vector<double> pathCm{0.5, 0.25}, melaninCm{0.1, 0.0};
  std::vector<double> depth(2);
  spectral_weights::pathDepths(2, 2, slabs.data(), pathCm.data(), melaninCm.data(),
                               melaninMuA.data(), depth.data());
  EXPECT_DOUBLE_EQ(depth[0], 0.5 + 1.0 + 0.75);  // 1·0.5 + 10·0.1 + 3·0.25
  EXPECT_DOUBLE_EQ(depth[1], 1.0 + 2.0 + 1.0);   // 2·0.5 + 20·0.1 + 4·0.25
}

TEST(SpectralWeights, ExponentialsAreExpWithinThreeUlp) {
  const std::vector<double> x{-3.0, -0.5, 0.0, 1e-9, 2.0, 300.0},
      y{0.25, -1.0, 0.0, 5.0, -2.0, 1.0};
  std::vector<double> out(x.size()), sums(x.size());
  spectral_weights::exponentials(x.size(), x.data(), -2.0, 0.5, out.data());
  spectral_weights::exponentialsOfSum(x.size(), x.data(), y.data(), -0.5, sums.data());
  for (std::size_t i = 0; i < x.size(); ++i) {
    expectRelativelyNear(out[i], std::exp(-2.0 * x[i] + 0.5), 7e-16, "exp", i);
    expectRelativelyNear(sums[i], std::exp(x[i] + y[i] - 0.5), 7e-16, "exp of sum", i);
  }
  const double belowRange = -800.0;  // the header's promise: 0 below −708
  spectral_weights::exponentials(1, &belowRange, 1.0, 0.0, out.data());
  EXPECT_EQ(out[0], 0.0);
}

// ---- addRefractionDensities against Snell's law and Walter et al. 2007 ----

namespace {
struct RefractionCase {
  bool fromInside;
  double heroIndex;
  double aspectSquared;
};

// The density term one λ of index ni should receive for d refracted into t: its facet h (the
// generalised half vector, oriented against d) must refract d into t by Snell's law with ni; then
// log[(1 − F)·n2²|t·h| / (n1 d·h − n2 t·h)² / (a²cos²θh + sin²θh)²], θh about `macro`; −∞ where
// no such facet faces the ray or transmits.
double expectedLogDensity(const Vec3& d, const Vec3& t, const Vec3& macro, double ni,
                          bool fromInside, double aspectSquared, double& logTransmitted) {
  const double n1 = fromInside ? ni : 1.0, n2 = fromInside ? 1.0 : ni;
  Vec3 h = d * n1 - t * n2;
  logTransmitted = 0;
  if (dot(h, h) == 0) return -INFINITY;
  h = normalize(h);
  if (dot(d, h) > 0) h = h * -1.0;
  const double cosD = dot(d, h), cosT = dot(t, h), cosFacet = dot(h, macro);
  const FresnelResult f = fresnel(cosD, n1, n2);
  if (!(cosT < 0 && cosFacet > 0 && f.reflectance < 1)) return -INFINITY;
  const Vec3 snell = refractDirection(d, h, n1, n2, f.cosTransmitted);
  EXPECT_NEAR(snell.x, t.x, 1e-12);  // h is the facet that refracts d into t for this index
  EXPECT_NEAR(snell.y, t.y, 1e-12);
  EXPECT_NEAR(snell.z, t.z, 1e-12);
  const double sin2 = 1 - cosFacet * cosFacet;
  const double facet = aspectSquared * cosFacet * cosFacet + sin2;
  const double jacobian = n1 * cosD - n2 * cosT;
  logTransmitted = std::log1p(-f.reflectance);
  return logTransmitted + std::log(n2 * n2 * std::fabs(cosT)) - 2 * std::log(std::fabs(jacobian)) -
         2 * std::log(facet);
}
}  // namespace

TEST(SpectralWeights, RefractionDensitiesUseEachIndexsOwnFacet) {
  const std::vector<double> index{1.45, 1.40, 1.60, 1.0, 1.52};
  std::vector<double> inverse;
  for (double n : index) inverse.push_back(1.0 / n);
  for (const RefractionCase c : {RefractionCase{false, 1.45, 0.3}, RefractionCase{true, 1.45, 0.3},
                                 RefractionCase{false, 1.45, 1e40}}) {
    // The walk's conventions (SpectralWalk::crossSurface): the macro normal and the facet face
    // the ray; into the skin is +z.
    const double heading = c.fromInside ? -1.0 : 1.0;
    const Vec3 macro{0, 0, -heading};
    const Vec3 d = normalize({0.35, -0.2, heading});
    const Vec3 m = normalize({-0.3, 0.1, -heading});
    const double n1 = c.fromInside ? c.heroIndex : 1.0, n2 = c.fromInside ? 1.0 : c.heroIndex;
    const FresnelResult hero = fresnel(dot(d, m), n1, n2);
    ASSERT_LT(hero.reflectance, 1.0);
    const Vec3 t = refractDirection(d, m, n1, n2, hero.cosTransmitted);
    for (const bool forced : {false, true}) {
      std::vector<double> logDensity(index.size(), 0.5), offset(index.size(), -0.25);
      spectral_weights::addRefractionDensities(index.size(), d, t, macro, index.data(),
                                               inverse.data(), c.fromInside, c.aspectSquared,
                                               forced, logDensity.data(), offset.data());
      int invalid = 0;
      for (std::size_t i = 0; i < index.size(); ++i) {
        double logTransmitted = 0;
        const double expected = expectedLogDensity(d, t, macro, index[i], c.fromInside,
                                                   c.aspectSquared, logTransmitted);
        if (std::isinf(expected)) {
          ++invalid;
          EXPECT_EQ(logDensity[i], -INFINITY) << "n " << index[i];
          EXPECT_EQ(offset[i], -0.25) << "n " << index[i];
          continue;
        }
        EXPECT_NEAR(logDensity[i], 0.5 + expected, 1e-12 * (1 + std::fabs(expected)))
            << "n " << index[i] << (c.fromInside ? " from inside" : " from the air");
        EXPECT_NEAR(offset[i], forced ? -0.25 - logTransmitted : -0.25, 1e-13) << "n " << index[i];
      }
      EXPECT_GE(invalid, 1);  // matched indices (n = 1) cannot bend d into t
    }
  }
}
