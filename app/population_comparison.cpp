#include "app/population_comparison.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>

#include "app/gnuplot_plot.h"

namespace hylios {
namespace {

/// Region lower edges (nm); each region runs to the next edge.
constexpr double kRegionEdgesNm[] = {250, 315, 400, 705, 1305};

PopulationRegion regionOver(const PopulationComparison& c, double fromNm, double toNm) {
  PopulationRegion r;
  double sum2 = 0;
  for (std::size_t i = 0; i < c.wavelengthNm.size(); ++i) {
    const double w = c.wavelengthNm[i];
    if (w < fromNm || w >= toNm) continue;
    if (r.count == 0) r.firstNm = w;
    r.lastNm = w;
    ++r.count;
    const double m = c.model[i].mean, slack = 2 * c.model[i].standardError;
    const double d = m - c.envelope.median[i];
    sum2 += d * d;
    const double excess = m > c.envelope.highest[i] + slack  ? m - c.envelope.highest[i]
                          : m < c.envelope.lowest[i] - slack ? m - c.envelope.lowest[i]
                                                             : 0.0;
    if (excess == 0) ++r.inside;
    if (std::fabs(excess) > std::fabs(r.worstExcess)) {
      r.worstExcess = excess;
      r.worstExcessNm = w;
    }
  }
  if (r.count > 0) r.rmsToMedian = std::sqrt(sum2 / static_cast<double>(r.count));
  return r;
}

}  // namespace

PopulationComparison compareWithPopulation(const std::string& specimen,
                                           const std::vector<double>& wavelengths,
                                           const std::vector<skin::Estimate>& model,
                                           double incidenceDeg, const SkinPopulation& population,
                                           const std::vector<std::size_t>& members,
                                           const std::string& groupName) {
  if (wavelengths.empty() || model.size() != wavelengths.size())
    throw std::invalid_argument("population comparison: " + std::to_string(model.size()) +
                                " model values for " + std::to_string(wavelengths.size()) +
                                " wavelengths");
  if (std::adjacent_find(wavelengths.begin(), wavelengths.end(), std::greater_equal<double>()) !=
      wavelengths.end())
    throw std::invalid_argument("population comparison: wavelengths must ascend");
  PopulationComparison c{specimen,    groupName, incidenceDeg,
                         wavelengths, model,     population.envelope(members, wavelengths),
                         {}};
  const double top = c.wavelengthNm.back() + 1;
  for (std::size_t k = 0; k < std::size(kRegionEdgesNm); ++k) {
    const double to = k + 1 < std::size(kRegionEdgesNm) ? kRegionEdgesNm[k + 1] : top;
    const PopulationRegion r = regionOver(c, kRegionEdgesNm[k], to);
    if (r.count > 0) c.regions.push_back(r);
  }
  c.regions.push_back(regionOver(c, c.wavelengthNm.front(), top));
  return c;
}

void plotPopulationComparisons(const std::filesystem::path& png, const std::string& title,
                               const std::vector<PopulationComparison>& comparisons) {
  std::vector<PlotPanel> panels;
  for (const PopulationComparison& c : comparisons) {
    const PopulationEnvelope& e = c.envelope;
    PlotSeries range{
        "measured: " + c.group + " (" + std::to_string(e.members) + " subjects), range and median",
        e.wavelengthNm,
        e.median,
        {},
        "lines lw 1 lc rgb 'black'"};
    range.bandLow = e.lowest;
    range.bandHigh = e.highest;
    PlotSeries model{"HyLIoS " + c.specimen + " ± 2σ", c.wavelengthNm, {}, {}, "lines lw 2"};
    for (const auto& m : c.model) {
      model.y.push_back(m.mean);
      model.yError.push_back(2 * m.standardError);
    }
    panels.push_back(
        {c.specimen + " vs " + c.group + ", " + fmt::format("{:g}", c.incidenceDeg) + "°",
         "wavelength (nm)",
         "reflectance",
         false,
         {range, model}});
  }
  plotPanels(png, title, panels, 1, 1400, 500 * static_cast<int>(comparisons.size()));
}

std::string populationTable(const std::vector<PopulationComparison>& comparisons) {
  if (comparisons.empty()) return "";
  const auto range = [](const PopulationRegion& r) {
    return fmt::format("{:g}", r.firstNm) + "–" + fmt::format("{:g}", r.lastNm) + " nm";
  };
  std::ostringstream md;
  md << "| comparison |";
  for (const PopulationRegion& r : comparisons.front().regions) md << " " << range(r) << " |";
  md << " RMS to the median, all |\n|---|";
  for (std::size_t k = 0; k < comparisons.front().regions.size(); ++k) md << "---|";
  md << "---|\n";
  for (const PopulationComparison& c : comparisons) {
    if (c.wavelengthNm != comparisons.front().wavelengthNm)
      throw std::invalid_argument("population table: comparisons on different wavelengths");
    md << "| " << c.specimen << " vs " << c.group << ", " << fmt::format("{:g}", c.incidenceDeg)
       << "° |";
    for (const PopulationRegion& r : c.regions) {
      md << " " << r.inside << "/" << r.count;
      if (r.worstExcess != 0)
        md << " (" << fmt::format("{:+.4f}", r.worstExcess) << " at "
           << fmt::format("{:g}", r.worstExcessNm) << ")";
      md << " |";
    }
    md << " " << fmt::format("{:.4f}", c.regions.back().rmsToMedian) << " |\n";
  }
  return md.str();
}

}  // namespace hylios
