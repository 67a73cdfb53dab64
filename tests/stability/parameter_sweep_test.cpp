// A sweep over 10⁴ random specimens × wavelengths × incidence angles, with parameters inside and
// at the edges of their physiological ranges (each parameter takes an edge value with
// probability 1/4). Each combination runs 200 rays and must give finite results, exact energy
// balance and no ray stopped by the event bound; and the spectral walk on a bundle of wavelengths
// around it must give finite weights within their bounds. The combinations are drawn from a fixed
// seed, so a failure names a reproducible case.
#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include "skin/core/random.h"
#include "skin/skin_optics.h"
#include "skin/skin_simulation.h"
#include "skin/specimen.h"
#include "skin/spectral_bundle.h"
#include "skin/spectral_database.h"
#include "skin/spectral_walk.h"

using namespace hylios::skin;

namespace {

const std::string kRoot = HYLIOS_SOURCE_DIR;

struct Range {
  const char* key;
  double low, high;
};

// Physiological ranges (paper Sec. 3 and Table 1, widened to the edges the model must survive).
constexpr Range kRanges[] = {
    {"melanosome_percent", 0, 10},
    {"colloidal_melanin_percent", 0, 30},
    {"blood_percent", 0, 10},
    {"oxygenation_percent", 0, 100},
    {"water_reduction_percent", 0, 100},
    {"surface_fold_aspect_ratio", 0.05, 2},
};

double draw(Rng& rng, double low, double high) {
  const double u = rng.uniform();
  if (u < 0.125) return low;
  if (u < 0.25) return high;
  return low + (high - low) * rng.uniform();
}

}  // namespace

TEST(ParameterSweep, TenThousandCombinationsStayFiniteBalancedAndBounded) {
  const SpectralDatabase spectra = SpectralDatabase::load(kRoot + "/assets/spectra");
  std::vector<Specimen> bases;
  for (const char* name : {"S1", "S2", "S3", "S4"})
    bases.push_back(loadSpecimen(name, kRoot + "/scenes/specimens"));
  constexpr int kCombinations = 10000;
  std::atomic<int> failures{0};
  std::mutex reportMutex;
  std::ostringstream report;
  tbb::parallel_for(0, kCombinations, [&](int i) {
    Rng rng(99, 0, static_cast<std::uint64_t>(i));
    Specimen s = bases[static_cast<std::size_t>(rng.uniform() * 4)];
    std::ostringstream description;
    description << "#" << i << " " << s.name;
    for (const Range& r : kRanges) {
      const double value = draw(rng, r.low, r.high);
      applyOverride(s, {r.key, value, "sweep"});
      description << " " << r.key << "=" << value;
    }
    const double wavelengthNm = draw(rng, 250, 2500);
    WalkRunOptions options;
    options.incidenceDeg = draw(rng, 0, 89.9);
    options.rays = 200;
    options.seed = static_cast<std::uint64_t>(i);
    description << " λ=" << wavelengthNm << " angle=" << options.incidenceDeg;
    const SkinTally t = simulateSkin(computeSkinOptics(s, spectra, wavelengthNm), options);
    // The spectral walk on a bundle around λ: every weight finite and within its bound (an exit
    // weight is roulette × transmittance × MIS ratio ≤ 1 × 1 × N; a split surface weight ≤ 1).
    std::vector<SkinOptics> near;
    for (double dw : {0.0, 3.0, 7.0})
      if (wavelengthNm + dw <= 2500)
        near.push_back(computeSkinOptics(s, spectra, wavelengthNm + dw));
    bool weightsOk = true;
    double worstWeight = 0;
    SpectralPath path;
    WalkOptions split;
    split.splitEntryReflection = (i % 2) == 0;
    split.tabulatedMelanosomes = (i % 3) == 0;
    for (const auto& members : groupIntoBundles(near, split)) {
      std::vector<SkinOptics> bundle;
      for (std::size_t m : members) bundle.push_back(near[m]);
      const SpectralWalk walk(bundle, split);
      for (std::uint64_t ray = 0; ray < 20; ++ray) {
        Rng walkRng(options.seed, 1, ray);
        walk.trace(incidentDirection(options.incidenceDeg), walkRng, path);
        for (std::size_t k = 0; k < bundle.size(); ++k) {
          const double w = path.exitWeight[k], a = path.absorbedTotal[k];
          const double surface = path.surfaceWeight.empty() ? 0.0 : path.surfaceWeight[k];
          worstWeight = std::max(worstWeight, w);
          weightsOk = weightsOk && std::isfinite(w) && std::isfinite(a) && w >= 0 &&
                      w <= static_cast<double>(bundle.size()) * (1 + 1e-12) && surface >= 0 &&
                      surface <= 1 && path.end != PathEnd::EventLimit;
        }
      }
    }
    const double balance = t.reflectance().mean + t.transmittance().mean + t.absorptance().mean;
    const bool ok = std::isfinite(balance) && std::fabs(balance - 1.0) < 1e-12 &&
                    std::isfinite(t.reflectance().standardError) && t.eventLimited().mean == 0.0 &&
                    std::isfinite(t.meanEvents()) && weightsOk;
    if (!ok && failures.fetch_add(1) < 10) {
      std::lock_guard<std::mutex> lock(reportMutex);
      report << description.str() << ": R+T+A=" << balance << " limited=" << t.eventLimited().mean
             << " spectral weights " << (weightsOk ? "ok" : "out of bounds") << " (largest "
             << worstWeight << ")\n";
    }
  });
  EXPECT_EQ(failures.load(), 0) << report.str();
}
