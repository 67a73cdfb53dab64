// A specimen's modelled curve against a group of a measured population (app/skin_population.h):
// per spectral region, how many wavelengths fall inside the group's measured range, the RMS to the
// group's median, and the largest excursion outside the range. `hylios validate` uses it for the
// paper's Fig. 9 (S3 against lightly pigmented skin, S4 against the darkest skin measured).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "app/skin_population.h"
#include "skin/core/statistics.h"

namespace hylios {

struct PopulationRegion {
  double firstNm = 0, lastNm = 0;  ///< the region's first and last compared wavelength
  std::size_t count = 0;
  std::size_t inside = 0;  ///< model within [lowest − 2σ, highest + 2σ] of the group
  double rmsToMedian = 0;
  double worstExcess = 0;  ///< signed distance beyond the range (model − nearest edge); 0 if none
  double worstExcessNm = 0;
};

struct PopulationComparison {
  std::string specimen, group;
  double incidenceDeg = 8;
  std::vector<double> wavelengthNm;
  std::vector<skin::Estimate> model;
  PopulationEnvelope envelope;
  /// 250–314, 315–399, 400–704, 705–1304, 1305–2500 nm (those holding a wavelength), then the
  /// whole curve.
  std::vector<PopulationRegion> regions;
};

/// A modelled curve (`model` at `wavelengths`, named `specimen`, at `incidenceDeg`) against the
/// envelope of `members` of `population`. Throws std::invalid_argument for unequal lengths or an
/// empty group, std::out_of_range for a wavelength the population does not cover.
PopulationComparison compareWithPopulation(const std::string& specimen,
                                           const std::vector<double>& wavelengths,
                                           const std::vector<skin::Estimate>& model,
                                           double incidenceDeg, const SkinPopulation& population,
                                           const std::vector<std::size_t>& members,
                                           const std::string& groupName);

/// One PNG with a panel per comparison: the group's range shaded, its median, the model ± 2σ.
void plotPopulationComparisons(const std::filesystem::path& png, const std::string& title,
                               const std::vector<PopulationComparison>& comparisons);

/// A Markdown table, a row per comparison and a column per region of the first one: how many
/// wavelengths lie inside the measured range and, if any lie outside, the largest excess (model −
/// nearest edge) and where; then the RMS to the group median over the whole curve. Throws
/// std::invalid_argument unless the comparisons share their wavelengths.
std::string populationTable(const std::vector<PopulationComparison>& comparisons);

}  // namespace hylios
