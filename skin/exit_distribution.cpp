#include "skin/exit_distribution.h"

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include "skin/core/constants.h"

namespace hylios::skin {
namespace {
constexpr double kHalfPi = kPi / 2;
constexpr double kDegPerRad = 180.0 / kPi;

const Histogram& requireHistogram(const std::optional<Histogram>& h, const char* what) {
  if (!h) throw std::invalid_argument(std::string("the tally kept no ") + what + " histogram");
  return *h;
}

DirectionBins binsOf(const SkinTally& tally) {
  if (tally.options().polarBins == 0)
    throw std::invalid_argument(
        "the tally kept no direction histograms (TallyOptions::polarBins = 0)");
  return DirectionBins(tally.options().polarBins, tally.options().azimuthBins);
}

/// The fraction of rays that left through a flattened direction bin.
using BinEstimate = std::function<Estimate(std::size_t bin)>;

/// Σ of the given bins (exclusive: one exit per ray).
Estimate sumOfBins(const BinEstimate& binEstimate, std::uint64_t packets,
                   const std::vector<std::size_t>& bins) {
  std::vector<Estimate> parts;
  parts.reserve(bins.size());
  for (std::size_t b : bins) parts.push_back(binEstimate(b));
  return sumOfExclusive(parts, packets);
}

/// Per-sr estimates of a side of the plane of incidence: for every polar ring, the bins near
/// `azimuthRad` merged and divided by their total solid angle.
std::vector<Estimate> inPlaneSide(const BinEstimate& binEstimate, std::uint64_t packets,
                                  const DirectionBins& bins, double azimuthRad) {
  const std::vector<std::size_t> near = bins.azimuthBinsNear(azimuthRad);
  std::vector<Estimate> side;
  for (std::size_t i = 0; i < bins.polarBins(); ++i) {
    std::vector<std::size_t> flat;
    for (std::size_t j : near) flat.push_back(bins.flatIndex(i, j));
    const double solidAngle = static_cast<double>(near.size()) * bins.solidAngleSr(i);
    side.push_back(scaled(sumOfBins(binEstimate, packets, flat), 1.0 / solidAngle));
  }
  return side;
}

/// Negative θ (φ = 180°) from −90° up to 0, then positive θ (φ = 0°) from 0 to 90°.
std::vector<Estimate> joinSides(const std::vector<Estimate>& back,
                                const std::vector<Estimate>& forward) {
  std::vector<Estimate> joined(back.rbegin(), back.rend());
  joined.insert(joined.end(), forward.begin(), forward.end());
  return joined;
}

std::vector<Estimate> meanOfEach(const std::vector<const std::vector<Estimate>*>& lists) {
  const std::size_t size = lists.front()->size();
  std::vector<Estimate> mean(size);
  for (std::size_t b = 0; b < size; ++b) {
    std::vector<Estimate> values;
    for (const auto* list : lists) {
      if (list->size() != size)
        throw std::invalid_argument("meanOverWavelengths: the distributions have different bins");
      values.push_back((*list)[b]);
    }
    mean[b] = meanOfIndependent(values);
  }
  return mean;
}
}  // namespace

DirectionBins::DirectionBins(std::size_t polarBins, std::size_t azimuthBins)
    : polarBins_(polarBins), azimuthBins_(azimuthBins) {
  if (polarBins == 0 || azimuthBins == 0)
    throw std::invalid_argument(
        "direction bins: need at least one polar and one azimuth bin, got " +
        std::to_string(polarBins) + " × " + std::to_string(azimuthBins));
}

std::size_t DirectionBins::flatIndex(std::size_t polarBin, std::size_t azimuthBin) const {
  if (polarBin >= polarBins_ || azimuthBin >= azimuthBins_)
    throw std::out_of_range("direction bin (" + std::to_string(polarBin) + ", " +
                            std::to_string(azimuthBin) + ") outside " + std::to_string(polarBins_) +
                            " × " + std::to_string(azimuthBins_));
  return polarBin * azimuthBins_ + azimuthBin;
}

double DirectionBins::polarLowerRad(std::size_t i) const {
  return kHalfPi * static_cast<double>(i) / static_cast<double>(polarBins_);
}
double DirectionBins::polarUpperRad(std::size_t i) const {
  return i + 1 == polarBins_ ? kHalfPi : polarLowerRad(i + 1);
}
double DirectionBins::polarCentreRad(std::size_t i) const {
  return 0.5 * (polarLowerRad(i) + polarUpperRad(i));
}
double DirectionBins::azimuthWidthRad() const {
  return 2 * kPi / static_cast<double>(azimuthBins_);
}
double DirectionBins::azimuthLowerRad(std::size_t j) const {
  return -kPi + azimuthWidthRad() * static_cast<double>(j);
}
double DirectionBins::azimuthCentreRad(std::size_t j) const {
  return azimuthLowerRad(j) + 0.5 * azimuthWidthRad();
}

double DirectionBins::solidAngleSr(std::size_t i) const {
  return (std::cos(polarLowerRad(i)) - std::cos(polarUpperRad(i))) * azimuthWidthRad();
}

double DirectionBins::projectedSolidAngleSr(std::size_t i) const {
  const double s1 = std::sin(polarLowerRad(i)), s2 = std::sin(polarUpperRad(i));
  return 0.5 * (s2 * s2 - s1 * s1) * azimuthWidthRad();
}

std::vector<std::size_t> DirectionBins::azimuthBinsNear(double azimuthRad) const {
  std::vector<std::size_t> near;
  const double width = azimuthWidthRad();
  for (std::size_t j = 0; j < azimuthBins_; ++j) {
    const double distance =
        std::remainder(azimuthCentreRad(j) - azimuthRad, 2 * kPi);  // in [−π, π]
    if (std::fabs(distance) < width * (1 - 1e-9)) near.push_back(j);
  }
  return near;  // never empty: the bin holding azimuthRad has its centre within width/2
}

Estimate sumOfExclusive(const std::vector<Estimate>& parts, std::uint64_t packets) {
  double mean = 0, secondMoment = 0;  // per packet: E[x], E[x²]
  const double n = static_cast<double>(packets);
  for (const Estimate& e : parts) {
    mean += e.mean;
    // Var/(n−1) = s² and Var = E[x²] − m² (RunningStatistic), so E[x²] = s²(n−1) + m².
    secondMoment +=
        packets < 2 ? 0.0 : e.standardError * e.standardError * (n - 1) + e.mean * e.mean;
  }
  if (packets < 2) return {mean, 0.0};
  const double variance = std::fmax(0.0, secondMoment - mean * mean);  // negative only by rounding
  return {mean, std::sqrt(variance / (n - 1))};
}

Estimate ratioOfExclusive(const Estimate& a, const Estimate& b, std::uint64_t packets) {
  if (b.mean == 0) throw std::domain_error("ratio of estimates: the denominator is 0");
  const double r = a.mean / b.mean;
  const double covariance = packets < 2 ? 0.0 : -a.mean * b.mean / static_cast<double>(packets - 1);
  const double variance = a.standardError * a.standardError +
                          r * r * b.standardError * b.standardError - 2 * r * covariance;
  return {r, std::sqrt(std::fmax(0.0, variance)) / std::fabs(b.mean)};
}

Estimate ratioOfIndependent(const Estimate& a, const Estimate& b) {
  return ratioOfExclusive(a, b, 0);  // no covariance
}

Estimate meanOfIndependent(const std::vector<Estimate>& estimates) {
  if (estimates.empty()) throw std::invalid_argument("mean of estimates: the list is empty");
  double sum = 0, variance = 0;
  for (const Estimate& e : estimates) {
    sum += e.mean;
    variance += e.standardError * e.standardError;
  }
  const double k = static_cast<double>(estimates.size());
  return {sum / k, std::sqrt(variance) / k};
}

Estimate scaled(const Estimate& e, double factor) {
  return {e.mean * factor, e.standardError * std::fabs(factor)};
}

ReflectionDistribution reflectionDistribution(const SkinTally& tally) {
  const DirectionBins bins = binsOf(tally);
  const Histogram& surface = requireHistogram(tally.surfaceDirections(), "surface direction");
  const Histogram& subsurface =
      requireHistogram(tally.subsurfaceDirections(), "subsurface direction");
  const std::uint64_t packets = surface.packets();
  ReflectionDistribution d;
  for (std::size_t i = 0; i < bins.polarBins(); ++i) {
    const double perSr = 1.0 / bins.solidAngleSr(i),
                 perProjectedSr = 1.0 / bins.projectedSolidAngleSr(i);
    for (std::size_t j = 0; j < bins.azimuthBins(); ++j) {
      const std::size_t b = bins.flatIndex(i, j);
      const Estimate s = surface.estimate(b), u = subsurface.estimate(b);
      const Estimate t =
          sumOfExclusive({s, u}, packets);  // a ray leaves once: surface or subsurface
      d.perSteradian.surface.push_back(scaled(s, perSr));
      d.perSteradian.subsurface.push_back(scaled(u, perSr));
      d.perSteradian.total.push_back(scaled(t, perSr));
      d.brdf.surface.push_back(scaled(s, perProjectedSr));
      d.brdf.subsurface.push_back(scaled(u, perProjectedSr));
      d.brdf.total.push_back(scaled(t, perProjectedSr));
    }
  }
  InPlaneCut& cut = d.inPlanePerSteradian;
  for (std::size_t i = bins.polarBins(); i-- > 0;)
    cut.signedPolarDeg.push_back(-bins.polarCentreRad(i) * kDegPerRad);
  for (std::size_t i = 0; i < bins.polarBins(); ++i)
    cut.signedPolarDeg.push_back(bins.polarCentreRad(i) * kDegPerRad);
  const BinEstimate surfaceBin = [&](std::size_t b) { return surface.estimate(b); };
  const BinEstimate subsurfaceBin = [&](std::size_t b) { return subsurface.estimate(b); };
  const BinEstimate totalBin = [&](std::size_t b) {
    return sumOfExclusive({surface.estimate(b), subsurface.estimate(b)}, packets);
  };
  cut.surface = joinSides(inPlaneSide(surfaceBin, packets, bins, kPi),
                          inPlaneSide(surfaceBin, packets, bins, 0.0));
  cut.subsurface = joinSides(inPlaneSide(subsurfaceBin, packets, bins, kPi),
                             inPlaneSide(subsurfaceBin, packets, bins, 0.0));
  cut.total = joinSides(inPlaneSide(totalBin, packets, bins, kPi),
                        inPlaneSide(totalBin, packets, bins, 0.0));
  d.surfaceReflectance = tally.surfaceReflectance();
  d.subsurfaceReflectance = tally.subsurfaceReflectance();
  d.totalReflectance = tally.reflectance();
  return d;
}

ReflectionDistribution meanOverWavelengths(
    const std::vector<ReflectionDistribution>& distributions) {
  if (distributions.empty()) throw std::invalid_argument("meanOverWavelengths: no distributions");
  ReflectionDistribution mean;
  auto each = [&](auto member) {
    std::vector<const std::vector<Estimate>*> lists;
    for (const auto& d : distributions) lists.push_back(&member(d));
    return meanOfEach(lists);
  };
  mean.perSteradian.surface =
      each([](const ReflectionDistribution& d) -> const auto& { return d.perSteradian.surface; });
  mean.perSteradian.subsurface = each(
      [](const ReflectionDistribution& d) -> const auto& { return d.perSteradian.subsurface; });
  mean.perSteradian.total =
      each([](const ReflectionDistribution& d) -> const auto& { return d.perSteradian.total; });
  mean.brdf.surface =
      each([](const ReflectionDistribution& d) -> const auto& { return d.brdf.surface; });
  mean.brdf.subsurface =
      each([](const ReflectionDistribution& d) -> const auto& { return d.brdf.subsurface; });
  mean.brdf.total =
      each([](const ReflectionDistribution& d) -> const auto& { return d.brdf.total; });
  mean.inPlanePerSteradian.signedPolarDeg =
      distributions.front().inPlanePerSteradian.signedPolarDeg;
  mean.inPlanePerSteradian.surface = each(
      [](const ReflectionDistribution& d) -> const auto& { return d.inPlanePerSteradian.surface; });
  mean.inPlanePerSteradian.subsurface = each([](const ReflectionDistribution& d) -> const auto& {
    return d.inPlanePerSteradian.subsurface;
  });
  mean.inPlanePerSteradian.total = each(
      [](const ReflectionDistribution& d) -> const auto& { return d.inPlanePerSteradian.total; });
  auto meanOf = [&](Estimate ReflectionDistribution::*member) {
    std::vector<Estimate> values;
    for (const auto& d : distributions) values.push_back(d.*member);
    return meanOfIndependent(values);
  };
  mean.surfaceReflectance = meanOf(&ReflectionDistribution::surfaceReflectance);
  mean.subsurfaceReflectance = meanOf(&ReflectionDistribution::subsurfaceReflectance);
  mean.totalReflectance = meanOf(&ReflectionDistribution::totalReflectance);
  return mean;
}

TransmissionProfile transmissionProfile(const SkinTally& tally) {
  const DirectionBins bins = binsOf(tally);
  const Histogram& transmitted =
      requireHistogram(tally.transmittedDirections(), "transmitted direction");
  const std::uint64_t packets = transmitted.packets();
  TransmissionProfile profile;
  std::vector<Estimate> ringFractions;
  for (std::size_t i = 0; i < bins.polarBins(); ++i) {
    std::vector<std::size_t> ring;
    for (std::size_t j = 0; j < bins.azimuthBins(); ++j) ring.push_back(bins.flatIndex(i, j));
    ringFractions.push_back(
        sumOfBins([&](std::size_t b) { return transmitted.estimate(b); }, packets, ring));
    const double ringSolidAngle = bins.solidAngleSr(i) * static_cast<double>(bins.azimuthBins());
    profile.polarLowerDeg.push_back(bins.polarLowerRad(i) * kDegPerRad);
    profile.polarUpperDeg.push_back(bins.polarUpperRad(i) * kDegPerRad);
    profile.solidAngleSr.push_back(ringSolidAngle);
    profile.perSteradian.push_back(scaled(ringFractions.back(), 1.0 / ringSolidAngle));
  }
  if (ringFractions.front().mean == 0)
    throw std::domain_error(
        "no ray was transmitted within " + std::to_string(profile.polarUpperDeg.front()) +
        "° of the normal: the profile cannot be normalised (more rays or fewer polar bins?)");
  const double ringRatio0 = bins.solidAngleSr(0);
  for (std::size_t i = 0; i < bins.polarBins(); ++i) {
    if (i == 0) {
      profile.relativeToNormal.push_back({1.0, 0.0});
      continue;
    }
    const Estimate fractionRatio = ratioOfExclusive(ringFractions[i], ringFractions[0], packets);
    profile.relativeToNormal.push_back(scaled(fractionRatio, ringRatio0 / bins.solidAngleSr(i)));
  }
  profile.transmittance = tally.transmittance();
  return profile;
}

double annulusAreaCm2(double innerCm, double outerCm) {
  if (!(innerCm >= 0 && outerCm >= innerCm))
    throw std::invalid_argument("annulus: need 0 ≤ inner ≤ outer radius, got " +
                                std::to_string(innerCm) + " and " + std::to_string(outerCm) +
                                " cm");
  return kPi * (outerCm * outerCm - innerCm * innerCm);
}

RadialProfile radialProfile(const SkinTally& tally) {
  const Histogram& radial = requireHistogram(tally.radialExits(), "radial exit");
  RadialProfile profile;
  for (std::size_t b = 0; b < radial.binCount(); ++b) {
    const double inner = radial.binCentre(b) - 0.5 * radial.binWidth();
    const double outer =
        b + 1 == radial.binCount() ? tally.options().maxRadiusCm : inner + radial.binWidth();
    profile.innerCm.push_back(b == 0 ? 0.0 : inner);
    profile.outerCm.push_back(outer);
    profile.fraction.push_back(radial.estimate(b));
    profile.perCm2.push_back(
        scaled(radial.estimate(b), 1.0 / annulusAreaCm2(profile.innerCm.back(), outer)));
  }
  profile.beyondMaxRadius = radial.estimate(radial.overflowIndex());
  profile.subsurfaceReflectance = tally.subsurfaceReflectance();
  return profile;
}

}  // namespace hylios::skin
