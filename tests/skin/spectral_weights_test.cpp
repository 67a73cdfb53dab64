// The spectral walk's vectorised Fresnel kernels (skin/spectral_weights.h) against skin::fresnel,
// whose branches they replace with selects: the same reflectance, to the bit as the header says,
// from the air and from inside, at normal, oblique and grazing incidence, beyond the critical
// angle and for matched indices; the log kernel adds vectorLog of the same values (≤ 2 ulp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "skin/core/random.h"
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

/// stayLosses over `stays` with slabs of coefficients `muA` (one vector per slab, layer = slab
/// index · 2), melanin `melaninMuA`, and MIS ratios `ratio`: its outputs, and in slabsOut the
/// slabs for referenceLosses (valid while `muA` lives).
struct StayLossesRun {
  std::vector<double> transmitted, absorbed, inMelanin;
};
StayLossesRun runStayLosses(const std::vector<std::vector<double>>& muA,
                            const std::vector<double>& melaninMuA, const std::vector<double>& ratio,
                            const std::vector<SpectralPath::Stay>& stays, bool bookMelanin,
                            std::vector<spectral_weights::SlabAbsorption>* slabsOut = nullptr) {
  const std::size_t n = ratio.size();
  std::vector<std::vector<float>> single;
  single.reserve(muA.size());
  std::vector<spectral_weights::SlabAbsorption> slabs;
  for (std::size_t k = 0; k < muA.size(); ++k) {
    single.emplace_back(muA[k].begin(), muA[k].end());
    slabs.push_back(
        {{muA[k].data(), single.back().data(), *std::max_element(muA[k].begin(), muA[k].end())},
         2 * k % kLayerCount});
  }
  const std::vector<float> melaninSingle(melaninMuA.begin(), melaninMuA.end());
  const spectral_weights::MelaninAbsorption melanin{
      melaninMuA.data(), melaninSingle.data(),
      *std::max_element(melaninMuA.begin(), melaninMuA.end())};
  StayLossesRun run{std::vector<double>(n), std::vector<double>(kLayerCount * n),
                    std::vector<double>(kLayerCount * n)};
  std::vector<float> work(2 * n);
  spectral_weights::stayLosses(n, stays.data(), stays.size(), slabs.data(), melanin, ratio.data(),
                               run.transmitted.data(), run.absorbed.data(),
                               bookMelanin ? run.inMelanin.data() : nullptr, work.data());
  if (slabsOut) {  // for the reference, which reads the double coefficients only
    for (auto& slab : slabs) slab.muA_perCmSingle = nullptr;
    *slabsOut = slabs;
  }
  return run;
}

void expectNearReference(const StayLossesRun& run, const ReferenceLosses& expected,
                         double relative) {
  for (std::size_t i = 0; i < run.transmitted.size(); ++i)
    expectRelativelyNear(run.transmitted[i], expected.transmitted[i], relative, "transmitted", i);
  for (std::size_t j = 0; j < run.absorbed.size(); ++j) {
    expectRelativelyNear(run.absorbed[j], expected.absorbed[j], relative, "absorbed", j);
    expectRelativelyNear(run.inMelanin[j], expected.inMelanin[j], relative, "in melanin", j);
  }
}
}  // namespace

TEST(SpectralWeights, OneStayLosesOneMinusItsTransmittance) {
  // Hand values: μa = 2 /cm over 0.5 cm is a depth of 1 (the exponential form, in double), so
  // T = e^{−1} and the loss 1 − e^{−1}.
  const std::vector<SpectralPath::Stay> stay{{0, 0.5, 0.0, 1.0}};
  const StayLossesRun run = runStayLosses({{2.0}}, {0.0}, {1.0}, stay, true);
  EXPECT_NEAR(run.transmitted[0], 0.36787944117144233, 1e-16);
  for (std::size_t layer = 0; layer < kLayerCount; ++layer) {
    EXPECT_NEAR(run.absorbed[layer], layer == 0 ? 0.63212055882855767 : 0.0, 1e-16) << layer;
    EXPECT_EQ(run.inMelanin[layer], 0.0) << layer;
  }
  // A shallow stay (the series, in float): depth 0.01, loss 1 − e^{−0.01} within 1e−6 relative.
  const std::vector<SpectralPath::Stay> shallow{{0, 0.005, 0.0, 1.0}};
  const StayLossesRun series = runStayLosses({{2.0}}, {0.0}, {1.0}, shallow, true);
  EXPECT_NEAR(series.absorbed[0], 0.009950166250831946, 1e-6 * 0.00995);
  EXPECT_NEAR(series.transmitted[0], 0.9900498337491681, 1e-6 * 0.00995);
}

TEST(SpectralWeights, StayLossesMatchTheStayByStayProductInEveryBranch) {
  // 19 wavelengths (a full 16-lane block and a remainder); four stays whose largest depth falls in
  // each of the kernel's four forms of 1 − e^{−d} (the float series to 4, 6 and 9 terms, and the
  // exponential in double), with and without melanin, roulette factors and MIS ratios other than
  // 1. The float series' fractions are within 1e−6 relative, and so is every output.
  const std::size_t n = 19;
  std::vector<double> sc(n), papillary(n), melaninMuA(n), ratio(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i) / (n - 1);
    sc[i] = 0.01 + 39.99 * x * x;
    papillary[i] = 3.0 * (1.0 - x);
    melaninMuA[i] = i % 5 == 4 ? 0.0 : 100.0 * (1.0 - 0.5 * x);
    ratio[i] = 0.5 + 1.5 * x;
  }
  const std::vector<SpectralPath::Stay> stays{{0, 1e-4, 0.0, 1.0},    // largest 0.004
                                              {1, 0.03, 1e-4, 2.0},   // 0.09 + 0.01
                                              {0, 0.01, 0.0, 1.0},    // 0.4
                                              {1, 0.5, 0.002, 4.0}};  // 1.5 + 0.2
  const std::vector<std::vector<double>> muA{sc, papillary};          // alive for the reference
  std::vector<spectral_weights::SlabAbsorption> slabs;
  const StayLossesRun run = runStayLosses(muA, melaninMuA, ratio, stays, true, &slabs);
  const ReferenceLosses expected = referenceLosses(n, stays, slabs, melaninMuA, ratio);
  expectNearReference(run, expected, 1e-6);
  EXPECT_GT(run.inMelanin[2 * n + 0], 0.0);  // the papillary stays' melanin was booked
  EXPECT_EQ(run.inMelanin[2 * n + 4], 0.0);  // no melanin absorption at the fifth wavelength
  // Without melanin's share (null): the transmittances and losses are the same bits.
  const StayLossesRun alone = runStayLosses(muA, melaninMuA, ratio, stays, false);
  EXPECT_EQ(alone.transmitted, run.transmitted);
  EXPECT_EQ(alone.absorbed, run.absorbed);
}

TEST(SpectralWeights, StayLossesKeepCoefficientsBeyondFloatInDouble) {
  // μa = 1e35 /cm over 2e−36 cm is a depth of 0.2, a series stay, but 1e35 is not a float: the
  // stay takes the double form, exact to rounding (T = e^{−0.2}, no infinity or NaN).
  const std::vector<std::vector<double>> muA{{1e35, 1.0}};
  const std::vector<SpectralPath::Stay> stay{{0, 2e-36, 0.0, 1.0}};
  std::vector<spectral_weights::SlabAbsorption> slabs;
  const StayLossesRun run = runStayLosses(muA, {0.0, 0.0}, {1.0, 1.0}, stay, true, &slabs);
  EXPECT_NEAR(run.transmitted[0], std::exp(-0.2), 1e-15);
  EXPECT_NEAR(run.absorbed[0], -std::expm1(-0.2), 1e-15);
  EXPECT_NEAR(run.transmitted[1], std::exp(-2e-36), 1e-15);
}

TEST(SpectralWeights, StayLossesStayWithinOneMillionthOverALongPath) {
  // 400 stays of random depths up to 0.45 in three slabs (the series forms, where the float
  // rounding lies): each layer's loss within 1e−6 relative of the double reference, and the
  // transmittance after all of them (total depth D ≈ 8–60) within 1e−6 + 1e−7·D relative: a
  // stay's rounding (≈ 3e−8 of its fraction) moves T by that share of the stay's depth, so T's
  // error grows with D while T itself falls as e^{−D} (its absolute error stays below 1e−8).
  const std::size_t n = 24;
  std::vector<std::vector<double>> muA(3, std::vector<double>(n));
  std::vector<double> melaninMuA(n), ratio(n, 1.0);
  Rng rng(26, 7);
  for (auto& slab : muA)
    for (double& mu : slab) mu = 0.3 * rng.uniform();
  for (double& mu : melaninMuA) mu = 10.0 * rng.uniform();
  std::vector<SpectralPath::Stay> stays;
  for (int k = 0; k < 400; ++k)
    stays.push_back({static_cast<std::size_t>(k % 3), rng.uniform(), 0.01 * rng.uniform(),
                     1.0 + std::floor(k / 100.0)});
  std::vector<spectral_weights::SlabAbsorption> slabs;
  const StayLossesRun run = runStayLosses(muA, melaninMuA, ratio, stays, true, &slabs);
  const ReferenceLosses expected = referenceLosses(n, stays, slabs, melaninMuA, ratio);
  double deepest = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double depth = -std::log(expected.transmitted[i]);
    deepest = std::max(deepest, depth);
    expectRelativelyNear(run.transmitted[i], expected.transmitted[i], 1e-6 + 1e-7 * depth,
                         "transmitted", i);
  }
  EXPECT_GT(deepest, 40.0);  // deep members, where the relative error builds up most
  for (std::size_t j = 0; j < run.absorbed.size(); ++j) {
    expectRelativelyNear(run.absorbed[j], expected.absorbed[j], 1e-6, "absorbed", j);
    expectRelativelyNear(run.inMelanin[j], expected.inMelanin[j], 1e-6, "in melanin", j);
  }
}

TEST(SpectralWeights, PathDepthsSumEachSlabsAndMelaninsDepth) {
  const std::vector<double> first{1.0, 2.0}, second{3.0, 4.0}, melaninMuA{10.0, 20.0};
  const std::vector<spectral_weights::SlabAbsorption> slabs{{{first.data(), nullptr, 2.0}, 0},
                                                            {{second.data(), nullptr, 4.0}, 1}};
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
