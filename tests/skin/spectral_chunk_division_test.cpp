// The work-division hook of the spectral estimator (skin/spectral_simulation.h) that the MPI layer
// uses (app/mpi_spectral.h): the chunks of any number of parts, each part run on its own and its
// tallies carried as bytes (SkinTally::appendBytes/fromBytes), merge into exactly the tallies of
// simulateSkinSpectral — every sum, count and histogram bin, bit for bit.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "skin/skin_optics.h"
#include "skin/spectral_simulation.h"
#include "tests/support/state_bytes.h"
#include "tests/support/test_spectra.h"

namespace hylios::skin {
namespace {

std::vector<SkinOptics> opticsAt(const char* name, const std::vector<double>& wavelengths) {
  const Specimen specimen = loadSpecimen(name, test::specimenDir());
  std::vector<SkinOptics> optics;
  for (double w : wavelengths) optics.push_back(computeSkinOptics(specimen, test::spectra(), w));
  return optics;
}

SpectralRunOptions run(std::uint64_t rays, const TallyOptions& tally) {
  SpectralRunOptions options;
  options.incidenceDeg = 30;
  options.rays = rays;
  options.seed = 9;
  options.walk.tabulatedMelanosomes = true;
  options.walk.splitEntryReflection = true;
  options.tally = tally;
  return options;
}

/// Runs `parts` parts separately, carries each part's chunk tallies through bytes, merges.
std::vector<SkinTally> dividedRun(const std::vector<SkinOptics>& optics,
                                  const SpectralRunOptions& options, std::size_t parts) {
  SpectralChunks all;
  for (std::size_t part = 0; part < parts; ++part) {
    const SpectralChunks mine = simulateSkinSpectralChunks(optics, options, part, parts);
    if (part == 0) {
      all.members = mine.members;
      all.tallies.resize(mine.tallies.size());
    }
    for (std::size_t c = 0; c < mine.tallies.size(); ++c) {
      if (c % parts != part) {
        EXPECT_TRUE(mine.tallies[c].empty()) << "part " << part << " ran chunk " << c;
        continue;
      }
      std::string bytes;
      for (const SkinTally& t : mine.tallies[c]) t.appendBytes(bytes);
      std::size_t offset = 0;
      for (std::size_t k = 0; k < mine.members[c].size(); ++k)
        all.tallies[c].push_back(SkinTally::fromBytes(options.tally, bytes, offset));
      EXPECT_EQ(offset, bytes.size());
    }
  }
  return mergeSpectralChunks(all, optics.size(), options.tally);
}

TEST(SpectralChunkDivision, AnyNumberOfPartsGivesTheUndividedTalliesBitForBit) {
  // 2500 rays: 3 chunks per bundle (1024, 1024, 452), so 2 and 3 parts split bundles unevenly,
  // and 7 parts leave some parts without a chunk.
  const std::vector<SkinOptics> optics = opticsAt("S1", {400, 430, 460, 550, 700, 1100});
  const SpectralRunOptions options = run(2500, {});
  const std::vector<SkinTally> whole = simulateSkinSpectral(optics, options);
  for (std::size_t parts : {1, 2, 3, 7}) {
    const std::vector<SkinTally> divided = dividedRun(optics, options, parts);
    ASSERT_EQ(divided.size(), whole.size());
    for (std::size_t i = 0; i < whole.size(); ++i) {
      EXPECT_EQ(hylios::test::stateBytes(divided[i]), hylios::test::stateBytes(whole[i]))
          << parts << " parts, wavelength " << i;
      EXPECT_EQ(divided[i].rays(), 2500u);
    }
  }
}

TEST(SpectralChunkDivision, HistogramsTravelAndMergeExactly) {
  // The brdf and radial-profile tallies: direction and radial histograms.
  TallyOptions tally;
  tally.polarBins = 6;
  tally.azimuthBins = 4;
  tally.radialBins = 10;
  const std::vector<SkinOptics> optics = opticsAt("S2", {450, 650});
  const SpectralRunOptions options = run(2100, tally);
  const std::vector<SkinTally> whole = simulateSkinSpectral(optics, options);
  const std::vector<SkinTally> divided = dividedRun(optics, options, 2);
  for (std::size_t i = 0; i < whole.size(); ++i) {
    EXPECT_EQ(hylios::test::stateBytes(divided[i]), hylios::test::stateBytes(whole[i]));
    ASSERT_TRUE(divided[i].radialExits().has_value());
    const std::size_t bin = 2;
    EXPECT_EQ(divided[i].radialExits()->estimate(bin).mean,
              whole[i].radialExits()->estimate(bin).mean);
  }
  // 24 direction bins + 2 (under/overflow) per histogram, three of them, and a radial one of 12:
  // a flag byte, then (spectral paths carry control weights) the control-variate sums: per fold a
  // count and the sums of U and U², per quantity (7 quantities, 6 layers) and fold the sums of T,
  // T² and T·U; the event count, then per histogram a packet count and 2 doubles per bin: 681
  // bytes per wavelength and chunk without histograms. An analog tally has 13 plain statistics
  // (count, sum, sum of squares) instead of the control-variate sums.
  EXPECT_EQ(hylios::test::stateBytes(whole[0]).size(),
            1 + 2 * 24 + 26 * 24 + 8 + 3 * (8 + 26 * 16) + (8 + 12 * 16));
  EXPECT_EQ(hylios::test::stateBytes(SkinTally()).size(), 1 + 13u * 24 + 8);
}

TEST(SpectralChunkDivision, BadPartsAndShortBytesAreRefused) {
  const std::vector<SkinOptics> optics = opticsAt("S1", {550});
  EXPECT_THROW(simulateSkinSpectralChunks(optics, run(100, {}), 2, 2), std::invalid_argument);
  EXPECT_THROW(simulateSkinSpectralChunks(optics, run(100, {}), 0, 0), std::invalid_argument);
  const SpectralChunks half = simulateSkinSpectralChunks(optics, run(3000, {}), 0, 2);
  EXPECT_THROW(mergeSpectralChunks(half, 1, {}), std::invalid_argument);  // chunk 1 not run
  std::string bytes = hylios::test::stateBytes(half.tallies[0][0]);
  bytes.pop_back();
  std::size_t offset = 0;
  EXPECT_THROW(SkinTally::fromBytes({}, bytes, offset), std::invalid_argument);
}

}  // namespace
}  // namespace hylios::skin
