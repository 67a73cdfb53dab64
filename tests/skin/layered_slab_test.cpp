// The generic layered slab (MCML's problem) against every published number in
// tests/data/validation/mc_benchmarks_published.csv, against closed forms for non-scattering
// plates, and for energy balance, determinism and thread-count independence.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "skin/core/constants.h"
#include "skin/core/thread_limit.h"
#include "skin/fresnel.h"
#include "skin/layered_slab.h"
#include "tests/support/slab_problems.h"

using hylios::kPi;

namespace hylios::skin {
namespace {

constexpr double kInf = test::kSemiInfinite;
using test::mcmlThreeLayerSample;
using test::singleLayer;
// Photons per published-benchmark run (13 runs, ~1.5 s in Release on 2 cores): analog sigma is
// sqrt(p (1 - p) / N), e.g. 3.0e-4 for Rd ~ 0.1, 4.7e-4 for Tt ~ 0.66, 4.3e-4 for Rd ~ 0.24
// (the test prints every row's sigma).
constexpr std::uint64_t kBenchmarkPhotons = 1000000;

// The problem behind each case_id of the CSV (its columns, or its notes for the 3-layer cases).
// Albedo/optical-thickness cases use mu_t = 1 cm^-1 and d = tau cm.
SlabProblem problemForCase(const std::string& caseId) {
  auto starts = [&](const char* prefix) { return caseId.rfind(prefix, 0) == 0; };
  if (starts("T6.1-") || caseId == "mcml2-sample1a")
    return singleLayer(1.0, {1.0, 10, 90, 0.75, 0.02}, 1.0);
  if (starts("T6.2-") || caseId == "mcml2-sample1b")
    return singleLayer(1.0, {1.5, 10, 90, 0.0, kInf}, 1.0);
  if (starts("T6.7-") || caseId == "mcml12-sample" || caseId == "mcml2-sample2")
    return mcmlThreeLayerSample();
  if (caseId == "vdH-oblique-1") return singleLayer(1.0, {1.0, 0.01, 0.99, 0.0, 1.0}, 1.0, 60.0);
  if (caseId == "vdH-oblique-2") return singleLayer(1.0, {1.0, 0.01, 0.99, 0.5, 4.0}, 1.0, 60.0);
  if (caseId == "iad-adbasic") return singleLayer(1.0, {1.0, 0.1, 0.9, 0.8, 1.0}, 1.0);
  if (caseId == "iadpy-test02") return singleLayer(1.0, {1.4, 0.5, 0.5, 0.9, 1.0}, 1.0);
  if (caseId == "iadpy-test06") return singleLayer(1.0, {1.4, 0.2, 0.8, 0.0, kInf}, 1.0);
  if (caseId == "iadpy-test02thick") return singleLayer(1.0, {1.0, 0.2, 0.8, 0.0, kInf}, 1.0);
  throw std::runtime_error("no slab problem known for case_id " + caseId);
}

std::vector<std::string> split(const std::string& text, const std::string& separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t at = text.find(separator, start);
    parts.push_back(text.substr(start, at - start));
    if (at == std::string::npos) return parts;
    start = at + separator.size();
  }
}

std::map<std::string, std::string> toRecord(const std::vector<std::string>& header,
                                            const std::vector<std::string>& fields) {
  std::map<std::string, std::string> record;
  for (std::size_t i = 0; i < header.size(); ++i) record[header[i]] = fields.at(i);
  return record;
}

std::vector<std::map<std::string, std::string>> readBenchmarks() {
  const std::string path =
      std::string(HYLIOS_SOURCE_DIR) + "/tests/data/validation/mc_benchmarks_published.csv";
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = split(line, ",");
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line))
    if (!line.empty()) rows.push_back(toRecord(header, split(line, ",")));
  return rows;
}

// Half a unit of the last printed decimal of a tabulated value ("0.2600" -> 5e-5).
double roundingAllowance(const std::string& valueText) {
  const std::size_t dot = valueText.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(valueText.size() - dot - 1);
  return 0.5 * std::pow(10.0, -decimals);
}

std::string trim(const std::string& s) {
  const std::size_t a = s.find_first_not_of(' '), b = s.find_last_not_of(' ');
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

struct Check {
  std::string label;
  Estimate ours;
  double published, publishedSigma, allowance;
};

class BenchmarkRunner {
 public:
  const SlabResult& result(const std::string& caseId, bool diffuse) {
    SlabProblem problem = problemForCase(caseId);
    problem.diffuseIncidence = diffuse;
    const std::string key = problemKey(problem);
    auto found = cache_.find(key);
    if (found != cache_.end()) return found->second;
    SlabRunOptions options;
    options.photons = kBenchmarkPhotons;
    options.seed = 20240601;
    return cache_.emplace(key, simulateLayeredSlab(problem, options)).first->second;
  }

 private:
  static std::string problemKey(const SlabProblem& p) {
    std::ostringstream key;
    key.precision(17);
    key << p.refractiveIndexAbove << ' ' << p.refractiveIndexBelow << ' ' << p.incidenceAngleDeg
        << ' ' << p.diffuseIncidence;
    for (const SlabLayer& l : p.layers)
      key << " | " << l.refractiveIndex << ' ' << l.muA_perCm << ' ' << l.muS_perCm << ' '
          << l.anisotropyG << ' ' << l.thicknessCm;
    return key.str();
  }
  std::map<std::string, SlabResult> cache_;
};

// Our estimate of one quantity token (first word of the CSV's quantity column).
Estimate ourQuantity(BenchmarkRunner& runner, const std::string& caseId, const std::string& token,
                     const std::string& quantityText) {
  const bool diffuse = token == "URU" || token == "UTU";
  const SlabResult& r = runner.result(caseId, diffuse);
  const Estimate totalReflectance{r.specularReflectance + r.diffuseReflectance.mean,
                                  r.diffuseReflectance.standardError};
  if (token == "Rd")
    return quantityText.find("as tabulated") != std::string::npos ? totalReflectance
                                                                  : r.diffuseReflectance;
  if (token == "UR1" || token == "URU") return totalReflectance;
  if (token == "Tt" || token == "UT1" || token == "UTU") return r.transmittance;
  if (token == "A") return r.absorptance;
  if (token == "Tb") return r.unscatteredTransmittance;
  if (token == "Td") return r.diffuseTransmittance;
  if (token == "Rsp") return {r.specularReflectance, 0.0};
  throw std::runtime_error("unknown quantity '" + token + "' for " + caseId);
}

// sigma of a published value: its std_error column; for a Monte Carlo value without one, the
// binomial sqrt(v (1 - v) / N) from its photon count (an upper bound for MCML's weighted tallies);
// tables and adding-doubling: 0 (their rounding goes into the allowance).
double publishedSigma(const std::map<std::string, std::string>& row, const std::string& token,
                      double value) {
  if (token == "Rsp") return 0.0;  // deterministic in MCML too
  if (!row.at("std_error").empty()) return std::stod(row.at("std_error"));
  const std::string& photons = row.at("photons_or_quadrature");
  if (row.at("method").find("Monte Carlo") != std::string::npos && !photons.empty() &&
      std::isdigit(static_cast<unsigned char>(photons[0])))
    return std::sqrt(value * (1 - value) / std::stod(photons));
  return 0.0;
}

// The rows' values; adding-doubling rows that also quote 32-point quadrature values use those.
std::vector<std::string> publishedValues(const std::map<std::string, std::string>& row) {
  const std::string& quadrature = row.at("photons_or_quadrature");
  for (const char* marker : {"q=32 gives ", "q=32: "}) {
    const std::size_t at = quadrature.find(marker);
    if (at == std::string::npos) continue;
    const std::size_t begin = at + std::string(marker).size();
    return split(quadrature.substr(begin, quadrature.find(')', begin) - begin), " / ");
  }
  return split(row.at("value"), " / ");
}

// Adding-doubling with fewer than 32 quadrature points: iadpy-test06 moves by 1.1e-4 (UR1) and
// 4.9e-4 (URU) from 16 to 32 points; for the 8-point iad-adbasic row we allow 1e-3.
double quadratureAllowance(const std::map<std::string, std::string>& row) {
  const std::string& q = row.at("photons_or_quadrature");
  if (q.find("quadrature points") == std::string::npos || q.find("q=32") != std::string::npos)
    return 0.0;
  return 1e-3;
}

std::vector<Check> checksForRow(BenchmarkRunner& runner,
                                const std::map<std::string, std::string>& row) {
  const std::string& caseId = row.at("case_id");
  const std::vector<std::string> tokens = split(row.at("quantity"), " / ");
  const std::vector<std::string> values = publishedValues(row);
  if (tokens.size() != values.size())
    throw std::runtime_error(caseId + ": quantities and values differ in number");
  std::vector<Check> checks;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const std::string token = trim(tokens[i]).substr(0, trim(tokens[i]).find(' '));
    const std::string valueText = trim(values[i]);
    const double value = std::stod(valueText);
    checks.push_back({caseId + " " + token, ourQuantity(runner, caseId, token, row.at("quantity")),
                      value, publishedSigma(row, token, value),
                      roundingAllowance(valueText) + quadratureAllowance(row)});
  }
  // The MCML 1.2 sample also lists absorptance per layer in its notes: "A_l per layer = a / b / c".
  const std::string& notes = row.at("notes");
  const std::size_t perLayer = notes.find("A_l per layer = ");
  if (perLayer != std::string::npos) {
    const auto layerValues = split(notes.substr(perLayer + 16), " / ");
    const SlabResult& r = runner.result(caseId, false);
    for (std::size_t l = 0; l < layerValues.size(); ++l) {
      const std::string valueText = trim(layerValues[l]);
      const double value = std::stod(valueText);
      checks.push_back({caseId + " A_layer" + std::to_string(l + 1), r.layerAbsorptance.at(l),
                        value, publishedSigma(row, "A", value), roundingAllowance(valueText)});
    }
  }
  return checks;
}

TEST(LayeredSlabTest, AgreesWithEveryPublishedBenchmark) {
  // Pass if |ours - published| <= 3 sqrt(sigma_ours^2 + sigma_published^2) + allowance.
  const auto rows = readBenchmarks();
  ASSERT_EQ(rows.size(), 35u);
  BenchmarkRunner runner;
  std::printf("%-30s %12s %10s %12s %10s %9s %7s\n", "case quantity", "ours", "sigma", "published",
              "sigma", "allow", "z");
  for (const auto& row : rows) {
    for (const Check& c : checksForRow(runner, row)) {
      const double sigma = std::hypot(c.ours.standardError, c.publishedSigma);
      const double difference = c.ours.mean - c.published;
      const double z = sigma > 0 ? difference / sigma : 0.0;
      std::printf("%-30s %12.6f %10.2e %12.6f %10.2e %9.1e %7.2f\n", c.label.c_str(), c.ours.mean,
                  c.ours.standardError, c.published, c.publishedSigma, c.allowance, z);
      EXPECT_LE(std::fabs(difference), 3 * sigma + c.allowance) << c.label;
    }
  }
}

// ---- Closed forms for non-scattering plates (incoherent multiple reflections) ----

// A plate of index n in air, absorption mua, thickness d, beam at angleDeg: with R the Fresnel
// reflectance at the entry angle and a = exp(-mua d / cos t), the incoherent sums give
// R_total = R + (1-R)^2 R a^2 / (1 - R^2 a^2) and T = (1-R)^2 a / (1 - R^2 a^2).
TEST(LayeredSlabTest, NonScatteringPlateMatchesIncoherentSums) {
  for (const double angleDeg : {0.0, 50.0}) {
    for (const double muA : {0.0, 3.0}) {
      const SlabProblem plate = singleLayer(1.0, {1.5, muA, 0.0, 0.0, 0.2}, 1.0, angleDeg);
      const double cosI = std::cos(angleDeg * kPi / 180.0);
      const FresnelResult f = fresnel(cosI, 1.0, 1.5);
      const double a = std::exp(-muA * 0.2 / f.cosTransmitted), R = f.reflectance;
      const double expectedT = (1 - R) * (1 - R) * a / (1 - R * R * a * a);
      const double expectedRd = (1 - R) * (1 - R) * R * a * a / (1 - R * R * a * a);
      SlabRunOptions options;
      options.photons = 100000;
      const SlabResult r = simulateLayeredSlab(plate, options);
      EXPECT_DOUBLE_EQ(r.specularReflectance, R);
      // Binomial sigmas <= sqrt(0.25 / 1e5) = 1.6e-3; tolerance 4 sigma of each estimate.
      EXPECT_NEAR(r.transmittance.mean, expectedT, 4 * r.transmittance.standardError) << angleDeg;
      EXPECT_NEAR(r.diffuseReflectance.mean, expectedRd, 4 * r.diffuseReflectance.standardError);
      EXPECT_EQ(r.unscatteredTransmittance.mean, r.transmittance.mean);  // nothing scatters
    }
  }
}

// Two lossless glasses 1.5 | 1.3 in air at normal incidence: three interfaces with
// R_i = ((n - n')/(n + n'))^2, combined by the adding rule for incoherent reflectors:
// T_12 = T_1 T_2 / (1 - R_1 R_2), R_12 (from below) = R_2 + T_2^2 R_1 / (1 - R_1 R_2),
// T = T_12 T_3 / (1 - R_12 R_3). Checks Fresnel between layers of different index.
TEST(LayeredSlabTest, TwoGlassLayersMatchAddingRule) {
  SlabProblem stack;
  stack.layers = {{1.5, 0, 0, 0, 0.1}, {1.3, 0, 0, 0, 0.05}};
  auto r = [](double n1, double n2) { return (n1 - n2) * (n1 - n2) / ((n1 + n2) * (n1 + n2)); };
  const double R1 = r(1.0, 1.5), R2 = r(1.5, 1.3), R3 = r(1.3, 1.0);
  const double T12 = (1 - R1) * (1 - R2) / (1 - R1 * R2);
  const double R12below = R2 + (1 - R2) * (1 - R2) * R1 / (1 - R1 * R2);
  const double expectedT = T12 * (1 - R3) / (1 - R12below * R3);  // = 0.9268...
  SlabRunOptions options;
  options.photons = 200000;
  const SlabResult result = simulateLayeredSlab(stack, options);
  // sigma = sqrt(T (1 - T) / N) = 5.8e-4; tolerance 4 sigma.
  EXPECT_NEAR(result.transmittance.mean, expectedT, 4 * result.transmittance.standardError);
  EXPECT_NEAR(
      result.specularReflectance + result.diffuseReflectance.mean + result.transmittance.mean, 1.0,
      1e-12);
}

// ---- Energy balance ----

std::vector<SlabProblem> energyBalanceProblems() {
  return {mcmlThreeLayerSample(), problemForCase("T6.2-mcml"), test::mismatchedSlab()};
}

TEST(LayeredSlabTest, AnalogPacketsScoreTheirWholeWeightExactlyOnce) {
  for (const SlabProblem& problem : energyBalanceProblems()) {
    const SlabWalker walker(problem, AbsorptionScheme::Analog);
    const double launchWeight = 1.0 - walker.specularReflectance();
    PhotonScores scores;
    for (std::uint64_t i = 0; i < 20000; ++i) {
      Rng rng(5, 0, i);
      walker.trace(rng, scores);
      double total = scores.diffuseReflectance + scores.transmittance;
      int nonzero = (scores.diffuseReflectance > 0) + (scores.transmittance > 0);
      for (double a : scores.layerAbsorptance) {
        total += a;
        nonzero += a > 0;
      }
      ASSERT_EQ(nonzero, 1) << "photon " << i;
      ASSERT_EQ(total, launchWeight) << "photon " << i;
    }
  }
}

TEST(LayeredSlabTest, WeightedPacketsBalanceEnergyInExpectation) {
  for (const SlabProblem& problem : energyBalanceProblems()) {
    const SlabWalker walker(problem, AbsorptionScheme::WeightWithRoulette);
    RunningStatistic total;
    PhotonScores scores;
    for (std::uint64_t i = 0; i < 20000; ++i) {
      Rng rng(6, 0, i);
      walker.trace(rng, scores);
      double sum = walker.specularReflectance() + scores.diffuseReflectance + scores.transmittance;
      for (double a : scores.layerAbsorptance) sum += a;
      total.add(sum);
    }
    // Roulette makes single packets gain or lose weight; the mean is 1 (sigma printed on failure).
    EXPECT_NEAR(total.mean(), 1.0, 4 * total.standardError()) << "sigma " << total.standardError();
  }
}

TEST(LayeredSlabTest, WeightedAndAnalogAbsorptionGiveTheSameMeans) {
  SlabRunOptions options;
  options.photons = 200000;
  options.seed = 3;
  const SlabResult analog = simulateLayeredSlab(mcmlThreeLayerSample(), options);
  options.scheme = AbsorptionScheme::WeightWithRoulette;
  const SlabResult weighted = simulateLayeredSlab(mcmlThreeLayerSample(), options);
  auto expectSame = [](const Estimate& a, const Estimate& b, const char* what) {
    // Independent runs (different random paths): 4 combined sigma (~1.3e-3 for Rd at 2e5).
    EXPECT_NEAR(a.mean, b.mean, 4 * std::hypot(a.standardError, b.standardError)) << what;
  };
  expectSame(analog.diffuseReflectance, weighted.diffuseReflectance, "Rd");
  expectSame(analog.transmittance, weighted.transmittance, "Tt");
  expectSame(analog.absorptance, weighted.absorptance, "A");
  for (std::size_t l = 0; l < 3; ++l)
    expectSame(analog.layerAbsorptance[l], weighted.layerAbsorptance[l], "A layer");
  // Implicit capture lowers the variance of the absorption tallies.
  EXPECT_LT(weighted.absorptance.standardError, analog.absorptance.standardError);
}

// ---- Geometry: hop across boundaries ----

void expectSameOutcomes(const SlabProblem& a, const SlabProblem& b) {
  const SlabWalker walkerA(a, AbsorptionScheme::Analog), walkerB(b, AbsorptionScheme::Analog);
  PhotonScores sa, sb;
  for (std::uint64_t i = 0; i < 20000; ++i) {
    Rng rngA(8, 0, i), rngB(8, 0, i);
    walkerA.trace(rngA, sa);
    walkerB.trace(rngB, sb);
    ASSERT_EQ(sa.diffuseReflectance, sb.diffuseReflectance) << "photon " << i;
    ASSERT_EQ(sa.transmittance, sb.transmittance) << "photon " << i;
    ASSERT_EQ(sa.unscatteredTransmittance, sb.unscatteredTransmittance) << "photon " << i;
  }
}

TEST(LayeredSlabTest, SplittingALayerAndAddingAnEmptyOneChangeNoPath) {
  // The optical depth left at a boundary is carried into the next layer, and matched boundaries
  // draw no random number, so each photon takes the same path (up to rounding) and ends alike.
  const SlabProblem whole = problemForCase("T6.1-mcml");
  SlabProblem split = whole;
  SlabLayer half = whole.layers[0];
  half.thicknessCm = 0.01;
  SlabLayer empty = half;
  empty.thicknessCm = 0.0;
  split.layers = {half, empty, half};
  expectSameOutcomes(whole, split);
}

TEST(LayeredSlabTest, SemiInfiniteEqualsVeryThick) {
  SlabProblem thick = problemForCase("mcml2-sample1b");
  thick.layers[0].thicknessCm = 1e8;  // MCML's sample1b
  expectSameOutcomes(problemForCase("mcml2-sample1b"), thick);
}

TEST(LayeredSlabTest, UnscatteredBeamThroughMatchedSlabIsBeerLambert) {
  // exp(-mut d / cos t) at 40 deg through a matched slab, mut = 10 cm^-1, d = 0.05 cm:
  // exp(-0.5 / 0.766) = 0.5206. sigma = sqrt(p (1 - p) / 1e5) = 1.6e-3; 4 sigma.
  const SlabProblem slab = singleLayer(1.0, {1.0, 2, 8, 0.9, 0.05}, 1.0, 40.0);
  SlabRunOptions options;
  options.photons = 100000;
  const SlabResult r = simulateLayeredSlab(slab, options);
  const double expected = std::exp(-0.5 / std::cos(40.0 * kPi / 180.0));
  EXPECT_NEAR(r.unscatteredTransmittance.mean, expected,
              4 * r.unscatteredTransmittance.standardError);
}

// ---- Diffuse incidence ----

TEST(LayeredSlabTest, DiffuseEntryCosineFollowsItsDensityChiSquare) {
  // Density of the entering light's ambient cosine: 2 mu (1 - R(mu)) / (1 - Rsp), n 1 -> 1.4.
  SlabProblem problem = singleLayer(1.0, {1.4, 1, 1, 0, 1}, 1.0);
  problem.diffuseIncidence = true;
  const SlabWalker walker(problem, AbsorptionScheme::Analog);
  const int bins = 20, samples = 200000;
  std::vector<double> expected(bins, 0.0);
  for (int b = 0; b < bins; ++b) {  // midpoint rule, 1000 points per bin
    for (int k = 0; k < 1000; ++k) {
      const double mu = (b + (k + 0.5) / 1000.0) / bins;
      expected[b] += 2 * mu * (1 - fresnelReflectance(mu, 1.0, 1.4)) / (1000.0 * bins);
    }
    expected[b] *= samples / (1 - walker.specularReflectance());
  }
  std::vector<int> observed(bins, 0);
  Rng rng(77);
  for (int i = 0; i < samples; ++i)
    ++observed[std::min(bins - 1, static_cast<int>(walker.sampleDiffuseEntryCos(rng) * bins))];
  double chiSquare = 0;
  for (int b = 0; b < bins; ++b) chiSquare += std::pow(observed[b] - expected[b], 2) / expected[b];
  EXPECT_LT(chiSquare, 43.8);  // 19 degrees of freedom, p = 0.001
  // Hemispherical specular reflectance 2 int R(mu) mu dmu, computed independently with the angle
  // forms R_s = sin^2(i-t)/sin^2(i+t), R_p = tan^2(i-t)/tan^2(i+t) and a 2e5-point midpoint rule:
  // air -> 1.4: 0.0768115; 1.4 -> 1.0 (light from the denser side, TIR beyond 45.6 deg): 0.528985.
  EXPECT_NEAR(walker.specularReflectance(), 0.0768115, 1e-6);
  SlabProblem fromDense = singleLayer(1.4, {1.0, 1, 1, 0, 1}, 1.0);
  fromDense.diffuseIncidence = true;
  EXPECT_NEAR(SlabWalker(fromDense, AbsorptionScheme::Analog).specularReflectance(), 0.528985,
              1e-6);
}

// ---- Determinism and validation ----

TEST(LayeredSlabTest, ResultIsIdenticalAtOneAndTwoThreadsAndAcrossRuns) {
  SlabRunOptions options;
  options.photons = 30000;  // several chunks
  options.seed = 12;
  auto run = [&](int threads) {
    const hylios::ThreadLimit limit(threads);
    return simulateLayeredSlab(mcmlThreeLayerSample(), options);
  };
  const SlabResult one = run(1), two = run(2), again = run(2);
  for (const SlabResult* other : {&two, &again}) {
    EXPECT_EQ(one.diffuseReflectance.mean, other->diffuseReflectance.mean);
    EXPECT_EQ(one.diffuseReflectance.standardError, other->diffuseReflectance.standardError);
    EXPECT_EQ(one.transmittance.mean, other->transmittance.mean);
    EXPECT_EQ(one.absorptance.standardError, other->absorptance.standardError);
    for (std::size_t l = 0; l < 3; ++l)
      EXPECT_EQ(one.layerAbsorptance[l].mean, other->layerAbsorptance[l].mean);
  }
  options.seed = 13;
  EXPECT_NE(run(2).diffuseReflectance.mean, one.diffuseReflectance.mean);
}

TEST(LayeredSlabTest, PhotonIUsesStreamSeedZeroI) {
  SlabRunOptions options;
  options.photons = 50;
  options.seed = 4;
  const SlabResult r = simulateLayeredSlab(mcmlThreeLayerSample(), options);
  const SlabWalker walker(mcmlThreeLayerSample(), AbsorptionScheme::Analog);
  RunningStatistic rd;
  PhotonScores scores;
  for (std::uint64_t i = 0; i < 50; ++i) {
    Rng rng(4, 0, i);
    walker.trace(rng, scores);
    rd.add(scores.diffuseReflectance);
  }
  EXPECT_EQ(r.diffuseReflectance.mean, rd.mean());
}

TEST(LayeredSlabTest, InvalidProblemsAreRejectedWithTheirPlace) {
  auto message = [](const SlabProblem& p) {
    try {
      validateSlabProblem(p);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  SlabProblem p = mcmlThreeLayerSample();
  EXPECT_EQ(message(p), "accepted");
  SlabProblem bad = p;
  bad.layers[1].muA_perCm = -1;
  EXPECT_NE(message(bad).find("layer 2: mua"), std::string::npos) << message(bad);
  bad = p;
  bad.layers[2].muS_perCm = std::nan("");
  EXPECT_NE(message(bad).find("layer 3: mus"), std::string::npos);
  bad = p;
  bad.layers[0].anisotropyG = 1.0;
  EXPECT_NE(message(bad).find("layer 1: g"), std::string::npos);
  bad = p;
  bad.layers[0].thicknessCm = kInf;
  EXPECT_NE(message(bad).find("only the last layer"), std::string::npos);
  bad = p;
  bad.layers[2] = {1.37, 0, 0, 0, kInf};
  EXPECT_NE(message(bad).find("semi-infinite"), std::string::npos);
  bad = p;
  bad.incidenceAngleDeg = 90;
  EXPECT_NE(message(bad).find("incidence angle"), std::string::npos);
  bad = p;
  bad.refractiveIndexBelow = 0;
  EXPECT_NE(message(bad).find("ambient below"), std::string::npos);
  bad.layers.clear();
  EXPECT_THROW(simulateLayeredSlab(bad, {}), std::invalid_argument);
}

}  // namespace
}  // namespace hylios::skin
