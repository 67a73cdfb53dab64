#include "skin/spectral_walk.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "skin/core/constants.h"
#include "skin/interface_crossing.h"
#include "skin/melanosome_interaction.h"
#include "skin/sampling/exponential_ziggurat.h"
#include "skin/sampling/rayleigh_sampling.h"
#include "skin/spectral_bundle.h"
#include "skin/spectral_walk_state.h"
#include "skin/spectral_weights.h"

namespace hylios::skin {
using spectral_walk_detail::kInfinity;
using spectral_walk_detail::kPendingTableIndices;

namespace {
/// Relative tolerance on index ratios that must be equal across the bundle (rounding only).
constexpr double kRatioTolerance = 1e-9;

/// Melanosome path-length table indices: log2 of the table's size, three indices from the top,
/// middle and low bits of one 64-bit random number (each uniform and independent of the others).
constexpr unsigned kTableIndexBits = 18;
static_assert(kSpectralMelanosomeTableSamples == std::size_t{1} << kTableIndexBits &&
              3 * kTableIndexBits <= 64);
constexpr std::uint64_t kTableIndexMask = (std::uint64_t{1} << kTableIndexBits) - 1;

/// An exponential free path of coefficient μ (given with its inverse): +∞ for μ = 0.
double sampleFreePathCm(double mu_perCm, double inverseMuCm, Rng& rng) {
  return mu_perCm > 0 ? sampleStandardExponential(rng) * inverseMuCm : kInfinity;
}

bool sameRatio(double a, double b) { return std::fabs(a - b) <= kRatioTolerance * std::fabs(b); }

void requireShared(bool same, const std::string& what) {
  if (!same)
    throw std::invalid_argument("spectral walk: the wavelengths of a bundle must share " + what);
}

/// log p(θ)·e^{θ/θo}/sinθ of Algorithm 2's law: p(θ) = e^{−θ/θo} sinθ (1 + θo²)/(θo²(1 +
/// e^{−π/θo})).
double logAngleNormalisation(double meanAngleRad) {
  if (meanAngleRad == 0) return 0;
  const double t2 = meanAngleRad * meanAngleRad;
  return std::log1p(t2) - std::log(t2) - std::log1p(std::exp(-kPi / meanAngleRad));
}

std::string layerText(Layer layer) { return std::string(layerName(layer)); }
}  // namespace

SpectralWalk::SpectralWalk(const std::vector<SkinOptics>& bundle, WalkOptions options)
    : options_(options), wavelengthCount_(bundle.size()) {
  if (bundle.empty()) throw std::invalid_argument("spectral walk: the bundle has no wavelength");
  const SkinWalk reference(bundle.front(), options);  // the same checks as the analog walk
  const SkinOptics& first = bundle.front();
  double depthCm = 0;
  for (Layer layer : kAllLayers) {
    if (index(layer) > index(options.deepestLayer)) break;
    const LayerOptics& lo = first[layer];
    if (!(lo.thicknessCm > 0)) continue;
    Slab slab;
    slab.layer = layer;
    slab.topCm = depthCm;
    slab.bottomCm = depthCm + lo.thicknessCm;
    slab.referenceIndex = lo.refractiveIndex;
    slab.muMelanosome_perCm = options.melanosomes ? lo.melanosome.mu_perCm : 0.0;
    for (const SkinOptics& o : bundle) {
      requireShared(o[layer].thicknessCm == lo.thicknessCm, "the thickness of " + layerText(layer));
      requireShared(
          o[layer].melanosome.mu_perCm == lo.melanosome.mu_perCm &&
              o[layer].melanosome.semiMinorAxisCm == lo.melanosome.semiMinorAxisCm &&
              o[layer].melanosome.semiMajorAxisCm == lo.melanosome.semiMajorAxisCm &&
              o[layer].melanosome.melanosomesPerComplex == lo.melanosome.melanosomesPerComplex,
          "the melanosomes of " + layerText(layer));
      requireShared(
          sameRatio(o[layer].refractiveIndex / o[Layer::StratumCorneum].refractiveIndex,
                    lo.refractiveIndex / first[Layer::StratumCorneum].refractiveIndex) &&
              sameRatio(o.melaninRefractiveIndex / o[layer].refractiveIndex,
                        first.melaninRefractiveIndex / lo.refractiveIndex),
          "the index ratios of " + layerText(layer) + " (indices dispersed by one factor)");
      slab.muA_perCm.push_back(lo.thicknessCm > 0 ? o[layer].muATotal_perCm : 0.0);
      const double rayleigh = options.rayleigh ? o[layer].muRayleigh_perCm : 0.0;
      slab.muRayleigh_perCm.push_back(rayleigh);
      slab.hasRayleigh = slab.hasRayleigh || rayleigh > 0;
    }
    if (!slab.hasRayleigh) slab.muRayleigh_perCm.clear();
    for (double mu : slab.muRayleigh_perCm) slab.logRayleigh.push_back(std::log(mu));
    slab.leastMuA_perCm = *std::min_element(slab.muA_perCm.begin(), slab.muA_perCm.end());
    slab.largestMuA_perCm = *std::max_element(slab.muA_perCm.begin(), slab.muA_perCm.end());
    slab.muA_perCmSingle.assign(slab.muA_perCm.begin(), slab.muA_perCm.end());
    if (slab.muMelanosome_perCm > 0) slab.inverseMuMelanosomeCm = 1.0 / slab.muMelanosome_perCm;
    for (double mu : slab.muRayleigh_perCm) {
      const double scatter = slab.muMelanosome_perCm + mu;
      slab.inverseMuScatterCm.push_back(scatter > 0 ? 1.0 / scatter : kInfinity);
    }
    std::optional<Melanosomes> shape;
    if (slab.muMelanosome_perCm > 0) {
      const MelanosomeLayer checked(first, layer);  // validates the geometry and θo
      const MelanosomeOptics& m = lo.melanosome;
      Melanosomes s;
      s.geometry.aspect = m.semiMajorAxisCm / m.semiMinorAxisCm;
      s.geometry.inverseAspect = m.semiMinorAxisCm / m.semiMajorAxisCm;
      s.geometry.entering = FresnelPair(lo.refractiveIndex, first.melaninRefractiveIndex);
      s.geometry.leaving = FresnelPair(first.melaninRefractiveIndex, lo.refractiveIndex);
      s.semiMinorAxisCm = m.semiMinorAxisCm;
      if (m.inComplexes) s.count = m.melanosomesPerComplex;
      if (options.tabulatedMelanosomes)
        s.table = MelanosomePathLengths::shared(
            melanosomeTableKey(s.geometry.aspect),
            melanosomeTableKey(first.melaninRefractiveIndex / lo.refractiveIndex),
            kSpectralMelanosomeTableSamples);
      shape = s;
    }
    melanosomes_.push_back(shape);
    slabs_.push_back(std::move(slab));
    depthCm += lo.thicknessCm;
  }
  for (std::size_t k = 0; k + 1 < slabs_.size(); ++k) {
    Slab& upper = slabs_[k];
    Slab& lower = slabs_[k + 1];
    upper.intoDeeper = FresnelPair(upper.referenceIndex, lower.referenceIndex);
    lower.intoShallower = FresnelPair(lower.referenceIndex, upper.referenceIndex);
  }
  for (const SkinOptics& o : bundle) {
    requireShared(o.surfaceAspectRatio == first.surfaceAspectRatio,
                  "the surface fold aspect ratio");
    requireShared((o.meanScatteringAngleRad == 0) == (first.meanScatteringAngleRad == 0),
                  "θo = 0 or θo > 0 (Algorithm 2's law is a point mass at θo = 0)");
    melaninMuA_perCm_.push_back(o.melanosomeInteriorMuA_perCm);
    meanAngleRad_.push_back(o.meanScatteringAngleRad);
    logAngleNormalisation_.push_back(logAngleNormalisation(o.meanScatteringAngleRad));
    anglesDiffer_ = anglesDiffer_ || o.meanScatteringAngleRad != first.meanScatteringAngleRad;
    surfaceIndex_.push_back(o[slabs_.front().layer].refractiveIndex);
    bottomIndex_.push_back(o[slabs_.back().layer].refractiveIndex);
    surfaceIndicesDiffer_ = surfaceIndicesDiffer_ || surfaceIndex_.back() != surfaceIndex_.front();
  }
  smallestSurfaceIndex_ = *std::min_element(surfaceIndex_.begin(), surfaceIndex_.end());
  surfaceGroups_ = SurfaceIndexGroups(surfaceIndex_);
  for (const Slab& slab : slabs_) splitsRayleigh_ = splitsRayleigh_ || slab.hasRayleigh;
  splitsRayleigh_ = splitsRayleigh_ && options.splitFirstRayleigh;
  leastMelaninMuA_perCm_ = *std::min_element(melaninMuA_perCm_.begin(), melaninMuA_perCm_.end());
  largestMelaninMuA_perCm_ = *std::max_element(melaninMuA_perCm_.begin(), melaninMuA_perCm_.end());
  melaninMuA_perCmSingle_.assign(melaninMuA_perCm_.begin(), melaninMuA_perCm_.end());
  requireShared(options.roughSurface || !surfaceIndicesDiffer_,
                "one surface index when the surface is smooth (a dispersive smooth interface "
                "refracts each wavelength elsewhere: split the bundle)");
  if (options.roughSurface) {
    facetPolar_.emplace(first.surfaceAspectRatio);
    aspectSquared_ = first.surfaceAspectRatio * first.surfaceAspectRatio;
  }
  heroShares_ = HeroShares(wavelengthCount_);
  if (options.heroSharesByLaw) {
    std::vector<double> depth;
    for (const SkinOptics& o : bundle) depth.push_back(rayleighDepth(o, options));
    heroShares_ = HeroShares(meanAngleRad_, depth);
  }
}

std::size_t SpectralWalk::drawHero(Rng& rng) const {
  if (wavelengthCount_ == 1) return 0;
  return heroShares_.draw(rng.uniform());
}

void SpectralWalk::startPath(State& s, const Vec3& direction, Rng& rng) const {
  s.path.events = 1;
  s.path.exitOffsetXCm = s.path.exitOffsetYCm = 0;
  s.hero = drawHero(rng);
  // Hero j proposed with probability c_j: log(n·c_j) in its proposal, so that misRatios' mean
  // over the heroes is the mixture Σ_j c_j q_j.
  if (!heroShares_.uniform()) s.proposalOffset = heroShares_.logScaledShares();
  s.direction = direction;
}

bool SpectralWalk::enterFromAir(State& s, Rng& rng, bool splitEntryReflection,
                                const FacetNumbers* firstFacet) const {
  if (crossSurface(s, false, rng, splitEntryReflection, firstFacet)) return true;
  s.zeroOutcomes();
  s.path.end = PathEnd::SurfaceReflection;
  s.path.exitDirection = s.direction;
  s.misRatios(s.path.exitWeight);
  return false;
}

void SpectralWalk::trace(const Vec3& incidentDirection, Rng& rng, SpectralPath& path,
                         bool splitEntryReflection, const FacetNumbers* firstFacet) const {
  State s(path, wavelengthCount_, options_.layerAbsorption, options_.melanosomeAbsorption);
  startPath(s, incidentDirection, rng);
  if (enterFromAir(s, rng, splitEntryReflection, firstFacet)) traceEntered(s, rng);
}

bool SpectralWalk::enter(const Vec3& incidentDirection, Rng& rng, SpectralPath& path,
                         SpectralEntry& entry, bool splitEntryReflection,
                         const FacetNumbers* firstFacet) const {
  State s(path, wavelengthCount_, options_.layerAbsorption, options_.melanosomeAbsorption);
  startPath(s, incidentDirection, rng);
  if (!enterFromAir(s, rng, splitEntryReflection, firstFacet)) return false;
  s.zeroOutcomes();  // the path pauses: its outcomes are the caller's (skin/exit_table_bundle.h)
  entry.direction = s.direction;
  entry.hero = s.hero;
  entry.logTarget = s.logDensity;
  entry.logProposal.resize(wavelengthCount_);
  for (std::size_t i = 0; i < wavelengthCount_; ++i)
    entry.logProposal[i] = s.logDensity[i] + s.proposalOffset[i];
  return true;
}

void SpectralWalk::traceEntered(const Vec3& transmittedDirection, Rng& rng,
                                SpectralPath& path) const {
  State s(path, wavelengthCount_, options_.layerAbsorption, options_.melanosomeAbsorption);
  startPath(s, transmittedDirection, rng);
  traceEntered(s, rng);
}

inline void SpectralWalk::drawTableIndices(State& s, Rng& rng) {
  const std::uint64_t bits = rng.nextU64();
  s.pendingIndex[s.pendingCount++] = static_cast<std::uint32_t>(bits >> (64 - kTableIndexBits));
  s.pendingIndex[s.pendingCount++] =
      static_cast<std::uint32_t>((bits >> (64 - 2 * kTableIndexBits)) & kTableIndexMask);
  s.pendingIndex[s.pendingCount++] =
      static_cast<std::uint32_t>((bits >> (64 - 3 * kTableIndexBits)) & kTableIndexMask);
}

inline std::uint32_t SpectralWalk::takeTableIndex(State& s, Rng& rng) {
  if (s.pendingCount == 0) drawTableIndices(s, rng);
  return s.pendingIndex[--s.pendingCount];
}

void SpectralWalk::meetMelanosomes(State& s, std::size_t k, Rng& rng) const {
  const Melanosomes& m = *melanosomes_[k];
  const unsigned count = m.count;
  double chordsOverA = 0;
  if (m.table) {  // a local sum, so that the table's loads (cache misses) overlap
    const float* table = m.table->pathLengthsSingle().data();
    double sum = 0;
    for (unsigned i = 0; i < count; ++i) sum += table[takeTableIndex(s, rng)];
    chordsOverA = sum;
    // Draws the next meeting's indices now and prefetches them from this layer's table (most
    // meetings follow one in the same layer; in another layer they are still uniform indices).
    const unsigned ahead = std::min(m.count, kPendingTableIndices - 2);
    while (s.pendingCount < ahead) drawTableIndices(s, rng);
    for (unsigned i = 0; i < s.pendingCount; ++i) __builtin_prefetch(table + s.pendingIndex[i]);
  } else {
    for (unsigned i = 0; i < count; ++i)
      walkInsideMelanosome(m.geometry, rng, [&chordsOverA](double chord) {
        chordsOverA += chord;
        return false;  // absorption is a weight: the internal path always runs to its end
      });
  }
  s.stayMelaninCm += chordsOverA * m.semiMinorAxisCm;
  const PolarCosSin theta =
      sampleExponentialPolarCosSin(meanAngleRad_[s.hero], rng);  // Algorithm 2
  if (anglesDiffer_) {  // Σ_k (log norm_i − θ_k/θo_i), added by settleDensities
    ++s.angleCount;
    s.angleSumRad += theta.thetaRad;
  }
  const Azimuth phi = sampleAzimuth(rng);
  s.direction = directionAbout(s.direction, theta.cosTheta, theta.sinTheta, phi.cosPhi, phi.sinPhi);
}

void SpectralWalk::endStay(State& s) const {
  s.pathCm[s.slab] += s.stayCm;
  s.melaninCm[s.slab] += s.stayMelaninCm;
  s.leastDepth +=
      slabs_[s.slab].leastMuA_perCm * s.stayCm + leastMelaninMuA_perCm_ * s.stayMelaninCm;
  if (options_.layerAbsorption && (s.stayCm > 0 || s.stayMelaninCm > 0)) {
    // Stored field by field into the vector: a temporary copied in whole made the copy's wide
    // load wait on the temporary's narrow stores (a store-forwarding stall, 3 % of the walk).
    SpectralPath::Stay& stay = s.stays.emplace_back();
    stay.slab = s.slab;
    stay.cm = s.stayCm;
    stay.melaninCm = s.stayMelaninCm;
    stay.roulette = s.roulette;
  }
  s.stayCm = s.stayMelaninCm = 0;
}

bool SpectralWalk::survivesRoulette(State& s, Rng& rng) const {
  // The transmittance of the least absorbed λ bounds every λ's (the MIS ratio is left out:
  // any survival probability that depends only on the path so far keeps the walk unbiased).
  // Most checks pass without an exp: below the bound the largest weight is above the threshold.
  if (s.leastDepth <= s.rouletteDepthBound) return true;
  const double largest = s.roulette * std::exp(-s.leastDepth);
  if (largest >= kSpectralRouletteWeight) return true;
  const double survival = largest / kSpectralRouletteWeight;
  if (survival > 0 && rng.uniform() < survival) {
    s.roulette /= survival;
    s.rouletteDepthBound = std::log(s.roulette / kSpectralRouletteWeight);
    return true;
  }
  finish(s, PathEnd::Absorbed, false);
  return false;
}

void SpectralWalk::settleDensities(State& s) const {
  const std::size_t n = wavelengthCount_;
  if (s.angleCount > 0) {
    const double count = s.angleCount, sum = s.angleSumRad;
    for (std::size_t i = 0; i < n; ++i)
      s.logDensity[i] += count * logAngleNormalisation_[i] - sum / meanAngleRad_[i];
    s.angleCount = 0;
    s.angleSumRad = 0;
  }
  for (std::size_t k = 0; k < slabs_.size(); ++k) {
    if (!(s.rayleighCm[k] > 0) && s.rayleighEvents[k] == 0) continue;
    const Slab& slab = slabs_[k];
    const double cm = s.rayleighCm[k], events = s.rayleighEvents[k];
    for (std::size_t i = 0; i < n; ++i)
      s.logDensity[i] += -slab.muRayleigh_perCm[i] * cm + events * slab.logRayleigh[i];
    s.rayleighCm[k] = 0;
    s.rayleighEvents[k] = 0;
  }
}

void SpectralWalk::splitAtRayleigh(State& s, double cosR, double sinR, const Azimuth& phi,
                                   Rng& rng) const {
  // E f(cos) = ½ E f(|cos|) + ½ E f(−|cos|) for the even Rayleigh law, whatever f: each branch
  // continues with the folded cosine's hemisphere, weight ½ (in its MIS ratio, SpectralWalk::
  // finish). The λ-dependent densities (where the event happened) are shared and already booked.
  SpectralPath& path = s.path;
  if (path.backward.empty()) path.backward.emplace_back();
  s.branchWeight = 0.5;
  State backward(path.backward.front(), s);
  backward.direction = directionAbout(s.direction, -std::fabs(cosR), sinR, phi.cosPhi, phi.sinPhi);
  path.split = true;
  path.splitAtEvent = path.events;
  traceEntered(backward, rng);
}

void SpectralWalk::finish(State& s, PathEnd end, bool scores) const {
  endStay(s);
  settleDensities(s);
  SpectralPath& path = s.path;
  path.end = end;
  path.exitOffsetXCm = s.position.x;
  path.exitOffsetYCm = s.position.y;
  std::vector<double>& ratio = s.ratio;
  s.misRatios(ratio);
  const std::size_t n = wavelengthCount_;
  if (s.branchWeight != 1.0)
    for (std::size_t i = 0; i < n; ++i) ratio[i] *= s.branchWeight;
  std::array<spectral_weights::SlabAbsorption, kLayerCount> slabs{};
  for (std::size_t k = 0; k < slabs_.size(); ++k)
    slabs[k] = {
        {slabs_[k].muA_perCm.data(), slabs_[k].muA_perCmSingle.data(), slabs_[k].largestMuA_perCm},
        index(slabs_[k].layer)};
  // Workspace: the transmittance per λ (and the path depths without layer absorption).
  std::vector<double>& work = path.work;
  double* transmitted = nullptr;
  if (options_.layerAbsorption) {  // each stay's loss, in the order the path made them
    work.resize(n);
    transmitted = work.data();
    path.singleWork.resize(2 * n);
    const spectral_weights::MelaninAbsorption melanin{
        melaninMuA_perCm_.data(), melaninMuA_perCmSingle_.data(), largestMelaninMuA_perCm_};
    spectral_weights::stayLosses(
        n, s.stays.data(), s.stays.size(), slabs.data(), melanin, ratio.data(), transmitted,
        path.absorbed.data(),
        options_.melanosomeAbsorption ? path.absorbedInMelanosomes.data() : nullptr,
        path.singleWork.data());
  } else {
    work.resize(2 * n);
    transmitted = work.data();
    double* depth = transmitted + n;
    spectral_weights::pathDepths(n, slabs_.size(), slabs.data(), s.pathCm.data(),
                                 s.melaninCm.data(), melaninMuA_perCm_.data(), depth);
    spectral_weights::exponentials(n, depth, -1.0, 0.0, transmitted);
  }
  for (std::size_t i = 0; i < n; ++i) {
    path.exitWeight[i] = scores ? s.roulette * transmitted[i] * ratio[i] : 0.0;
    // E[ratio] = 1 − (the surface weight scored at a split entry): E = 1 − R − T.
    path.absorbedTotal[i] = ratio[i] - path.exitWeight[i];
  }
}

void SpectralWalk::traceEntered(State& s, Rng& rng) const {
  SpectralPath& path = s.path;
  const std::size_t slabCount = slabs_.size();
  while (path.events < SkinWalk::kMaxEvents) {
    ++path.events;
    const Slab& slab = slabs_[s.slab];
    Vec3& d = s.direction;
    const bool rayleighHere = s.rayleighAvailable && slab.hasRayleigh;
    const double muScatter =
        slab.muMelanosome_perCm + (rayleighHere ? slab.muRayleigh_perCm[s.hero] : 0.0);
    const double toBoundaryCm = d.z > 0   ? (slab.bottomCm - s.position.z) / d.z
                                : d.z < 0 ? (slab.topCm - s.position.z) / d.z
                                          : kInfinity;
    const double inverseMuCm =
        rayleighHere ? slab.inverseMuScatterCm[s.hero] : slab.inverseMuMelanosomeCm;
    const double freePathCm = sampleFreePathCm(muScatter, inverseMuCm, rng);
    const bool collides = freePathCm < toBoundaryCm;
    const double flightCm = collides ? freePathCm : toBoundaryCm;
    if (!std::isfinite(flightCm)) break;  // parallel to the layers with nothing to stop it
    s.stayCm += flightCm;
    s.position += d * flightCm;
    const bool rayleighEvent = collides && rng.uniform() * muScatter >= slab.muMelanosome_perCm;
    if (rayleighHere && wavelengthCount_ > 1) {  // −μR_i·flight (+ log μR_i), settleDensities
      s.rayleighCm[s.slab] += flightCm;
      if (rayleighEvent) ++s.rayleighEvents[s.slab];
    }
    if (collides) {
      if (!rayleighEvent) {
        meetMelanosomes(s, s.slab, rng);
        continue;
      }
      double cosR = sampleRayleighCos(rng.uniform());  // Algorithm 1's density
      const double sinR = std::sqrt((1.0 - cosR) * (1.0 + cosR));
      const Azimuth phi = sampleAzimuth(rng);
      s.rayleighAvailable = false;
      if (splitsRayleigh_ && s.branchWeight == 1.0) {  // the path's first Rayleigh event
        splitAtRayleigh(s, cosR, sinR, phi, rng);
        cosR = std::fabs(cosR);
      }
      d = directionAbout(d, cosR, sinR, phi.cosPhi, phi.sinPhi);
      continue;
    }
    s.position.z = d.z > 0 ? slab.bottomCm : slab.topCm;
    if (d.z < 0 && s.slab == 0) {  // the skin surface, from inside
      if (crossSurface(s, true, rng)) {
        path.exitDirection = s.direction;
        return finish(s, PathEnd::SubsurfaceReflection, true);
      }
      continue;
    }
    if (d.z > 0 && s.slab + 1 == slabCount) {
      if (options_.deepestLayer == Layer::ReticularDermis) {  // dermis–hypodermis: diffuse, R = 1
        const Vec3 local = sampleCosineHemisphereByDisk(rng);
        d = Vec3{local.x, local.y, -local.z};
        continue;
      }
      if (crossBottom(s, rng)) return finish(s, PathEnd::Transmitted, true);
      continue;
    }
    const std::size_t next = d.z > 0 ? s.slab + 1 : s.slab - 1;
    const InterfaceCrossing crossing =
        crossPlaneInterfaceZ(d, d.z > 0 ? slab.intoDeeper : slab.intoShallower, rng);
    d = crossing.direction;
    if (crossing.transmitted) {  // a layer's stay ends, then roulette
      endStay(s);
      s.slab = next;
      if (slabs_[next].layer == Layer::PapillaryDermis) s.rayleighAvailable = true;  // a new pass
      if (!survivesRoulette(s, rng)) return;
    }
  }
  finish(s, PathEnd::EventLimit, true);
}

}  // namespace hylios::skin
