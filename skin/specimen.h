// A skin specimen: the parameters of paper Table 1 (S1–S4) and Table 2 (fixed values).
//
// Loaded from TOML files (scenes/specimens/S1.toml ...). All lengths in cm unless the name says
// otherwise; contents are stored as fractions in [0, 1] (files give percent, key names say so).
#pragma once
#include <array>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "skin/core/enum_names.h"
#include "skin/layer.h"

namespace hylios::skin {

/// How melanosomes are distributed (paper Sec. 3.2, 4.2.2, Fig. 3).
enum class MelanosomeArrangement {
  LightComplexes,     ///< spheres of diameter 2× the melanosome major axis (lightly pigmented)
  ModerateComplexes,  ///< spheres of diameter 1× the major axis (moderately pigmented)
  Dispersed,          ///< individually dispersed prolate spheroids (darkly pigmented)
};
/// The arrangements' names in specimen files (`arrangement`).
inline constexpr EnumNames<MelanosomeArrangement, 3> kArrangementNames{
    {{MelanosomeArrangement::LightComplexes, "light_complexes"},
     {MelanosomeArrangement::ModerateComplexes, "moderate_complexes"},
     {MelanosomeArrangement::Dispersed, "dispersed"}}};

/// Table 2: values held fixed across specimens.
struct FixedParameters {
  std::array<double, kLayerCount>
      refractiveIndexAt1300nm{};  ///< per layer (epidermal layers share 1.4)
  double melaninRefractiveIndex = 0;
  double bloodHemoglobin_mgPerMl = 0;
  double bloodMethemoglobin_mgPerMl = 0;
  double bloodCarboxyhemoglobin_mgPerMl = 0;
  double bloodSulfhemoglobin_mgPerMl = 0;
  double bloodBilirubin_mgPerMl = 0;
  double bloodBetaCarotene_mgPerMl = 0;
  double stratumCorneumBetaCarotene_mgPerMl = 0;
  double epidermisBetaCarotene_mgPerMl = 0;
  std::array<double, kLayerCount> waterFraction{};  ///< per layer, before any water reduction
  std::array<double, kLayerCount> lipidFraction{};
  double stratumCorneumKeratinFraction = 0;
  /// Keratin of the living epidermis (granulosum, spinosum, basale), volume fraction; not in the
  /// paper's tables (docs/interpretations.md).
  double epidermisKeratinFraction = 0;
  double stratumCorneumUrocanicAcid_molPerL = 0;
  double dna_mgPerMl = 0;
};

struct Specimen {
  std::string name;                   ///< e.g. "S1"
  std::filesystem::path sourceFile;   ///< where it was loaded from (empty if built in code)
  double surfaceFoldAspectRatio = 0;  ///< s of Sec. 4.3
  std::array<double, kLayerCount> thicknessCm{};
  std::array<double, kLayerCount>
      melanosomeFraction{};  ///< volume fraction v; 0 outside the epidermis
  std::array<double, kLayerCount> colloidalMelaninFraction{};  ///< 0 outside the epidermis
  double melanosomeEumelanin_mgPerMl = 0;
  double melanosomePheomelanin_mgPerMl = 0;
  double melanosomeMajorAxisUm = 0;  ///< full axis length (Table 1 "dimensions")
  double melanosomeMinorAxisUm = 0;
  MelanosomeArrangement arrangement = MelanosomeArrangement::LightComplexes;
  std::array<double, kLayerCount> bloodFraction{};  ///< 0 outside the dermis
  double oxygenatedBloodFraction = 0;
  double waterReduction = 0;  ///< fraction in [0, 1]; every layer's water × (1 − reduction)
  FixedParameters fixed;
};

/// Error in a specimen file or override; what() reads "file:line:col: message".
class SpecimenError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A quantity that scenes and command lines vary, applied after loading (e.g.
/// "melanosome_percent=3", "water_reduction_percent=20"). See applyOverride for the keys.
struct SpecimenOverride {
  std::string key;
  double value = 0;
  std::string origin;  ///< where it came from, for messages ("--set", "scene.toml:12:5")
};

/// Loads a specimen by name ("S1" … "S4", looked up in `specimenDir`) or by path.
Specimen loadSpecimen(const std::string& nameOrPath, const std::filesystem::path& specimenDir);
/// Parses a specimen from TOML text; `sourceName` is used in error locations.
Specimen parseSpecimen(const std::string& tomlText, const std::string& sourceName);
/// Applies one override; throws SpecimenError (with override.origin) for unknown keys or values
/// out of range.
void applyOverride(Specimen& specimen, const SpecimenOverride& override_);
/// The keys applyOverride accepts, for --help texts.
std::vector<std::string> overrideKeys();
/// Checks physical consistency (ranges); throws SpecimenError.
void validateSpecimen(const Specimen& specimen);

}  // namespace hylios::skin
