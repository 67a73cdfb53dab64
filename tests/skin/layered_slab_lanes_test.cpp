// The slab's lane walk (skin/layered_slab_lanes.h) against the exact scalar walk it replaces
// (SlabWalker::trace, weighted scheme), on stacks that exercise every path of the lanes: the MCML
// sample, a semi-infinite plate of index 1.5, layers of different index with total internal
// reflection, a lossless gap and an empty layer, diffuse light, and a 12-layer stack (more than
// eight layers: the table look-ups gather instead of permuting). Also: MCML 1.2's own sample
// output, the event limit, energy balance, each packet's row, the same bytes at one and two
// threads, and the fallback to the scalar walk for stacks that single precision does not
// represent.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "skin/core/thread_limit.h"
#include "skin/layered_slab.h"
#include "skin/layered_slab_lanes.h"
#include "tests/support/score_family.h"
#include "tests/support/slab_problems.h"

namespace hylios::skin {
namespace {

struct NamedProblem {
  std::string name;
  SlabProblem problem;
};

std::vector<NamedProblem> lanesProblems() {
  SlabProblem diffuse = test::singleLayer(1.0, {1.4, 1, 20, 0.7, 0.1}, 1.2);
  diffuse.diffuseIncidence = true;
  SlabProblem twelveLayers;
  twelveLayers.refractiveIndexBelow = 1.4;
  for (int k = 0; k < 12; ++k)
    twelveLayers.layers.push_back(
        {1.3 + 0.02 * k, 0.5 + 0.2 * k, 30.0 - 2 * k, 0.9 - 0.1 * k, 0.02});
  twelveLayers.incidenceAngleDeg = 30;
  return {
      {"MCML sample", test::mcmlThreeLayerSample()},
      {"semi-infinite n 1.5", test::singleLayer(1.0, {1.5, 10, 90, 0.0, test::kSemiInfinite}, 1.0)},
      {"mismatched", test::mismatchedSlab()},
      {"diffuse light", diffuse},
      {"twelve layers", twelveLayers}};
}

SlabResult run(const SlabProblem& problem, bool lanes, std::uint64_t seed, std::uint64_t photons,
               std::uint32_t eventLimit = kSlabEventLimit) {
  SlabRunOptions options;
  options.eventLimit = eventLimit;
  options.photons = photons;
  options.seed = seed;
  options.scheme = AbsorptionScheme::WeightWithRoulette;
  options.laneWalk = lanes;
  return simulateLayeredSlab(problem, options);
}

TEST(SlabLaneWalker, MatchesTheScalarWalk) {
  // 2·10^5 packets each, independent seeds; every quantity of every stack is one score of the
  // family (difference over the combined standard error), judged at 1 % family-wise.
  test::ScoreFamily family;
  for (const NamedProblem& p : lanesProblems()) {
    const SlabResult lanes = run(p.problem, true, 31, 200000);
    const SlabResult scalar = run(p.problem, false, 32, 200000);
    auto compare = [&](const std::string& what, const Estimate& a, const Estimate& b) {
      family.add(p.name + " " + what,
                 test::zScore(a.mean - b.mean, std::hypot(a.standardError, b.standardError)));
    };
    compare("Rd", lanes.diffuseReflectance, scalar.diffuseReflectance);
    compare("Tt", lanes.transmittance, scalar.transmittance);
    compare("unscattered Tt", lanes.unscatteredTransmittance, scalar.unscatteredTransmittance);
    compare("A", lanes.absorptance, scalar.absorptance);
    for (std::size_t l = 0; l < lanes.layerAbsorptance.size(); ++l)
      compare("A layer " + std::to_string(l + 1), lanes.layerAbsorptance[l],
              scalar.layerAbsorptance[l]);
    // Same estimator, same variance per packet: the standard errors agree to sampling error
    // (a standard error from 2·10^5 heavy-tailed weights is good to a few per cent).
    EXPECT_NEAR(lanes.absorptance.standardError / scalar.absorptance.standardError, 1.0, 0.15)
        << p.name;
  }
  family.expectWithinFamilyWiseBound();
}

TEST(SlabLaneWalker, AgreesWithMcmlsOwnSampleOutput) {
  // MCML 1.2's sample.mco (tests/data/validation/mc_benchmarks_published.csv, mcml12-sample),
  // 10^6 photons: Rd 0.237544, Tt 0.0964896, A 0.641594, per layer 0.2612 / 0.1488 / 0.2316 (4
  // digits). Its standard errors are those of the same estimator at 10^6 photons, taken equal to
  // ours (MCML's per-photon spread, docs/benchmarks.md "Session 11": within 7 % of ours), so the
  // combined sigma is sqrt(2) of ours (Rd ~4.4e-4); 4 combined sigma, plus the rounding.
  const SlabResult r = run(test::mcmlThreeLayerSample(), true, 7, 1000000);
  auto expectNear = [](const Estimate& ours, double published, double rounding, const char* what) {
    EXPECT_NEAR(ours.mean, published, 4 * std::sqrt(2.0) * ours.standardError + rounding) << what;
  };
  expectNear(r.diffuseReflectance, 0.237544, 0, "Rd");
  expectNear(r.transmittance, 0.0964896, 0, "Tt");
  expectNear(r.absorptance, 0.641594, 0, "A");
  const double perLayer[3] = {0.2612, 0.1488, 0.2316};
  for (std::size_t l = 0; l < 3; ++l) expectNear(r.layerAbsorptance[l], perLayer[l], 5e-5, "A_l");
  EXPECT_NEAR(r.specularReflectance, 0.0243729, 1e-7);
}

TEST(SlabLaneWalker, StopsAtTheEventLimitAsTheScalarWalk) {
  // A limit of 60 events stops a good part of the MCML sample's packets (about 67 events on
  // average) and of the mismatched stack's: both walks must book the same weight as
  // event-limited and keep the same law for the rest (scores of one family, as above).
  test::ScoreFamily family;
  for (const SlabProblem& problem : {test::mcmlThreeLayerSample(), test::mismatchedSlab()}) {
    const SlabResult lanes = run(problem, true, 41, 100000, 60);
    const SlabResult scalar = run(problem, false, 42, 100000, 60);
    EXPECT_GT(lanes.eventLimited.mean, 0.01);
    auto compare = [&](const char* what, const Estimate& a, const Estimate& b) {
      family.add(what, test::zScore(a.mean - b.mean, std::hypot(a.standardError, b.standardError)));
    };
    compare("event-limited", lanes.eventLimited, scalar.eventLimited);
    compare("Rd", lanes.diffuseReflectance, scalar.diffuseReflectance);
    compare("Tt", lanes.transmittance, scalar.transmittance);
    compare("A", lanes.absorptance, scalar.absorptance);
    // What was stopped is neither reflected, transmitted nor absorbed: the balance holds with it.
    const double total = lanes.specularReflectance + lanes.diffuseReflectance.mean +
                         lanes.transmittance.mean + lanes.absorptance.mean +
                         lanes.eventLimited.mean;
    EXPECT_NEAR(
        total, 1.0,
        4 * std::hypot(lanes.absorptance.standardError, lanes.diffuseReflectance.standardError));
  }
  family.expectWithinFamilyWiseBound();
}

TEST(SlabLaneWalker, EndsInAScatteringLayerThatNeverAbsorbs) {
  // 10^6 optical depths that only scatter: a packet's stay has no finite mean (a random walk's
  // return time), so without the bound some of 2000 packets would take ~10^12 steps. With it,
  // the run ends; nothing is absorbed or transmitted, and each packet's weight (1: no roulette,
  // matched indices) is reflected or event-limited.
  const SlabProblem deep = test::singleLayer(1.0, {1.0, 0, 1e6, 0.0, 1.0}, 1.0);
  for (const bool lanes : {true, false}) {
    const SlabResult r = run(deep, lanes, 3, 2000);
    EXPECT_EQ(r.absorptance.mean, 0.0);
    EXPECT_EQ(r.transmittance.mean, 0.0);
    EXPECT_NEAR(r.diffuseReflectance.mean + r.eventLimited.mean, 1.0, 1e-6) << lanes;
  }
}

TEST(SlabLaneWalker, BalancesEnergyInExpectation) {
  for (const NamedProblem& p : lanesProblems()) {
    const SlabWalker walker(p.problem, AbsorptionScheme::WeightWithRoulette);
    const SlabLaneWalker lanes(walker);
    const std::uint64_t packets = 20000;
    std::vector<double> rows(packets * lanes.scoresPerPacket(), -1.0);
    lanes.trace(8, 0, packets, rows.data());
    RunningStatistic total;
    for (std::uint64_t i = 0; i < packets; ++i) {
      const double* row = rows.data() + i * lanes.scoresPerPacket();
      double sum = walker.specularReflectance();
      int exits = 0;
      for (std::size_t q = 0; q < lanes.scoresPerPacket(); ++q) {
        ASSERT_TRUE(std::isfinite(row[q]) && row[q] >= 0.0) << p.name << " packet " << i;
        if (q != SlabLaneWalker::kUnscatteredTransmittance) sum += row[q];
      }
      exits += row[SlabLaneWalker::kDiffuseReflectance] > 0;
      exits += row[SlabLaneWalker::kTransmittance] > 0;
      ASSERT_LE(exits, 1) << p.name << " packet " << i;
      ASSERT_LE(row[SlabLaneWalker::kUnscatteredTransmittance],
                row[SlabLaneWalker::kTransmittance]);
      total.add(sum);
    }
    // Roulette makes single packets gain or lose weight; the mean is 1.
    EXPECT_NEAR(total.mean(), 1.0, 4 * total.standardError())
        << p.name << ", sigma " << total.standardError();
  }
}

TEST(SlabLaneWalker, SameBytesAtOneAndTwoThreads) {
  for (const NamedProblem& p : lanesProblems()) {
    auto at = [&](int threads) {
      const ThreadLimit limit(threads);
      return run(p.problem, true, 12, 30000);  // several chunks of 4096
    };
    const SlabResult one = at(1), two = at(2);
    EXPECT_EQ(one.diffuseReflectance.mean, two.diffuseReflectance.mean) << p.name;
    EXPECT_EQ(one.diffuseReflectance.standardError, two.diffuseReflectance.standardError);
    EXPECT_EQ(one.transmittance.mean, two.transmittance.mean) << p.name;
    EXPECT_EQ(one.absorptance.mean, two.absorptance.mean) << p.name;
    for (std::size_t l = 0; l < one.layerAbsorptance.size(); ++l)
      EXPECT_EQ(one.layerAbsorptance[l].mean, two.layerAbsorptance[l].mean) << p.name;
  }
}

TEST(SlabLaneWalker, TakesOnlyStacksThatSinglePrecisionRepresents) {
  auto represented = [](const SlabProblem& problem) {
    return SlabLaneWalker::represents(SlabWalker(problem, AbsorptionScheme::WeightWithRoulette));
  };
  for (const NamedProblem& p : lanesProblems()) EXPECT_TRUE(represented(p.problem)) << p.name;
  SlabProblem dense = test::mcmlThreeLayerSample();
  dense.layers[1].muS_perCm = 2e30;  // beyond 1e30 cm^-1
  SlabProblem thinDeep = test::mcmlThreeLayerSample();
  thinDeep.layers[2].thicknessCm = 1e-4;  // 1e-4 cm at 0.2 cm depth: 2^-11 of its depth
  SlabProblem tiny = test::singleLayer(1.0, {1.4, 1, 10, 0.5, 1e-35}, 1.0);
  SlabProblem faint = test::singleLayer(1.0, {1.4, 1e-31, 0, 0.5, 0.1}, 1.0);
  for (const SlabProblem* problem : {&dense, &thinDeep, &tiny, &faint}) {
    EXPECT_FALSE(represented(*problem));
    const SlabWalker walker(*problem, AbsorptionScheme::WeightWithRoulette);
    EXPECT_THROW(SlabLaneWalker{walker}, std::invalid_argument);
    // simulateLayeredSlab falls back to the scalar walk: the same bytes as asking for it.
    const SlabResult asked = run(*problem, true, 4, 5000), scalar = run(*problem, false, 4, 5000);
    EXPECT_EQ(asked.diffuseReflectance.mean, scalar.diffuseReflectance.mean);
    EXPECT_EQ(asked.absorptance.mean, scalar.absorptance.mean);
  }
  SlabProblem thinShallow = test::mcmlThreeLayerSample();
  thinShallow.layers[0].thicknessCm = 1e-4;  // at its own depth: the whole of it
  EXPECT_TRUE(represented(thinShallow));
}

TEST(SlabLaneWalker, RefusesTheAnalogScheme) {
  const SlabWalker analog(test::mcmlThreeLayerSample(), AbsorptionScheme::Analog);
  EXPECT_THROW(SlabLaneWalker{analog}, std::invalid_argument);
}

}  // namespace
}  // namespace hylios::skin
