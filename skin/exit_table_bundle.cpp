#include "skin/exit_table_bundle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "skin/core/constants.h"
#include "skin/sampling/discrete_sampling.h"

namespace hylios::skin {
namespace {

bool sameLayout(const ExitTableSettings& a, const ExitTableSettings& b) {
  return a.cosineBins == b.cosineBins && a.radialBins == b.radialBins &&
         a.offsetAzimuthBins == b.offsetAzimuthBins;
}

/// Per λ: p_λ(e) / ((1/N) Σ_j q_j(e)), the entry stage's ratio, into `out`.
void entryRatios(const SpectralEntry& entry, std::vector<double>& out) {
  const std::size_t n = entry.logTarget.size();
  double top = -std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < n; ++j)
    top = std::max({top, entry.logTarget[j], entry.logProposal[j]});
  out.resize(n);
  double proposal = 0;
  for (std::size_t j = 0; j < n; ++j) {
    out[j] = std::exp(entry.logProposal[j] - top);
    proposal += out[j];
  }
  for (std::size_t i = 0; i < n; ++i) {  // the target differs where a transmission was forced
    const double target =
        entry.logTarget[i] == entry.logProposal[i] ? out[i] : std::exp(entry.logTarget[i] - top);
    out[i] = target * static_cast<double>(n) / proposal;
  }
}

}  // namespace

ExitTableBundle::ExitTableBundle(const SpectralWalk& entryWalk,
                                 std::vector<const ExitTable*> tables)
    : entryWalk_(entryWalk), tables_(std::move(tables)) {
  if (tables_.size() != entryWalk_.size())
    throw std::invalid_argument("exit table bundle: " + std::to_string(tables_.size()) +
                                " tables for a walk of " + std::to_string(entryWalk_.size()) +
                                " wavelengths");
  for (const ExitTable* t : tables_) {
    if (!t) throw std::invalid_argument("exit table bundle: a table is missing");
    if (!sameLayout(t->settings(), tables_.front()->settings()))
      throw std::invalid_argument("exit table bundle: the tables' bins differ");
  }
  exitingByBin_.resize(static_cast<std::size_t>(tables_.front()->bins()));
  for (std::size_t k = 0; k < exitingByBin_.size(); ++k) {
    ExitingInBin& exiting = exitingByBin_[k];
    std::vector<const ExitTable::Bin*> bins;
    for (std::size_t i = 0; i < tables_.size(); ++i) {
      const ExitTable::Bin& b = tables_[i]->bins_[k];
      if (b.subsurface > 0 && !b.offsetCdf.empty() && b.offsetCdf.back() > 0) {
        // P(subsurface exit) as the table's own sampling has it: the outcome's share of the bin's
        // total outcome weight (ExitTable::sampleBin).
        exiting.members.push_back({i, b.subsurface / b.outcomeCdf.back()});
        bins.push_back(&b);
      }
    }
    if (bins.empty()) continue;
    const std::size_t cells = bins.front()->offsetWeights.size(), m = bins.size();
    exiting.cellProbability.resize(cells * m);
    for (std::size_t j = 0; j < m; ++j)
      for (std::size_t c = 0; c < cells; ++c)
        exiting.cellProbability[c * m + j] = bins[j]->offsetWeights[c] / bins[j]->offsetCdf.back();
  }
}

void ExitTableBundle::sample(const Vec3& incident, Rng& rng, SpectralPath& path,
                             bool splitEntryReflection, const std::array<double, 2>* stratified,
                             const FacetNumbers* firstFacet) const {
  thread_local SpectralEntry entry;
  path.exitEntryWeight.clear();
  if (!entryWalk_.enter(incident, rng, path, entry, splitEntryReflection, firstFacet)) return;
  const std::size_t n = tables_.size();
  thread_local std::vector<double> ratio, density;
  entryRatios(entry, ratio);
  const int k = tables_.front()->chooseBin(entry.direction.z, rng.uniform());
  const auto bin = static_cast<std::size_t>(k);
  const std::vector<ExitingMember>& exiting = exitingByBin_[bin].members;
  path.exitWeight.assign(n, 0.0);
  if (exiting.empty()) {
    path.end = PathEnd::Absorbed;
    return;
  }
  const std::size_t m = exiting.size();
  const double uHero = stratified ? (*stratified)[0] : rng.uniform();
  const double uCell = stratified ? (*stratified)[1] : rng.uniform();
  const std::size_t hero =
      exiting[std::min(m - 1, static_cast<std::size_t>(uHero * static_cast<double>(m)))].member;
  const ExitTable& heroTable = *tables_[hero];
  const std::size_t A = static_cast<std::size_t>(heroTable.settings_.offsetAzimuthBins);
  const std::size_t cell = pickCumulative(heroTable.bins_[bin].offsetCdf, uCell);
  const int radial = static_cast<int>(cell / A);
  const double r = heroTable.radiusInCell(k, radial, rng.uniform());
  double phi = (static_cast<double>(cell % A) + rng.uniform()) / static_cast<double>(A) * kPi;
  if (rng.uniform() < 0.5) phi = -phi;
  phi += std::atan2(entry.direction.y, entry.direction.x);
  // π_λ(c) u_λ(r | c), up to the in-cell density that every table shares (all but the overflow).
  const bool overflow = radial > heroTable.settings_.radialBins;
  density.assign(n, 0.0);
  double mixture = 0;
  const double* cellProbability = exitingByBin_[bin].cellProbability.data() + cell * m;
  for (std::size_t j = 0; j < m; ++j) {
    const ExitingMember& e = exiting[j];
    double d = cellProbability[j];
    if (overflow) {
      const ExitTable& t = *tables_[e.member];
      const double lo = t.radialCellLowerCm(radial), hi = t.radialCellUpperCm(k, radial);
      d = r < hi && hi > lo ? d / (hi - lo) : 0.0;
    }
    density[e.member] = d;
    mixture += d;
  }
  mixture /= static_cast<double>(m);
  path.exitEntryWeight.assign(n, 0.0);
  for (const ExitingMember& e : exiting) {
    const std::size_t i = e.member;
    path.exitEntryWeight[i] = ratio[i] * e.subsurfaceShare;
    path.exitWeight[i] = path.exitEntryWeight[i] * density[i] / mixture;
  }
  path.end = PathEnd::SubsurfaceReflection;
  path.exitOffsetXCm = r * std::cos(phi);
  path.exitOffsetYCm = r * std::sin(phi);
  path.exitDirection = Vec3{0, 0, -1};
}

}  // namespace hylios::skin
