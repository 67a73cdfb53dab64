// A band's exit tables sampled at once (skin/exit_table_bundle.h, issue 12): for every wavelength
// the weighted exits have the expectation of that wavelength's own table sampled alone
// (ExitTable::sample) — the surface and subsurface reflectance within 4 combined standard errors,
// the exit offsets' distribution (radius groups × side) by a chi-square over the groups' z-scores
// — in the visible (Rayleigh spread across the band) and the near IR (θo of Algorithm 2 differing
// across it), at 0°, 45° and 80° incidence, with and without the entry split; weights are finite
// and non-negative, also with the exit's draw and the first facet from stratified numbers, and
// mismatched bundles are refused.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "skin/core/constants.h"
#include "skin/core/statistics.h"
#include "skin/exit_table_bundle.h"
#include "skin/specimen.h"
#include "tests/support/chi2.h"
#include "tests/support/test_spectra.h"

using namespace hylios;
using namespace hylios::skin;

namespace {

constexpr int kRadiusGroups = 5;  // exit radius groups, each split by the sign of the x offset
constexpr double kGroupEdgesCm[kRadiusGroups - 1] = {0.005, 0.02, 0.06, 0.2};

int offsetGroup(double xCm, double yCm) {
  const double r = std::hypot(xCm, yCm);
  int g = 0;
  while (g < kRadiusGroups - 1 && r >= kGroupEdgesCm[g]) ++g;
  return 2 * g + (xCm < 0 ? 1 : 0);
}

/// Per wavelength: surface and subsurface reflectance and the subsurface weight per offset group.
struct ExitTallies {
  std::vector<RunningStatistic> surface, subsurface;
  std::vector<std::vector<RunningStatistic>> groups;  // [λ][group]
  explicit ExitTallies(std::size_t n)
      : surface(n), subsurface(n), groups(n, std::vector<RunningStatistic>(2 * kRadiusGroups)) {}
};

struct Bundle {
  std::vector<SkinWalk> walks;
  std::vector<ExitTable> tables;
  std::vector<SkinOptics> optics;
  SpectralWalk entryWalk;
  Bundle(const std::vector<double>& wavelengthsNm, const ExitTableSettings& settings)
      : walks(makeWalks(wavelengthsNm)),
        tables(ExitTable::buildBundle(pointers(walks), settings)),
        optics(opticsOf(walks)),
        entryWalk(optics) {}
  static std::vector<SkinWalk> makeWalks(const std::vector<double>& nm) {
    static const Specimen specimen = loadSpecimen("S1", test::specimenDir());
    std::vector<SkinWalk> w;
    for (double x : nm) w.emplace_back(computeSkinOptics(specimen, test::spectra(), x));
    return w;
  }
  static std::vector<const SkinWalk*> pointers(const std::vector<SkinWalk>& w) {
    std::vector<const SkinWalk*> p;
    for (const SkinWalk& x : w) p.push_back(&x);
    return p;
  }
  static std::vector<SkinOptics> opticsOf(const std::vector<SkinWalk>& w) {
    std::vector<SkinOptics> o;
    for (const SkinWalk& x : w) o.push_back(x.optics());
    return o;
  }
  ExitTableBundle sampler() const {
    std::vector<const ExitTable*> t;
    for (const ExitTable& x : tables) t.push_back(&x);
    return ExitTableBundle(entryWalk, t);
  }
};

Vec3 incidence(double degrees) {
  const double a = degrees * kPi / 180;
  return {std::sin(a), 0, std::cos(a)};
}

/// Path p's numbers for the exit's draw and the entry's first facet from a rank-1 lattice (each
/// coordinate (p + 1/2)/paths or {p·g} for an irrational g): stratified, as a pixel sampler's are.
struct LatticeNumbers {
  std::array<double, 2> exit;
  FacetNumbers facet;
  LatticeNumbers(int p, int paths) {
    auto frac = [p](double g) { return std::fmod(p * g, 1.0); };
    exit = {(p + 0.5) / paths, frac(0.6180339887498949)};
    facet.polar = {frac(0.7548776662466927), frac(0.5698402909980532)};
    facet.azimuth = frac(0.4142135623730950);
  }
};

ExitTallies sampleBundle(const Bundle& b, double degrees, bool split, int paths, bool stratified) {
  const ExitTableBundle sampler = b.sampler();
  ExitTallies t(sampler.size());
  Rng rng(7);
  SpectralPath path;
  for (int p = 0; p < paths; ++p) {
    const LatticeNumbers numbers(p, paths);
    if (stratified)
      sampler.sample(incidence(degrees), rng, path, split, &numbers.exit, &numbers.facet);
    else
      sampler.sample(incidence(degrees), rng, path, split);
    for (std::size_t i = 0; i < sampler.size(); ++i) {
      const double w = path.exitWeight[i];
      EXPECT_TRUE(std::isfinite(w) && w >= 0) << w;
      const bool surface = path.end == PathEnd::SurfaceReflection;
      const double splitWeight = path.surfaceWeight.empty() ? 0.0 : path.surfaceWeight[i];
      t.surface[i].add((surface ? w : 0.0) + splitWeight);
      const bool subsurface = path.end == PathEnd::SubsurfaceReflection;
      t.subsurface[i].add(subsurface ? w : 0.0);
      const int g = subsurface ? offsetGroup(path.exitOffsetXCm, path.exitOffsetYCm) : -1;
      for (int k = 0; k < 2 * kRadiusGroups; ++k) t.groups[i][k].add(k == g ? w : 0.0);
    }
  }
  return t;
}

ExitTallies sampleEachTable(const Bundle& b, double degrees, int paths) {
  ExitTallies t(b.tables.size());
  for (std::size_t i = 0; i < b.tables.size(); ++i) {
    Rng rng(100 + i);
    for (int p = 0; p < paths; ++p) {
      const SkinPath path = b.tables[i].sample(incidence(degrees), rng);
      t.surface[i].add(path.end == PathEnd::SurfaceReflection ? 1.0 : 0.0);
      const bool subsurface = path.end == PathEnd::SubsurfaceReflection;
      t.subsurface[i].add(subsurface ? 1.0 : 0.0);
      const int g = subsurface ? offsetGroup(path.exitOffsetXCm, path.exitOffsetYCm) : -1;
      for (int k = 0; k < 2 * kRadiusGroups; ++k) t.groups[i][k].add(k == g ? 1.0 : 0.0);
    }
  }
  return t;
}

double zScore(const RunningStatistic& a, const RunningStatistic& b) {
  const double sigma = std::hypot(a.standardError(), b.standardError());
  return sigma > 0 ? (a.mean() - b.mean()) / sigma : (a.mean() == b.mean() ? 0.0 : 1e9);
}

void expectSameExits(const Bundle& b, double degrees, bool split, bool stratified = false) {
  const int paths = 60000;
  const ExitTallies bundle = sampleBundle(b, degrees, split, paths, stratified);
  const ExitTallies alone = sampleEachTable(b, degrees, paths);
  double chi2 = 0;
  int dof = 0;
  for (std::size_t i = 0; i < b.tables.size(); ++i) {
    const std::string at = std::to_string(b.optics[i].wavelengthNm) + " nm at " +
                           std::to_string(degrees) + "°" + (split ? ", split" : "") +
                           (stratified ? ", stratified" : "") + ": ";
    EXPECT_LT(std::fabs(zScore(bundle.surface[i], alone.surface[i])), 4.0)
        << at << "surface " << bundle.surface[i].mean() << " against " << alone.surface[i].mean();
    EXPECT_LT(std::fabs(zScore(bundle.subsurface[i], alone.subsurface[i])), 4.0)
        << at << "subsurface " << bundle.subsurface[i].mean() << " against "
        << alone.subsurface[i].mean();
    for (int k = 0; k < 2 * kRadiusGroups; ++k) {
      if (alone.groups[i][k].sum() < 20) continue;  // too few exits there for a normal z
      const double z = zScore(bundle.groups[i][k], alone.groups[i][k]);
      chi2 += z * z;
      ++dof;
    }
  }
  ASSERT_GT(dof, 10);
  EXPECT_GT(test::chi2SurvivalProbability(chi2, dof), 1e-3)
      << "offset groups: chi2 = " << chi2 << " over " << dof << " groups";
}

ExitTableSettings tableSettings() {
  ExitTableSettings s;
  s.cosineBins = 4;
  s.raysPerBin = 3000;
  return s;
}

}  // namespace

// Seven visible channels at once: the Rayleigh optical depth spans a factor of 3.7 across them.
TEST(ExitTableBundle, VisibleBandHasEachTablesExpectation) {
  const Bundle b({400, 450, 500, 550, 600, 650, 700}, tableSettings());
  for (double degrees : {0.0, 45.0, 80.0}) expectSameExits(b, degrees, false);
  expectSameExits(b, 45.0, true);
}

// The exit's draw and the entry's first facet from stratified numbers (a pixel sampler's, in the
// renderer): the same expectations. The z-scores take the paths as independent, which stratified
// numbers only make smaller, so the 4σ bounds hold a fortiori.
TEST(ExitTableBundle, StratifiedNumbersKeepEachTablesExpectation) {
  const Bundle b({400, 450, 500, 550, 600, 650, 700}, tableSettings());
  expectSameExits(b, 0.0, true, true);
  expectSameExits(b, 60.0, true, true);
  expectSameExits(b, 45.0, false, true);
}

// The θo ramp of Algorithm 2 (780–1400 nm) and water's rise: tables that differ widely.
TEST(ExitTableBundle, NearInfraredBandHasEachTablesExpectation) {
  const Bundle b({900, 1000, 1100, 1200, 1300}, tableSettings());
  expectSameExits(b, 0.0, false);
  expectSameExits(b, 45.0, true);
}

// The second stage's ratio has mean 1 given the entry: exitWeight − exitEntryWeight averages to 0,
// also when multiplied by any function of the entry (here exitEntryWeight itself), which the
// renderer's control variate needs (renderer/tracing/integrator.h). 4σ per wavelength.
TEST(ExitTableBundle, SecondStageAddsNothingInExpectationGivenTheEntry) {
  const Bundle b({400, 450, 500, 550, 600, 650, 700}, tableSettings());
  const ExitTableBundle sampler = b.sampler();
  for (double degrees : {0.0, 60.0}) {
    std::vector<RunningStatistic> difference(sampler.size()), weighted(sampler.size());
    Rng rng(11);
    SpectralPath path;
    std::size_t exits = 0;
    for (int p = 0; p < 60000; ++p) {
      sampler.sample(incidence(degrees), rng, path, true);
      const bool subsurface = path.end == PathEnd::SubsurfaceReflection;
      exits += subsurface;
      ASSERT_EQ(path.exitEntryWeight.size(), subsurface ? sampler.size() : 0u);
      for (std::size_t i = 0; i < sampler.size(); ++i) {
        const double d = subsurface ? path.exitWeight[i] - path.exitEntryWeight[i] : 0.0;
        difference[i].add(d);
        weighted[i].add(subsurface ? d * path.exitEntryWeight[i] : 0.0);
      }
    }
    ASSERT_GT(exits, 10000u);
    for (std::size_t i = 0; i < sampler.size(); ++i) {
      const std::string at =
          std::to_string(b.optics[i].wavelengthNm) + " nm at " + std::to_string(degrees) + "°";
      EXPECT_GT(difference[i].standardError(), 0) << at;
      EXPECT_LT(std::fabs(difference[i].mean()), 4 * difference[i].standardError()) << at;
      EXPECT_LT(std::fabs(weighted[i].mean()), 4 * weighted[i].standardError()) << at;
    }
  }
}

TEST(ExitTableBundle, RefusesMismatchedTables) {
  const Bundle b({500, 600}, tableSettings());
  EXPECT_THROW(ExitTableBundle(b.entryWalk, {&b.tables[0]}), std::invalid_argument);
  EXPECT_THROW(ExitTableBundle(b.entryWalk, {&b.tables[0], nullptr}), std::invalid_argument);
  ExitTableSettings other = tableSettings();
  other.cosineBins = 5;
  const Bundle c({600}, other);
  EXPECT_THROW(ExitTableBundle(b.entryWalk, {&b.tables[0], &c.tables[0]}), std::invalid_argument);
}
