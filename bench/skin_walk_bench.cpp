// Throughput of the HyLIoS walk (rays/s, one thread) for specimens S1 and S4 at 365, 550, 1100 and
// 1650 nm (45° incidence, the paper's full model; skinWalkTabulated: the same with
// WalkOptions::tabulatedMelanosomes, issue 5), and of the MCML three-layer sample slab
// (photons/s, analog absorption, one thread). items_per_second is the figure to read.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>

#include "skin/core/thread_limit.h"
#include "skin/layered_slab.h"
#include "skin/skin_simulation.h"
#include "skin/specimen.h"
#include "skin/spectral_database.h"

namespace {
using namespace hylios::skin;

std::filesystem::path dataRoot() {
  const char* fromEnvironment = std::getenv("HYLIOS_DATA_DIR");
  return fromEnvironment ? std::filesystem::path(fromEnvironment)
                         : std::filesystem::path(HYLIOS_SOURCE_DIR);
}

const SpectralDatabase& spectra() {
  static const SpectralDatabase database =
      SpectralDatabase::load(dataRoot() / "assets" / "spectra");
  return database;
}

const Specimen& specimen(const std::string& name) {
  static std::map<std::string, Specimen> loaded;
  auto it = loaded.find(name);
  if (it == loaded.end())
    it = loaded.emplace(name, loadSpecimen(name, dataRoot() / "scenes" / "specimens")).first;
  return it->second;
}

/// Rays per iteration: enough that one iteration is a few milliseconds at the slowest wavelength.
constexpr std::uint64_t kRaysPerIteration = 8192;

void skinWalkWith(benchmark::State& state, const std::string& specimenName,
                  bool tabulatedMelanosomes) {
  const hylios::ThreadLimit oneThread(1);
  const double wavelengthNm = static_cast<double>(state.range(0));
  const SkinOptics optics = computeSkinOptics(specimen(specimenName), spectra(), wavelengthNm);
  WalkRunOptions run;
  run.incidenceDeg = 45;
  run.rays = kRaysPerIteration;
  run.walk.tabulatedMelanosomes = tabulatedMelanosomes;
  double events = 0;
  for (auto _ : state) {
    const SkinTally tally = simulateSkin(optics, run);
    events = tally.meanEvents();
    benchmark::DoNotOptimize(tally);
    run.seed += 1;  // fresh rays each iteration
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kRaysPerIteration));
  state.counters["events_per_ray"] = events;
}

void skinWalk(benchmark::State& state, const std::string& specimenName) {
  skinWalkWith(state, specimenName, false);
}

void skinWalkTabulated(benchmark::State& state, const std::string& specimenName) {
  skinWalkWith(state, specimenName, true);
}

void mcmlThreeLayerSlab(benchmark::State& state) {
  const hylios::ThreadLimit oneThread(1);
  // MCML manual Table 6.7 / the MCML sample input: three layers of n = 1.37 in air.
  SlabProblem problem;
  problem.layers = {{1.37, 1, 100, 0.9, 0.1}, {1.37, 1, 10, 0.0, 0.1}, {1.37, 2, 10, 0.7, 0.2}};
  SlabRunOptions run;
  run.photons = 50000;
  // Arg 0: analog; 1: weighted, one packet at a time (double); 2: weighted in eight float lanes.
  run.scheme =
      state.range(0) == 0 ? AbsorptionScheme::Analog : AbsorptionScheme::WeightWithRoulette;
  run.laneWalk = state.range(0) == 2;
  for (auto _ : state) {
    benchmark::DoNotOptimize(simulateLayeredSlab(problem, run));
    run.seed += 1;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * run.photons));
}

/// The wavelengths (nm) of the walk benchmarks, timed in ms of process CPU time.
void atWalkWavelengths(benchmark::internal::Benchmark* b) {
  for (int nm : {365, 550, 1100, 1650}) b->Arg(nm);
  b->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
}

}  // namespace

BENCHMARK_CAPTURE(skinWalk, S1, std::string("S1"))->Apply(atWalkWavelengths);
BENCHMARK_CAPTURE(skinWalk, S4, std::string("S4"))->Apply(atWalkWavelengths);
BENCHMARK_CAPTURE(skinWalkTabulated, S1, std::string("S1"))->Apply(atWalkWavelengths);
BENCHMARK_CAPTURE(skinWalkTabulated, S4, std::string("S4"))->Apply(atWalkWavelengths);
BENCHMARK(mcmlThreeLayerSlab)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();

BENCHMARK_MAIN();
