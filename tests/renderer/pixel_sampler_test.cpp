// The pixel samplers (renderer/tracing/pixel_sampler.h): the Sobol' generator against its known
// first points, the (0,m,2)-net property of every 2-D request and the stratification of every 1-D
// request for each half of a pixel's samples and each power-of-two prefix, independence between
// pixels, halves and requests (chi-square), the independent sampler's draw order, and renders with
// the sobol sampler: a white furnace equal to its known answer within its standard error, the
// film's half-split noise figure equal to the two-seed one, the same image at 1 and 2 threads and
// for any pass size.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

#include "renderer/image/film.h"
#include "renderer/tracing/integrator.h"
#include "renderer/tracing/pixel_sampler.h"
#include "skin/core/random.h"
#include "skin/core/thread_limit.h"
#include "tests/support/chi2.h"
#include "tests/support/test_scenes.h"

using namespace hylios;

namespace {

/// True when the n = 2^m points (x, y) in [0, 1)² put exactly one point in every elementary
/// interval [a/2^i, (a+1)/2^i) × [b/2^(m−i), (b+1)/2^(m−i)) — a (0,m,2)-net in base 2.
::testing::AssertionResult isZeroMTwoNet(const std::vector<std::array<double, 2>>& points) {
  const std::size_t n = points.size();
  int m = 0;
  while ((std::size_t{1} << m) < n) ++m;
  if ((std::size_t{1} << m) != n) return ::testing::AssertionFailure() << n << " points";
  for (int i = 0; i <= m; ++i) {
    std::set<std::uint64_t> boxes;
    for (const auto& p : points) {
      if (!(p[0] >= 0 && p[0] < 1 && p[1] >= 0 && p[1] < 1))
        return ::testing::AssertionFailure() << "point outside [0, 1)²";
      const auto a = static_cast<std::uint64_t>(std::ldexp(p[0], i));
      const auto b = static_cast<std::uint64_t>(std::ldexp(p[1], m - i));
      boxes.insert((a << 32) | b);
    }
    if (boxes.size() != n)
      return ::testing::AssertionFailure() << "intervals 2^-" << i << " × 2^-" << (m - i) << ": "
                                           << boxes.size() << " of " << n << " occupied";
  }
  return ::testing::AssertionSuccess();
}

/// True when the 2^m values put one in every interval [a/2^m, (a+1)/2^m).
::testing::AssertionResult isStratified(const std::vector<double>& values) {
  std::set<std::uint64_t> cells;
  for (const double v : values) {
    if (!(v >= 0 && v < 1)) return ::testing::AssertionFailure() << "value " << v;
    cells.insert(static_cast<std::uint64_t>(v * static_cast<double>(values.size())));
  }
  if (cells.size() != values.size())
    return ::testing::AssertionFailure()
           << cells.size() << " of " << values.size() << " intervals occupied";
  return ::testing::AssertionSuccess();
}

/// The requests a camera path of a one-band film makes first: camera (band 1-D, film 2-D, lens
/// 2-D), a light sample (1-D, 1-D, 2-D) and a bounce (2-D).
struct PathNumbers {
  std::vector<double> oneD;
  std::vector<std::array<double, 2>> twoD;
};
PathNumbers drawPath(const PixelSampler& sampler, std::uint64_t pixel, std::uint64_t sample,
                     std::uint64_t seed) {
  skin::Rng rng(seed, pixel, sample);
  SampleStream stream = sampler.stream(pixel, sample, rng);
  const CameraSample c = sampler.cameraSample(pixel, sample, stream);
  PathNumbers p;
  p.oneD = {c.band};
  p.twoD = {{c.filmX, c.filmY}, {c.lensU, c.lensV}};
  p.oneD.push_back(stream.get1D());
  p.oneD.push_back(stream.get1D());
  p.twoD.push_back(stream.get2D());
  p.twoD.push_back(stream.get2D());
  return p;
}

/// χ² of an r × c contingency table against independence with the table's own margins:
/// (r − 1)(c − 1) degrees of freedom (also when the margins are fixed by stratification).
double independencePValue(const std::vector<std::vector<double>>& table) {
  const std::size_t rows = table.size(), cols = table[0].size();
  std::vector<double> rowSum(rows, 0), colSum(cols, 0);
  double total = 0;
  for (std::size_t i = 0; i < rows; ++i)
    for (std::size_t j = 0; j < cols; ++j) {
      rowSum[i] += table[i][j];
      colSum[j] += table[i][j];
      total += table[i][j];
    }
  double chi2 = 0;
  for (std::size_t i = 0; i < rows; ++i)
    for (std::size_t j = 0; j < cols; ++j) {
      const double expected = rowSum[i] * colSum[j] / total;
      chi2 += (table[i][j] - expected) * (table[i][j] - expected) / expected;
    }
  return test::chi2SurvivalProbability(chi2, static_cast<int>((rows - 1) * (cols - 1)));
}

std::vector<std::vector<double>> jointHistogram(const std::vector<double>& a,
                                                const std::vector<double>& b, int bins) {
  std::vector<std::vector<double>> table(static_cast<std::size_t>(bins),
                                         std::vector<double>(static_cast<std::size_t>(bins), 0));
  for (std::size_t k = 0; k < a.size(); ++k)
    table[static_cast<std::size_t>(a[k] * bins)][static_cast<std::size_t>(b[k] * bins)] += 1;
  return table;
}

}  // namespace

TEST(Sobol, FirstTwoDimensionsAreVanDerCorputAndTheClassicSecondDimension) {
  const double vdc[8] = {0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
  const double second[8] = {0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
  for (std::uint32_t i = 0; i < 8; ++i) {
    EXPECT_EQ(sobol::dimension0(i), static_cast<std::uint32_t>(vdc[i] * 4294967296.0)) << i;
    EXPECT_EQ(sobol::dimension1(i), static_cast<std::uint32_t>(second[i] * 4294967296.0)) << i;
  }
  // Direction number k has digit j set where C(k, j) is odd (Lucas): 1111 for k = 3, all for 31.
  EXPECT_EQ(sobol::dimension1(1u << 3), 0xf0000000u);
  EXPECT_EQ(sobol::dimension1(1u << 31), 0xffffffffu);
}

TEST(Sobol, EveryAlignedBlockOfTheFirstTwoDimensionsIsANet) {
  for (int m = 0; m <= 12; ++m)
    for (const std::uint32_t block : {0u, 1u, 7u, 1000u}) {
      std::vector<std::array<double, 2>> points;
      for (std::uint32_t j = 0; j < (1u << m); ++j) {
        const std::uint32_t i = (block << m) + j;
        points.push_back({sobol::dimension0(i) * 0x1.0p-32, sobol::dimension1(i) * 0x1.0p-32});
      }
      EXPECT_TRUE(isZeroMTwoNet(points)) << "m " << m << ", block " << block;
    }
}

TEST(Sobol, OwenScrambleIsNestedAndBijective) {
  // Values sharing their k leading digits keep sharing exactly k after the scramble (nested:
  // digit k depends only on the digits above it; bijective: differing digits stay different).
  skin::Rng rng(3);
  for (int trial = 0; trial < 20000; ++trial) {
    const auto seed = static_cast<std::uint32_t>(rng.nextU64());
    const auto v = static_cast<std::uint32_t>(rng.nextU64());
    const int k = static_cast<int>(rng.nextU64() % 32);
    const std::uint32_t w =
        v ^ (0x80000000u >> k) ^ (static_cast<std::uint32_t>(rng.nextU64()) & (0x7fffffffu >> k));
    const std::uint32_t sv = sobol::owenScramble(v, seed), sw = sobol::owenScramble(w, seed);
    ASSERT_EQ(__builtin_clz(sv ^ sw), k) << std::hex << v << " " << w << " seed " << seed;
  }
  // And each digit is flipped or not about equally often over seeds: the leading digit's flip
  // rate over 20000 seeds is 1/2 ± 4σ (σ = √(1/4/20000) = 0.0035).
  int flips = 0;
  for (int trial = 0; trial < 20000; ++trial)
    flips += sobol::owenScramble(0, static_cast<std::uint32_t>(rng.nextU64())) >> 31;
  EXPECT_NEAR(flips / 20000.0, 0.5, 4 * 0.0035);
}

TEST(Sobol, FastRequestsEqualTheCompositionOfScrambleShuffleAndDimension) {
  skin::Rng rng(4);
  for (int trial = 0; trial < 10000; ++trial) {
    const auto i = static_cast<std::uint32_t>(rng.nextU64() >> (trial % 33 + 31));
    const auto s1 = static_cast<std::uint32_t>(rng.nextU64()),
               s2 = static_cast<std::uint32_t>(rng.nextU64()),
               s3 = static_cast<std::uint32_t>(rng.nextU64());
    const std::uint32_t j = sobol::owenScramble(i, s1);
    ASSERT_EQ(sobol::scrambledRadicalInverse(sobol::dimension0(i), s1, s2),
              sobol::owenScramble(sobol::dimension0(j), s2));
    const std::array<std::uint32_t, 2> p =
        sobol::scrambledSobol2D(sobol::dimension0(i), s1, s2, s3);
    ASSERT_EQ(p[0], sobol::owenScramble(sobol::dimension0(j), s2));
    ASSERT_EQ(p[1], sobol::owenScramble(sobol::dimension1(j), s3));
  }
}

TEST(PixelSampler, EachHalfOfAPixelsSamplesIsStratifiedInEveryRequestAtEveryPowerOfTwo) {
  const PixelSampler sampler(SamplerKind::Sobol, 11, 1);
  constexpr int kLog2 = 10;
  // Every sample is one point of one half, and the first 2^k samples of each half are points
  // 0 … 2^k − 1 of it (the halves' own numbering, pixel_sampler.h).
  std::array<std::vector<std::uint64_t>, 2> samplesOfHalf;
  for (std::uint64_t sample = 0; sample < (2u << kLog2); ++sample) {
    auto& half = samplesOfHalf[inSecondFilmHalf(sample) ? 1 : 0];
    ASSERT_EQ(filmHalfPoint(sample), half.size()) << "sample " << sample;
    half.push_back(sample);
  }
  ASSERT_EQ(samplesOfHalf[0].size(), samplesOfHalf[1].size());
  for (const std::uint64_t pixel : {0ull, 12345ull})
    for (std::uint64_t half = 0; half < 2; ++half) {
      std::vector<PathNumbers> paths;
      for (const std::uint64_t sample : samplesOfHalf[half])
        paths.push_back(drawPath(sampler, pixel, sample, 11));
      for (int m = 0; m <= kLog2; ++m) {
        const std::size_t n = std::size_t{1} << m;
        for (std::size_t r = 0; r < paths[0].twoD.size(); ++r) {
          std::vector<std::array<double, 2>> points;
          for (std::size_t k = 0; k < n; ++k) points.push_back(paths[k].twoD[r]);
          EXPECT_TRUE(isZeroMTwoNet(points))
              << "pixel " << pixel << ", half " << half << ", 2-D request " << r << ", n " << n;
        }
        for (std::size_t r = 0; r < paths[0].oneD.size(); ++r) {
          std::vector<double> values;
          for (std::size_t k = 0; k < n; ++k) values.push_back(paths[k].oneD[r]);
          EXPECT_TRUE(isStratified(values))
              << "pixel " << pixel << ", half " << half << ", 1-D request " << r << ", n " << n;
        }
      }
    }
}

TEST(PixelSampler, FilmHalvesHoldWholeBlocksOfFourAtEveryMultipleOfFour) {
  // From 8 samples on, at every multiple of 4 each half holds a multiple of 4 points (aligned
  // blocks of its sequence: nets), 12 giving 8 and 4; from 2 samples on neither half is empty.
  std::array<std::uint64_t, 2> points{0, 0};
  for (std::uint64_t done = 1; done <= 64; ++done) {
    ++points[inSecondFilmHalf(done - 1) ? 1 : 0];
    if (done >= 2) {
      EXPECT_TRUE(points[0] > 0 && points[1] > 0) << done;
    }
    if (done >= 8 && done % 4 == 0) {
      EXPECT_TRUE(points[0] % 4 == 0 && points[1] % 4 == 0) << done;
    }
    if (done == 12) {
      EXPECT_TRUE(points[0] == 8 && points[1] == 4);
    }
    if (done % 8 == 0) {
      EXPECT_EQ(points[0], points[1]) << done;
    }
  }
}

TEST(PixelSampler, PixelsHalvesSeedsAndRequestsAreScrambledIndependently) {
  const PixelSampler sampler(SamplerKind::Sobol, 5, 1), other(SamplerKind::Sobol, 6, 1);
  constexpr int kBins = 8;
  // Across 20000 pixels, sample 0: uniform marginals (64 bins, χ² at 1 %), and no dependence
  // between neighbouring pixels, between the pixel's two halves, between seeds, or between the
  // film and light requests of one path (8 × 8 tables, 49 dof).
  std::vector<double> film, nextPixel, secondHalf, otherSeed, light, band;
  for (std::uint64_t p = 0; p < 20000; ++p) {
    const PathNumbers a = drawPath(sampler, p, 0, 5);
    film.push_back(a.twoD[0][0]);
    light.push_back(a.twoD[2][0]);
    band.push_back(a.oneD[0]);
    nextPixel.push_back(drawPath(sampler, p + 1, 0, 5).twoD[0][0]);
    secondHalf.push_back(drawPath(sampler, p, 1, 5).twoD[0][0]);  // the second half's point 0
    otherSeed.push_back(drawPath(other, p, 0, 6).twoD[0][0]);
  }
  for (const auto* values : {&film, &light, &band})
    EXPECT_TRUE(test::chi2Accepts(test::chi2Test1D(
        *values, [](double) { return 1.0; }, test::uniformEdges(0, 1, 64))));
  EXPECT_GT(independencePValue(jointHistogram(film, nextPixel, kBins)), 0.01);
  EXPECT_GT(independencePValue(jointHistogram(film, secondHalf, kBins)), 0.01);
  EXPECT_GT(independencePValue(jointHistogram(film, otherSeed, kBins)), 0.01);
  EXPECT_GT(independencePValue(jointHistogram(film, light, kBins)), 0.01);
  // Within one pixel's 4096 samples of one half: each request is stratified, so the margins are
  // fixed; the pairing of two requests (padding) must still look independent.
  std::vector<double> x0, x1, y0, y1;
  for (std::uint64_t k = 0; k < 4096; ++k) {
    const PathNumbers a = drawPath(sampler, 77, 2 * k, 5);
    x0.push_back(a.twoD[0][0]);
    y0.push_back(a.twoD[0][1]);
    x1.push_back(a.twoD[3][0]);
    y1.push_back(a.oneD[1]);
  }
  EXPECT_GT(independencePValue(jointHistogram(x0, x1, kBins)), 0.01);
  EXPECT_GT(independencePValue(jointHistogram(y0, y1, kBins)), 0.01);
}

TEST(PixelSampler, IndependentSamplerDrawsTheRngInTheRenderersOrder) {
  // The numbers renders drew before samplers existed: band jitter, film x, y, lens u, v, then the
  // path's, all from Rng(seed, pixel, sample); the band rotated per block of `strata` samples.
  const std::uint64_t seed = 9, strata = 3;
  const PixelSampler sampler(SamplerKind::Independent, seed, strata);
  for (std::uint64_t s = 0; s < 10; ++s) {
    skin::Rng rng(seed, 42, s), expected(seed, 42, s);
    SampleStream stream = sampler.stream(42, s, rng);
    const CameraSample c = sampler.cameraSample(42, s, stream);
    const double rotation = skin::Rng(seed, 42, ~std::uint64_t{0} - s / strata).uniform();
    double u = (static_cast<double>(s % strata) + expected.uniform()) / strata + rotation;
    u -= std::floor(u);
    EXPECT_EQ(c.band, u);
    EXPECT_EQ(c.filmX, expected.uniform());
    EXPECT_EQ(c.filmY, expected.uniform());
    EXPECT_EQ(c.lensU, expected.uniform());
    EXPECT_EQ(c.lensV, expected.uniform());
    EXPECT_EQ(stream.get1D(), expected.uniform());
    const std::array<double, 2> pair = stream.get2D();
    EXPECT_EQ(pair[0], expected.uniform());
    EXPECT_EQ(pair[1], expected.uniform());
    SampleStream branch = stream.branch();
    EXPECT_EQ(branch.get1D(), expected.uniform());
    EXPECT_EQ(stream.rng().uniform(), expected.uniform());
  }
}

TEST(PixelSampler, SobolStreamFallsBackToTheRngAfterItsDimensions) {
  const PixelSampler sampler(SamplerKind::Sobol, 2, 1);
  skin::Rng rng(2, 8, 5), expected(2, 8, 5);
  SampleStream stream = sampler.stream(8, 5, rng);
  while (stream.dimension() + 2 <= kLowDiscrepancyDimensions) stream.get2D();
  while (stream.dimension() < kLowDiscrepancyDimensions) stream.get1D();
  EXPECT_EQ(stream.get1D(), expected.uniform());  // the Sobol' dimensions drew nothing from rng
  EXPECT_THROW(sampler.stream(8, std::uint64_t{1} << 33, rng), std::invalid_argument);
}

namespace {

/// A Lambertian sphere (ρ = 1, radius 1) in a uniform environment L = 2 seen from +z: every
/// pixel's expectation is L (the sphere reflects exactly what the sky sends).
SceneDesc furnace(SamplerKind sampler, int spp, std::uint64_t seed) {
  SceneDesc scene;
  scene.camera.position = {0, 0, 4};
  scene.camera.verticalFovDeg = 35;
  scene.film.width = scene.film.height = 32;
  scene.film.samplesPerPixel = spp;
  scene.film.bands = {test::singleWavelengthBand(550)};
  MaterialDesc white;
  white.kind = MaterialDesc::Kind::Diffuse;
  white.name = "white";
  white.reflectance = test::constantSpectrum(1.0);
  scene.materials = {white};
  ShapeDesc sphere;
  sphere.kind = ShapeDesc::Kind::Sphere;
  sphere.material = "white";
  scene.shapes = {sphere};
  LightDesc sky;
  sky.kind = LightDesc::Kind::Environment;
  sky.emission = test::constantSpectrum(2.0);
  scene.lights = {sky};
  scene.integrator.maxDepth = 4;
  scene.integrator.seed = seed;
  scene.integrator.sampler = sampler;
  return scene;
}

Film renderFurnace(SamplerKind sampler, int spp, std::uint64_t seed, int samplesPerPass = 0) {
  const SceneDesc scene = furnace(sampler, spp, seed);
  Film film(scene.film);
  const Integrator integrator(scene, {550});
  RenderOptions options = quietRenderOptions("furnace");
  options.samplesPerPass = samplesPerPass;
  integrator.render(film, options);
  return film;
}

}  // namespace

TEST(PixelSampler, SobolFurnaceEqualsTheSkyAndItsHalvesEstimateTheNoiseUnbiased) {
  // 1024 pixels at 64 spp, seeds 1 and 2. Per pixel, the film's halves E and O (32 samples each)
  // are independent, so (E − O)²/4 estimates the variance of the pixel's value; two seeds' values A
  // and B give (A − B)²/2 for the same variance. Over the sphere's pixels: the image mean is L
  // within 4 standard errors (σ² = Σ (E − O)²/4 / N²), and the two variance estimates agree: each
  // is a mean of N scaled χ²₁ values (relative σ ≈ √(2/N) each; more where the per-pixel variance
  // varies), so their ratio is 1 within 4·√(4/N) plus that spread, measured by the spread of
  // the per-pixel variance itself.
  const Film a = renderFurnace(SamplerKind::Sobol, 64, 1),
             b = renderFurnace(SamplerKind::Sobol, 64, 2);
  double sum = 0, halfVariance = 0, seedVariance = 0, halfSquares = 0, seedSquares = 0;
  int n = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const double value = a.value(x, y, 0);
      const double e = a.halfValue(x, y, 0, false), o = a.halfValue(x, y, 0, true);
      if (e == 2.0 && o == 2.0 && b.value(x, y, 0) == 2.0) continue;  // the sky: exact
      const double h = (e - o) * (e - o) / 4,
                   s = (value - b.value(x, y, 0)) * (value - b.value(x, y, 0)) / 2;
      sum += value;
      halfVariance += h;
      seedVariance += s;
      halfSquares += h * h;
      seedSquares += s * s;
      ++n;
    }
  ASSERT_GT(n, 300);
  const double mean = sum / n, standardError = std::sqrt(halfVariance) / n;
  EXPECT_NEAR(mean, 2.0, 4 * standardError) << "σ " << standardError << ", " << n << " pixels";
  EXPECT_LT(standardError, 0.01);
  // Relative standard error of each mean of per-pixel variance estimates: √(mean of squares −
  // square of mean) / (√N · mean), measured.
  const double hm = halfVariance / n, sm = seedVariance / n;
  const double relHalf = std::sqrt(halfSquares / n - hm * hm) / (std::sqrt(n) * hm);
  const double relSeed = std::sqrt(seedSquares / n - sm * sm) / (std::sqrt(n) * sm);
  EXPECT_NEAR(hm / sm, 1.0, 4 * std::hypot(relHalf, relSeed))
      << "half-split " << hm << ", two seeds " << sm << " (relative σ " << relHalf << ", "
      << relSeed << ")";
}

TEST(PixelSampler, SobolRenderIsTheSameAtOneAndTwoThreadsAndAnyPassSize) {
  Film one(furnace(SamplerKind::Sobol, 12, 3).film), two = one;
  {
    const ThreadLimit limit(1);
    one = renderFurnace(SamplerKind::Sobol, 12, 3, 5);
  }
  {
    const ThreadLimit limit(2);
    two = renderFurnace(SamplerKind::Sobol, 12, 3, 0);
  }
  EXPECT_EQ(one.sums(), two.sums());
  EXPECT_EQ(one.secondHalfSums(), two.secondHalfSums());
  // and differs from the independent sampler's image (the setting is used)
  EXPECT_NE(one.sums(), renderFurnace(SamplerKind::Independent, 12, 3).sums());
}
