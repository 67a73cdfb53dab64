// The light-absorbing materials of HyLIoS (paper Sec. 3.1, Fig. 2, Table 2).
#pragma once
#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace hylios::skin {

enum class Absorber : std::size_t {
  Keratin = 0,
  Dna,
  UrocanicAcid,
  Eumelanin,
  Pheomelanin,
  Oxyhemoglobin,
  Deoxyhemoglobin,
  Carboxyhemoglobin,
  Methemoglobin,
  Sulfhemoglobin,
  Bilirubin,
  BetaCarotene,
  Water,
  Lipid,
};
inline constexpr std::size_t kAbsorberCount = 14;

inline constexpr std::array<Absorber, kAbsorberCount> kAllAbsorbers = {
    Absorber::Keratin,         Absorber::Dna,
    Absorber::UrocanicAcid,    Absorber::Eumelanin,
    Absorber::Pheomelanin,     Absorber::Oxyhemoglobin,
    Absorber::Deoxyhemoglobin, Absorber::Carboxyhemoglobin,
    Absorber::Methemoglobin,   Absorber::Sulfhemoglobin,
    Absorber::Bilirubin,       Absorber::BetaCarotene,
    Absorber::Water,           Absorber::Lipid};

/// snake_case name used in CSV columns (mu_a_<name>_per_cm) and messages.
constexpr std::string_view absorberName(Absorber a) {
  constexpr std::array<std::string_view, kAbsorberCount> names = {
      "keratin",         "dna",
      "urocanic_acid",   "eumelanin",
      "pheomelanin",     "oxyhemoglobin",
      "deoxyhemoglobin", "carboxyhemoglobin",
      "methemoglobin",   "sulfhemoglobin",
      "bilirubin",       "beta_carotene",
      "water",           "lipid"};
  return names[static_cast<std::size_t>(a)];
}
constexpr std::size_t index(Absorber a) { return static_cast<std::size_t>(a); }
/// The concentration unit in which an absorber's specific absorption coefficient is expressed.
/// μa of a mixture [cm⁻¹] = Σ specificAbsorption(a, λ) · concentration(a) in that unit.
enum class ConcentrationUnit {
  VolumeFraction,     ///< pure-substance μa [cm⁻¹] per volume fraction (water, lipid, keratin)
  MassConcentration,  ///< [cm⁻¹ per mg/mL]   (melanins, hemoglobins, bilirubin, β-carotene, DNA)
  MolarConcentration,  ///< [cm⁻¹ per mol/L]   (urocanic acid)
};

}  // namespace hylios::skin
