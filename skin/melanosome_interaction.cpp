#include "skin/melanosome_interaction.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "skin/melanosome_path_lengths.h"
#include "skin/sampling/exponential_polar_sampling.h"
#include "skin/sampling/polar_rejection_sampling.h"
#include "skin/spheroid.h"

namespace hylios::skin {
namespace {
void requirePositiveIndex(double n, const char* what) {
  if (!(n > 0 && std::isfinite(n)))
    throw std::invalid_argument(std::string("melanosome interaction: ") + what + " " +
                                std::to_string(n) + " is not positive and finite");
}

}  // namespace

MelanosomeLayer::MelanosomeLayer(double semiMinor, double semiMajor, double interiorMuA,
                                 double nLayer, double nMelanin) {
  checkProlateSpheroid({semiMinor, semiMajor});
  if (!(interiorMuA >= 0 && std::isfinite(interiorMuA)))
    throw std::invalid_argument("melanosome interaction: interior absorption coefficient " +
                                std::to_string(interiorMuA) + " is negative or not finite");
  requirePositiveIndex(nLayer, "layer refractive index");
  requirePositiveIndex(nMelanin, "melanin refractive index");
  geometry_.entering = FresnelPair(nLayer, nMelanin);
  geometry_.leaving = FresnelPair(nMelanin, nLayer);
  geometry_.aspect = semiMajor / semiMinor;
  geometry_.inverseAspect = semiMinor / semiMajor;
  muA_perMinorAxis_ = interiorMuA * semiMinor;
}

MelanosomeLayer::MelanosomeLayer(const SkinOptics& optics, Layer layer,
                                 MelanosomeAbsorption absorption)
    : MelanosomeLayer(optics[layer].melanosome.semiMinorAxisCm,
                      optics[layer].melanosome.semiMajorAxisCm, optics.melanosomeInteriorMuA_perCm,
                      optics[layer].refractiveIndex, optics.melaninRefractiveIndex) {
  const MelanosomeOptics& m = optics[layer].melanosome;
  if (m.inComplexes) {
    if (!(m.melanosomesPerComplex >= 1 && m.melanosomesPerComplex < 1000000000u))
      throw std::invalid_argument(
          "melanosome interaction: " + std::to_string(m.melanosomesPerComplex) +
          " melanosomes per complex in " + std::string(layerName(layer)) + " is outside [1, 1e9)");
    count_ = m.melanosomesPerComplex;
  }
  meanAngleRad_ = optics.meanScatteringAngleRad;
  const bool angleOk = meanAngleRad_ == 0.0 || (meanAngleRad_ >= kMinExponentialMeanAngleRad &&
                                                meanAngleRad_ <= kMaxExponentialMeanAngleRad);
  if (!angleOk)
    throw std::invalid_argument("melanosome interaction: mean scattering angle " +
                                std::to_string(meanAngleRad_) +
                                " rad must be 0 or in [1e-300, 1e6]");
  if (absorption == MelanosomeAbsorption::Tabulated)
    tabulate(optics[layer].refractiveIndex, optics.melaninRefractiveIndex);
}

void MelanosomeLayer::tabulate(double nLayer, double nMelanin) {
  tabulated_ = true;
  if (muA_perMinorAxis_ == 0) return;  // clear melanosomes never absorb: no table needed
  const auto table = MelanosomePathLengths::shared(melanosomeTableKey(geometry_.aspect),
                                                   melanosomeTableKey(nMelanin / nLayer));
  const double one = table->absorptionProbability(muA_perMinorAxis_);  // one pass over the table
  absorbedByCount_ = MelanosomePathLengths::absorptionByCount(one, count_);
}

double MelanosomeLayer::tabulatedAbsorption() const {
  if (!tabulated_)
    throw std::logic_error(
        "MelanosomeLayer::tabulatedAbsorption: the layer traces its melanosomes");
  return absorbedByCount_;
}

bool MelanosomeLayer::absorbedInOne(Rng& rng) const {
  // Eq. 1 with the melanin coefficient on each chord; 1 − u is exact, so log(1 − u) = log1p(−u).
  const double mu = muA_perMinorAxis_;
  const auto absorbedOnChord = [mu, &rng](double chord) {
    return mu > 0 && -std::log(1.0 - rng.uniform()) < mu * chord;
  };
  return walkInsideMelanosome(geometry_, rng, absorbedOnChord) == MelanosomeWalkEnd::Stopped;
}

MelanosomeEvent MelanosomeLayer::interact(const Vec3& direction, Rng& rng) const {
  MelanosomeEvent event;
  const unsigned count = count_;
  if (tabulated_) {  // one uniform for all `count` melanosomes: absorbed with 1 − q^count
    event.melanosomesMet = count;
    if (rng.uniform() < absorbedByCount_) {
      event.absorbed = true;
      return event;
    }
  } else {
    for (unsigned i = 0; i < count; ++i) {
      ++event.melanosomesMet;
      if (absorbedInOne(rng)) {
        event.absorbed = true;
        return event;
      }
    }
  }
  const PolarCosSin theta = sampleExponentialPolarCosSin(meanAngleRad_, rng);  // Algorithm 2
  const Azimuth phi = sampleAzimuth(rng);
  event.direction =
      directionAbout(direction, theta.cosTheta, theta.sinTheta, phi.cosPhi, phi.sinPhi);
  return event;
}

bool absorbedInMelanosome(const Vec3& direction, double semiMinorCm, double semiMajorCm,
                          double interiorMuA_perCm, double nLayer, double nMelanin, Rng& rng) {
  if (!(std::fabs(dot(direction, direction) - 1.0) <= 1e-6))
    throw std::invalid_argument("absorbedInMelanosome: the direction is not a unit vector");
  return MelanosomeLayer(semiMinorCm, semiMajorCm, interiorMuA_perCm, nLayer, nMelanin)
      .absorbedInOne(rng);
}

}  // namespace hylios::skin
