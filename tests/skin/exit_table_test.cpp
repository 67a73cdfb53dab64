// ExitTable (skin/exit_table.h): the table mode agrees with the exact walk for specimen S1, its
// sampler reproduces its own stored distributions (chi-square), building is deterministic at any
// thread count, and the file format rejects every kind of damage.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <vector>

#include "skin/core/constants.h"
#include "skin/core/thread_limit.h"
#include "skin/exit_table.h"
#include "skin/skin_simulation.h"
#include "skin/specimen.h"
#include "skin/spectral_database.h"
#include "tests/support/chi2.h"
#include "tests/support/test_spectra.h"

using hylios::kPi;

using namespace hylios;
using namespace hylios::skin;

namespace {

using hylios::test::spectra;

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::path(HYLIOS_BINARY_DIR) / "exit_table_test";
  std::filesystem::create_directories(dir);
  return dir / name;
}

/// Statistics of many outcomes of one sampler (walk or table) at one incidence.
struct Outcomes {
  static constexpr int kPolarBins = 6;
  std::uint64_t rays = 0, reflected = 0, subsurface = 0, forward = 0;
  double radiusSum = 0, radiusSquares = 0;
  std::vector<std::uint64_t> polar = std::vector<std::uint64_t>(kPolarBins, 0);

  void add(const SkinPath& p) {
    ++rays;
    if (p.end == PathEnd::SurfaceReflection) ++reflected;
    if (p.end != PathEnd::SubsurfaceReflection) return;
    ++reflected;
    ++subsurface;
    if (p.exitOffsetXCm > 0) ++forward;  // exits on the side the light travels towards
    const double r = std::hypot(p.exitOffsetXCm, p.exitOffsetYCm);
    radiusSum += r;
    radiusSquares += r * r;
    polar[static_cast<std::size_t>(
        std::min(static_cast<int>(-p.exitDirection.z * kPolarBins), kPolarBins - 1))]++;
  }
  Estimate fraction(std::uint64_t count, std::uint64_t of) const {
    const double n = static_cast<double>(of), p = static_cast<double>(count) / n;
    return {p, std::sqrt(p * (1 - p) / (n - 1))};
  }
  Estimate meanRadius() const {
    const double n = static_cast<double>(subsurface), m = radiusSum / n;
    return {m, std::sqrt((radiusSquares / n - m * m) / (n - 1))};
  }
};

/// |a − b| within 4 combined σ, σ_table added for the table's own statistical error.
void expectAgree(const char* what, Estimate walk, Estimate table, double tableError) {
  const double sigma =
      std::sqrt(walk.standardError * walk.standardError +
                table.standardError * table.standardError + tableError * tableError);
  EXPECT_LT(std::fabs(walk.mean - table.mean), 4 * sigma)
      << what << ": walk " << walk.mean << " ± " << walk.standardError << ", table " << table.mean
      << " ± " << table.standardError << " (table's own error " << tableError << ")";
}

}  // namespace

class TableAgreesWithWalk : public ::testing::TestWithParam<double> {};

// Total reflectance, subsurface fraction, mean exit radius, forward fraction of the exit offset and
// the exit polar distribution at 0° and 50° incidence. Each comparison: 4 combined standard
// errors (walk sample, table sample, and the table's own error bounded by the largest bin s.e.).
TEST_P(TableAgreesWithWalk, S1) {
  const double wavelengthNm = GetParam();
  const SkinWalk walk(test::s1Optics(wavelengthNm));
  ExitTableSettings settings;
  settings.cosineBins = 16;
  settings.raysPerBin = 4000;
  const ExitTable table = ExitTable::build(walk, settings);
  // The table's own error: bounded by the largest per-bin standard error (the sampled mixture of
  // bins has weights summing to 1); for fractions of subsurface exits by 0.5/√(fewest exits in a
  // bin).
  double binError = 0, radiusError = 0, fewestExits = 1e300;
  for (int k = 0; k < table.bins(); ++k) {
    const BinStatistics s = table.statistics(k);
    binError = std::max(binError, s.subsurface.standardError);
    radiusError = std::max(radiusError, s.meanExitRadiusCm.standardError);
    fewestExits = std::min(fewestExits, s.subsurface.mean * static_cast<double>(s.rays));
  }
  const double exitFractionError = 0.5 / std::sqrt(fewestExits);
  const std::uint64_t rays = 40000;
  for (const double incidenceDeg : {0.0, 50.0}) {
    SCOPED_TRACE(testing::Message() << wavelengthNm << " nm, " << incidenceDeg << "°");
    const Vec3 incident = incidentDirection(incidenceDeg);
    Outcomes w, t;
    for (std::uint64_t i = 0; i < rays; ++i) {
      Rng a(11, 1, i), b(12, 2, i);
      w.add(walk.trace(incident, a));
      t.add(table.sample(incident, b));
    }
    expectAgree("reflectance", w.fraction(w.reflected, w.rays), t.fraction(t.reflected, t.rays),
                binError);
    expectAgree("subsurface", w.fraction(w.subsurface, w.rays), t.fraction(t.subsurface, t.rays),
                binError);
    expectAgree("mean exit radius (cm)", w.meanRadius(), t.meanRadius(), radiusError);
    expectAgree("forward exits", w.fraction(w.forward, w.subsurface),
                t.fraction(t.forward, t.subsurface), exitFractionError);
    for (int j = 0; j < Outcomes::kPolarBins; ++j)
      expectAgree("exit polar bin", w.fraction(w.polar[static_cast<std::size_t>(j)], w.subsurface),
                  t.fraction(t.polar[static_cast<std::size_t>(j)], t.subsurface),
                  exitFractionError);
  }
}

INSTANTIATE_TEST_SUITE_P(Wavelengths, TableAgreesWithWalk, ::testing::Values(365.0, 550.0, 800.0));

// ---- the sampler against the table's own distributions ----

class ExitTableSampling : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    ExitTableSettings settings;
    settings.cosineBins = 4;
    settings.raysPerBin = 6000;
    table_ = new ExitTable(ExitTable::build(SkinWalk(test::s1Optics(550)), settings));
  }
  static void TearDownTestSuite() { delete table_; }
  static const ExitTable* table_;
};
const ExitTable* ExitTableSampling::table_ = nullptr;

// Samples at a bin centre (transmitted azimuth 40°): radial cells, the offset azimuth relative to
// the transmitted azimuth, the exit polar bins, and the position within a log radial cell (uniform
// in log r), each a chi-square test at p > 1e-4.
TEST_F(ExitTableSampling, ReproducesTheStoredDistributions) {
  const ExitTable& table = *table_;
  const int bin = 2;
  const double mu = table.binCosine(bin), s = std::sqrt(1 - mu * mu), phiT = 40 * kPi / 180;
  const Vec3 transmitted{s * std::cos(phiT), s * std::sin(phiT), mu};
  const std::vector<double> radial = table.radialDistribution(bin);
  const std::vector<double> azimuth = table.offsetAzimuthDistribution(bin);
  const std::vector<double> polar = table.exitPolarDistribution(bin);
  std::vector<double> radialSeen(radial.size()), azimuthSeen(azimuth.size()),
      polarSeen(polar.size()), within(10);
  const int n = 200000;
  int subsurface = 0, positiveSide = 0;
  Rng rng(5);
  for (int i = 0; i < n; ++i) {
    const SkinPath p = table.sampleEntered(transmitted, rng);
    if (p.end != PathEnd::SubsurfaceReflection) continue;
    ++subsurface;
    const double r = std::hypot(p.exitOffsetXCm, p.exitOffsetYCm);
    int cell = 0;
    while (cell + 1 < static_cast<int>(radial.size()) && r >= table.radialCellUpperCm(bin, cell))
      ++cell;
    ASSERT_GE(r, table.radialCellLowerCm(cell));
    radialSeen[static_cast<std::size_t>(cell)]++;
    if (cell >= 1 && cell + 1 < static_cast<int>(radial.size())) {
      const double lo = table.radialCellLowerCm(cell), hi = table.radialCellUpperCm(bin, cell);
      within[std::min<std::size_t>(
          9, static_cast<std::size_t>(std::log(r / lo) / std::log(hi / lo) * 10))]++;
    }
    double rel = std::atan2(p.exitOffsetYCm, p.exitOffsetXCm) - phiT;
    rel = std::remainder(rel, 2 * kPi);
    if (rel > 0) ++positiveSide;
    azimuthSeen[std::min(
        azimuth.size() - 1,
        static_cast<std::size_t>(std::fabs(rel) / kPi * static_cast<double>(azimuth.size())))]++;
    polarSeen[std::min(
        polar.size() - 1,
        static_cast<std::size_t>(-p.exitDirection.z * static_cast<double>(polar.size())))]++;
  }
  auto expected = [&](const std::vector<double>& f, double total) {
    std::vector<double> e;
    for (double x : f) e.push_back(x * total);
    return e;
  };
  const double total = subsurface;
  for (auto [name, seen, probability] : {std::tuple{"radial", &radialSeen, &radial},
                                         std::tuple{"offset azimuth", &azimuthSeen, &azimuth},
                                         std::tuple{"exit polar", &polarSeen, &polar}}) {
    const auto result = test::chi2FromCounts(*seen, expected(*probability, total));
    EXPECT_TRUE(result.problem.empty()) << name << ": " << result.problem;
    EXPECT_GT(result.pValue, 1e-4)
        << name << ": chi2 " << result.statistic << ", dof " << result.degreesOfFreedom;
  }
  double inCells = 0;
  for (double c : within) inCells += c;
  const auto uniform = test::chi2FromCounts(within, std::vector<double>(10, inCells / 10));
  EXPECT_GT(uniform.pValue, 1e-4) << "log-uniform within radial cells: chi2 " << uniform.statistic;
  // The two sides of the incidence plane are equally likely: binomial s.e. 0.5/√n.
  EXPECT_LT(std::fabs(positiveSide / total - 0.5), 4 * 0.5 / std::sqrt(total));
  // Subsurface probability of the bin: binomial, sampling s.e. only (the table's value is exact).
  const double p = table.statistics(bin).subsurface.mean;
  EXPECT_LT(std::fabs(total / n - p), 4 * std::sqrt(p * (1 - p) / n));
}

// Between two bin centres the two bins are mixed with the linear-interpolation weights.
TEST_F(ExitTableSampling, InterpolatesLinearlyBetweenBinCentres) {
  const ExitTable& table = *table_;
  const double f = 0.3, mu = (1 - f) * table.binCosine(1) + f * table.binCosine(2);
  const double expected =
      (1 - f) * table.statistics(1).subsurface.mean + f * table.statistics(2).subsurface.mean;
  const int n = 200000;
  int subsurface = 0;
  Rng rng(9);
  for (int i = 0; i < n; ++i)
    subsurface += table.sampleEntered({std::sqrt(1 - mu * mu), 0, mu}, rng).end ==
                  PathEnd::SubsurfaceReflection;
  EXPECT_LT(std::fabs(static_cast<double>(subsurface) / n - expected),
            4 * std::sqrt(expected * (1 - expected) / n));
}

TEST_F(ExitTableSampling, AbsorptionAndSubsurfaceAddUpPerBin) {
  for (int k = 0; k < table_->bins(); ++k) {
    const BinStatistics s = table_->statistics(k);
    EXPECT_NEAR(s.subsurface.mean + s.absorbed.mean + s.transmitted.mean + s.eventLimited.mean, 1.0,
                1e-12);
    EXPECT_EQ(s.rays, 6000u);
    EXPECT_GT(s.meanExitRadiusCm.mean, 0);
  }
}

// ---- determinism and files ----

TEST(ExitTableFile, BuildIsTheSameAtAnyThreadCountAndRoundTrips) {
  const SkinWalk walk(test::s1Optics(450));
  ExitTableSettings settings;
  settings.cosineBins = 3;
  settings.raysPerBin = 5000;  // 3 chunks per bin
  const auto one = scratch("one.hxt"), two = scratch("two.hxt");
  {
    const hylios::ThreadLimit limit(1);
    ExitTable::build(walk, settings).write(one);
  }
  const ExitTable table = ExitTable::build(walk, settings);
  table.write(two);
  auto bytes = [](const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_EQ(bytes(one), bytes(two));
  std::string why;
  const auto read = ExitTable::read(two, walk, settings, &why);
  ASSERT_TRUE(read) << why;
  Rng a(3), b(3);
  for (int i = 0; i < 1000; ++i) {
    const SkinPath x = table.sample({0.3, 0, std::sqrt(0.91)}, a),
                   y = read->sample({0.3, 0, std::sqrt(0.91)}, b);
    ASSERT_EQ(x.end, y.end);
    ASSERT_EQ(x.exitOffsetXCm, y.exitOffsetXCm);
    ASSERT_EQ(x.exitDirection.z, y.exitDirection.z);
  }
}

TEST(ExitTableFile, DamagedStaleOrForeignFilesAreRejected) {
  const SkinWalk walk(test::s1Optics(450));
  ExitTableSettings settings;
  settings.cosineBins = 2;
  settings.raysPerBin = 300;
  const auto good = scratch("good.hxt");
  ExitTable::build(walk, settings).write(good);
  std::ifstream in(good, std::ios::binary);
  const std::string bytes(std::istreambuf_iterator<char>(in), {});
  std::string why;
  ASSERT_TRUE(ExitTable::read(good, walk, settings, &why)) << why;
  auto rejects = [&](const std::string& content, const char* reason) {
    const auto bad = scratch("bad.hxt");
    std::ofstream(bad, std::ios::binary | std::ios::trunc) << content;
    std::string whyNot;
    EXPECT_FALSE(ExitTable::read(bad, walk, settings, &whyNot)) << reason;
    EXPECT_FALSE(whyNot.empty()) << reason;
  };
  for (std::size_t size : {std::size_t{0}, std::size_t{7}, std::size_t{39}, std::size_t{40},
                           bytes.size() / 2, bytes.size() - 1})
    rejects(bytes.substr(0, size), "truncated");
  rejects(bytes + "x", "trailing byte");
  for (std::size_t at : {std::size_t{3}, std::size_t{9}, std::size_t{17}, std::size_t{25},
                         std::size_t{33}, std::size_t{41}, bytes.size() / 2, bytes.size() - 1}) {
    std::string flipped = bytes;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x10);
    rejects(flipped, "bit flip");
  }
  // A stale table: the same file read for other inputs (one coefficient changed, other settings).
  SkinOptics changed = walk.optics();
  changed.layers[1].muATotal_perCm *= 1.001;
  EXPECT_NE(ExitTable::key(changed, walk.options(), settings),
            ExitTable::key(walk.optics(), walk.options(), settings));
  EXPECT_FALSE(ExitTable::read(good, SkinWalk(changed), settings));
  ExitTableSettings moreRays = settings;
  moreRays.raysPerBin += 1;
  EXPECT_FALSE(ExitTable::read(good, walk, moreRays));
  WalkOptions noRayleigh;
  noRayleigh.rayleigh = false;
  EXPECT_FALSE(ExitTable::read(good, SkinWalk(walk.optics(), noRayleigh), settings));
  EXPECT_FALSE(ExitTable::read(scratch("missing.hxt"), walk, settings));
}

TEST(ExitTableFile, KeyCoversEveryInput) {
  const SkinOptics optics = test::s1Optics(550);
  const WalkOptions walk;
  const ExitTableSettings settings;
  const std::uint64_t base = ExitTable::key(optics, walk, settings);
  EXPECT_EQ(base, ExitTable::key(optics, walk, settings));
  std::vector<std::uint64_t> keys{base};
  auto withOptics = [&](auto change) {
    SkinOptics o = optics;
    change(o);
    keys.push_back(ExitTable::key(o, walk, settings));
  };
  withOptics([](SkinOptics& o) { o.wavelengthNm += 1; });
  withOptics([](SkinOptics& o) { o.layers[0].thicknessCm *= 1.01; });
  withOptics([](SkinOptics& o) { o.layers[2].muA_perCm[0] += 1e-9; });
  withOptics([](SkinOptics& o) { o.layers[4].muRayleigh_perCm += 1; });
  withOptics([](SkinOptics& o) { o.layers[3].melanosome.mu_perCm += 1; });
  withOptics([](SkinOptics& o) { o.melanosomeInteriorMuA_perCm += 1; });
  withOptics([](SkinOptics& o) { o.surfaceAspectRatio += 0.01; });
  auto withWalk = [&](auto change) {
    WalkOptions w = walk;
    change(w);
    keys.push_back(ExitTable::key(optics, w, settings));
  };
  withWalk([](WalkOptions& w) { w.melanosomes = false; });
  withWalk([](WalkOptions& w) { w.roughSurface = false; });
  withWalk([](WalkOptions& w) { w.deepestLayer = Layer::StratumBasale; });
  withWalk([](WalkOptions& w) { w.tabulatedMelanosomes = true; });
  auto withSettings = [&](auto change) {
    ExitTableSettings s = settings;
    change(s);
    keys.push_back(ExitTable::key(optics, walk, s));
  };
  withSettings([](ExitTableSettings& s) { s.cosineBins += 1; });
  withSettings([](ExitTableSettings& s) { s.seed += 1; });
  withSettings([](ExitTableSettings& s) { s.radialBins += 1; });
  withSettings([](ExitTableSettings& s) { s.polarBins += 1; });
  withSettings([](ExitTableSettings& s) { s.tabulatedMelanosomes = !s.tabulatedMelanosomes; });
  withSettings([](ExitTableSettings& s) { s.raysByUse = !s.raysByUse; });
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(std::unique(keys.begin(), keys.end()), keys.end())
      << "two different inputs gave the same key";
}

TEST(ExitTableFile, BadSettingsAreClearErrors) {
  const SkinWalk walk(test::s1Optics(550));
  ExitTableSettings settings;
  settings.cosineBins = 0;
  EXPECT_THROW(ExitTable::build(walk, settings), std::invalid_argument);
  settings.cosineBins = 4;
  settings.raysPerBin = 1;
  EXPECT_THROW(ExitTable::build(walk, settings), std::invalid_argument);
}
