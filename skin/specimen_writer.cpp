#include "skin/specimen_writer.h"

#include <fmt/format.h>

#include <sstream>

namespace hylios::skin {
namespace {

std::string number(double v) { return fmt::format("{}", v); }
std::string percent(double fraction) { return number(fraction * 100.0); }

std::string arrangementName(MelanosomeArrangement a) {
  return std::string(enumName(a, kArrangementNames));
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

}  // namespace

std::string formatSpecimenToml(const Specimen& s, const std::string& header) {
  std::ostringstream out;
  if (!header.empty()) {
    std::istringstream lines(header);
    std::string line;
    while (std::getline(lines, line)) out << "# " << line << "\n";
    out << "\n";
  }
  const auto& f = s.fixed;
  const auto L = [](Layer l) { return index(l); };
  out << "name = " << quoted(s.name) << "\n";
  out << "surface_fold_aspect_ratio = " << number(s.surfaceFoldAspectRatio) << "\n";
  out << "skin_dna_mg_per_ml = " << number(f.dna_mgPerMl) << "\n";
  out << "water_reduction_percent = " << percent(s.waterReduction) << "\n\n";

  const std::size_t sc = L(Layer::StratumCorneum);
  out << "[stratum_corneum]\n";
  out << "thickness_cm = " << number(s.thicknessCm[sc]) << "\n";
  out << "refractive_index_at_1300nm = " << number(f.refractiveIndexAt1300nm[sc]) << "\n";
  out << "water_percent = " << percent(f.waterFraction[sc]) << "\n";
  out << "lipid_percent = " << percent(f.lipidFraction[sc]) << "\n";
  out << "keratin_percent = " << percent(f.stratumCorneumKeratinFraction) << "\n";
  out << "urocanic_acid_mol_per_l = " << number(f.stratumCorneumUrocanicAcid_molPerL) << "\n";
  out << "beta_carotene_mg_per_ml = " << number(f.stratumCorneumBetaCarotene_mgPerMl) << "\n\n";

  const std::size_t sb = L(Layer::StratumBasale);
  out << "[epidermis]\n";
  out << "refractive_index_at_1300nm = " << number(f.refractiveIndexAt1300nm[sb]) << "\n";
  out << "water_percent = " << percent(f.waterFraction[sb]) << "\n";
  out << "lipid_percent = " << percent(f.lipidFraction[sb]) << "\n";
  out << "keratin_percent = " << percent(f.epidermisKeratinFraction) << "\n";
  out << "beta_carotene_mg_per_ml = " << number(f.epidermisBetaCarotene_mgPerMl) << "\n\n";

  for (Layer l : {Layer::StratumGranulosum, Layer::StratumSpinosum, Layer::StratumBasale}) {
    out << "[" << layerName(l) << "]\n";
    out << "thickness_cm = " << number(s.thicknessCm[L(l)]) << "\n";
    out << "melanosome_percent = " << percent(s.melanosomeFraction[L(l)]) << "\n";
    out << "colloidal_melanin_percent = " << percent(s.colloidalMelaninFraction[L(l)]) << "\n\n";
  }

  out << "[melanosomes]\n";
  out << "arrangement = " << quoted(arrangementName(s.arrangement)) << "\n";
  out << "major_axis_um = " << number(s.melanosomeMajorAxisUm) << "\n";
  out << "minor_axis_um = " << number(s.melanosomeMinorAxisUm) << "\n";
  out << "eumelanin_mg_per_ml = " << number(s.melanosomeEumelanin_mgPerMl) << "\n";
  out << "pheomelanin_mg_per_ml = " << number(s.melanosomePheomelanin_mgPerMl) << "\n";
  out << "refractive_index_at_1300nm = " << number(f.melaninRefractiveIndex) << "\n\n";

  for (Layer l : {Layer::PapillaryDermis, Layer::ReticularDermis}) {
    out << "[" << layerName(l) << "]\n";
    out << "thickness_cm = " << number(s.thicknessCm[L(l)]) << "\n";
    out << "blood_percent = " << percent(s.bloodFraction[L(l)]) << "\n";
    out << "refractive_index_at_1300nm = " << number(f.refractiveIndexAt1300nm[L(l)]) << "\n";
    out << "water_percent = " << percent(f.waterFraction[L(l)]) << "\n";
    out << "lipid_percent = " << percent(f.lipidFraction[L(l)]) << "\n\n";
  }

  out << "[blood]\n";
  out << "oxygenated_percent = " << percent(s.oxygenatedBloodFraction) << "\n";
  out << "hemoglobin_mg_per_ml = " << number(f.bloodHemoglobin_mgPerMl) << "\n";
  out << "methemoglobin_mg_per_ml = " << number(f.bloodMethemoglobin_mgPerMl) << "\n";
  out << "carboxyhemoglobin_mg_per_ml = " << number(f.bloodCarboxyhemoglobin_mgPerMl) << "\n";
  out << "sulfhemoglobin_mg_per_ml = " << number(f.bloodSulfhemoglobin_mgPerMl) << "\n";
  out << "bilirubin_mg_per_ml = " << number(f.bloodBilirubin_mgPerMl) << "\n";
  out << "beta_carotene_mg_per_ml = " << number(f.bloodBetaCarotene_mgPerMl) << "\n";
  return out.str();
}

}  // namespace hylios::skin
