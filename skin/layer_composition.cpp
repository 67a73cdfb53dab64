#include "skin/layer_composition.h"

namespace hylios::skin {

ConcentrationUnit absorberConcentrationUnit(Absorber absorber) {
  switch (absorber) {
    case Absorber::Water:
    case Absorber::Lipid:
    case Absorber::Keratin:
      return ConcentrationUnit::VolumeFraction;
    case Absorber::UrocanicAcid:
      return ConcentrationUnit::MolarConcentration;
    default:
      return ConcentrationUnit::MassConcentration;
  }
}

namespace {

void addBlood(const Specimen& s, double bloodFraction, AbsorberConcentrations& c) {
  const FixedParameters& f = s.fixed;
  const double oxy = s.oxygenatedBloodFraction;
  // Eq. 3: every blood-borne absorber weighted by the layer's blood volume fraction.
  c[index(Absorber::Oxyhemoglobin)] = bloodFraction * f.bloodHemoglobin_mgPerMl * oxy;
  c[index(Absorber::Deoxyhemoglobin)] = bloodFraction * f.bloodHemoglobin_mgPerMl * (1.0 - oxy);
  c[index(Absorber::Carboxyhemoglobin)] = bloodFraction * f.bloodCarboxyhemoglobin_mgPerMl;
  c[index(Absorber::Methemoglobin)] = bloodFraction * f.bloodMethemoglobin_mgPerMl;
  c[index(Absorber::Sulfhemoglobin)] = bloodFraction * f.bloodSulfhemoglobin_mgPerMl;
  c[index(Absorber::Bilirubin)] = bloodFraction * f.bloodBilirubin_mgPerMl;
  c[index(Absorber::BetaCarotene)] = bloodFraction * f.bloodBetaCarotene_mgPerMl;
}

}  // namespace

AbsorberConcentrations layerAbsorberConcentrations(const Specimen& s, Layer layer) {
  AbsorberConcentrations c{};
  const FixedParameters& f = s.fixed;
  const std::size_t i = index(layer);
  c[index(Absorber::Water)] = f.waterFraction[i] * (1.0 - s.waterReduction);
  c[index(Absorber::Lipid)] = f.lipidFraction[i];
  if (layer == Layer::StratumCorneum) {
    c[index(Absorber::Keratin)] = f.stratumCorneumKeratinFraction;
    c[index(Absorber::UrocanicAcid)] = f.stratumCorneumUrocanicAcid_molPerL;
    c[index(Absorber::BetaCarotene)] = f.stratumCorneumBetaCarotene_mgPerMl;
    c[index(Absorber::Dna)] = f.dna_mgPerMl;
  } else if (isPigmentedEpidermis(layer)) {
    c[index(Absorber::Keratin)] = f.epidermisKeratinFraction;
    c[index(Absorber::BetaCarotene)] = f.epidermisBetaCarotene_mgPerMl;
    c[index(Absorber::Dna)] = f.dna_mgPerMl;
    // Colloidal melanin: the fraction of the layer's volume holding melanin at the melanosome
    // concentrations of Table 1 (docs/interpretations.md).
    const double colloidal = s.colloidalMelaninFraction[i];
    c[index(Absorber::Eumelanin)] = colloidal * s.melanosomeEumelanin_mgPerMl;
    c[index(Absorber::Pheomelanin)] = colloidal * s.melanosomePheomelanin_mgPerMl;
  } else {
    addBlood(s, s.bloodFraction[i], c);
  }
  return c;
}

}  // namespace hylios::skin
