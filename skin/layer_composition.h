// What each layer contains, as concentrations of the absorbers of Sec. 3.1 (paper Sec. 4.1,
// Eq. 3; Tables 1–2). This is the one place where specimen parameters become the weights of the
// specific absorption coefficients:
//
//   μa(layer, absorber, λ) = ζ(absorber, λ) · concentration(layer, absorber)
//
// with each concentration in the unit of absorberConcentrationUnit(absorber):
//   volume fraction  — water (× (1 − water reduction)), lipid, keratin (Table 2 percent / 100)
//   mg/mL            — DNA, β-carotene, melanins, hemoglobins, bilirubin
//   mol/L            — urocanic acid
//
// Per layer (the paper's Table 2; choices in docs/interpretations.md):
//   stratum corneum       keratin, water, lipid, urocanic acid, β-carotene (SC), DNA
//   granulosum/spinosum/  water, lipid, keratin (not in Table 2: the living cells' protein;
//   basale                  docs/interpretations.md), β-carotene (epidermis), DNA, colloidal
//                           melanin: eumelanin = f_colloidal · c_eu, pheomelanin = f_colloidal ·
//                           c_pheo (c = the melanosome concentrations of Table 1;
//                           docs/interpretations.md)
//   papillary/reticular   water, lipid, and v_blood × whole blood (Eq. 3):
//   dermis                  HbO2 = Hb · oxy, Hb = Hb · (1 − oxy) with Hb = 147 mg/mL, and
//                           HbCO, MetHb, SHb, bilirubin, β-carotene (blood) at Table 2 values.
// DNA (Table 2 "skin DNA density") sits in the stratum corneum and the three epidermal layers,
// where Sec. 3.1 places the UV absorbers; the dermis gets none.
#pragma once
#include <array>

#include "skin/absorber.h"
#include "skin/layer.h"
#include "skin/specimen.h"

namespace hylios::skin {

/// Concentration of every absorber in a layer, indexed by index(Absorber).
using AbsorberConcentrations = std::array<double, kAbsorberCount>;

/// The unit layerAbsorberConcentrations uses for `absorber` (must equal the spectral data's).
ConcentrationUnit absorberConcentrationUnit(Absorber absorber);

/// The concentrations of `layer` of `specimen` (zeros for absorbers the layer lacks).
AbsorberConcentrations layerAbsorberConcentrations(const Specimen& specimen, Layer layer);

}  // namespace hylios::skin
